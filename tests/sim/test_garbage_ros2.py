"""The garbage field as a ROS 2 robot: its messages, its actions, and whole missions with
the mind in another process, over DDS on 127.0.0.1."""

from __future__ import annotations

import math
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("cyclonedds", reason="the ROS 2 sim needs the ros2 extra (cyclonedds)")

from robocog.bridges.body import RobotBody  # noqa: E402
from robocog.bridges.config import BridgeConfig  # noqa: E402
from robocog.bridges.ros2.link import Ros2Link  # noqa: E402
from robocog.bridges.ros2.loopback import LOOPBACK_URI, use_loopback  # noqa: E402
from robocog.robot import Detection, Drop, GoTo, Gripper, Obstacle, Pick, Pose, Status  # noqa: E402
from robocog.sim.field import column_of, fence_ranges  # noqa: E402
from robocog.sim.ros2 import GarbageRobot  # noqa: E402
from robocog.worlds.garbage import GarbageConfig, GarbageField  # noqa: E402
from tests.bridges.conftest import random_domain  # noqa: E402
from tests.bridges.procs import Child, child_env, wait_until  # noqa: E402


def test_the_scan_is_cast_against_the_fence() -> None:
    # at (1, 5) facing +x in a 10 m square: behind (-pi) the fence is 1 m off, to the
    # left (+pi/2, beam 270 of 360) 5 m, ahead 9 m
    ranges = fence_ranges(1.0, 5.0, 0.0, 10.0)
    assert ranges[0] == pytest.approx(1.0)
    assert ranges[180] == pytest.approx(9.0)
    assert ranges[270] == pytest.approx(5.0)
    assert min(ranges) == pytest.approx(1.0)


def test_a_columns_bearing_is_the_bridges_bearing() -> None:
    from robocog.bridges.perception import bearing_of

    for bearing in (-0.5, -0.1, 0.0, 0.2, 0.52):
        column = column_of(bearing, math.radians(60))
        assert bearing_of(column, 640, math.radians(60)) == pytest.approx(bearing, abs=1e-12)


@pytest.fixture
def served() -> Iterator[tuple[RobotBody, GarbageRobot, GarbageField]]:
    """The field served in real time (fast), and a bridge body on it, in this process."""
    use_loopback()
    domain = random_domain()
    world = GarbageField(GarbageConfig(), seed=3)
    robot = GarbageRobot(world, domain, rate=50.0)
    thread = threading.Thread(target=robot.run, daemon=True)
    thread.start()
    config = BridgeConfig.preset("garbage")
    body = RobotBody(Ros2Link(config, domain), config).start()
    try:
        yield body, robot, world
    finally:
        body.close()
        robot.close()
        thread.join(timeout=5)


def test_the_field_reaches_a_bridge_as_percepts_and_takes_goals_and_grasps(
    served: tuple[RobotBody, GarbageRobot, GarbageField],
) -> None:
    body, robot, world = served
    assert wait_until(lambda: body.percept_age() < 1.0, 20)
    seen: list[Any] = []
    assert wait_until(lambda: bool(seen.extend(body.percepts()) or True) and _has_pose(seen), 10)
    assert any(isinstance(p, Obstacle) for p in seen)
    assert Gripper(None) in seen
    start = next(p for p in seen if isinstance(p, Pose))
    assert (start.x, start.y) == pytest.approx(world.start)
    # the first checkpoint, then a grasp: the field's own outcomes come back
    outcome = body.execute(GoTo("next"))
    assert outcome.ok, outcome
    assert world.last_checkpoint == 0 and robot.goals == 1
    assert wait_until(lambda: any(isinstance(p, Detection) for p in body.percepts()), 10)
    picked = body.execute(Pick("trash"))
    assert picked.ok == (world.holding is not None)
    if picked.ok:
        assert body.execute(Drop()).ok
        assert world.collected() == 1


def _has_pose(percepts: list[Any]) -> bool:
    return any(isinstance(p, Pose) for p in percepts)


def test_a_stalled_base_makes_goto_fail_after_its_time_out() -> None:
    use_loopback()
    domain = random_domain()
    world = GarbageField(GarbageConfig(), seed=1)
    robot = GarbageRobot(world, domain, rate=50.0, stall=True)
    thread = threading.Thread(target=robot.run, daemon=True)
    thread.start()
    config = BridgeConfig.preset("garbage")
    from dataclasses import replace

    config = replace(config, goto_timeout=1.0)
    body = RobotBody(Ros2Link(config, domain), config).start()
    try:
        assert wait_until(lambda: body.percept_age() < 1.0, 20)
        started = time.monotonic()
        outcome = body.execute(GoTo("p0"))
        assert outcome.status is Status.FAILED and "no navigation result" in outcome.reason
        assert time.monotonic() - started >= 1.0
        assert world.last_checkpoint == -1  # never there
    finally:
        body.close()
        robot.close()
        thread.join(timeout=5)


# -- whole missions: the sim in this process, the bridge (the mind) in another ----------------


@pytest.mark.slow
@pytest.mark.parametrize("mind", ["nars", "bdi"])
def test_a_mission_over_ros2_collects_what_the_same_mission_collects_in_process(
    mind: str,
) -> None:
    from robocog.experiments.garbage import default_minds, run_once
    from robocog.experiments.over_ros2 import run_mission

    [spec] = default_minds([mind])
    why = spec.probe()
    if why:
        pytest.skip(why)
    use_loopback()
    config = GarbageConfig()
    local = run_once(spec, config, 3)
    remote = run_mission(mind, config, 3, domain=random_domain(), timeout=240)
    assert remote.error is None, remote.error
    assert remote.collected >= 1
    # lock-step over DDS: the same frames, the same decisions, the same field
    assert (remote.collected, remote.frames) == (local.collected, local.cycles)
    assert remote.sim_seconds == pytest.approx(local.sim_seconds)


@pytest.mark.slow
def test_the_two_commands_of_the_readme_collect_trash() -> None:
    """``robocog sim garbage --ros2 --loopback`` and ``robocog bridge ros2 --loopback``,
    each a process of its own, as a user starts them (fast: --rate 40).

    Both are stopped (SIGTERM) once the bridge has reached a checkpoint and dropped what
    it picked, a few tens of simulated seconds in, rather than at the end of the
    mission: the bridge first, while the sim still answers the goal it may be waiting
    on, then the sim, which reports what the field counted."""
    domain = str(random_domain())
    env = child_env({"CYCLONEDDS_URI": LOOPBACK_URI})
    base = [sys.executable, "-m", "robocog.cli"]
    sim = Child(
        [*base, "sim", "garbage", "--ros2", "--loopback", "--domain", domain, "--seed", "3"]
        + ["--rate", "40"],
        env,
        "sim",
    )
    bridge = Child(
        [*base, "bridge", "ros2", "--loopback", "--domain", domain, "--mind", "bdi", "-v"],
        env,
        "bridge",
    )
    try:

        def cleaned() -> bool:
            err = bridge.stderr_text()
            return "GoTo(place='next') -> succeeded" in err and "Drop() -> succeeded" in err

        wait_until(lambda: cleaned() or sim.proc.poll() is not None, 120)
    finally:
        # it stops in under a second on a quiet machine; on a loaded one a stop that
        # comes while it is still starting can take longer: what it wrote is enough
        bridge.stop(timeout=30)
        sim.stop(timeout=30)
    out, bridge_err = "".join(sim.lines), bridge.stderr_text()
    assert sim.proc.returncode == 0, sim.stderr_text()[-2000:]
    collected = int(out.split("collected ")[1].split(" of ")[0])
    assert collected >= 1, out + bridge_err[-3000:]
    assert "GoTo(place='next') -> succeeded" in bridge_err
    assert "unknown place" not in bridge_err


@pytest.mark.slow
def test_a_recorded_mission_replays_to_the_same_decisions(tmp_path: Path) -> None:
    """``robocog replay``: the recorded percepts, fed to a fresh mind of the same seed,
    give the decisions recorded in every frame."""
    pytest.importorskip("mcap", reason="recording needs the ros2 extra (mcap)")
    from robocog.bridges.replay import read_frames, replay
    from robocog.experiments.garbage import default_minds
    from robocog.experiments.over_ros2 import run_mission
    from robocog.minds.bdi_mind import BdiMind

    [spec] = default_minds(["bdi"])
    if spec.probe():
        pytest.skip(spec.probe() or "")
    use_loopback()
    path = tmp_path / "bdi-3.mcap"
    run = run_mission("bdi", GarbageConfig(), 3, domain=random_domain(), record=path, timeout=240)
    assert run.error is None, run.error
    config = BridgeConfig.preset("garbage")
    frames = read_frames(path, config)
    assert len(frames) == run.frames
    decided = replay(frames, config, BdiMind())
    recorded = [[type(c).__name__ for c in f.recorded] for f, _ in decided]
    replayed = [[type(c).__name__ for c in commands] for _, commands in decided]
    assert sum(map(len, recorded)) >= 5
    assert replayed == recorded
    result = subprocess.run(
        [sys.executable, "-m", "robocog.cli", "replay", str(path), "--mind", "bdi"],
        capture_output=True,
        text=True,
        env=child_env(),
        timeout=120,
    )
    assert result.returncode == 0, result.stderr
    assert "0 different" in result.stdout


def test_the_bridge_ends_when_the_sim_ends_its_mission() -> None:
    """The sim says ``ended: WHY`` on /mission/state when its mission is over (here
    after 40 frames), and a bridge on it ends its run with that reason."""
    from robocog.bridges.runner import BridgeRunner
    from tests.bridges.reflex import ReflexMind

    use_loopback()
    domain = random_domain()
    world = GarbageField(GarbageConfig(), seed=3)
    robot = GarbageRobot(world, domain, rate=50.0, max_frames=40)
    thread = threading.Thread(target=robot.run, daemon=True)
    thread.start()
    config = BridgeConfig.preset("garbage")
    body = RobotBody(Ros2Link(config, domain), config).start()
    runner = BridgeRunner(body, ReflexMind())  # type: ignore[arg-type]
    try:
        started = time.monotonic()
        assert runner.run(duration=60.0) == 0
        took = time.monotonic() - started
    finally:
        body.close()
        robot.close()
        thread.join(timeout=5)
    assert robot.ended is not None and "40 frames" in robot.ended
    assert runner.mission_ended == robot.ended
    assert took < 30.0
    # (a loaded machine may trip the watchdog before the first frame; never after the end)
    assert runner.events[-1][1].startswith("the robot ended its mission: 40 frames")
