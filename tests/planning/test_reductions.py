from __future__ import annotations

import random

import pytest

from robocog.planning.heuristics import BlocksView
from robocog.planning.reductions import BlocksReduction
from robocog.planning.search import astar, bfs
from robocog.planning.world import Scene, build_task

from .conftest import random_goal, random_scene
from .test_heuristics import _pddl_task


@pytest.mark.parametrize("seed", range(60))
def test_reduced_astar_is_as_short_as_exhaustive_bfs(seed: int) -> None:
    rng = random.Random(5000 + seed)
    scene = random_scene(rng, rng.randint(1, 5), rng.randint(0, 2))
    goal = [f for f in random_goal(rng, scene) if f[0] == "on"] or [("on", "b0", "F0")]
    if "F0" not in scene.fixed and goal == [("on", "b0", "F0")]:
        scene.fixed.append("F0")
    task = build_task(scene, goal)
    view = BlocksView(task)
    assert BlocksReduction.applies(task, view)
    full = bfs(task, "first")
    reduced = astar(BlocksReduction(task, view), view)
    assert (full.plan is None) == (reduced.plan is None)
    if full.plan is not None:
        assert len(reduced.plan) == len(full.plan)
        assert task.validate(reduced.plan)


@pytest.mark.parametrize("seed", range(30))
def test_reduced_astar_in_the_pddl_blocks_world(seed: int) -> None:
    rng = random.Random(7000 + seed)
    task = _pddl_task(rng, rng.randint(2, 6))
    view = BlocksView(task)
    full = bfs(task, "first")
    reduced = astar(BlocksReduction(task, view), view)
    assert len(reduced.plan) == len(full.plan)


def test_a_constructive_move_is_the_only_one_tried() -> None:
    task = build_task(Scene(["a", "b", "c"], []), [("on", "a", "b")])
    space = BlocksReduction(task, BlocksView(task))
    steps = [(op.name, op.args) for op, _ in space.successors(task.init)]
    assert steps == [("pickup", ("a",))]


def test_goals_beyond_supports_are_searched_without_reduction() -> None:
    task = build_task(Scene(["a", "b"], []), [("in-hand", "a")])
    assert not BlocksReduction.applies(task, BlocksView(task))
