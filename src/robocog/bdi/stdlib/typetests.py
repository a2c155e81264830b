"""Type tests: ``.ground``, ``.atom``, ``.number``, ``.string``, ``.literal``,
``.structure``, ``.var``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.stdlib.base import internal, need_args
from robocog.bdi.terms import Cons, Literal, Nil, Var
from robocog.bdi.unifier import deref, resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("ground")
def _ground(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "ground")
    from robocog.bdi.terms import is_ground

    return is_ground(resolve(args[0], s))


@internal("atom")
def _atom(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "atom")
    v = resolve(args[0], s)
    return v.__class__ is Literal and not v.args and not v.neg


@internal("number")
def _number(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "number")
    v = resolve(args[0], s)
    return v.__class__ is int or v.__class__ is float


@internal("string")
def _string(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "string")
    return resolve(args[0], s).__class__ is str


@internal("literal")
def _literal(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "literal")
    return resolve(args[0], s).__class__ is Literal


@internal("structure")
def _structure(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "structure")
    return resolve(args[0], s).__class__ in (Literal, Cons, Nil)


@internal("var")
def _var(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "var")
    return deref(args[0], s).__class__ is Var
