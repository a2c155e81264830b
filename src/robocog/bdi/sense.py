"""What an agent takes in at the start of a cycle (the first step of Jason's reasoning
cycle): changed percepts become beliefs, one message is processed, timers and ``.wait``s
that are due wake their intentions.

These functions are the :class:`~robocog.bdi.agent.Agent`'s methods (bound there under
the names they had, a leading underscore for the internal ones), kept here by the step
of the cycle they belong to.
"""

from __future__ import annotations

import heapq
from typing import TYPE_CHECKING

from robocog.bdi import plans as P
from robocog.bdi.circumstance import (
    Event,
    IntendedMeans,
    Intention,
)
from robocog.bdi.logic import holds
from robocog.bdi.messages import handle_message
from robocog.bdi.plans import (
    BELIEF,
)
from robocog.bdi.terms import (
    SOURCE_PERCEPT,
    Literal,
    Term,
    term_str,
)
from robocog.bdi.unifier import (
    unify,
)

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


def perceive(self: Agent) -> None:
    """Take in the current percepts now rather than at the next cycle (``.perceive``):
    beliefs with ``source(percept)`` follow them, with their events."""
    self._buf()


def buf(self: Agent) -> None:
    self._percepts_dirty = False
    new = self._percepts
    old = self._perceived
    # percepts are kept without annotations: source(percept) is their only one
    for lit in [p for p in old if p not in new]:
        gone = self.bb.remove(
            Literal.make(lit.functor, lit.args, (SOURCE_PERCEPT,), lit.neg, lit.ground)
        )
        if gone is not None:
            self.post(Event(P.Trigger("-", BELIEF, gone), None))
    for lit in new:
        if lit not in old:
            b = Literal.make(lit.functor, lit.args, (SOURCE_PERCEPT,), lit.neg, lit.ground)
            if self.bb.add(b) is not None:
                self.post(Event(P.Trigger("+", BELIEF, b), None))
    self._perceived = dict(new)


#: what a message taken from the mailbox does (the agent's ``_process_message``)
process_message = handle_message


class Deadline:
    """A goal's ``hard_deadline``: when it is due and the goal's plan is still in its
    intention, the goal fails with ``error(deadline_reached)``, as in Jason."""

    __slots__ = ("intention", "im")

    def __init__(self, intention: Intention, im: IntendedMeans) -> None:
        self.intention = intention
        self.im = im


def add_deadline(self: Agent, delay_ms: float, i: Intention, im: IntendedMeans) -> None:
    """Fail the goal of ``im`` in ``i`` unless it is finished within ``delay_ms``."""
    self._timer_seq += 1
    heapq.heappush(self._timers, (self.clock + delay_ms, self._timer_seq, Deadline(i, im)))


def _deadline_due(self: Agent, d: Deadline) -> None:
    i, im = d.intention, d.im
    if i.dropped:
        return
    for pos in range(len(i.stack) - 1, -1, -1):
        if i.stack[pos] is im:
            break
    else:
        return  # the goal was achieved (or dropped) in time
    del i.stack[pos + 1 :]
    self._unschedule(i)
    self.fail_intention(i, "deadline_reached", "hard deadline reached")


def stale_timer(self: Agent, entry: tuple) -> bool:
    """True for a timer nothing waits on any more (dropped from the front of the heap,
    so that an agent does not stay awake for it)."""
    _t, seq, i = entry
    if i.__class__ is Deadline:
        d = i.intention
        return d.dropped or all(im is not i.im for im in d.stack)
    return self._timer_of.get(i.id) != seq or i.dropped


def wake_timers(self: Agent) -> None:
    while self._timers and self._timers[0][0] <= self.clock:
        _t, seq, i = heapq.heappop(self._timers)
        if i.__class__ is Deadline:
            _deadline_due(self, i)
            continue
        if self._timer_of.get(i.id) != seq:
            continue  # a wait the intention no longer waits on (it failed or moved on)
        del self._timer_of[i.id]
        entry = self.C.pending.pop(i.id, None)
        if entry is None or i.dropped:
            continue
        if entry[1] in ("wait_event", "wait_formula"):
            # the awaited event or condition did not come in time: .wait fails,
            # unless it was given a variable for the elapsed time
            if self._resume_wait(i) is False:
                self.fail_intention(i, "wait_timeout", "timeout in .wait")  # Jason's words
            continue
        self._advance(i)


def resume_wait(self: Agent, i: Intention) -> bool:
    """Resume ``i`` after a ``.wait``; False if it timed out without an elapsed var."""
    got = self.wait_elapsed.pop(i.id, None)
    if got is None:
        return False
    term, start = got
    elapsed = self.clock - start
    unify(term, int(elapsed) if elapsed == int(elapsed) else elapsed, i.top().s, [])
    self._advance(i)
    return True


def add_timer(self: Agent, delay_ms: float, i: Intention) -> None:
    """Suspend ``i`` and resume it after ``delay_ms`` (used by ``.wait``)."""
    self._timer_seq += 1
    self._timer_of[i.id] = self._timer_seq
    heapq.heappush(self._timers, (self.clock + delay_ms, self._timer_seq, i))
    self.C.pending[i.id] = (i, "wait")
    ms = int(delay_ms)  # Jason keeps the timeout as a whole number (a long)
    self.wait_reasons[i.id] = Literal("wait", (i.id,), (Literal("time", (ms,)),))


def wait_event(self: Agent, trigger: P.Trigger, i: Intention, timeout: float | None) -> None:
    """Suspend ``i`` until an event unifying with ``trigger`` happens."""
    deadline = None if timeout is None else self.clock + timeout
    self._event_waiters.append((trigger, i, deadline))
    self.C.pending[i.id] = (i, "wait_event")
    self.wait_reasons[i.id] = Literal("wait", (i.id,), (trigger.literal,))
    if deadline is not None:
        self._timer_seq += 1
        self._timer_of[i.id] = self._timer_seq
        heapq.heappush(self._timers, (deadline, self._timer_seq, i))


def wait_formula(self: Agent, f: Term, i: Intention, timeout: float | None) -> None:
    """Suspend ``i`` until the formula ``f`` holds (checked at each cycle)."""
    self._formula_waiters.append((f, i))
    self.C.pending[i.id] = (i, "wait_formula")
    self.wait_reasons[i.id] = Literal("wait", (i.id,), (f,))
    if timeout is not None:
        self._timer_seq += 1
        self._timer_of[i.id] = self._timer_seq
        heapq.heappush(self._timers, (self.clock + timeout, self._timer_seq, i))


def check_formula_waiters(self: Agent) -> None:
    keep = []
    for f, i in self._formula_waiters:
        if i.id not in self.C.pending or i.dropped:
            continue
        try:
            ok = holds(self, f, i.top().s, [])
        except Exception as exc:  # noqa: BLE001 - a bad formula ends the wait as failed
            self.warn(f".wait on {term_str(f)}: {exc}")
            self.C.pending.pop(i.id, None)
            self.fail_intention(i, "ia_failed", str(exc))
            continue
        if ok:
            self.C.pending.pop(i.id, None)
            if not self._resume_wait(i):
                self._advance(i)
        else:
            keep.append((f, i))
    self._formula_waiters = keep


def check_event_waiters(self: Agent, trig: P.Trigger) -> None:
    keep = []
    for entry in self._event_waiters:
        t, i, _d = entry
        if (
            t.op == trig.op
            and t.kind == trig.kind
            and i.id in self.C.pending
            and unify(t.literal, trig.literal, i.top().s, [])
        ):
            self.C.pending.pop(i.id, None)
            if not self._resume_wait(i):
                self._advance(i)
        elif i.id in self.C.pending:
            keep.append(entry)
    self._event_waiters = keep
