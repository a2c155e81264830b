"""Strings: ``.term2string``, ``.substring``, ``.upper_case``, ``.lower_case``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import arg_text, bind, bind_each, internal, need_args
from robocog.bdi.terms import Term, Var, term_str
from robocog.bdi.unifier import deref, resolve, undo, unify

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("term2string")
def _term2string(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "term2string")
    t = deref(args[0], s)
    if t.__class__ is not Var:
        return bind(term_str(resolve(t, s)), args[1], s, trail)
    text = resolve(args[1], s)
    if text.__class__ is not str:
        raise ActionError(".term2string: one argument must be bound")
    from robocog.bdi.parser import ParseError, parse_term

    try:
        return bind(parse_term(text), args[0], s, trail)
    except ParseError as exc:
        raise ActionError(f".term2string: {exc}") from exc


@internal("substring")
def _substring(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    """Jason's three uses: ``.substring(Sub, S)`` tests; with a number third and an
    unbound first, ``.substring(X, S, Begin[, End])`` cuts S; otherwise every position
    of Sub in S (and, with four arguments, where it ends) is a solution."""
    need_args(args, 2, "substring", 4)
    first = resolve(args[0], s)
    full = arg_text(args[1], s)
    if len(args) == 2:
        return arg_text(first, s) in full
    start = resolve(args[2], s)
    numeric = start.__class__ is int or start.__class__ is float
    if numeric and first.__class__ is Var:
        end = resolve(args[3], s) if len(args) == 4 else len(full)
        if not (end.__class__ is int or end.__class__ is float):
            end = len(full)
        b, e = int(start), int(end)
        if not 0 <= b <= e <= len(full):
            raise ActionError(f"begin {b}, end {e}, length {len(full)}", "internal_action")
        return bind(full[b:e], args[0], s, trail)
    sub = arg_text(first, s)
    found = []
    k = full.find(sub)
    while k >= 0:
        found.append(k)
        k = full.find(sub, k + 1)
    if len(args) == 3:
        return bind_each(iter(found), args[2], s, trail)
    return _positions(found, len(sub), args[2], args[3], s, trail)


def _positions(found: list, n: int, at: Term, end: Term, s: dict, trail: list) -> Any:
    mark = len(trail)
    for k in found:
        if unify(at, k, s, trail) and unify(end, k - 1 + n, s, trail):
            yield None
        undo(s, trail, mark)


@internal("upper_case")
def _upper(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "upper_case")
    return bind(arg_text(args[0], s).upper(), args[1], s, trail)


@internal("lower_case")
def _lower(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "lower_case")
    return bind(arg_text(args[0], s).lower(), args[1], s, trail)
