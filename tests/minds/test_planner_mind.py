"""PlannerMind on the tabletop: plan from tags and sentences, execute, replan on failure."""

from __future__ import annotations

import pytest

from robocog.experiments.assembly_thesis import experiment
from robocog.minds.planner_mind import PlannerMind, command_for_step
from robocog.planning.planner import Step
from robocog.robot import Outcome, PickUp, PutDown, Stack, Unstack
from robocog.robot.loop import Loop
from robocog.worlds.tabletop import TabletopWorld


def run(world: TabletopWorld, mind: PlannerMind, cycles: int = 100) -> int:
    return Loop(world, mind).run(cycles, until=lambda: not mind.busy)


def test_steps_become_manipulator_commands() -> None:
    assert command_for_step(Step("pickup", ("A",))) == PickUp("A")
    assert command_for_step(Step("putdown", ("A",))) == PutDown("A")
    assert command_for_step(Step("stack", ("A", "B"))) == Stack("A", "B")
    assert command_for_step(Step("unstack", ("A", "B"))) == Unstack("A", "B")
    with pytest.raises(ValueError):
        command_for_step(Step("juggle", ("A",)))


def test_table_5_2_is_planned_from_tags_and_sentences_and_reached() -> None:
    exp = experiment("5.2")
    world = TabletopWorld()
    mind = PlannerMind()
    record = mind.request(exp.request, facts=exp.facts)
    run(world, mind)
    assert record.status == "reached"
    assert record.executed == list(exp.plan)
    assert all(world.holds(fact) for fact in record.goal)
    assert record.replans == 0 and record.first_plan is not None
    assert record.first_plan.optimal


def test_a_failed_grasp_is_replanned_and_the_goal_still_reached() -> None:
    exp = experiment("5.4")
    world = TabletopWorld(fail_grasps={1, 2, 4})
    mind = PlannerMind()
    record = mind.request(exp.request, facts=exp.facts)
    run(world, mind)
    assert record.status == "reached"
    assert record.replans == 3
    assert len(record.failures) == 3 and all("slipped" in f for f in record.failures)
    assert all(world.holds(fact) for fact in record.goal)
    assert world.failed_grasps == 3


def test_the_mind_gives_up_after_too_many_failures() -> None:
    exp = experiment("5.2")
    world = TabletopWorld(fail_grasps=range(1, 50))
    mind = PlannerMind(max_replans=3)
    record = mind.request(exp.request, facts=exp.facts)
    run(world, mind)
    assert record.status == "failed" and "replans" in record.message


def test_unreadable_sentences_fail_the_request_with_the_reason() -> None:
    mind = PlannerMind()
    record = mind.request("Put the clamp somewhere nice.")
    assert record.status == "failed" and record.message
    assert mind.decide() == []


def test_an_unknown_goal_object_cannot_be_reached() -> None:
    world = TabletopWorld()
    mind = PlannerMind(facts="The table is a fixed object.")
    record = mind.request("The BettClamp is on the Unicorn. The Unicorn is on the BettClamp.")
    run(world, mind)
    assert record.status == "failed"


def test_the_gripper_percept_corrects_the_scene_before_replanning() -> None:
    exp = experiment("5.2")
    world = TabletopWorld()
    mind = PlannerMind()
    record = mind.request(exp.request, facts=exp.facts)
    mind.perceive(world.percepts())
    command = mind.decide()[0]
    assert command == PickUp("BettClamp")
    assert world.execute(command).ok
    # the arm took the clamp but its report was lost: the mind hears a failure
    mind.on_outcome(command, Outcome.failure("no answer from the arm"))
    assert record.status == "planning"
    assert mind.scene is not None and mind.scene.held is None
    mind.perceive(world.percepts())  # the gripper says it holds the clamp
    assert mind.decide() == [Stack("BettClamp", "workbench")]
    assert mind.scene.held == "BettClamp"
    run(world, mind)
    assert record.status == "reached" and record.replans == 1
    assert all(world.holds(fact) for fact in record.goal)


def test_plan_progress_names_the_plan_and_its_next_step() -> None:
    exp = experiment("5.2")
    world = TabletopWorld()
    mind = PlannerMind()
    assert mind.plan_progress() == ([], 0)
    mind.request(exp.request, facts=exp.facts)
    loop = Loop(world, mind)
    loop.step()
    steps, index = mind.plan_progress()
    assert [str(s) for s in steps] == list(exp.plan) and index == 1
    steps.clear()  # a copy: the mind's plan stays
    assert len(mind.plan_progress()[0]) == len(exp.plan)
    loop.run(20, until=lambda: not mind.busy)
    assert mind.plan_progress()[1] == len(exp.plan)
