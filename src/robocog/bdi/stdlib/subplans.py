"""``.done`` and ``.done(G)``: JasonER's end of a goal (see :mod:`robocog.bdi.er`).

A plan with the goal condition ``<: false`` never ends by itself; ``.done`` in it, or
in one of its sub-plans, achieves its goal: the intention pursuing it goes on after
the goal, and a branch a sub-plan ran in ends.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.er import done
from robocog.bdi.signals import DONE
from robocog.bdi.stdlib.base import internal, need_args
from robocog.bdi.unifier import resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("done")
def _done(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    need_args(args, 0, "done", 1)
    trig = P.Trigger("+", P.ACHIEVE, resolve(args[0], s)) if args else None
    current = ctx[0] if ctx else None
    if ctx:
        _i, im, _step = ctx
        if im.cur is not None:
            im.cur = (None, im.cur[1])  # step over .done, as .succeed_goal does
    changed = done(ag, trig, current)
    if ctx and not changed:
        ag._advance(current)
    return DONE if ctx else True
