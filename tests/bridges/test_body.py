"""Commands become velocity, goals and gripper requests; percepts come from readings."""

from __future__ import annotations

import math
import threading
import time

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import BoxReading, PoseReading, ScanReading
from robocog.robot import (
    Body,
    Cancel,
    Detection,
    Drop,
    Forward,
    GoTo,
    Gripper,
    Look,
    Obstacle,
    Pick,
    Pose,
    Stack,
    Status,
    Turn,
)
from tests.bridges.fakes import FakeLink

FAST = BridgeConfig(
    linear_speed=1.0,
    angular_speed=1.0,
    command_rate=50.0,
    gripper_timeout=0.3,
    places={"bin": (2.0, 1.0, 0.5)},
)


def body_with(config: BridgeConfig = FAST) -> tuple[RobotBody, FakeLink]:
    link = FakeLink()
    return RobotBody(link, config).start(), link


def test_it_is_a_body() -> None:
    body, _link = body_with()
    assert isinstance(body, Body)


def test_turn_publishes_the_signed_rate_for_the_right_time_then_zero() -> None:
    body, link = body_with()
    start = time.monotonic()
    outcome = body.execute(Turn(-0.2))
    took = time.monotonic() - start
    assert outcome.ok
    twists = link.of("twist")
    assert twists[0] == (0.0, -1.0)
    assert twists[-1] == (0.0, 0.0)
    assert 0.18 <= took < 1.0


def test_forward_drives_straight_and_backwards_when_negative() -> None:
    body, link = body_with()
    assert body.execute(Forward(-0.05)).ok
    assert link.of("twist")[0] == (-1.0, 0.0)


def test_a_zero_move_sends_no_velocity() -> None:
    body, link = body_with()
    assert body.execute(Forward(0.0)).ok and body.execute(Turn(0.0)).ok
    assert link.of("twist") == []


def test_a_long_move_is_cut_at_the_limit() -> None:
    body, _link = body_with(BridgeConfig(linear_speed=1.0, max_motion_seconds=0.1))
    start = time.monotonic()
    assert body.execute(Forward(100.0)).ok
    assert time.monotonic() - start < 1.0


def test_a_halt_cancels_a_motion_under_way_and_refuses_new_ones() -> None:
    body, link = body_with(BridgeConfig(angular_speed=0.5))
    timer = threading.Timer(0.2, body.halt, args=("test",))
    timer.start()
    outcome = body.execute(Turn(2.0))  # four seconds, cut short
    timer.join()
    assert outcome.status is Status.CANCELLED
    assert "test" in outcome.reason
    assert link.of("twist")[-1] == (0.0, 0.0)
    assert link.of("cancel")
    assert body.execute(Forward(1.0)).status is Status.CANCELLED
    assert body.execute(Cancel()).ok
    body.resume()
    assert body.execute(Forward(0.01)).ok


def test_goto_sends_the_places_coordinates() -> None:
    body, link = body_with()
    assert body.execute(GoTo("bin")).ok
    assert link.of("goal") == [(2.0, 1.0, 0.5, 1)]
    unknown = body.execute(GoTo("moon"))
    assert unknown.status is Status.FAILED and "moon" in unknown.reason


def test_goto_waits_for_the_goal_result_when_asked() -> None:
    config = BridgeConfig(places={"bin": (2.0, 1.0, 0.0)}, goto_wait=2.0)
    body, _link = body_with(config)
    threading.Timer(0.1, body.on_goal_result, args=(1, "aborted")).start()
    outcome = body.execute(GoTo("bin"))
    assert outcome.status is Status.FAILED and "aborted" in outcome.reason
    threading.Timer(0.1, body.on_pose, args=(PoseReading(2.1, 1.0, 0.0),)).start()
    assert body.execute(GoTo("bin")).ok  # arrival seen in the pose


def test_goto_gives_up_and_cancels_after_the_wait() -> None:
    config = BridgeConfig(places={"bin": (2.0, 1.0, 0.0)}, goto_wait=0.2)
    body, link = body_with(config)
    outcome = body.execute(GoTo("bin"))
    assert outcome.status is Status.FAILED
    assert link.of("cancel")


def test_pick_succeeds_when_the_gripper_reports_a_hold() -> None:
    body, link = body_with()
    link.on_gripper_request = "bottle"
    assert body.execute(Pick("bottle")).ok
    assert link.of("gripper") == [("pick bottle",)]
    link.on_gripper_request = "open"
    assert body.execute(Drop()).ok


def test_pick_fails_when_the_gripper_stays_empty() -> None:
    body, _link = body_with()
    outcome = body.execute(Pick("cup"))
    assert outcome.status is Status.FAILED and "pick cup" in outcome.reason


def test_commands_it_cannot_carry_out_fail_with_a_reason() -> None:
    body, _link = body_with()
    assert body.execute(Look("left")).status is Status.FAILED
    assert "manipulator" in body.execute(Stack("a", "b")).reason


def test_percepts_come_from_the_latest_readings() -> None:
    body, _link = body_with()
    assert body.percepts() == [Gripper(None)]
    assert math.isinf(body.percept_age())
    body.on_scan(ScanReading(0.8, 0.0, 0.1, 10.0, [1.0]))
    body.on_boxes([BoxReading("bottle", 0.9, 320.0)])
    body.on_pose(PoseReading(2.0, 1.0, 0.25))
    body.on_gripper("cup")
    percepts = body.percepts()
    assert Obstacle("left", 1.0) in percepts
    assert Pose(2.0, 1.0, 0.25, "bin") in percepts
    assert Gripper("cup") in percepts
    [seen] = [p for p in percepts if isinstance(p, Detection)]
    assert seen.label == "bottle" and abs(seen.bearing) < 1e-9
    assert body.percept_age() < 1.0


def test_detections_expire() -> None:
    body, _link = body_with(BridgeConfig(detection_ttl=0.05))
    body.on_boxes([BoxReading("bottle", 0.9, 320.0)])
    time.sleep(0.1)
    assert not [p for p in body.percepts() if isinstance(p, Detection)]


def test_text_lines_are_kept_until_read() -> None:
    body, _link = body_with()
    body.on_text("<a --> b>.\n\n<b --> c>.")
    assert body.texts() == ["<a --> b>.", "<b --> c>."]
    assert body.texts() == []


def test_close_stops_the_robot_and_the_link() -> None:
    body, link = body_with()
    body.close()
    assert link.of("twist")[-1] == (0.0, 0.0) and link.closed
