"""The rule table's generated matchers (``robocog/nars/matchers.py``).

The file must be what the generator makes of the table today, and each matcher must
conclude exactly what the generic pattern matcher and builder of ``rules.py`` conclude
from the same premises: the same conclusion term, truth and variable introduction, or
nothing.
"""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.nars import truth as tf
from robocog.nars.matchers import MATCHERS
from robocog.nars.narsese import parse_pattern
from robocog.nars.rulegen import MATCHERS_MODULE, matcher_source
from robocog.nars.rules import RULES, Emit, build, match
from robocog.nars.terms import Term, atom, compound
from robocog.nars.truth import Truth

SOURCE = Path(__file__).resolve().parents[2] / "src" / "robocog" / "nars" / MATCHERS_MODULE

#: each row's patterns, parsed once
_PATTERNS = [
    (parse_pattern(p1), parse_pattern(p2) if p2 else None, parse_pattern(c), getattr(tf, fn), vi)
    for p1, p2, c, fn, vi, _ in RULES
]
_VARIABLES = sorted(
    {a for p in _PATTERNS for x in p[:3] if x is not None for a in x.atoms()}, key=str
)


def test_the_generated_module_is_current_with_the_rule_table() -> None:
    assert SOURCE.read_text(encoding="utf-8") == matcher_source(), (
        "the rule table changed: run `PYTHONPATH=src python tools/nars_rule_matchers.py`"
    )
    assert len(MATCHERS) == len(RULES)


def _small_terms() -> st.SearchStrategy[Term]:
    """Few names (so that components coincide, as the rules demand) in small compounds."""
    names = st.sampled_from(["a", "b", "c", "#1", "$1"]).map(atom)
    return st.recursive(
        names,
        lambda inner: st.one_of(
            st.tuples(st.sampled_from(["-->", "*", "&&", "==>", "<->"]), inner, inner).map(
                lambda x: compound(x[0], (x[1], x[2]))
            ),
            st.tuples(st.sampled_from(["!", "{}", "[]"]), inner).map(
                lambda x: compound(x[0], (x[1],))
            ),
        ),
        max_leaves=4,
    )


@st.composite
def _premises(draw: st.DrawFn) -> tuple[Term, Term]:
    """A premise pair built from two rows' patterns (often one), so that most pairs
    fit some rule and many fit none."""
    bindings = {v: draw(_small_terms()) for v in _VARIABLES}
    first = draw(st.sampled_from(_PATTERNS))
    second = first if draw(st.booleans()) else draw(st.sampled_from(_PATTERNS))
    t1 = build(first[0], bindings)
    t2 = build(second[1] if second[1] is not None else second[0], bindings)
    return t1, t2


def _collect(into: list[tuple[Term, Truth, bool]]) -> Emit:
    """An ``emit`` that keeps what it is handed in ``into``."""

    def emit(term: Term, t: Truth, intro: bool) -> None:
        into.append((term, t, intro))

    return emit


_V1 = Truth(0.9, 0.8)
_V2 = Truth(0.7, 0.6)


@settings(max_examples=300, deadline=None)
@given(_premises())
def test_each_matcher_concludes_what_the_generic_matcher_and_builder_conclude(
    pair: tuple[Term, Term],
) -> None:
    t1, t2 = pair
    for (p1, p2, conclusion, fn, vi), matcher in zip(_PATTERNS, MATCHERS, strict=True):
        second, v2 = (t2, _V2) if p2 is not None else (t1, _V1)
        bindings: dict[Term, Term] = {}
        fits = match(p1, t1, bindings) and (p2 is None or match(p2, t2, bindings))
        expected = [(build(conclusion, bindings), fn(_V1, v2), vi)] if fits else []
        got: list[tuple[Term, Truth, bool]] = []
        matcher(t1, second, _V1, v2, _collect(got))
        assert got == expected, (str(t1), str(t2), p1, p2)


def test_the_premise_pairs_above_do_fit_rules() -> None:
    """The generator of premise pairs is not vacuous: the rows' own shapes fit them."""
    b = {v: atom(str(v).lower() + "x") for v in _VARIABLES}
    fitted = 0
    for (p1, p2, _c, _fn, _vi), matcher in zip(_PATTERNS, MATCHERS, strict=True):
        t1 = build(p1, b)
        t2 = build(p2, b) if p2 is not None else t1
        got: list[tuple[Term, Truth, bool]] = []
        matcher(t1, t2, _V1, _V1, _collect(got))
        fitted += len(got)
    assert fitted >= len(_PATTERNS) - 5
