"""Communication and the system: ``.send``, ``.broadcast``, ``.all_names``,
``.perceive``, ``.stopMAS``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.messages import broadcast, send
from robocog.bdi.signals import DONE
from robocog.bdi.stdlib.base import LIBRARY, bind, internal, need_args
from robocog.bdi.terms import NIL, Literal, make_list
from robocog.bdi.unifier import resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("send")
def _send(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    need_args(args, 3, "send", 5)
    return send(ag, args, s, ctx)


@internal("broadcast")
def _broadcast(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "broadcast")
    broadcast(ag, resolve(args[0], s), resolve(args[1], s))
    return True


@internal("all_names")
def _all_names(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "all_names")
    names = [ag.name] if ag.mas is None else list(ag.mas.agents)
    return bind(make_list([Literal(n) for n in names]), args[0], s, trail)


@internal("perceive")
def _perceive(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.perceive``: update the beliefs from the percepts now (with no environment
    there are none, and nothing changes)."""
    need_args(args, 0, "perceive")
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
