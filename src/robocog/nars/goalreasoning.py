"""Declarative goal reasoning, as ONA 0.9.3 does it before a goal's decision.

ONA 0.9.2 pursues a goal only through temporal implications (``=/>``). 0.9.3 adds two
ways for eternal, declarative knowledge to pass a goal on:

- inheritance subgoaling (``declarative_inheritance_subgoaling``): a goal
  ``<X --> Y>`` and a belief sharing one of its sides, ``<Z --> X>``, ``<X --> Z>``,
  ``<Y --> Z>`` or ``<Z --> Y>`` (or the similarity), give the goal with ``Z`` in place
  of that side; with a product ``<(X * Y) --> W>`` the belief may replace ``X``, ``Y``
  or ``W`` (NAL-4). Where the belief points from the goal's term to ``Z`` the truth is
  deduction; where it points the other way, deduction with the belief's conversion;
  a similarity is read as deduction.
- implication subgoaling (``declarative_implications_subgoaling``): a goal ``g`` and
  an eternal ``<pre ==> g>`` give ``pre!`` by goal deduction from the goal event its
  concept held before; when ``pre`` has just happened (a belief event within
  ``event_belief_distance``) the goal's own event is predicted instead.

The functions compute conclusions; the reasoner (``decision.py``) queues them, so this
module holds the rules and none of the reasoner's state.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

from . import truth as tf
from .event import BELIEF, GOAL, Event
from .stamp import has_duplicate, merge, overlap
from .terms import Term, compound
from .truth import Truth
from .unify import apply, unify

INHERITANCE = "-->"
SIMILARITY = "<->"
PRODUCT = "*"


def _inh(s: Term, p: Term) -> Term:
    return compound(INHERITANCE, (s, p))


def inheritance_subgoal(goal: Term, belief: Term) -> tuple[Term, bool] | None:
    """The subgoal that ``belief`` (an inheritance or similarity) gives for ``goal`` (an
    inheritance), and whether its truth takes the belief's conversion; None if they
    share no side. ONA's cases in ONA's order: the first that applies wins, except that
    a product goal's predicate cases E and F are both tried and F wins."""
    if goal.op != INHERITANCE or belief.op not in (INHERITANCE, SIMILARITY):
        return None
    x, y = goal.args
    bs, bp = belief.args
    if x.op != PRODUCT:
        if x is bp:  # <Z --> X>: want Z to be Y
            return _inh(bs, y), True
        if x is bs:  # <X --> Z>
            return _inh(bp, y), False
        if y is bs:  # <Y --> Z>: want X to be Z
            return _inh(x, bp), False
        if y is bp:  # <Z --> Y>
            return _inh(x, bs), True
        return None
    if len(x.args) != 2:
        return None
    x1, x2 = x.args
    w = y
    found: tuple[Term, bool] | None = None
    if x1 is bp:  # A
        found = _inh(compound(PRODUCT, (bs, x2)), w), True
    elif x1 is bs:  # B
        found = _inh(compound(PRODUCT, (bp, x2)), w), False
    elif x2 is bs:  # C
        found = _inh(compound(PRODUCT, (x1, bp)), w), True
    elif x2 is bp:  # D
        found = _inh(compound(PRODUCT, (x1, bs)), w), False
    elif w is bs:  # E
        found = _inh(x, bp), True
    if w is bp:  # F (ONA tests it after E without ``else``)
        found = _inh(x, bs), False
    return found


def inheritance_subgoals(goal: Event, beliefs: Iterable[Event], stamp_size: int) -> list[Event]:
    """The subgoals of ``goal`` from each eternal belief in ``beliefs`` (ONA: the beliefs
    of the concepts sharing a name with the goal), at the goal's occurrence time."""
    out: list[Event] = []
    if goal.term.op != INHERITANCE or has_duplicate(goal.stamp):
        return out
    for b in beliefs:
        if overlap(goal.stamp, b.stamp) or has_duplicate(b.stamp):
            continue
        found = inheritance_subgoal(goal.term, b.term)
        if found is None:
            continue
        term, converted = found
        if b.term.op == SIMILARITY or not converted:
            t = tf.deduction(goal.truth, b.truth)
        else:
            t = tf.deduction(goal.truth, tf.conversion(b.truth))
        stamp = merge(b.stamp, goal.stamp, stamp_size)
        out.append(Event(term, GOAL, t, stamp, goal.occurrence_time, goal.creation_time))
    return out


def implication_subgoals(
    goal: Event,
    goal_spike: Event | None,
    links: Iterable[tuple[Term, Truth, tuple[int, ...]]],
    recent_event: Callable[[Term], Event | None],
    now: int,
    stamp_size: int,
) -> tuple[list[Event], list[Event]]:
    """(subgoals, predictions) from the eternal ``<pre ==> post>`` beliefs in ``links``
    (term, truth, stamp) whose ``post`` unifies with the goal.

    ``goal_spike`` is the goal event the goal's concept held before this goal (ONA
    deduces from it, so a goal's first selection derives nothing this way);
    ``recent_event(pre)`` is ``pre``'s belief event if it happened within the belief
    distance, else None: then the goal is predicted (belief deduction) rather than
    ``pre`` wanted."""
    goals: list[Event] = []
    predictions: list[Event] = []
    for link, truth, stamp in links:
        if link.op != "==>":
            continue
        bind = unify(link.args[1], goal.term)
        if bind is None:
            continue
        if goal_spike is not None and overlap(goal_spike.stamp, stamp):
            continue
        imp = apply(link, bind) if bind else link
        pre, post = imp.args
        spike = recent_event(pre)
        if spike is not None:
            t = tf.deduction(truth, spike.truth)
            predictions.append(
                Event(
                    post,
                    BELIEF,
                    t,
                    merge(spike.stamp, stamp, stamp_size),
                    spike.occurrence_time,
                    now,
                )
            )
            continue
        if goal_spike is None:
            continue  # ONA deduces from an empty goal event: confidence 0, dropped
        t = tf.goal_deduction(goal_spike.truth, truth)
        goals.append(Event(pre, GOAL, t, merge(goal_spike.stamp, stamp, stamp_size), now, now))
    return goals, predictions


__all__ = ["implication_subgoals", "inheritance_subgoal", "inheritance_subgoals"]
