"""Beliefs: ``.findall``, ``.setof``, ``.count``, ``.abolish``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError, solve
from robocog.bdi.stdlib.base import belief_event, bind, internal, need_args
from robocog.bdi.terms import Literal, make_list, sort_key
from robocog.bdi.unifier import deref, resolve, undo

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("findall")
def _findall(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "findall")
    query = deref(args[1], s)
    if query.__class__ is Literal and query.functor[0] != "." and query.args:
        got = ag.bb.collect(query, args[0], s)
        if got is not None:
            return bind(make_list(got), args[2], s, trail)
    out = []
    mark = len(trail)
    for _ in solve(ag, args[1], s, trail):
        out.append(resolve(args[0], s, {}))
    undo(s, trail, mark)
    return bind(make_list(out), args[2], s, trail)


@internal("setof")
def _setof(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "setof")
    out = []
    mark = len(trail)
    for _ in solve(ag, args[1], s, trail):
        v = resolve(args[0], s, {})
        if v not in out:
            out.append(v)
    undo(s, trail, mark)
    return bind(make_list(sorted(out, key=sort_key)), args[2], s, trail)


@internal("count")
def _count(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "count")
    n = 0
    mark = len(trail)
    for _ in solve(ag, args[0], s, trail):
        n += 1
    undo(s, trail, mark)
    return bind(n, args[1], s, trail)


@internal("abolish")
def _abolish(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "abolish")
    pattern = resolve(args[0], s)
    if pattern.__class__ is not Literal:
        raise ActionError(".abolish: argument must be a literal")
    for gone in ag.bb.abolish(pattern):
        ag.post(belief_event("-", P.BELIEF, gone))
    return True
