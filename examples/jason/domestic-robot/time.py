"""The robot's clock: ``time.check(T)`` gives the time of day as ``"HH:MM:SS"``."""

from __future__ import annotations

import datetime

from robocog.bdi.environment import internal_action


@internal_action
def check(agent, out):  # noqa: ANN001, ANN201 - an internal action's signature
    """Say the time (as Jason's version logs it) and give it as a string."""
    now = datetime.datetime.now().strftime("%H:%M:%S")
    agent.print(f"Check Time={now}")
    return (now,)
