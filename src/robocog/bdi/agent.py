"""The agent and its reasoning cycle, as Jason defines it.

One call to :meth:`Agent.step` is one reasoning cycle:

1. *sense*: percepts that changed become beliefs annotated ``source(percept)`` (and
   ``+b``/``-b`` events); one message from the mailbox is processed; timers that are due
   wake their intentions;
2. *deliberate*: one event is selected (FIFO), the first applicable plan in program
   order is found and pushed as an intended means (tail-recursion optimisation pops the
   finished caller first);
3. *act*: one finished environment action is fed back, then one intention is selected
   (round robin) and one formula of its body is executed.

Goal failures generate ``-!g`` events annotated with ``error(...)``, searched down the
intention as Jason does; belief changes made by a plan are handled in the same
intention (``intBels = sameFocus``). The selection functions are methods meant to be
overridden.
"""

from __future__ import annotations

import functools
import heapq
import sys
from collections import deque
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.bdi import context
from robocog.bdi import plans as P
from robocog.bdi.actions import ActionFn, ActionHandle, to_python
from robocog.bdi.beliefs import BeliefBase
from robocog.bdi.circumstance import (
    Circumstance,
    Event,
    Fork,
    IntendedMeans,
    Intention,
    new_event,
    new_im,
)
from robocog.bdi.logic import NOT_SUPPORTED, ActionError, holds, solve, unknown_action
from robocog.bdi.messages import Message, handle_message
from robocog.bdi.parser import (
    ParseError,
    Program,
    Rule,
    parse_literal,
    parse_program,
    parse_term,
    read_source,
)
from robocog.bdi.plans import (
    ACHIEVE,
    ACHIEVE_NF,
    ACHIEVE_STEP,
    ACTION,
    ADD_BEL,
    ADD_BEL_END,
    ADD_BEL_NF,
    BELIEF,
    CONSTRAINT,
    DEL_ADD_BEL,
    DEL_BEL,
    DEL_BEL_NF,
    FOR,
    FOR_NEXT,
    FORK,
    IF,
    INTERNAL,
    JOIN,
    TEST,
    TEST_STEP,
    WHILE,
    WHILE_AGAIN,
)
from robocog.bdi.signals import DONE, SUSPEND
from robocog.bdi.terms import (
    SOURCE_PERCEPT,
    SOURCE_SELF,
    Arith,
    Cons,
    Literal,
    Term,
    Var,
    is_ground,
    term_str,
)
from robocog.bdi.unifier import (
    EvalError,
    deref,
    resolve,
    undo,
    unify,
    variables,
)

if TYPE_CHECKING:
    from robocog.bdi.mas import MultiAgentSystem


Option = tuple  # (Plan, substitution)


def _with_source(lit: Literal, src: Literal = SOURCE_SELF) -> Literal:
    annots = lit.annots
    if not annots:
        return Literal.make(lit.functor, lit.args, (src,), lit.neg, lit.ground and src.ground)
    for a in annots:
        if a.__class__ is Literal and a.functor == "source":
            return lit
    return lit.add_annots((src,))


@functools.lru_cache(maxsize=4096)
def _parse_cached(text: str) -> Literal:
    return parse_literal(text)


@functools.lru_cache(maxsize=4096)
def _bare_cached(text: str) -> Literal:
    return parse_literal(text).without_annots()


def _bare(x: str | Literal) -> Literal:
    """A percept as a literal without annotations."""
    return _bare_cached(x) if x.__class__ is str else _as_literal(x).without_annots()


def _as_literal(x: str | Literal) -> Literal:
    return _parse_cached(x) if isinstance(x, str) else x


class Agent:
    """An AgentSpeak agent: beliefs, plans, events and intentions, and its cycle."""

    #: Jason's tail-recursion optimisation (on by default, as in Jason)
    tail_recursion = True

    def __init__(
        self,
        source: str | Program = "",
        name: str = "agent",
        *,
        file: str = "",
        printer: Callable[[str, str], None] | None = None,
        warn: Callable[[str, str], None] | None = None,
        asl_path: Iterable[str | Path] = (),
    ) -> None:
        from robocog.bdi import stdlib

        self.name = name
        self.bb = BeliefBase()
        self.pl = P.PlanLibrary()
        self.C = Circumstance()
        self.cycle = 0
        self.clock = 0.0  # milliseconds of (virtual) time, advanced by run()
        self.mas: MultiAgentSystem | None = None
        self.mailbox: deque[Message] = deque()
        self.printer = printer or _default_printer
        self.warner = warn or _default_warner
        self._actions: dict[str, tuple[ActionFn, bool]] = {}
        self._internal: dict[str, Callable] = dict(stdlib.LIBRARY)
        self._feedback: deque[tuple[Intention, bool, str, Literal]] = deque()
        self._waiting_actions: list[tuple[ActionHandle, Intention]] = []
        self._timers: list[tuple[float, int, Intention]] = []
        self._timer_seq = 0
        self._event_waiters: list[tuple[P.Trigger, Intention, float | None]] = []
        self._formula_waiters: list[tuple[Term, Intention]] = []
        #: intention id -> (variable for the elapsed time, start) of a running .wait
        self.wait_elapsed: dict[int, tuple[Term, float]] = {}
        self._percepts: dict[Literal, None] = {}
        self._perceived: dict[Literal, None] = {}
        self._percepts_dirty = False
        self._asks: dict[str, tuple[Intention, Term]] = {}
        self._custom_option = type(self).select_option is not Agent.select_option
        self._has_atomic = False
        self._custom_event = type(self).select_event is not Agent.select_event
        self._custom_intention = type(self).select_intention is not Agent.select_intention
        self.file = file
        #: folders searched for included files after the including file's own
        self.asl_path = tuple(asl_path)
        if isinstance(source, Program):
            self.load_program(source)
        elif source:
            self.load(source, file)

    # ------------------------------------------------------------------ building
    @classmethod
    def from_file(cls, path: str | Path, name: str | None = None, **kw: Any) -> Agent:
        """Build an agent from an ``.asl`` file, named after the file unless told."""
        p = Path(path)
        return cls(read_source(p), name or p.stem, file=str(p), **kw)

    def load(self, text: str, source: str = "") -> None:
        """Parse ``text`` and add its beliefs, rules, initial goals and plans."""
        self.load_program(parse_program(text, source, self.asl_path))

    def load_program(self, prog: Program) -> None:
        """Add a parsed program: beliefs (with ``+b`` events), rules, goals, plans."""
        for plan in prog.plans:
            self.add_plan(plan)
        # Jason inserts initial beliefs back to front, each at the front of the base
        for b in reversed(prog.beliefs):
            if isinstance(b, Rule):
                self.bb.add_rule(Rule(_with_source(b.head), b.body))
            else:
                lit = resolve(b, {})
                if not is_ground(lit):
                    self.bb.add_rule(Rule(_with_source(lit), Literal("true")))
                    continue
                self.bb.add(_with_source(lit))
        for b in prog.beliefs:
            if not isinstance(b, Rule):
                lit = _with_source(resolve(b, {}))
                if is_ground(lit):
                    self.post(Event(P.Trigger("+", BELIEF, lit), None))
        for g in prog.goals:
            lit = _with_source(resolve(g, {}, {}))
            self.C.events.append(Event(P.Trigger("+", ACHIEVE, lit), None))

    def add_plan(self, plan: P.Plan | str, at_end: bool = True) -> None:
        """Add a plan (object or source text) to the plan library."""
        if isinstance(plan, str):
            from robocog.bdi.parser import parse_plan

            plan = parse_plan(plan)
        if plan.label is not None and any(
            a.__class__ is Literal and a.functor == "atomic" for a in plan.label.annots
        ):
            self._has_atomic = True
        self.pl.add(plan, at_end)

    # ------------------------------------------------------------------ Python API
    def register_action(self, name: str, fn: ActionFn, raw: bool = False) -> None:
        """Make ``name(...)`` in plan bodies call ``fn``.

        ``fn`` gets the arguments as Python values (or as terms with ``raw=True``) and
        returns True/None, False or an :class:`ActionHandle` (see ``actions``).
        """
        self._actions[name] = (fn, raw)

    def register_internal_action(self, name: str, fn: Callable) -> None:
        """Add an internal action ``.name``: ``fn(agent, args, s, trail, ctx)``."""
        self._internal[name if name.startswith(".") else "." + name] = fn

    def internal_action(self, name: str) -> Callable | None:
        """The implementation of internal action ``name`` (with its leading dot)."""
        return self._internal.get(name)

    def count_solutions(self, query: Term, s: dict) -> int:
        """How many ways ``query`` holds on the beliefs under ``s`` (``.count``)."""
        n = 0
        trail: list = []
        for _ in solve(self, query, s, trail):
            n += 1
        undo(s, trail, 0)
        return n

    def add_percept(self, percept: str | Literal) -> None:
        """Perceive ``percept`` from the next cycle on (until removed)."""
        lit = _as_literal(percept).without_annots()
        if lit not in self._percepts:
            self._percepts[lit] = None
            self._percepts_dirty = True
            self._wake()

    def remove_percept(self, percept: str | Literal) -> None:
        """Stop perceiving ``percept``."""
        lit = _as_literal(percept).without_annots()
        if lit in self._percepts:
            del self._percepts[lit]
            self._percepts_dirty = True
            self._wake()

    def set_percepts(self, percepts: Iterable[str | Literal]) -> None:
        """Replace all percepts at once (what the sensors report now)."""
        if not percepts and not self._percepts and percepts.__class__ in (list, tuple):
            return  # nothing perceived before or now
        new = dict.fromkeys(map(_bare, percepts))
        if list(new) != list(self._percepts):
            self._percepts = new
            self._percepts_dirty = True
            self._wake()

    def clear_percepts(self) -> None:
        """Perceive nothing."""
        self.set_percepts(())

    def percepts(self) -> list[Literal]:
        """What the agent is told it perceives."""
        return list(self._percepts)

    def add_belief(self, belief: str | Literal) -> None:
        """Add a belief (``source(self)`` unless annotated) and its ``+b`` event."""
        lit = _with_source(resolve(_as_literal(belief), {}))
        if self.bb.add(lit) is not None:
            self.post(Event(P.Trigger("+", BELIEF, lit), None))
            self._wake()

    def remove_belief(self, belief: str | Literal) -> None:
        """Remove a belief (its ``source(self)`` unless annotated) and post ``-b``."""
        lit = _with_source(resolve(_as_literal(belief), {}))
        gone = self.bb.remove(lit)
        if gone is not None:
            self.post(Event(P.Trigger("-", BELIEF, gone), None))
            self._wake()

    def add_goal(self, goal: str | Literal) -> None:
        """Post ``+!goal`` as a new (external) goal."""
        lit = _with_source(resolve(_as_literal(goal), {}, {}))
        self.post(Event(P.Trigger("+", ACHIEVE, lit), None))
        self._wake()

    def _wake(self) -> None:
        """Tell the system this agent, asleep perhaps, has news from outside."""
        if self.mas is not None:
            self.mas.wake(self)

    def beliefs(self, functor: str | None = None) -> list[Literal]:
        """The facts in the belief base (optionally of one functor), newest first."""
        return [b for b in self.bb if functor is None or b.functor == functor]

    def query(self, formula: str | Term) -> list[dict[str, Term]]:
        """All solutions of a formula, e.g. ``"at(X) & X \\== door"``, as name -> value."""
        f = parse_term(formula) if isinstance(formula, str) else formula
        names = [v for v in variables(f) if v.name != "_"]
        context.running.set(self)
        out = []
        s: dict = {}
        for _ in solve(self, f, s, []):
            out.append({v.name: resolve(v, s) for v in names})
        return out

    def believes(self, formula: str | Term) -> bool:
        """True if the formula follows from the beliefs."""
        f = parse_term(formula) if isinstance(formula, str) else formula
        return holds(self, f, {}, [])

    # ------------------------------------------------------------------ selection
    def select_event(self, events: deque[Event]) -> Event | None:
        """Jason's default: the oldest event. Override to change; remove what you pick."""
        return events.popleft()

    def select_option(self, options: list[Option]) -> Option | None:
        """Jason's default: the first applicable plan in program order."""
        return options[0] if options else None

    def select_intention(self, running: deque[Intention]) -> Intention | None:
        """Jason's default: round robin (the intention that waited longest)."""
        return running.popleft()

    # ------------------------------------------------------------------ output
    def print(self, text: str) -> None:
        """Output of ``.print``; goes to ``printer(name, text)``."""
        self.printer(self.name, text)

    def warn(self, text: str) -> None:
        """A diagnostic; goes to ``warner(name, text)`` (stderr by default)."""
        self.warner(self.name, text)

    # ------------------------------------------------------------------ running
    def post(self, ev: Event) -> None:
        """Add an event (and wake intentions waiting for it with ``.wait``)."""
        if self._has_atomic and ev.intention is not None and _is_atomic(ev.intention):
            self.C.atomic_event = ev
            return
        if self._event_waiters:
            self._check_event_waiters(ev.trigger)
        elif (
            ev.intention is None
            and ev.trigger.kind == BELIEF
            and not self._custom_event
            and not self.pl.has_candidate(ev.trigger)
        ):
            return  # it would be discarded when selected, without using a cycle
        self.C.events.append(ev)

    def is_idle(self) -> bool:
        """Nothing to do now: no event, no runnable intention, no news to take in."""
        C = self.C
        if C.events or C.running or self._feedback or self.mailbox or self._percepts_dirty:
            return False
        if C.atomic_intention is not None or C.atomic_event is not None:
            return False
        for h, _i in self._waiting_actions:
            if h.done:
                return False
        if self._timers and self._timers[0][0] <= self.clock:
            return False
        return True

    def has_pending(self) -> bool:
        """True while some intention waits for an action outcome, a timer or a reply."""
        return bool(self.C.pending)

    def next_timer(self) -> float | None:
        """When the earliest ``.wait`` ends (virtual milliseconds), if any."""
        return self._timers[0][0] if self._timers else None

    def run(self, max_cycles: int | None = None, advance_clock: bool = True) -> int:
        """Run cycles until idle (skipping virtual time to pending timers); returns cycles."""
        n = 0
        C = self.C
        events = C.events
        running = C.running
        step = self.step
        # the cycle of step(), inlined for the common case (nothing to sense, no atomic
        # plan, default selection functions); anything else goes through step()
        inline = (
            type(self).step is Agent.step and not self._custom_event and not self._custom_intention
        )
        deliberate = self._deliberate
        execute = self._execute
        feedback = self._feedback
        waiting = self._waiting_actions
        mailbox = self.mailbox
        limit = sys.maxsize if max_cycles is None else max_cycles
        popleft = events.popleft
        next_intention = running.popleft
        while n < limit:
            if events or running or feedback or C.atomic_intention is not None:
                n += 1
                if (
                    inline
                    and not self._percepts_dirty
                    and not mailbox
                    and not self._timers
                    and not self._formula_waiters
                    and not self._has_atomic
                ):
                    context.running.set(self)
                    self.cycle += 1
                    while events:
                        if deliberate(popleft()):
                            break
                    if feedback or waiting:
                        self._process_feedback()
                    if running:
                        execute(next_intention())
                else:
                    step()
                continue
            if self.is_idle():
                if advance_clock and self._timers:
                    self.clock = max(self.clock, self._timers[0][0])
                    continue
                break
            self.step()
            n += 1
        return n

    def step(self) -> None:
        """One reasoning cycle."""
        context.running.set(self)
        self.cycle += 1
        C = self.C
        # ---- sense
        if self._percepts_dirty:
            self._buf()
        if self.mailbox:
            self._process_message(self.mailbox.popleft())
        if self._timers and self._timers[0][0] <= self.clock:
            self._wake_timers()
        if self._formula_waiters:
            self._check_formula_waiters()
        # ---- deliberate (an external belief event that no plan handles is discarded
        # and the next event selected in the same cycle, as in Jason)
        events = C.events
        if C.atomic_intention is not None:
            pass  # an atomic intention runs alone: no event is selected
        elif C.atomic_event is not None:
            ev = C.atomic_event
            C.atomic_event = None
            self._deliberate(ev)
        else:
            while events:
                ev = self.select_event(events) if self._custom_event else events.popleft()
                if ev is None or self._deliberate(ev):
                    break
        # ---- act
        if self._feedback or self._waiting_actions:
            self._process_feedback()
        if C.atomic_intention is not None:
            i = C.atomic_intention
            C.atomic_intention = None
            self._execute(i)
            return
        running = C.running
        if running:
            i = self.select_intention(running) if self._custom_intention else running.popleft()
            if i is not None:
                self._execute(i)

    # ------------------------------------------------------------------ sense
    def perceive(self) -> None:
        """Take in the current percepts now rather than at the next cycle (``.perceive``):
        beliefs with ``source(percept)`` follow them, with their events."""
        self._buf()

    def _buf(self) -> None:
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

    def _process_message(self, msg: Message) -> None:
        handle_message(self, msg)

    def _wake_timers(self) -> None:
        while self._timers and self._timers[0][0] <= self.clock:
            _t, _seq, i = heapq.heappop(self._timers)
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

    def _resume_wait(self, i: Intention) -> bool:
        """Resume ``i`` after a ``.wait``; False if it timed out without an elapsed var."""
        got = self.wait_elapsed.pop(i.id, None)
        if got is None:
            return False
        term, start = got
        elapsed = self.clock - start
        unify(term, int(elapsed) if elapsed == int(elapsed) else elapsed, i.top().s, [])
        self._advance(i)
        return True

    def add_timer(self, delay_ms: float, i: Intention) -> None:
        """Suspend ``i`` and resume it after ``delay_ms`` (used by ``.wait``)."""
        self._timer_seq += 1
        heapq.heappush(self._timers, (self.clock + delay_ms, self._timer_seq, i))
        self.C.pending[i.id] = (i, "wait")

    def wait_event(self, trigger: P.Trigger, i: Intention, timeout: float | None) -> None:
        """Suspend ``i`` until an event unifying with ``trigger`` happens."""
        deadline = None if timeout is None else self.clock + timeout
        self._event_waiters.append((trigger, i, deadline))
        self.C.pending[i.id] = (i, "wait_event")
        if deadline is not None:
            self._timer_seq += 1
            heapq.heappush(self._timers, (deadline, self._timer_seq, i))

    def wait_formula(self, f: Term, i: Intention, timeout: float | None) -> None:
        """Suspend ``i`` until the formula ``f`` holds (checked at each cycle)."""
        self._formula_waiters.append((f, i))
        self.C.pending[i.id] = (i, "wait_formula")
        if timeout is not None:
            self._timer_seq += 1
            heapq.heappush(self._timers, (self.clock + timeout, self._timer_seq, i))

    def _check_formula_waiters(self) -> None:
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

    def _check_event_waiters(self, trig: P.Trigger) -> None:
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

    # ------------------------------------------------------------------ deliberate
    def relevant_plans(self, trigger: P.Trigger) -> list[P.Plan]:
        """Plans whose trigger unifies with ``trigger``, in program order."""
        out = []
        for plan in self.pl.candidates(trigger):
            if unify(plan.trigger.literal, trigger.literal, {}, []):
                out.append(plan)
        return out

    def applicable_options(self, ev: Event) -> list[Option]:
        """Every (plan, substitution) whose trigger unifies and whose context holds."""
        out = []
        for plan in self.pl.candidates(ev.trigger):
            s: dict = {}
            trail: list = []
            if unify(plan.trigger.literal, ev.trigger.literal, s, trail):
                if plan.test is None or self._context(plan, s, trail):
                    out.append((plan, s))
        return out

    def _context(self, plan: P.Plan, s: dict, trail: list) -> bool:
        try:
            return plan.test(self, s, trail)
        except Exception as exc:  # noqa: BLE001 - a bad context is just false
            self.warn(f"error in the context of {plan.trigger!r}: {exc}")
            return False

    def _deliberate(self, ev: Event) -> bool:
        """Handle one event; False when it was discarded without using the cycle."""
        trig = ev.trigger
        pl = self.pl
        got = trig.cands
        if got is not None and got[0] is pl and got[1] == pl.version:
            cands = got[2]
        else:
            cands = pl.candidates(trig)
        if not cands:
            i = ev.intention
            if trig.kind == BELIEF:
                if i is None:
                    return False
                # a belief change of this intention that no plan handles: carry on
                if not i.dropped:
                    self._advance(i)
                return True
            self._no_plan(ev, "relevant")
            return True
        if self._custom_option:
            option = self.select_option(self.applicable_options(ev))
            if option is None:
                return self._no_option(ev)
            plan, s = option
        else:
            lit = trig.literal
            simple = lit.__class__ is Literal and not lit.neg
            trail: list = []  # emptied after each plan that is not applicable
            for plan in cands:
                bind = plan.bind
                if bind >= 0 and simple:
                    # the candidates have the event's arity: the parameters take its args
                    if bind == 1:
                        s: dict = {plan.params[0]: lit.args[0]}
                    elif bind == 0:
                        s = {}
                    else:
                        s = dict(zip(plan.params, lit.args))  # noqa: B905
                elif bind == -2 and simple and lit.ground:
                    # a ground trigger without annotations against a ground event of
                    # the same predicate: unification is equality of the arguments
                    if plan.trigger.literal.args != lit.args:
                        continue
                    s = {}
                else:
                    s = {}
                    if not unify(plan.trigger.literal, lit, s, trail):
                        trail.clear()
                        continue
                test = plan.test
                if test is None:
                    break
                try:
                    if test(self, s, trail):
                        break
                except Exception as exc:  # noqa: BLE001 - a bad context is just false
                    self.warn(f"error in the context of {plan.trigger!r}: {exc}")
                trail.clear()
            else:
                return self._no_option(ev)
        im = new_im(plan, trig, s, plan.body)
        i = ev.intention
        if i is None:
            i = Intention()
            i.stack.append(im)
            self._requeue(i)
            return True
        if i.dropped:
            return True
        stack = i.stack
        top = stack[-1] if stack else None
        cur = top.cur if top is not None else None
        if cur is not None and cur[1] is None and self.tail_recursion:
            if trig.op == "+" and trig.kind != BELIEF:
                t1 = top.trigger
                l1 = t1.literal
                l2 = trig.literal
                if (
                    t1.op == "+"
                    and t1.kind != BELIEF
                    and l1.__class__ is Literal
                    and l2.__class__ is Literal
                    and l1.functor == l2.functor
                    and len(l1.args) == len(l2.args)
                ):
                    stack.pop()
                    ret = top.ret
                    im.ret = ret if ret is not None and ret[0] == "fixed" else self._tro_ret(top)
        stack.append(im)
        if self._has_atomic:
            self._requeue(i)
        else:
            self.C.running.append(i)
        return True

    def _no_option(self, ev: Event) -> bool:
        """No applicable plan for ``ev``: False when it is discarded without using the
        cycle (an external belief change), else the failure of its goal."""
        if ev.intention is None and ev.trigger.kind == BELIEF:
            return False
        self._no_plan(ev, "applicable")
        return True

    def _tro_ret(self, top: IntendedMeans) -> Any:
        """What the intended means replacing ``top`` must give back to ``top``'s caller."""
        ret = top.ret
        if ret is not None and ret[0] == "fixed":
            return ret
        val = top.trigger.literal
        if not val.ground:
            val = resolve(val, top.s)
        if is_ground(val):
            if ret is not None:
                val = _propagate(val, ret[1])
            return ("fixed", val)
        entry = (top.cur[0].term, top.s, top.trigger.literal)
        return ("chain", (entry, ret[1] if ret is not None else None))

    def _no_plan(self, ev: Event, what: str) -> None:
        trig = ev.trigger
        if trig.op == "+" and trig.kind != BELIEF:
            msg = f"Found a goal for which there is no {what} plan: {trig!r}"
            fail_ev = self._failure_event(ev.intention, trig, in_stack=False)
            if fail_ev is not None:
                self._annotate_failure(fail_ev, f"no_{what}", msg, trig.literal, 0)
                self.post(fail_ev)
            else:
                self.warn(msg)
                if ev.intention is not None:
                    self._drop(ev.intention)
        elif ev.intention is not None:
            # a belief change of this intention that no plan handles: carry on
            if not ev.intention.dropped:
                self._advance(ev.intention)
        elif trig.kind != BELIEF:
            self.warn(f"no {what} plan for {trig!r}")

    # ------------------------------------------------------------------ failure
    def _failure_event(
        self, i: Intention | None, tevent: P.Trigger, in_stack: bool = True
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
            while pos <= last and not _unifies(seq[pos][0].literal, goal, seq[pos][1].s):
                pos += 1
            while pos <= last and _unifies(seq[pos][0].literal, goal, seq[pos][1].s):
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

    def _annotate_failure(self, ev: Event, error: str, msg: str, code: Term, line: int) -> None:
        annots: list[Term] = [Literal("error", (Literal(error),)), Literal("error_msg", (msg,))]
        if code is not None:
            c = code.without_annots() if code.__class__ is Literal else code
            annots.append(Literal("code", (c,)))
        if self.file:
            annots.append(Literal("code_src", (self.file,)))
        if line:
            annots.append(Literal("code_line", (line,)))
        lit = ev.trigger.literal
        if lit.__class__ is Literal:
            ev.trigger = P.Trigger(ev.trigger.op, ev.trigger.kind, lit.add_annots(annots))

    def fail_intention(
        self,
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
            ev.trigger = P.Trigger(
                ev.trigger.op, ev.trigger.kind, ev.trigger.literal.add_annots(extra)
            )
        self.post(ev)

    def _drop(self, i: Intention) -> None:
        """Forget an intention everywhere it may be waiting."""
        i.dropped = True
        C = self.C
        C.pending.pop(i.id, None)
        if C.atomic_intention is i:
            C.atomic_intention = None
        if C.atomic_event is not None and C.atomic_event.intention is i:
            C.atomic_event = None
        if i in C.running:
            C.running.remove(i)
        C.keep_events(lambda e: e.intention is not i)

    # ------------------------------------------------------------------ act
    def _process_feedback(self) -> None:
        item = None
        if self._feedback:
            item = self._feedback.popleft()
        else:
            for k, (h, i) in enumerate(self._waiting_actions):
                if h.done:
                    del self._waiting_actions[k]
                    item = (i, bool(h.ok), h.reason, h.action)
                    break
        if item is None:
            return
        i, ok, reason, _action = item
        if self.C.pending.pop(i.id, None) is None or i.dropped:
            return
        if ok:
            # the action succeeded: on to the next formula (``_advance``)
            stack = i.stack
            im = stack[-1]
            cur = im.cur
            if cur is not None:
                cur = im.cur = cur[1]
            if cur is None:
                self._clear(i)
                if not stack:
                    return
            if self._has_atomic:
                self._requeue(i)
            else:
                self.C.running.append(i)
        else:
            noenv = (Literal("noenv"),) if reason == NO_ENVIRONMENT else ()
            self.fail_intention(i, "action_failed", reason, noenv)

    def execute_action(self, action: Literal) -> Any:
        """Run an environment action; override to plug in an environment object."""
        entry = self._actions.get(action.functor)
        if entry is None:
            if self.mas is not None and self.mas.environment is not None:
                return self.mas.environment(self.name, action)
            if not self._actions:
                raise ActionError(NO_ENVIRONMENT)  # Jason's words, when there is none
            raise ActionError(f"no environment action {action.functor}/{len(action.args)}")
        fn, raw = entry
        if raw:
            return fn(*action.args)
        return fn(*map(to_python, action.args))

    def _act(self, i: Intention, lit: Literal) -> None:
        try:
            result = self.execute_action(lit)
        except Exception as exc:  # noqa: BLE001 - any failure of user code fails the action
            self.C.pending[i.id] = (i, "action")
            self._feedback.append((i, False, str(exc), lit))
            return
        self.C.pending[i.id] = (i, "action")
        if result is True or result is None:
            self._feedback.append((i, True, "", lit))
        elif isinstance(result, ActionHandle):
            result.action = lit
            self._waiting_actions.append((result, i))
        else:
            self._feedback.append((i, result is not False, "", lit))

    def _requeue(self, i: Intention) -> None:
        """Put ``i`` back among the running intentions (Jason's ``addRunningIntention``)."""
        if self._has_atomic and _is_atomic(i):
            self.C.atomic_intention = i
        else:
            self.C.running.append(i)

    def _advance(self, i: Intention) -> None:
        """Jason's ``removeActionReQueue`` followed by ``ClrInt``."""
        stack = i.stack
        im = stack[-1]
        cur = im.cur
        if cur is not None:
            cur = im.cur = cur[1]
        if cur is None:
            self._clear(i)
            if not stack:
                return
        if self._has_atomic:
            self._requeue(i)
        else:
            self.C.running.append(i)

    def _clear(self, i: Intention) -> None:
        """Pop finished intended means, giving their result back to the caller."""
        stack = i.stack
        while stack:
            top = stack[-1]
            if top.cur is not None:
                return
            stack.pop()
            trig = top.trigger
            if trig.op == "-" and trig.kind != BELIEF and stack:
                # a failure plan finished: drop everything down to the failed goal
                goal = resolve(trig.literal, top.s)
                im = stack[-1]
                if not _awaits(im, goal):
                    im = stack.pop()
                while stack and not (
                    (im.trigger.kind != BELIEF and _unifies(im.trigger.literal, goal, im.s))
                    or _awaits(im, goal)
                ):
                    im = stack.pop()
                if stack:
                    caller = stack[-1]
                    if caller.cur is not None:
                        unify(caller.cur[0].term, goal, caller.s, [])
                        caller.cur = caller.cur[1]
                continue
            if stack:
                caller = stack[-1]
                if caller.cur is not None:
                    ret = top.ret
                    lit = trig.literal
                    if ret is None and lit.__class__ is Literal and lit.ground:
                        # the goal was sent without variables: nothing comes back
                        caller.cur = caller.cur[1]
                        continue
                    if ret is None:
                        val = resolve(lit, top.s)
                    elif ret[0] == "fixed":
                        val = ret[1]
                    else:
                        val = _propagate(resolve(lit, top.s), ret[1])
                    # through a variable too (``?C`` with C bound to a literal)
                    term = deref(caller.cur[0].term, caller.s)
                    if term.__class__ is Literal and not term.ground:
                        unify(term, val, caller.s, [])
                    caller.cur = caller.cur[1]

    def _execute(self, i: Intention) -> None:
        """Execute one formula of the top intended means of ``i`` (Jason's ExecInt)."""
        stack = i.stack
        im = stack[-1]
        cur = im.cur
        if cur is None:
            # an empty body (``<- true``): the plan is finished at once
            self._clear(i)
            if stack:
                if self._has_atomic:
                    self._requeue(i)
                else:
                    self.C.running.append(i)
            return
        step = cur[0]
        k = step.kind
        s = im.s
        try:
            if k == ACHIEVE_STEP:
                trig = step.cache
                if trig is None:
                    goal = step.state
                    if goal is None:
                        goal = step.term
                        if goal.__class__ is Literal:
                            goal = step.state = _with_source(goal)
                    if goal.__class__ is Literal and goal.ground:
                        # a goal without variables: the same trigger every time
                        trig = step.cache = P.Trigger("+", ACHIEVE, goal)
                    else:
                        memo = step.memo  # reuse what _remember() kept, if the value is the same
                        if memo:
                            x = s.get(memo[0])
                            while x.__class__ is Var:
                                x = s.get(x)
                            memo = memo[2] if x is memo[1] and x is not None else None
                        else:
                            memo = None
                        if memo is not None:
                            trig = memo
                        else:
                            lit = resolve(goal, s, {})
                            if lit.__class__ is not Literal:
                                raise ActionError(
                                    f"{term_str(lit)} is not a goal", "body_var_without_value"
                                )
                            if lit is not goal and goal.__class__ is not Literal:
                                lit = _with_source(lit)
                            trig = self._trigger(step, "+", ACHIEVE, lit)
                            _remember(step, goal, s, trig)
                if self._event_waiters or self._has_atomic:
                    self.post(Event(trig, i))
                else:
                    self.C.events.append(new_event(trig, i))
            elif k == ACTION:
                lit = step.memo  # reuse what _remember() kept, if the value is the same
                if lit:
                    x = s.get(lit[0])
                    while x.__class__ is Var:
                        x = s.get(x)
                    lit = lit[2] if x is lit[1] and x is not None else None
                else:
                    lit = None
                if lit is None:
                    lit = resolve(step.term, s)
                    _remember(step, step.term, s, lit)
                if lit.__class__ is Var:
                    raise ActionError(f"variable {lit.name} has no value", "body_var_without_value")
                if lit.__class__ is not Literal:
                    raise ActionError(f"{term_str(lit)} is not an action")
                if lit.functor[0] == ".":
                    fn = self._internal.get(lit.functor)
                    if fn is None:
                        self._unknown_internal(i, lit)
                        return
                    r = fn(self, lit.args, s, [], (i, im, step))
                    if r is False:
                        self.fail_intention(i, "ia_failed", "")
                    elif r is not SUSPEND and r is not DONE:
                        if r is True or r is None or any(True for _ in r):
                            self._advance(i)
                        else:
                            self.fail_intention(i, "ia_failed", "")
                else:
                    self._act(i, lit)
            elif k == DEL_ADD_BEL:
                self._del_add_step(i, step, s)
            elif k == INTERNAL:
                lit = step.term
                fn = self._internal.get(lit.functor)
                if fn is None:
                    self._unknown_internal(i, resolve(lit, s))
                    return
                r = fn(self, lit.args, s, [], (i, im, step))
                if r is True or r is None:
                    self._advance(i)
                elif r is False:
                    self.fail_intention(i, "ia_failed", "")
                elif r is SUSPEND or r is DONE:
                    pass
                else:
                    ok = False
                    for _ in r:
                        ok = True
                        break
                    if ok:
                        self._advance(i)
                    else:
                        self.fail_intention(i, "ia_failed", "")
            elif k == ADD_BEL or k == ADD_BEL_NF or k == ADD_BEL_END:
                self._add_belief_step(i, step, s)
            elif k == DEL_BEL or k == DEL_BEL_NF:
                self._del_belief_step(i, step, s)
            elif k == CONSTRAINT:
                if holds(self, step.term, s, []):
                    self._advance(i)
                else:
                    self.fail_intention(
                        i, "constraint_failed", f"Constraint {step!r} was not satisfied"
                    )
            elif k == TEST_STEP:
                self._test_step(i, step, s)
            elif k == ACHIEVE_NF:
                lit = resolve(step.term, s, {})
                if lit.__class__ is not Literal:
                    raise ActionError(f"{term_str(lit)} is not a goal", "body_var_without_value")
                self.post(Event(P.Trigger("+", ACHIEVE, _with_source(lit)), None))
                self._advance(i)
            elif k == IF:
                self._if_step(i, im, step)
            elif k == WHILE or k == WHILE_AGAIN:
                self._while_step(i, im, step)
            elif k == FOR or k == FOR_NEXT:
                self._for_step(i, im, step)
            elif k == FORK:
                self._fork_step(i, im, step)
            elif k == JOIN:
                self._join_step(i, step)
            else:
                raise ActionError(f"cannot execute {step!r}")
        except ActionError as exc:
            self.fail_intention(i, exc.error, str(exc), getattr(exc, "annots", ()))
        except EvalError as exc:
            self.fail_intention(i, "ia_failed", str(exc))
        except RecursionError:
            self.fail_intention(i, "ia_failed", "term nesting too deep")
        except Exception as exc:  # noqa: BLE001 - a faulty extension must not stop the agent
            self.warn(f"error executing {step!r}: {exc.__class__.__name__}: {exc}")
            self.fail_intention(i, "ia_failed", str(exc))

    # ---- body formulas
    def _unknown_internal(self, i: Intention, lit: Literal) -> None:
        """An internal action nobody defined goes to the environment, as in Jason (and
        fails there with ``action_failed`` unless the environment knows it); one of
        Jason's own that robocog lacks fails, saying so."""
        if lit.functor in NOT_SUPPORTED:
            raise ActionError(unknown_action(lit))
        self.warn(f"{unknown_action(lit)}: handed to the environment, as Jason does")
        self._act(i, lit)

    def _fork_step(self, i: Intention, im: IntendedMeans, step: P.Step) -> None:
        """Jason's ``.fork``: each branch goes on as an intention of its own, a copy of
        ``i`` whose plan runs the branch, then a join, then what followed the fork; ``i``
        itself is done. The branches share the intended means below the forking one
        (only one branch ever returns into them) and each has its own bindings."""
        fork = Fork(step.term == "and")
        rest = im.cur[1]
        below = i.stack[:-1]
        for branch in step.blocks:
            join = P.Step(JOIN, None, line=step.line, state=fork)
            b = Intention()
            top = new_im(im.plan, im.trigger, dict(im.s), P.prepend(branch, (join, rest)))
            top.ret = im.ret
            b.stack = [*below, top]
            b.fork = (fork, len(i.stack))
            fork.branches.append(b)
            fork.to_finish += 1
        i.stack = []
        for b in fork.branches:
            self._requeue(b)

    def _join_step(self, i: Intention, step: P.Step) -> None:
        """Jason's ``.join``: with ``|&|`` the last branch to arrive goes on and the
        others end here; with ``|||`` the first goes on and the others are dropped."""
        fork = step.state
        assert isinstance(fork, Fork)
        fork.to_finish -= 1
        if fork.both:
            if fork.to_finish == 0:
                self._advance(i)
            return
        for b in fork.branches:
            if b is not i:
                self._drop(b)
        fork.branches = [i]
        self._advance(i)

    def _fork_failure(self, i: Intention) -> bool:
        """What a failure in a branch does to its fork; True when the failure ends there
        (a branch of ``|||`` failing below its own goals: the others go on). A failure
        handled in the branch's own subgoals is the branch's affair."""
        fork, point = i.fork or (None, 0)
        assert fork is not None
        for im in i.stack[point:]:
            t = im.trigger
            if t.kind != BELIEF and self.pl.has_candidate(P.Trigger("-", t.kind, t.literal)):
                return False
        if fork.both:
            for b in fork.branches:
                if b is not i:
                    self._drop(b)
            fork.branches = [i]
            i.fork = None
            return False
        fork.branches = [b for b in fork.branches if b is not i]
        self.warn(f"no failure event was generated for {i.stack[-1].trigger!r} (a branch of |||)")
        self._drop(i)
        return True

    def _add_belief_step(self, i: Intention, step: P.Step, s: dict) -> None:
        lit = resolve(_sourced(step), s, {})
        if lit.__class__ is not Literal:
            raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
        lit = _with_source(lit)
        added = self.bb.add(lit, at_end=step.kind == ADD_BEL_END)
        if added is None:
            self._advance(i)
            return
        trig = self._trigger(step, "+", BELIEF, lit)
        if step.kind == ADD_BEL_NF:
            self.post(Event(trig, None))
            self._advance(i)
        else:
            self.post(Event(trig, i))

    def _del_belief_step(self, i: Intention, step: P.Step, s: dict) -> None:
        lit = resolve(_sourced(step), s)
        if lit.__class__ is not Literal:
            raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
        lit = _with_source(lit)
        gone = self._remove_matching(lit, s)
        if gone is None:
            self._advance(i)
            return
        trig = self._trigger(step, "-", BELIEF, gone)
        if step.kind == DEL_BEL_NF:
            self.post(Event(trig, None))
            self._advance(i)
        else:
            self.post(Event(trig, i))

    def _remove_matching(self, lit: Literal, s: dict) -> Literal | None:
        if lit.ground:
            return self.bb.remove(lit)
        for b in self.bb.candidates(lit.key):
            if b.__class__ is not Literal:
                continue
            mark: list = []
            if unify(lit, b, s, mark):
                exact = resolve(lit, s)
                if not exact.ground:
                    exact = Literal(b.functor, b.args, exact.annots, b.neg)
                return self.bb.remove(exact)
            for v in mark:
                del s[v]
        return None

    def _del_add_step(self, i: Intention, step: P.Step, s: dict) -> None:
        term = _sourced(step)
        lit = resolve(term, s, {})
        if lit.__class__ is not Literal:
            raise ActionError(f"{term_str(lit)} is not a belief", "body_var_without_value")
        if term is step.term:  # else the source is already there
            lit = _with_source(lit)
        gone = self.bb.remove_first((lit.functor, len(lit.args), lit.neg), lit.annots)
        if gone is not None:
            cands = self._step_cands(step, "-", BELIEF, gone)
            if cands is None or cands[2] or self._event_waiters or self._custom_event:
                trig = P.Trigger("-", BELIEF, gone)
                trig.cands = cands
                self.post(Event(trig, None))
            # else: an external -b event that no plan handles, which post() would drop
        added = self.bb.add(lit)
        if added is None:
            self._advance(i)
            return
        ev = new_event(self._trigger(step, "+", BELIEF, lit), i)
        if self._has_atomic or self._event_waiters:
            self.post(ev)
        else:
            self.C.events.append(ev)  # what post() does for it

    def _trigger(self, step: P.Step, op: str, kind: str, lit: Literal) -> P.Trigger:
        """The trigger of an event posted by ``step``, with its candidate plans (which
        depend only on the step's functor and arity, so they are looked up once)."""
        trig = P.Trigger(op, kind, lit)
        pl = self.pl
        rel = step.rel
        if rel is not None and rel[0] is pl and rel[1] == pl.version:
            got = rel[2].get(op)
            if got is not None:
                trig.cands = got
                return trig
        elif step.term.__class__ is Literal:
            rel = step.rel = (pl, pl.version, {})
        else:
            return trig
        pl.candidates(trig)
        rel[2][op] = trig.cands
        return trig

    def _step_cands(self, step: P.Step, op: str, kind: str, lit: Literal) -> tuple | None:
        """What :meth:`_trigger` would put in the trigger's ``cands``."""
        pl = self.pl
        rel = step.rel
        if rel is not None and rel[0] is pl and rel[1] == pl.version:
            got = rel[2].get(op)
            if got is not None:
                return got
        return self._trigger(step, op, kind, lit).cands

    def _test_step(self, i: Intention, step: P.Step, s: dict) -> None:
        f = step.term
        if holds(self, f, s, []):
            self._advance(i)
            return
        lit = deref(f, s)
        if lit.__class__ is Literal and not lit.functor.startswith("."):
            lit = _with_source(resolve(lit, s, {}))
            trig = P.Trigger("+", TEST, lit)
            if self.pl.has_candidate(trig):
                self.post(Event(trig, i))
                return
        self.fail_intention(i, "test_goal_failed", f"Failed to test '{term_str(resolve(f, s))}'")

    def _if_step(self, i: Intention, im: IntendedMeans, step: P.Step) -> None:
        s = im.s
        block = None
        chosen = False
        for cond, body in step.blocks:
            if holds(self, cond, s, []):
                block = body
                chosen = True
                break
        if not chosen:
            block = step.state
        rest = im.cur[1]
        im.cur = (None, P.prepend(block, rest)) if block is not None else (None, rest)
        self._advance(i)

    def _while_step(self, i: Intention, im: IntendedMeans, step: P.Step) -> None:
        s = im.s
        if step.kind == WHILE:
            backup = dict(s)
            loop = P.Step(WHILE_AGAIN, step.term, step.blocks, step.line, backup)
        else:
            backup = step.state
            s.clear()
            s.update(backup)
            loop = step
        rest = im.cur[1]
        if holds(self, step.term, s, []):
            im.cur = (None, P.prepend(step.blocks[0], (loop, rest)))
        else:
            im.cur = (None, rest)
        self._advance(i)

    def _for_step(self, i: Intention, im: IntendedMeans, step: P.Step) -> None:
        s = im.s
        if step.kind == FOR:
            backup = dict(s)
            sols: list[dict] = []
            work = dict(s)
            for _ in solve(self, step.term, work, []):
                sols.append(dict(work))
            state = (iter(sols), backup)
            loop = P.Step(FOR_NEXT, step.term, step.blocks, step.line, state)
        else:
            state = step.state
            loop = step
        it, backup = state
        rest = im.cur[1]
        nxt = next(it, None)
        s.clear()
        if nxt is not None:
            s.update(nxt)
            im.cur = (None, P.prepend(step.blocks[0], (loop, rest)))
        else:
            s.update(backup)
            im.cur = (None, rest)
        self._advance(i)

    # ------------------------------------------------------------------ goals
    def intentions(self) -> list[Intention]:
        """All live intentions."""
        return self.C.intentions()

    def drop_goal(self, goal: Literal, how: str, current: Intention | None = None) -> bool:
        """Jason's ``.succeed_goal``/``.fail_goal``/``.drop_intention`` on every intention
        that has ``goal`` in its stack; returns True if ``current`` was changed."""
        touched_current = False
        for i in self.C.intentions() + ([current] if current is not None else []):
            if i.dropped or not i.stack:
                continue
            for pos in range(len(i.stack) - 1, -1, -1):
                im = i.stack[pos]
                t = im.trigger
                if t.kind == ACHIEVE and t.op == "+" and _unifies(goal, t.literal, {}):
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
            # succeed: remove the goal's plan and continue its caller
            del i.stack[pos:]
            self._unschedule(i)
            if not i.stack:
                i.dropped = True
                continue
            caller = i.stack[-1]
            if caller.cur is not None:
                caller.cur = caller.cur[1]
            if caller.cur is None:
                self._clear(i)
            if i.stack:
                self._requeue(i)
        # events for the goal (not yet intentions) go too
        if how != "fail":
            self.C.keep_events(
                lambda e: (
                    not (
                        e.intention is None
                        and e.trigger.kind == ACHIEVE
                        and _unifies(goal, e.trigger.literal, {})
                    )
                )
            )
        return touched_current

    def intentions_for(self, goal: Literal, extra: Intention | None = None) -> list[Intention]:
        """The live intentions with ``+!goal`` in their stack (and ``extra`` if it has)."""
        found = []
        for i in self.C.intentions() + ([extra] if extra is not None else []):
            if i.dropped or not i.stack:
                continue
            for im in i.stack:
                t = im.trigger
                if t.kind == ACHIEVE and t.op == "+" and _unifies(goal, t.literal, {}):
                    found.append(i)
                    break
        return found

    def suspend(self, i: Intention, current: bool) -> None:
        """Set ``i`` aside until :meth:`resume` (Jason's ``.suspend``). The current
        intention stops at the ``.suspend`` it runs and goes on after it when resumed;
        another one is taken off the running queue as it stands."""
        if not current:
            self._unschedule(i)
        self.C.pending[i.id] = (i, "suspend_ia" if current else "suspended")

    def suspension(self, i: Intention) -> str | None:
        """Why ``i`` is suspended, as ``.suspended`` reports it, or None."""
        entry = self.C.pending.get(i.id)
        if entry is None or entry[1] not in ("suspend_ia", "suspended"):
            return None
        return "suspend_ia"

    def resume(self, i: Intention) -> bool:
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

    def _unschedule(self, i: Intention) -> None:
        C = self.C
        C.pending.pop(i.id, None)
        if C.atomic_intention is i:
            C.atomic_intention = None
        if C.atomic_event is not None and C.atomic_event.intention is i:
            C.atomic_event = None
        if i in C.running:
            C.running.remove(i)
        C.keep_events(lambda e: e.intention is not i)


def _sourced(step: P.Step) -> Term:
    """The belief term of a ``+b``/``-b``/``-+b`` step with ``source(self)`` added when it
    has no source (computed once: resolving keeps ground annotations as they are)."""
    got = step.cache
    if got is None:
        term = step.term
        got = term
        if term.__class__ is Literal:
            for a in term.annots:
                if not is_ground(a):
                    break
            else:
                got = _with_source(term)
        step.cache = got
    return got


def _remember(step: P.Step, term: Term, s: dict, built: Any) -> None:
    """Keep ``built`` in ``step.memo`` when ``term`` (a literal without arithmetic) has a
    single variable whose value is ground: while that variable has the very same value,
    resolving ``term`` would build the same thing, so ``_execute`` reuses it."""
    memo = step.memo
    if memo is False:
        return
    if memo is None:
        vs = variables(term) if term.__class__ is Literal and not _has_arith(term) else ()
        if len(vs) != 1:
            step.memo = False
            return
        var = vs[0]
    else:
        var = memo[0]
    x = s.get(var)
    while x.__class__ is Var:
        x = s.get(x)
    if x is not None and is_ground(x):
        step.memo = (var, x, built)


def _has_arith(t: Term) -> bool:
    c = t.__class__
    if c is Arith:
        return True
    if c is Literal:
        return any(_has_arith(a) for a in t.args) or any(_has_arith(a) for a in t.annots)
    if c is Cons:
        return _has_arith(t.head) or _has_arith(t.tail)
    return False


def _is_atomic(i: Intention) -> bool:
    for im in i.stack:
        label = im.plan.label
        if label is not None and label.annots:
            for a in label.annots:
                if a.__class__ is Literal and a.functor == "atomic":
                    return True
    return False


def _awaits(im: IntendedMeans, goal: Term) -> bool:
    """True when ``im`` stands at ``!goal`` (a step an internal action stepped over,
    such as ``.fail_goal``, is None and awaits nothing)."""
    cur = im.cur
    if cur is None or cur[0] is None:
        return False
    return cur[0].kind == ACHIEVE_STEP and _unifies(cur[0].term, goal, im.s)


def _unifies(a: Term, b: Term, s: dict) -> bool:
    """Test unification without keeping any binding."""
    trail: list = []
    ok = unify(a, b, s, trail)
    for v in trail:
        del s[v]
    return ok


def _propagate(val: Term, chain: tuple | None) -> Term:
    """Give ``val`` back through the frames tail recursion removed (innermost first)."""
    while chain is not None:
        (step_term, s2, trig_lit), chain = chain
        unify(step_term, val, s2, [])
        val = resolve(trig_lit, s2)
    return val


#: why an environment action fails in an agent that has no environment at all
NO_ENVIRONMENT = "no environment configured!"


def _default_printer(name: str, text: str) -> None:
    sys.stdout.write(f"[{name}] {text}\n")


def _default_warner(name: str, text: str) -> None:
    sys.stderr.write(f"[{name}] {text}\n")


__all__ = ["Agent", "ActionHandle", "ParseError", "SUSPEND", "DONE"]
