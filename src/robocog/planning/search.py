"""Search over planning states: the thesis's breadth-first search and A*.

Both work on any *space* with ``init``, ``is_goal(state)`` and ``successors(state)``
yielding ``(step, next_state)``; a ``Task`` is one such space, the rule matcher over
fact sets (``matcher.MatcherSpace``) another.

Breadth-first search follows Section 4.5.1: nodes are taken from a FIFO queue, each one
taken is one iteration, a node whose state repeats is not expanded, and the hand
alternates between actions that take an object and actions that place it (the space does
that). Four modes:

* ``first``  - stop at the first solution (the shortest plan);
* ``bounded``- the same, but give up after ``max_iterations``;
* ``whole``  - explore every reachable state and keep every solution node found;
* ``quick``  - ``first`` on a space restricted to actions that touch an object named in
  the goal (the caller restricts the space; fast, but it may miss a plan).

The goal is tested when a node is taken (``goal_test="taken"``, as Section 4.5.1.2
says) or, faster, when it is created (``goal_test="created"``, what the thesis's small
tables count). ``prune="global"`` drops a state seen anywhere before (each state is expanded once);
``prune="branch"`` drops it only when it repeats on its own branch, as the thesis did,
which expands far more nodes but gives the same shortest length.

A* orders nodes by g + h with an admissible h, so its first plan is a shortest one;
nodes reached again by a cheaper path are reopened, so consistency is not required.
"""

from __future__ import annotations

import heapq
import time
from collections import deque
from collections.abc import Callable, Hashable, Iterator
from dataclasses import dataclass, field
from typing import Any, Protocol

MODES = ("first", "bounded", "whole", "quick")


class Space(Protocol):
    """What a search needs from a problem."""

    init: Any

    def is_goal(self, state: Any) -> bool:
        """True when *state* satisfies the request: the search stops (or counts it) there."""
        ...

    def successors(self, state: Any) -> Iterator[tuple[Any, Any]]:
        """Each ``(step, next_state)`` one action leads to; the plan is the steps taken."""
        ...


@dataclass
class SearchResult:
    """What a search found and what it cost.

    ``plan`` is None when no plan was found. ``optimal`` is True when the plan is known
    to be a shortest one. ``complete`` is True when the search ended by its own rule
    (goal found or space exhausted) rather than by a limit. ``solutions`` counts the
    solution nodes found (more than one only in ``whole`` mode) and ``lengths`` their
    plan lengths.
    """

    plan: list[Any] | None
    iterations: int
    generated: int
    seconds: float
    optimal: bool
    complete: bool
    solutions: int = 0
    lengths: list[int] = field(default_factory=list)
    algorithm: str = "bfs"


def _path(parents: dict[Hashable, tuple[Hashable, Any] | None], state: Hashable) -> list[Any]:
    steps: list[Any] = []
    link = parents[state]
    while link is not None:
        prev, step = link
        steps.append(step)
        link = parents[prev]
    steps.reverse()
    return steps


def _bfs_result(
    found: list[list[Any]],
    mode: str,
    iterations: int,
    generated: int,
    start: float,
    complete: bool,
) -> SearchResult:
    """The result of either BFS walk: the first plan found, and every solution's length."""
    plan = found[0] if found else None
    return SearchResult(
        plan=plan,
        iterations=iterations,
        generated=generated,
        seconds=time.perf_counter() - start,
        optimal=plan is not None and mode != "quick",
        complete=complete,
        solutions=len(found),
        lengths=[len(p) for p in found],
    )


def bfs(
    space: Space,
    mode: str = "first",
    max_iterations: int | None = None,
    prune: str = "global",
    max_nodes: int = 5_000_000,
    goal_test: str = "taken",
) -> SearchResult:
    """Breadth-first search in one of the thesis's modes (see the module docstring).

    ``goal_test="created"`` tests each new state as it is generated instead of when it
    is taken from the queue: the same shortest plan, without expanding the plan's last
    level (global pruning, modes other than ``whole``).
    """
    if goal_test not in ("taken", "created"):
        raise ValueError("goal_test must be 'taken' or 'created'")
    if mode not in MODES:
        raise ValueError(f"unknown search mode {mode!r}; choose one of {', '.join(MODES)}")
    if prune not in ("global", "branch"):
        raise ValueError("prune must be 'global' or 'branch'")
    if mode == "bounded" and max_iterations is None:
        raise ValueError("the bounded mode needs max_iterations")
    if prune == "branch":
        return _bfs_branch(space, mode, max_iterations, max_nodes)
    start = time.perf_counter()
    parents: dict[Hashable, tuple[Hashable, Any] | None] = {space.init: None}
    queue: deque[Hashable] = deque([space.init])
    iterations = generated = 0
    found: list[list[Any]] = []
    complete = True
    early = goal_test == "created" and mode != "whole"
    if early and space.is_goal(space.init):
        found.append([])
        queue.clear()
    while queue:
        if max_iterations is not None and iterations >= max_iterations:
            complete = False
            break
        state = queue.popleft()
        iterations += 1
        if not early and space.is_goal(state):
            found.append(_path(parents, state))
            if mode != "whole":
                break
            continue
        for step, nxt in space.successors(state):
            generated += 1
            if nxt not in parents:
                parents[nxt] = (state, step)
                if early and space.is_goal(nxt):
                    found.append(_path(parents, nxt))
                    break
                queue.append(nxt)
        if found and early:
            break
        if len(parents) > max_nodes:
            complete = False
            break
    return _bfs_result(found, mode, iterations, generated, start, complete)


def _bfs_branch(
    space: Space, mode: str, max_iterations: int | None, max_nodes: int
) -> SearchResult:
    """BFS over the search tree, pruning a state only if it repeats on its own branch."""
    start = time.perf_counter()
    # a node: (state, parent node or None, step, depth)
    root: tuple[Any, Any, Any, int] = (space.init, None, None, 0)
    queue: deque[tuple[Any, Any, Any, int]] = deque([root])
    iterations = generated = 0
    found: list[list[Any]] = []
    complete = True
    while queue:
        if max_iterations is not None and iterations >= max_iterations:
            complete = False
            break
        node = queue.popleft()
        iterations += 1
        state = node[0]
        if space.is_goal(state):
            steps = []
            cur = node
            while cur[1] is not None:
                steps.append(cur[2])
                cur = cur[1]
            found.append(steps[::-1])
            if mode != "whole":
                break
            continue
        ancestor = node[1]
        repeated = False
        while ancestor is not None:
            if ancestor[0] == state:
                repeated = True
                break
            ancestor = ancestor[1]
        if repeated:
            continue
        for step, nxt in space.successors(state):
            generated += 1
            queue.append((nxt, node, step, node[3] + 1))
        if len(queue) > max_nodes:
            complete = False
            break
    return _bfs_result(found, mode, iterations, generated, start, complete)


def astar(
    space: Space,
    heuristic: Callable[[Any], int],
    max_nodes: int = 5_000_000,
    max_seconds: float | None = None,
) -> SearchResult:
    """A* with an admissible *heuristic*; ties go to the node with the smaller h."""
    start = time.perf_counter()
    init = space.init
    h0 = heuristic(init)
    best_g: dict[Hashable, int] = {init: 0}
    parents: dict[Hashable, tuple[Hashable, Any] | None] = {init: None}
    counter = 0
    heap: list[tuple[int, int, int, Hashable]] = [(h0, h0, counter, init)]
    iterations = generated = 0
    complete = True
    plan = None
    while heap:
        _f, h, _c, state = heapq.heappop(heap)
        g = best_g[state]
        if _f - h != g:  # a cheaper path to this state was found after this entry
            continue
        iterations += 1
        if space.is_goal(state):
            plan = _path(parents, state)
            break
        if len(best_g) > max_nodes or (
            max_seconds is not None
            and iterations & 1023 == 0
            and time.perf_counter() - start > max_seconds
        ):
            complete = False
            break
        g1 = g + 1
        for step, nxt in space.successors(state):
            generated += 1
            old = best_g.get(nxt)
            if old is not None and old <= g1:
                continue
            best_g[nxt] = g1
            parents[nxt] = (state, step)
            hn = heuristic(nxt)
            counter += 1
            heapq.heappush(heap, (g1 + hn, hn, counter, nxt))
    return SearchResult(
        plan=plan,
        iterations=iterations,
        generated=generated,
        seconds=time.perf_counter() - start,
        optimal=plan is not None,
        complete=complete,
        solutions=1 if plan is not None else 0,
        lengths=[len(plan)] if plan is not None else [],
        algorithm="astar",
    )


def tree_levels(space: Space, depth: int, max_nodes: int = 2_000_000) -> list[int]:
    """Nodes at each depth 0..depth of the thesis's search tree.

    The tree is the one ``prune="branch"`` walks: a node whose state repeats an ancestor's
    is a leaf. Its level sizes do not depend on the order children are generated in, so
    they bound the iteration count of any breadth-first walk of that tree.
    """
    levels = [1]
    frontier: list[tuple[Any, tuple[Any, ...]]] = [(space.init, ())]
    for _ in range(depth):
        nxt: list[tuple[Any, tuple[Any, ...]]] = []
        count = 0
        for state, ancestors in frontier:
            if state in ancestors or space.is_goal(state):
                continue
            chain = (*ancestors, state)
            for _step, child in space.successors(state):
                count += 1
                nxt.append((child, chain))
            if count > max_nodes:
                raise MemoryError("the tree is too large to count")
        levels.append(count)
        frontier = nxt
    return levels
