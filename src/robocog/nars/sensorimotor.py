"""Events in time: temporal and procedural induction, implication tables, anticipation.

Functions over a :class:`~robocog.nars.state.Reasoner` (ONA's Cycle.c and Memory.c
parts for events in time). Each concept that received an event sits in
an occurrence-time index (a bounded FIFO, newest first); a selected event is paired
with the recent events there to induce ``<a =/> b>`` and ``<(a &/ ^op) =/> b>``. The
implications are stored in the predicate concept's table for the operation, and the
concepts holding implications for each operation are indexed, so neither induction nor
anticipation scans the whole memory.
"""

from __future__ import annotations

try:
    import cython
except ImportError:  # the pure engine runs without Cython
    from . import cy as cython

from collections.abc import Sequence
from typing import TYPE_CHECKING

from . import truth as tf
from .declarative import drop_fresh, predict_negated
from .event import BELIEF, ETERNAL, Event, Implication, event_of, outdone, revised_or_chosen
from .rules import variable_forms
from .spikegroups import group_add, group_keys, group_remove
from .stamp import Size, fmt, merge, overlap
from .state import Reasoner, emit, remember, shows
from .terms import (
    EQUIVALENCE,
    IMPLICATION,
    NEGATION,
    SEQUENCE,
    TEMPORAL_IMPLICATION,
    Bindings,
    Term,
    compound,
)
from .truth import Cycle, Truth, expectation
from .unify import apply, unify

if TYPE_CHECKING:
    from collections import deque

    from .memory import Concept
    from .table import Table


#: "not yet known": a pattern's group before it is first chosen, a match not yet made
_UNKNOWN = object()


def split_precondition(subject: Term) -> tuple[Term, Term | None]:
    """``(pre &/ op)`` -> (pre, op); anything else -> (subject, None)."""
    if subject.op == SEQUENCE and subject.args[1].is_op:
        return subject.args[0], subject.args[1]
    if subject.is_op:
        return subject, None
    return subject, None


def _sequence_length(t: Term) -> int:
    n = 1
    while t.op == SEQUENCE:
        n += 1
        t = t.args[0]
    return n


def _has_op(t: Term) -> bool:
    while t.op == SEQUENCE:
        if t.args[1].is_op:
            return True
        t = t.args[0]
    return t.is_op


def executable(op: Term) -> bool:
    """``^op`` or ``<({SELF} * args) --> ^op>`` / ``<(#1 * args) --> ^op>``: ours to run."""
    if op.op is None:
        return True
    s = op.args[0]
    first = s.args[0] if s.op == "*" else s
    if first.op == "{}" and len(first.args) == 1:
        first = first.args[0]  # {SELF} or {$1}
    return first.name == "SELF" or first.is_var


# ------------------------------------------------------------- operations
def op_id(s: Reasoner, op: Term) -> int:
    """1-based id of the operation ``op`` (``^name`` or ``<args --> ^name>``); 0 if unknown."""
    name = op.name if op.op is None else op.args[1].name
    try:
        return s.op_names.index(name) + 1
    except ValueError:
        return 0


# ------------------------------------------------------------ implications
def add_implication(
    s: Reasoner,
    term: Term,
    t: Truth,
    stamp: tuple[int, ...],
    dt: float,
    is_input: bool,
    priority: float,
    creation_time: int | None = None,
) -> Implication | None:
    """Store ``<pre =/> post>`` in the table of ``post`` for its operation."""
    subject, predicate = term.args
    pre, op = split_precondition(subject)
    opi = 0
    if op is not None:
        if not executable(op):
            return None
        opi = op_id(s, op)
        if opi == 0:
            return None
    now = s.time
    mem = s.memory
    cfg = s.config
    # the source first: making the target last means nothing evicts it before it is indexed
    source: Concept = mem.conceptualize(pre, now)
    source.use(now, is_input, cfg.eternal_input_usage_boost)
    target: Concept = mem.conceptualize(predicate, now)
    target.use(now, is_input, cfg.eternal_input_usage_boost)
    imp = Implication(term, t, stamp, dt, now if creation_time is None else creation_time, pre)
    # (the concept's tables read directly once made, and the index's entry for the
    # operation made only when missing: this runs for every induced link)
    tables = target.precondition_beliefs
    if tables is None:
        tables = target.tables(cfg.operations_max, cfg.table_size)
    table: Table = tables[opi]
    stored = table.add_and_revise(imp, cfg.stamp_size)
    posts = s.table_index.get(opi)
    if posts is None:
        s.table_index[opi] = {target: None}
    else:
        posts[target] = None
    if stored is not None and not is_input and shows(s, priority):
        emit(s, f"Derived: dt={dt:f} {term}. Priority={priority:f} Stamp={fmt(stamp)} {t}")
        if stored is not imp and stored.truth.c > t.c:
            emit(
                s,
                f"Revised: dt={stored.dt:f} {stored.term}. Priority={priority:f} "
                f"Stamp={fmt(stored.stamp)} {stored.truth}",
            )
    return stored


def forget_concept(s: Reasoner, c: Concept) -> None:
    """Drop an evicted concept from the implication, link and time indexes."""
    drop_fresh(s, c)
    # (if it is not there, it fell off the end of the full index)
    if c.timed and _drop(s.time_index, c) and s.groups is not None:
        group_remove(s.groups, c, _keys_of(s, c.term))
    tables = c.precondition_beliefs
    if tables is not None:
        for opi, table in enumerate(tables):
            if not table.items:
                continue
            d = s.table_index.get(opi)
            if d is not None:
                d.pop(c, None)
    t = c.term
    op = t.op
    if op is IMPLICATION or op is EQUIVALENCE:  # (by identity: ``terms.CONNECTORS``)
        s.general_links.pop(t, None)
        for side in t.args:
            d2 = s.links_by_subject.get(side)
            if d2 is not None:
                d2.pop(t, None)
                if not d2:
                    del s.links_by_subject[side]


# ------------------------------------------------------ declarative links
def note_link(s: Reasoner, term: Term) -> None:
    """Index an eternal ``==>``/``<=>`` belief by its condition (both sides of ``<=>``)."""
    sides = [term.args[0]] if term.op is IMPLICATION else [term.args[0], term.args[1]]
    for side in sides:
        if side.has_var:
            s.general_links[term] = None
            while len(s.general_links) > 4 * s.config.table_size:
                del s.general_links[next(iter(s.general_links))]
        else:
            s.links_by_subject.setdefault(side, {})[term] = None


# -------------------------------------------------------------- induction
def note_event(s: Reasoner, c: Concept) -> None:
    """Remember that ``c`` just received an event (newest first)."""
    idx = s.time_index
    if c.timed and idx and idx[0] is c:
        # the newest already, and so the newest of its groups too (each change of the
        # index since its last note would have made another concept the newest)
        return
    groups = s.groups
    present = False
    if c.timed:  # it has been in the index (a search for any other is in vain)
        present = _drop(idx, c)  # (if not, it fell off the end of the full index)
    if not present and groups is not None and len(idx) == idx.maxlen:
        gone = idx[-1]  # about to fall off the full index
        group_remove(groups, gone, _keys_of(s, gone.term))
    c.timed = True
    idx.appendleft(c)
    if groups is not None:
        group_add(groups, c, _keys_of(s, c.term))


def _drop(idx: deque[Concept], c: Concept) -> bool:
    """``idx.remove(c)``, found by identity: True if it was there. A deque compares
    each entry it passes with ``==``, which for concepts is a rich comparison falling
    back to identity, several times the cost of this loop over the 512 entries."""
    i = 0
    for x in idx:
        if x is c:
            del idx[i]
            return True
        i += 1
    return False


def _keys_of(s: Reasoner, term: Term) -> Sequence[object]:
    """The groups a concept of ``term`` belongs in: ``group_keys(term)``, kept on the
    term (a function of the term alone, and the same concepts come and go, in every
    reasoner of the process), and none for a term with variables, which stays out of
    the groups."""
    if term.has_var:
        return ()
    keys = term.keys
    if keys is None:
        keys = term.keys = group_keys(term)
    return keys


def process_belief_event(s: Reasoner, e: Event, priority: float) -> None:
    """ONA's sensorimotor processing of a selected belief event (Cycle.c, 0.9.2).

    Concepts are visited newest first in the occurrence-time index; a sequence made
    on the way takes effect at once (its concept's event is replaced before later
    concepts are visited), as in ONA.
    """
    cfg = s.config
    now = s.time
    if e.occurrence_time == ETERNAL or e.processed:
        return
    if now - e.occurrence_time >= cfg.max_sequence_timediff:
        return
    e.processed = True
    window = cfg.precondition_consequence_distance
    occ = e.occurrence_time
    e_is_op = e.term.is_op
    # (declared for the compiled engine: concepts and events read as structs, and
    # the time and its windows as floats, C doubles when compiled, exact below
    # 2**53 cycles: the first test of every index entry makes no integer)
    at: float = occ
    span: float = window
    c: Concept
    op_ev: Event
    pre: Event
    b: Event | None
    if not e_is_op:
        # procedural: <(pre &/ op) =/> e> for an op between pre and e. One pass over
        # the index finds the operation events in the window and the precondition
        # events that pass every test but the one against the operation's time, in
        # the index's order; the pairs are made after it. (``_induce`` changes no
        # concept's event, selection time or term, nor any event, so what the pass
        # sees holds while the pairs are made; and the tests are pure reads, so
        # their order is free: the time window, which excludes most of the index,
        # comes first.)
        op_events: list[Event] = []
        pre_events: list[Event] = []
        for c in s.time_index:
            b = c.belief_spike
            if b is None:
                continue
            if c.term.is_op:
                if (
                    b.creation_time >= now
                    or b.occurrence_time >= occ
                    or abs(b.occurrence_time - occ) >= window
                    or abs(c.selected_time - occ) >= window
                ):
                    continue
                op_events.append(b)
            elif not (
                abs(b.occurrence_time - at) >= span
                or b.creation_time >= now
                or abs(c.selected_time - occ) >= window
                or (c.term.n_imp and c.term.op in ("==>", "<=>"))
                or c.term is e.term
            ):
                pre_events.append(b)
        for op_ev in op_events:
            for pre in pre_events:
                if pre.occurrence_time >= op_ev.occurrence_time or overlap(pre.stamp, e.stamp):
                    continue
                _induce(s, pre, op_ev, e, priority)
    # temporal: <c =/> e> for recent non-op events, and the sequence (c &/ e)
    tdiff = cfg.max_sequence_timediff
    reach: float = tdiff
    concurrent = cfg.allow_concurrent_implications
    # (read once for the recent events below, not for each)
    least = cfg.min_confidence
    longest = cfg.max_sequence_len
    size = cfg.stamp_size
    for c in () if e_is_op else list(s.time_index):  # an operation pairs with none
        b = c.belief_spike
        if (
            b is None
            or abs(b.occurrence_time - at) > reach  # most of the index: first
            or b.creation_time > now
            or abs(c.selected_time - occ) > tdiff
            or b.occurrence_time > occ
            # (a term's count of ==>/<=> spares nearly every term the string test)
            or (c.term.n_imp and c.term.op in ("==>", "<=>"))
            or c.term.is_op
            or overlap(b.stamp, e.stamp)
            or (not concurrent and b.occurrence_time == occ)
        ):
            continue
        t = tf.intersection(tf.projection(b.truth, b.occurrence_time, occ), e.truth)
        if t.c < least:
            continue
        if c.term is not e.term:
            _induce(s, b, None, e, priority)
            if b.occurrence_time == occ:
                _induce(s, e, None, b, priority)
        if _sequence_length(c.term) + 1 <= longest and not _has_op(c.term):
            seq = compound(SEQUENCE, (c.term, e.term))
            stamp = merge(b.stamp, e.stamp, size)
            _activate_sequence(s, Event(seq, BELIEF, t, stamp, occ, now))
    if priority >= 1.0:  # fresh input: assume failure of what it promises
        anticipate(s, e)


def _activate_sequence(s: Reasoner, se: Event) -> None:
    """A sequence that just happened: its concept gets the event, it is not queued."""
    mem = s.memory
    c: Concept = mem.conceptualize(se.term, s.time)
    old: Event | None = c.belief_spike
    if old is None or old.occurrence_time < se.occurrence_time:
        c.belief_spike = se
    c.selected_time = s.time
    note_event(s, c)


def _induce(s: Reasoner, pre: Event, op: Event | None, post: Event, priority: float) -> None:
    """beliefInduction: ``<pre =/> post>`` (or with ``op``) with ONA's truth."""
    cfg = s.config
    if op is not None:
        pre_t = tf.intersection(
            tf.projection(pre.truth, pre.occurrence_time, op.occurrence_time), op.truth
        )
        pre_occ = op.occurrence_time
    else:
        pre_t = pre.truth
        pre_occ = pre.occurrence_time
    proj = tf.projection(pre_t, pre_occ, post.occurrence_time)
    t = tf.eternalize(tf.induction(post.truth, proj))
    if t.c < cfg.min_confidence:
        return  # most pairs stop here: the link's term and stamp are not built
    size = cfg.stamp_size
    if op is not None:
        subj = compound(SEQUENCE, (pre.term, op.term))
        stamp = merge(merge(pre.stamp, op.stamp, size), post.stamp, size)
    else:
        subj = pre.term
        stamp = merge(pre.stamp, post.stamp, size)
    dt = float(post.occurrence_time - pre_occ)
    term = compound(TEMPORAL_IMPLICATION, (subj, post.term))
    p = priority * expectation(t)
    add_implication(s, term, t, stamp, dt, False, p)
    if cfg.allow_var_intro:
        # (a ``=/>`` link's forms: those a variable-introducing rule would derive)
        for v in variable_forms(term):
            add_implication(s, v, t, stamp, dt, False, p)


# ------------------------------------------------------------ anticipation
def anticipate(s: Reasoner, e: Event) -> None:
    """Assumption of failure (ONA 0.9.2's Decision_Anticipate): see ``_anticipate``.

    What it learns of each precondition is kept on the precondition's term for the
    call (``Term.anticipated``) and taken off the terms when it ends, however it ends:
    left there, it would keep the events it names alive.
    """
    touched: Touched = []
    try:
        _anticipate(s, e, touched)
    finally:
        for t in touched:
            t.anticipated = None


#: the last number given to an anticipation (see ``_anticipate``): a counter of the
#: process, since the terms the records hang on are the process's
_SERIAL = [0]
#: the terms given a record (an alias the compiled engine reads as a plain list)
Touched = list[Term]


def _anticipate(s: Reasoner, e: Event, touched: Touched) -> None:
    """Assumption of failure (ONA 0.9.2's Decision_Anticipate).

    For every implication in the table of the event's operation (table 0 for a plain
    event) whose precondition concept has a belief event, the outcome is predicted
    from that event projected to now in sequence with the operation; if the
    prediction is expected, one piece of negative evidence is counted against the
    implication, which the outcome, if it arrives, outweighs by induction. The age of
    the precondition is not checked: projection makes old ones too weak to count.
    """
    cfg = s.config
    now = s.time
    opi = op_id(s, e.term) if e.term.is_op else 0
    targets = s.table_index.get(opi)
    if not targets:
        return
    mem = s.memory
    op_truth = Truth(1.0, 0.9)
    # ONA 0.9.3 predicts a plain event's outcome from the precondition's event as it
    # is, at the time that event promises it; 0.9.2 from it projected to now
    as_is = opi == 0 and not cfg.anticipation_projects_precondition
    threshold: float = cfg.anticipation_threshold
    # A precondition whose projected truth is this weak cannot lift a prediction
    # above the threshold (expectation - 1/2 <= c / 2) nor to confidence 0.05, so
    # only an exactly-zero predicted frequency still counts; this skips the many
    # implications whose precondition happened long ago without computing them.
    weak = min(0.05, 1.98 * (threshold - 0.5)) if threshold > 0.5 + 1e-9 else 0.0
    # What anticipation knows of a precondition (see _Source) is kept on its term, as
    # ``anticipated``: the same precondition serves many implications, and a field
    # read is cheaper than a dict look-up at each of the hundreds of links visited. A
    # record counts only if it carries this call's number (``serial``); a new number
    # drops them all when the concept store changes below, and ``anticipated = None``
    # one when an event changes. Each term given one goes into ``touched``.
    serial = _SERIAL[0] = _SERIAL[0] + 1
    groups: dict[object, dict[Concept, None]] | None = None
    var_sources: list[Term] = []
    confidence: float = cfg.anticipation_confidence
    outcomes = s.outcomes
    stamp_size = cfg.stamp_size
    boost = cfg.eternal_input_usage_boost
    showing = shows(s, 1.0)  # printing is rare: test once
    shows_predictions = cfg.print_predictions
    negations = cfg.anticipation_negated_outcomes
    evictions = mem.evictions
    # (mem.find and mem.conceptualize of a concept that exists, read from the dict)
    concepts: dict[Term, Concept] = mem.concepts
    post: Concept
    oc: Concept | None
    imp: Implication
    it: Truth
    table: Table
    spike: Event
    src: _Source | None
    found: Event | None
    bind: Bindings | None
    outcome: Term
    pattern: _Pattern
    pf: float
    pc: float
    fc: float
    weight: float
    for post in list(targets):
        if concepts.get(post.term) is not post:
            targets.pop(post, None)
            continue
        tables = post.precondition_beliefs
        if tables is None or opi >= len(tables):
            continue
        table = tables[opi]
        # (a copy: failures below move the links; a tuple is the cheapest to make)
        items = tuple(table.items)
        for k in range(len(items)):
            imp = items[k]
            source = imp.source
            if source is None:
                continue
            src = source.anticipated
            if src is None or src.serial != serial:
                if source.has_var:
                    var_sources.append(source)
                    if groups is None:
                        groups = spike_groups(s)
                    # (source_spike, keeping the pattern for the bindings)
                    pattern = _pattern(s, source)
                    sc = concepts.get(source)
                    found = sc.belief_spike if sc is not None else None
                    found = _newest_instance(pattern, groups, found)
                    bind = None if found is None else pattern.match(found.term)
                else:  # what source_spike and unify give for a ground precondition
                    sc = concepts.get(source)
                    found = sc.belief_spike if sc is not None else None
                    bind = None if found is None or found.term is not source else {}
                src = _source(found, bind, as_is, op_truth, weak, now)
                src.serial = serial
                source.anticipated = src
                touched.append(source)
            spike = src.spike
            if spike is None:
                continue
            # deduction and its expectation written out (most links stop here);
            # the same operations in the same order as tf.deduction/expectation
            it = imp.truth
            pf = it.f * src.f
            if src.weak and pf != 0.0:
                continue
            if opi:
                pre_term, op_term = split_precondition(imp.term.args[0])
                subs = unify(pre_term, spike.term)
                if subs is None or op_term is None:
                    continue
                if unify(apply(op_term, subs), e.term) is None:
                    continue  # same operation, other arguments
            pc = it.c * src.c * pf
            if pc * (pf - 0.5) + 0.5 <= threshold and not (pc < 0.05 and pf == 0.0):
                continue
            # one failure counted against the link
            rdt = _offset(imp.dt)  # also the prediction's offset below
            fc = _failure_confidence(spike.truth, rdt, confidence)
            failure = tf.truth_of(0.0, fc)
            weight = tf.c2w(fc)
            table.add_failure(imp, failure, weight, stamp_size, k)
            bind = src.bind
            if bind is None:
                continue
            if bind:
                # the same link meets the same instance at every input: keep the
                # instantiated outcome (a pure function of the two terms)
                okey = (imp.term, spike.term)
                outcome = outcomes.get(okey)
                if outcome is None:
                    outcome = remember(outcomes, okey, apply(imp.term.args[1], bind))
            else:
                outcome = imp.term.args[1]
            if outcome.has_var or overlap(spike.stamp, imp.stamp):
                continue
            oc = concepts.get(outcome)
            if oc is None:
                oc = mem.conceptualize(outcome, now)
                if mem.evictions != evictions:
                    evictions = mem.evictions
                    serial = _SERIAL[0] = _SERIAL[0] + 1
                    var_sources.clear()
                    groups = None
            oc.use(now, False, boost)
            occ = (spike.occurrence_time if as_is else now) + rdt
            if as_is or imp.dt > 0.0:  # (0.9.3: every prediction is one)
                old = oc.predicted_belief
                negated = negations and outcome.op == NEGATION
                # most predictions lose to the one already made (nothing changes,
                # nothing is shown): those are not made
                if old is not None and not negated and outdone(old, outcome, occ, pc):
                    continue
                pred = _prediction(outcome, pf, pc, spike, imp, occ, now, stamp_size)
                oc.predicted_belief, _ = revised_or_chosen(old, pred, stamp_size, True)
                if showing and shows_predictions:
                    _show_prediction(s, old, oc.predicted_belief)
                if negated:
                    predict_negated(s, pred, table, imp, failure, weight)
                    if mem.evictions != evictions:
                        evictions = mem.evictions
                        serial = _SERIAL[0] = _SERIAL[0] + 1
                        var_sources.clear()
                        groups = None
            elif oc.belief_spike is None or occ > oc.belief_spike.occurrence_time:
                old = oc.belief_spike
                if old is None or not outdone(old, outcome, occ, pc):
                    pred = _prediction(outcome, pf, pc, spike, imp, occ, now, stamp_size)
                    oc.belief_spike, _ = revised_or_chosen(old, pred, stamp_size, True)
                    if showing:
                        _show_prediction(s, old, oc.belief_spike)
                # only this term's entry changes, and the entries of preconditions
                # with variables that the outcome instantiates (the others cannot
                # have found their event in its concept)
                outcome.anticipated = None
                if var_sources:
                    kept = []
                    for v in var_sources:
                        if (v.op is not None and v.op != outcome.op) or unify(v, outcome) is None:
                            kept.append(v)
                        else:
                            v.anticipated = None
                    var_sources[:] = kept


def _prediction(
    outcome: Term,
    f: float,
    c: float,
    spike: Event,
    imp: Implication,
    occ: Cycle,
    now: Cycle,
    stamp_size: Size,
) -> Event:
    """The outcome predicted from ``spike`` through ``imp``, of truth (``f``, ``c``)."""
    # (``truth_of`` and ``event_of`` rather than the keyword-capable constructors)
    stamp = merge(spike.stamp, imp.stamp, stamp_size)
    return event_of(outcome, BELIEF, tf.truth_of(f, c), stamp, occ, now)


@cython.freelist(64)
@cython.cclass
class _Source:
    """What anticipation knows of one precondition term during one input: ``spike``,
    its concept's belief event (or the newest instance's), None if there is none; ``f``
    and ``c``, that event's truth projected to now with the operation; ``weak``, whether
    that is too weak to lift a prediction (see ``anticipate``); ``bind``, the bindings
    making the precondition that event's term (None: it is not)."""

    __slots__ = ("spike", "f", "c", "weak", "bind", "serial")


def _source(
    spike: Event | None, bind: Bindings | None, as_is: bool, op: Truth, weak: float, now: Cycle
) -> _Source:
    """The :class:`_Source` of a precondition whose event is ``spike``, then ``op``."""
    src: _Source = _Source.__new__(_Source)
    src.spike = spike
    src.bind = bind
    if spike is None:
        return src
    t = spike.truth
    if as_is:  # ONA 0.9.3: the event as it happened
        src.f = t.f
        src.c = t.c
    else:
        # tf.intersection(tf.projection(t, spike.occurrence_time, now), op), the
        # same products in the same order, without making the two truths
        c = t.c
        if spike.occurrence_time != -1:  # (not ETERNAL: projection leaves those)
            c = c * tf.decay(abs(now - spike.occurrence_time))
        src.f = t.f * op.f
        src.c = c * op.c
    src.weak = src.c < weak
    return src


def _offset(dt: float) -> int:
    """``round(dt)`` (halves to even) for an offset, written out so that compiled it is
    C arithmetic, not a call of the builtin (anticipation rounds hundreds of offsets per
    input). ``x - int(x)`` is exact for a float, so the comparisons with 1/2 are too;
    offsets stay far below 2**63, where the compiled engine's integers end."""
    if dt < 0.0:
        return -_offset(-dt)
    n = int(dt)
    r = dt - n
    if r > 0.5 or (r == 0.5 and n % 2 == 1):
        n += 1
    return n


def spike_groups(s: Reasoner) -> dict[object, dict[Concept, None]]:
    """Concepts of the occurrence-time index without variables, grouped so that a
    precondition with variables is unified only against terms that can match it: by
    connector and arity, and by each component at each position (a path of
    connector, arity and index from the top); key ``None`` holds all of them. Each
    group is ordered oldest to newest. Built once, then kept in step with the index
    by :func:`note_event` and :func:`forget_concept`; whether a member has a belief
    event is checked where it is read, since events come and go more often than
    concepts."""
    groups = s.groups
    if groups is None:
        groups = s.groups = {None: {}}
        for c in reversed(s.time_index):  # oldest first: the newest ends last
            group_add(groups, c, _keys_of(s, c.term))
    return groups


#: the groups of ``spike_groups`` (an alias the compiled engine reads as a dict)
_Groups = dict[object, dict["Concept", None]]


def source_spike(s: Reasoner, source: Term, groups: _Groups | None = None) -> Event | None:
    """The belief event of a precondition concept; a concept with variables holds
    the newest event that instantiates it (ONA activates such concepts too)."""
    concepts: dict[Term, Concept] = s.memory.concepts  # (its find, read from the dict)
    c: Concept | None = concepts.get(source)
    best = c.belief_spike if c is not None else None
    if source.has_var:
        if groups is None:
            groups = spike_groups(s)
        best = _newest_instance(_pattern(s, source), groups, best)
    return best


def _pattern(s: Reasoner, source: Term) -> _Pattern:
    """The :class:`_Pattern` of the precondition ``source`` (with variables), made
    when first asked for."""
    pattern: _Pattern | None = s.patterns.get(source)
    if pattern is None:
        pattern = remember(s.patterns, source, _Pattern(source))
    return pattern


def _newest_instance(pattern: _Pattern, groups: _Groups, best: Event | None) -> Event | None:
    """The belief event of the newest concept in ``groups`` that instantiates
    ``pattern``'s precondition, if it is newer than ``best``; else ``best``."""
    # Every instance is in each of the pattern's groups, all ordered alike (by their
    # concepts' last event), so each group yields the same first match and an empty
    # one means none. The smallest is the cheapest to scan; group sizes drift slowly,
    # so it is chosen afresh only now and then.
    pattern.uses += 1
    key = pattern.key
    group: dict[Concept, None] | None
    if key is _UNKNOWN or not pattern.uses & 31:
        group = None
        for k in pattern.keys:
            g = groups.get(k)
            if not g:
                return best  # no concept has this component here: none matches
            if group is None or len(g) < len(group):
                group = g
                key = k
        pattern.key = key
    else:
        # The group read last time is still the one of its key while it has members:
        # a group leaves ``groups`` only once empty, and a new one is made for the
        # key if it fills again (this saves hashing the key at every input).
        group = pattern.group
        if not group or pattern.groups is not groups:
            group = groups.get(key)
            if not group:
                return best
    pattern.group = group
    pattern.groups = groups
    matches = pattern.matches
    c2: Concept
    b: Event | None
    for c2 in reversed(group):  # newest first
        b = c2.belief_spike
        if b is None:
            continue
        bind = matches.get(c2.term, _UNKNOWN)  # (pattern.match, read inline)
        if bind is _UNKNOWN:
            bind = pattern.match(c2.term)
        if bind is None:
            continue
        if best is None or b.occurrence_time > best.occurrence_time:
            best = b
        break
    return best


def _show_prediction(s: Reasoner, old: Event | None, new: Event) -> None:
    """Print a changed prediction as ONA does (a derived event of priority 1); the
    caller has checked that derivations of that priority are shown."""
    if old is not None and old.truth == new.truth and old.occurrence_time == new.occurrence_time:
        return
    emit(s, "Derived: " + new.line(1.0))


def _failure_confidence(pre: Truth, rdt: Cycle, confidence: float) -> float:
    """The confidence of one failure of a link whose precondition had truth ``pre``
    ``rdt`` cycles before the predicted outcome: induction from a {0, ``confidence``}
    outcome and the projected precondition, made eternal, so
    ``tf.eternalize(tf.induction(Truth(0.0, confidence), tf.projection(pre, 0, rdt))).c``
    (its frequency is 0), the same operations in the same order without making the
    truths (anticipation counts hundreds of failures per input)."""
    past_c = pre.c * tf.decay(abs(rdt))
    return tf.w2c(tf.w2c(pre.f * past_c * confidence))


class _Pattern:
    """What ``source_spike`` keeps about a precondition with variables."""

    __slots__ = ("source", "keys", "key", "uses", "matches", "group", "groups")

    def __init__(self, source: Term) -> None:
        self.source = source
        #: the groups every instance of the precondition is in
        self.keys = group_keys(source, ground_only=True)
        #: the one of them scanned (the smallest when last chosen)
        self.key: object = _UNKNOWN
        self.uses = 0
        #: ground term -> unify(precondition, term), a pure function of the two
        self.matches: dict[Term, dict[Term, Term] | None] = {}
        #: the group of ``key`` when last read, and the groups it was read from
        self.group: dict[Concept, None] | None = None
        self.groups: _Groups | None = None

    def match(self, term: Term) -> dict[Term, Term] | None:
        """``unify(source, term)``, remembered (nobody changes the bindings returned)."""
        bind = self.matches.get(term, _UNKNOWN)
        if bind is _UNKNOWN:
            # (a few groups' worth: each pattern has its own)
            bind = remember(self.matches, term, unify(self.source, term), 128)
        return bind
