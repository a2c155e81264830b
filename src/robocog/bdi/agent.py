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

This module holds the agent's state, its Python API and the cycle itself (``run`` and
``step``); each step's work is in a module of its own, whose functions are bound here as
the agent's methods: :mod:`robocog.bdi.sense`, :mod:`robocog.bdi.deliberate`,
:mod:`robocog.bdi.act` and :mod:`robocog.bdi.body` (one formula of an intention), and
:mod:`robocog.bdi.failure` (goal failure, dropping and suspending).
"""

from __future__ import annotations

import functools
import heapq
import sys
import time
from collections import deque
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.bdi import act, body, context, deliberate, failure, sense
from robocog.bdi import plans as P
from robocog.bdi.actions import ActionFn, ActionHandle
from robocog.bdi.beliefs import BeliefBase
from robocog.bdi.circumstance import (
    Circumstance,
    Event,
    Intention,
)
from robocog.bdi.er import clear_satisfied, has_goal_conditions
from robocog.bdi.formulas import (
    is_atomic,
    with_source,
)
from robocog.bdi.logic import holds, solve
from robocog.bdi.messages import Message
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
    BELIEF,
)
from robocog.bdi.signals import DONE, SUSPEND
from robocog.bdi.terms import (
    Literal,
    Term,
    Var,
    is_ground,
    term_str,
)
from robocog.bdi.unifier import (
    EvalError,
    resolve,
    undo,
    variables,
)

if TYPE_CHECKING:
    from robocog.bdi.mas import MultiAgentSystem


Option = tuple  # (Plan, substitution)


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


#: Jason's idle events (see Agent._jag_events)
_JAG_SLEEPING = P.Trigger("+", P.BELIEF, Literal("jag_sleeping"))
_JAG_AWAKING = P.Trigger("+", P.BELIEF, Literal("jag_awaking"))


class Agent:
    """An AgentSpeak agent: beliefs, plans, events and intentions, and its cycle."""

    #: Jason's tail-recursion optimisation (on by default, as in Jason)
    tail_recursion = True

    #: an agent architecture (:class:`robocog.bdi.environment.AgentArch`) that sees
    #: the agent's actions and the messages it sends, or None
    arch = None

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
        self._jag_version = -1
        self._jag = False
        self._sleeping = False
        #: the timer each waiting intention waits on (by intention id), so that the
        #: timer of a wait it no longer waits on is ignored
        self._timer_of: dict[int, int] = {}
        self._event_waiters: list[tuple[P.Trigger, Intention, float | None]] = []
        self._formula_waiters: list[tuple[Term, Intention]] = []
        #: intention id -> (variable for the elapsed time, start) of a running .wait
        self.wait_elapsed: dict[int, tuple[Term, float]] = {}
        #: why each intention on a ``.wait`` waits, as ``.intention`` reports it
        self.wait_reasons: dict[int, Term] = {}
        self._percepts: dict[Literal, None] = {}
        self._perceived: dict[Literal, None] = {}
        self._percepts_dirty = False
        self._asks: dict[str, tuple[Intention, Term]] = {}
        self._custom_option = type(self).select_option is not Agent.select_option
        self._has_atomic = False
        #: whether a plan has JasonER sub-plans (their scope is then looked at)
        self.has_subplans = False
        #: whether a plan has a goal condition to check each cycle (other than false)
        self.has_goal_conds = False
        self._custom_event = type(self).select_event is not Agent.select_event
        self._custom_intention = type(self).select_intention is not Agent.select_intention
        self.file = file
        #: the program's name as Jason gives it in ``code_src`` and plan labels
        self.url = f"file:{file}" if file else ""
        #: folders searched for included files after the including file's own
        self.asl_path = tuple(asl_path)
        #: functions the program defines by a rule (``register_function``): name ->
        #: (name, arity, predicate)
        self.functions: dict[str, tuple[str, int, str]] = {}
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
        self.functions.update(prog.functions)
        for plan in prog.plans:
            self.add_plan(plan)
        # Jason inserts initial beliefs back to front, each at the front of the base
        for b in reversed(prog.beliefs):
            if isinstance(b, Rule):
                self.bb.add_rule(Rule(with_source(b.head), b.body))
            else:
                lit = resolve(b, {})
                if not is_ground(lit):
                    self.bb.add_rule(Rule(with_source(lit), Literal("true")))
                    continue
                self.bb.add(with_source(lit))
        for b in prog.beliefs:
            if not isinstance(b, Rule):
                lit = with_source(resolve(b, {}))
                if is_ground(lit):
                    self.post(Event(P.Trigger("+", BELIEF, lit), None))
        for g in prog.goals:
            lit = with_source(resolve(g, {}, {}))
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
        if plan.subplans is not None:
            self.has_subplans = True
        if plan.goal_cond is not None or plan.subplans is not None:
            self.has_goal_conds = self.has_goal_conds or has_goal_conditions(plan)
        self.pl.add(plan, at_end)

    # ------------------------------------------------------------------ Python API
    def register_action(self, name: str, fn: ActionFn, raw: bool = False) -> None:
        """Make ``name(...)`` in plan bodies call ``fn``.

        ``fn`` gets the arguments as Python values (or as terms with ``raw=True``) and
        returns True/None, False or an :class:`ActionHandle` (see ``actions``).
        """
        self._actions[name] = (fn, raw)

    def register_internal_action(self, name: str, fn: Callable) -> None:
        """Add an internal action ``.name`` (or ``lib.name``, a library's, kept as it is):
        ``fn(agent, args, s, trail, ctx)``."""
        self._internal[name if "." in name else "." + name] = fn

    def library_calls(self) -> list[tuple[str, int]]:
        """The library internal actions (``mylib.act``) the plans call, with the line of
        the first call of each, in plan order."""
        from robocog.bdi.terms import And, Not, Or

        found: dict[str, int] = {}

        def formula(t: object, line: int) -> None:
            c = t.__class__
            if c is Literal:
                f = t.functor
                if "." in f and not f.startswith(".") and f not in found:
                    found[f] = line
            elif c is And or c is Or:
                formula(t.left, line)
                formula(t.right, line)
            elif c is Not:
                formula(t.arg, line)

        def chain(ch: P.Chain, line: int) -> None:
            for st in P.chain_steps(ch):
                at = st.line or line
                if st.kind in (P.INTERNAL, P.CONSTRAINT, P.TEST_STEP):
                    formula(st.term, at)
                elif st.kind == P.IF:
                    for cond, body in st.blocks:
                        formula(cond, at)
                        chain(body, at)
                    chain(st.state, at)
                elif st.kind in (P.WHILE, P.FOR):
                    formula(st.term, at)
                    for body in st.blocks:
                        chain(body, at)
                elif st.kind == P.FORK:
                    for b in st.blocks:
                        if b is not None:
                            chain(b, at)

        for plan in self.pl:
            if plan.context is not None:
                formula(plan.context, plan.line)
            if plan.body is not None:
                chain(plan.body, plan.line)
        return list(found.items())

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

    def function_value(self, name: str, args: list) -> int | float:
        """The value of ``name(args)``, a function the program registered: the first
        answer's last argument of its predicate's query, which must be a number (Jason's
        ``RuleToFunction``); an :class:`EvalError` when there is none."""
        fn = self.functions.get(name)
        if fn is None or fn[1] != len(args):
            raise EvalError(f"unknown function {name}/{len(args)}")
        result = Var("__RuleToFunctionResult")
        s: dict = {}
        for _ in solve(self, Literal(fn[2], (*args, result)), s, []):
            value = resolve(result, s)
            if value.__class__ is int or value.__class__ is float:
                return value
            raise EvalError(f"The result of {fn[2]} (={term_str(value)}) is not numeric!")
        raise EvalError(f"No solution was found for rule {fn[2]}")

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
        lit = with_source(resolve(_as_literal(belief), {}))
        if self.bb.add(lit) is not None:
            self.post(Event(P.Trigger("+", BELIEF, lit), None))
            self._wake()

    def remove_belief(self, belief: str | Literal) -> None:
        """Remove a belief (its ``source(self)`` unless annotated) and post ``-b``."""
        lit = with_source(resolve(_as_literal(belief), {}))
        gone = self.bb.remove(lit)
        if gone is not None:
            self.post(Event(P.Trigger("-", BELIEF, gone), None))
            self._wake()

    def add_goal(self, goal: str | Literal) -> None:
        """Post ``+!goal`` as a new (external) goal."""
        lit = with_source(resolve(_as_literal(goal), {}, {}))
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
        context.enter(self)
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
        if self._has_atomic and ev.intention is not None and is_atomic(ev.intention):
            self.C.atomic_event = ev
            return
        if self._event_waiters:
            self._check_event_waiters(ev.trigger)
        elif (
            ev.intention is None
            and ev.trigger.kind == BELIEF
            and not self._custom_event
            and not self.pl.has_candidate(ev.trigger)
            and not self.has_subplans  # (a sub-plan of an intention may take it)
        ):
            return  # it would be discarded when selected, without using a cycle
        self.C.events.append(ev)

    # ---- Jason's idle events: +jag_sleeping when the agent has nothing to do, then
    # +jag_awaking when news comes (for agents with plans for them)
    def _jag_plans(self) -> bool:
        pl = self.pl
        if self._jag_version != pl.version:
            self._jag_version = pl.version
            self._jag = pl.has_candidate(_JAG_SLEEPING) or pl.has_candidate(_JAG_AWAKING)
        return self._jag

    @property
    def sleeping(self) -> bool:
        """True while the agent is idle in Jason's sense (after ``+jag_sleeping``)."""
        return self._sleeping

    def _can_sleep(self) -> bool:
        C = self.C
        return not (C.events or C.running or self._feedback or self.mailbox)

    def _jag_events(self) -> None:
        if self._can_sleep():
            if not self._sleeping:
                self._sleeping = True
                if self.pl.has_candidate(_JAG_SLEEPING):
                    self.C.events.append(Event(_JAG_SLEEPING, None))
            return
        if not self._sleeping:
            return
        awake = bool(self.mailbox)
        if not awake:
            for ev in self.C.events:
                i = ev.intention
                if ev.trigger != _JAG_SLEEPING or (
                    i is not None and any(im.trigger == _JAG_SLEEPING for im in i.stack)
                ):
                    awake = True
                    break
        if awake:
            self._sleeping = False
            if self.pl.has_candidate(_JAG_AWAKING):
                self.C.events.append(Event(_JAG_AWAKING, None))

    def is_idle(self) -> bool:
        """Nothing to do now: no event, no runnable intention, no news to take in."""
        C = self.C
        if C.events or C.running or self._feedback or self.mailbox or self._percepts_dirty:
            return False
        if not self._sleeping and self._jag_plans():
            return False  # it has +jag_sleeping to post first
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
        """When the earliest ``.wait`` or deadline is due (milliseconds), if any."""
        timers = self._timers
        while timers and sense.stale_timer(self, timers[0]):
            heapq.heappop(timers)
        return timers[0][0] if timers else None

    def run(
        self, max_cycles: int | None = None, advance_clock: bool = True, real_time: bool = False
    ) -> int:
        """Run cycles until idle; returns the cycles run.

        With ``real_time`` the clock of ``.wait`` and deadlines is the wall clock, as in
        Jason: an idle agent with a timer sleeps until it is due. Otherwise the clock is
        virtual: it stands still while the agent works and jumps to the next timer when
        it is idle (``advance_clock``), so a run is the same on any machine."""
        n = 0
        mono = time.monotonic
        t0 = mono()
        base = self.clock
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
        now_running = context.running.get
        while n < limit:
            if real_time:
                self.clock = base + (mono() - t0) * 1000.0
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
                    if now_running() is not self:  # as context.enter(self)
                        context.enter(self)
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
                if real_time and self._timers:
                    # sleep until the first timer is due (in short steps, so that
                    # news from outside is taken in on time)
                    time.sleep(min(0.05, max(0.0, (self._timers[0][0] - self.clock) / 1000.0)))
                    continue
                if advance_clock and self._timers:
                    self.clock = max(self.clock, self._timers[0][0])
                    continue
                break
            self.step()
            n += 1
        return n

    def step(self) -> None:
        """One reasoning cycle."""
        context.enter(self)
        self.cycle += 1
        C = self.C
        # ---- sense
        if self._percepts_dirty:
            self._buf()
        if self._jag_plans():
            self._jag_events()
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
        # ---- act (first, as Jason, the plans whose goal condition holds are done)
        if self.has_goal_conds:
            clear_satisfied(self)
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

    # ---- sense: percepts, messages, timers and waits (robocog.bdi.sense)
    perceive = sense.perceive
    _buf = sense.buf
    _process_message = sense.process_message
    _wake_timers = sense.wake_timers
    _resume_wait = sense.resume_wait
    add_timer = sense.add_timer
    _add_deadline = sense.add_deadline
    wait_event = sense.wait_event
    wait_formula = sense.wait_formula
    _check_formula_waiters = sense.check_formula_waiters
    _check_event_waiters = sense.check_event_waiters

    # ---- deliberate: relevant and applicable plans, intended means (robocog.bdi.deliberate)
    relevant_plans = deliberate.relevant_plans
    applicable_options = deliberate.applicable_options
    _context = deliberate.context
    _deliberate = deliberate.deliberate
    _no_option = deliberate.no_option
    _tro_ret = deliberate.tro_ret
    _no_plan = deliberate.no_plan

    # ---- act: actions and their feedback, moving intentions on (robocog.bdi.act)
    _process_feedback = act.process_feedback
    execute_action = act.execute_action
    _act = act.act
    _requeue = act.requeue
    _advance = act.advance
    _clear = act.clear

    # ---- execute one formula of an intention (robocog.bdi.body)
    _execute = body.execute
    _unknown_internal = body.unknown_internal
    _fork_step = body.fork_step
    _join_step = body.join_step
    _fork_failure = body.fork_failure
    _add_belief_step = body.add_belief_step
    _del_belief_step = body.del_belief_step
    _remove_matching = body.remove_matching
    _del_add_step = body.del_add_step
    _trigger = body.trigger
    _step_cands = body.step_cands
    _test_step = body.test_step
    _if_step = body.if_step
    _while_step = body.while_step
    _for_step = body.for_step

    # ---- failure, dropping and suspending goals (robocog.bdi.failure)
    _failure_event = failure.failure_event
    _annotate_failure = failure.annotate_failure
    fail_intention = failure.fail_intention
    _drop = failure.drop
    intentions = failure.intentions
    drop_goal = failure.drop_goal
    succeed_at = failure.succeed_at
    intentions_for = failure.intentions_for
    suspend = failure.suspend
    suspension = failure.suspension
    resume = failure.resume
    _unschedule = failure.unschedule


def _default_printer(name: str, text: str) -> None:
    sys.stdout.write(f"[{name}] {text}\n")


def _default_warner(name: str, text: str) -> None:
    sys.stderr.write(f"[{name}] {text}\n")


__all__ = ["Agent", "ActionHandle", "ParseError", "SUSPEND", "DONE"]
