"""Commands become velocity, goals and gripper requests; percepts come from readings."""

from __future__ import annotations

import logging
import math
import threading
import time
from dataclasses import replace

import pytest

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


def test_goto_sends_the_places_coordinates_and_ends_with_the_navigators_result() -> None:
    body, link = body_with(replace(FAST, goto_timeout=5.0))
    link.goal_status = "succeeded"
    assert body.execute(GoTo("bin")).ok
    assert link.of("goal") == [(2.0, 1.0, 0.5, 1)]


@pytest.mark.parametrize(
    ("status", "expected"),
    [("aborted", Status.FAILED), ("canceled", Status.CANCELLED), ("rejected", Status.FAILED)],
)
def test_a_goal_that_does_not_arrive_is_no_success(status: str, expected: Status) -> None:
    body, link = body_with(replace(FAST, goto_timeout=5.0))
    link.goal_status = status
    outcome = body.execute(GoTo("bin"))
    assert outcome.status is expected and status in outcome.reason


def test_goto_never_succeeds_before_the_result_even_when_the_pose_is_there() -> None:
    body, link = body_with(replace(FAST, goto_timeout=0.3))
    body.on_pose(PoseReading(2.0, 1.0, 0.0))  # already there, by the pose
    started = time.monotonic()
    outcome = body.execute(GoTo("bin"))
    assert outcome.status is Status.FAILED and "no navigation result" in outcome.reason
    assert time.monotonic() - started >= 0.3
    assert link.of("cancel")  # the goal is cancelled on the time-out


def test_an_unknown_place_fails_and_is_warned_once_with_the_known_names(
    caplog: pytest.LogCaptureFixture,
) -> None:
    body, link = body_with()
    with caplog.at_level(logging.WARNING, logger="robocog.bridges"):
        for _ in range(3):
            outcome = body.execute(GoTo("moon"))
            assert outcome.status is Status.FAILED and "moon" in outcome.reason
    warnings = [r.getMessage() for r in caplog.records if "moon" in r.getMessage()]
    assert len(warnings) == 1 and "bin" in warnings[0]
    assert link.of("goal") == []


ROUTE = BridgeConfig(
    places={"a": (1.0, 0.0, 0.0), "b": (2.0, 0.0, 0.0), "c": (3.0, 0.0, 0.0)},
    route=("a", "b", "c"),
    start=(0.0, 0.0, 0.0),
    goto_timeout=5.0,
)


def test_next_follows_the_route_and_ends_at_the_start() -> None:
    body, link = body_with(ROUTE)
    link.goal_status = "succeeded"
    for _ in range(5):
        assert body.execute(GoTo("next")).ok
    xs = [goal[0] for goal in link.of("goal")]
    assert xs == [1.0, 2.0, 3.0, 0.0, 1.0]  # a, b, c, the start, and round again


def test_start_is_the_configured_start_else_the_routes_first_place() -> None:
    body, link = body_with(ROUTE)
    link.goal_status = "succeeded"
    assert body.execute(GoTo("start")).ok
    assert link.of("goal")[-1][:2] == (0.0, 0.0)
    body, link = body_with(replace(ROUTE, start=None))
    link.goal_status = "succeeded"
    assert body.execute(GoTo("start")).ok
    assert link.of("goal")[-1][:2] == (1.0, 0.0)
    for _ in range(3):
        body.execute(GoTo("next"))
    assert [g[0] for g in link.of("goal")][1:] == [2.0, 3.0, 1.0]  # wraps to the first


def test_a_failed_goal_does_not_advance_the_route_but_the_pose_does() -> None:
    body, link = body_with(replace(ROUTE, place_radius=0.3))
    link.goal_status = "aborted"
    assert not body.execute(GoTo("next")).ok
    link.goal_status = "succeeded"
    assert body.execute(GoTo("next")).ok
    assert [g[0] for g in link.of("goal")] == [1.0, 1.0]
    body.on_pose(PoseReading(3.0, 0.1, 0.0))  # driven to c by hand
    body.percepts()
    assert body.execute(GoTo("next")).ok
    assert link.of("goal")[-1][:2] == (0.0, 0.0)  # after c: the start


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


def test_a_lock_step_frame_waits_for_the_detections_its_scan_overtook() -> None:
    # DDS may deliver a frame's best-effort scan before its reliable detections: the
    # decision must wait for the detections stamped with the scan's time
    body, _link = body_with(replace(FAST, lockstep=True))
    scan = ScanReading(-math.pi, math.pi / 180, 0.05, 12.0, [5.0] * 360)
    body.on_boxes([], stamp=1.0)
    body.on_scan(scan, stamp=1.0)
    assert body.wait_for_frame(0, 1.0) == (1, 1.0)
    body.on_scan(scan, stamp=2.0)  # the scan of frame 2 first

    def late_detections() -> None:
        time.sleep(0.2)
        body.on_boxes([BoxReading("cup", 0.9, 320.0, (1.0, 0.0, 0.0))], stamp=2.0)

    threading.Thread(target=late_detections).start()
    frames, stamp = body.wait_for_frame(1, 1.0)
    assert (frames, stamp) == (2, 2.0)
    assert any(isinstance(p, Detection) and p.label == "cup" for p in body.percepts())


def test_a_robot_that_does_not_stamp_its_detections_is_not_waited_for() -> None:
    body, _link = body_with(replace(FAST, lockstep=True))
    scan = ScanReading(-math.pi, math.pi / 180, 0.05, 12.0, [5.0] * 360)
    body.on_boxes([])
    body.on_scan(scan, stamp=3.0)
    start = time.monotonic()
    assert body.wait_for_frame(0, 1.0) == (1, 3.0)
    assert time.monotonic() - start < 0.5
