"""Small functions over formulas and intentions that several steps of the reasoning cycle use."""

from __future__ import annotations

from typing import Any

from robocog.bdi import plans as P
from robocog.bdi.circumstance import (
    IntendedMeans,
    Intention,
)
from robocog.bdi.plans import (
    ACHIEVE_STEP,
)
from robocog.bdi.terms import (
    SOURCE_SELF,
    Arith,
    Cons,
    Literal,
    Term,
    Var,
    is_ground,
)
from robocog.bdi.unifier import (
    resolve,
    unify,
    variables,
)

#: why an environment action fails in an agent that has no environment at all
NO_ENVIRONMENT = "no environment configured!"


def with_source(lit: Literal, src: Literal = SOURCE_SELF) -> Literal:
    annots = lit.annots
    if not annots:
        return Literal.make(lit.functor, lit.args, (src,), lit.neg, lit.ground and src.ground)
    for a in annots:
        if a.__class__ is Literal and a.functor == "source":
            return lit
    return lit.add_annots((src,))


def sourced(step: P.Step) -> Term:
    """The belief term of a ``+b``/``-b``/``-+b`` step with ``source(self)`` added when it
    has no source (computed once: resolving keeps ground annotations as they are)."""
    got = step.cache
    if got is None:
        term = step.term
        got = term
        if term.__class__ is Literal:
            for a in term.annots:
                if not is_ground(a):
                    break
            else:
                got = with_source(term)
        step.cache = got
    return got


def remember(step: P.Step, term: Term, s: dict, built: Any) -> None:
    """Keep ``built`` in ``step.memo`` when ``term`` (a literal without arithmetic) has a
    single variable whose value is ground: while that variable has the very same value,
    resolving ``term`` would build the same thing, so ``_execute`` reuses it."""
    memo = step.memo
    if memo is False:
        return
    if memo is None:
        vs = variables(term) if term.__class__ is Literal and not has_arith(term) else ()
        if len(vs) != 1:
            step.memo = False
            return
        var = vs[0]
    else:
        var = memo[0]
    x = s.get(var)
    while x.__class__ is Var:
        x = s.get(x)
    if x is not None and is_ground(x):
        step.memo = (var, x, built)


def has_arith(t: Term) -> bool:
    c = t.__class__
    if c is Arith:
        return True
    if c is Literal:
        return any(has_arith(a) for a in t.args) or any(has_arith(a) for a in t.annots)
    if c is Cons:
        return has_arith(t.head) or has_arith(t.tail)
    return False


def is_atomic(i: Intention) -> bool:
    for im in i.stack:
        label = im.plan.label
        if label is not None and label.annots:
            for a in label.annots:
                if a.__class__ is Literal and a.functor == "atomic":
                    return True
    return False


def awaits(im: IntendedMeans, goal: Term) -> bool:
    """True when ``im`` stands at ``!goal`` (a step an internal action stepped over,
    such as ``.fail_goal``, is None and awaits nothing)."""
    cur = im.cur
    if cur is None or cur[0] is None:
        return False
    return cur[0].kind == ACHIEVE_STEP and unifies_under(cur[0].term, goal, im.s)


def unifies_under(a: Term, b: Term, s: dict) -> bool:
    """Test unification without keeping any binding."""
    trail: list = []
    ok = unify(a, b, s, trail)
    for v in trail:
        del s[v]
    return ok


def propagate(val: Term, chain: tuple | None) -> Term:
    """Give ``val`` back through the frames tail recursion removed (innermost first)."""
    while chain is not None:
        (step_term, s2, trig_lit), chain = chain
        unify(step_term, val, s2, [])
        val = resolve(trig_lit, s2)
    return val
