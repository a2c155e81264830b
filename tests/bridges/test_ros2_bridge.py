"""`robocog bridge ros2` against a stand-in robot process, over DDS on 127.0.0.1."""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable
from typing import Any

import pytest

from tests.bridges.procs import Child, bridge_argv

#: every test here starts a robot and a bridge as processes and waits on them over DDS
pytestmark = pytest.mark.slow

WATCHDOG = 1.0
#: scheduling slack on a loaded two-core machine, on top of the watchdog time
SLACK = 1.5
REFLEX = "tests.bridges.reflex:make"


def standin(domain: int, scene: dict[str, Any] | None = None) -> list[str]:
    return [
        sys.executable,
        "-m",
        "robocog.testing.ros2_standin",
        "--domain",
        str(domain),
        "--scene",
        json.dumps(scene or {}),
    ]


def bridge(domain: int, mind: str = REFLEX, *extra: str) -> list[str]:
    return bridge_argv(
        "ros2",
        "--mind",
        mind,
        "--loopback",
        "--domain",
        str(domain),
        "--watchdog",
        str(WATCHDOG),
        "--place",
        "bin=2.0,1.0,1.5",
        "-v",
        *extra,
    )


def is_turn(event: dict[str, Any]) -> bool:
    return event["event"] == "cmd_vel" and event["angular"] != 0.0


def start_robot(
    spawn: Callable[..., Child], domain: int, env: dict[str, str], scene: dict[str, Any]
) -> Child:
    robot = spawn(standin(domain, scene), env, "standin")
    assert robot.wait_event(lambda e: e["event"] == "ready", 30), robot.stderr_text()
    return robot


def test_an_obstacle_on_the_left_turns_the_robot_right_and_a_bottle_is_picked(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]]
) -> None:
    domain, env = dds
    robot = start_robot(spawn, domain, env, {"obstacle": [0.9, 1.0]})
    run = spawn(bridge(domain), env, "bridge")
    turn = robot.wait_event(is_turn, 30)
    assert turn is not None, run.stderr_text()[-3000:]
    assert turn["angular"] < 0  # away from the obstacle on the left: clockwise

    mark = len(robot.events)
    robot.send({"obstacle": [-0.9, 1.0]})
    left = robot.wait_event(lambda e: is_turn(e) and e["angular"] > 0, 15, since=mark)
    assert left is not None, "an obstacle on the right should turn the robot left"

    mark = len(robot.events)
    robot.send({"obstacle": None, "detections": [{"label": "bottle", "x": 300}]})
    pick = robot.wait_event(lambda e: e["event"] == "gripper", 15, since=mark)
    assert pick is not None, run.stderr_text()[-3000:]
    assert pick["text"] == "pick bottle"
    # the stand-in's gripper now reports the bottle, so the bridge reports the pick done
    assert run.wait_for(lambda: "Pick(target='bottle') -> succeeded" in "".join(run.errors), 10)


def test_narsese_text_reaches_the_mind_and_goals_go_to_navigate_to_pose_and_cancel(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]]
) -> None:
    domain, env = dds
    robot = start_robot(spawn, domain, env, {})
    run = spawn(bridge(domain), env, "bridge")
    assert run.wait_for(lambda: "bridge ros2 up" in "".join(run.errors), 30)
    time.sleep(1.0)  # discovery between the two processes
    goal = None
    for _ in range(5):  # a /narsese line published before discovery completes is lost
        robot.send({"narsese": "goto bin"})
        goal = robot.wait_event(lambda e: e["event"] == "goal", 3)
        if goal:
            break
    assert goal is not None, run.stderr_text()[-3000:]
    assert goal["frame"] == "map"
    assert (goal["x"], goal["y"]) == (2.0, 1.0)
    assert goal["yaw"] == pytest.approx(1.5)

    mark = len(robot.events)
    robot.send({"narsese": "cancel"})
    cancel = robot.wait_event(lambda e: e["event"] == "cancel", 10, since=mark)
    assert cancel is not None and cancel["all"]


def test_losing_the_robot_stops_it_within_the_watchdog_time_and_the_bridge_resumes(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]]
) -> None:
    domain, env = dds
    # the observer only listens (it publishes nothing), so it outlives the robot
    observer = start_robot(spawn, domain, env, {"alive": False})
    robot = start_robot(spawn, domain, env, {"obstacle": [0.9, 1.0]})
    run = spawn(bridge(domain), env, "bridge")
    assert observer.wait_event(is_turn, 30), run.stderr_text()[-3000:]

    mark = len(observer.events)
    robot.kill()
    lost_at = time.time()
    cancel = observer.wait_event(lambda e: e["event"] == "cancel", WATCHDOG + 10, since=mark)
    assert cancel is not None, run.stderr_text()[-3000:]
    assert cancel["t"] - lost_at <= WATCHDOG + SLACK
    # the zero velocity and the cancel travel on different topics, which DDS may deliver
    # in either order: the robot is stopped when a zero velocity came in time and no
    # other velocity came after it (one writer's samples keep their order)
    time.sleep(0.3)
    moves = [e for e in observer.events[mark:] if e["event"] == "cmd_vel"]
    stops = [e for e in moves if (e["linear"], e["angular"]) == (0.0, 0.0) and e["t"] >= lost_at]
    assert stops and stops[0]["t"] - lost_at <= WATCHDOG + SLACK
    assert (moves[-1]["linear"], moves[-1]["angular"]) == (0.0, 0.0)
    # "no percepts for 1 s", or the scan's own limit when it ran out first ("no scan ...")
    assert run.wait_for(lambda: "watchdog: robot stopped: no " in "".join(run.errors), 5)
    time.sleep(WATCHDOG)
    settled = cancel["t"] + 0.3
    moving = [e for e in observer.events if is_turn(e) and e["t"] > settled]
    assert moving == [], "the robot must stay stopped while it is gone"

    mark = len(observer.events)
    start_robot(spawn, domain, env, {"obstacle": [0.9, 1.0]})
    again = observer.wait_event(is_turn, 30, since=mark)
    assert again is not None and again["angular"] < 0
    assert run.wait_for(lambda: "percepts are back; resuming" in "".join(run.errors), 5)


def _mind_turns_away_then_picks(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]], *mind: str
) -> None:
    """The bridge running *mind* turns from an obstacle, then picks up a bottle it sees."""
    domain, env = dds
    robot = start_robot(spawn, domain, env, {"obstacle": [0.9, 1.0]})
    run = spawn(bridge(domain, *mind), env, "bridge")
    turn = robot.wait_event(is_turn, 60)
    assert turn is not None, run.stderr_text()[-3000:]
    assert turn["angular"] < 0
    mark = len(robot.events)
    robot.send({"obstacle": None, "detections": [{"label": "bottle", "x": 320}]})
    pick = robot.wait_event(lambda e: e["event"] == "gripper", 60, since=mark)
    assert pick is not None and pick["text"].startswith("pick"), run.stderr_text()[-3000:]


def test_the_nars_mind_drives_the_robot(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]], nars_knowledge: str
) -> None:
    _mind_turns_away_then_picks(spawn, dds, "nars", "--knowledge", nars_knowledge)


def test_the_bdi_mind_drives_the_robot(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]], bdi_program: str
) -> None:
    _mind_turns_away_then_picks(spawn, dds, "bdi", "--program", bdi_program)


def test_the_bridge_ends_when_its_robot_ends_the_mission(
    spawn: Callable[..., Child], dds: tuple[int, dict[str, str]]
) -> None:
    domain, env = dds
    robot = start_robot(spawn, domain, env, {"obstacle": [0.9, 1.0]})
    run = spawn(bridge(domain, REFLEX, "--duration", "120"), env, "bridge")
    assert robot.wait_event(is_turn, 60), run.stderr_text()[-3000:]
    robot.send({"mission": "running"})  # any other state: the bridge goes on
    time.sleep(0.5)
    assert run.proc.poll() is None
    robot.send({"mission": "ended: all bins emptied"})
    assert run.wait_for(lambda: run.proc.poll() is not None, 20), run.stderr_text()[-3000:]
    assert run.proc.returncode == 0
    err = run.stderr_text()
    assert "the robot ended its mission (all bins emptied)" in err
    tail = err.split("the robot ended its mission: all bins emptied")[-1]
    assert "watchdog" not in tail
