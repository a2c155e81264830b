"""Communication and the system: ``.send``, ``.broadcast``, ``.all_names``,
``.perceive``, ``.stopMAS``."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.bdi.logic import ActionError
from robocog.bdi.messages import broadcast, send
from robocog.bdi.parser import read_source
from robocog.bdi.signals import DONE
from robocog.bdi.stdlib.base import LIBRARY, arg_text, bind, internal, need_args
from robocog.bdi.stdlib.goals import drop_every_intention
from robocog.bdi.terms import NIL, Literal, Term, make_list, term_str
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
    """``.stopMAS``: the system stops; ``.stopMAS(T)``: the agents that are not asleep
    get ``+jag_shutting_down(T)`` and T milliseconds to handle it, as in Jason."""
    deadline = resolve(args[0], s) if args else 0
    if ag.mas is not None and isinstance(deadline, (int, float)) and deadline > 0:
        ag.mas.shut_down(deadline)
        return True
    if ag.mas is not None:
        ag.mas.stopped = True
    for i in ag.C.intentions():
        ag._drop(i)
    ag.C.events.clear()
    if ctx:
        ag._drop(ctx[0])
        return DONE
    return True


def _name(t: Term, s: dict, what: str) -> str:
    v = resolve(t, s)
    if v.__class__ is Literal and not v.args:
        return v.functor
    if v.__class__ is str and v:
        return v
    raise ActionError(f".{what}: {term_str(v)} is not an agent name")


def _system(ag: Agent, what: str) -> Any:
    if ag.mas is None:
        raise ActionError(f".{what}: the agent runs alone (no system of agents)")
    return ag.mas


def _new_agent(ag: Agent, name: str, what: str) -> Agent:
    mas = _system(ag, what)
    if name in mas.agents:
        raise ActionError(f".{what}: there is already an agent named {name}")
    return type(ag)("", name, printer=ag.printer, warn=ag.warner, asl_path=ag.asl_path)


@internal("create_agent")
def _create_agent(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.create_agent(Name, "file.asl")``: a new agent running the program (looked up
    beside this agent's file, then in its source path)."""
    need_args(args, 1, "create_agent", 3)
    name = _name(args[0], s, "create_agent")
    new = _new_agent(ag, name, "create_agent")
    if len(args) > 1:
        file = arg_text(args[1], s)
        here = Path(ag.file).parent if ag.file else Path(".")
        found = next(
            (p for p in [here / file, *(Path(d) / file for d in ag.asl_path)] if p.is_file()),
            None,
        )
        if found is None:
            raise ActionError(f".create_agent: no file {file}")
        new = type(ag)(
            read_source(found), name, file=str(found), printer=ag.printer, warn=ag.warner,
            asl_path=ag.asl_path,
        )  # fmt: skip
        new.url = f"file:{file}"
    ag.mas.add(new)
    return True


@internal("kill_agent")
def _kill_agent(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Any:
    """``.kill_agent(Name)``: the agent stops and leaves the system."""
    need_args(args, 1, "kill_agent")
    name = _name(args[0], s, "kill_agent")
    mas = _system(ag, "kill_agent")
    if mas.remove(name) is None:
        return False
    if name == ag.name:
        return drop_every_intention(ag, ctx)
    return True


@internal("clone")
def _clone(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.clone(Name)``: a new agent with this one's beliefs, rules and plans (not its
    goals or intentions), as Jason's."""
    need_args(args, 1, "clone")
    name = _name(args[0], s, "clone")
    new = _new_agent(ag, name, "clone")
    new.file, new.url = ag.file, ag.url
    for plan in ag.pl:
        new.pl.add(plan)
    for rule in ag.bb.rules():
        new.bb.add_rule(rule, at_end=True)
    for b in reversed(list(ag.bb)):
        new.bb.add(b)
    ag.mas.add(new)
    return True


# ---- the directory facilitator (Jason's DF, kept by the system of agents)
def _service(args: tuple, s: dict, what: str) -> tuple[Term, Term]:
    service = resolve(args[0], s)
    kind = resolve(args[1], s) if len(args) > 2 or (what != "df_search" and len(args) > 1) else None
    return service, kind


@internal("df_register")
def _df_register(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.df_register(Service[, Type])``: offer a service; subscribers are told
    ``provider(Agent, Service)``."""
    need_args(args, 1, "df_register", 2)
    mas = _system(ag, "df_register")
    service, kind = _service(args, s, "df_register")
    mas.df_register(ag.name, service, kind)
    return True


@internal("df_deregister")
def _df_deregister(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "df_deregister", 2)
    mas = _system(ag, "df_deregister")
    service, kind = _service(args, s, "df_deregister")
    mas.df_deregister(ag.name, service, kind)
    return True


@internal("df_search")
def _df_search(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.df_search(Service[, Type], Agents)``: the agents that offer the service."""
    need_args(args, 2, "df_search", 3)
    mas = _system(ag, "df_search")
    service, kind = _service(args, s, "df_search")
    names = mas.df_search(service, kind)
    return bind(make_list([Literal(n) for n in names]), args[-1], s, trail)


@internal("df_subscribe")
def _df_subscribe(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.df_subscribe(Service[, Type])``: be told ``provider(Agent, Service)`` for each
    agent that offers the service, now and later."""
    need_args(args, 1, "df_subscribe", 2)
    mas = _system(ag, "df_subscribe")
    service, kind = _service(args, s, "df_subscribe")
    mas.df_subscribe(ag.name, service, kind)
    return True


__all__ = ["LIBRARY", "internal", "NIL"]
