"""Unification, substitution and arithmetic evaluation.

A substitution is a plain ``dict`` from :class:`Var` to term. Unification binds
variables in place and records each new binding on a *trail* (a list), so that a
caller exploring alternatives (the belief base, rules, ``|``) can undo exactly what one
attempt bound with :func:`undo`. Each intended means owns its own substitution, which is
what lets one plan be instantiated many times without copying its body.

Annotations follow Jason: ``unify(a, b)`` requires the annotations of ``a`` to be a
subset of those of ``b`` (so a query ``p[source(percept)]`` finds only perceived ``p``).
"""

from __future__ import annotations

import math
import random
import time
from collections.abc import Iterator
from typing import Any

from robocog.bdi.containers import QueueTerm, SetTerm
from robocog.bdi.context import running
from robocog.bdi.nsterm import NsLiteral, ns_rename, ns_resolve, ns_unify
from robocog.bdi.terms import (
    NIL,
    And,
    AnnotTail,
    Arith,
    Body,
    Cons,
    Literal,
    Nil,
    Not,
    Or,
    PlanTerm,
    Rel,
    Term,
    Var,
    fresh_var,
    is_ground,
    sort_annots,
)

_new = object.__new__


class EvalError(Exception):
    """An arithmetic expression could not be evaluated (unbound variable, bad type)."""


def deref(t: Term, s: dict) -> Term:
    """Follow variable bindings until a non-variable or an unbound variable."""
    while t.__class__ is Var:
        v = s.get(t)
        if v is None:
            return t
        t = v
    return t


def undo(s: dict, trail: list, mark: int) -> None:
    """Remove the bindings recorded on ``trail`` after position ``mark``."""
    while len(trail) > mark:
        del s[trail.pop()]


def unify(a: Term, b: Term, s: dict, trail: list) -> bool:
    """Unify ``a`` with ``b`` under ``s``; on failure some bindings may remain on the trail."""
    while True:
        while a.__class__ is Var:
            v = s.get(a)
            if v is None:
                break
            a = v
        while b.__class__ is Var:
            v = s.get(b)
            if v is None:
                break
            b = v
        ca = a.__class__
        cb = b.__class__
        if ca is Var:
            if a is b:
                return True
            s[a] = b
            trail.append(a)
            return True
        if cb is Var:
            s[b] = a
            trail.append(b)
            return True
        if ca is Literal:
            if cb is not Literal:
                if cb is Arith:
                    return unify(a, evaluate(b, s), s, trail)
                return cb is NsLiteral and ns_unify(b, a, s, trail, unify)
            if a is b:
                return True
            if a.functor != b.functor or a.neg != b.neg:
                return False
            aa = a.args
            ba = b.args
            if len(aa) != len(ba):
                return False
            if a.ground and b.ground:
                if aa != ba:
                    return False
            else:
                for x, y in zip(aa, ba):  # noqa: B905 - same length, checked above
                    if not unify(x, y, s, trail):
                        return False
            if a.annots:
                return annots_subset(a.annots, b.annots, s, trail)
            return True
        if ca is Cons:
            if cb is not Cons:
                return False
            if a is b:
                return True
            if not unify(a.head, b.head, s, trail):
                return False
            a = a.tail
            b = b.tail
            continue
        if ca is Arith:
            try:
                a = evaluate(a, s)
            except EvalError:  # 1 div 0 equals nothing
                return False
            if a.__class__ is Arith:
                return False
            continue
        if cb is Arith:
            try:
                b = evaluate(b, s)
            except EvalError:  # 1 div 0 equals nothing
                return False
            if b.__class__ is Arith:
                return False
            continue
        if ca is int or ca is float:
            return (cb is int or cb is float) and a == b
        if ca is str:
            return cb is str and a == b
        if ca is Nil:
            return cb is Nil
        if ca is Body:
            return cb is Body and unify_bodies(a, b, s, trail)
        if ca is PlanTerm:
            return cb is PlanTerm and (a is b or unify_plans(a, b, s, trail))
        if ca is NsLiteral:
            return ns_unify(a, b, s, trail, unify)
        return a == b


def annots_subset(aa: tuple, ba: tuple, s: dict, trail: list) -> bool:
    """Jason's rule for annotations: each of ``aa`` unifies with one of ``ba``."""
    if aa[-1].__class__ is AnnotTail:
        return _with_tail(aa, ba, s, trail)
    for x in aa:
        for y in ba:
            mark = len(trail)
            if unify(x, y, s, trail):
                break
            undo(s, trail, mark)
        else:
            return False
    return True


def _with_tail(aa: tuple, ba: tuple, s: dict, trail: list) -> bool:
    """``aa`` ends with a tail ``|T``: each of its other annotations takes the first of
    ``ba`` it unifies with that no other took (constants sort before variables, so
    they choose first), and ``T`` unifies with the list of those left, in order."""
    used = [False] * len(ba)
    for x in aa[:-1]:
        for j, y in enumerate(ba):
            if used[j] or y.__class__ is AnnotTail:
                continue
            mark = len(trail)
            if unify(x, y, s, trail):
                used[j] = True
                break
            undo(s, trail, mark)
        else:
            return False
    rest: Term = NIL
    for j in range(len(ba) - 1, -1, -1):
        if not used[j] and ba[j].__class__ is not AnnotTail:
            rest = Cons(ba[j], rest)
    return unify(aa[-1].var, rest, s, trail)


def resolve_annots(annots: tuple, s: dict, fresh: dict | None) -> tuple:
    """``annots`` under ``s``: a tail bound to a list gives its elements, sorted in."""
    out = []
    for a in annots:
        if a.__class__ is AnnotTail:
            v = resolve(a.var, s, fresh)
            if v.__class__ is Cons or v.__class__ is Nil:
                while v.__class__ is Cons:
                    out.append(v.head)
                    v = v.tail
                if v.__class__ is not Nil:
                    out.append(AnnotTail(v))
            else:
                out.append(AnnotTail(v))
        else:
            out.append(resolve(a, s, fresh))
    return sort_annots(out)


def annots_ways(aa: tuple, ba: tuple, s: dict, trail: list, k: int = 0) -> Iterator[None]:
    """Each way every annotation of ``aa`` unifies with one of ``ba`` (bindings in ``s``,
    undone between ways): the backtracking form of :func:`annots_subset`."""
    if k == 0 and aa and aa[-1].__class__ is AnnotTail:
        mark = len(trail)
        if _with_tail(aa, ba, s, trail):
            yield None
        undo(s, trail, mark)
        return
    if k == len(aa):
        yield None
        return
    x = aa[k]
    for y in ba:
        mark = len(trail)
        if unify(x, y, s, trail):
            yield from annots_ways(aa, ba, s, trail, k + 1)
        undo(s, trail, mark)


def resolve(t: Term, s: dict, fresh: dict | None = None) -> Term:
    """Apply ``s`` to ``t`` and evaluate arithmetic whose operands are numbers.

    With ``fresh`` (a dict), variables still unbound are replaced by new variables (the
    same new variable for each occurrence); this is how terms leave a plan's scope
    without their variables clashing with another instance of the same plan.
    """
    c = t.__class__
    if c is Var:
        while True:
            v = s.get(t)
            if v is None:
                break
            t = v
            if t.__class__ is not Var:
                return resolve(t, s, fresh)
        if fresh is None:
            return t
        nv = fresh.get(t)
        if nv is None:
            nv = fresh[t] = fresh_var()
        return nv
    if c is Literal:
        if t.ground:
            return t
        args = []
        ground = True
        for a in t.args:
            ac = a.__class__
            if ac is Var:
                v = s.get(a)
                while v is not None and v.__class__ is Var:
                    a = v
                    v = s.get(a)
                if v is None:
                    if fresh is not None:
                        nv = fresh.get(a)
                        if nv is None:
                            nv = fresh[a] = fresh_var()
                        a = nv
                    ground = False
                else:
                    vc = v.__class__
                    if vc is int or vc is float or vc is str:
                        a = v
                    elif v.ground:
                        a = v
                    else:
                        a = resolve(v, s, fresh)
                        if ground and not is_ground(a):
                            ground = False
            elif ac is int or ac is float or ac is str:
                pass
            elif a.ground:
                pass
            elif ac is Arith:
                # the common ``X + 1`` / ``X - 1`` on integers, else evaluate()
                x = a.left
                if x.__class__ is Var:
                    x = s.get(x)
                y = a.right
                if (
                    x.__class__ is int
                    and y.__class__ is int
                    and (a.op == "+" or a.op == "-")
                    and -(2**62) < x < 2**62
                    and -(2**62) < y < 2**62
                ):
                    a = x + y if a.op == "+" else x - y
                else:
                    a = evaluate(a, s, fresh, False)
                    if ground and a.__class__ is not int and a.__class__ is not float:
                        ground = is_ground(a)
            else:
                a = resolve(a, s, fresh)
                if ground and not is_ground(a):
                    ground = False
            args.append(a)
        annots = t.annots
        if annots:
            for a in annots:
                if a.__class__ is not Literal or not a.ground:
                    break
            else:
                # ground annotations (typically ``source(self)``) are kept as they are
                out = _new(Literal)
                out.functor = t.functor
                out.args = tuple(args)
                out.annots = annots
                out.neg = t.neg
                out.ground = ground
                out._hash = None
                return out
            annots = resolve_annots(annots, s, fresh)
            if ground:
                for a in annots:
                    if not is_ground(a):
                        ground = False
                        break
        return Literal.make(t.functor, tuple(args), annots, t.neg, ground)
    if c is int or c is float or c is str:
        return t
    if c is Cons:
        if t.ground:
            return t
        items = []
        while t.__class__ is Cons and not t.ground:
            items.append(resolve(t.head, s, fresh))
            t = t.tail
            while t.__class__ is Var:
                v = s.get(t)
                if v is None:
                    break
                t = v
        # a ground tail (typically an accumulator) is shared, not copied
        out = t if t.__class__ is Cons or t.__class__ is Nil else resolve(t, s, fresh)
        for item in reversed(items):
            out = Cons(item, out)
        return out
    if c is Arith:
        return evaluate(t, s, fresh, strict=False)
    if c is Rel:
        return Rel(t.op, resolve(t.left, s, fresh), resolve(t.right, s, fresh))
    if c is And:
        return And(resolve(t.left, s, fresh), resolve(t.right, s, fresh))
    if c is Or:
        return Or(resolve(t.left, s, fresh), resolve(t.right, s, fresh))
    if c is Not:
        return Not(resolve(t.arg, s, fresh))
    if c is Body:
        return map_body(t, lambda x: resolve(x, s, fresh))
    if c is NsLiteral:
        return ns_resolve(t, s, fresh, resolve)
    return t


def map_body(t: Body, fn: Any) -> Body:
    """The same body with ``fn`` applied to the term of each plain formula (those
    without blocks of their own: ``if``/``while``/``for`` steps are kept)."""
    out = []
    for st in t.steps:
        if st.blocks or st.term is None or isinstance(st.term, str):
            out.append(st)
        else:
            out.append(st.__class__(st.kind, fn(st.term), st.blocks, st.line, st.state))
    return Body(tuple(out), t.bare)


def var_step(t: Body, k: int) -> Var | None:
    """The variable of step ``k`` of ``t`` when the step is a bare variable (``{H; R}``)."""
    st = t.steps[k]
    v = st.term
    if v.__class__ is Var and not st.blocks and repr(st) == v.name:
        return v
    return None


def _steps(chain: Any) -> list:
    """The steps of a body chain (nested ``(step, rest)`` pairs)."""
    out = []
    while chain is not None:
        out.append(chain[0])
        chain = chain[1]
    return out


def _chain(steps: list) -> Any:
    out = None
    for st in reversed(steps):
        out = (st, out)
    return out


def unify_plans(a: PlanTerm, b: PlanTerm, s: dict, trail: list) -> bool:
    """Plan terms part by part: label (as Jason gives it), trigger, context (``true``
    when there is none) and body, so ``P = {@L +!T : C <- B}`` takes a plan apart."""
    pa, pb = a.plan, b.plan
    ta, tb = pa.trigger, pb.trigger
    if ta is None or tb is None or ta.op != tb.op or ta.kind != tb.kind:
        return False
    la, lb = a.label, b.label
    if (la is None) != (lb is None) or (la is not None and not unify(la, lb, s, trail)):
        return False
    if not unify(ta.literal, tb.literal, s, trail):
        return False
    ca = pa.context if pa.context is not None else Literal("true")
    cb = pb.context if pb.context is not None else Literal("true")
    if not unify(ca, cb, s, trail):
        return False
    return unify_bodies(Body(tuple(_steps(pa.body))), Body(tuple(_steps(pb.body))), s, trail)


def unify_bodies(a: Body, b: Body, s: dict, trail: list) -> bool:
    """Body terms: step by step, where a bare variable as the last step of one takes
    the rest of the other and one as a step takes that step (``{H; R}``); a body that
    is one bare variable (``<- B``) takes the whole of the other."""
    for x, y in ((a, b), (b, a)):
        if len(x.steps) == 1 and var_step(x, 0) is not None and not x.bare:
            return unify(var_step(x, 0), Body(y.steps), s, trail)
    for x, y in ((a, b), (b, a)):
        n = len(x.steps)
        if n and n <= len(y.steps) + 1 and var_step(x, n - 1) is not None and n >= 2:
            for k in range(n - 1):
                if k >= len(y.steps) or not _unify_step(x, k, y, k, s, trail):
                    return False
            return unify(var_step(x, n - 1), Body(y.steps[n - 1 :]), s, trail)
    if len(a.steps) != len(b.steps):
        return False
    return all(_unify_step(a, k, b, k, s, trail) for k in range(len(a.steps)))


def _unify_step(a: Body, i: int, b: Body, j: int, s: dict, trail: list) -> bool:
    va, vb = var_step(a, i), var_step(b, j)
    if va is not None:
        return unify(va, Body((b.steps[j],), bare=True), s, trail)
    if vb is not None:
        return unify(vb, Body((a.steps[i],), bare=True), s, trail)
    x, y = a.steps[i], b.steps[j]
    if x.kind != y.kind or x.blocks or y.blocks:
        return x is y
    return unify(x.term, y.term, s, trail)


def _to_int(x: float | int) -> int:
    if x.__class__ is int:
        return x
    if not math.isfinite(x):
        raise EvalError(f"{x} is not a finite number")
    return int(x)


def _norm(x: float | int) -> float | int:
    """Keep integral results as ``int`` while they fit a Java long, as Jason prints them."""
    if x.__class__ is int and -(2**63) <= x < 2**63:
        return x
    return float(x)


def _apply_op(op: str, x, y):  # noqa: ANN001, ANN202 - numbers
    if op == "+":
        return _norm(x + y)
    if op == "-":
        return _norm(x - y)
    if op == "*":
        return _norm(x * y)
    if op == "/":
        if y == 0:  # Java doubles: no error, an infinity (or NaN)
            if x == 0 or x != x:
                return math.nan
            return math.copysign(math.inf, x) * (
                math.copysign(1.0, y) if y.__class__ is float else 1
            )
        return x / y
    if op == "div":
        xi, yi = _to_int(x), _to_int(y)
        if yi == 0:
            raise EvalError("division by zero")
        q = abs(xi) // abs(yi)
        return q if (xi >= 0) == (yi >= 0) else -q
    if op == "mod":
        if x.__class__ is float or y.__class__ is float:
            # Java's % on doubles: the remainder takes the dividend's sign, 7.9 mod 2 is
            # 1.9000000000000004, and a zero divisor gives NaN rather than an error
            return math.fmod(x, y) if y != 0 else math.nan
        xi, yi = _to_int(x), _to_int(y)
        if yi == 0:
            raise EvalError("division by zero")
        r = abs(xi) % abs(yi)
        return r if xi >= 0 else -r
    if op == "**":
        try:
            r = float(x) ** float(y)
        except (OverflowError, ZeroDivisionError) as exc:
            raise EvalError(str(exc)) from exc
        if isinstance(r, complex):
            return math.nan  # as Java's Math.pow
        if r == int(r) and abs(r) < 2**63 if math.isfinite(r) else False:
            return int(r)
        return r
    raise EvalError(f"unknown operator {op}")


def evaluate(t: Term, s: dict, fresh: dict | None = None, strict: bool = True) -> Term:
    """Evaluate an arithmetic term; non-numeric operands leave an expression behind."""
    c = t.__class__
    if c is Var:
        t = deref(t, s)
        c = t.__class__
    if c is int or c is float:
        return t
    if c is not Arith:
        return resolve(t, s, fresh)
    if t.op == "call":
        if strict:
            return _call(t, s, fresh, strict)
        try:
            return _call(t, s, fresh, strict)
        except EvalError:
            return Arith("call", resolve(t.left, s, fresh))
    left = t.left
    lc = left.__class__
    if lc is Var:
        v = s.get(left)
        while v is not None:
            left = v
            if v.__class__ is not Var:
                break
            v = s.get(v)
        lc = left.__class__
    if lc is not int and lc is not float:
        left = evaluate(left, s, fresh, strict)
        lc = left.__class__
    right = t.right
    if right is None:
        if lc is int or lc is float:
            return -left if t.op == "-" else left
        return Arith(t.op, left)
    rc = right.__class__
    if rc is Var:
        v = s.get(right)
        while v is not None:
            right = v
            if v.__class__ is not Var:
                break
            v = s.get(v)
        rc = right.__class__
    if rc is not int and rc is not float:
        right = evaluate(right, s, fresh, strict)
        rc = right.__class__
    if (lc is int or lc is float) and (rc is int or rc is float):
        op = t.op
        if op == "+":
            r = left + right
            if r.__class__ is float or -(2**63) <= r < 2**63:
                return r
        elif op == "-":
            r = left - right
            if r.__class__ is float or -(2**63) <= r < 2**63:
                return r
        if strict:
            return _apply_op(t.op, left, right)
        try:
            return _apply_op(t.op, left, right)
        except EvalError:
            return Arith(t.op, left, right)
    return Arith(t.op, left, right)


def _call(t: Arith, s: dict, fresh: dict | None, strict: bool) -> Term:
    """Jason's arithmetic functions ``math.abs(X)``, ``math.max(X, Y)``, ..."""
    lit = t.left
    if lit.functor == ".count":
        return _count(lit.args[0], s)
    args = [evaluate(a, s, fresh, strict) for a in lit.args]
    if lit.functor == ".length":
        v = args[0]
        if v.__class__ is str:
            return len(v)
        if v.__class__ is Cons or v.__class__ is Nil:
            n = 0
            while v.__class__ is Cons:
                n += 1
                v = v.tail
            return n
        if v.__class__ is SetTerm or v.__class__ is QueueTerm:
            return len(v)
        raise EvalError(f".length: {v!r} is not a list or a string")
    if lit.functor == "system.time":  # Java's System.currentTimeMillis()
        return int(time.time() * 1000)
    if not lit.functor.startswith("math."):  # a function of the program's rules
        agent = running.get()
        if agent is None:
            raise EvalError(f"unknown function {lit.functor}/{len(args)}")
        return agent.function_value(lit.functor, args)
    name = lit.functor[5:]
    if (
        name in ("sum", "average", "mean", "median", "max", "min", "std_dev")
        and len(args) == 1
        and args[0].__class__ in (Cons, Nil)
    ):
        items = []
        x = args[0]
        while x.__class__ is Cons:
            items.append(evaluate(x.head, s))
            x = x.tail
        if all(i.__class__ in (int, float) for i in items):
            if name == "sum":
                return _norm(sum(items))
            if not items:
                raise EvalError(f"{lit.functor} of an empty list")
            if name in ("average", "mean"):
                return sum(items) / len(items)
            if name == "max":
                return max(items)
            if name == "min":
                return min(items)
            if name == "median":
                srt = sorted(items)
                mid = len(srt) // 2
                return srt[mid] if len(srt) % 2 else (srt[mid - 1] + srt[mid]) / 2
            mean = sum(items) / len(items)
            return math.sqrt(sum((x - mean) ** 2 for x in items) / (len(items) - 1 or 1))
    if not all(a.__class__ in (int, float) for a in args):
        return Arith("call", Literal(lit.functor, tuple(args)))
    fn = _FUNCTIONS.get((name, len(args)))
    if fn is None:
        raise EvalError(f"unknown function {lit.functor}/{len(args)}")
    try:
        return fn(*args)
    except (ValueError, OverflowError, ZeroDivisionError) as exc:
        raise EvalError(f"{lit.functor}: {exc}") from exc


_RNG = random.Random(0)


def _count(query: Term, s: dict) -> int:
    agent = running.get()
    if agent is None:
        raise EvalError(".count needs an agent")
    return agent.count_solutions(query, s)


def _round(x: float) -> int:
    return int(math.floor(x + 0.5))


_FUNCTIONS = {
    ("abs", 1): abs,
    ("sqrt", 1): math.sqrt,
    ("max", 2): max,
    ("min", 2): min,
    ("floor", 1): lambda x: int(math.floor(x)),
    ("ceil", 1): lambda x: int(math.ceil(x)),
    ("round", 1): _round,
    ("log", 1): math.log,
    ("pow", 2): lambda x, y: _apply_op("**", x, y),
    ("pi", 0): lambda: math.pi,
    ("e", 0): lambda: math.e,
    ("sin", 1): math.sin,
    ("cos", 1): math.cos,
    ("tan", 1): math.tan,
    ("atan", 1): math.atan,
    ("atan2", 2): math.atan2,
    ("mod", 2): lambda x, y: _apply_op("mod", x, y),
    ("signum", 1): lambda x: (x > 0) - (x < 0),
    ("acos", 1): math.acos,
    ("asin", 1): math.asin,
    ("random", 0): lambda: _RNG.random(),
    ("random", 1): lambda x: _RNG.random() * x,
}


def number(t: Term, s: dict) -> int | float:
    """The numeric value of ``t`` under ``s``, or :class:`EvalError`."""
    v = evaluate(t, s)
    if v.__class__ is int or v.__class__ is float:
        return v
    raise EvalError(f"{v!r} is not a number")


def rename(t: Term, mapping: dict) -> Term:
    """A copy of ``t`` with each variable replaced by a fresh one (consistently)."""
    c = t.__class__
    if c is Var:
        nv = mapping.get(t)
        if nv is None:
            nv = mapping[t] = Var(t.name)
        return nv
    if c is Literal:
        if t.ground:
            return t
        return Literal(
            t.functor,
            tuple([rename(a, mapping) for a in t.args]),
            tuple(
                [
                    AnnotTail(rename(a.var, mapping))
                    if a.__class__ is AnnotTail
                    else rename(a, mapping)
                    for a in t.annots
                ]
            ),
            t.neg,
        )
    if c is Cons:
        if t.ground:
            return t
        return Cons(rename(t.head, mapping), rename(t.tail, mapping))
    if c is Arith:
        return Arith(
            t.op, rename(t.left, mapping), None if t.right is None else rename(t.right, mapping)
        )
    if c is Rel:
        return Rel(t.op, rename(t.left, mapping), rename(t.right, mapping))
    if c is And:
        return And(rename(t.left, mapping), rename(t.right, mapping))
    if c is Or:
        return Or(rename(t.left, mapping), rename(t.right, mapping))
    if c is Not:
        return Not(rename(t.arg, mapping))
    if c is Body:
        return map_body(t, lambda x: rename(x, mapping))
    if c is PlanTerm:
        return map_plan(t, lambda x: rename(x, mapping))
    if c is NsLiteral:
        return ns_rename(t, lambda x: rename(x, mapping))
    return t


def map_plan(t: PlanTerm, fn: Any) -> PlanTerm:
    """A plan term with ``fn`` applied to its terms: ``rename`` (a plan term in a rule's
    body shares the rule's variables) or a substitution (``.add_plan``)."""
    p = t.plan
    trig = p.trigger
    if trig is not None:
        trig = trig.__class__(trig.op, trig.kind, fn(trig.literal))
    steps = [
        st
        if st.blocks or st.term is None or isinstance(st.term, str)
        else st.__class__(st.kind, fn(st.term), st.blocks, st.line, st.state)
        for st in _steps(p.body)
    ]
    plan = p.__class__(
        trig,
        None if p.context is None else fn(p.context),
        _chain(steps),
        None if p.label is None else fn(p.label),
        p.source,
        p.line,
    )
    label = None if t.label is None else fn(t.label)
    return PlanTerm(plan, t.text, t.bare, label)


def variables(t: Term, out: list | None = None) -> list:
    """The distinct variables of ``t`` in order of first occurrence."""
    if out is None:
        out = []
    c = t.__class__
    if c is Var:
        if t not in out:
            out.append(t)
    elif c is Literal:
        if not t.ground:
            for a in t.args:
                variables(a, out)
            for a in t.annots:
                variables(a.var if a.__class__ is AnnotTail else a, out)
    elif c is Cons:
        while t.__class__ is Cons:
            variables(t.head, out)
            t = t.tail
        variables(t, out)
    elif c is Arith:
        variables(t.left, out)
        if t.right is not None:
            variables(t.right, out)
    elif c is Rel or c is And or c is Or:
        variables(t.left, out)
        variables(t.right, out)
    elif c is Not:
        variables(t.arg, out)
    elif c is NsLiteral:
        variables(t.ns, out)
        variables(t.lit, out)
    return out
