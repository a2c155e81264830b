"""The circumstance: events, intended means, intentions, and what is pending.

An intention is a stack of intended means. Each intended means points into its plan's
compiled body (``cur``) and owns its substitution (``s``), so a plan instance costs one
small object. ``ret`` carries what tail-recursion optimisation removed from the stack:
``None`` (nothing), ``("fixed", literal)`` (the value to give back is already known) or
``("chain", frames)``, a linked list of the frames whose variables still wait for it.
"""

from __future__ import annotations

import itertools
from collections import deque
from collections.abc import Callable

from robocog.bdi.plans import Chain, Plan, Trigger

_intention_ids = itertools.count(1)


class Event:
    """A trigger, with the intention that waits for it (``None`` for an external event)."""

    __slots__ = ("trigger", "intention")

    def __init__(self, trigger: Trigger, intention: Intention | None = None) -> None:
        self.trigger = trigger
        self.intention = intention

    def __repr__(self) -> str:
        where = f" (intention {self.intention.id})" if self.intention is not None else ""
        return f"<event {self.trigger!r}{where}>"


class IntendedMeans:
    """A plan being executed for a trigger."""

    __slots__ = ("plan", "trigger", "s", "cur", "ret", "base")

    def __init__(self, plan: Plan, trigger: Trigger, s: dict, cur: Chain) -> None:
        self.plan = plan
        self.trigger = trigger
        self.s = s
        self.cur = cur
        self.ret = None
        #: JasonER: the bindings the plan was chosen with, its sub-plans' starting point
        self.base: dict | None = None

    def __repr__(self) -> str:
        return f"<im {self.trigger!r}>"


_new = object.__new__


def new_event(trigger: Trigger, intention: Intention | None) -> Event:
    """``Event(trigger, intention)`` without the call to ``__init__`` (hot path)."""
    ev = _new(Event)
    ev.trigger = trigger
    ev.intention = intention
    return ev


def new_im(plan: Plan, trigger: Trigger, s: dict, cur: Chain) -> IntendedMeans:
    """``IntendedMeans(plan, trigger, s, cur)`` without the call to ``__init__``."""
    im = _new(IntendedMeans)
    im.plan = plan
    im.trigger = trigger
    im.s = s
    im.cur = cur
    im.ret = None
    im.base = None
    return im


class Intention:
    """A stack of intended means; the top is the one that runs."""

    __slots__ = ("id", "stack", "dropped", "fork")

    def __init__(self) -> None:
        self.id = next(_intention_ids)
        self.stack: list[IntendedMeans] = []
        self.dropped = False
        #: for a branch of a fork (``|&|``, ``|||``): (the fork, the size of the stack
        #: up to the intended means that forked)
        self.fork: tuple[Fork, int] | None = None

    def top(self) -> IntendedMeans:
        """The intended means that runs next."""
        return self.stack[-1]

    def __len__(self) -> int:
        return len(self.stack)

    def __repr__(self) -> str:
        return f"<intention {self.id}: {' / '.join(repr(im.trigger) for im in self.stack)}>"


class Fork:
    """The branches of one ``|&|`` or ``|||`` and how many are still to finish."""

    __slots__ = ("both", "branches", "to_finish")

    def __init__(self, both: bool) -> None:
        self.both = both
        self.branches: list[Intention] = []
        self.to_finish = 0


class Circumstance:
    """Events, running intentions and the intentions waiting for something."""

    def __init__(self) -> None:
        self.events: deque[Event] = deque()
        self.running: deque[Intention] = deque()
        #: intention id -> (intention, why) for intentions waiting on an action, a timer,
        #: an answer or an event
        self.pending: dict[int, tuple[Intention, str]] = {}
        #: Jason's AI and AE: the running atomic intention and the event it waits for
        self.atomic_intention: Intention | None = None
        self.atomic_event: Event | None = None

    def keep_events(self, keep: Callable[[Event], bool]) -> None:
        """Remove, in place, the events for which ``keep`` is false."""
        kept = [e for e in self.events if keep(e)]
        if len(kept) != len(self.events):
            self.events.clear()
            self.events.extend(kept)

    def intentions(self) -> list[Intention]:
        """Every live intention (running, in an event, or pending), each once."""
        seen: dict[int, Intention] = {}
        for i in self.running:
            seen[i.id] = i
        if self.atomic_intention is not None:
            seen[self.atomic_intention.id] = self.atomic_intention
        if self.atomic_event is not None and self.atomic_event.intention is not None:
            seen[self.atomic_event.intention.id] = self.atomic_event.intention
        for e in self.events:
            if e.intention is not None:
                seen[e.intention.id] = e.intention
        for i, _why in self.pending.values():
            seen[i.id] = i
        return list(seen.values())
