"""Moves that never need to be tried in a pick-and-place task, for faster optimal search.

Two classic facts about the blocks world (Gupta and Nau, 1992) hold for the planner's
tasks as long as the goal only says what stands on what:

1. if an object can go straight to its final place (its goal support is in place and
   clear, or it belongs on the table or on a fixed object), some shortest plan does that
   now; so when such a *constructive* move exists it is the only one tried;
2. otherwise some shortest plan moves a misplaced object onto the table (its resting
   place); so a held object that cannot go to its final place is only put down, and an
   object already in place is never picked up.

The reduced space keeps at least one shortest plan from every state, so A* on it still
returns shortest plans while expanding far fewer states. The test suite checks the
lengths against exhaustive breadth-first search on random scenes.
"""

from __future__ import annotations

from collections.abc import Iterator

from robocog.planning.heuristics import REST, UNSPECIFIED, BlocksView, moves_one_object
from robocog.planning.task import Operator, Task, bits


class BlocksReduction:
    """A search space over a task's states with the two pruning rules applied."""

    def __init__(self, task: Task, view: BlocksView) -> None:
        self.task = task
        self.view = view
        self.init = task.init
        pos = {name: i for i, name in enumerate(view.names)}
        self._subject: dict[int, int] = {}
        self._target: dict[int, int] = {}
        for op in task.operators:
            x = pos.get(op.args[0], -1) if op.args else -1
            self._subject[id(op)] = x
            target = REST
            for b in bits(op.add & view.on_mask):
                ox, oy = view.on_of[b]
                if ox == x:
                    target = oy
            self._target[id(op)] = target

    @staticmethod
    def applies(task: Task, view: BlocksView) -> bool:
        """True when the goal is only about supports and every action moves one object."""
        if task.goal_absent:
            return False
        for i in bits(task.goal):
            fact = task.facts[i]
            about_support = (fact[0] == "on" and len(fact) == 3) or (
                fact[0] == "ontable" and len(fact) == 2
            )
            if not about_support:
                return False
        return moves_one_object(task, view.names)

    def is_goal(self, state: int) -> bool:
        """The task's goal test."""
        return self.task.is_goal(state)

    def successors(self, state: int) -> Iterator[tuple[Operator, int]]:
        """The task's successors, less the moves the two rules make unnecessary."""
        view = self.view
        n = view.n
        gs = view.goal_support
        sup, occupant, status, _below, held = view.analyse(state)

        def ready(target: int) -> bool:
            if target < 0 or target >= n:
                return True  # the resting place or a fixed object
            return status[target] == 1 and occupant[target] == -1 and target != held

        ops = list(self.task.applicable(state))
        if held >= 0:
            goal = gs[held]
            want = goal if goal != UNSPECIFIED and ready(goal) else REST
            for op in ops:
                if self._target[id(op)] == want:
                    yield op, op.apply(state)
                    return
            for op in ops:  # no such placement here: keep them all
                yield op, op.apply(state)
            return
        takes = [op for op in ops if status[self._subject[id(op)]] == 2]
        for op in takes:
            x = self._subject[id(op)]
            if gs[x] != UNSPECIFIED and gs[x] != sup[x] and ready(gs[x]):
                yield op, op.apply(state)
                return
        for op in takes:
            yield op, op.apply(state)
