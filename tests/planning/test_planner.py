from __future__ import annotations

import pytest

from robocog.planning.planner import (
    Planner,
    PlanningError,
    Step,
    goal_from_english,
    scene_from_english,
)
from robocog.planning.world import Scene, SceneError

FACTS = "The workbench is a fixed object. The bolt is on the screw."


def test_sentences_make_the_scene() -> None:
    scene = scene_from_english(
        ["screw", "bolt", "washer", "workbench"], FACTS + " The washer is in the hand."
    )
    assert scene.fixed == ["workbench"]
    assert scene.on == {"bolt": "screw"}
    assert scene.held == "washer"


@pytest.mark.parametrize(
    ("facts", "message"),
    [
        ("The a is on the b. The b is on the a.", "loop"),
        ("The a is on the b. The c is on the b.", "cannot both be on"),
        ("The a is in the hand. The b is in the hand.", "already holds"),
        ("The t is a fixed object. The t is on the a.", "fixed object"),
        ("The a is on the b. The a is on the c.", "already on"),
    ],
)
def test_impossible_scenes_are_refused_with_the_reason(facts: str, message: str) -> None:
    with pytest.raises(PlanningError, match=message):
        scene_from_english(["a", "b", "c"], facts)


def test_plan_from_a_hand_that_holds_something() -> None:
    scene = scene_from_english(["a", "b", "t"], "The t is a fixed object. The a is in the hand.")
    result = Planner().plan(scene, "The b is on the a.")
    assert [str(s) for s in result.steps] == [
        '(putdown (ConceptNode "a"))',
        '(pickup (ConceptNode "b"))',
        '(stack (ConceptNode "b") (ConceptNode "a"))',
    ]


def test_execute_step_by_step_and_replan_after_a_failure() -> None:
    planner = Planner()
    scene = scene_from_english(["a", "b", "c", "t"], "The t is a fixed object. The c is on the a.")
    goal = goal_from_english("The a is on the b. The b is on the t.")
    plan = planner.plan(scene, goal)
    assert plan.optimal
    scene = plan.steps[0].apply(scene)
    # the object slips and lands on the fixed object instead: the robot replans from there
    scene = Scene(scene.objects, scene.fixed, {**scene.on, scene.held: "t"}, None)
    again = planner.plan(scene, goal)
    for step in again.steps:
        scene = step.apply(scene)
    assert scene.on["a"] == "b" and scene.on["b"] == "t"


def test_a_step_that_cannot_be_done_says_why() -> None:
    scene = Scene(["a", "b"], [], on={"a": "b"})
    with pytest.raises(SceneError, match="not clear"):
        Step("pickup", ("b",)).apply(scene)
    with pytest.raises(SceneError, match="not in the hand"):
        Step("putdown", ("a",)).apply(scene)


def test_unreachable_request_reports_no_plan() -> None:
    scene = Scene(["a"], ["t"])
    result = Planner().plan(scene, [("on", "t", "a")])
    assert not result.found and "no plan exists" in result.message


def test_strict_requests_refuse_unknown_objects() -> None:
    with pytest.raises(PlanningError, match="not known"):
        Planner().plan(Scene(["a"], []), "The a is on the ghost.", strict=True)


def test_bad_mode_and_engine_are_refused() -> None:
    with pytest.raises(PlanningError, match="unknown mode"):
        Planner().plan(Scene(["a", "b"], []), "The a is on the b.", mode="dfs")
    with pytest.raises(PlanningError, match="unknown engine"):
        Planner().plan(Scene(["a", "b"], []), "The a is on the b.", engine="gpu")


def test_result_json_has_the_documented_keys() -> None:
    result = Planner().plan(Scene(["a", "b"], []), "The a is on the b.")
    data = result.to_json()
    assert {"steps", "length", "iterations", "seconds", "optimal"} <= set(data)
    assert data["steps"] == [
        '(pickup (ConceptNode "a"))',
        '(stack (ConceptNode "a") (ConceptNode "b"))',
    ]
    assert data["length"] == 2 and data["optimal"] is True


def test_quick_mode_is_marked_optimal_only_when_proved() -> None:
    scene = Scene(["a", "b", "c"], [], on={"c": "a"})
    result = Planner().plan(scene, "The a is on the b.", mode="quick")
    assert not result.found and "quick search" in result.message
