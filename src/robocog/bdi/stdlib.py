"""Jason's standard internal actions (``.print``, ``.member``, ``.findall``, ...).

Each internal action is ``fn(agent, args, s, trail, ctx)``: ``args`` are the literal's
arguments *before* substitution, ``s`` the substitution (bind outputs in it with
``unify``), and ``ctx`` is ``(intention, intended_means, step)`` when the action runs as
a body formula, ``None`` when it is used inside a context or a condition. It returns
``True``/``False``, a generator yielding once per solution (like ``.member``), or
:data:`~robocog.bdi.agent.SUSPEND` / :data:`~robocog.bdi.agent.DONE` when it has taken
care of its intention itself.
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError, solve
from robocog.bdi.signals import DONE, SUSPEND
from robocog.bdi.terms import (
    NIL,
    Body,
    Cons,
    Literal,
    Nil,
    PlanTerm,
    Term,
    Var,
    is_list,
    iter_list,
    make_list,
    print_str,
    sort_key,
    term_str,
)
from robocog.bdi.unifier import deref, resolve, undo, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent

LIBRARY: dict[str, Callable] = {}


def internal(name: str) -> Callable[[Callable], Callable]:
    """Register an internal action under ``.name``."""

    def deco(fn: Callable) -> Callable:
        LIBRARY["." + name] = fn
        return fn

    return deco


def _need(args: tuple, n: int, name: str, most: int | None = None) -> None:
    most = n if most is None else most
    if not n <= len(args) <= most:
        raise ActionError(f".{name} takes {n}{'' if most == n else f'..{most}'} arguments")


def _list(t: Term, s: dict, name: str) -> list:
    v = resolve(t, s)
    if not is_list(v):
        raise ActionError(f".{name}: {term_str(v)} is not a list")
    return list(iter_list(v))


def _num(t: Term, s: dict, name: str) -> int | float:
    v = resolve(t, s)
    if v.__class__ is int or v.__class__ is float:
        return v
    raise ActionError(f".{name}: {term_str(v)} is not a number")


def _text(t: Term, s: dict) -> str:
    v = resolve(t, s)
    return v if v.__class__ is str else term_str(v)


def _out(value: Term, target: Term, s: dict, trail: list) -> bool:
    return unify(target, value, s, trail)


def _each(values: Iterator[Term], target: Term, s: dict, trail: list) -> Iterator[None]:
    mark = len(trail)
    for v in values:
        if unify(target, v, s, trail):
            yield None
        undo(s, trail, mark)


# ---------------------------------------------------------------- output and identity
@internal("print")
def _print(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    ag.print("".join(print_str(resolve(a, s)) for a in args))
    return True


LIBRARY[".println"] = _print


@internal("my_name")
def _my_name(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "my_name")
    return _out(Literal(ag.name), args[0], s, trail)


# ---------------------------------------------------------------- lists
@internal("length")
def _length(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "length")
    v = resolve(args[0], s)
    if v.__class__ is str:
        n = len(v)
    elif is_list(v):
        n = sum(1 for _ in iter_list(v))
    else:
        raise ActionError(f".length: {term_str(v)} is not a list or string")
    return _out(n, args[1], s, trail)


@internal("member")
def _member(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 2, "member")
    return _each(iter(_list(args[1], s, "member")), args[0], s, trail)


@internal("concat")
def _concat(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    if len(args) < 2:
        raise ActionError(".concat takes at least 2 arguments")
    parts = [resolve(a, s) for a in args[:-1]]
    if all(p.__class__ is str for p in parts) or any(p.__class__ is str for p in parts):
        if all(is_list(p) for p in parts):
            pass
        else:
            return _out("".join(print_str(p) for p in parts), args[-1], s, trail)
    items: list = []
    for p in parts:
        if not is_list(p):
            raise ActionError(f".concat: {term_str(p)} is not a list")
        items.extend(iter_list(p))
    return _out(make_list(items), args[-1], s, trail)


@internal("nth")
def _nth(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    _need(args, 3, "nth")
    items = _list(args[1], s, "nth")
    n = deref(args[0], s)
    if n.__class__ is Var:
        return _nth_all(items, args[0], args[2], s, trail)
    k = int(_num(n, s, "nth"))
    if not 0 <= k < len(items):
        return False
    return _out(items[k], args[2], s, trail)


def _nth_all(items: list, idx: Term, target: Term, s: dict, trail: list) -> Iterator[None]:
    mark = len(trail)
    for k, v in enumerate(items):
        if unify(idx, k, s, trail) and unify(target, v, s, trail):
            yield None
        undo(s, trail, mark)


@internal("max")
def _max(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "max")
    items = _list(args[0], s, "max")
    if not items:
        return False
    return _out(max(items, key=sort_key), args[1], s, trail)


@internal("min")
def _min(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "min")
    items = _list(args[0], s, "min")
    if not items:
        return False
    return _out(min(items, key=sort_key), args[1], s, trail)


@internal("sort")
def _sort(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "sort")
    items = sorted(_list(args[0], s, "sort"), key=sort_key)
    return _out(make_list(items), args[1], s, trail)


@internal("reverse")
def _reverse(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "reverse")
    v = resolve(args[0], s)
    if v.__class__ is str:
        return _out(v[::-1], args[1], s, trail)
    return _out(make_list(_list(v, s, "reverse")[::-1]), args[1], s, trail)


@internal("empty")
def _empty(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "empty")
    v = resolve(args[0], s)
    return v.__class__ is Nil or v == ""


@internal("delete")
def _delete(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "delete")
    what = resolve(args[0], s)
    v = resolve(args[1], s)
    if v.__class__ is str:
        if what.__class__ is int:
            return _out(v[:what] + v[what + 1 :], args[2], s, trail)
        return _out(v.replace(_text(what, s), ""), args[2], s, trail)
    items = _list(v, s, "delete")
    if what.__class__ is int:
        out = items[:what] + items[what + 1 :]
    else:
        out = [x for x in items if not _unifies(what, x)]
    return _out(make_list(out), args[2], s, trail)


def _unifies(a: Term, b: Term) -> bool:
    return unify(a, b, {}, [])


@internal("union")
def _union(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "union")
    out = sorted(set(_list(args[0], s, "union")) | set(_list(args[1], s, "union")), key=sort_key)
    return _out(make_list(out), args[2], s, trail)


@internal("intersection")
def _intersection(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "intersection")
    b = set(_list(args[1], s, "intersection"))
    out = sorted({x for x in _list(args[0], s, "intersection") if x in b}, key=sort_key)
    return _out(make_list(out), args[2], s, trail)


@internal("difference")
def _difference(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "difference")
    b = set(_list(args[1], s, "difference"))
    out = sorted({x for x in _list(args[0], s, "difference") if x not in b}, key=sort_key)
    return _out(make_list(out), args[2], s, trail)


@internal("range")
def _range(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 3, "range", 4)
    lo = int(_num(args[1], s, "range"))
    hi = int(_num(args[2], s, "range"))
    step = int(_num(args[3], s, "range")) if len(args) > 3 else 1
    if step == 0:
        raise ActionError(".range: step cannot be 0")
    v = deref(args[0], s)
    if v.__class__ is not Var:
        n = _num(v, s, "range")
        ok = lo <= n <= hi if step > 0 else hi <= n <= lo
        return iter([None]) if ok and (n - lo) % step == 0 else iter(())
    stop = hi + (1 if step > 0 else -1)
    return _each(iter(range(lo, stop, step)), args[0], s, trail)


@internal("list")
def _is_list(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "list")
    v = resolve(args[0], s)
    return v.__class__ in (Cons, Nil)


# ---------------------------------------------------------------- type tests
@internal("ground")
def _ground(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "ground")
    from robocog.bdi.terms import is_ground

    return is_ground(resolve(args[0], s))


@internal("atom")
def _atom(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "atom")
    v = resolve(args[0], s)
    return v.__class__ is Literal and not v.args and not v.neg


@internal("number")
def _number(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "number")
    v = resolve(args[0], s)
    return v.__class__ is int or v.__class__ is float


@internal("string")
def _string(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "string")
    return resolve(args[0], s).__class__ is str


@internal("literal")
def _literal(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "literal")
    return resolve(args[0], s).__class__ is Literal


@internal("structure")
def _structure(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "structure")
    return resolve(args[0], s).__class__ in (Literal, Cons, Nil)


@internal("var")
def _var(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "var")
    return deref(args[0], s).__class__ is Var


# ---------------------------------------------------------------- strings
@internal("term2string")
def _term2string(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "term2string")
    t = deref(args[0], s)
    if t.__class__ is not Var:
        return _out(term_str(resolve(t, s)), args[1], s, trail)
    text = resolve(args[1], s)
    if text.__class__ is not str:
        raise ActionError(".term2string: one argument must be bound")
    from robocog.bdi.parser import ParseError, parse_term

    try:
        return _out(parse_term(text), args[0], s, trail)
    except ParseError as exc:
        raise ActionError(f".term2string: {exc}") from exc


@internal("substring")
def _substring(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    _need(args, 2, "substring", 3)
    sub = _text(args[0], s)
    full = _text(args[1], s)
    if len(args) == 2:
        return sub in full
    positions = []
    k = full.find(sub)
    while k >= 0:
        positions.append(k)
        k = full.find(sub, k + 1)
    return _each(iter(positions), args[2], s, trail)


@internal("upper_case")
def _upper(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "upper_case")
    return _out(_text(args[0], s).upper(), args[1], s, trail)


@internal("lower_case")
def _lower(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "lower_case")
    return _out(_text(args[0], s).lower(), args[1], s, trail)


# ---------------------------------------------------------------- beliefs
@internal("findall")
def _findall(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "findall")
    out = []
    mark = len(trail)
    for _ in solve(ag, args[1], s, trail):
        out.append(resolve(args[0], s, {}))
    undo(s, trail, mark)
    return _out(make_list(out), args[2], s, trail)


@internal("setof")
def _setof(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "setof")
    out = []
    mark = len(trail)
    for _ in solve(ag, args[1], s, trail):
        v = resolve(args[0], s, {})
        if v not in out:
            out.append(v)
    undo(s, trail, mark)
    return _out(make_list(sorted(out, key=sort_key)), args[2], s, trail)


@internal("count")
def _count(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "count")
    n = 0
    mark = len(trail)
    for _ in solve(ag, args[0], s, trail):
        n += 1
    undo(s, trail, mark)
    return _out(n, args[1], s, trail)


@internal("abolish")
def _abolish(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "abolish")
    pattern = resolve(args[0], s)
    if pattern.__class__ is not Literal:
        raise ActionError(".abolish: argument must be a literal")
    for gone in ag.bb.abolish(pattern):
        ag.post(_event("-", P.BELIEF, gone))
    return True


def _event(op: str, kind: str, lit: Literal):  # noqa: ANN202 - Event
    from robocog.bdi.circumstance import Event

    return Event(P.Trigger(op, kind, lit), None)


# ---------------------------------------------------------------- goals and intentions
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
    err = ActionError(msg)
    for a in annots:
        if a.__class__ is Literal and a.functor == "error" and len(a.args) == 1:
            err.error = term_str(a.args[0])
    err.annots = tuple(
        a
        for a in annots
        if not (a.__class__ is Literal and a.functor in ("error", "error_msg") and len(a.args) == 1)
    )
    raise err


def _end_goal(how: str, ag: Agent, args: tuple, s: dict, ctx: Any) -> Any:
    """``.succeed_goal`` / ``.fail_goal``: end every pursuit of a goal, as ``how`` says.

    The calling intention first steps over this formula, so that when the goal it drops
    is not one of its own it simply goes on with its next formula.
    """
    _need(args, 1, f"{how}_goal")
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


@internal("drop_all_desires")
def _drop_all_desires(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    ag.C.keep_events(lambda e: not (e.intention is None and e.trigger.kind == P.ACHIEVE))
    for i in ag.C.intentions():
        ag._drop(i)
    if ctx:
        ag._drop(ctx[0])
        return DONE
    return True


@internal("suspend")
def _suspend(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    """``.suspend``: the running intention waits for ``.resume``; ``.suspend(G)``: so
    do the intentions pursuing ``G``."""
    _need(args, 0, "suspend", 1)
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
    _need(args, 1, "resume")
    for i in ag.intentions_for(resolve(args[0], s)):
        ag.resume(i)
    return True


@internal("suspended")
def _suspended(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    """``.suspended(G, R)``: a suspended intention pursues ``G``, for reason ``R``."""
    _need(args, 2, "suspended")
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


@internal("intend")
def _intend(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 1, "intend")
    goals = []
    live = ag.C.intentions() + ([ctx[0]] if ctx else [])
    for i in live:
        for im in i.stack:
            if im.trigger.kind == P.ACHIEVE and im.trigger.op == "+":
                goals.append(resolve(im.trigger.literal, im.s))
    return _each(iter(goals), args[0], s, trail)


@internal("desire")
def _desire(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 1, "desire")
    goals = [
        e.trigger.literal
        for e in ag.C.events
        if e.trigger.kind == P.ACHIEVE and e.trigger.op == "+"
    ]
    live = ag.C.intentions() + ([ctx[0]] if ctx else [])
    for i in live:
        for im in i.stack:
            if im.trigger.kind == P.ACHIEVE and im.trigger.op == "+":
                goals.append(resolve(im.trigger.literal, im.s))
    return _each(iter(goals), args[0], s, trail)


# ---------------------------------------------------------------- time
@internal("wait")
def _wait(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    _need(args, 1, "wait", 3)
    if ctx is None:
        raise ActionError(".wait can only be used in a plan body")
    i = ctx[0]
    first = resolve(args[0], s)
    if first.__class__ is int or first.__class__ is float:
        ag.add_timer(float(first), i)
        return SUSPEND
    timeout = float(_num(args[1], s, "wait")) if len(args) > 1 else None
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
    return all(_out(v, a, s, trail) for v, a in zip(values, args, strict=True))


@internal("time")
def _time(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.time(H, M, S)`` or ``.time(H, M, S, MS)``: the local time of day."""
    _need(args, 3, "time", 4)
    now = time.time()
    t = time.localtime(now)
    parts = (t.tm_hour, t.tm_min, t.tm_sec, int(now * 1000) % 1000)
    return _out_all(parts[: len(args)], args, s, trail)


@internal("date")
def _date(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "date")
    t = time.localtime()
    return _out_all((t.tm_year, t.tm_mon, t.tm_mday), args, s, trail)


@internal("random")
def _random(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.random(X)``: a number in [0, 1); ``.random(X, N)``: N of them, one per
    backtrack; ``.random(List, X)``: a member of the list."""
    _need(args, 1, "random", 2)
    rng = getattr(ag, "rng", None)
    if rng is None:
        rng = ag.rng = random.Random(0)
    if len(args) == 2:
        first = resolve(args[0], s)
        if is_list(first):
            items = list(iter_list(first))
            return bool(items) and _out(items[rng.randrange(len(items))], args[1], s, trail)
        count = _num(args[1], s, "random")
        if count.__class__ is not int or not 0 <= count <= 10**6:
            raise ActionError(".random: the count must be an integer from 0 to 1000000")
        return _each((rng.random() for _ in range(count)), args[0], s, trail)
    return _out(rng.random(), args[0], s, trail)


# ---------------------------------------------------------------- plans
@internal("add_plan")
def _add_plan(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "add_plan", 3)
    p = resolve(args[0], s)
    at_end = True
    if len(args) > 2:
        at_end = term_str(resolve(args[2], s)) != "begin"
    texts = list(iter_list(p)) if is_list(p) else [p]
    for t in texts:
        if t.__class__ is PlanTerm:
            t = t.text  # read again, so each addition is a plan of its own
        if t.__class__ is not str:
            raise ActionError(".add_plan expects a plan term or a string")
        from robocog.bdi.parser import ParseError

        try:
            ag.add_plan(t, at_end)
        except ParseError as exc:
            raise ActionError(f".add_plan: {exc}") from exc
    return True


@internal("remove_plan")
def _remove_plan(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "remove_plan", 2)
    label = resolve(args[0], s)
    names = list(iter_list(label)) if is_list(label) else [label]
    for n in names:
        ag.pl.remove(n.functor if n.__class__ is Literal else str(n))
    return True


@internal("relevant_plans")
def _relevant_plans(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.relevant_plans(Trigger, Plans[, Labels])``: the plans whose trigger unifies
    with ``Trigger`` (a plan term ``{+!g}`` or its text), as plan terms, and their labels."""
    from robocog.bdi.messages import plan_terms, trigger_of

    _need(args, 2, "relevant_plans", 3)
    trigger = trigger_of(resolve(args[0], s))
    if trigger is None:
        raise ActionError('.relevant_plans expects a trigger like {+!g} or "+!g"')
    plans = plan_terms(ag, trigger)
    if not unify(args[1], make_list(plans), s, trail):
        return False
    if len(args) > 2:
        labels = [p.plan.label for p in plans if p.plan.label is not None]
        return unify(args[2], make_list(labels), s, trail)
    return True


@internal("plan_label")
def _plan_label(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.plan_label(Plan, Label)``: the plan term of the plan labelled ``Label``."""
    from robocog.bdi.terms import PlanTerm

    _need(args, 2, "plan_label", 2)
    label = resolve(args[1], s)
    name = label.functor if label.__class__ is Literal else str(label).lstrip("@")
    plan = ag.pl.get(name)
    if plan is None:
        return False
    return unify(args[0], PlanTerm(plan, str(plan).rstrip(".")), s, trail)


# ---------------------------------------------------------------- communication
@internal("send")
def _send(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    from robocog.bdi.messages import send

    _need(args, 3, "send", 5)
    return send(ag, args, s, ctx)


@internal("broadcast")
def _broadcast(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    from robocog.bdi.messages import broadcast

    _need(args, 2, "broadcast")
    broadcast(ag, resolve(args[0], s), resolve(args[1], s))
    return True


@internal("all_names")
def _all_names(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "all_names")
    names = [ag.name] if ag.mas is None else list(ag.mas.agents)
    return _out(make_list([Literal(n) for n in names]), args[0], s, trail)


@internal("perceive")
def _perceive(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.perceive``: update the beliefs from the percepts now (with no environment
    there are none, and nothing changes)."""
    _need(args, 0, "perceive")
    ag.perceive()
    return True


@internal("stopMAS")
def _stop_mas(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    if ag.mas is not None:
        ag.mas.stopped = True
    for i in ag.C.intentions():
        ag._drop(i)
    ag.C.events.clear()
    if ctx:
        ag._drop(ctx[0])
        return DONE
    return True


__all__ = ["LIBRARY", "internal", "NIL"]


# ---------------------------------------------------------------- more of Jason's library
@internal("asserta")
def _asserta(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "asserta")
    return _assert(ag, resolve(args[0], s), at_end=False)


@internal("assertz")
def _assertz(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "assertz")
    return _assert(ag, resolve(args[0], s), at_end=True)


def _assert(ag: Agent, lit: Term, at_end: bool) -> bool:
    from robocog.bdi.terms import SOURCE_SELF

    if lit.__class__ is not Literal:
        raise ActionError("assert: argument must be a literal")
    if not lit.sources():
        lit = lit.add_annots((SOURCE_SELF,))
    if ag.bb.add(lit, at_end=at_end) is not None:
        ag.post(_event("+", P.BELIEF, lit))
    return True


@internal("puts")
def _puts(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    import re

    _need(args, 1, "puts", 2)
    text = resolve(args[0], s)
    if text.__class__ is not str:
        raise ActionError(".puts expects a string")
    values = {v.name: v for v in s if v.__class__ is Var}

    def sub(m: re.Match) -> str:
        from robocog.bdi.parser import ParseError, parse_term

        src = m.group(1)
        try:
            t = parse_term(src)
        except ParseError:
            return m.group(0)
        from robocog.bdi.unifier import variables

        mapping = {v: values[v.name] for v in variables(t) if v.name in values}
        t = resolve(resolve(t, mapping), s)
        return print_str(t)

    out = re.sub(r"#\{([^}]*)\}", sub, text)
    if len(args) > 1:
        return _out(out, args[1], s, trail)
    ag.print(out)
    return True


#: the widest field .printf pads to (a huge width would allocate gigabytes)
MAX_FORMAT_WIDTH = 10_000
#: how long a regular expression of .replace may run before it is stopped
REGEX_SECONDS = 1.0


@internal("printf")
def _printf(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    import re

    if not args:
        raise ActionError(".printf needs a format")
    fmt = resolve(args[0], s)
    if fmt.__class__ is not str:
        raise ActionError(".printf: the format must be a string")
    vals = [resolve(a, s) for a in args[1:]]
    k = 0

    def sub(m: re.Match) -> str:
        nonlocal k
        spec = m.group(0)
        if spec == "%%":
            return "%"
        if spec == "%n":
            return "\n"
        if k >= len(vals):
            raise ActionError(".printf: not enough arguments")
        v = vals[k]
        k += 1
        conv = spec[-1]
        sizes = [int(n) for n in re.findall(r"\d+", spec)]
        if any(n > MAX_FORMAT_WIDTH for n in sizes):
            raise ActionError(f".printf: a width or precision over {MAX_FORMAT_WIDTH} in {spec}")
        try:
            if conv == "s":
                return spec % print_str(v)
            if conv == "d":
                return spec % int(v)
            if conv in "feg":
                return spec % float(v)
        except (TypeError, ValueError) as exc:
            raise ActionError(f".printf: {exc}") from exc
        return spec

    ag.print(re.sub(r"%[-#+ 0,(]*\d*(?:\.\d+)?[sdfegn%]", sub, fmt))
    return True


def _sublists(items: list) -> Iterator[Term]:
    for i in range(len(items)):
        for j in range(len(items), i, -1):
            yield make_list(items[i:j])
    yield NIL


@internal("prefix")
def _prefix(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 2, "prefix")
    v = resolve(args[1], s)
    if v.__class__ is str:
        return _each((v[:j] for j in range(len(v), -1, -1)), args[0], s, trail)
    items = _list(v, s, "prefix")
    return _each((make_list(items[:j]) for j in range(len(items), -1, -1)), args[0], s, trail)


@internal("suffix")
def _suffix(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 2, "suffix")
    v = resolve(args[1], s)
    if v.__class__ is str:
        return _each((v[j:] for j in range(len(v) + 1)), args[0], s, trail)
    items = _list(v, s, "suffix")
    return _each((make_list(items[j:]) for j in range(len(items) + 1)), args[0], s, trail)


@internal("sublist")
def _sublist(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    _need(args, 2, "sublist")
    return _each(_sublists(_list(args[1], s, "sublist")), args[0], s, trail)


@internal("replace")
def _replace(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.replace(S, Regex, New, R)``, with Java's regular expressions; a pattern that
    backtracks for longer than REGEX_SECONDS is stopped with an error."""
    import regex

    _need(args, 4, "replace")
    text = _text(args[0], s)
    pattern = _text(args[1], s)
    repl = _text(args[2], s)
    try:
        out = regex.sub(pattern, repl.replace("\\", "\\\\"), text, timeout=REGEX_SECONDS)
    except regex.error as exc:
        raise ActionError(f".replace: {exc}") from exc
    except TimeoutError as exc:
        raise ActionError(f".replace: the pattern ran longer than {REGEX_SECONDS} s") from exc
    return _out(out, args[3], s, trail)


@internal("copy_term")
def _copy_term(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "copy_term")
    return _out(resolve(args[0], s, {}), args[1], s, trail)


@internal("add_annot")
def _add_annot(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 3, "add_annot")
    t = resolve(args[0], s)
    a = resolve(args[1], s)
    if t.__class__ is Literal:
        extra = list(iter_list(a)) if is_list(a) else [a]
        t = t.add_annots(extra)
    elif is_list(t):
        extra = list(iter_list(a)) if is_list(a) else [a]
        t = make_list([x.add_annots(extra) if x.__class__ is Literal else x for x in iter_list(t)])
    return _out(t, args[2], s, trail)


@internal("eval")
def _eval(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "eval")
    from robocog.bdi.logic import holds

    mark = len(trail)
    ok = holds(ag, args[1], s, trail)
    undo(s, trail, mark)
    return _out(Literal("true" if ok else "false"), args[0], s, trail)


@internal("shuffle")
def _shuffle(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 2, "shuffle")
    items = _list(args[0], s, "shuffle")
    rng = getattr(ag, "rng", None)
    if rng is None:
        rng = ag.rng = random.Random(0)
    rng.shuffle(items)
    return _out(make_list(items), args[1], s, trail)


@internal("set_random_seed")
def _set_random_seed(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "set_random_seed")
    ag.rng = random.Random(int(_num(args[0], s, "set_random_seed")))
    return True


@internal("drop_event")
def _drop_event(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    _need(args, 1, "drop_event")
    goal = resolve(args[0], s)
    ag.C.keep_events(lambda e: not (e.intention is None and _unifies(goal, e.trigger.literal)))
    return True
