from __future__ import annotations

import random

import pytest

from robocog.planning.heuristics import BlocksView
from robocog.planning.search import astar, bfs, tree_levels
from robocog.planning.world import Scene, build_task

from .conftest import random_goal, random_scene


def _task():
    scene = Scene(["a", "b", "c"], ["table"], on={"a": "b"})
    return build_task(scene, [("on", "b", "a"), ("on", "c", "table")])


def test_first_mode_returns_a_valid_shortest_plan() -> None:
    task = _task()
    result = bfs(task, "first")
    assert result.optimal and result.complete
    assert task.validate(result.plan)
    shorter = bfs(task, "bounded", max_iterations=result.iterations - 1)
    assert shorter.plan is None and not shorter.complete


def test_whole_mode_explores_everything_and_keeps_every_solution() -> None:
    task = _task()
    first = bfs(task, "first")
    whole = bfs(task, "whole")
    assert whole.complete and whole.solutions >= 1
    assert whole.iterations > first.iterations
    assert whole.lengths[0] == len(first.plan) == min(whole.lengths)


def test_branch_pruning_expands_more_but_finds_the_same_length() -> None:
    task = _task()
    a = bfs(task, "first", prune="global")
    b = bfs(task, "first", prune="branch")
    assert len(a.plan) == len(b.plan)
    assert b.generated >= a.generated


def test_quick_mode_may_miss_a_plan_the_full_search_finds() -> None:
    # the goal names only a and b, but c lies on a and must be moved away
    task = build_task(Scene(["a", "b", "c"], [], on={"c": "a"}), [("on", "a", "b")])
    quick = bfs(task.restricted({"a", "b"}), "quick")
    assert quick.plan is None
    assert bfs(task, "first").plan is not None


def test_hand_free_and_hand_busy_actions_alternate() -> None:
    task = _task()
    plan = bfs(task, "first").plan
    kinds = [op.kind for op in plan]
    assert kinds == ["take", "place"] * (len(plan) // 2)


def test_unknown_mode_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown search mode"):
        bfs(_task(), "sideways")
    with pytest.raises(ValueError, match="max_iterations"):
        bfs(_task(), "bounded")


@pytest.mark.parametrize("seed", range(30))
def test_astar_finds_plans_as_short_as_bfs(seed: int) -> None:
    rng = random.Random(seed)
    scene = random_scene(rng, rng.randint(1, 5), rng.randint(0, 2))
    goal = random_goal(rng, scene)
    task = build_task(scene, goal)
    b = bfs(task, "first")
    a = astar(task, BlocksView(task))
    assert (a.plan is None) == (b.plan is None)
    if a.plan is not None:
        assert len(a.plan) == len(b.plan)
        assert task.validate(a.plan)
        assert a.iterations <= b.iterations


def test_tree_levels_count_the_thesis_tree() -> None:
    task = build_task(Scene(["a", "b"], ["t"]), [("on", "b", "a")])
    levels = tree_levels(task, 2)
    # pickup a or b; then putdown, stack on t, stack on the other object
    assert levels == [1, 2, 6]


@pytest.mark.parametrize("seed", range(10))
def test_goal_test_on_creation_gives_the_same_length_with_fewer_iterations(seed: int) -> None:
    rng = random.Random(300 + seed)
    scene = random_scene(rng, rng.randint(1, 4), rng.randint(0, 2))
    task = build_task(scene, random_goal(rng, scene))
    taken = bfs(task, "first", goal_test="taken")
    created = bfs(task, "first", goal_test="created")
    assert (taken.plan is None) == (created.plan is None)
    if taken.plan is not None:
        assert len(created.plan) == len(taken.plan)
        assert task.validate(created.plan)
        assert created.iterations <= taken.iterations
