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
from .stamp import merge
from .state import Reasoner, emit, shows
from .terms import NEGATION, Term
from .truth import Truth, expectation
from .unify import apply, unify

if TYPE_CHECKING:
    from .memory import Concept
    from .table import Table


def note_fresh_belief(s: Reasoner, c: Concept) -> None:
    """``c``'s eternal belief was just made or revised (newest last)."""
    fresh = s.fresh_beliefs
    fresh.pop(c, None)
    fresh[c] = None


def forward_eternal(s: Reasoner, on_new_belief: Callable[[Reasoner, Concept], None]) -> None:
    """ONA 0.9.3's declarative pass for eternal beliefs: each ground belief made or
    revised within the tolerance meets the strongest ``==>`` beliefs whose
    condition it instantiates; the consequence's eternal belief is revised with
    the deduction (or the stronger kept), and, being fresh, travels on next cycle;
    ``on_new_belief(s, concept)`` is told of each (open questions may have their answer)."""
    cfg = s.config
    now = s.time
    mem = s.memory
    fresh = s.fresh_beliefs
    oldest = now - cfg.belief_last_used_tolerance
    while fresh:
        c = next(iter(fresh))
        b = c.belief
        if b is not None and b.creation_time >= oldest and mem.find(c.term) is c:
            break
        del fresh[c]  # (stale: older than the tolerance, gone, or evicted)
    if not fresh:
        return
    # ONA keeps a consequence's ``==>`` beliefs in a table ordered by expectation
    # and uses the strongest ``top_k_declarative_implications`` of each table
    tables: dict[Term, list[tuple[Term, Event]]] = {}
    for link in declarative_links(s):
        lc = mem.find(link)
        if link.op == "==>" and lc is not None and lc.belief is not None:
            tables.setdefault(link.args[1], []).append((link, lc.belief))
    if not tables:
        return
    links: list[tuple[Term, Event]] = []
    for entries in tables.values():
        entries.sort(key=lambda x: -expectation(x[1].truth))
        links += entries[: cfg.top_k_declarative_implications]
    size = cfg.stamp_size
    derived: list[Event] = []
    for c in list(fresh):
        b = c.belief
        if b is None or b.creation_time < oldest or c.term.has_var:
            continue
        for link, lb in links:
            cond, concl = link.args
            if cond.op is not None and cond.op != c.term.op:
                continue
            bind = unify(cond, c.term)
            if bind is None:
                continue
            target = apply(concl, bind)
            if target.has_var:
                continue
            t = tf.deduction(lb.truth, b.truth)
            if t.c < cfg.min_confidence:
                continue
            stamp = merge(b.stamp, lb.stamp, size)
            derived.append(Event(target, BELIEF, t, stamp, ETERNAL, now))
    for e in derived:
        if e.term.op == NEGATION and cfg.anticipation_negated_outcomes:
            e = Event(e.term.args[0], BELIEF, tf.negation(e.truth), e.stamp, ETERNAL, now)
        tc = mem.conceptualize(e.term, now)
        old = tc.belief
        if old is not None and old.stamp == e.stamp:
            continue
        new, _ = revised_or_chosen(old, e, size)
        if new is old:
            continue
        new.creation_time = now
        tc.belief = new
        if shows(s, 1.0):
            emit(s, "Derived: " + new.line(1.0))
        note_fresh_belief(s, tc)
        on_new_belief(s, tc)


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


__all__ = ["declarative_links", "forward_eternal", "note_fresh_belief", "predict_negated"]
