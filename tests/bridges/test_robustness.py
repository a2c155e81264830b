"""Bad input and lost robots: malformed CDR, results of unknown goals, NaN readings, a stale
sensor, a simulator killed mid-goal. The bridge logs once, stops the robot, carries on."""

from __future__ import annotations

import logging
import math
import struct
import subprocess
import sys
import threading
import time
from dataclasses import replace
from typing import Any

import pytest

try:
    from cyclonedds.core import DDSException
except ImportError:  # the tests that need it skip
    DDSException = RuntimeError  # type: ignore[assignment,misc]

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import BoxReading, PoseReading, ScanReading
from robocog.bridges.runner import BridgeRunner
from robocog.robot import Command, Detection, GoTo, Obstacle, Outcome, Pose, Status, Turn
from tests.bridges.fakes import FakeLink
from tests.bridges.procs import wait_until

SCAN = ScanReading(-math.pi / 2, math.pi / 180, 0.05, 10.0, [1.0] * 181)


def test_nan_and_infinite_readings_never_reach_the_mind_and_are_counted() -> None:
    body = RobotBody(FakeLink(), BridgeConfig(places={"bin": (0.0, 0.0, 0.0)})).start()
    body.on_pose(PoseReading(math.nan, 0.0, 0.0))
    body.on_pose(PoseReading(1.0, math.inf, 0.0))
    body.on_boxes([BoxReading("bottle", 0.9, math.nan), BoxReading("cup", math.nan, 320.0)])
    body.on_scan(ScanReading(math.nan, 0.01, 0.05, 10.0, [1.0] * 10))  # NaN angles
    body.on_scan(ScanReading(-1.0, 0.01, 0.05, 10.0, [math.nan] * 10))
    percepts = body.percepts()
    assert not any(isinstance(p, Pose | Detection | Obstacle) for p in percepts)
    assert body.dropped == {"pose": 2, "detection": 2, "scan": 2}
    # the good ones still pass, +inf ranges (no return) included
    body.on_scan(ScanReading(-1.0, 0.01, 0.05, 10.0, [math.inf] * 10))
    body.on_boxes([BoxReading("bottle", 0.9, 320.0)])
    body.on_pose(PoseReading(0.1, 0.0, 0.0))
    percepts = body.percepts()
    assert Obstacle("none", 2.0) in percepts
    assert any(isinstance(p, Detection) and math.isfinite(p.bearing) for p in percepts)
    assert any(isinstance(p, Pose) and p.place == "bin" for p in percepts)


class Driver:
    """A mind that always turns a little (so a halt shows as cancelled motion)."""

    def __init__(self) -> None:
        self.outcomes: list[Outcome] = []

    def perceive(self, percepts: Any) -> None:
        return

    def decide(self) -> list[Command]:
        return [Turn(0.05)]

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        self.outcomes.append(outcome)


def test_a_stale_scan_halts_motion_within_the_watchdog_time_while_poses_arrive() -> None:
    config = BridgeConfig(watchdog_seconds=0.5, angular_speed=1.0, command_rate=50.0)
    link = FakeLink()
    body = RobotBody(link, config).start()
    runner = BridgeRunner(body, Driver())
    stop = threading.Event()

    def robot() -> None:
        scans = 0
        while not stop.wait(0.05):
            body.on_pose(PoseReading(0.0, 0.0, 0.0))
            if scans < 20:  # one second of scans, then the lidar falls silent
                body.on_scan(SCAN)
                scans += 1
                last_scan[0] = time.monotonic()

    last_scan = [0.0]
    feeder = threading.Thread(target=robot, daemon=True)
    feeder.start()
    worker = threading.Thread(target=runner.run, kwargs={"duration": 4.0}, daemon=True)
    worker.start()
    try:
        assert wait_until(lambda: any("no scan" in e for _t, e in runner.events), 4)
        halted_at = next(t for t, e in runner.events if "no scan" in e)
        # the event's wall time against the last scan's monotonic time: compare ages
        assert body.halted is not None and "no scan" in body.halted
        assert halted_at - (time.time() - (time.monotonic() - last_scan[0])) <= 0.5 + 0.5
        assert link.of("cancel")  # goals cancelled, zero velocity sent
        assert link.of("twist")[-1] == (0.0, 0.0)
    finally:
        stop.set()
        runner.stop()
        worker.join(timeout=5)


def test_results_of_unknown_goals_are_logged_once_and_ignored(
    caplog: pytest.LogCaptureFixture,
) -> None:
    pytest.importorskip("cyclonedds")
    from cyclonedds.domain import DomainParticipant

    from robocog.bridges.ros2 import messages as m
    from robocog.bridges.ros2.actions import ActionClient
    from robocog.bridges.ros2.link import RELIABLE
    from robocog.bridges.ros2.loopback import use_loopback
    from tests.bridges.conftest import random_domain

    use_loopback()
    client = ActionClient(
        DomainParticipant(random_domain()), "/navigate_to_pose", m.NAVIGATE_TO_POSE, RELIABLE
    )
    on_sent, on_result = client.handlers[0][1], client.handlers[1][1]
    with caplog.at_level(logging.WARNING, logger="robocog.bridges.ros2"):
        for seq in range(5):
            on_result(m.NavigateToPoseGetResultResponse(client.guid, 1000 + seq, 4))
            on_sent(m.NavigateToPoseSendGoalResponse(client.guid, 2000 + seq, True))
        on_result(m.NavigateToPoseGetResultResponse(client.guid + 1, 1, 4))  # another's
    messages = [r.getMessage() for r in caplog.records]
    assert sum("result of an unknown goal" in t for t in messages) == 1
    assert sum("goal reply for no goal of ours" in t for t in messages) == 1


def test_a_malformed_cdr_sample_is_logged_once_and_the_link_carries_on(
    caplog: pytest.LogCaptureFixture,
) -> None:
    pytest.importorskip("cyclonedds")
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.pub import DataWriter
    from cyclonedds.topic import Topic

    from robocog.bridges.ros2 import messages as m
    from robocog.bridges.ros2.link import RELIABLE, SENSOR, Ros2Link
    from robocog.bridges.ros2.loopback import use_loopback
    from tests.bridges.conftest import random_domain

    use_loopback()
    domain = random_domain()
    config = BridgeConfig()
    body = RobotBody(Ros2Link(config, domain), config).start()
    dp = DomainParticipant(domain)
    scans = DataWriter(dp, Topic(dp, "rt/scan", m.LaserScan, qos=SENSOR), qos=SENSOR)
    poses = DataWriter(
        dp, Topic(dp, "rt/amcl_pose", m.PoseWithCovarianceStamped, qos=RELIABLE), qos=RELIABLE
    )
    # a scan whose ranges claim two billion floats and carry eight bytes: a broken driver.
    # Cyclone checks what it sends and what it receives, so such a sample never leaves a
    # Cyclone writer ...
    good = m.LaserScan(angle_min=-1.0, angle_increment=0.1, range_min=0.05, range_max=5.0)
    head = good.serialize()[:-8]  # everything up to the two sequence lengths
    broken = m.LaserScan()
    broken.serialize = lambda use_version_2=False: (
        head + struct.pack("<I", 2_000_000_000) + b"\0" * 8
    )
    with pytest.raises(DDSException):
        scans.write(broken)

    # ... and when another stack delivers a sample the reader cannot take (Cyclone raises
    # on it), the link logs it once, drops it, and keeps serving every topic
    link = body.link
    index = next(i for i, (r, _h) in enumerate(link.readers) if r.topic.name == "rt/scan")
    reader, handler = link.readers[index]
    link.readers[index] = (_Failing(reader, 5), handler)
    try:
        with caplog.at_level(logging.WARNING, logger="robocog.bridges.ros2"):
            assert wait_until(lambda: bool(scans.get_matched_subscriptions()), 20)
            pose = m.PoseWithCovarianceStamped()
            pose.pose.pose.position.x = 1.5

            def fed() -> bool:
                poses.write(pose)
                scans.write(good)
                percepts = body.percepts()
                return any(isinstance(p, Obstacle) for p in percepts) and any(
                    isinstance(p, Pose) and p.x == 1.5 for p in percepts
                )

            assert wait_until(fed, 20, step=0.1)  # the link still reads both topics
        problems = [r.getMessage() for r in caplog.records if "rt/scan" in r.getMessage()]
        assert len(problems) == 1, problems
    finally:
        body.close()


class _Failing:
    """A reader whose first ``times`` takes fail as Cyclone fails on a sample it cannot
    deserialize."""

    def __init__(self, reader: Any, times: int) -> None:
        self.reader = reader
        self.topic = reader.topic
        self.times = times

    def take(self, n: int) -> list[Any]:
        if self.times > 0:
            self.times -= 1
            self.reader.take(n)  # the bad sample is gone
            raise DDSException(-1, "malformed sample")
        return self.reader.take(n)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.reader, name)


@pytest.mark.slow
def test_a_sim_killed_mid_goal_halts_the_robot_and_the_bridge_carries_on_when_it_returns(
    tmp_path: Any,
) -> None:
    """A real-time sim process is killed while a GoTo is under way: the GoTo ends
    cancelled within the watchdog time, the robot is halted; a new sim comes up and the
    mind's next GoTo succeeds, in the same bridge."""
    pytest.importorskip("cyclonedds")
    from robocog.bridges.ros2.link import Ros2Link
    from robocog.bridges.ros2.loopback import LOOPBACK_URI, use_loopback
    from tests.bridges.conftest import random_domain
    from tests.bridges.procs import child_env

    use_loopback()
    domain = random_domain()
    env = child_env({"CYCLONEDDS_URI": LOOPBACK_URI})

    def sim(rate: str) -> subprocess.Popen[str]:
        argv = [sys.executable, "-m", "robocog.cli", "sim", "garbage", "--ros2", "--loopback"]
        argv += ["--domain", str(domain), "--rate", rate]
        return subprocess.Popen(
            argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env
        )

    class Goer:
        def __init__(self) -> None:
            self.outcomes: list[tuple[float, Outcome]] = []

        def perceive(self, percepts: Any) -> None:
            return

        def decide(self) -> list[Command]:
            return [GoTo("p0")]

        def on_outcome(self, command: Command, outcome: Outcome) -> None:
            self.outcomes.append((time.monotonic(), outcome))

    config = replace(BridgeConfig.preset("garbage"), watchdog_seconds=1.0, goto_timeout=120.0)
    body = RobotBody(Ros2Link(config, domain), config).start()
    mind = Goer()
    runner = BridgeRunner(body, mind)
    first = sim("0.5")  # the first goal takes about half a minute
    worker = threading.Thread(target=runner.run, kwargs={"duration": 90.0}, daemon=True)
    second = None
    try:
        worker.start()
        assert wait_until(lambda: body.scans > 0, 30)
        time.sleep(2.0)  # the goal is under way
        assert not mind.outcomes
        first.kill()
        killed = time.monotonic()
        assert wait_until(lambda: bool(mind.outcomes), 10)
        at, outcome = mind.outcomes[0]
        # the goal's own watchdog or the body's scan watchdog, whichever fires first
        assert outcome.status is Status.CANCELLED, outcome
        assert "no percepts" in outcome.reason or "no scan" in outcome.reason, outcome.reason
        assert at - killed <= 1.0 + 1.5
        assert body.halted is not None
        second = sim("50")
        assert wait_until(lambda: any(o.ok for _t, o in mind.outcomes), 60), mind.outcomes
        assert any("percepts are back" in e for _t, e in runner.events)
        assert worker.is_alive()  # never crashed
    finally:
        runner.stop()
        worker.join(timeout=10)
        body.close()
        for proc in (first, second):
            if proc is not None and proc.poll() is None:
                proc.kill()
                proc.wait(timeout=10)
