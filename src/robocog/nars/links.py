"""Declarative links in time: events that just happened travel forward through
``==>`` and ``<=>`` beliefs (ONA's Cycle_ProcessBeliefEvents, the part for declarative
implications).

Functions over a :class:`~robocog.nars.state.Reasoner`. An eternal ``==>``/``<=>``
belief is indexed by its condition (``sensorimotor.note_link``); at every cycle, each
concept of the occurrence-time index whose event is fresh meets the links whose
condition it instantiates, and the consequence gets a belief event at the same time
(:func:`forward_links`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from . import truth as tf
from .event import BELIEF, Event
from .sensorimotor import note_event
from .stamp import merge, overlap
from .state import Reasoner, remember
from .terms import Term
from .unify import apply, may_unify, unify

if TYPE_CHECKING:
    from .memory import Concept

#: entries a remembered-results dict holds before it starts afresh
_CACHE_SIZE = 1024

#: "not yet known": a consequence not yet worked out
_UNKNOWN = object()


def forward_links(s: Reasoner) -> None:
    """Events that just happened travel forward through ``==>``/``<=>`` beliefs:
    the consequence gets a belief event at the same time (deduction / analogy)."""
    cfg = s.config
    now = s.time
    mem = s.memory
    if not s.links_by_subject and not s.general_links:
        return
    tolerance = cfg.belief_last_used_tolerance
    c: Concept
    lc: Concept | None
    tcon: Concept
    spike: Event
    old: Event | None
    link: Term
    a: Term
    b: Term
    cond: Term
    concl: Term
    term: Term
    target: Term
    # (a loop rather than a comprehension, so that the compiled engine reads ``c``
    # and ``last`` as declared; and the age test against a float, a C double when
    # compiled, exact for any cycle count below 2**53, so the index's 512 entries
    # are tested without making an integer each)
    oldest: float = now - tolerance
    last: Event | None
    fresh: list[Concept] = []
    for c in s.time_index:
        last = c.belief_spike
        if last is not None and last.creation_time >= oldest and not c.term.has_var:
            fresh.append(c)
    limit = cfg.top_k_declarative_implications * 4
    # (mem.find, read from the dict: it runs for every link at every cycle)
    concepts: dict[Term, Concept] = mem.concepts
    consequences = s.consequences
    found: object
    known: dict
    for c in fresh:
        spike = c.belief_spike
        term = c.term
        links = list(s.links_by_subject.get(term, ()))
        for g in s.general_links:
            links.append(g)
        if len(links) > limit:
            del links[limit:]
        for link in links:
            lc = concepts.get(link)
            if lc is None or lc.belief is None:
                s.links_by_subject.get(term, {}).pop(link, None)
                continue
            a, b = link.args
            # the consequence of each side is a function of the link and the term:
            # the same concept meets the same link at every cycle while its event
            # is fresh, so it is kept, per link and side
            sides = consequences.get(link)
            if sides is None:
                sides = remember(consequences, link, ({}, {}), 256)
            # (each side of ``<=>`` in turn, chosen without building pairs of sides)
            for side in range(2 if link.op == "<=>" else 1):
                if side == 0:
                    cond = a
                    concl = b
                else:
                    cond = b
                    concl = a
                if not may_unify(cond, term):
                    continue  # what unify would say first, without the call
                known = sides[side]
                found = known.get(term, _UNKNOWN)
                if found is _UNKNOWN:
                    bind = unify(cond, term)
                    consequence = None if bind is None else apply(concl, bind)
                    found = remember(known, term, consequence, _CACHE_SIZE)
                if found is None:
                    continue
                target = found
                if target.has_var or overlap(spike.stamp, lc.belief.stamp):
                    continue
                fn = tf.deduction if link.op == "==>" else tf.analogy
                t = fn(lc.belief.truth, spike.truth)
                if t.c < cfg.min_confidence:
                    continue
                tcon = mem.conceptualize(target, now)
                old = tcon.belief_spike
                if old is not None and (
                    old.occurrence_time > spike.occurrence_time
                    or (old.occurrence_time == spike.occurrence_time and old.truth.c >= t.c)
                ):
                    continue
                tcon.belief_spike = Event(
                    target,
                    BELIEF,
                    t,
                    merge(spike.stamp, lc.belief.stamp, cfg.stamp_size),
                    spike.occurrence_time,
                    now,
                )
                note_event(s, tcon)
