"""Declarative implications in ONA 0.9.3's cycle: the pass of fresh eternal beliefs
through ``==>`` beliefs, and negated consequences.

Functions over a :class:`~robocog.nars.state.Reasoner`, below ``sensorimotor`` (which
predicts negated consequences through :func:`predict_negated`). Both are ONA 0.9.3's and run only when their parameters say so
(``declarative_implications_cycle_process``, ``anticipation_negated_outcomes``); with
ONA 0.9.2's parameters nothing here is called.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from . import truth as tf
from .event import BELIEF, ETERNAL, Event, Implication, revised_or_chosen
from .memory import Concept
from .stamp import merge, overlap
from .state import Reasoner, emit, shows
from .terms import NEGATION, Term
from .truth import Truth, expectation
from .unify import apply, unify

if TYPE_CHECKING:
    from .table import Table


def note_fresh_belief(s: Reasoner, c: Concept) -> None:
    """``c``'s eternal belief was just made or revised (newest last).

    Each fresh concept keeps an entry ``[order, belief, min_confidence, stamp_size,
    negated, groups, deductions, consequences]``: when it was noted, the groups it is
    filed in, what its belief deduced through each link (for the belief and parameters
    named), and each link's consequence for its term. It is filed under the shapes of
    conditions its term may instantiate (``s.fresh_shapes``: shape -> group of
    concepts), so that a cycle meets only the fresh beliefs some link's condition may
    take; the entry keeps the groups themselves, so that leaving them hashes no shape."""
    fresh: dict = s.fresh_beliefs
    filed: dict
    d: dict
    entry = fresh.pop(c, None)
    if entry is None:
        groups: list = []
        if not c.term.has_var:
            filed = s.fresh_shapes
            for key in _term_shapes(c.term):
                found = filed.get(key)
                if found is None:
                    if len(filed) >= s.fresh_swept + s.fresh_swept + _SWEEP_AT:
                        filed = _sweep(s)
                    d = {}
                    filed[key] = d
                else:
                    d = found
                d[c] = None
                groups.append(d)
        entry = [0, None, 0.0, 0, False, groups, None, None]
    s.fresh_order += 1
    entry[0] = s.fresh_order
    fresh[c] = entry


#: shapes filed before the groups left empty are swept away
_SWEEP_AT = 4096


def _sweep(s: Reasoner) -> dict:
    """Drop the empty groups of ``s.fresh_shapes`` (a concept leaving its groups leaves
    them in place, empty or not; no entry refers to an empty one). Swept when the
    groups have doubled since the last sweep, so each group costs one look."""
    s.fresh_shapes = {key: d for key, d in s.fresh_shapes.items() if d}
    s.fresh_swept = len(s.fresh_shapes)
    return s.fresh_shapes


def drop_fresh(s: Reasoner, c: Concept) -> None:
    """``c`` is no longer fresh (stale, or evicted)."""
    entry = s.fresh_beliefs.pop(c, None)
    if entry is None:
        return
    d: dict
    for d in entry[5]:
        d.pop(c, None)


def forward_eternal(s: Reasoner, on_new_belief: Callable[[Reasoner, Concept], None]) -> None:
    """ONA 0.9.3's declarative pass for eternal beliefs: each ground belief made or
    revised within the tolerance meets the strongest ``==>`` beliefs whose
    condition it instantiates; the consequence's eternal belief is revised with
    the deduction (or the stronger kept), and, being fresh, travels on next cycle;
    ``on_new_belief(s, concept)`` is told of each (open questions may have their answer).

    The deduction is as new as the newer of its premises (ONA's DERIVATION_STAMP takes
    the later creation time of the two, Decision_Anticipate keeps it), so a consequence
    stays fresh only while what it came from is."""
    c: Concept
    cfg = s.config
    now = s.time
    mem = s.memory
    concepts: dict = mem.concepts
    fresh = s.fresh_beliefs
    oldest = now - cfg.belief_last_used_tolerance
    # the stale ones at the front (older than the tolerance, gone, or evicted) leave;
    # one walk finds them all (a dict whose front entries were deleted is walked past
    # their slots by every new iterator, so one iterator per dropped concept cost a
    # walk of the whole table each)
    stale: list = []
    for c in fresh:
        b = c.belief
        if b is not None and b.creation_time >= oldest and concepts.get(c.term) is c:
            break
        stale.append(c)
    for c in stale:
        drop_fresh(s, c)
    if not fresh:
        return
    links, by_shape = strongest_links(s)
    if not links:
        return
    size = cfg.stamp_size
    least = cfg.min_confidence
    negated = cfg.anticipation_negated_outcomes
    # (ONA 0.9.3 deduces here from premises that share evidence; opt-in refusal)
    disjoint = cfg.declarative_pass_disjoint_evidence
    show = shows(s, 1.0)
    # the fresh beliefs that some link's condition may take, with the links' positions
    # (each fresh belief meets the links in their order, the beliefs in their order)
    filed = s.fresh_shapes
    met: dict[Concept, list[int]] = {}
    for key, positions in by_shape.items():
        concepts_here = filed.get(key)
        if not concepts_here:
            continue
        for c in concepts_here:
            m = met.get(c)
            if m is None:
                met[c] = list(positions)
            else:
                m += positions
    order = sorted([(fresh[x][0], x) for x in met])
    # each deduction is [term, truth, stamp, the belief it last left as it was], with
    # the creation time it has this cycle
    derived: list[tuple[list, int]] = []
    lb: Event
    for _, c in order:
        b = c.belief
        if b is None or b.creation_time < oldest:
            continue
        term = c.term
        bt = b.creation_time
        # a belief stays fresh for several cycles and meets mostly the same links at
        # each: what it deduced through each link is kept in its entry while its
        # belief, the link's belief and the parameters read here are the same; what
        # the link's consequence is for this term (a unification) while the concept is
        # fresh (its term never changes)
        entry = fresh[c]
        if (
            entry[1] is not b
            or entry[2] != least
            or entry[3] != size
            or entry[4] != negated
            or entry[6] is None
        ):
            entry[1] = b
            entry[2] = least
            entry[3] = size
            entry[4] = negated
            entry[6] = {}
        known: dict = entry[6]
        targets = entry[7]
        positions = met[c]
        positions.sort()
        for i in positions:
            link, lb = links[i]
            hit = known.get(link)
            if hit is not None and hit[0] is lb:
                found = hit[1]
            else:
                if targets is None:
                    targets = entry[7] = {}
                target = targets.get(link, _UNKNOWN)
                if target is _UNKNOWN:
                    target = _consequence(term, link)
                    targets[link] = target
                found = None if target is None else _deduction(b, lb, target, least, size, negated)
                known[link] = (lb, found)
            if found is not None:
                if disjoint and overlap(b.stamp, lb.stamp):
                    continue
                lt = lb.creation_time
                derived.append((found, bt if bt > lt else lt))
    # the same belief would be left as it is again (a revision or choice reads only
    # what an event never changes), so it is not tried again
    tc: Concept
    for found, made in derived:
        target = found[0]
        tc = concepts.get(target)
        if tc is None:
            tc = mem.conceptualize(target, now)
        old = tc.belief
        if old is not None and (old is found[3] or old.stamp == found[2]):
            continue
        e = Event(target, BELIEF, found[1], found[2], ETERNAL, made)
        new, _ = revised_or_chosen(old, e, size, True)
        if new is old:
            found[3] = old
            continue
        tc.belief = new
        if show:
            emit(s, "Derived: " + new.line(1.0))
        note_fresh_belief(s, tc)
        on_new_belief(s, tc)


#: "not yet worked out": a link's consequence for a term not yet unified
_UNKNOWN = object()


def _consequence(term: Term, link: Term) -> Term | None:
    """The ground consequence of ``link`` for the ground ``term`` as its condition, or
    None if the condition does not take it or the consequence keeps a variable."""
    cond, concl = link.args
    if cond.op is not None and cond.op != term.op:
        return None
    bind = unify(cond, term)
    if bind is None:
        return None
    target = apply(concl, bind)
    if target.has_var:
        return None
    return target


def _deduction(
    b: Event, lb: Event, target: Term, least: float, size: int, negated: bool
) -> list | None:
    """What the eternal belief ``b`` deduces as ``target`` through a link believed as
    ``lb``: the consequence's term, truth and stamp (and a slot for the belief it
    last left unchanged), a negated consequence ``(! x)`` as ``x`` with the negated
    truth when ``negated``; None if too weak."""
    t = tf.deduction(lb.truth, b.truth)
    if t.c < least:
        return None
    stamp = merge(b.stamp, lb.stamp, size)
    if target.op == NEGATION and negated:
        return [target.args[0], tf.negation(t), stamp, None]
    return [target, t, stamp, None]


#: the conditions of more components than this are indexed by connector and arity only
_WIDEST = 3


def _component_shape(t: Term) -> object:
    """What a condition's component demands of the term's component in its place: that
    very term (ground), anything (a variable: None), or a compound of its connector and
    arity (a compound with variables)."""
    if not t.has_var:
        return t
    if t.op is None:
        return None
    return (t.op, len(t.args))


def _condition_shape(cond: Term) -> object:
    """The key under which a condition is indexed: every ground term it unifies with
    has this key among :func:`_term_shapes`."""
    if not cond.has_var:
        return cond
    if cond.op is None:
        return None
    if len(cond.args) > _WIDEST:
        return (cond.op, len(cond.args))
    return (cond.op, tuple([_component_shape(a) for a in cond.args]))


def _term_shapes(t: Term) -> list[object]:
    """The keys of every condition that may unify with the ground term ``t`` (unify
    is positional: same connector, arity, and each component the same ground term, a
    variable, or a compound of the same connector and arity), each once."""
    keys: list[object] = [None, t]
    op = t.op
    if op is None:
        return keys
    args = t.args
    n = len(args)
    if n > _WIDEST:
        keys.append((op, n))
        return keys
    # what each component may be in a condition: itself, any term, or (for a compound)
    # a compound of its connector and arity
    options: list[tuple] = []
    for a in args:
        if a.op is None:
            options.append((a, None))
        else:
            options.append((a, None, (a.op, len(a.args))))
    # every combination but the first (every component itself: a condition whose
    # components are all ground is ground, and keyed by itself), written out for the
    # arities indexed, in the order of the product
    if n == 1:
        for x in options[0][1:]:
            keys.append((op, (x,)))
    elif n == 2:
        first = options[0][0]
        second = options[1][0]
        for x in options[0]:
            for y in options[1]:
                if x is first and y is second:
                    continue
                keys.append((op, (x, y)))
    elif n == 3:
        first = options[0][0]
        second = options[1][0]
        third = options[2][0]
        for x in options[0]:
            for y in options[1]:
                for z in options[2]:
                    if x is first and y is second and z is third:
                        continue
                    keys.append((op, (x, y, z)))
    return keys


def strongest_links(
    s: Reasoner,
) -> tuple[list[tuple[Term, Event]], dict[object, list[int]]]:
    """The ``==>`` beliefs the declarative pass uses, in the order it uses them (ONA
    keeps a consequence's ``==>`` beliefs in a table ordered by expectation and uses the
    strongest ``top_k_declarative_implications`` of each table), with an index of their
    positions by the shape of the condition (:func:`_condition_shape`).

    Kept between cycles: rebuilt only when some link or its belief is another than the
    last time (a belief is never changed in place, only replaced), so that a cycle
    costs a look at each link rather than a sort of them all and a unification of each
    fresh belief with each link."""
    concepts: dict = s.memory.concepts
    current: list[tuple[Term, Event]] = []
    link: Term
    lc: Concept
    for link in declarative_links(s):
        if link.op != "==>":
            continue
        found = concepts.get(link)
        if found is None:
            continue
        lc = found
        if lc.belief is not None:
            current.append((link, lc.belief))
    cached = s.strongest
    shapes: dict = {}
    if cached is not None:
        shapes = cached[3]
        seen = cached[0]
        if len(seen) == len(current):
            same = True
            for i in range(len(current)):
                a = seen[i]
                b = current[i]
                if a[0] is not b[0] or a[1] is not b[1]:
                    same = False
                    break
            if same:
                return cached[1], cached[2]
    tables: dict[Term, list[tuple[Term, Event]]] = {}
    for entry in current:
        tables.setdefault(entry[0].args[1], []).append(entry)
    links: list[tuple[Term, Event]] = []
    k = s.config.top_k_declarative_implications
    # (each table by expectation, strongest first, equal ones in their order: a sort
    # of (minus expectation, place) pairs, without a key function called per link)
    for entries in tables.values():
        if len(entries) > 1:
            ranked = sorted([(-expectation(x[1].truth), i) for i, x in enumerate(entries)])
            entries = [entries[i] for _, i in ranked]
        links += entries[:k]
    # (a link's shape is its condition's: kept for the links still in use, as most are
    # at the next rebuild)
    by_shape: dict[object, list[int]] = {}
    kept: dict = {}
    for i, (link, _) in enumerate(links):
        key = shapes.get(link, _UNKNOWN)
        if key is _UNKNOWN:
            key = _condition_shape(link.args[0])
        kept[link] = key
        d = by_shape.get(key)
        if d is None:
            by_shape[key] = [i]
        else:
            d.append(i)
    s.strongest = (current, links, by_shape, kept)
    return links, by_shape


def declarative_links(s: Reasoner) -> list[Term]:
    """Every indexed ``==>``/``<=>`` belief term, ground conditions first."""
    out: dict[Term, None] = {}
    for links in s.links_by_subject.values():
        out.update(links)
    out.update(s.general_links)
    return list(out)


def predict_negated(
    s: Reasoner,
    pred: Event,
    table: Table,
    imp: Implication,
    failure: Truth,
    weight: float,
) -> None:
    """ONA 0.9.3's negation handling: a predicted ``(! x)`` is also ``x`` predicted
    with the negated truth, and if that prediction is expected (or a weak zero) the
    link counts one more failure (``failure``, of evidence weight ``weight``, as the
    prediction's did)."""
    cfg = s.config
    t = tf.negation(pred.truth)
    if expectation(t) > cfg.anticipation_threshold or (t.c < 0.05 and t.f == 0.0):
        table.add_failure(imp, failure, weight, cfg.stamp_size)
    inner = pred.term.args[0]
    if inner.has_var:
        return
    ic = s.memory.conceptualize(inner, s.time)
    neg = Event(inner, BELIEF, t, pred.stamp, pred.occurrence_time, pred.creation_time)
    ic.predicted_belief = revised_or_chosen(ic.predicted_belief, neg, cfg.stamp_size, True)[0]


__all__ = [
    "declarative_links",
    "drop_fresh",
    "forward_eternal",
    "note_fresh_belief",
    "predict_negated",
    "strongest_links",
]
