"""The registry of internal actions and the argument helpers every family of them shares."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError
from robocog.bdi.terms import Literal, Term, list_items, term_str
from robocog.bdi.unifier import resolve, undo, unify

LIBRARY: dict[str, Callable] = {}


def internal(name: str) -> Callable[[Callable], Callable]:
    """Register an internal action under ``.name``."""

    def deco(fn: Callable) -> Callable:
        LIBRARY["." + name] = fn
        return fn

    return deco


def need_args(args: tuple, n: int, name: str, most: int | None = None) -> None:
    """Raise :class:`ActionError` unless ``args`` has between ``n`` and ``most`` items."""
    most = n if most is None else most
    if not n <= len(args) <= most:
        # Jason's words, and its error id
        if n == most:
            expected = " One argument is expected." if n == 1 else f" {n} arguments are expected."
        else:
            expected = f" From {n} to {most} arguments are expected."
        raise ActionError(
            f"The internal action '{name}' has not received the required number of "
            f"argument(s).{expected}",
            "wrong_arguments",
        )


def arg_list(t: Term, s: dict, name: str) -> list:
    """The items of the list ``t`` is bound to; an ActionError naming ``.name`` otherwise."""
    v = resolve(t, s)
    items = list_items(v)
    if items is None:
        raise ActionError(f".{name}: {term_str(v)} is not a list")
    return list(items)


def arg_number(t: Term, s: dict, name: str) -> int | float:
    """The number ``t`` is bound to; an ActionError naming ``.name`` otherwise."""
    v = resolve(t, s)
    if v.__class__ is int or v.__class__ is float:
        return v
    raise ActionError(f".{name}: {term_str(v)} is not a number")


def arg_text(t: Term, s: dict) -> str:
    """``t`` as text: a string as it is, any other term as Jason prints it."""
    v = resolve(t, s)
    return v if v.__class__ is str else term_str(v)


def bind(value: Term, target: Term, s: dict, trail: list) -> bool:
    """Bind an output argument: unify ``target`` with ``value``, recording on ``trail``."""
    return unify(target, value, s, trail)


def bind_each(values: Iterator[Term], target: Term, s: dict, trail: list) -> Iterator[None]:
    """Yield once for each of ``values`` that unifies with ``target``, undoing in between
    (how a generator action offers several solutions)."""
    mark = len(trail)
    for v in values:
        if unify(target, v, s, trail):
            yield None
        undo(s, trail, mark)


def unifies(a: Term, b: Term) -> bool:
    """Whether ``a`` and ``b`` unify, leaving no binding behind."""
    return unify(a, b, {}, [])


def belief_event(op: str, kind: str, lit: Literal):  # noqa: ANN202 - Event
    """An external event (no intention) for a change of belief or goal."""
    from robocog.bdi.circumstance import Event

    return Event(P.Trigger(op, kind, lit), None)
