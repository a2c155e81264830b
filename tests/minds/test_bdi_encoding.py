"""Percepts as AgentSpeak beliefs, environment actions as Commands."""

from __future__ import annotations

import math

from robocog.minds.bdi_encoding import command_for_action, name, percept_beliefs
from robocog.robot import Detection, Drop, Forward, GoTo, Gripper, Obstacle, Pick, Pose, Turn


def test_a_frame_becomes_beliefs_without_duplicates() -> None:
    frame = [
        Detection("bottle", math.radians(20), 1.0, 0.9, "bottle1"),
        Detection("bottle", 0.0, 1.5, 0.9, "bottle2"),
        Obstacle("none", 2.0),
        Pose(0, 0, 0, "p3"),
        Gripper(None),
    ]
    assert percept_beliefs(frame) == [
        "see(bottle)",
        "position(bottle,left)",
        "position(bottle,center)",
        "obstacle(free)",
        "at(p3)",
        "gripper(open)",
    ]
    assert percept_beliefs([Gripper("cup1"), Obstacle("front", 1.0)]) == [
        "gripper(hold)",
        "obstacle(front)",
    ]


def test_names_are_agentspeak_atoms() -> None:
    assert name("Water Bottle") == "water_bottle"
    assert name("3d") == "n3d"


def test_actions_map_to_commands() -> None:
    assert command_for_action("goto", ["next"]) == GoTo("next")
    assert command_for_action("goto", ["p2"]) == GoTo("p2")
    assert command_for_action("pick", ["cup"]) == Pick("cup")
    assert command_for_action("drop", []) == Drop()
    assert command_for_action("forward", [1.5]) == Forward(1.5)
    assert command_for_action("left", [90]) == Turn(math.radians(90))
    assert command_for_action("forward", ["far"]) == Forward(0.5)  # not a distance: one step
    assert command_for_action("right", []).angle < 0  # type: ignore[union-attr]
    assert command_for_action("fly", []) is None
