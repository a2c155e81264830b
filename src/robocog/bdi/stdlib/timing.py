"""Time and chance: ``.wait``, ``.time``, ``.date``, ``.random``."""

from __future__ import annotations

import random
import time
import zlib
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError
from robocog.bdi.signals import SUSPEND
from robocog.bdi.stdlib.base import arg_number, bind, bind_each, internal, need_args
from robocog.bdi.terms import Body, Literal, PlanTerm, Term, is_list, iter_list, term_str
from robocog.bdi.unifier import resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("wait")
def _wait(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    need_args(args, 1, "wait", 3)
    if ctx is None:
        raise ActionError(".wait can only be used in a plan body")
    i = ctx[0]
    first = resolve(args[0], s)
    if first.__class__ is int or first.__class__ is float:
        ag.add_timer(float(first), i)
        return SUSPEND
    timeout = float(arg_number(args[1], s, "wait")) if len(args) > 1 else None
    if len(args) > 2:
        ag.wait_elapsed[i.id] = (args[2], ag.clock)
    trig = _trigger_of(first)
    if trig is not None:
        ag.wait_event(trig, i, timeout)
        return SUSPEND
    from robocog.bdi.logic import holds
    from robocog.bdi.terms import And, Not, Or, Rel

    f = args[0]
    if resolve(f, s).__class__ not in (Literal, Rel, And, Or, Not):
        raise ActionError(f".wait: cannot wait for {term_str(first)}")
    if holds(ag, f, s, trail):
        return True
    ag.wait_formula(f, i, timeout)
    return SUSPEND


def _trigger_of(t: Term) -> P.Trigger | None:
    if t.__class__ is PlanTerm:
        return t.plan.trigger
    if t.__class__ is str:
        from robocog.bdi.parser import ParseError, parse_plan

        try:
            return parse_plan(t).trigger
        except ParseError:
            return None
    if t.__class__ is Body and len(t.steps) == 1:
        st = t.steps[0]
        kinds = {
            P.ADD_BEL: ("+", P.BELIEF),
            P.DEL_BEL: ("-", P.BELIEF),
            P.ACHIEVE_STEP: ("+", P.ACHIEVE),
        }
        if st.kind in kinds:
            op, kind = kinds[st.kind]
            return P.Trigger(op, kind, st.term)
    return None


def _out_all(values: tuple, args: tuple, s: dict, trail: list) -> bool:
    """Unify each argument with its value, in order, stopping at the first mismatch."""
    return all(bind(v, a, s, trail) for v, a in zip(values, args, strict=True))


@internal("time")
def _time(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.time(H, M, S)`` or ``.time(H, M, S, MS)``: the local time of day."""
    need_args(args, 3, "time", 4)
    now = time.time()
    t = time.localtime(now)
    parts = (t.tm_hour, t.tm_min, t.tm_sec, int(now * 1000) % 1000)
    return _out_all(parts[: len(args)], args, s, trail)


@internal("date")
def _date(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "date")
    t = time.localtime()
    return _out_all((t.tm_year, t.tm_mon, t.tm_mday), args, s, trail)


@internal("random")
def _random(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.random(X)``: a number in [0, 1); ``.random(X, N)``: N of them, one per
    backtrack; ``.random(List, X)``: a member of the list."""
    need_args(args, 1, "random", 2)
    rng = getattr(ag, "rng", None)
    if rng is None:
        # each agent its own sequence (agents from one program differ), reproducible
        rng = ag.rng = random.Random(zlib.crc32(ag.name.encode()))
    if len(args) == 2:
        first = resolve(args[0], s)
        if is_list(first):
            items = list(iter_list(first))
            return bool(items) and bind(items[rng.randrange(len(items))], args[1], s, trail)
        count = arg_number(args[1], s, "random")
        if count.__class__ is not int or not 0 <= count <= 10**6:
            raise ActionError(".random: the count must be an integer from 0 to 1000000")
        return bind_each((rng.random() for _ in range(count)), args[0], s, trail)
    return bind(rng.random(), args[0], s, trail)
