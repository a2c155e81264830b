"""Logical consequence: contexts, rule bodies, test goals and conditions.

``solve`` is a Prolog-style generator: it yields once for each solution, with the
bindings of that solution present in the substitution, and removes them before
looking for the next one. Solutions come in a fixed order (belief base order, then
left to right), so an agent is deterministic.
"""

from __future__ import annotations

import itertools
import operator
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING

from robocog.bdi.nsterm import DEFAULT, NsLiteral, split_ns, with_ns
from robocog.bdi.terms import (
    NS_SEP,
    And,
    Body,
    Literal,
    Not,
    Or,
    PlanTerm,
    Rel,
    RuleTerm,
    Term,
    Var,
    compare,
    term_str,
)
from robocog.bdi.unifier import EvalError, deref, evaluate, resolve, undo, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


class ActionError(Exception):
    """An internal action was called wrongly; becomes an ``ia_failed`` goal failure."""

    def __init__(self, message: str, error: str = "ia_failed") -> None:
        super().__init__(message)
        self.error = error


def solve(agent: Agent, f: Term, s: dict, trail: list) -> Iterator[None]:
    """Yield once per way ``f`` follows from the agent's beliefs (bindings left in ``s``)."""
    c = f.__class__
    if c is Var:
        f = deref(f, s)
        c = f.__class__
        if c is Var:
            raise ActionError(f"unbound variable {f.name} used as a formula")
    if c is Literal:
        functor = f.functor
        if functor[0] == "." or ("." in functor and agent.internal_action(functor) is not None):
            # Jason's own (``.print``) or a library's (``mylib.act``)
            yield from _internal(agent, f, s, trail)
            return
        if not f.args and not f.neg and not f.annots:
            if functor == "true":
                yield None
                return
            if functor == "false":
                return
        yield from agent.bb.query(f, s, trail, agent)
        return
    if c is And:
        for _ in solve(agent, f.left, s, trail):
            yield from solve(agent, f.right, s, trail)
        return
    if c is Or:
        yield from solve(agent, f.left, s, trail)
        yield from solve(agent, f.right, s, trail)
        return
    if c is Not:
        mark = len(trail)
        for _ in solve(agent, f.arg, s, trail):
            undo(s, trail, mark)
            return
        yield None
        return
    if c is Rel:
        mark = len(trail)
        if relation(f, s, trail):
            yield None
        undo(s, trail, mark)
        return
    if c is NsLiteral:
        yield from _solve_ns(agent, f, s, trail)
        return
    if c is Body:
        raise ActionError("a plan body is not a logical formula")
    raise ActionError(f"{term_str(f)} is not a logical formula")


def _solve_ns(agent: Agent, f: NsLiteral, s: dict, trail: list) -> Iterator[None]:
    """A literal whose namespace is a variable: asked in that namespace once it has a
    value, else in each namespace the agent knows (in the order it met them)."""
    r = resolve(f, s)
    if r.__class__ is Literal:
        yield from solve(agent, r, s, trail)
        return
    seen: dict[str, None] = {DEFAULT: None}
    for b in agent.bb:
        seen[split_ns(b)[0]] = None
    for p in agent.pl:
        if p.trigger is not None and p.trigger.literal.__class__ is Literal:
            seen[split_ns(p.trigger.literal)[0]] = None
    for ns in seen:
        mark = len(trail)
        if unify(f.ns, Literal(ns), s, trail):
            yield from solve(agent, with_ns(ns, f.lit), s, trail)
        undo(s, trail, mark)


_TRUTH = ("true", "false")

#: the comparisons ``relation`` decides at once when both sides are numbers
_NUM_OPS = {
    ">": operator.gt,
    "<": operator.lt,
    ">=": operator.ge,
    "<=": operator.le,
    "==": operator.eq,
}


def holds(agent: Agent, f: Term, s: dict, trail: list) -> bool:
    """First solution of ``f``: its bindings stay in ``s``; False leaves ``s`` unchanged."""
    c = f.__class__
    if c is Rel:
        mark = len(trail)
        if relation(f, s, trail):
            return True
        undo(s, trail, mark)
        return False
    if c is And:
        left = f.left
        if left.__class__ is Rel or left.__class__ is Not:
            # a deterministic left side needs no backtracking into it
            mark = len(trail)
            if holds(agent, left, s, trail) and holds(agent, f.right, s, trail):
                return True
            undo(s, trail, mark)
            return False
        if (
            left.__class__ is Literal
            and left.functor[0] != "."
            and (left.args or left.functor not in _TRUTH)
        ):
            # a fact query with at most one answer needs no backtracking either
            mark = len(trail)
            got = agent.bb.first_det(left, s, trail)
            if got is False:
                return False
            if got is True:
                if holds(agent, f.right, s, trail):
                    return True
                undo(s, trail, mark)
                return False
    elif c is Not:
        mark = len(trail)
        if holds(agent, f.arg, s, trail):
            undo(s, trail, mark)
            return False
        return True
    elif c is Literal and f.functor[0] != "." and (f.args or f.functor not in _TRUTH):
        got = agent.bb.first(f, s, trail)
        if got is not None:
            return got
    for _ in solve(agent, f, s, trail):
        return True
    return False


def right_assoc(f: Term) -> Term:
    """``(a & b) & c`` as ``a & (b & c)``: the same solutions in the same order, but the
    left side of each conjunction is a single formula, which :func:`holds` can often
    decide without a generator."""
    if f.__class__ is And:
        left = f.left
        if left.__class__ is And:
            return right_assoc(And(left.left, And(left.right, f.right)))
        right = right_assoc(f.right)
        return f if right is f.right else And(left, right)
    return f


def compile_cond(f: Term) -> Callable[[Agent, dict, list], bool]:
    """A function ``test(agent, s, trail)`` that does what ``holds(agent, f, s, trail)``
    does, with the dispatch on the shape of ``f`` done once (plan contexts are tested
    at every event for their trigger)."""
    c = f.__class__
    if c is Rel:
        num = _NUM_OPS.get(f.op)
        if num is not None:
            left, right = f.left, f.right

            def test_num(agent: Agent, s: dict, trail: list) -> bool:
                a = left
                while a.__class__ is Var:
                    v = s.get(a)
                    if v is None:
                        break
                    a = v
                b = right
                while b.__class__ is Var:
                    v = s.get(b)
                    if v is None:
                        break
                    b = v
                ca = a.__class__
                cb = b.__class__
                if (ca is int or ca is float) and (cb is int or cb is float):
                    return num(a, b)
                mark = len(trail)
                if relation(f, s, trail):
                    return True
                undo(s, trail, mark)
                return False

            return test_num

        def test_rel(agent: Agent, s: dict, trail: list) -> bool:
            mark = len(trail)
            if relation(f, s, trail):
                return True
            undo(s, trail, mark)
            return False

        return test_rel
    if c is Not:
        inner = compile_cond(f.arg)

        def test_not(agent: Agent, s: dict, trail: list) -> bool:
            mark = len(trail)
            if inner(agent, s, trail):
                undo(s, trail, mark)
                return False
            return True

        return test_not
    if _is_fact_query(f):
        key = (f.functor, len(f.args), f.neg)

        def test_lit(agent: Agent, s: dict, trail: list) -> bool:
            bb = agent.bb
            if key not in bb._index:
                return False  # nothing of that predicate (first would say so)
            got = bb.first(f, s, trail, key)
            if got is not None:
                return got
            for _ in solve(agent, f, s, trail):
                return True
            return False

        return test_lit
    if c is And:
        left = f.left
        right = compile_cond(f.right)
        num = _NUM_OPS.get(left.op) if left.__class__ is Rel else None
        if num is not None:
            # ``N > 0 & ...``: the comparison of numbers done in place
            a0, b0 = left.left, left.right

            def test_and_num(agent: Agent, s: dict, trail: list) -> bool:
                a = a0
                while a.__class__ is Var:
                    v = s.get(a)
                    if v is None:
                        break
                    a = v
                b = b0
                while b.__class__ is Var:
                    v = s.get(b)
                    if v is None:
                        break
                    b = v
                ca = a.__class__
                cb = b.__class__
                if (ca is int or ca is float) and (cb is int or cb is float):
                    return num(a, b) and right(agent, s, trail)
                mark = len(trail)
                if relation(left, s, trail) and right(agent, s, trail):
                    return True
                undo(s, trail, mark)
                return False

            return test_and_num
        if left.__class__ is Rel or left.__class__ is Not:
            first = compile_cond(left)

            def test_and(agent: Agent, s: dict, trail: list) -> bool:
                mark = len(trail)
                if first(agent, s, trail) and right(agent, s, trail):
                    return True
                undo(s, trail, mark)
                return False

            return test_and
        if _is_fact_query(left):
            key = (left.functor, len(left.args), left.neg)

            def test_and_lit(agent: Agent, s: dict, trail: list) -> bool:
                bb = agent.bb
                if key not in bb._index:
                    return False  # nothing of that predicate (first_det would say so)
                mark = len(trail)
                got = bb.first_det(left, s, trail, key)
                if got is False:
                    return False
                if got is True:
                    if right(agent, s, trail):
                        return True
                    undo(s, trail, mark)
                    return False
                for _ in solve(agent, f, s, trail):
                    return True
                return False

            return test_and_lit

    def test(agent: Agent, s: dict, trail: list) -> bool:
        return holds(agent, f, s, trail)

    return test


def _is_fact_query(f: Term) -> bool:
    return (
        f.__class__ is Literal and f.functor[0] != "." and bool(f.args or f.functor not in _TRUTH)
    )


def relation(f: Rel, s: dict, trail: list) -> bool:
    """Evaluate a relational expression, binding for ``=`` and ``=..``."""
    op = f.op
    left = f.left
    right = f.right
    lc = left.__class__
    if lc is Var:
        left = deref(left, s)
        lc = left.__class__
    rc = right.__class__
    if rc is Var:
        right = deref(right, s)
        rc = right.__class__
    if (lc is int or lc is float) and (rc is int or rc is float):
        if op == ">":
            return left > right
        if op == "<":
            return left < right
        if op == ">=":
            return left >= right
        if op == "<=":
            return left <= right
        if op == "==":
            return left == right
    try:
        left = evaluate(left, s)
        right = evaluate(right, s)
    except EvalError as exc:
        raise ActionError(str(exc)) from exc
    if op == "=":
        return unify(left, right, s, trail)
    if op == "\\=":
        mark = len(trail)
        ok = unify(left, right, s, trail)
        undo(s, trail, mark)
        return not ok
    if op == "==":
        return _equal(left, right, s)
    if op == "\\==":
        return not _equal(left, right, s)
    if op == "=..":
        return _univ(left, right, s, trail)
    lc, rc = left.__class__, right.__class__
    if (lc is int or lc is float) and (rc is int or rc is float):
        a, b = left, right
        if op == "<":
            return a < b
        if op == "<=":
            return a <= b
        if op == ">":
            return a > b
        if op == ">=":
            return a >= b
    else:
        left = resolve(left, s)
        right = resolve(right, s)
        if left.__class__ is Var or right.__class__ is Var:
            return False
        cmp = compare(left, right)
        if op == "<":
            return cmp < 0
        if op == "<=":
            return cmp <= 0
        if op == ">":
            return cmp > 0
        if op == ">=":
            return cmp >= 0
    raise ActionError(f"unknown operator {op}")


def _equal(a: Term, b: Term, s: dict) -> bool:
    a = resolve(a, s)
    b = resolve(b, s)
    if a.__class__ is Var or b.__class__ is Var:
        return a is b
    if (a.__class__ in (int, float)) != (b.__class__ in (int, float)):
        return False
    return a == b


#: the namespace of every literal (Jason's ``default``)
DEFAULT_NS = Literal("default")


def _plan_parts(t: PlanTerm) -> Term:
    """``{@l +!g : c <- b} =.. [L, T, C, B]``: the label as Jason gives it, the trigger
    (a plan term of the trigger alone), the context (``true`` when there is none) and
    the body as a body term, with fresh variables shared by the four."""
    from robocog.bdi.terms import make_list
    from robocog.bdi.unifier import rename, variables

    plan = t.plan
    label = t.label if t.label is not None else Literal("l")
    context = plan.context if plan.context is not None else Literal("true")
    steps = []
    chain = plan.body
    while chain is not None:
        steps.append(chain[0])
        chain = chain[1]
    body = Body(tuple(steps))
    trig = plan.trigger
    found = variables(context, variables(trig.literal))
    for st in body.steps:
        if not st.blocks and st.term is not None and not isinstance(st.term, str):
            variables(st.term, found)
    mapping = {v: Var(f"_{next(_fresh)}") for v in found if v.name != "_"}
    lit = rename(trig.literal, mapping)
    only = plan.__class__(trig.__class__(trig.op, trig.kind, lit), None, None)
    trigger = PlanTerm(only, repr(trig), bare=True)
    return make_list([label, trigger, rename(context, mapping), rename(body, mapping)])


_fresh = itertools.count(20)


def _univ(left: Term, right: Term, s: dict, trail: list) -> bool:
    from robocog.bdi.terms import NIL, Cons, iter_list, list_items, make_list

    left = resolve(left, s)
    if left.__class__ is PlanTerm:
        return unify(_plan_parts(left), right, s, trail)
    if left.__class__ is RuleTerm:
        left = left.head  # Jason takes a rule apart as its head
    if left.__class__ is Literal:
        # Jason 3.3: [namespace, functor, args, annotations]; robocog has the default
        # namespace only
        ns, _sep, f = left.functor.rpartition(NS_SEP)
        shape = list_items(resolve(right, s))
        if shape is not None and len(shape) == 3 and not ns:
            # the older form, [functor, args, annotations], which Jason 3.3 still takes
            parts = make_list([Literal(f), make_list(left.args), make_list(left.annots)])
            return unify(parts, right, s, trail)
        parts = make_list(
            [
                Literal(ns) if ns else DEFAULT_NS,
                Literal(f),
                make_list(left.args),
                make_list(left.annots),
            ]
        )
        return unify(parts, right, s, trail)
    right = resolve(right, s)
    if right.__class__ is Cons:
        items = list(iter_list(right))
        ns = None
        if len(items) == 4 and items[0].__class__ is Literal:
            ns = items[0].functor  # the namespace first, as Jason 3.3 writes it
            items = items[1:]
        if not items or items[0].__class__ is not Literal:
            return False
        args = tuple(iter_list(items[1])) if len(items) > 1 else ()
        annots = tuple(iter_list(items[2])) if len(items) > 2 else ()
        f = items[0].functor
        if ns is not None and ns != DEFAULT_NS.functor:
            f = f"{ns}{NS_SEP}{f}"
        lit = Literal(f, args, annots)
        return unify(left, lit, s, trail)
    return right is NIL and False


def _internal(agent: Agent, lit: Literal, s: dict, trail: list) -> Iterator[None]:
    """An internal action used as a formula (in a context, condition or rule)."""
    fn = agent.internal_action(lit.functor)
    if fn is None:
        raise ActionError(unknown_action(lit))
    result = fn(agent, lit.args, s, trail, None)
    if result is True:
        yield None
    elif result is False or result is None:
        return
    else:
        yield from result


#: internal actions of Jason 3.3's standard library that robocog does not have
NOT_SUPPORTED = frozenset(
    {
        ".list_rules",
        ".save_agent", ".at", ".print_unifier",
        ".verbose", ".add_nested_source", ".current_intention", ".intention", ".signal",
    }
)  # fmt: skip


def unknown_action(lit: Literal) -> str:
    """The error of an internal action robocog does not run: Jason's own ones are named
    as not supported, anything else as unknown."""
    name = f"{lit.functor}/{len(lit.args)}"
    if lit.functor in NOT_SUPPORTED:
        return f"not supported: {name}"
    return f"unknown internal action {name}"
