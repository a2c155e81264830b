"""The reasoner: input, the inference cycle, question answering and persistence.

``NAR`` is the public face of the package. It keeps ONA's order of work per cycle
(select the strongest belief event, infer with the concepts sharing a name with it,
forget a little) and ONA's output lines, so a transcript can be compared with ONA's.
"""

from __future__ import annotations

import heapq
import itertools
import math
import os
from collections.abc import Callable
from pathlib import Path

from . import commands, memfile
from . import truth as tf
from .config import MAX_TIME, Config
from .decision import DecisionMixin
from .declarative import DeclarativeMixin
from .event import BELIEF, ETERNAL, GOAL, Event, Implication, revised_or_chosen
from .inference import Derivation, apply_double, apply_single, special
from .memory import Concept, Memory
from .narsese import MAX_LINE, NarseseError, Sentence, parse_sentence
from .rules import RuleTable, rejected
from .sensorimotor import SensorimotorMixin
from .stamp import fmt, has_duplicate, merge, overlap
from .terms import F_COMPOSED, TEMPORAL_IMPLICATION, Term, atom
from .truth import Truth, expectation
from .unify import unify

PENDING_QUESTIONS = 32
#: the most cycles one input line may ask for (a bare number): ONA's examples ask for
#: a thousand at most; a hundred million is hours of work, so more is a typo
MAX_CYCLES_PER_LINE = 100_000_000
DEFAULT_OPERATIONS = (
    "^left",
    "^right",
    "^up",
    "^down",
    "^say",
    "^pick",
    "^drop",
    "^go",
    "^activate",
    "^deactivate",
)

_RULE_TABLES: dict[int, RuleTable] = {}


def _rule_table(level: int) -> RuleTable:
    t = _RULE_TABLES.get(level)
    if t is None:
        t = _RULE_TABLES[level] = RuleTable(level)
    return t


class NAR(SensorimotorMixin, DecisionMixin, DeclarativeMixin):
    """A Non-Axiomatic Reasoner with ONA's behaviour and a bounded memory."""

    def __init__(self, seed: int = 666, ona: str = "0.9.2", **config_overrides: object) -> None:
        # ``ona``: whose behaviour to follow, ONA 0.9.2's (the papers') or 0.9.3's
        self.config = Config.for_ona(ona, **config_overrides)
        self.seed = seed
        self._rand_state = seed
        self._answer_cbs: list[Callable[[Event], None]] = []
        self._derivation_cbs: list[Callable[[Event], None]] = []
        self._execution_cbs: list[Callable[[str, Term | None], None]] = []
        self.output: Callable[[str], None] | None = None
        self.operations: dict[str, Callable[[Term | None], object] | None] = {}
        #: where ``*save``/``*load`` lines may write and read (None: they are refused)
        self.memory_dir: Path | None = None
        self.reset()

    # ------------------------------------------------------------------ state
    def reset(self) -> None:
        """Forget everything (ONA's ``*reset``); the random generator is not reseeded."""
        c = self.config
        self.memory = Memory(
            c.concepts_max, c.operations_max, c.table_size, c.cycling_belief_events_max
        )
        self.time = 1
        self.stamp_base = 1
        self.concept_threshold = 0.0
        self.matched_total = 0
        self.op_names: list[str] = list(DEFAULT_OPERATIONS)
        for name, fn in list(self.operations.items()):
            del self.operations[name]
            self.register_operation(name, fn)  # type: ignore[arg-type]
        self.process_id = 0
        self.stats = {"inputs": 0, "derived": 0, "selected": 0, "answers": 0}
        self.pending_questions: dict[Term, None] = {}
        self._init_sensorimotor()
        self._init_goals()
        self.memory.on_remove = self._forget_concept

    def random_state(self) -> int:
        """The random generator's state, as a saved memory keeps it."""
        return self._rand_state

    def set_random_state(self, state: int) -> None:
        """Continue the random sequence from ``state`` (a value of :meth:`random_state`)."""
        if not -(1 << 63) <= state < 1 << 64:
            raise ValueError(f"a random state is in [-2**63, 2**64), not {state}")
        self._rand_state = state

    def rand(self) -> int:
        """ONA's ``myrand``: the POSIX example LCG, 0..32767."""
        self._rand_state = (self._rand_state * 1103515245 + 12345) & 0xFFFFFFFFFFFFFFFF
        return (self._rand_state // 65536) % 32768

    # --------------------------------------------------------------- callbacks
    def on_answer(self, cb: Callable[[Event], None]) -> None:
        """Call ``cb(event)`` with every answer found."""
        self._answer_cbs.append(cb)

    def on_derivation(self, cb: Callable[[Event], None]) -> None:
        """Call ``cb(event)`` with every derived event that enters the event queue."""
        self._derivation_cbs.append(cb)

    def on_execution(self, cb: Callable[[str, Term | None], None]) -> None:
        """Call ``cb(op_name, argument)`` whenever an operation is executed."""
        self._execution_cbs.append(cb)

    def register_operation(self, name: str, fn: Callable[[Term | None], object]) -> None:
        """Make ``name`` (e.g. ``^pick``) executable, calling ``fn(argument)`` when it is."""
        if not name.startswith("^"):
            raise ValueError(f"operation names start with '^': {name!r}")
        if name not in self.op_names:
            # take the first of ONA's default (no-op) slots nobody registered yet
            free = [
                i
                for i, n in enumerate(self.op_names)
                if n in DEFAULT_OPERATIONS and n not in self.operations
            ]
            if free:
                self.op_names[free[0]] = name
            elif len(self.op_names) < self.config.operations_max:
                self.op_names.append(name)
            else:
                raise ValueError(f"no free operation slot for {name}")
        self.operations[name] = fn

    def _print(self, line: str) -> None:
        if self.output is not None:
            self.output(line)

    def emit(self, line: str) -> None:
        """Write one output line (to ``output``, if set), as the reasoner's own are."""
        self._print(line)

    def name_operation(self, k: int, name: str) -> None:
        """ONA's ``*setopname k name``: operation ``k`` (1-based) is called ``name``."""
        if not 1 <= k <= self.config.operations_max:
            raise ValueError(
                f"operation number {k} is out of range [1, {self.config.operations_max}]"
            )
        if not name.startswith("^"):
            raise ValueError("operation names start with '^'")
        names = list(self.op_names)
        while len(names) < k:
            names.append(f"^op{len(names) + 1}")
        names[k - 1] = name
        self.op_names = [n for i, n in enumerate(names) if i < k or n != name]

    def _shows(self, priority: float) -> bool:
        return self.config.print_derivations and priority > self.config.volume_threshold

    # ------------------------------------------------------------------ input
    def add_input(self, text: str) -> None:
        """One Narsese line or shell command; bad input raises :class:`NarseseError`
        and leaves the reasoner as it was."""
        line = text.strip()
        if not line:
            self.cycles(1)
            return
        if line.startswith("//"):
            self._print("Comment: " + line[2:])
            return
        if len(line) > MAX_LINE:
            raise NarseseError(1, MAX_LINE + 1, f"line longer than {MAX_LINE} characters")
        if line.isdigit():
            if not (line.isascii() and len(line) <= 12):
                raise NarseseError(1, 1, "a number of cycles is written in digits 0-9")
            n = int(line)
            if n > MAX_CYCLES_PER_LINE:
                raise NarseseError(1, 1, f"at most {MAX_CYCLES_PER_LINE} cycles per line")
            self._print(f"performing {n} inference steps:")
            self.cycles(n)
            self._print(f"done with {n} additional inference steps.")
            return
        if line.startswith("*"):
            self._command(line)
            return
        s = parse_sentence(line)
        if self.time >= MAX_TIME:
            raise NarseseError(1, 1, f"the reasoner's time has reached {MAX_TIME}; *reset")
        self.add_sentence(s)

    def add_sentence(self, s: Sentence) -> None:
        """Enter a parsed sentence: beliefs and goals run one cycle, questions are answered."""
        if s.punctuation == "?":
            self.answer(s.term, s.tense)
            return
        if s.tense is None and s.punctuation == GOAL:
            raise NarseseError(1, 1, "eternal goals are not supported; add ':|:'")
        if s.tense not in (None, ":|:"):
            raise NarseseError(1, 1, "only present-tense events (':|:') can be input")
        t = s.truth or tf.DEFAULT
        occ = ETERNAL if s.tense is None else self.time
        e = Event(
            s.term,
            s.punctuation,
            t,
            (self.stamp_base,),
            occ,
            self.time,
            s.dt or 0.0,
            is_input=True,
        )
        self.stamp_base += 1
        self.stats["inputs"] += 1
        self._add_event(e, 1.0, is_input=True)
        self.cycles(1)

    # ---------------------------------------------------------------- commands
    def _command(self, line: str) -> None:
        """A ``*`` line: see :mod:`robocog.nars.commands` for the table of commands."""
        commands.execute(self, line)

    def concept_line(self, con: Concept) -> str:
        """ONA's ``*concepts`` line for ``con``."""
        b = con.belief
        tv = f" {b.truth}" if b is not None else ""
        return (
            f'//{con.term}: {{ "priority": {self._priority(con):f}, '
            f'"usefulness": {con.usefulness(self.time):f}, "useCount": {con.use_count}, '
            f'"lastUsed": {con.last_used}}}{tv}'
        )

    def statistics(self) -> list[str]:
        """ONA-style statistics lines."""
        return [
            "Statistics",
            "----------",
            f"currentTime:\t\t\t{self.time}",
            f"total concepts:\t\t\t{len(self.memory)}",
            f"concept capacity:\t\t{self.memory.capacity}",
            f"evicted concepts:\t\t{self.memory.evictions}",
            f"current average concept priority:\t{self._avg_priority():f}",
            f"current belief events cnt:\t\t{len(self.memory.belief_events)}",
            f"total input events:\t\t{self.stats['inputs']}",
            f"total derived events:\t\t{self.stats['derived']}",
            f"total selected events:\t\t{self.stats['selected']}",
            f"total answers:\t\t\t{self.stats['answers']}",
            f"distinct names:\t\t\t{len(self.memory.atom_index)}",
        ]

    def _avg_priority(self) -> float:
        n = len(self.memory)
        return sum(self._priority(c) for c in self.memory) / n if n else 0.0

    # ------------------------------------------------------------- priorities
    def _priority(self, c: Concept) -> float:
        """Concept priority with the per-cycle decay applied lazily."""
        return c.priority_at(self.time, self.config.concept_durability)

    def _raise_priority(self, c: Concept, p: float) -> None:
        """Lift the (decayed) priority of ``c`` to at least ``p``, as of now."""
        cp = self._priority(c)
        c.priority = p if p > cp else cp  # ``max(cp, p)`` without the call
        c.priority_time = self.time

    # ----------------------------------------------------------------- events
    def _add_event(
        self, e: Event, priority: float, is_input: bool = False, revised: bool = False
    ) -> None:
        """ONA's Memory_AddEvent for input and revised events: queue the event and store
        it in its concept. (Derived beliefs take :meth:`_derived`, which makes the
        decisions that only concern them.)"""
        if e.truth.c < self.config.min_confidence or priority <= 0.0:
            return
        if e.type == GOAL:
            if is_input:
                self._print("Input: " + e.line(priority))
            self._add_goal(e, priority, 0)
            return
        self._store(e, priority, is_input, revised, True)

    def _store(self, e: Event, priority: float, is_input: bool, revised: bool, index: bool) -> None:
        """Queue a belief event that passed the filters and store it in its concept."""
        added = False
        op = e.term.op
        if op != TEMPORAL_IMPLICATION and (is_input or (op != "==>" and op != "<=>")):
            added = self._queue(e, priority)  # only input implications become events
        if added and not is_input:
            self.stats["derived"] += 1
            if self._shows(priority):
                self._print(("Revised: " if revised else "Derived: ") + e.line(priority))
            for cb in self._derivation_cbs:
                cb(e)
        self._process_new_belief(e, priority, is_input, index)

    def _queue(self, e: Event, priority: float) -> bool:
        q = self.memory.belief_events
        if e.type == BELIEF:
            prio = q.prio
            if len(prio) >= q.capacity and priority < q.lowest():
                return False  # the full queue would refuse it whatever the checks below say
            if q.contains(e):
                return False
            c = self.memory.find(e.term)
            if c is not None and c.belief is not None:
                if c.belief.same(e):
                    return False
                if e.occurrence_time == ETERNAL and c.belief.truth.c > e.truth.c:
                    return False
            return q.push(e, priority)
        return False

    def _process_new_belief(
        self, e: Event, priority: float, is_input: bool, index: bool = True
    ) -> None:
        now = self.time
        eternal_input = is_input and e.occurrence_time == ETERNAL
        if e.term.op == TEMPORAL_IMPLICATION:
            if is_input:
                self._print("Input: " + e.line(priority))
            self._add_implication(e.term, e.truth, e.stamp, e.dt, is_input, priority)
            return
        c: Concept = self.memory.conceptualize(e.term, now)
        c.use(now, eternal_input, self.config.eternal_input_usage_boost)
        self._raise_priority(c, priority)
        if e.occurrence_time != ETERNAL:
            if index:
                # derived compositions stay out of the occurrence-time index: they
                # serve semantic inference and answers, while temporal induction and
                # anticipation see what they saw when compositions needed a concept
                self._note_event(c)
            stamp_size = self.config.stamp_size
            if e.occurrence_time <= now:
                c.belief_spike = revised_or_chosen(c.belief_spike, e, stamp_size)[0]
            else:
                c.predicted_belief = revised_or_chosen(c.predicted_belief, e, stamp_size)[0]
            if not self.config.eternalize_events:
                if is_input:
                    self._print("Input: " + e.line(priority))
                return
            # ONA 0.9.2 also keeps the event's evidence as a (weaker) eternal belief
            eternal = Event(e.term, BELIEF, tf.eternalize(e.truth), e.stamp, ETERNAL, now, e.dt)
            belief, revised = revised_or_chosen(c.belief, eternal, stamp_size)
            belief.creation_time = now
            c.belief = belief
            if is_input:
                self._print("Input: " + e.line(priority))
            if revised:
                self._add_event(belief, priority, revised=True)
            return
        if c.belief is None:
            # a first belief needs no copy: of an eternal event only ``creation_time``
            # ever changes, and it is ``now`` already
            belief, revised = e, False
        else:
            belief, revised = revised_or_chosen(c.belief, e, self.config.stamp_size)
        belief.creation_time = now
        c.belief = belief
        if self.config.declarative_implications_cycle_process:
            self.note_fresh_belief(c)  # ONA 0.9.3: it may meet ``==>`` beliefs
        if e.term.op in ("==>", "<=>"):
            self._note_link(e.term)
        if self.pending_questions:
            self._check_pending(c)
        if is_input:
            self._print("Input: " + e.line(priority))
        if revised:
            if self._shows(priority):
                self._print("Revised: " + belief.line(priority))
            self._add_event(belief, priority, revised=True)

    def _derived(
        self, term: Term, t: Truth, stamp: tuple[int, ...], occurrence: int, priority: float
    ) -> None:
        """A derived belief: ONA's Memory_AddEvent for derived events (compositions only
        where their concept exists, priority scaled by complexity) after the conclusion
        filters, each check made once and the cheap ones first, then :meth:`_store`."""
        cfg = self.config
        composition = (len(stamp) > 1 or occurrence != ETERNAL) and _needs_existing_concept(
            term, occurrence
        )
        if (
            composition
            and (cfg.compositions_need_concept or term.has_var)
            and term not in self.memory.concepts
        ):
            return  # compositions are only kept where their concept already exists
        if rejected(term):
            return
        op = term.op
        if (op == "==>" or op == "<=>") and not term.has_indep_var:
            # ONA refuses this only for conclusions with variables introduced: a ground
            # ``==>`` (from a conditional deduction) it keeps, which its 0.9.3 pass uses
            if term.has_var or not cfg.declarative_implications_cycle_process:
                return
        if cfg.restricted_concept_creation and term not in self.memory.concepts:
            return  # ONA 0.9.3's *restrictedconceptcreation
        priority *= 1.0 / math.log2(1.0 + term.complexity)
        if t.c < cfg.min_confidence or priority <= 0.0:
            return
        e = Event(term, BELIEF, t, stamp, occurrence, self.time)
        self._store(e, priority, False, False, not composition or cfg.compositions_need_concept)

    # ------------------------------------------------------------------ cycle
    def cycles(self, n: int) -> None:
        """Run ``n`` inference cycles."""
        # capacities follow the configuration, so ``nar.config.concepts_max = N`` works
        self.memory.capacity = self.config.concepts_max
        self.memory.belief_events.capacity = self.config.cycling_belief_events_max
        for _ in range(n):
            self._cycle()

    def _cycle(self) -> None:
        popped = self.memory.belief_events.pop()
        if popped is not None:
            priority, e = popped
            self.stats["selected"] += 1
            if self._shows(priority):
                self._print("Selected: " + e.line(priority))
            if e.occurrence_time != ETERNAL:
                sc = self.memory.find(e.term)
                if sc is not None:
                    sc.selected_time = self.time
                self._process_belief_event(e, priority)
        self._forward_links()
        if self.config.declarative_implications_cycle_process:
            self._forward_eternal()  # ONA 0.9.3
        self._process_goals()
        if popped is not None:
            self._semantic_inference(popped[1], popped[0])
        self.memory.belief_events.decay(self.config.event_durability)
        for q in self.goal_layers:
            q.decay(self.config.event_durability)
        self.time += 1

    def _semantic_inference(self, e: Event, priority: float) -> None:
        cfg = self.config
        table = _rule_table(cfg.semantic_inference_nal_level)
        now = self.time
        # a stamp counting one input twice refuses every conclusion drawn with it, so
        # such a premise (pair) is skipped whole rather than conclusion by conclusion
        if not has_duplicate(e.stamp):
            single = Derivation(self, e.occurrence_time, e.stamp, priority, 1.0)
            apply_single(table, e.term, e.truth, single)
        self.process_id += 1
        avg = self.matched_total / now
        self.concept_threshold = min(
            1.0,
            max(
                0.0,
                self.concept_threshold
                + (avg - cfg.belief_concept_match_target) * cfg.concept_threshold_adaptation,
            ),
        )
        threshold = self.concept_threshold
        chosen: list[tuple[Concept, float]] = []
        limit = cfg.belief_concept_match_target
        durability = cfg.concept_durability
        c: Concept
        for c in self.memory.related(e.term):
            cp = c.priority_at(now, durability)
            if cp < threshold:
                continue
            chosen.append((c, cp))
            if len(chosen) >= limit:
                break
        self.matched_total += len(chosen)
        spikes_alone = cfg.event_pairs_with_events
        for c, cp in chosen:
            belief = c.belief
            if (
                e.occurrence_time != ETERNAL
                and c.belief_spike is not None
                and abs(e.occurrence_time - c.belief_spike.occurrence_time)
                < cfg.event_belief_distance
                and (belief is not None or spikes_alone)
            ):
                belief = c.belief_spike.projected(e.occurrence_time)
            elif belief is None:
                continue
            if overlap(e.stamp, belief.stamp):
                continue
            c.use(now, False, 0)
            stamp = merge(e.stamp, belief.stamp, cfg.stamp_size)
            if has_duplicate(stamp):
                continue
            d = Derivation(self, e.occurrence_time, stamp, priority, cp)
            apply_double(table, e.term, c.term, e.truth, belief.truth, d)
            special(e.term, c.term, e.truth, belief.truth, d)
            special(c.term, e.term, belief.truth, e.truth, d)

    # -------------------------------------------------------------- questions
    def answer(self, question: Term, tense: str | None = None) -> Event | None:
        """Answer a question at once with the best belief, printing ONA's lines."""
        self._print(f"Input: {question}?" + (f" {tense}" if tense else ""))
        best: Event | None = None
        best_c: Concept | None = None
        best_e = -1.0
        if question.op == TEMPORAL_IMPLICATION:
            return self._answer_implication(question)
        for c in self._candidates(question):
            if unify(question, c.term, query_only=True) is None and c.term is not question:
                continue
            cands: list[Event] = []
            if tense is None:
                if c.belief is not None:
                    cands.append(c.belief)
            else:
                if tense in (":|:", ":\\:") and c.belief_spike is not None:
                    cands.append(c.belief_spike)
                if tense in (":|:", ":/:") and c.predicted_belief is not None:
                    cands.append(c.predicted_belief)
            for b in cands:
                ex = expectation(b.projected(self.time).truth)
                if ex >= best_e:
                    best, best_c, best_e = b, c, ex
        if best is None:
            self._print("Answer: None.")
            if tense is None:
                self._pend(question)
            return None
        if best_c is not None:
            self._raise_priority(best_c, self.config.question_priming)
            best_c.use(self.time, False, 0)
        self._report_answer(best)
        return best

    def _answer_implication(self, question: Term) -> Event | None:
        """``<a =/> b>?``: the best matching link in the precondition tables."""
        best: Implication | None = None
        best_e = -1.0
        for table in self.table_index.values():
            for post in table:
                if unify(question.args[1], post.term, query_only=True) is None:
                    continue
                for links in post.precondition_beliefs or ():
                    for imp in links.items:
                        if imp.term is question or (
                            question.has_query_var
                            and unify(question, imp.term, query_only=True) is not None
                        ):
                            ex = expectation(imp.truth)
                            if ex >= best_e:
                                best, best_e = imp, ex
        if best is None:
            self._print("Answer: None.")
            return None
        e = Event(best.term, BELIEF, best.truth, best.stamp, ETERNAL, best.creation_time, best.dt)
        self._report_answer(e)
        return e

    def _report_answer(self, best: Event) -> None:
        self.stats["answers"] += 1
        if best.occurrence_time == ETERNAL:
            self._print(
                f"Answer: {best.term}. creationTime={best.creation_time} "
                f"Stamp={fmt(best.stamp)} {best.truth}"
            )
        else:
            self._print(
                f"Answer: {best.term}. :|: occurrenceTime={best.occurrence_time} "
                f"creationTime={best.creation_time} Stamp={fmt(best.stamp)} {best.truth}"
            )
        for cb in self._answer_cbs:
            cb(best)

    def _pend(self, question: Term) -> None:
        """Keep an unanswered question open and bring the beliefs about its names back
        into attention, so the next cycles can derive what it asks for.

        ONA answers only at input; here an open question is answered (one more
        ``Answer:`` line) as soon as a belief for it is derived. At most
        ``PENDING_QUESTIONS`` stay open, the oldest is dropped first.
        """
        pending = self.pending_questions
        if question in pending:
            return
        pending[question] = None
        while len(pending) > PENDING_QUESTIONS:
            del pending[next(iter(pending))]
        self._bridge(question)
        for a in dict.fromkeys(x for x in question.atoms() if not x.is_var):
            d = self.memory.atom_index.get(a)
            if not d:
                continue
            strongest = heapq.nlargest(
                2,
                (c for c in itertools.islice(d, 200) if c.belief is not None),
                key=lambda c: c.use_count,
            )
            q = self.memory.belief_events
            for c in strongest:
                if not q.contains(c.belief):  # type: ignore[arg-type]
                    q.push(c.belief.copy(), 1.0)  # type: ignore[arg-type]

    def _bridge(self, question: Term) -> None:
        """Question-guided premise choice: pair beliefs about the question's subject
        with beliefs about its predicate that share a middle term, and infer from
        each pair at once (backward chaining one link deep)."""
        if question.op is None or len(question.args) != 2 or question.has_var:
            return
        s_names = [a for a in question.args[0].atoms() if not a.is_var]
        p_names = [a for a in question.args[1].atoms() if not a.is_var]
        if not s_names or not p_names:
            return
        idx = self.memory.atom_index
        limit = 50_000
        side_p: dict[Term, list[Concept]] = {}
        for a in p_names:
            for c in itertools.islice(idx.get(a, ()), limit):
                if c.belief is not None:
                    for x in _names(c.term):
                        side_p.setdefault(x, []).append(c)
        skip = set(s_names) | set(p_names)
        table = _rule_table(self.config.semantic_inference_nal_level)
        done: set[tuple[int, int]] = set()
        for a in s_names:
            for c in list(itertools.islice(idx.get(a, ()), limit)):
                b1 = c.belief
                if b1 is None:
                    continue
                for m in _names(c.term):
                    if m in skip:
                        continue
                    for d in side_p.get(m, ()):
                        b2 = d.belief
                        key = (c.id, d.id)
                        if c is d or b2 is None or key in done or overlap(b1.stamp, b2.stamp):
                            continue
                        done.add(key)
                        stamp = merge(b1.stamp, b2.stamp, self.config.stamp_size)
                        if has_duplicate(stamp):
                            continue
                        der = Derivation(self, ETERNAL, stamp, 1.0, 1.0)
                        apply_double(table, c.term, d.term, b1.truth, b2.truth, der)

    def _on_new_belief(self, c: Concept) -> None:
        """``c`` got a new eternal belief outside the event path: open questions may
        have their answer."""
        if self.pending_questions:
            self._check_pending(c)

    def _check_pending(self, c: Concept) -> None:
        """Answer open questions that the new belief of ``c`` answers."""
        b = c.belief
        if b is None:
            return
        for q in list(self.pending_questions):
            if q is c.term or (q.has_query_var and unify(q, c.term, query_only=True) is not None):
                del self.pending_questions[q]
                self._report_answer(b)

    def _candidates(self, question: Term) -> list[Concept]:
        if not question.has_var:
            c = self.memory.find(question)
            return [c] if c is not None else []
        names = {a for a in question.atoms() if not a.is_var}
        best: dict[Concept, None] | None = None
        for a in names:
            d = self.memory.atom_index.get(a)
            if d is None:
                return []
            if best is None or len(d) < len(best):
                best = d
        if best is None:
            return list(self.memory)
        return list(best)

    def ask(self, question: str) -> Event | None:
        """Answer a question given as text, e.g. ``"<a --> ?1>?"``."""
        s = parse_sentence(question.strip())
        if s.punctuation != "?":
            raise NarseseError(1, len(question.strip()), "a question ends with '?'")
        return self.answer(s.term, s.tense)

    # ------------------------------------------------------------ persistence
    def save(self, path: str | os.PathLike[str]) -> None:
        """Write the whole memory to ``path`` as a memory file (``memfile``): atomically,
        mode 0600, never over a file that is not a robocog memory."""
        memfile.write_file(path, memfile.encode(self))

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> NAR:
        """A reasoner restored from a file written by :meth:`save`; a file that is not
        one, or that is damaged, raises :class:`memfile.MemoryFileError` (one line)."""
        snap = memfile.load_file(path)
        nar = cls(seed=snap.seed)
        nar._take(snap)
        return nar

    def restore(self, path: str | os.PathLike[str]) -> None:
        """Replace this reasoner's state by the one saved at ``path`` (``*load``); the
        output, callbacks and registered operations stay. A refused file changes
        nothing."""
        snap = memfile.load_file(path)
        self._take(snap)

    def _take(self, snap: memfile.Snapshot) -> None:
        for k, v in snap.config.items():
            setattr(self.config, k, v)
        self.seed = snap.seed
        self._rand_state = snap.rand
        self.memory = snap.memory
        self.time = snap.time
        self.stamp_base = snap.stamp_base
        self.concept_threshold = snap.concept_threshold
        self.matched_total = snap.matched_total
        self.process_id = snap.process_id
        self.op_names = snap.op_names
        self.stats = snap.stats
        self.pending_questions = snap.pending_questions
        # the sensorimotor indexes' caches start empty, as they do after a reset
        self._init_sensorimotor()
        self.time_index = snap.time_index
        self.table_index = snap.table_index
        self.links_by_subject = snap.links_by_subject
        self.general_links = snap.general_links
        self.goal_layers = snap.goal_layers
        self.recent_goal_concepts = snap.recent_goal_concepts
        self.memory.on_remove = self._forget_concept


_IMAGES = frozenset({"/1", "/2", "\\1", "\\2"})
_COMPOSED = frozenset({"-", "~", "&", "|"})


def _needs_existing_concept(t: Term, occurrence: int) -> bool:
    """ONA: images at the top, differences and intersections anywhere, and
    conjunctions with dependent variables (or in time) are derived only into
    concepts that already exist."""
    if t.op == "&&" and (t.has_dep_var or occurrence != ETERNAL):
        return True
    if (
        t.op is not None
        and len(t.args) == 2
        and (t.args[0].op in _IMAGES or t.args[1].op in _IMAGES)
    ):
        return True
    return bool(t.flags & F_COMPOSED)


def _names(t: Term) -> list[Term]:
    return [a for a in dict.fromkeys(t.atoms()) if not a.is_var]


__all__ = ["NAR", "NarseseError", "atom"]
