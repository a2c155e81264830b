"""Executing the rest of OpenCog 2021's executable atoms: arithmetic, value flows,
formulas, defined schemas, DualLink and MapLink.

``execute_any`` is what ``cog-execute!`` does with any atom: queries and grounded
schemas go to :func:`robocog.atomspace.execute.execute`; arithmetic links (PlusLink,
MinusLink, TimesLink, DivideLink) compute over NumberNodes (giving a NumberNode) or over
FloatValues and truth values (giving a FloatValue, element by element); ValueOfLink and
its kin read Values; SetValueLink and SetTVLink write them; a PredicateFormulaLink gives
a truth value from two numeric formulas; an evaluatable atom gives its truth value; a
DefinedSchemaNode runs its definition; anything else is added and returned.
"""

from __future__ import annotations

import operator
from typing import TYPE_CHECKING, Any

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import Atom, Link, Node, variables_of
from robocog.atomspace.execute import (
    GroundedError,
    MissingValue,
    evaluate,
    execute,
    set_flow,
)
from robocog.atomspace.matcher import PatternError, parse_variables, substitute
from robocog.atomspace.matcher.variables import type_admits
from robocog.atomspace.values import (
    FALSE_TV,
    TRUE_TV,
    FloatValue,
    LinkValue,
    QueueValue,
    TruthValue,
    Value,
)

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace

_ARITH = {
    "PlusLink": operator.add,
    "MinusLink": operator.sub,
    "TimesLink": operator.mul,
    "DivideLink": operator.truediv,
}
_EVALUATABLE = frozenset(
    {
        "EvaluationLink",
        "NotLink",
        "AndLink",
        "OrLink",
        "EqualLink",
        "IdenticalLink",
        "PresentLink",
        "AbsentLink",
        "GreaterThanLink",
        "SatisfactionLink",
        "TrueLink",
        "FalseLink",
        "PredicateFormulaLink",
        "DefinedPredicateNode",
        "SequentialAndLink",
        "SequentialOrLink",
        "ParallelLink",
        "ThreadJoinLink",
    }
)
#: how deep definitions may call one another while executing
MAX_CALLS = 200


class FlowError(PatternError):
    """An atom that cannot be executed as written (wrong kinds of arguments)."""


def number_text(x: float) -> str:
    """A number as OpenCog 2021 names a NumberNode (ten significant digits)."""
    if float(x).is_integer() and abs(x) < 1e15:
        return str(int(x))
    return f"{x:.10g}"


def _numbers(
    space: AtomSpace, v: Any, depth: int, env: dict | None = None
) -> tuple[list[float], bool]:
    """(the numbers of an operand, whether it was a NumberNode); ``env`` gives the
    Values that variables stand for (a schema applied to a FloatValue)."""
    if env and v in env:
        v = env[v]
    elif env and isinstance(v, Atom) and v[0] in _ARITH:
        v = _arith(space, v, depth + 1, env)
    elif isinstance(v, Atom) and _executes(v):
        v = execute_any(space, v, depth + 1)
    if isinstance(v, Node) and v[0] == "NumberNode":
        try:
            return [float(p) for p in v[1].split()], True
        except ValueError:
            raise FlowError(f"not a number: {v}") from None
    if isinstance(v, TruthValue):
        return [v.strength, v.confidence], False
    if isinstance(v, FloatValue):
        return list(v.items), False
    raise FlowError(f"arithmetic over a non-number: {str(v)[:200]}")


def _executes(a: Atom) -> bool:
    t = a[0]
    return (
        t in _ARITH
        or t in _t.QUERY_TYPES
        or t == "ExecutionOutputLink"
        or t == "PutLink"
        or t == "DefinedSchemaNode"
        or _t.is_a(t, "ValueOfLink")
        or t in ("SetValueLink", "SetTVLink", "MapLink", "DualLink", "ExecuteThreadedLink")
        or t == "CondLink"
    )


def _arith(space: AtomSpace, atom: Atom, depth: int, env: dict | None = None) -> Any:
    op = _ARITH[atom[0]]
    if not env and any(variables_of(a) for a in atom[1]):
        return space.add(atom)  # not closed: OpenCog returns it as it is
    acc: list[float] | None = None
    all_nodes = True
    for a in atom[1]:
        nums, is_node = _numbers(space, a, depth, env)
        all_nodes = all_nodes and is_node
        if acc is None:
            acc = nums
            continue
        n = max(len(acc), len(nums))
        if len(acc) == 1:
            acc = acc * n
        if len(nums) == 1:
            nums = nums * n
        try:
            acc = [op(x, y) for x, y in zip(acc, nums, strict=False)]
        except ZeroDivisionError:
            raise FlowError(f"division by zero in {str(atom)[:200]}") from None
    if acc is None:
        acc = [0.0 if atom[0] in ("PlusLink", "MinusLink") else 1.0]
    if all_nodes:
        return space.add(Node("NumberNode", " ".join(number_text(x) for x in acc)))
    return FloatValue(acc)


def _definition(space: AtomSpace, node: Atom) -> Atom:
    for d in space.incoming(node, "DefineLink"):
        if d[1][0] == node:
            return d[1][1]
    raise FlowError(f"{node} is not defined")


def _apply_lambda(space: AtomSpace, fn: Atom, args: Atom | Value | None) -> Atom:
    """Beta-reduce a LambdaLink (or a formula with free variables) over ``args``."""
    if fn[0] == "LambdaLink":
        parts = fn[1]
        decl = parts[0] if len(parts) == 2 else None
        body = parts[-1]
        variables, _allowed = parse_variables(decl, body)
    else:
        body = fn
        variables = variables_of(fn)
    if not variables:
        return body
    if isinstance(args, LinkValue):
        given = tuple(args.items)
    elif isinstance(args, Atom) and args[0] == "ListLink" and len(variables) != 1:
        given = args[1]
    elif isinstance(args, Atom) and args[0] == "ListLink" and len(args[1]) == 1:
        given = args[1]
    elif args is None:
        given = ()
    else:
        given = (args,)
    if len(given) != len(variables):
        raise FlowError(f"{len(variables)} variables but {len(given)} arguments")
    return _beta(body, dict(zip(variables, given, strict=True)))


def _beta(atom: Atom, mapping: dict) -> Atom:
    """``atom`` with the variables of ``mapping`` replaced, also inside nested scopes
    (a GetLink in a LambdaLink's body) that do not declare them again."""
    if atom.__class__ is Node:
        return mapping.get(atom, atom)
    out = atom[1]
    if atom[0] in _t.QUERY_TYPES or atom[0] == "LambdaLink":
        first = out[0] if out else None
        if first is not None and (first in mapping or first[0] in _t.VARIABLE_DECLS):
            bound = set(variables_of(first)) if first[0] in _t.VARIABLE_DECLS else {first}
            if first[0] == "TypedVariableLink":
                bound = {first[1][0]}
            mapping = {k: v for k, v in mapping.items() if k not in bound}
            if not mapping:
                return atom
    new = tuple(_beta(a, mapping) for a in out)
    if all(x is y for x, y in zip(new, out, strict=True)):
        return atom
    return Link(atom[0], *new)


def execute_any(space: AtomSpace, atom: Atom, depth: int = 0) -> Any:  # noqa: C901
    """Execute ``atom`` as OpenCog 2021's ``cog-execute!`` does."""
    if depth > MAX_CALLS:
        raise FlowError(f"execution nested more than {MAX_CALLS} deep")
    t = atom[0]
    out = atom[1]
    if t in _ARITH:
        return _arith(space, atom, depth)
    if t == "DefinedSchemaNode":
        return execute_any(space, _definition(space, atom), depth + 1)
    if t in ("TruthValueOfLink", "StrengthOfLink", "ConfidenceOfLink", "CountOfLink"):
        if not out:
            raise FlowError(f"{t} needs an atom")
        target = out[0]
        if _executes(target):
            target = execute_any(space, target, depth + 1)
        if not isinstance(target, Atom):
            raise FlowError(f"{t} of a non-atom")
        tv = space.get_tv(target)
        if t == "TruthValueOfLink":
            return tv
        if t == "StrengthOfLink":
            return FloatValue([tv.strength])
        if t == "ConfidenceOfLink":
            return FloatValue([tv.confidence])
        return FloatValue([0.0])
    if t in ("ValueOfLink", "FloatValueOfLink", "StreamValueOfLink"):
        if len(out) != 2:
            raise FlowError("ValueOfLink takes an atom and a key")
        v = space.get_value(out[0], out[1])
        if v is None:
            raise MissingValue(f"no value at key {out[1]} on {str(out[0])[:200]}")
        if t == "StreamValueOfLink" and isinstance(v, QueueValue):
            return LinkValue(v.items)  # a queue read as a stream gives what it holds
        return v
    if t == "SetValueLink":
        if len(out) < 3:
            raise FlowError("SetValueLink takes an atom, a key and a value")
        value = _flow_value(space, out[2:], depth)
        space.set_value(out[0], out[1], value)
        return value
    if t == "SetTVLink":
        if len(out) < 2:
            raise FlowError("SetTVLink takes an atom and a truth value")
        value = _flow_value(space, out[1:], depth, want_tv=True)
        if not isinstance(value, TruthValue):
            nums = list(value.items) if isinstance(value, FloatValue) else []
            if len(nums) < 2:
                raise FlowError(f"SetTVLink: not a truth value: {value}")
            value = TruthValue(min(1.0, max(0.0, nums[0])), min(1.0, max(0.0, nums[1])))
        space.set_tv(out[0], value)
        return value
    if t == "PredicateFormulaLink" and variables_of(atom):
        return space.add(atom)  # a formula with free variables is its own value
    if t in _EVALUATABLE:
        return evaluate_any(space, atom, depth + 1)
    if t == "CondLink":
        # (Cond test1 expr1 test2 expr2 ... [default]): the first true test's expression
        for i in range(0, len(out) - 1, 2):
            if evaluate_any(space, out[i], depth + 1).is_true():
                return _value_of(space, out[i + 1], depth)
        if len(out) % 2 == 1:
            return _value_of(space, out[-1], depth)
        return space.add(Link("SetLink"))
    if t == "ExecutionOutputLink" and out and out[0][0] in ("DefinedSchemaNode", "LambdaLink"):
        fn = _definition(space, out[0]) if out[0][0] == "DefinedSchemaNode" else out[0]
        args = _ground(space, out[1], depth) if len(out) > 1 else None
        return execute_any(space, _apply_lambda(space, fn, args), depth + 1)
    if t == "ExecuteThreadedLink":
        # the threads run one after the other here; each result in its own queue
        items = out[-1][1] if out and out[-1][0] in ("SetLink", "ListLink") else out
        return QueueValue(
            [_queued(execute_any(space, a, depth + 1)) for a in items if a[0] != "NumberNode"]
        )
    if t in ("ParallelLink", "ThreadJoinLink", "SleepLink"):
        return evaluate_any(space, atom, depth + 1)
    if t == "DualLink":
        return space.add(_dual(space, atom))
    if t == "MapLink":
        return _map(space, atom, depth)
    if t == "PutLink":
        r = execute(space, atom)
        if r is None:
            return False  # a DeleteLink reduced: OpenCog gives no atom
        if isinstance(r, Atom) and _executes(r) and r[0] not in _t.QUERY_TYPES:
            return execute_any(space, r, depth + 1)
        return r
    if t == "QueryLink":
        # OpenCog 2021: a QueryLink gives the QueueValue of its rewrites

        res = execute(space, atom)
        return QueueValue(res[1]) if isinstance(res, Atom) else res
    return execute(space, atom)


def _flow_value(space: AtomSpace, parts: tuple, depth: int, want_tv: bool = False) -> Any:
    """The value a SetValueLink/SetTVLink stores: one expression, or a function and
    its arguments."""
    if len(parts) == 1:
        v = parts[0]
        if isinstance(v, Atom) and (v[0] in _EVALUATABLE or v[0] == "DefinedPredicateNode"):
            if want_tv:
                return evaluate_any(space, v, depth + 1)
        if isinstance(v, Atom) and _executes(v):
            return execute_any(space, v, depth + 1)
        if isinstance(v, Atom) and v[0] == "PredicateFormulaLink":
            return evaluate_any(space, v, depth + 1)
        if isinstance(v, Atom):
            return LinkValue([v])
        return v
    fn, args = parts[0], parts[1]
    if fn[0] in ("DefinedSchemaNode", "DefinedPredicateNode"):
        fn = _definition(space, fn)
    if fn[0] == "PredicateFormulaLink" or want_tv:
        return evaluate_any(
            space,
            Link("EvaluationLink", fn, args)
            if fn[0] != "LambdaLink"
            else _apply_lambda(space, fn, args),
            depth + 1,
        )
    if isinstance(args, Atom) and _executes(args):
        args = execute_any(space, args, depth + 1)
    if isinstance(args, Value) and not isinstance(args, LinkValue) and fn[0] == "LambdaLink":
        # a schema over a Value: its variable stands for the Value in the arithmetic
        parts = fn[1]
        variables, _allowed = parse_variables(parts[0] if len(parts) == 2 else None, parts[-1])
        body = parts[-1]
        if len(variables) == 1 and body[0] in _ARITH:
            return _arith(space, body, depth + 1, {variables[0]: args})
    return execute_any(space, _apply_lambda(space, fn, args), depth + 1)


def evaluate_any(space: AtomSpace, atom: Atom, depth: int = 0) -> TruthValue:  # noqa: C901
    """The truth value of ``atom``, as ``cog-evaluate!`` gives it."""
    if depth > MAX_CALLS:
        raise FlowError(f"evaluation nested more than {MAX_CALLS} deep")
    t = atom[0]
    out = atom[1]
    if t == "PredicateFormulaLink":
        if len(out) < 2:
            raise FlowError("PredicateFormulaLink takes two formulas")
        nums = []
        for f in out[-2:]:
            v, _is_node = _numbers(space, f, depth)
            if not v:
                raise FlowError("a formula gave no number")
            nums.append(min(1.0, max(0.0, v[0])))
        return TruthValue(nums[0], nums[1])
    if t in ("TrueLink", "FalseLink", "SleepLink"):
        for a in out:  # what they wrap is run, its value ignored
            if a.__class__ is Link:
                _run_for_effect(space, a, depth)
        return FALSE_TV if t == "FalseLink" else TRUE_TV
    if t in ("ParallelLink", "ThreadJoinLink"):
        # the threads run one after the other here
        results = [_run_for_effect(space, a, depth) for a in out]
        if t == "ThreadJoinLink":
            return TRUE_TV if all(r is not False for r in results) else FALSE_TV
        return TRUE_TV
    if (
        t == "EvaluationLink"
        and out
        and out[0][0] in ("DefinedPredicateNode", "PredicateFormulaLink", "LambdaLink")
    ):
        fn = _definition(space, out[0]) if out[0][0] == "DefinedPredicateNode" else out[0]
        args = out[1] if len(out) > 1 else None
        if fn[0] == "PredicateFormulaLink" and any(f[0] == "LambdaLink" for f in fn[1]):
            # formulas wrapped in LambdaLinks: each is applied to the arguments
            parts = [_apply_lambda(space, f, args) if f[0] == "LambdaLink" else f for f in fn[1]]
            return evaluate_any(space, Link("PredicateFormulaLink", *parts), depth + 1)
        return evaluate_any(space, _apply_lambda(space, fn, args), depth + 1)
    if t == "DefinedPredicateNode":
        return evaluate_any(space, _definition(space, atom), depth + 1)
    if t == "NotLink" and len(out) == 1:
        tv = evaluate_any(space, out[0], depth + 1)
        return TruthValue(1.0 - tv.strength, tv.confidence)
    if t in ("AndLink", "SequentialAndLink"):
        for a in out:
            if not evaluate_any(space, a, depth + 1).is_true():
                return FALSE_TV
        return TRUE_TV
    if t in ("OrLink", "SequentialOrLink"):
        for a in out:
            if evaluate_any(space, a, depth + 1).is_true():
                return TRUE_TV
        return FALSE_TV
    if t == "GreaterThanLink" and len(out) == 2:
        x, _ = _numbers(space, out[0], depth)
        y, _ = _numbers(space, out[1], depth)
        return TRUE_TV if x and y and x[0] > y[0] else FALSE_TV
    if t in ("TruthValueOfLink", "StrengthOfLink", "ConfidenceOfLink"):
        v = execute_any(space, atom, depth + 1)
        return v if isinstance(v, TruthValue) else TRUE_TV
    if _t.is_a(t, "SetValueLink") or t in _ARITH:
        v = execute_any(space, atom, depth + 1)
        if isinstance(v, TruthValue):
            return v
        if isinstance(v, FloatValue) and len(v.items) >= 2:
            return TruthValue(min(1.0, max(0.0, v.items[0])), min(1.0, max(0.0, v.items[1])))
        return TRUE_TV
    if t == "EqualLink":
        vals = [execute_any(space, a, depth + 1) if _executes(a) else a for a in out]
        return TRUE_TV if all(v == vals[0] for v in vals[1:]) else FALSE_TV
    try:
        return evaluate(space, atom)
    except GroundedError:
        raise


def _match(pattern: Atom, term: Atom, variables: set, allowed: dict, b: dict) -> bool:
    """Does ``term`` match ``pattern`` (binding ``variables`` in ``b``)?"""
    if pattern in variables:
        if pattern in b:
            return b[pattern] == term
        ok = allowed.get(pattern)
        if ok is not None and not ok(term):
            return False
        b[pattern] = term
        return True
    if pattern.__class__ is Node or term.__class__ is Node:
        return pattern == term
    if pattern[0] != term[0] or len(pattern[1]) != len(term[1]):
        return False
    if pattern[0] in _t.UNORDERED:
        return _match_unordered(list(pattern[1]), list(term[1]), variables, allowed, b)
    return all(
        _match(p, x, variables, allowed, b) for p, x in zip(pattern[1], term[1], strict=True)
    )


def _match_unordered(ps: list, ts: list, variables: set, allowed: dict, b: dict) -> bool:
    if not ps:
        return True
    p = ps[0]
    for i, x in enumerate(ts):
        trial = dict(b)
        if _match(p, x, variables, allowed, trial) and _match_unordered(
            ps[1:], ts[:i] + ts[i + 1 :], variables, allowed, trial
        ):
            b.clear()
            b.update(trial)
            return True
    return False


def _type_check(allowed: Any) -> Any:
    if allowed is None:
        return None

    def check(term: Atom) -> bool:
        return type_admits(allowed, term)

    return check


def _map(space: AtomSpace, atom: Atom, depth: int) -> Any:
    """MapLink: the pattern (a LambdaLink, a ScopeLink or a term with variables) matched
    against each member of the arguments; each match gives the groundings (one atom, or
    a ListLink for several variables; with an ImplicationLink body, its rewrite)."""
    out = atom[1]
    if len(out) != 2:
        raise FlowError("MapLink takes a pattern and arguments")
    fn, args = out
    if _executes(args):
        args = execute_any(space, args, depth + 1)
    rewrite = None
    if fn[0] == "ImplicationScopeLink":
        parts = fn[1]
        decl = parts[0] if len(parts) == 3 else None
        body, rewrite = parts[-2], parts[-1]
        variables, allowed = parse_variables(decl, body)
    elif fn[0] in ("LambdaLink", "ScopeLink"):
        parts = fn[1]
        decl = parts[0] if len(parts) == 2 else None
        body = parts[-1]
        variables, allowed = parse_variables(decl, body)
    else:
        body = fn
        variables, allowed = variables_of(fn), {}
    if body[0] == "ImplicationLink" and len(body[1]) == 2:
        body, rewrite = body[1]
    checks = (
        {v: _type_check(a) for v, a in (allowed or {}).items()} if isinstance(allowed, dict) else {}
    )
    members = (
        args[1]
        if isinstance(args, Atom) and args[0] in ("SetLink", "ListLink")
        else (tuple(args.items) if isinstance(args, LinkValue) else (args,))
    )
    single = not (
        isinstance(args, LinkValue)
        or (isinstance(args, Atom) and args[0] in ("SetLink", "ListLink"))
    )
    members = tuple(_ground(space, m, depth) for m in members)
    results = []
    vs = set(variables)
    for m in members:
        b: dict = {}
        if not _match(body, m, vs, checks, b):
            continue
        if rewrite is not None:
            r = substitute(rewrite, b)
            results.append(execute_any(space, r, depth + 1) if _executes(r) else space.add(r))
        elif len(variables) == 1:
            results.append(b[variables[0]])
        else:
            results.append(Link("ListLink", *[b[v] for v in variables]))
    if single:
        return results[0] if results else space.add(Link("SetLink"))
    if isinstance(args, LinkValue):
        return LinkValue(results)
    kind = args[0] if isinstance(args, Atom) and args[0] in ("SetLink", "ListLink") else "SetLink"
    return space.add(Link(kind, *results))


def _ground(space: AtomSpace, atom: Any, depth: int) -> Any:
    """An argument with its arithmetic done (``(Times (Number 3) (Number 2))`` is 6)."""
    if not isinstance(atom, Atom) or atom.__class__ is Node:
        return atom
    if atom[0] in _ARITH and not variables_of(atom):
        return execute_any(space, atom, depth + 1)
    new = tuple(_ground(space, a, depth) for a in atom[1])
    if all(x is y for x, y in zip(new, atom[1], strict=True)):
        return atom
    return Link(atom[0], *new)


def _dual(space: AtomSpace, atom: Atom) -> Atom:
    """DualLink: the patterns in the space (atoms with free variables) that the given
    ground term matches; a SetLink of them."""
    out = atom[1]
    if len(out) != 1:
        raise FlowError("DualLink takes one term")
    term = out[0]
    found = []
    seen = set()
    stack = [a for a in space if a.__class__ is Link and a[0] == term[0]]
    for cand in stack:
        if cand in seen or cand == term:
            continue
        seen.add(cand)
        vs = variables_of(cand)
        if not vs:
            continue
        if _match(cand, term, set(vs), {}, {}):
            found.append(cand)
    return Link("SetLink", *found)


def _value_of(space: AtomSpace, a: Atom, depth: int) -> Any:
    """An expression's value: executed when executable, else the atom (added)."""
    if _executes(a) or a[0] == "CondLink":
        return execute_any(space, a, depth + 1)
    return space.add(a)


def _queued(r: Any) -> Any:
    """A thread's result as ExecuteThreadedLink collects it (a QueueValue)."""
    if isinstance(r, QueueValue):
        return r
    return QueueValue([r] if r is not None else [])


def _run_for_effect(space: AtomSpace, a: Atom, depth: int) -> Any:
    """Run what a TrueLink, ParallelLink... holds; False if it evaluated false."""
    if a[0] in _EVALUATABLE or a[0] in ("ParallelLink", "ThreadJoinLink", "SleepLink"):
        return evaluate_any(space, a, depth + 1).is_true() or False
    if _executes(a):
        return execute_any(space, a, depth + 1)
    return a


def _flow_operand(space: AtomSpace, atom: Atom) -> Any:
    return execute_any(space, atom) if _executes(atom) else atom


set_flow(_flow_operand)

__all__ = ["FlowError", "evaluate_any", "execute_any", "number_text"]

_ = Value
