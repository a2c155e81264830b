"""BdiMind: the paper's BDI baseline as an AgentSpeak agent driving the garbage field."""

from __future__ import annotations

import pytest

from robocog.minds.bdi_mind import BdiMind, probe, program
from robocog.robot import Detection, Drop, GoTo, Gripper, Mind, Obstacle, Outcome, Pick, Pose
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig, GarbageField

pytestmark = pytest.mark.skipif(probe() is not None, reason=f"interpreter not usable: {probe()}")


def _frame(seen: bool = True, holding: str | None = None) -> list:
    frame: list = [Obstacle("none", 2.0), Gripper(holding), Pose(0, 0, 0, "p0")]
    if seen:
        frame.insert(0, Detection("bottle", 0.0, 1.0, 0.9, "bottle1"))
    return frame


def test_the_program_is_the_background_knowledge_translated() -> None:
    text = program()
    for plan in (
        "+!collect : gripper(hold) <- drop; !collect.",
        "+!collect : gripper(open) & see(X) & trash(X) <- pick(X); !collect.",
        "+!collect : gripper(open) <- goto(next); !collect.",
    ):
        assert plan in text
    assert "trash(bottle)." in text and "trash(cup)." in text


def test_percepts_become_beliefs_replaced_each_frame() -> None:
    mind = BdiMind()
    assert isinstance(mind, Mind)
    mind.perceive(_frame())
    mind.decide()
    assert "see(bottle)[source(percept)]" in mind.beliefs("see")
    mind.on_outcome(Pick("bottle"), Outcome.failure("missed"))
    mind.perceive(_frame(seen=False))
    mind.decide()
    assert mind.beliefs("see") == []
    assert any(b.startswith("at(p0)") for b in mind.beliefs("at"))


def test_an_action_waits_for_its_outcome() -> None:
    mind = BdiMind()
    mind.perceive(_frame())
    assert mind.decide() == [Pick("bottle")]
    mind.perceive(_frame())
    assert mind.decide() == []  # the intention waits for the robot
    mind.on_outcome(Pick("bottle"), Outcome.success())
    mind.perceive(_frame(seen=False, holding="bottle1"))
    assert mind.decide() == [Drop()]
    mind.on_outcome(Drop(), Outcome.success())
    mind.perceive(_frame(seen=False))
    assert mind.decide() == [GoTo("next")]


def test_a_failed_pick_is_tried_again_while_the_object_is_seen() -> None:
    mind = BdiMind()
    picks = 0
    for _ in range(4):
        mind.perceive(_frame())
        for command in mind.decide():
            picks += command == Pick("bottle")
            mind.on_outcome(command, Outcome.failure("slipped"))
    assert picks == 4


def _tipped_in_front() -> GarbageField:
    world = GarbageField(seed=1)
    t = world.trash[0]
    world.trash[:] = [t]
    t.recognisable, t.upright = True, False
    world.x, world.y, world.theta = t.x - 1.0, t.y, 0.0
    return world


def test_against_the_field_it_re_picks_a_tipped_object() -> None:
    world = _tipped_in_front()
    loop = Loop(world, BdiMind())
    loop.run(12)
    assert world.trash[0].picks_while_tipped >= 2


def test_a_whole_mission_collects_and_ends() -> None:
    world = GarbageField(GarbageConfig(), seed=6)
    loop = Loop(world, BdiMind())
    loop.run(2000, until=lambda: world.done)
    assert world.done
    assert world.collected() > 0
    assert loop.stats.summary()["reason_p99_ms"] < 1000
