"""Output and identity: ``.print``, ``.my_name``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.stdlib.base import LIBRARY, bind, internal, need_args
from robocog.bdi.terms import Literal, print_str
from robocog.bdi.unifier import resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("print")
def _print(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    ag.print("".join(print_str(resolve(a, s)) for a in args))
    return True


LIBRARY[".println"] = _print


@internal("my_name")
def _my_name(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "my_name")
    return bind(Literal(ag.name), args[0], s, trail)
