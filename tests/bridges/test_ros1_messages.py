"""ROS 1 message classes the bridge makes itself when Debian's package is not there."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[2] / "src"
SYSTEM_PYTHON = "/usr/bin/python3"
#: nav_msgs/Odometry's MD5 in ROS 1 (the same in every distribution since Hydro)
ODOMETRY_MD5 = "cd5e73d190d741a2f92e81eda573aca7"

PROBE = """
import sys
if {block}:
    sys.modules["nav_msgs"] = None  # as if python3-nav-msgs were not installed
from io import BytesIO
from robocog.bridges.ros1.node import odometry_class
Odometry = odometry_class()
odom = Odometry()
odom.header.frame_id = "odom"
odom.child_frame_id = "base_link"
odom.pose.pose.position.x = 1.5
buffer = BytesIO()
odom.serialize(buffer)
back = Odometry()
back.deserialize(buffer.getvalue())
print(Odometry._type, Odometry._md5sum, back.pose.pose.position.x, back.child_frame_id)
"""


def _run(block: bool) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(SRC)
    return subprocess.run(
        [SYSTEM_PYTHON, "-c", PROBE.format(block=block)],
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )


def _has_genpy() -> bool:
    if not Path(SYSTEM_PYTHON).exists():
        return False
    probe = subprocess.run(
        [SYSTEM_PYTHON, "-c", "import genpy, geometry_msgs.msg, std_msgs.msg"],
        capture_output=True,
        env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"},
    )
    return probe.returncode == 0


@pytest.mark.skipif(not _has_genpy(), reason="Debian's genpy and message packages are missing")
@pytest.mark.parametrize("block", [True, False])
def test_odometry_is_generated_with_the_real_checksum_when_nav_msgs_is_missing(
    block: bool,
) -> None:
    run = _run(block)
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["nav_msgs/Odometry", ODOMETRY_MD5, "1.5", "base_link"]
