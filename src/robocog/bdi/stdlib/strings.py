"""Strings: ``.term2string``, ``.substring``, ``.upper_case``, ``.lower_case``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import arg_text, bind, bind_each, internal, need_args
from robocog.bdi.terms import Var, term_str
from robocog.bdi.unifier import deref, resolve

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
    need_args(args, 2, "substring", 3)
    sub = arg_text(args[0], s)
    full = arg_text(args[1], s)
    if len(args) == 2:
        return sub in full
    positions = []
    k = full.find(sub)
    while k >= 0:
        positions.append(k)
        k = full.find(sub, k + 1)
    return bind_each(iter(positions), args[2], s, trail)


@internal("upper_case")
def _upper(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "upper_case")
    return bind(arg_text(args[0], s).upper(), args[1], s, trail)


@internal("lower_case")
def _lower(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "lower_case")
    return bind(arg_text(args[0], s).lower(), args[1], s, trail)
