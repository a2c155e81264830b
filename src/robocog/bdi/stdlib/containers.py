"""Sets and queues: ``.set.create``/``add``/``add_all``/``remove``/``clear``/``copy``/
``union``/``intersection``/``difference``/``to_list`` and ``.queue.create``/``add``/
``add_all``/``head``/``remove``/``clear``/``copy``/``to_list``, as in Jason.

Each changes its collection in place, and the change stays when the rule or plan that
made it backtracks (see :mod:`robocog.bdi.containers`). As in Jason, the ``.set``
actions given a free variable first make a new set and bind it, while the ``.queue``
actions need a queue made by ``.queue.create`` (only ``create`` binds one).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from robocog.bdi.containers import QueueTerm, SetTerm
from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import bind, internal, need_args
from robocog.bdi.terms import Term, Var, list_items, make_list, term_str
from robocog.bdi.unifier import deref, resolve

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


def members_of(t: Term, s: dict, name: str) -> list:
    """The terms of a list or a set argument (what Jason's ``Collection`` takes)."""
    v = resolve(t, s)
    if v.__class__ is SetTerm or v.__class__ is QueueTerm:
        return v.members()
    items = list_items(v)
    if items is None:
        raise ActionError(f".{name}: {term_str(v)} is neither a list nor a set")
    return list(items)


def _set(args: tuple, s: dict, trail: list, name: str) -> SetTerm:
    """The set of the first argument; a free variable there is bound to a new one."""
    v = deref(args[0], s)
    if v.__class__ is SetTerm:
        return v
    if v.__class__ is Var:
        new = SetTerm()
        bind(new, v, s, trail)
        return new
    raise ActionError(f".set.{name}: {term_str(v)} is not a set")


def _queue(args: tuple, s: dict, name: str) -> QueueTerm:
    v = deref(args[0], s)
    if v.__class__ is QueueTerm:
        return v
    raise ActionError(f".queue.{name}: {term_str(v)} is not a queue (see .queue.create)")


# ---------------------------------------------------------------- sets


@internal("set.create")
def _set_create(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.set.create(S)``: S (a free variable) becomes a new empty set; fails otherwise."""
    need_args(args, 1, "set.create")
    v = deref(args[0], s)
    return v.__class__ is Var and bind(SetTerm(), v, s, trail)


@internal("set.add")
def _set_add(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.add")
    _set(args, s, trail, "add").add(resolve(args[1], s))
    return True


@internal("set.add_all")
def _set_add_all(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.add_all")
    st = _set(args, s, trail, "add_all")
    for t in members_of(args[1], s, "set.add_all"):
        st.add(t)
    return True


@internal("set.union")
def _set_union(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    return _set_add_all(ag, args, s, trail, ctx)


@internal("set.remove")
def _set_remove(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.remove")
    _set(args, s, trail, "remove").remove(resolve(args[1], s))
    return True


@internal("set.clear")
def _set_clear(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "set.clear")
    _set(args, s, trail, "clear").clear()
    return True


@internal("set.intersection")
def _set_intersection(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.intersection")
    _set(args, s, trail, "intersection").retain(members_of(args[1], s, "set.intersection"))
    return True


@internal("set.difference")
def _set_difference(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.difference")
    st = _set(args, s, trail, "difference")
    for t in members_of(args[1], s, "set.difference"):
        st.remove(t)
    return True


@internal("set.copy")
def _set_copy(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.copy")
    return bind(SetTerm(_set(args, s, trail, "copy").members()), args[1], s, trail)


@internal("set.to_list")
def _set_to_list(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "set.to_list")
    return bind(make_list(_set(args, s, trail, "to_list").members()), args[1], s, trail)


# ---------------------------------------------------------------- queues


@internal("queue.create")
def _queue_create(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.queue.create(Q)`` a first-in-first-out queue, ``.queue.create(Q, priority)`` one
    that gives its least member first; fails when Q is not a free variable."""
    need_args(args, 1, "queue.create", 2)
    v = deref(args[0], s)
    if v.__class__ is not Var:
        return False
    priority = len(args) == 2 and term_str(resolve(args[1], s)) == "priority"
    return bind(QueueTerm(priority), v, s, trail)


@internal("queue.add")
def _queue_add(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "queue.add")
    _queue(args, s, "add").offer(resolve(args[1], s))
    return True


@internal("queue.add_all")
def _queue_add_all(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "queue.add_all")
    q = _queue(args, s, "add_all")
    for t in members_of(args[1], s, "queue.add_all"):
        q.offer(t)
    return True


@internal("queue.head")
def _queue_head(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.queue.head(Q, X)``: X unifies with the first member, which stays in Q; an empty
    queue fails."""
    need_args(args, 2, "queue.head")
    t = _queue(args, s, "head").peek()
    return t is not None and bind(t, args[1], s, trail)


@internal("queue.remove")
def _queue_remove(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.queue.remove(Q, X)``: the first member leaves Q and X unifies with it (the
    member is gone even when it does not unify, as in Jason); an empty queue fails."""
    need_args(args, 2, "queue.remove")
    t = _queue(args, s, "remove").poll()
    return t is not None and bind(t, args[1], s, trail)


@internal("queue.clear")
def _queue_clear(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "queue.clear")
    _queue(args, s, "clear").clear()
    return True


@internal("queue.copy")
def _queue_copy(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "queue.copy")
    return bind(_queue(args, s, "copy").copy(), args[1], s, trail)


@internal("queue.to_list")
def _queue_to_list(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "queue.to_list")
    return bind(make_list(_queue(args, s, "to_list").members()), args[1], s, trail)
