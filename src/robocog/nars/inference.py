"""Declarative (NAL 1-6) inference on one selected event and one concept's belief.

The rule table does the syllogisms; the special inferences add what structural
matching cannot: detachment through ``==>``/``<=>`` and conjunction elimination with
unification, which is how ``<<$1 --> penguin> ==> ...>`` meets ``<pingu --> penguin>``.
"""

from __future__ import annotations

try:
    import cython
except ImportError:  # the pure engine runs without Cython
    from . import cy as cython

from . import truth as tf
from .matchers import MATCHERS
from .memorize import add_derived
from .rules import RuleTable, variable_forms
from .stamp import Stamp
from .state import Reasoner
from .terms import CONJUNCTION, EQUIVALENCE, IMPLICATION, Term, compound
from .truth import Truth
from .unify import apply, unify

_RULE_TABLES: dict[tuple[int, bool], RuleTable] = {}


def rule_table(level: int, plain_conjunctions: bool = False) -> RuleTable:
    """The rule table of NAL level ``level``, with ONA 0.9.3's ``A, B |- (A && B)``
    when ``plain_conjunctions`` (built once, then shared)."""
    key = (level, plain_conjunctions)
    t = _RULE_TABLES.get(key)
    if t is None:
        t = _RULE_TABLES[key] = RuleTable(level, MATCHERS, plain_conjunctions)
    return t


@cython.freelist(64)
@cython.cclass
class Derivation:
    """Where the conclusions of one premise pair go (the reasoner whose memory takes
    them, :func:`~robocog.nars.memorize.add_derived`), with their shared context."""

    __slots__ = ("state", "occurrence", "stamp", "parent_priority", "concept_priority")

    def __init__(
        self,
        state: Reasoner,
        occurrence: int,
        stamp: Stamp,
        parent_priority: float,
        concept_priority: float,
    ) -> None:
        self.state = state
        self.occurrence = occurrence
        self.stamp = stamp
        self.parent_priority = parent_priority
        self.concept_priority = concept_priority

    def emit(self, term: Term, t: Truth, var_intro: bool = False) -> None:
        """Hand one conclusion to memory, introducing variables where the rule asks."""
        # the premises' priorities times the conclusion's truth expectation, computed
        # once for a conclusion and its variable-introduced forms alike
        priority = self.concept_priority * self.parent_priority * (t.c * (t.f - 0.5) + 0.5)
        if not var_intro:  # the common case
            add_derived(self.state, term, t, self.stamp, self.occurrence, priority)
            return
        v: Term
        for v in variable_forms(term):
            add_derived(self.state, v, t, self.stamp, self.occurrence, priority)


def apply_single(table: RuleTable, term: Term, t: Truth, d: Derivation) -> None:
    """Single-premise rules on ``term``."""
    c: Term
    for c, fn, _swapped, var_intro in table.single_conclusions(term):
        d.emit(c, fn(t, t), var_intro)


def apply_double(table: RuleTable, t1: Term, t2: Term, v1: Truth, v2: Truth, d: Derivation) -> None:
    """Two-premise rules in both premise orders (truth arguments follow the pattern)."""
    c: Term
    for c, fn, swapped, var_intro in table.conclusions(t1, t2):
        d.emit(c, fn(v2, v1) if swapped else fn(v1, v2), var_intro)


def special(term1: Term, term2: Term, v1: Truth, v2: Truth, d: Derivation) -> None:
    """Detachment and elimination through implications and conjunctions, with unification."""
    op = term2.op
    # (connectors by identity: see ``terms.CONNECTORS``)
    if op is IMPLICATION or op is EQUIVALENCE:
        is_impl = op is IMPLICATION
        subj, pred = term2.args
        s = unify(subj, term1)
        if s is not None:
            c = apply(pred, s)
            d.emit(c, tf.deduction(v2, v1) if is_impl else tf.analogy(v2, v1))
        if is_impl and subj.op is CONJUNCTION:
            first, rest = subj.args
            s = unify(first, term1)
            if s is None:
                first, rest = rest, first
                s = unify(first, term1)
            if s is not None:
                c = apply(compound(IMPLICATION, (rest, pred)), s)
                d.emit(c, tf.deduction(v2, v1))
        s = unify(pred, term1)
        if s is not None:
            c = apply(subj, s)
            d.emit(c, tf.abduction(v2, v1) if is_impl else tf.analogy(v2, v1))
    elif op is CONJUNCTION:
        subj, pred = term2.args
        s = unify(subj, term1)
        if s is not None:
            d.emit(apply(pred, s), tf.anonymous_analogy(v2, v1))
