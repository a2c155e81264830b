"""A Cyclone DDS configuration that keeps every packet on 127.0.0.1.

Tests, benchmarks and a first try of the bridge on a laptop must not send discovery
traffic to a network: this configuration binds Cyclone to the loopback address, turns
multicast off and names 127.0.0.1 as the only peer, so discovery runs over unicast.
Cyclone reads it from ``CYCLONEDDS_URI`` when the first participant is created.
"""

from __future__ import annotations

import os
from collections.abc import MutableMapping

LOOPBACK_URI = (
    "<CycloneDDS><Domain Id='any'><General>"
    "<Interfaces><NetworkInterface address='127.0.0.1' multicast='false'/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
    "<Peers><Peer address='127.0.0.1'/></Peers></Discovery>"
    "</Domain></CycloneDDS>"
)


def use_loopback(env: MutableMapping[str, str] | None = None) -> MutableMapping[str, str]:
    """Put the loopback configuration in ``env`` (the process environment by default).

    Call it before the first DomainParticipant exists; it returns ``env`` so that it can
    prepare a child process's environment too.
    """
    target = os.environ if env is None else env
    target["CYCLONEDDS_URI"] = LOOPBACK_URI
    return target


def loopback_unless_configured() -> None:
    """Keep this process's DDS on loopback, unless the user's own ``CYCLONEDDS_URI``
    already says where it runs (theirs wins)."""
    if "CYCLONEDDS_URI" not in os.environ:
        use_loopback()
