"""Environment actions: how a plan's external action reaches Python and comes back.

An action callable receives the action's arguments (as Python values by default) and
returns one of:

- ``True`` or ``None``: the action succeeded;
- ``False``: the action failed (the goal fails with ``error(action_failed)``);
- an :class:`ActionHandle`: the outcome is not known yet. The intention that executed
  the action waits, the agent keeps reasoning about its other intentions, and the
  environment calls :meth:`ActionHandle.succeed` or :meth:`ActionHandle.fail` when the
  robot reports the outcome (from any thread). The agent picks the outcome up at the
  start of one of its next cycles, as Jason's feedback actions.

Raising an exception also fails the action, with the exception text as the reason.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from robocog.bdi.terms import Cons, Literal, Nil, Term, iter_list, make_list


class ActionHandle:
    """The outcome of an environment action that completes later."""

    __slots__ = ("_ok", "reason", "_lock", "action")

    def __init__(self) -> None:
        self._ok: bool | None = None
        self.reason = ""
        self._lock = threading.Lock()
        self.action: Literal | None = None

    def succeed(self) -> None:
        """Report success; the waiting intention continues after the action."""
        with self._lock:
            if self._ok is None:
                self._ok = True

    def fail(self, reason: str = "") -> None:
        """Report failure; the waiting goal fails with ``error(action_failed)``."""
        with self._lock:
            if self._ok is None:
                self._ok = False
                self.reason = reason

    @property
    def done(self) -> bool:
        """True once an outcome was reported."""
        return self._ok is not None

    @property
    def ok(self) -> bool | None:
        """``True``/``False`` once reported, ``None`` while pending."""
        return self._ok

    def __repr__(self) -> str:
        state = {None: "pending", True: "succeeded", False: "failed"}[self._ok]
        return f"<action {self.action!r} {state}>"


ActionFn = Callable[..., Any]


def to_python(t: Term) -> Any:
    """A term as a plain Python value: numbers and strings as they are, atoms as their
    name, lists as lists; other structures stay :class:`Literal`."""
    c = t.__class__
    if c is int or c is float or c is str:
        return t
    if c is Literal and not t.args and not t.annots and not t.neg:
        return t.functor
    if c is Cons or c is Nil:
        return [to_python(x) for x in iter_list(t)]
    return t


def from_python(v: Any) -> Term:
    """A Python value as a term: ``str`` becomes a string term, lists become lists."""
    if isinstance(v, bool):
        return Literal("true" if v else "false")
    if isinstance(v, (int, float, str)):
        return v
    if isinstance(v, (list, tuple)):
        return make_list([from_python(x) for x in v])
    return v
