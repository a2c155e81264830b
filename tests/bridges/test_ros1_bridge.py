"""`robocog bridge ros1` against a stand-in robot and a stand-in move_base, with
ROS master on 127.0.0.1 started by the test."""

from __future__ import annotations

import re
import subprocess
import sys
import time
from collections.abc import Callable
from typing import Any

import pytest

from tests.bridges.procs import SRC, SYSTEM_PYTHON, Child, bridge_argv

#: every test here starts a stand-in robot and a bridge as processes on a ROS master and
#: waits on them
pytestmark = pytest.mark.slow

WATCHDOG = 1.0
#: scheduling slack on a loaded two-core machine, on top of the watchdog time
SLACK = 1.5
REFLEX = "tests.bridges.reflex:make"


def start_robot(
    spawn: Callable[..., Child],
    env: dict[str, str],
    goal_seconds: float = 1.0,
    *extra: str,
) -> Child:
    argv = [
        SYSTEM_PYTHON,
        str(SRC.parent / "testing" / "ros1_standin.py"),
        "--goal-seconds",
        str(goal_seconds),
        *extra,
    ]
    robot_env = {k: v for k, v in env.items() if k != "PYTHONPATH"}
    robot = spawn(argv, robot_env, "standin")
    assert robot.wait_event(lambda e: e["event"] == "ready", 30), robot.stderr_text()
    return robot


def bridge(mind: str = REFLEX, *extra: str) -> list[str]:
    return bridge_argv(
        "ros1",
        "--mind",
        mind,
        "--watchdog",
        str(WATCHDOG),
        "--place",
        "bin=2.0,1.0",
        "--config",
        str(SRC.parents[2] / "tests" / "bridges" / "data" / "ros1.toml"),
        "-v",
        *extra,
    )


def is_turn(event: dict[str, Any]) -> bool:
    return event["event"] == "cmd_vel" and event["angular"] != 0.0


def logged(run: Child, text: str, timeout: float = 10.0) -> bool:
    return run.wait_for(lambda: text in "".join(run.errors), timeout)


def test_ros1_obstacle_left_turns_right_and_a_bottle_is_picked(
    spawn: Callable[..., Child], roscore: dict[str, str]
) -> None:
    robot = start_robot(spawn, roscore)
    robot.send({"obstacle": [0.9, 1.0]})
    run = spawn(bridge(), roscore, "bridge")
    turn = robot.wait_event(is_turn, 40)
    assert turn is not None, run.stderr_text()[-3000:]
    assert turn["angular"] < 0

    mark = len(robot.events)
    robot.send({"obstacle": None, "detections": [{"label": "bottle", "x": 300}]})
    pick = robot.wait_event(lambda e: e["event"] == "gripper", 15, since=mark)
    assert pick is not None, run.stderr_text()[-3000:]
    assert pick["text"] == "pick bottle"
    assert logged(run, "Pick(target='bottle') -> succeeded")


def test_ros1_goals_go_through_move_base_and_can_be_cancelled(
    spawn: Callable[..., Child], roscore: dict[str, str]
) -> None:
    robot = start_robot(spawn, roscore, goal_seconds=0.5)
    run = spawn(bridge(REFLEX, "--goto-timeout", "10"), roscore, "bridge")
    assert logged(run, "bridge ros1 up", 40), run.stderr_text()[-3000:]
    goal = None
    for _ in range(5):  # a /narsese line sent before the subscription connects is lost
        robot.send({"narsese": "goto bin"})
        goal = robot.wait_event(lambda e: e["event"] == "goal", 4)
        if goal:
            break
    assert goal is not None, run.stderr_text()[-3000:]
    assert (goal["frame"], goal["x"], goal["y"]) == ("map", 2.0, 1.0)
    assert logged(run, "GoTo(place='bin') -> succeeded")

    # a base that stalls: no result within the time-out, so the goal is cancelled and
    # the GoTo fails; it never counts as arrived
    robot.send({"goal_seconds": 30})
    run.stop()
    run = spawn(bridge(REFLEX, "--goto-timeout", "1"), roscore, "bridge")
    assert logged(run, "bridge ros1 up", 40)
    mark = len(robot.events)
    for _ in range(5):
        robot.send({"narsese": "goto bin"})
        if robot.wait_event(lambda e: e["event"] == "goal", 4, since=mark):
            break
    cancel = robot.wait_event(lambda e: e["event"] == "cancel", 15, since=mark)
    assert cancel is not None, run.stderr_text()[-3000:]
    assert logged(run, "GoTo(place='bin') -> failed no navigation result for bin within 1 s")


def test_ros1_losing_the_robot_stops_it_and_the_bridge_resumes(
    spawn: Callable[..., Child], roscore: dict[str, str]
) -> None:
    robot = start_robot(spawn, roscore)
    robot.send({"obstacle": [0.9, 1.0]})
    run = spawn(bridge(), roscore, "bridge")
    assert robot.wait_event(is_turn, 40), run.stderr_text()[-3000:]

    mark = len(robot.events)
    robot.send({"alive": False})  # the sensors fall silent; the robot still listens
    lost_at = time.time()
    stop = robot.wait_event(lambda e: e["event"] == "cancel_request", WATCHDOG + 10, since=mark)
    assert stop is not None, run.stderr_text()[-3000:]
    assert stop["t"] - lost_at <= WATCHDOG + SLACK
    assert stop["all"]
    assert logged(run, "watchdog: robot stopped: no ")  # percepts, or a sensor's own limit
    zero = [e for e in robot.events[mark:] if e["event"] == "cmd_vel" and not is_turn(e)]
    assert zero, "the watchdog sends zero velocity"
    time.sleep(WATCHDOG)
    assert [e for e in robot.events if is_turn(e) and e["t"] > stop["t"] + 0.3] == []

    mark = len(robot.events)
    robot.send({"alive": True})
    again = robot.wait_event(is_turn, 30, since=mark)
    assert again is not None and again["angular"] < 0
    assert logged(run, "percepts are back; resuming")


def test_ros1_killing_the_robot_stops_it_and_a_new_robot_is_driven(
    spawn: Callable[..., Child], roscore: dict[str, str]
) -> None:
    observer = start_robot(spawn, roscore, 1.0, "--listen-only")
    robot = start_robot(spawn, roscore)
    robot.send({"obstacle": [0.9, 1.0]})
    run = spawn(bridge(), roscore, "bridge")
    assert observer.wait_event(is_turn, 40), run.stderr_text()[-3000:]

    mark = len(observer.events)
    robot.kill()
    lost_at = time.time()
    stop = observer.wait_event(lambda e: e["event"] == "cancel_request", WATCHDOG + 10, since=mark)
    assert stop is not None, run.stderr_text()[-3000:]
    assert stop["t"] - lost_at <= WATCHDOG + SLACK
    assert logged(run, "watchdog: robot stopped: no ")  # percepts, or a sensor's own limit
    time.sleep(WATCHDOG)
    assert [e for e in observer.events if is_turn(e) and e["t"] > stop["t"] + 0.3] == []

    mark = len(observer.events)
    again = start_robot(spawn, roscore)
    again.send({"obstacle": [0.9, 1.0]})
    turn = observer.wait_event(is_turn, 40, since=mark)
    assert turn is not None and turn["angular"] < 0, run.stderr_text()[-3000:]
    assert logged(run, "percepts are back; resuming")


def _mind_turns_away_then_picks(
    spawn: Callable[..., Child], roscore: dict[str, str], *mind: str
) -> None:
    """The bridge running *mind* turns from an obstacle, then picks up a bottle it sees."""
    robot = start_robot(spawn, roscore)
    robot.send({"obstacle": [0.9, 1.0]})
    run = spawn(bridge(*mind), roscore, "bridge")
    turn = robot.wait_event(is_turn, 60)
    assert turn is not None and turn["angular"] < 0, run.stderr_text()[-3000:]
    mark = len(robot.events)
    robot.send({"obstacle": None, "detections": [{"label": "bottle", "x": 320}]})
    pick = robot.wait_event(lambda e: e["event"] == "gripper", 60, since=mark)
    assert pick is not None and pick["text"].startswith("pick"), run.stderr_text()[-3000:]


def test_ros1_the_nars_mind_drives_the_robot(
    spawn: Callable[..., Child], roscore: dict[str, str], nars_knowledge: str
) -> None:
    _mind_turns_away_then_picks(spawn, roscore, "nars", "--knowledge", nars_knowledge)


def test_ros1_the_bdi_mind_drives_the_robot(
    spawn: Callable[..., Child], roscore: dict[str, str], bdi_program: str
) -> None:
    _mind_turns_away_then_picks(spawn, roscore, "bdi", "--program", bdi_program)


@pytest.mark.parametrize("mind", ["nars", "bdi"])
def test_ros1_the_garbage_field_served_by_the_sim_is_cleaned_through_move_base(
    roscore: dict[str, str], mind: str
) -> None:
    """``robocog sim garbage --ros1`` (a rospy node serving move_base through actionlib)
    and ``robocog bridge ros1`` with a shipped mind: trash is collected over a real
    roscore, and the GoTos are move_base goals that succeed."""
    sim = subprocess.Popen(
        [sys.executable, "-m", "robocog.cli", "sim", "garbage", "--ros1", "--seed", "3"]
        # ten times real time, a frame every 40 ms: at 25 times (every 16 ms) the NARS
        # mind, 20-30 ms per frame at p99, fell behind the field now and then, and about
        # one mission in four collected nothing
        + ["--rate", "10"],
        env=roscore,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    run = subprocess.Popen(
        bridge_argv("ros1", "--mind", mind, "--duration", "110", "-v"),
        env=roscore,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    bridge_err = ""
    try:
        out, err = sim.communicate(timeout=120)  # the sim ends with the field's mission
        # and the bridge with it, told so on /mission/state (its --duration is far off)
        _, bridge_err = run.communicate(timeout=30)
    finally:
        if run.poll() is None:
            run.terminate()
            _, bridge_err = run.communicate(timeout=30)
        if sim.poll() is None:
            sim.kill()
    assert sim.returncode == 0, err[-2000:]
    assert run.returncode == 0, bridge_err[-3000:]
    assert "the robot ended its mission (battery spent" in bridge_err or (
        "the robot ended its mission (route complete" in bridge_err
    ), bridge_err[-3000:]
    collected = int(out.split("collected ")[1].split(" of ")[0])
    assert collected >= 1, out + bridge_err[-3000:]
    assert re.search(r"GoTo\(place='\w+'\) -> succeeded", bridge_err), bridge_err[-3000:]
    assert "unknown place" not in bridge_err
