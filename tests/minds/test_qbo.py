"""The Q.bo's atomic actions over Look/Forward/Turn, and the beliefs they return."""

from __future__ import annotations

import math

import pytest

from robocog.minds.qbo import (
    STEP_LENGTH,
    QboActions,
    QboPerception,
    ReachExitReference,
    degrees,
    parse_action,
)
from robocog.robot import Detection, Forward, Look, Pose, Range, Turn
from robocog.robot.loop import Loop
from robocog.worlds.room import RoomConfig, RoomWorld

QUIET = RoomConfig(motion_noise=0.0, turn_noise=0.0, drift=0.0, sonar_noise=0.0)


def run_action(world: RoomWorld, name: str, args: list[object]) -> list[object]:
    actions = QboActions()
    actions.start(name, args, world.percepts())
    commands = []
    for _ in range(50):
        command = actions.next_command(world.percepts())
        if command is None:
            break
        commands.append(command)
        actions.on_outcome(command, world.execute(command))
    assert not actions.busy
    return commands


def test_tcp_write_is_unwrapped_and_unknown_actions_refused() -> None:
    assert parse_action("tcp_write(forward_Qbo(45))") == ("forward_Qbo", ["45"])
    assert parse_action("looking_Qbo(door)") == ("looking_Qbo", ["door"])
    with pytest.raises(ValueError, match="unknown"):
        parse_action("fly_Qbo(3)")
    with pytest.raises(ValueError):
        parse_action("forward_Qbo(")


def test_directions_are_whole_degrees_in_half_open_circle() -> None:
    assert degrees(math.pi) == 180
    assert degrees(-math.pi) == 180
    assert degrees(math.radians(225)) == -135
    assert degrees(math.radians(44.6)) == 45


def test_forward_qbo_turns_to_the_base_direction_then_moves_one_step() -> None:
    world = RoomWorld(seed=1, config=QUIET)
    world.x, world.y, world.theta = 2.0, 2.0, 0.0
    commands = run_action(world, "forward_Qbo", [90])
    assert [type(c) for c in commands] == [Turn, Forward]
    assert commands[1] == Forward(STEP_LENGTH)
    assert degrees(world.theta) == 90
    assert world.y == pytest.approx(2.0 + STEP_LENGTH, abs=0.03)


def test_search_qbo_turns_little_by_little_until_free() -> None:
    world = RoomWorld(seed=1, config=QUIET)
    world.x, world.y, world.theta = 5.5, 1.5, math.pi / 2  # the east wall to the right
    commands = run_action(world, "search_Qbo", [0])
    turns = [c for c in commands if isinstance(c, Turn)]
    assert len(turns) >= 3, "facing the wall, it must turn more than once"
    assert isinstance(commands[-1], Forward)
    heading = degrees(world.theta)
    assert 0 < abs(heading) <= 90
    assert math.hypot(world.x - 5.5, world.y - 1.5) > 0.1


def test_looking_qbo_answers_with_the_best_area_in_absolute_degrees() -> None:
    perception = QboPerception()
    perception.look_started("door")
    percepts = [
        Pose(0.0, 0.0, math.radians(30), None),
        Range("us_left", 1.0),
        Range("us_right", 0.3),
        Detection("door", math.radians(20), 2.0, 0.7),
        Detection("door", math.radians(-40), 2.0, 0.9),
        Detection("entry", math.radians(60), 2.0, 0.99),
    ]
    beliefs = perception.update(percepts)
    assert "my_current_direction(30)" in beliefs
    assert "found_obstacle" in beliefs
    assert "found_target(door)" in beliefs
    assert "target_direction(-10)" in beliefs
    assert "front_of(door)" in beliefs  # recognised and the sonar meets something
    # the answer stays until the next look, as a Jason percept does
    later = perception.update([Pose(1.0, 0.0, 0.0, None), Range("us_left", 1.0)])
    assert "found_target(door)" in later and "found_obstacle" not in later
    assert "front_of(door)" not in later
    perception.look_started("door")
    assert not any(b.startswith("found_target") for b in perception.update([Pose(0, 0, 0)]))


def test_bad_arguments_are_refused() -> None:
    actions = QboActions()
    with pytest.raises(ValueError):
        actions.start("forward_Qbo", ["north"], [])
    with pytest.raises(ValueError):
        actions.start("looking_Qbo", [], [])
    assert not actions.busy


def test_a_look_is_one_command() -> None:
    world = RoomWorld(seed=1)
    assert run_action(world, "looking_Qbo", ["door"]) == [Look("around")]


def test_reference_plans_reach_the_door_then_look_for_the_entry() -> None:
    world = RoomWorld(seed=0)
    mind = ReachExitReference()
    Loop(world, mind).run(400, until=lambda: world.exited() or mind.done)
    assert mind.log[0] == "reach_object(door) expected 0"
    assert "front_of(door)" in mind.log
    entry = next(line for line in mind.log if line.startswith("reach_object(entry)"))
    stop = mind.log.index("front_of(door)")
    assert stop < mind.log.index(entry)
    assert world.exited() or world.at_entrance()


def test_the_agent_waits_for_each_action_to_end_on_the_robot() -> None:
    pytest.importorskip("robocog.bdi.stdlib")
    from robocog.minds.qbo import QboBdiMind

    program = """
    !go.
    +!go <- looking_Qbo(door); tcp_write(forward_Qbo(90)); .print(moved).
    """
    world = RoomWorld(seed=1, config=QUIET)
    world.x, world.y, world.theta = 2.0, 2.0, 0.0
    mind = QboBdiMind(program)
    Loop(world, mind).run(20, until=lambda: mind.done and bool(mind.output))
    assert mind.log == ["looking_Qbo(door)", "forward_Qbo(90)"]
    assert mind.output == ["moved"]
    assert degrees(world.theta) == 90
    assert world.y == pytest.approx(2.0 + STEP_LENGTH, abs=0.03)


def test_an_unknown_tcp_write_fails_the_goal() -> None:
    pytest.importorskip("robocog.bdi.stdlib")
    from robocog.minds.qbo import QboBdiMind

    program = """
    !go.
    +!go <- tcp_write(fly_Qbo(3)).
    -!go <- .print(failed).
    """
    world = RoomWorld(seed=1)
    mind = QboBdiMind(program)
    Loop(world, mind).run(10)
    assert mind.output == ["failed"]
    assert world.commands == 0
