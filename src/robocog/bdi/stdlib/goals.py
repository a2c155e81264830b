"""Goals and intentions: ``.fail``, ``.succeed_goal``, ``.fail_goal``, the ``.drop_*``
family, ``.suspend``, ``.resume``, ``.suspended``, ``.intend``, ``.desire``."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError
from robocog.bdi.signals import DONE, SUSPEND
from robocog.bdi.stdlib.base import bind_each, internal, need_args
from robocog.bdi.terms import Literal, Term, print_str
from robocog.bdi.unifier import resolve, undo, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("fail")
def _fail(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    if not args:
        return False
    annots = tuple(resolve(a, s) for a in args)
    msg = "fail"
    for a in annots:
        if a.__class__ is Literal and a.functor == "error_msg" and len(a.args) == 1:
            msg = print_str(a.args[0])
            break
    # as Jason: the failure of an internal action that raised (error(internal_action)),
    # with the arguments, an error(...) among them too, as further annotations
    err = ActionError(msg, "internal_action")
    err.annots = tuple(
        a
        for a in annots
        if not (a.__class__ is Literal and a.functor == "error_msg" and len(a.args) == 1)
    )
    raise err


def _end_goal(how: str, ag: Agent, args: tuple, s: dict, ctx: Any) -> Any:
    """``.succeed_goal`` / ``.fail_goal``: end every pursuit of a goal, as ``how`` says.

    The calling intention first steps over this formula, so that when the goal it drops
    is not one of its own it simply goes on with its next formula.
    """
    need_args(args, 1, f"{how}_goal")
    goal = resolve(args[0], s)
    current = ctx[0] if ctx else None
    if ctx:
        _step_over(ag, ctx)
    changed = ag.drop_goal(goal, how, current)
    if ctx and not changed:
        ag._advance(current)
    return DONE if ctx else True


@internal("succeed_goal")
def _succeed_goal(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    return _end_goal("succeed", ag, args, s, ctx)


@internal("fail_goal")
def _fail_goal(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    return _end_goal("fail", ag, args, s, ctx)


def _step_over(ag: Agent, ctx: Any) -> None:
    """Move the current intention past the running internal action (without requeueing)."""
    _i, im, _step = ctx
    if im.cur is not None:
        im.cur = (None, im.cur[1])


@internal("drop_intention")
def _drop_intention(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    if not args:
        if ctx:
            ag._drop(ctx[0])
            return DONE
        return True
    goal = resolve(args[0], s)
    current = ctx[0] if ctx else None
    changed = ag.drop_goal(goal, "drop", current)
    if ctx and changed:
        return DONE
    return True


@internal("drop_desire")
def _drop_desire(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    return _drop_intention(ag, args, s, trail, ctx)


@internal("drop_all_intentions")
def _drop_all_intentions(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    """Every other intention is dropped; the one running this action goes on, as in
    Jason 3.3."""
    current = ctx[0] if ctx else None
    for i in ag.C.intentions():
        if i is not current:
            ag._drop(i)
    return True


def drop_every_intention(ag: Agent, ctx: Any) -> Any:
    """Drop every intention, the one running this action (``ctx``) last; ``DONE`` when
    there was one, so that its body stops, else ``True``. For the actions that end all
    an agent pursues (``.drop_all_desires``, ``.kill_agent`` of itself)."""
    for i in ag.C.intentions():
        ag._drop(i)
    if ctx:
        ag._drop(ctx[0])
        return DONE
    return True


@internal("drop_all_desires")
def _drop_all_desires(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    ag.C.keep_events(lambda e: not (e.intention is None and e.trigger.kind == P.ACHIEVE))
    return drop_every_intention(ag, ctx)


@internal("suspend")
def _suspend(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    """``.suspend``: the running intention waits for ``.resume``; ``.suspend(G)``: so
    do the intentions pursuing ``G``."""
    need_args(args, 0, "suspend", 1)
    current = ctx[0] if ctx else None
    if not args:
        if current is None:
            raise ActionError(".suspend can only be used in a plan body")
        ag.suspend(current, True)
        return SUSPEND
    goal = resolve(args[0], s)
    stop_here = False
    for i in ag.intentions_for(goal, current):
        if i is current:
            stop_here = True
        else:
            ag.suspend(i, False)
    if stop_here and current is not None:
        ag.suspend(current, True)
        return SUSPEND
    return True


@internal("resume")
def _resume(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.resume(G)``: the suspended intentions pursuing ``G`` run again."""
    need_args(args, 1, "resume")
    for i in ag.intentions_for(resolve(args[0], s)):
        ag.resume(i)
    return True


@internal("suspended")
def _suspended(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    """``.suspended(G, R)``: a suspended intention pursues ``G``, for reason ``R``."""
    need_args(args, 2, "suspended")
    mark = len(trail)
    for i in ag.C.intentions():
        why = ag.suspension(i)
        if why is None:
            continue
        for im in i.stack:
            t = im.trigger
            if t.kind == P.ACHIEVE and t.op == "+":
                if unify(args[0], resolve(t.literal, im.s), s, trail) and unify(
                    args[1], Literal(why), s, trail
                ):
                    yield None
                undo(s, trail, mark)


@internal("drop_all_events")
def _drop_all_events(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    ag.C.keep_events(lambda e: e.intention is not None)
    return True


def _intended_goals(ag: Agent, ctx: Any) -> list[Term]:
    """The achievement goals of every live intention, the running one included."""
    goals = []
    live = ag.C.intentions() + ([ctx[0]] if ctx else [])
    for i in live:
        for im in i.stack:
            if im.trigger.kind == P.ACHIEVE and im.trigger.op == "+":
                goals.append(resolve(im.trigger.literal, im.s))
    return goals


@internal("intend")
def _intend(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 1, "intend")
    return bind_each(iter(_intended_goals(ag, ctx)), args[0], s, trail)


@internal("desire")
def _desire(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    """What is intended, and the achievement goals still waiting as events."""
    need_args(args, 1, "desire")
    goals = [
        e.trigger.literal
        for e in ag.C.events
        if e.trigger.kind == P.ACHIEVE and e.trigger.op == "+"
    ]
    goals += _intended_goals(ag, ctx)
    return bind_each(iter(goals), args[0], s, trail)
