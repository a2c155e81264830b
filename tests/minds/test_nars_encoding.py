"""The encodings of Hammer et al., Section IV: percepts to Narsese events, operations to Commands.

Each event the encodings build is the sentence the engine's reader makes of its text.
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from robocog.minds.nars_encoding import (
    OPERATIONS,
    atom,
    command_for,
    detection_events,
    direction,
    encode,
    goal_at,
    gripper_event,
    gripper_events,
    not_seen,
    obstacle_event,
    place_event,
    recall_questions,
    seen_as,
)
from robocog.nars import parse_sentence, parse_term
from robocog.robot import Detection, Drop, Forward, GoTo, Gripper, Obstacle, Pick, Pose, Turn

FOV = math.radians(60)


def read(*lines: str) -> list:
    """The sentences of Narsese lines, as the engine reads them."""
    return [parse_sentence(line) for line in lines]


def test_bearing_is_split_in_thirds_of_the_field_of_view() -> None:
    assert direction(math.radians(25), FOV) == "left"
    assert direction(math.radians(5), FOV) == "center"
    assert direction(math.radians(-5), FOV) == "center"
    assert direction(math.radians(-25), FOV) == "right"


@given(st.floats(min_value=-math.pi, max_value=math.pi))
def test_every_bearing_falls_in_exactly_one_third(bearing: float) -> None:
    third = direction(bearing, FOV)
    assert third in ("left", "center", "right")
    assert (third == "left") == (bearing > FOV / 6)
    assert (third == "right") == (bearing < -FOV / 6)


def test_a_detection_becomes_position_see_and_instance_events() -> None:
    d = Detection("bottle", math.radians(-20), 1.2, 0.8, "bottle3")
    assert detection_events(d, FOV) == read(
        "<bottle --> [right]>. :|:",
        "<bottle --> [see]>. :|:",
        "<{bottle3} --> [see]>. :|:",
    )
    assert detection_events(d, FOV, instances=False)[-1] == read("<bottle --> [see]>. :|:")[0]


def test_obstacle_place_and_gripper_events() -> None:
    assert [obstacle_event(Obstacle("front", 1.0)), obstacle_event(Obstacle("none", 2.0))] == read(
        "<obstacle --> [front]>. :|:", "<obstacle --> [free]>. :|:"
    )
    assert [place_event(Pose(1, 2, 0, "p3"))] == read("<({SELF} * {p3}) --> at>. :|:")
    assert place_event(Pose(1, 2, 0, None)) is None
    assert [
        gripper_event(Gripper("cup1")),
        gripper_event(Gripper(None)),
        gripper_event(False),
    ] == read(
        "<gripper --> [hold]>. :|:",
        "<gripper --> [open]>. :|:",
        "<gripper --> [open]>. :|:",
    )
    assert gripper_events(True) == read(
        "<gripper --> [hold]>. :|:",
        "<gripper --> [open]>. :|: {0.0 0.9}",
    )
    assert gripper_events(Gripper(None))[1] == read("<gripper --> [hold]>. :|: {0.0 0.9}")[0]
    assert [goal_at("p2")] == read("<({SELF} * {p2}) --> at>! :|:")


def test_a_frame_reports_the_most_confident_detections_first_and_at_most_three() -> None:
    frame = [
        Detection("cup", 0.0, 3.0, 0.4, "cup1"),
        Detection("bottle", 0.0, 1.0, 0.9, "bottle2"),
        Detection("cup", 0.0, 2.0, 0.5, "cup3"),
        Detection("cup", 0.0, 2.0, 0.6, "cup4"),
        Obstacle("none", 2.0),
        Gripper(None),
        Pose(0, 0, 0, "p1"),
    ]
    events = encode(frame, FOV)
    instances = [e for e in events if e.term.subject.op == "{}"]
    assert instances == read(
        "<{bottle2} --> [see]>. :|:",
        "<{cup4} --> [see]>. :|:",
        "<{cup3} --> [see]>. :|:",
    )
    assert events[0] == read("<({SELF} * {p1}) --> at>. :|:")[0]  # the place comes first
    assert events[-3:] == read(
        "<obstacle --> [free]>. :|:",
        "<gripper --> [open]>. :|:",
        "<gripper --> [hold]>. :|: {0.0 0.9}",
    )
    assert recall_questions(frame) == [s.term for s in read("<bottle --> ?1>?", "<cup --> ?1>?")]


def test_names_become_atoms() -> None:
    assert atom("water bottle") == "water_bottle"
    assert atom("7up") == "n7up"


def test_operations_map_to_commands() -> None:
    places = ["p0", "p1", "start"]
    assert OPERATIONS == ("^forward", "^left", "^right", "^goto", "^pick", "^drop")
    assert command_for("^forward", None) == Forward(0.5)
    assert isinstance(command_for("^left", None), Turn)
    assert command_for("^left", None).angle > 0  # type: ignore[union-attr]
    assert command_for("^right", None).angle < 0  # type: ignore[union-attr]
    goto, pick = "^goto", "^pick"
    assert command_for(goto, parse_term("({SELF} * (next * p1))"), places) == GoTo("p1")
    assert command_for(goto, parse_term("({SELF} * {start})"), places) == GoTo("start")
    assert command_for(goto, parse_term("({SELF} * next)"), places) == GoTo("next")
    assert command_for(pick, parse_term("({SELF} * {bottle3})"), places) == Pick("bottle3")
    assert command_for(pick, parse_term("({SELF} * ({SELF} * {cup2}))"), places) == Pick("cup2")
    assert command_for("^pick", None, places) == Pick("trash")
    assert command_for("^drop", None) == Drop()
    assert command_for("^say", None) is None


def test_a_sighting_is_reported_under_the_kind_the_reasoner_names() -> None:
    q = parse_term("<bottle --> ?1>")
    seen = seen_as(q, parse_term("<bottle --> trash>"), 1.0, 0.9)
    assert seen == parse_sentence("<trash --> [see]>. :|: {1.000000 0.810000}")
    # frequency and confidence to six decimal places, as the paper's channel reports them
    seen = seen_as(q, parse_term("<bottle --> trash>"), 0.7777777777, 0.9)
    assert seen == parse_sentence("<trash --> [see]>. :|: {0.777778 0.630000}")
    assert seen_as(q, parse_term("<bottle --> [left]>"), 1.0, 0.9) is None
    assert seen_as(q, parse_term("<cup --> trash>"), 1.0, 0.9) is None
    assert seen_as(q, parse_term("<bottle --> (trash & glass)>"), 1.0, 0.9) is None
    assert seen_as(q, parse_term("<bottle --> bottle>"), 1.0, 0.9) is None
    assert seen_as(q, None, 0.0, 0.0) is None


def test_a_kind_not_in_view_is_denied() -> None:
    assert not_seen(parse_term("trash")) == parse_sentence("<trash --> [see]>. :|: {0.0 0.9}")
