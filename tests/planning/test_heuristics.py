from __future__ import annotations

import random
from collections import deque

import pytest

from robocog.planning.heuristics import BlocksView
from robocog.planning.pddl import Problem, ground, read_domain
from robocog.planning.world import build_task

from .conftest import random_goal, random_scene

DOMAIN = """(define (domain blocks) (:requirements :strips :typing) (:types block)
 (:predicates (on ?x - block ?y - block) (ontable ?x - block) (clear ?x - block) (handempty) (holding ?x - block))
 (:action pick-up :parameters (?x - block) :precondition (and (clear ?x) (ontable ?x) (handempty))
  :effect (and (not (ontable ?x)) (not (clear ?x)) (not (handempty)) (holding ?x)))
 (:action put-down :parameters (?x - block) :precondition (holding ?x)
  :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
 (:action stack :parameters (?x - block ?y - block) :precondition (and (holding ?x) (clear ?y))
  :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
 (:action unstack :parameters (?x - block ?y - block) :precondition (and (on ?x ?y) (clear ?x) (handempty))
  :effect (and (holding ?x) (clear ?y) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))"""


def true_distances(task) -> dict[int, int]:
    """Exact distance to the goal of every reachable state (backward BFS)."""
    seen = {task.init}
    queue = deque([task.init])
    back: dict[int, list[int]] = {}
    while queue:
        s = queue.popleft()
        for _op, t in task.successors(s):
            back.setdefault(t, []).append(s)
            if t not in seen:
                seen.add(t)
                queue.append(t)
    dist = {s: 0 for s in seen if task.is_goal(s)}
    queue = deque(dist)
    while queue:
        s = queue.popleft()
        for p in back.get(s, ()):
            if p not in dist:
                dist[p] = dist[s] + 1
                queue.append(p)
    return dist


@pytest.mark.parametrize("seed", range(40))
def test_never_overestimates_on_any_reachable_state(seed: int) -> None:
    rng = random.Random(seed)
    scene = random_scene(rng, rng.randint(2, 4), rng.randint(0, 2))
    goal = random_goal(rng, scene)
    task = build_task(scene, goal)
    h = BlocksView(task)
    dist = true_distances(task)
    assert dist, "the goal is reachable in a blocks scene"
    for state, d in dist.items():
        assert h(state) <= d
        if d == 0:
            assert h(state) == 0


def _pddl_task(rng: random.Random, n: int):
    names = [f"b{i}" for i in range(n)]

    def towers() -> list[tuple[str, ...]]:
        order = names[:]
        rng.shuffle(order)
        facts, placed = [], []
        for x in order:
            free = [p for p in placed if all(f[2] != p for f in facts if f[0] == "on")]
            under = rng.choice([None, *free])
            facts.append(("ontable", x) if under is None else ("on", x, under))
            placed.append(x)
        return facts

    init = towers()
    covered = {f[2] for f in init if f[0] == "on"}
    init += [("clear", x) for x in names if x not in covered] + [("handempty",)]
    goal = [f for f in towers() if rng.random() < 0.8]
    problem = Problem("p", "blocks", [(x, "block") for x in names], init, [(True, g) for g in goal])
    return ground(read_domain(DOMAIN), problem)


@pytest.mark.parametrize("seed", range(25))
def test_never_overestimates_in_the_pddl_blocks_world(seed: int) -> None:
    rng = random.Random(1000 + seed)
    task = _pddl_task(rng, rng.randint(2, 5))
    h = BlocksView(task)
    for state, d in true_distances(task).items():
        assert h(state) <= d


def test_an_object_that_must_move_twice_is_counted_twice() -> None:
    # a lies on b, and the goal wants b under a (a on c on b) with b moved onto d:
    # a must leave b before b moves and come back after, so a moves twice
    from robocog.planning.search import bfs
    from robocog.planning.world import Scene

    goal = [("on", "a", "c"), ("on", "c", "b"), ("on", "b", "d")]
    task = build_task(Scene(["a", "b", "c", "d"], [], on={"a": "b"}), goal)
    optimum = len(bfs(task).plan)
    assert optimum == 8
    assert BlocksView(task)(task.init) == optimum
