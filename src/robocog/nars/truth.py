"""NAL truth values and truth functions, as ONA computes them.

A truth value is (frequency, confidence). Evidence weight w and confidence c are related
by c = w / (w + k) with evidential horizon k = 1. Each function here is the one ONA uses
for the rule of the same name, so derived values agree with ONA to the printed digits.
"""

from __future__ import annotations

try:
    import cython
except ImportError:  # the pure engine runs without Cython
    from . import cy as cython


from collections.abc import Iterator

HORIZON = 1.0
MAX_CONFIDENCE = 0.99
PROJECTION_DECAY = 0.8
#: the constants as the functions below read them: compiled, these are C doubles
#: (``truth.pxd``), while the public names above stay readable from Python
_K = HORIZON
_MAX_C = MAX_CONFIDENCE
_DECAY = PROJECTION_DECAY

#: a time, counted in reasoning cycles (the compiled engine declares it a C long)
Cycle = int


@cython.freelist(64)
@cython.cclass
class Truth:
    """Frequency ``f`` and confidence ``c``, both in [0, 1]; never changed once made.

    A plain class with two slots rather than a tuple: compiled, it is an extension type
    whose fields are C doubles (``truth.pxd``), read without an attribute lookup.
    """

    __slots__ = ("f", "c")

    def __init__(self, f: float, c: float) -> None:
        self.f = f
        self.c = c

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Truth):
            return NotImplemented
        return self.f == other.f and self.c == other.c

    def __hash__(self) -> int:
        return hash((self.f, self.c))

    def __iter__(self) -> Iterator[float]:
        """``f, c = truth``."""
        return iter((self.f, self.c))

    def __reduce__(self) -> tuple[type, tuple[float, float]]:
        return (Truth, (self.f, self.c))

    def __repr__(self) -> str:
        return f"Truth(f={self.f!r}, c={self.c!r})"

    def __str__(self) -> str:
        return f"Truth: frequency={self.f:f}, confidence={self.c:f}"


def truth_of(f: float, c: float) -> Truth:
    """``Truth(f, c)`` without the keyword-capable constructor call (millions are made)."""
    t: Truth = Truth.__new__(Truth)
    t.f = f
    t.c = c
    return t


DEFAULT = Truth(1.0, 0.9)
STRUCTURAL = Truth(1.0, 0.9)


def w2c(w: float) -> float:
    """Confidence of evidence weight ``w``."""
    return w / (w + _K)


def c2w(c: float) -> float:
    """Evidence weight of confidence ``c``."""
    return _K * c / (1.0 - c)


def _or(a: float, b: float) -> float:
    return 1.0 - (1.0 - a) * (1.0 - b)


def expectation(t: Truth) -> float:
    """How much a truth value speaks for the statement: c(f - 1/2) + 1/2."""
    return t.c * (t.f - 0.5) + 0.5


def revision(a: Truth, b: Truth) -> Truth:
    """Pool two bodies of independent evidence."""
    return pooled(a, b, c2w(a.c), c2w(b.c))


def pooled(a: Truth, b: Truth, w1: float, w2: float) -> Truth:
    """:func:`revision` of ``a`` and ``b`` given their evidence weights ``c2w(a.c)`` and
    ``c2w(b.c)``, for callers that need those weights anyway (an implication's revised
    offset is weighted by them) or revise many times with one ``b``."""
    w = w1 + w2
    # min(1.0, f) and min(MAX_CONFIDENCE, max(w2c(w), a.c, b.c)) spelled out, with the
    # builtins' choices (the earlier of equals; a NaN frequency gives 1): anticipation
    # revises thousands of links per input and the calls cost more than the arithmetic
    if w > 0:
        f = (w1 * a.f + w2 * b.f) / w
        if not f < 1.0:
            f = 1.0
    else:
        f = 0.0
    c = w2c(w)
    if a.c > c:
        c = a.c
    if b.c > c:
        c = b.c
    if not c < _MAX_C:
        c = _MAX_C
    return truth_of(f, c)


def deduction(a: Truth, b: Truth) -> Truth:
    """M-->P, S-->M |- S-->P."""
    f = a.f * b.f
    return truth_of(f, a.c * b.c * f)


def abduction(a: Truth, b: Truth) -> Truth:
    """P-->M, S-->M |- S-->P."""
    return truth_of(b.f, w2c(a.f * a.c * b.c))


def induction(a: Truth, b: Truth) -> Truth:
    """M-->P, M-->S |- S-->P (abduction with the premises swapped)."""
    return abduction(b, a)


def exemplification(a: Truth, b: Truth) -> Truth:
    """P-->M, M-->S |- S-->P."""
    return truth_of(1.0, w2c(a.f * b.f * a.c * b.c))


def comparison(a: Truth, b: Truth) -> Truth:
    """M-->P, M-->S |- S<->P."""
    f0 = _or(a.f, b.f)
    f = 0.0 if f0 == 0.0 else a.f * b.f / f0
    return truth_of(f, w2c(f0 * a.c * b.c))


def analogy(a: Truth, b: Truth) -> Truth:
    """M-->P, S<->M |- S-->P."""
    f = a.f * b.f
    return truth_of(f, a.c * b.c * b.f)


def resemblance(a: Truth, b: Truth) -> Truth:
    """M<->P, S<->M |- S<->P."""
    f = a.f * b.f
    return truth_of(f, a.c * b.c * _or(a.f, b.f))


def intersection(a: Truth, b: Truth) -> Truth:
    """Extensional intersection / conjunction of both premises."""
    return truth_of(a.f * b.f, a.c * b.c)


def union(a: Truth, b: Truth) -> Truth:
    """Union / disjunction of both premises."""
    return truth_of(_or(a.f, b.f), a.c * b.c)


def difference(a: Truth, b: Truth) -> Truth:
    """What holds of the first and not of the second."""
    return truth_of(a.f * (1.0 - b.f), a.c * b.c)


def negation(a: Truth, _b: Truth | None = None) -> Truth:
    """(! A)."""
    return truth_of(1.0 - a.f, a.c)


def conversion(a: Truth, _b: Truth | None = None) -> Truth:
    """S-->P |- P-->S."""
    return truth_of(1.0, w2c(a.f * a.c))


def contraposition(a: Truth, _b: Truth | None = None) -> Truth:
    """(S ==> P) |- ((! P) ==> (! S))."""
    return truth_of(0.0, w2c((1.0 - a.f) * a.c))


def structural_deduction(a: Truth, _b: Truth | None = None) -> Truth:
    """Deduction with the analytic premise {1, 0.9}."""
    return deduction(a, STRUCTURAL)


def structural_deduction_negated(a: Truth, _b: Truth | None = None) -> Truth:
    """Negation of :func:`structural_deduction`."""
    return negation(structural_deduction(a))


def structural_intersection(a: Truth, _b: Truth | None = None) -> Truth:
    """Intersection with the analytic premise {1, 0.9}."""
    return intersection(a, STRUCTURAL)


def structural_abduction(a: Truth, _b: Truth | None = None) -> Truth:
    """Abduction with the analytic premise {1, 0.9}."""
    return abduction(a, STRUCTURAL)


def decompose_pnn(a: Truth, b: Truth) -> Truth:
    """S, (S && A) |- A and its relatives (positive, negative, negative)."""
    fn = a.f * (1.0 - b.f)
    return truth_of(1.0 - fn, fn * a.c * b.c)


def decompose_npp(a: Truth, b: Truth) -> Truth:
    """S, (S || A) |- A and its relatives."""
    f = (1.0 - a.f) * b.f
    return truth_of(f, f * a.c * b.c)


def decompose_pnp(a: Truth, b: Truth) -> Truth:
    """S, (S ~ A) |- A and its relatives."""
    f = a.f * (1.0 - b.f)
    return truth_of(f, f * a.c * b.c)


def decompose_ppp(a: Truth, b: Truth) -> Truth:
    """NPP of the negated first premise."""
    return decompose_npp(negation(a), b)


def decompose_nnn(a: Truth, b: Truth) -> Truth:
    """Both premises negative."""
    fn = (1.0 - a.f) * (1.0 - b.f)
    return truth_of(1.0 - fn, fn * a.c * b.c)


def eternalize(a: Truth) -> Truth:
    """An event's evidence as a timeless belief."""
    return truth_of(a.f, w2c(a.c))


#: ``PROJECTION_DECAY ** d`` for the distances that occur (the same floats, looked up)
_DECAY_POWERS = [PROJECTION_DECAY**d for d in range(1024)]


def decay(d: Cycle) -> float:
    """``PROJECTION_DECAY ** d``, the factor of a confidence projected ``d >= 0`` cycles
    away (read from a table for the distances that occur)."""
    return _DECAY_POWERS[d] if d < 1024 else _DECAY**d


def projection(a: Truth, source_time: Cycle, target_time: Cycle) -> Truth:
    """Confidence decays by 0.8 per cycle of distance; eternal (-1) is unchanged."""
    if source_time == -1:
        return a
    return truth_of(a.f, a.c * decay(abs(target_time - source_time)))


def anonymous_analogy(a: Truth, b: Truth) -> Truth:
    """Analogy with the second premise turned into an anonymous similarity."""
    return analogy(a, truth_of(1.0, w2c(b.f * b.c)))


def goal_deduction(goal: Truth, belief: Truth) -> Truth:
    """The more confident of deduction and negated deduction from the negated goal."""
    d = deduction(goal, belief)
    dn = negation(deduction(negation(goal), belief))
    return d if d.c >= dn.c else dn


def frequency_greater(a: Truth, b: Truth) -> Truth:
    """Comparative relation: more of the property."""
    return truth_of(1.0, a.c * b.c) if a.f > b.f else truth_of(0.0, 0.0)


def frequency_equal(a: Truth, b: Truth) -> Truth:
    """Comparative relation: as much of the property."""
    return truth_of(1.0, a.c * b.c) if a.f == b.f else truth_of(0.0, 0.0)
