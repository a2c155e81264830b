"""NAL 1-6 declarative rule table, term reductions and conclusion filters.

Rules are written as Narsese patterns in which single capital letters stand for any
term; a straight-line matcher of each is generated from the table into ``matchers.py``
(by ``rulegen.py``), and the table indexes the matchers by the connectors of the two
premises, so a premise pair only tries the rules that can fit it. Every two-premise
rule applies in both premise orders with the truth function's arguments following the
pattern, as in ONA's generated rule table.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from . import truth as tf
from .filters import hol_component_invalid
from .narsese import parse_pattern
from .terms import (
    CONJUNCTION,
    CONNECTORS,
    DISJUNCTION,
    EQUIVALENCE,
    EXT_IMAGE1,
    EXT_IMAGE2,
    EXT_INTERSECTION,
    EXT_SET,
    IMPLICATION,
    INHERITANCE,
    INT_IMAGE1,
    INT_IMAGE2,
    INT_INTERSECTION,
    INT_SET,
    NEGATION,
    SEQUENCE,
    SIMILARITY,
    TEMPORAL_IMPLICATION,
    Components,
    Term,
    atom,
    compound,
    substitute,
)
from .truth import Truth

TruthFn = Callable[[Truth, Truth], Truth]

#: ONA 0.9.3's row ``A, B |- (A && B)``: any two premises give their conjunction, the
#: stepping stone to transitivity (a ``==>`` whose condition is a conjunction takes it in
#: 0.9.3's declarative pass). 0.9.2's table has it for two relations only, ``<(A * B) -->
#: R>, <(B * C) --> S>``; only a table made with ``plain_conjunctions`` has the row.
PLAIN_CONJUNCTION: tuple[str, str | None, str, str, bool, int] = (
    "A",
    "B",
    "(A && B)",
    "intersection",
    False,
    6,
)

# (premise1, premise2 or None, conclusion, truth function, introduce variables, min NAL level)
RULES: list[tuple[str, str | None, str, str, bool, int]] = [
    # NAL-1 syllogisms
    ("<S --> M>", "<M --> P>", "<S --> P>", "deduction", False, 1),
    ("<A --> B>", "<A --> C>", "<C --> B>", "induction", False, 1),
    ("<A --> C>", "<B --> C>", "<B --> A>", "abduction", False, 1),
    ("<A --> B>", "<B --> C>", "<C --> A>", "exemplification", False, 1),
    # NAL-2 similarity
    ("<S <-> P>", None, "<P <-> S>", "structural_intersection", False, 2),
    ("<M <-> P>", "<S <-> M>", "<S <-> P>", "resemblance", False, 2),
    ("<P --> M>", "<S --> M>", "<S <-> P>", "comparison", False, 2),
    ("<M --> P>", "<M --> S>", "<S <-> P>", "comparison", False, 2),
    ("<M --> P>", "<S <-> M>", "<S --> P>", "analogy", False, 2),
    ("<P --> M>", "<S <-> M>", "<P --> S>", "analogy", False, 2),
    ("S", "<S <-> P>", "P", "analogy", False, 2),
    ("S", "<P <-> S>", "P", "analogy", False, 2),
    ("<S --> {P}>", None, "<S <-> {P}>", "structural_intersection", False, 2),
    ("<[S] --> P>", None, "<[S] <-> P>", "structural_intersection", False, 2),
    ("<{M} --> P>", "<S <-> M>", "<{S} --> P>", "analogy", False, 2),
    ("<P --> [M]>", "<S <-> M>", "<P --> [S]>", "analogy", False, 2),
    ("<{A} <-> {B}>", None, "<A <-> B>", "structural_intersection", False, 2),
    ("<[A] <-> [B]>", None, "<A <-> B>", "structural_intersection", False, 2),
    # NAL-3 set and intersection decomposition
    ("<{A B} --> M>", None, "<{A} --> M>", "structural_deduction", False, 3),
    ("<{A B} --> M>", None, "<{B} --> M>", "structural_deduction", False, 3),
    ("<M --> [A B]>", None, "<M --> [A]>", "structural_deduction", False, 3),
    ("<M --> [A B]>", None, "<M --> [B]>", "structural_deduction", False, 3),
    ("<(S | P) --> M>", None, "<S --> M>", "structural_deduction", False, 3),
    ("<M --> (S & P)>", None, "<M --> S>", "structural_deduction", False, 3),
    ("<(S | P) --> M>", None, "<P --> M>", "structural_deduction", False, 3),
    ("<M --> (S & P)>", None, "<M --> P>", "structural_deduction", False, 3),
    ("<(A ~ S) --> M>", None, "<A --> M>", "structural_deduction", False, 3),
    ("<M --> (B - S)>", None, "<M --> B>", "structural_deduction", False, 3),
    ("<(A ~ S) --> M>", None, "<S --> M>", "structural_deduction_negated", False, 3),
    ("<M --> (B - S)>", None, "<M --> S>", "structural_deduction_negated", False, 3),
    # NAL-3 composition
    ("<P --> M>", "<S --> M>", "<(P | S) --> M>", "intersection", False, 3),
    ("<P --> M>", "<S --> M>", "<(P & S) --> M>", "union", False, 3),
    ("<P --> M>", "<S --> M>", "<(P ~ S) --> M>", "difference", False, 3),
    ("<M --> P>", "<M --> S>", "<M --> (P & S)>", "intersection", False, 3),
    ("<M --> P>", "<M --> S>", "<M --> (P | S)>", "union", False, 3),
    ("<M --> P>", "<M --> S>", "<M --> (P - S)>", "difference", False, 3),
    # NAL-3 two-premise decomposition
    ("<S --> M>", "<(S | P) --> M>", "<P --> M>", "decompose_pnn", False, 3),
    ("<P --> M>", "<(S | P) --> M>", "<S --> M>", "decompose_pnn", False, 3),
    ("<S --> M>", "<(S & P) --> M>", "<P --> M>", "decompose_npp", False, 3),
    ("<P --> M>", "<(S & P) --> M>", "<S --> M>", "decompose_npp", False, 3),
    ("<S --> M>", "<(S ~ P) --> M>", "<P --> M>", "decompose_pnp", False, 3),
    ("<S --> M>", "<(P ~ S) --> M>", "<P --> M>", "decompose_nnn", False, 3),
    ("<M --> S>", "<M --> (S & P)>", "<M --> P>", "decompose_pnn", False, 3),
    ("<M --> P>", "<M --> (S & P)>", "<M --> S>", "decompose_pnn", False, 3),
    ("<M --> S>", "<M --> (S | P)>", "<M --> P>", "decompose_npp", False, 3),
    ("<M --> P>", "<M --> (S | P)>", "<M --> S>", "decompose_npp", False, 3),
    ("<M --> S>", "<M --> (S - P)>", "<M --> P>", "decompose_pnp", False, 3),
    ("<M --> S>", "<M --> (P - S)>", "<M --> P>", "decompose_nnn", False, 3),
    # NAL-4 relations
    ("<(A * B) --> (S * M)>", None, "<A --> S>", "structural_deduction", False, 4),
    ("<(A * B) --> (S * M)>", None, "<B --> M>", "structural_deduction", False, 4),
    ("<(A * B) --> R>", None, "<A --> (R /1 B)>", "structural_intersection", False, 4),
    ("<A --> (R /1 B)>", None, "<(A * B) --> R>", "structural_intersection", False, 4),
    ("<(A * B) --> R>", None, "<B --> (R /2 A)>", "structural_intersection", False, 4),
    ("<B --> (R /2 A)>", None, "<(A * B) --> R>", "structural_intersection", False, 4),
    ("<R --> (A * B)>", None, "<(R \\1 B) --> A>", "structural_intersection", False, 4),
    ("<(R \\1 B) --> A>", None, "<R --> (A * B)>", "structural_intersection", False, 4),
    ("<R --> (A * B)>", None, "<(R \\2 A) --> B>", "structural_intersection", False, 4),
    ("<(R \\2 A) --> B>", None, "<R --> (A * B)>", "structural_intersection", False, 4),
    ("<{R} |-> [P]>", "<{S} |-> [P]>", "<({R} * {S}) --> (+ P)>", "frequency_greater", False, 4),
    ("<(A * B) --> (+ P)>", "<(B * C) --> (+ P)>", "<(A * C) --> (+ P)>", "deduction", False, 4),
    ("<{R} |-> [P]>", "<{S} |-> [P]>", "<({R} * {S}) --> (= P)>", "frequency_equal", False, 4),
    ("<(A * B) --> (= P)>", "<(B * C) --> (= P)>", "<(A * C) --> (= P)>", "deduction", False, 4),
    ("<(A * B) --> (= P)>", None, "<(B * A) --> (= P)>", "structural_intersection", False, 4),
    ("<(A * B) --> R>", "<(C * B) --> R>", "<C --> A>", "abduction", False, 4),
    ("<(A * B) --> R>", "<(A * C) --> R>", "<C --> B>", "abduction", False, 4),
    ("<R --> (A * B)>", "<R --> (C * B)>", "<C --> A>", "induction", False, 4),
    ("<R --> (A * B)>", "<R --> (A * C)>", "<C --> B>", "induction", False, 4),
    ("<(A * B) --> R>", "<C --> A>", "<(C * B) --> R>", "deduction", False, 4),
    ("<(A * B) --> R>", "<A --> C>", "<(C * B) --> R>", "induction", False, 4),
    ("<(A * B) --> R>", "<C <-> A>", "<(C * B) --> R>", "analogy", False, 4),
    ("<(A * B) --> R>", "<C --> B>", "<(A * C) --> R>", "deduction", False, 4),
    ("<(A * B) --> R>", "<B --> C>", "<(A * C) --> R>", "induction", False, 4),
    ("<(A * B) --> R>", "<C <-> B>", "<(A * C) --> R>", "analogy", False, 4),
    ("<R --> (A * B)>", "<A --> C>", "<R --> (C * B)>", "deduction", False, 4),
    ("<R --> (A * B)>", "<C --> A>", "<R --> (C * B)>", "abduction", False, 4),
    ("<R --> (A * B)>", "<C <-> A>", "<R --> (C * B)>", "analogy", False, 4),
    ("<R --> (A * B)>", "<B --> C>", "<R --> (A * C)>", "deduction", False, 4),
    ("<R --> (A * B)>", "<C --> B>", "<R --> (A * C)>", "abduction", False, 4),
    ("<R --> (A * B)>", "<C <-> B>", "<R --> (A * C)>", "analogy", False, 4),
    ("<(A * B) --> R>", "<(C * B) --> R>", "<A <-> C>", "comparison", False, 4),
    ("<(A * B) --> R>", "<(A * C) --> R>", "<B <-> C>", "comparison", False, 4),
    ("<R --> (A * B)>", "<R --> (C * B)>", "<A <-> C>", "comparison", False, 4),
    ("<R --> (A * B)>", "<R --> (A * C)>", "<B <-> C>", "comparison", False, 4),
    # NAL-5 negation, conjunction, disjunction
    ("(! A)", None, "A", "negation", False, 5),
    ("(A && B)", None, "A", "structural_deduction", False, 5),
    ("(A && B)", None, "B", "structural_deduction", False, 5),
    ("(A && B)", None, "(B && A)", "structural_intersection", False, 5),
    ("S", "(S && A)", "A", "decompose_pnn", False, 5),
    ("S", "(S || A)", "A", "decompose_npp", False, 5),
    ("S", "((! S) && A)", "A", "decompose_nnn", False, 5),
    ("S", "((! S) || A)", "A", "decompose_ppp", False, 5),
    # NAL-5 implication syllogisms
    ("<S ==> M>", "<M ==> P>", "<S ==> P>", "deduction", False, 5),
    ("<A ==> B>", "<A ==> C>", "<C ==> B>", "induction", False, 5),
    ("<A ==> C>", "<B ==> C>", "<B ==> A>", "abduction", False, 5),
    ("<A ==> B>", "<B ==> C>", "<C ==> A>", "exemplification", False, 5),
    ("<A ==> C>", "<B ==> C>", "<(A && B) ==> C>", "union", False, 5),
    ("<A ==> C>", "<B ==> C>", "<(A || B) ==> C>", "intersection", False, 5),
    ("<C ==> A>", "<C ==> B>", "<C ==> (A && B)>", "intersection", False, 5),
    ("<C ==> A>", "<C ==> B>", "<C ==> (A || B)>", "union", False, 5),
    ("<(S && P) ==> M>", "<S ==> M>", "P", "abduction", False, 5),
    ("<(C && M) ==> P>", "<S ==> M>", "<(C && S) ==> P>", "deduction", False, 5),
    ("<(C && P) ==> M>", "<(C && S) ==> M>", "<S ==> P>", "abduction", False, 5),
    ("<(C && M) ==> P>", "<M ==> S>", "<(C && S) ==> P>", "induction", False, 5),
    # NAL-5 equivalence
    ("<S <=> P>", None, "<P <=> S>", "structural_intersection", False, 5),
    ("<S ==> P>", "<P ==> S>", "<S <=> P>", "intersection", False, 5),
    ("<P ==> M>", "<S ==> M>", "<S <=> P>", "comparison", False, 5),
    ("<M ==> P>", "<M ==> S>", "<S <=> P>", "comparison", False, 5),
    ("<M ==> P>", "<S <=> M>", "<S ==> P>", "analogy", False, 5),
    ("<P ==> M>", "<S <=> M>", "<P ==> S>", "analogy", False, 5),
    ("<M <=> P>", "<S <=> M>", "<S <=> P>", "resemblance", False, 5),
    ("<M <=> P>", None, "<M ==> P>", "structural_deduction", False, 5),
    ("<M <=> P>", None, "<P ==> M>", "structural_deduction", False, 5),
    # NAL-6 variable introduction
    ("<C --> A>", "<C --> B>", "<<C --> B> ==> <C --> A>>", "induction", True, 6),
    ("<A --> C>", "<B --> C>", "<<B --> C> ==> <A --> C>>", "induction", True, 6),
    ("<C --> A>", "<C --> B>", "<<C --> B> <=> <C --> A>>", "comparison", True, 6),
    ("<A --> C>", "<B --> C>", "<<B --> C> <=> <A --> C>>", "comparison", True, 6),
    ("(! <C --> A>)", "<C --> B>", "<<C --> B> ==> (! <C --> A>)>", "induction", True, 6),
    ("(! <A --> C>)", "<B --> C>", "<<B --> C> ==> (! <A --> C>)>", "induction", True, 6),
    ("(! <C --> A>)", "<C --> B>", "<<C --> B> <=> (! <C --> A>)>", "comparison", True, 6),
    ("(! <A --> C>)", "<B --> C>", "<<B --> C> <=> (! <A --> C>)>", "comparison", True, 6),
    ("<C --> A>", "(! <C --> B>)", "<(! <C --> B>) ==> <C --> A>>", "induction", True, 6),
    ("<A --> C>", "(! <B --> C>)", "<(! <B --> C>) ==> <A --> C>>", "induction", True, 6),
    ("<C --> A>", "(! <C --> B>)", "<(! <C --> B>) <=> <C --> A>>", "comparison", True, 6),
    ("<A --> C>", "(! <B --> C>)", "<(! <B --> C>) <=> <A --> C>>", "comparison", True, 6),
    ("<C --> A>", "<C --> B>", "(<C --> B> && <C --> A>)", "intersection", True, 6),
    ("<A --> C>", "<B --> C>", "(<B --> C> && <A --> C>)", "intersection", True, 6),
    ("(! <C --> A>)", "<C --> B>", "(<C --> B> && (! <C --> A>))", "intersection", True, 6),
    ("(! <A --> C>)", "<B --> C>", "(<B --> C> && (! <A --> C>))", "intersection", True, 6),
    ("<C --> A>", "(! <C --> B>)", "((! <C --> B>) && <C --> A>)", "intersection", True, 6),
    ("<A --> C>", "(! <B --> C>)", "((! <B --> C>) && <A --> C>)", "intersection", True, 6),
    (
        "<(A * B) --> R>",
        "<(B * A) --> S>",
        "<<(B * A) --> S> ==> <(A * B) --> R>>",
        "induction",
        True,
        6,
    ),
    (
        "(! <(B * A) --> R>)",
        "<(A * B) --> S>",
        "<<(A * B) --> S> ==> (! <(B * A) --> R>)>",
        "induction",
        True,
        6,
    ),
    (
        "<(B * A) --> R>",
        "(! <(A * B) --> S>)",
        "<(! <(A * B) --> S>) ==> <(B * A) --> R>>",
        "induction",
        True,
        6,
    ),
    PLAIN_CONJUNCTION,
    (
        "<(A * C) --> M>",
        "(<(A * B) --> R> && <(B * C) --> S>)",
        "<(<(A * B) --> R> && <(B * C) --> S>) ==> <(A * C) --> M>>",
        "induction",
        True,
        6,
    ),
]


def is_pattern_variable(t: Term) -> bool:
    """Single capital letters are pattern variables in the rule table."""
    return t.op is None and len(t.name) == 1 and t.name.isupper()  # type: ignore[arg-type]


def match(p: Term, t: Term, b: dict[Term, Term]) -> bool:
    """Structural match of pattern ``p`` against ``t``, extending bindings ``b``."""
    if p.op is None:
        if is_pattern_variable(p):
            got = b.get(p)
            if got is None:
                b[p] = t
                return True
            return got is t
        return p is t
    if p.op != t.op or len(p.args) != len(t.args):
        return False
    return all(match(pa, ta, b) for pa, ta in zip(p.args, t.args, strict=True))


def make(op: str, args: Components) -> Term:
    """Build a compound applying ONA's term reductions."""
    # the connector's one object (a matcher passes its own string), so that it can be
    # told by identity (see ``terms.CONNECTORS``)
    connectors: dict = CONNECTORS  # (typed: the compiled ``get`` is the dict's own)
    op = connectors.get(op, op)
    if len(args) == 2:
        a, b = args
        if a is b and (
            op is EXT_INTERSECTION
            or op is INT_INTERSECTION
            or op is CONJUNCTION
            or op is DISJUNCTION
        ):
            return a
        if op is INT_INTERSECTION and a.op is EXT_SET and b.op is EXT_SET:
            return make(EXT_SET, a.args + b.args)
        if op is EXT_INTERSECTION and a.op is INT_SET and b.op is INT_SET:
            return make(INT_SET, a.args + b.args)
    if op is EXT_SET or op is INT_SET:
        seen: list[Term] = []
        for a in args:
            if a not in seen:
                seen.append(a)
        args = tuple(seen)
    return compound(op, args)


#: connectors whose terms ``make`` may reduce; every other one is a plain ``compound``
REDUCED_OPS = frozenset(
    {EXT_INTERSECTION, INT_INTERSECTION, CONJUNCTION, DISJUNCTION, EXT_SET, INT_SET}
)


def build(p: Term, b: dict[Term, Term]) -> Term:
    """Instantiate conclusion pattern ``p`` with bindings ``b`` (reducing as it goes)."""
    if p.op is None:
        return b.get(p, p)
    return make(p.op, tuple(build(a, b) for a in p.args))


#: where a matcher hands its conclusion: ``emit(term, truth, introduce_variables)``
Emit = Callable[[Term, Truth, bool], None]
#: a rule's matcher: ``matcher(t1, t2, v1, v2, emit)`` (``t2``, ``v2`` repeat the
#: premise for a single-premise rule)
Matcher = Callable[[Term, Term, Truth, Truth, Emit], None]


#: one conclusion of a premise pair: its term, the truth function, whether that takes
#: the premises' truths in the opposite order, whether variables are to be introduced
Conclusion = tuple[Term, TruthFn, bool, bool]
#: how many premise pairs (and single premises) a rule table remembers the conclusions of,
#: at most and at least (see ``RuleTable.conclusions``): the least holds the pairs a
#: robot's loop meets again (some thousands in a mission), since a table that remembers
#: fewer pairs than come back meets none of them again and would never grow
REMEMBERED_PAIRS = 1 << 15
REMEMBERED_PAIRS_LEAST = 1 << 12
#: the truth the matchers are given while their conclusions are only recorded
_SOME_TRUTH = Truth(1.0, 0.9)


def _record(rules: list[Rule], t1: Term, t2: Term, swapped: bool, into: list[Conclusion]) -> None:
    """Run ``rules`` on the premises ``t1`` and ``t2`` and record their conclusions into
    ``into``, each with its rule's truth function; one ``emit`` serves every rule (a
    new pair of premises meets several rules, and an ``emit`` is a closure to make)."""
    got: list[tuple[Term, bool]] = []

    def record(term: Term, _t: Truth, var_intro: bool) -> None:
        got.append((term, var_intro))

    for r in rules:
        r.apply(t1, t2, _SOME_TRUTH, _SOME_TRUTH, record)  # type: ignore[misc]
        if got:
            for term, var_intro in got:
                into.append((term, r.truth, swapped, var_intro))
            got.clear()


@dataclass(slots=True)
class Rule:
    """One rule of the table; ``apply(t1, t2, v1, v2, emit)`` matches and emits."""

    p1: Term
    p2: Term | None
    conclusion: Term
    truth: TruthFn
    var_intro: bool
    level: int
    name: str
    apply: Matcher | None = None


def _next_limit(limit: int, hits: int) -> int:
    """How many premise pairs to remember after ``limit`` of them met ``hits`` again."""
    if hits < limit // 16:
        return max(REMEMBERED_PAIRS_LEAST, limit // 2)
    if hits > limit // 2:
        return min(REMEMBERED_PAIRS, limit * 2)
    return limit


def _root(p: Term) -> str:
    return "*any*" if is_pattern_variable(p) else (p.op or "*atom*")


class RuleTable:
    """Compiled rules, indexed by premise connectors.

    Compiled, an extension type (rules.pxd): every premise pair asks it for its
    conclusions, so its fields are read as C struct members and its methods called in C.
    """

    def __init__(
        self, level: int, matchers: Sequence[Matcher], plain_conjunctions: bool = False
    ) -> None:
        """The rules of NAL ``level`` and below, each with its matcher from
        ``matchers`` (one per row of the table, in order: ``matchers.MATCHERS``);
        :data:`PLAIN_CONJUNCTION` only with ``plain_conjunctions``."""
        self.single: dict[str, list[Rule]] = {}
        self.double: dict[tuple[str, str], list[Rule]] = {}
        self._cache: dict[tuple[str | None, str | None], list[Rule]] = {}
        self._single_cache: dict[str | None, list[Rule]] = {}
        self._shape_cache: dict[tuple[object, ...], list[Rule]] = {}
        # what the rules conclude from a premise (pair), see ``conclusions``
        self._pairs: dict[tuple[Term, Term], tuple[Conclusion, ...]] = {}
        self._pairs_limit = REMEMBERED_PAIRS
        self._pair_hits = 0  # since the pairs were last cleared
        self._singles: dict[Term, tuple[Conclusion, ...]] = {}
        if len(matchers) != len(RULES):
            raise ValueError(f"{len(matchers)} matchers for {len(RULES)} rules")
        for row, matcher in zip(RULES, matchers, strict=True):
            p1, p2, c, fn, vi, lvl = row
            if lvl > level or (row is PLAIN_CONJUNCTION and not plain_conjunctions):
                continue
            r = Rule(
                parse_pattern(p1),
                parse_pattern(p2) if p2 else None,
                parse_pattern(c),
                getattr(tf, fn),
                vi,
                lvl,
                fn,
            )
            r.apply = matcher
            if r.p2 is None:
                self.single.setdefault(_root(r.p1), []).append(r)
            else:
                self.double.setdefault((_root(r.p1), _root(r.p2)), []).append(r)

    def conclusions(self, t1: Term, t2: Term) -> tuple[Conclusion, ...]:
        """What the two-premise rules conclude from ``t1`` and ``t2`` in both orders,
        in the order the rules apply: each conclusion with how its truth is had from
        the premises' (:data:`Conclusion`).

        The conclusions are a function of the two (interned) terms alone, and a robot's
        premise pairs meet again at nearly every step, so they are remembered (up to
        :data:`REMEMBERED_PAIRS` pairs, then afresh): a pair met again costs one look-up
        instead of its rules' matching and the building of their conclusions. A stream
        of ever new statements (a taxonomy read in) meets no pair twice; remembered,
        their conclusions are tens of megabytes that keep their terms alive and crowd
        the cache. So when the pairs are full and few were met again since the last
        time, the next round remembers half as many (down to
        :data:`REMEMBERED_PAIRS_LEAST`), and twice as many when most were.
        """
        key = (t1, t2)
        pairs: dict = self._pairs  # (typed, the compiled look-up is the dict's own)
        got = pairs.get(key)
        if got is None:
            found: list[Conclusion] = []
            _record(self.candidates(t1, t2), t1, t2, False, found)
            _record(self.candidates(t2, t1), t2, t1, True, found)
            got = tuple(found)
            if len(pairs) >= self._pairs_limit:
                self._pairs_limit = _next_limit(self._pairs_limit, self._pair_hits)
                self._pair_hits = 0
                pairs.clear()
            pairs[key] = got
        else:
            self._pair_hits += 1
        return got

    @property
    def pairs_limit(self) -> int:
        """How many premise pairs the table remembers the conclusions of, as of now."""
        return self._pairs_limit

    def single_conclusions(self, t: Term) -> tuple[Conclusion, ...]:
        """What the single-premise rules conclude from ``t`` (as ``conclusions``, the
        truth function taking the premise's truth twice), remembered alike."""
        got = self._singles.get(t)
        if got is None:
            found: list[Conclusion] = []
            _record(self.single_rules(t.op), t, t, False, found)
            got = tuple(found)
            if len(self._singles) >= REMEMBERED_PAIRS:
                self._singles.clear()
            self._singles[t] = got
        return got

    def single_rules(self, op: str | None) -> list[Rule]:
        """Single-premise rules whose premise can have connector ``op``."""
        got = self._single_cache.get(op)
        if got is None:
            key = op or "*atom*"
            got = self.single.get(key, []) + self.single.get("*any*", [])
            self._single_cache[op] = got
        return got

    def candidates(self, t1: Term, t2: Term) -> list[Rule]:
        """The rules that can match this premise pair, judged by the connectors of the
        premises and of their two components and by which components are identical;
        the (few) survivors run the full matcher. Cached per such shape."""
        a1 = t1.args
        a2 = t2.args
        if len(a1) != 2 or len(a2) != 2:
            return self.double_rules(t1.op, t2.op)
        x0: Term = a1[0]
        x1: Term = a1[1]
        y0: Term = a2[0]
        y1: Term = a2[1]
        key = (
            t1.op,
            t2.op,
            x0.op,
            x1.op,
            y0.op,
            y1.op,
            (x0 is x1)
            | (x0 is y0) << 1
            | (x0 is y1) << 2
            | (x1 is y0) << 3
            | (x1 is y1) << 4
            | (y0 is y1) << 5,
        )
        shapes: dict = self._shape_cache
        got = shapes.get(key)
        if got is None:
            got = [r for r in self.double_rules(t1.op, t2.op) if _fits(r, key)]
            shapes[key] = got
        return got

    def double_rules(self, op1: str | None, op2: str | None) -> list[Rule]:
        """Two-premise rules whose premises can have connectors ``op1``, ``op2``."""
        got = self._cache.get((op1, op2))
        if got is None:
            k1 = op1 or "*atom*"
            k2 = op2 or "*atom*"
            got = []
            for a in (k1, "*any*"):
                for c in (k2, "*any*"):
                    got.extend(self.double.get((a, c), []))
            self._cache[(op1, op2)] = got
        return got


_PAIRS = ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3))
#: a premise pair's shape, as ``RuleTable.candidates`` keys it (an alias the compiled
#: engine reads as a plain tuple)
Shape = tuple[object, ...]


def _fits(r: Rule, key: Shape) -> bool:
    """Could rule ``r`` match a premise pair of shape ``key`` (see ``candidates``)?"""
    comps: list[Term | None] = []
    for p, k in ((r.p1, 0), (r.p2, 1)):
        if p is None or is_pattern_variable(p):
            comps += [None, None]
            continue
        if p.op != key[k] or len(p.args) != 2:
            return False
        for i, a in enumerate(p.args):
            if not is_pattern_variable(a) and a.op != key[2 + 2 * k + i]:
                return False
            comps.append(a)
    eq = key[6]
    for bit, (i, j) in enumerate(_PAIRS):
        a, b = comps[i], comps[j]
        if a is not None and b is not None and a is b and is_pattern_variable(a):
            if not eq >> bit & 1:  # type: ignore[operator]
                return False
    return True


# ---------------------------------------------------------------- variable introduction
#: how often each name occurs (an alias the compiled engine reads as a plain dict)
Counts = dict[Term, int]


def _count_statement_atoms(
    t: Term, counts: Counts, extensional: bool, ignore_structure: bool, spatial: bool
) -> None:
    # (connectors by identity: see ``terms.CONNECTORS``)
    op = t.op
    if op is INHERITANCE or op is SIMILARITY:
        sim = op is SIMILARITY
        s, p = t.args
        s_image = s.op is INT_IMAGE1 or s.op is INT_IMAGE2
        p_image = p.op is EXT_IMAGE1 or p.op is EXT_IMAGE2
        if extensional or sim:
            if s_image:
                _count_statement_atoms(s.args[0], counts, extensional, True, spatial)
            else:
                _count_statement_atoms(s, counts, extensional, True, spatial)
            if p_image:
                _count_statement_atoms(p.args[1], counts, extensional, True, spatial)
        if not extensional or sim:
            if p_image:
                _count_statement_atoms(p.args[0], counts, extensional, True, spatial)
            else:
                _count_statement_atoms(p, counts, extensional, True, spatial)
            if s_image:
                _count_statement_atoms(s.args[1], counts, extensional, True, spatial)
    if ignore_structure or spatial:
        if (op is EXT_SET or op is INT_SET) and len(t.args) > 1 and not spatial:
            return
        for a in t.atoms():
            if not a.is_var:
                counts[a] = counts.get(a, 0) + 1


def _count_hol(t: Term, counts: Counts, extensional: bool) -> None:
    op = t.op
    if op is NEGATION:
        _count_hol(t.args[0], counts, extensional)
        return
    if (
        op is SEQUENCE
        or op is CONJUNCTION
        or op is TEMPORAL_IMPLICATION
        or op is IMPLICATION
        or op is EQUIVALENCE
    ):
        ext = extensional or op is SEQUENCE
        _count_hol(t.args[0], counts, ext)
        _count_hol(t.args[1], counts, ext)
        return
    _count_statement_atoms(t, counts, extensional, False, op is INT_SET)


def _hol_counts(t: Term, extensional: bool) -> Counts:
    """``_count_hol`` of one implication side, kept on the term (callers must not mutate)."""
    got = t.hol
    if got is None:
        got = t.hol = [None, None]
    i = 1 if extensional else 0
    counts = got[i]
    if counts is None:
        counts = got[i] = {}
        _count_hol(t, counts, extensional)
    return counts


def _first_free(t: Term, prefix: str) -> int:
    if not t.has_var:
        return 1
    used = {a.name for a in t.atoms() if a.is_var and a.name[0] == prefix}  # type: ignore[index]
    i = 1
    while f"{prefix}{i}" in used:
        i += 1
    return i


#: ``$1``..``$9`` and ``#1``..``#9`` (index 0 unused), held here so they stay interned
_IND_VARS = (None, *(atom(f"${i}") for i in range(1, 10)))
_DEP_VARS = (None, *(atom(f"#{i}") for i in range(1, 10)))


def introduce_implication_variables(t: Term, extensional: bool) -> Term | None:
    """ONA's variable introduction for ``==>``/``<=>``/``=/>`` conclusions."""
    cl = _hol_counts(t.args[0], extensional)
    cr = _hol_counts(t.args[1], extensional)
    if not _shared_or_twice(cl, cr):
        return None  # no name to abstract (half of all calls end here)
    dep = ind = 1
    if t.has_var:  # the first free numbers are 1 unless some variable is there already
        dep = _first_free(t, "#")
        ind = _first_free(t, "$")
    mapping: dict[Term, Term] = {}
    for a in t.level_order_atoms():
        if a in mapping:
            continue
        vl = cl.get(a)
        vr = cr.get(a)
        if (vl is not None and vl >= 2) or (vr is not None and vr >= 2) or (vl and vr):
            if vl and vr:
                if ind > 9:
                    continue
                mapping[a] = _IND_VARS[ind]
                ind += 1
            else:
                if dep > 9:
                    continue
                mapping[a] = _DEP_VARS[dep]
                dep += 1
    if not mapping:
        return None
    return substitute(t, mapping)


def _shared_or_twice(cl: Counts, cr: Counts) -> bool:
    """True if some name of the counts ``cl`` and ``cr`` occurs on both sides or twice
    on one (loops over the dicts rather than calls to their methods: the compiled
    engine runs them in C, once per new conclusion)."""
    for a, v in cl.items():
        if v >= 2 or a in cr:
            return True
    return _twice(cr)


def _twice(counts: Counts) -> bool:
    """True if some name of ``counts`` occurs twice (a loop, as ``_shared_or_twice``)."""
    for v in counts.values():
        if v >= 2:
            return True
    return False


def introduce_conjunction_variables(t: Term, extensional: bool) -> Term | None:
    """ONA's dependent-variable introduction for ``&&`` conclusions."""
    if t.op is CONJUNCTION:  # the counts of ``&&`` are those of its sides, added
        counts = dict(_hol_counts(t.args[0], extensional))
        for a, v in _hol_counts(t.args[1], extensional).items():
            counts[a] = counts.get(a, 0) + v
    else:
        counts = {}
        _count_hol(t, counts, extensional)
    if not _twice(counts):
        return None  # no name occurs twice (half of all calls end here)
    dep = _first_free(t, "#")
    mapping: dict[Term, Term] = {}
    for a in t.level_order_atoms():
        if a in mapping:
            continue
        if counts.get(a, 0) >= 2 and dep <= 9:
            mapping[a] = _DEP_VARS[dep]
            dep += 1
    if not mapping:
        return None
    return substitute(t, mapping)


def variable_forms(t: Term) -> tuple[Term, ...]:
    """The conclusions a rule that introduces variables derives from its conclusion
    ``t``: for ``==>``/``<=>``/``=/>`` and ``&&`` the forms with variables introduced
    (extensionally, then intensionally) that pass the component filter, a ``==>`` or
    ``<=>`` only with an independent variable; any other term itself.

    A function of the term alone, kept on it: the same premise pairs meet at nearly
    every step, so the same conclusions come back. A term whose only form is itself
    keeps a marker instead, since a term holding itself is never swept from the
    interning table.
    """
    got = t.forms
    if got is None:
        got = _variable_forms(t)
        t.forms = _ITSELF if len(got) == 1 and got[0] is t else got
    elif got is _ITSELF:
        return (t,)
    return got


#: kept on a term whose only variable form is itself (see ``variable_forms``); a
#: tuple no form list can be, as ``()`` is one object in CPython
_ITSELF: tuple[object, ...] = (object(),)


def _variable_forms(t: Term) -> tuple[Term, ...]:
    op = t.op
    found: list[Term] = []
    # (connectors by identity: see ``terms.CONNECTORS``)
    if op is IMPLICATION or op is EQUIVALENCE or op is TEMPORAL_IMPLICATION:
        for ext in (True, False):
            v = introduce_implication_variables(t, ext)
            if v is not None and v is not t and not hol_component_invalid(v):
                if (v.op is IMPLICATION or v.op is EQUIVALENCE) and not v.has_indep_var:
                    continue
                found.append(v)
        return tuple(found)
    if op is CONJUNCTION:
        for ext in (True, False):
            v = introduce_conjunction_variables(t, ext)
            if v is not None and v is not t and not hol_component_invalid(v):
                found.append(v)
        return tuple(found)
    return (t,)
