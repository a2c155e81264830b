"""How an event enters memory (ONA's Memory_AddEvent and Memory_ProcessNewBeliefEvent).

Functions over a :class:`~robocog.nars.state.Reasoner`. An input or revised event is
queued among the cycling belief events (or, a goal, in the first goal layer) and stored
in its concept: a belief event as the concept's spike or prediction, an eternal belief
revised with the one there, an implication in its consequence's table. A derived belief
(:func:`add_derived`, where :class:`~robocog.nars.inference.Derivation` sends every
conclusion) first passes the filters that only concern derivations. A new belief may
answer an open question (:func:`check_pending`).
"""

from __future__ import annotations

import math

from . import truth as tf
from .decision import add_goal
from .declarative import note_fresh_belief
from .event import BELIEF, ETERNAL, GOAL, Event, event_of, revised_or_chosen
from .filters import rejected
from .memory import Concept, EventQueue
from .sensorimotor import add_implication, note_event, note_link
from .stamp import Stamp, fmt
from .state import Reasoner, emit, shows
from .terms import (
    CONJUNCTION,
    EQUIVALENCE,
    F_COMPOSED,
    F_IMAGE,
    F_IMAGE_ARGUMENT,
    IMPLICATION,
    TEMPORAL_IMPLICATION,
    Term,
)
from .truth import Cycle, Truth
from .unify import unify

#: a derived belief's priority factor for its term's complexity, ``1 / log2(1 + c)``,
#: computed once for the complexities of nearly every term (a term's is at least 1)
_SCALED = 256
_BY_COMPLEXITY = [0.0] + [1.0 / math.log2(1.0 + c) for c in range(1, _SCALED)]
_COMPOSED = frozenset({"-", "~", "&", "|"})


def concept_priority(s: Reasoner, c: Concept) -> float:
    """Concept priority with the per-cycle decay applied lazily."""
    return c.priority_at(s.time, s.config.concept_durability)


def raise_priority(s: Reasoner, c: Concept, p: float) -> None:
    """Lift the (decayed) priority of ``c`` to at least ``p``, as of now."""
    cp = concept_priority(s, c)
    c.priority = p if p > cp else cp  # ``max(cp, p)`` without the call
    c.priority_time = s.time


def add_event(
    s: Reasoner, e: Event, priority: float, is_input: bool = False, revised: bool = False
) -> None:
    """ONA's Memory_AddEvent for input and revised events: queue the event and store
    it in its concept. (Derived beliefs take :func:`add_derived`, which makes the
    decisions that only concern them.)"""
    if e.truth.c < s.config.min_confidence or priority <= 0.0:
        return
    if e.type == GOAL:
        if is_input:
            emit(s, "Input: " + e.line(priority))
        add_goal(s, e, priority, 0)
        return
    _store(s, e, priority, is_input, revised, True)


def _store(
    s: Reasoner, e: Event, priority: float, is_input: bool, revised: bool, index: bool
) -> None:
    """Queue a belief event that passed the filters and store it in its concept."""
    added = False
    op = e.term.op
    # (connectors by identity: see ``terms.CONNECTORS``)
    if op is not TEMPORAL_IMPLICATION and (
        is_input
        or (
            op is not IMPLICATION
            and op is not EQUIVALENCE
            and (op is not CONJUNCTION or s.config.derived_conjunction_events)
        )
    ):
        added = _queue(s, e, priority)  # only input implications (and conjunctions) cycle
    if added and not is_input:
        s.stats["derived"] += 1
        if shows(s, priority):
            emit(s, ("Revised: " if revised else "Derived: ") + e.line(priority))
        for cb in s.derivation_cbs:
            cb(e)
    _process_new_belief(s, e, priority, is_input, index)


def _queue(s: Reasoner, e: Event, priority: float) -> bool:
    q: EventQueue = s.memory.belief_events
    if e.type == BELIEF:
        prio = q.prio
        if len(prio) >= q.capacity and priority < q.lowest():
            return False  # the full queue would refuse it whatever the checks below say
        if q.contains(e):
            return False
        c: Concept | None = s.memory.concepts.get(e.term)  # (its find, read from the dict)
        if c is not None and c.belief is not None:
            if c.belief.same(e):
                return False
            if e.occurrence_time == ETERNAL and c.belief.truth.c > e.truth.c:
                return False
        return q.push(e, priority)
    return False


def _process_new_belief(
    s: Reasoner, e: Event, priority: float, is_input: bool, index: bool = True
) -> None:
    now = s.time
    eternal_input = is_input and e.occurrence_time == ETERNAL
    if e.term.op is TEMPORAL_IMPLICATION:
        if is_input:
            emit(s, "Input: " + e.line(priority))
        add_implication(s, e.term, e.truth, e.stamp, e.dt, is_input, priority)
        return
    # most conclusions are about a concept that exists: found without the method call
    concepts: dict = s.memory.concepts
    c: Concept | None = concepts.get(e.term)
    if c is None:
        c = s.memory.conceptualize(e.term, now)
    c.use(now, eternal_input, s.config.eternal_input_usage_boost)
    raise_priority(s, c, priority)
    if e.occurrence_time != ETERNAL:
        if index:
            # derived compositions stay out of the occurrence-time index: they
            # serve semantic inference and answers, while temporal induction and
            # anticipation see what they saw when compositions needed a concept
            note_event(s, c)
        stamp_size = s.config.stamp_size
        if e.occurrence_time <= now:
            c.belief_spike = revised_or_chosen(c.belief_spike, e, stamp_size)[0]
        else:
            c.predicted_belief = revised_or_chosen(c.predicted_belief, e, stamp_size)[0]
        if not s.config.eternalize_events:
            if is_input:
                emit(s, "Input: " + e.line(priority))
            return
        # ONA 0.9.2 also keeps the event's evidence as a (weaker) eternal belief
        eternal = Event(e.term, BELIEF, tf.eternalize(e.truth), e.stamp, ETERNAL, now, e.dt)
        belief, revised = revised_or_chosen(c.belief, eternal, stamp_size)
        belief.creation_time = now
        c.belief = belief
        if is_input:
            emit(s, "Input: " + e.line(priority))
        if revised:
            add_event(s, belief, priority, revised=True)
        return
    if c.belief is None:
        # a first belief needs no copy: of an eternal event only ``creation_time``
        # ever changes, and it is ``now`` already
        belief, revised = e, False
    else:
        belief, revised = revised_or_chosen(c.belief, e, s.config.stamp_size)
    belief.creation_time = now
    c.belief = belief
    if s.config.declarative_implications_cycle_process:
        note_fresh_belief(s, c)  # ONA 0.9.3: it may meet ``==>`` beliefs
    op = e.term.op
    if op is IMPLICATION or op is EQUIVALENCE:
        note_link(s, e.term)
    if s.pending_questions:
        check_pending(s, c)
    if is_input:
        emit(s, "Input: " + e.line(priority))
    if revised:
        if shows(s, priority):
            emit(s, "Revised: " + belief.line(priority))
        add_event(s, belief, priority, revised=True)


def add_derived(
    s: Reasoner, term: Term, t: Truth, stamp: Stamp, occurrence: Cycle, priority: float
) -> None:
    """A derived belief: ONA's Memory_AddEvent for derived events (compositions only
    where their concept exists, priority scaled by complexity) after the conclusion
    filters, each check made once and the cheap ones first, then :func:`_store`."""
    cfg = s.config
    composition = (len(stamp) > 1 or occurrence != ETERNAL) and _needs_existing_concept(
        term, occurrence
    )
    if (
        composition
        and (cfg.compositions_need_concept or term.has_var)
        and term not in s.memory.concepts
    ):
        return  # compositions are only kept where their concept already exists
    op = term.op
    if (
        cfg.image_compounds_need_concept
        and (op is CONJUNCTION or op is IMPLICATION)
        and term.flags & F_IMAGE
        and term not in s.memory.concepts
    ):
        return  # ONA 0.9.3: a conjunction or ``==>`` with an image in it
    if rejected(term):
        return
    if (op is IMPLICATION or op is EQUIVALENCE) and not term.has_indep_var:
        # ONA refuses this only for conclusions with variables introduced: a ground
        # ``==>`` (from a conditional deduction) it keeps, which its 0.9.3 pass uses
        if term.has_var or not cfg.declarative_implications_cycle_process:
            return
    if cfg.restricted_concept_creation and term not in s.memory.concepts:
        return  # ONA 0.9.3's *restrictedconceptcreation
    cx = term.complexity
    priority *= _BY_COMPLEXITY[cx] if 0 < cx < _SCALED else 1.0 / math.log2(1.0 + cx)
    if t.c < cfg.min_confidence or priority <= 0.0:
        return
    # (``event_of``: the fields ``Event(...)`` sets, without the keyword-capable call)
    e = event_of(term, BELIEF, t, stamp, occurrence, s.time)
    _store(s, e, priority, False, False, not composition or cfg.compositions_need_concept)


def report_answer(s: Reasoner, best: Event) -> None:
    s.stats["answers"] += 1
    if best.occurrence_time == ETERNAL:
        emit(
            s,
            f"Answer: {best.term}. creationTime={best.creation_time} "
            f"Stamp={fmt(best.stamp)} {best.truth}",
        )
    else:
        emit(
            s,
            f"Answer: {best.term}. :|: occurrenceTime={best.occurrence_time} "
            f"creationTime={best.creation_time} Stamp={fmt(best.stamp)} {best.truth}",
        )
    for cb in s.answer_cbs:
        cb(best)


def on_new_belief(s: Reasoner, c: Concept) -> None:
    """``c`` got a new eternal belief outside the event path: open questions may
    have their answer."""
    if s.pending_questions:
        check_pending(s, c)


def check_pending(s: Reasoner, c: Concept) -> None:
    """Answer open questions that the new belief of ``c`` answers."""
    b = c.belief
    if b is None:
        return
    for q in list(s.pending_questions):
        if q is c.term or (q.has_query_var and unify(q, c.term, query_only=True) is not None):
            del s.pending_questions[q]
            report_answer(s, b)


def _needs_existing_concept(t: Term, occurrence: Cycle) -> bool:
    """ONA: images at the top, differences and intersections anywhere, and
    conjunctions with dependent variables (or in time) are derived only into
    concepts that already exist."""
    if t.flags & (F_COMPOSED | F_IMAGE_ARGUMENT):  # kept on the term
        return True
    return t.op is CONJUNCTION and (t.has_dep_var or occurrence != ETERNAL)
