"""An admissible heuristic for pick-and-place tasks: a lower bound on remaining actions.

The bound reads the state as towers (which object stands on which, what is in the hand)
and counts how often each object must still be moved, in the manner of the classic
blocks-world bounds (Gupta and Nau; Slaney and Thiebaux):

* an object is *in place* when it stands where the goal wants it (or the goal does not
  say), nothing under it must move, and the goal does not reserve its support for a
  different object; every object not in place must be moved at least once;
* an object must be moved twice when a misplaced object that lies below it now must also
  lie below it in the goal: its first move cannot be the final one;
* two single-move objects each of which must move before the other's final move form a
  deadlock, and one of them moves twice; disjoint pairs are counted greedily.

Each move costs two actions (take and place) except the one already half done when the
object is in the hand. Fixed objects and the resting place hold any number of objects.
Every part is a valid lower bound, so the sum is admissible and A* returns shortest plans.
"""

from __future__ import annotations

from collections.abc import Iterable

from robocog.planning.task import PLACE, TAKE, Task, bits

REST = -1  #: support of an object resting where it was found (PDDL: on the table)
UNSPECIFIED = -2  #: the goal says nothing about the object's support
HELD = -3


class BlocksView:
    """How to read towers from a task's facts, and the goal's towers, prepared once."""

    def __init__(
        self,
        task: Task,
        on: str = "on",
        held: Iterable[str] = ("in-hand", "holding"),
        rest: Iterable[str] = ("ontable",),
    ) -> None:
        held_preds = set(held)
        rest_preds = set(rest)
        self.names = list(task.objects)
        self.n = n = len(self.names)
        pos = {name: i for i, name in enumerate(self.names)}
        for j, name in enumerate(task.fixed):
            pos.setdefault(name, n + j)
        self.on_of: dict[int, tuple[int, int]] = {}
        self.held_of: dict[int, int] = {}
        self.on_mask = 0
        self.held_mask = 0
        for i, fact in enumerate(task.facts):
            if fact[0] == on and len(fact) == 3 and fact[1] in pos and fact[2] in pos:
                if pos[fact[1]] < n:
                    self.on_of[i] = (pos[fact[1]], pos[fact[2]])
                    self.on_mask |= 1 << i
            elif fact[0] in held_preds and len(fact) == 2 and pos.get(fact[1], n) < n:
                self.held_of[i] = pos[fact[1]]
                self.held_mask |= 1 << i
        gs = [UNSPECIFIED] * n
        for i in bits(task.goal):
            fact = task.facts[i]
            if fact[0] == on and len(fact) == 3 and pos.get(fact[1], n) < n and fact[2] in pos:
                gs[pos[fact[1]]] = pos[fact[2]]
            elif fact[0] in rest_preds and len(fact) == 2 and pos.get(fact[1], n) < n:
                gs[pos[fact[1]]] = REST
        self.goal_support = gs
        self.goal_top = [-1] * n
        for x, y in enumerate(gs):
            if 0 <= y < n:
                self.goal_top[y] = x
        self.goal_below = [0] * n
        for x in range(n):
            m, y, steps = 0, gs[x], 0
            while 0 <= y < n and steps <= n:
                m |= 1 << y
                y = gs[y]
                steps += 1
            self.goal_below[x] = m

    @staticmethod
    def fits(task: Task) -> bool:
        """True when the task reads as towers: every action takes or places one object.

        The bound is only sound for such tasks; other PDDL domains get ``blind``.
        """
        return bool(task.busy) and moves_one_object(task, task.objects)

    def analyse(self, state: int) -> tuple[list[int], list[int], list[int], list[int], int]:
        """Supports, occupants, status (1 in place, 2 misplaced), misplaced-below masks
        and the held object (-1 if the hand is free) of *state*."""
        n = self.n
        gs = self.goal_support
        gtop = self.goal_top
        sup = [REST] * n
        held = -1
        on_of = self.on_of
        for b in bits(state & self.on_mask):
            x, y = on_of[b]
            sup[x] = y
        m = state & self.held_mask
        if m:
            held = self.held_of[(m & -m).bit_length() - 1]
            sup[held] = HELD
        occupant = [-1] * n
        for x in range(n):
            s = sup[x]
            if 0 <= s < n:
                occupant[s] = x
        # status: 1 in place, 2 misplaced; below: misplaced objects under x now
        status = [0] * n
        below = [0] * n
        for x in range(n):
            if status[x]:
                continue
            chain = []
            y = x
            while True:
                chain.append(y)
                s = sup[y]
                if s == HELD:
                    base_ok, base_below = False, 0
                    break
                if not 0 <= s < n:
                    base_ok, base_below = True, 0
                    break
                if status[s]:
                    base_ok = status[s] == 1
                    base_below = below[s] | ((1 << s) if status[s] == 2 else 0)
                    break
                y = s
            ok, under = base_ok, base_below
            for z in reversed(chain):
                s = sup[z]
                good = ok and s != HELD and (gs[z] == UNSPECIFIED or gs[z] == s)
                if good and 0 <= s < n and gtop[s] not in (-1, z):
                    good = False  # the goal wants another object on this support
                status[z] = 1 if good else 2
                below[z] = under
                ok = good
                under = under | ((1 << z) if not good else 0)
        return sup, occupant, status, below, held

    def __call__(self, state: int) -> int:
        """Lower bound on the number of actions from *state* to the goal."""
        n = self.n
        gs = self.goal_support
        gtop = self.goal_top
        sup, occupant, status, below, held = self.analyse(state)
        misplaced = 0
        for x in range(n):
            if status[x] == 2:
                misplaced |= 1 << x
        if held >= 0 and gs[held] == UNSPECIFIED and gtop.count(held) == 0:
            # the hand's object need not go anywhere unless something else must move
            if misplaced == 1 << held:
                return 0
        gbelow = self.goal_below
        singles = []
        total = 0
        for x in bits(misplaced):
            gmis = gbelow[x] & misplaced
            two = bool(below[x] & gmis)
            if x == held and not two and 0 <= gs[x] < n and occupant[gs[x]] >= 0:
                two = True  # its support is covered and cannot be cleared first
            if two:
                total += 2
            else:
                total += 1
                singles.append(x)
        # greedy disjoint deadlock pairs among objects that would move only once
        used = 0
        for i, x in enumerate(singles):
            if used >> x & 1:
                continue
            bx = below[x]
            gx = gbelow[x] & misplaced
            for y in singles[i + 1 :]:
                if used >> y & 1:
                    continue
                gy = gbelow[y] & misplaced
                by = below[y]
                xy = (bx >> y & 1) or (gy >> x & 1) or (bx & gy)
                if not xy:
                    continue
                yx = (by >> x & 1) or (gx >> y & 1) or (by & gx)
                if yx:
                    used |= (1 << x) | (1 << y)
                    total += 1
                    break
        actions = 2 * total
        if held >= 0 and misplaced >> held & 1:
            actions -= 1
        return actions


def moves_one_object(task: Task, names: Iterable[str]) -> bool:
    """True when every action takes or places one object, the first of its arguments.

    Both the bound and the move reductions read a state as towers of *names*; an action
    that moves anything else (or several things) would break what they assume.
    """
    names = set(names)
    return all(
        op.kind in (TAKE, PLACE) and op.args and op.args[0] in names for op in task.operators
    )


def blind(state: int) -> int:
    """The zero heuristic: A* becomes uniform-cost search (always admissible)."""
    return 0
