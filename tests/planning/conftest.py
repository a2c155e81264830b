"""Shared builders for the planner tests: random scenes and goals from a seed."""

from __future__ import annotations

import random

from robocog.planning.world import Scene


def random_scene(rng: random.Random, n: int, fixed: int, hand: bool = True) -> Scene:
    """A random legal scene of *n* movable and *fixed* fixed objects."""
    objects = [f"b{i}" for i in range(n)]
    scene = Scene(list(objects), [f"F{i}" for i in range(fixed)])
    order = objects[:]
    rng.shuffle(order)
    if hand and order and rng.random() < 0.3:
        scene.held = order.pop()
    placed: list[str] = []
    for x in order:
        free = [p for p in placed if p not in scene.on.values()]
        choice = rng.choice([None, *scene.fixed, *free])
        if choice is not None:
            scene.on[x] = choice
        placed.append(x)
    return scene


def random_goal(rng: random.Random, scene: Scene) -> list[tuple[str, ...]]:
    """A random non-empty subset of the facts of another random scene."""
    target = random_scene(rng, len(scene.objects), len(scene.fixed))
    facts: list[tuple[str, ...]] = [("on", a, b) for a, b in target.on.items()]
    if target.held is not None and rng.random() < 0.5:
        facts.append(("in-hand", target.held))
    if not facts:
        return []
    return rng.sample(facts, rng.randint(1, len(facts)))
