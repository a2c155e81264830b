"""Fixtures of the bridge tests: loopback-only DDS settings, a ROS master on 127.0.0.1, and
child processes that are always ended, whatever the test's fate."""

from __future__ import annotations

import hashlib
import itertools
import os
import random
import shutil
import subprocess
import time
import xmlrpc.client
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from tests.bridges.procs import SYSTEM_PYTHON, Child, child_env, free_port

_domains = itertools.count(0)
#: blocks of three domains (a test may use d, d + 1 and d + 2), 76 of them in 1..228
_BLOCKS = 76
#: pytest-xdist's workers share the run's id: from it they all draw the same random
#: start, and each takes the blocks congruent to its own number, so two tests running at
#: once in one run never share a domain; runs of other people start elsewhere
_RUN = os.environ.get("PYTEST_XDIST_TESTRUNUID") or str(random.SystemRandom().random())
_FIRST = int.from_bytes(hashlib.sha256(_RUN.encode()).digest()[:4], "big") % _BLOCKS
_WORKER = int(os.environ.get("PYTEST_XDIST_WORKER", "gw0")[2:] or 0)
_WORKERS = max(1, int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1")))


def random_domain() -> int:
    """A DDS domain id (1..228) that no other test of this run uses at the same time."""
    block = (_FIRST + _WORKER + _WORKERS * next(_domains)) % _BLOCKS
    return 1 + 3 * block


@pytest.fixture
def spawn() -> Iterator[Callable[..., Child]]:
    """Start children that are all stopped at the end of the test."""
    children: list[Child] = []

    def start(argv: list[str], env: dict[str, str] | None = None, name: str = "") -> Child:
        child = Child(argv, env, name)
        children.append(child)
        return child

    yield start
    for child in reversed(children):
        child.stop()


@pytest.fixture
def dds() -> tuple[int, dict[str, str]]:
    """A DDS domain of its own and an environment that keeps Cyclone on 127.0.0.1."""
    pytest.importorskip("cyclonedds", reason="the ROS 2 bridge needs the ros2 extra (cyclonedds)")
    from robocog.bridges.ros2.loopback import LOOPBACK_URI

    domain = random_domain()
    env = child_env({"CYCLONEDDS_URI": LOOPBACK_URI, "ROS_DOMAIN_ID": str(domain)})
    return domain, env


def _has_rospy() -> str:
    """Why ROS 1 tests cannot run here, or '' when they can."""
    if not Path(SYSTEM_PYTHON).exists():
        return f"{SYSTEM_PYTHON} is missing"
    if shutil.which("rosmaster") is None:
        return "rosmaster is missing (run .ci/install_ros.sh)"
    probe = subprocess.run(
        [SYSTEM_PYTHON, "-c", "import rospy, actionlib, move_base_msgs.msg, sensor_msgs.msg"],
        capture_output=True,
        text=True,
        env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"},
    )
    if probe.returncode != 0:
        return "Debian's rospy packages are missing (run .ci/install_ros.sh)"
    return ""


@pytest.fixture(scope="module")
def roscore(tmp_path_factory: pytest.TempPathFactory) -> Iterator[dict[str, str]]:
    """A ROS master on 127.0.0.1 and a free port; yields the environment that reaches it.

    ``rosmaster --core`` is what ``roscore`` starts, without roslaunch and the C++
    ``rosout`` logger (and the Boost and ICU libraries they bring), which no test reads."""
    reason = _has_rospy()
    if reason:
        pytest.skip(reason)
    port = free_port()
    home = tmp_path_factory.mktemp("ros_home")
    env = child_env(
        {
            "ROS_MASTER_URI": f"http://127.0.0.1:{port}",
            "ROS_IP": "127.0.0.1",
            "ROS_HOME": str(home),
            "ROS_LOG_DIR": str(home / "log"),
        }
    )
    env.pop("ROS_HOSTNAME", None)
    core_env = {k: v for k, v in env.items() if k != "PYTHONPATH"}
    core = Child(["rosmaster", "--core", "-p", str(port)], core_env, "rosmaster")
    try:
        master = xmlrpc.client.ServerProxy(env["ROS_MASTER_URI"])
        deadline = time.monotonic() + 30
        while True:
            try:
                code, _msg, _uri = master.getUri("/test")
                if code == 1:
                    break
            except OSError:
                pass
            if time.monotonic() > deadline or core.proc.poll() is not None:
                pytest.fail(f"rosmaster did not come up: {core.stderr_text()[-2000:]}")
            time.sleep(0.2)
        yield env
    finally:
        core.stop()


DATA = Path(__file__).with_name("data")


def _mind_class(name: str) -> str:
    """Why the mind ``--mind name`` cannot drive a robot here, or '' when it can: its
    engine may be missing or not yet able to act (the registry's probe)."""
    from robocog.minds import registry

    return registry.probe(name) or ""


@pytest.fixture
def nars_knowledge() -> str:
    """The Narsese background knowledge for `--mind nars`; skips while NarsMind is missing."""
    reason = _mind_class("nars")
    if reason:
        pytest.skip(reason)
    return str(DATA / "reflex.nal")


@pytest.fixture
def bdi_program() -> str:
    """The AgentSpeak program for `--mind bdi`; skips while BdiMind is missing."""
    reason = _mind_class("bdi")
    if reason:
        pytest.skip(reason)
    return str(DATA / "reflex.asl")
