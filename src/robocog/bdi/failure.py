"""Goal failure (Jason's generateGoalDeletion and the search for ``-!g`` down the intention),
and dropping, succeeding, failing, suspending and resuming goals and intentions.

These functions are the :class:`~robocog.bdi.agent.Agent`'s methods (bound there under
the names they had, a leading underscore for the internal ones), kept here by the step
of the cycle they belong to.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from robocog.bdi import plans as P
from robocog.bdi.circumstance import (
    Event,
    Intention,
)
from robocog.bdi.formulas import (
    unifies_under,
)
from robocog.bdi.plans import (
    ACHIEVE,
    BELIEF,
)
from robocog.bdi.terms import (
    Literal,
    Term,
)
from robocog.bdi.unifier import (
    EvalError,
    resolve,
)

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


def failure_event(
    self: Agent, i: Intention | None, tevent: P.Trigger, in_stack: bool = True
) -> Event | None:
    """Jason's search for the ``-!g`` event that handles a failure in ``i``."""
    pl = self.pl
    if i is None or not i.stack:
        if tevent.kind != BELIEF and tevent.op == "+":
            ft = P.Trigger("-", tevent.kind, tevent.literal)
            if pl.has_candidate(ft):
                return Event(ft, i)
        return None
    seq: list = [] if in_stack else [(tevent, None)]
    for im in reversed(i.stack):
        seq.append((im.trigger, im))
    last = len(seq) - 1
    pos = 0
    if in_stack and tevent.kind != BELIEF and tevent.op == "-":
        # failure inside a failure plan: skip down past the goal it was handling
        # (when nothing lies below that goal, the intention is dropped, as Jason
        # drops it: a failing -!g plan never handles its own failure again)
        goal = resolve(tevent.literal, i.stack[-1].s)
        pos = 1
        while pos <= last and not unifies_under(seq[pos][0].literal, goal, seq[pos][1].s):
            pos += 1
        while pos <= last and unifies_under(seq[pos][0].literal, goal, seq[pos][1].s):
            pos += 1
        if pos > last:
            return None
    t, im = seq[pos]
    ft = P.Trigger("-", t.kind, t.literal)
    while not pl.has_candidate(ft) and pos < last:
        pos += 1
        t, im = seq[pos]
        ft = P.Trigger("-", t.kind, t.literal)
    if t.kind != BELIEF and pl.has_candidate(ft):
        lit = resolve(t.literal, im.s) if im is not None else t.literal
        return Event(P.Trigger("-", t.kind, lit), i)
    return None


def annotate_failure(self: Agent, ev: Event, error: str, msg: str, code: Term, line: int) -> None:
    annots: list[Term] = [Literal("error", (Literal(error),)), Literal("error_msg", (msg,))]
    if code is not None:
        c = code.without_annots() if code.__class__ is Literal else code
        annots.append(Literal("code", (c,)))
    if self.url:
        annots.append(Literal("code_src", (self.url,)))
    if line:
        annots.append(Literal("code_line", (line,)))
    lit = ev.trigger.literal
    if lit.__class__ is Literal:
        ev.trigger = P.Trigger(ev.trigger.op, ev.trigger.kind, lit.add_annots(annots))


def fail_intention(
    self: Agent,
    i: Intention,
    error: str = "ia_failed",
    msg: str = "",
    extra: Iterable[Term] = (),
) -> None:
    """Make the current goal of ``i`` fail (Jason's ``generateGoalDeletion``)."""
    if not i.stack:
        return
    if i.fork is not None and self._fork_failure(i):
        return
    im = i.stack[-1]
    ev = self._failure_event(i, im.trigger)
    if ev is None:
        self.warn(f"no failure plan for {im.trigger!r} ({error}{': ' + msg if msg else ''})")
        self._drop(i)
        return
    step = im.cur[0] if im.cur is not None else None
    code = None
    line = 0
    if step is not None:
        line = step.line
        if step.term is not None and step.term.__class__ is not tuple:
            try:
                code = resolve(step.term, im.s)
            except (EvalError, RecursionError):
                code = step.term
    self._annotate_failure(ev, error, msg, code, line)
    extra = tuple(extra)
    if extra and ev.trigger.literal.__class__ is Literal:
        ev.trigger = P.Trigger(ev.trigger.op, ev.trigger.kind, ev.trigger.literal.add_annots(extra))
    self.post(ev)


def drop(self: Agent, i: Intention) -> None:
    """Forget an intention everywhere it may be waiting."""
    i.dropped = True
    self._unschedule(i)


def intentions(self: Agent) -> list[Intention]:
    """All live intentions."""
    return self.C.intentions()


def succeed_at(self: Agent, i: Intention, pos: int) -> None:
    """The goal of ``i.stack[pos]`` is achieved: its plan and those above it go, and the
    caller goes on after the goal (``.succeed_goal``, and a Jason-ER goal condition)."""
    del i.stack[pos:]
    self._unschedule(i)
    if not i.stack:
        i.dropped = True
        return
    caller = i.stack[-1]
    if caller.cur is not None:
        caller.cur = caller.cur[1]
    if caller.cur is None:
        self._clear(i)
    if i.stack:
        self._requeue(i)


def drop_goal(self: Agent, goal: Literal, how: str, current: Intention | None = None) -> bool:
    """Jason's ``.succeed_goal``/``.fail_goal``/``.drop_intention`` on every intention
    that has ``goal`` in its stack; returns True if ``current`` was changed."""
    touched_current = False
    for i in self.C.intentions() + ([current] if current is not None else []):
        if i.dropped or not i.stack:
            continue
        for pos in range(len(i.stack) - 1, -1, -1):
            im = i.stack[pos]
            t = im.trigger
            if t.kind == ACHIEVE and t.op == "+" and unifies_under(goal, t.literal, {}):
                break
        else:
            continue
        if i is current:
            touched_current = True
        if how == "drop":
            self._drop(i)
            continue
        if how == "fail":
            del i.stack[pos + 1 :]
            self._unschedule(i)
            self.fail_intention(i, "ia_failed", "goal failed by .fail_goal")
            continue
        succeed_at(self, i, pos)
    # events for the goal (not yet intentions) go too
    if how != "fail":
        self.C.keep_events(
            lambda e: (
                not (
                    e.intention is None
                    and e.trigger.kind == ACHIEVE
                    and unifies_under(goal, e.trigger.literal, {})
                )
            )
        )
    return touched_current


def intentions_for(self: Agent, goal: Literal, extra: Intention | None = None) -> list[Intention]:
    """The live intentions with ``+!goal`` in their stack (and ``extra`` if it has)."""
    found = []
    for i in self.C.intentions() + ([extra] if extra is not None else []):
        if i.dropped or not i.stack:
            continue
        for im in i.stack:
            t = im.trigger
            if t.kind == ACHIEVE and t.op == "+" and unifies_under(goal, t.literal, {}):
                found.append(i)
                break
    return found


def suspend(self: Agent, i: Intention, current: bool) -> None:
    """Set ``i`` aside until :meth:`resume` (Jason's ``.suspend``). The current
    intention stops at the ``.suspend`` it runs and goes on after it when resumed;
    another one is taken off the running queue as it stands."""
    if not current:
        self._unschedule(i)
    self.C.pending[i.id] = (i, "suspend_ia" if current else "suspended")


def suspension(self: Agent, i: Intention) -> str | None:
    """Why ``i`` is suspended, as ``.suspended`` reports it, or None."""
    entry = self.C.pending.get(i.id)
    if entry is None or entry[1] not in ("suspend_ia", "suspended"):
        return None
    return "suspend_ia"


def resume(self: Agent, i: Intention) -> bool:
    """Let an intention set aside by :meth:`suspend` run again; False if it was not."""
    entry = self.C.pending.get(i.id)
    if entry is None or entry[1] not in ("suspend_ia", "suspended"):
        return False
    del self.C.pending[i.id]
    if entry[1] == "suspend_ia":
        self._advance(i)  # past the .suspend that stopped it
    else:
        self._requeue(i)
    return True


def unschedule(self: Agent, i: Intention) -> None:
    """Take ``i`` out of every queue and wait it is in (it stays alive)."""
    C = self.C
    C.pending.pop(i.id, None)
    if C.atomic_intention is i:
        C.atomic_intention = None
    if C.atomic_event is not None and C.atomic_event.intention is i:
        C.atomic_event = None
    if i in C.running:
        C.running.remove(i)
    C.keep_events(lambda e: e.intention is not i)
