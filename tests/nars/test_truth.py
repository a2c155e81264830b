"""Truth functions against values worked out by hand from NAL's definitions."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.nars import truth as tf
from robocog.nars.stamp import has_duplicate, merge, overlap
from robocog.nars.truth import Truth

A = Truth(1.0, 0.9)
B = Truth(0.7, 0.8)

# each value below is computed from the definition written next to it
HAND = [
    ("deduction", A, B, (0.7, 0.9 * 0.8 * 0.7)),  # f1f2, c1c2f1f2
    ("abduction", A, B, (0.7, 0.72 / 1.72)),  # f2, w2c(f1c1c2)
    ("induction", A, B, (1.0, 0.7 * 0.72 / (0.7 * 0.72 + 1))),  # f1, w2c(f2c1c2)
    ("exemplification", A, B, (1.0, 0.504 / 1.504)),  # 1, w2c(f1f2c1c2)
    ("comparison", A, B, (0.7, 0.72 / 1.72)),  # f1f2/or, w2c(or c1c2); or = 1
    ("analogy", A, B, (0.7, 0.72 * 0.7)),  # f1f2, c1c2f2
    ("resemblance", A, B, (0.7, 0.72)),  # f1f2, c1c2 or(f1,f2)
    ("intersection", A, B, (0.7, 0.72)),
    ("union", A, B, (1.0, 0.72)),
    ("difference", A, B, (0.3, 0.72)),
    ("decompose_pnn", A, B, (0.7, 0.3 * 0.72)),  # fn=f1(1-f2)=0.3 -> 1-fn, fn c1c2
    ("decompose_npp", B, A, (0.3, 0.3 * 0.72)),  # (1-f1)f2, f c1c2
    ("decompose_pnp", A, B, (0.3, 0.3 * 0.72)),  # f1(1-f2), f c1c2
    ("decompose_nnn", B, Truth(0.5, 0.9), (1 - 0.15, 0.15 * 0.72)),  # fn=(1-f1)(1-f2)
]


@pytest.mark.parametrize(("name", "a", "b", "want"), HAND)
def test_two_premise_functions(name: str, a: Truth, b: Truth, want: tuple[float, float]) -> None:
    got = getattr(tf, name)(a, b)
    assert got.f == pytest.approx(want[0])
    assert got.c == pytest.approx(want[1])


def test_revision_of_two_inductions_gives_ona_greenplant_value() -> None:
    # w = 0.81 each: f = (0.7*0.81 + 0.8*0.81)/1.62 = 0.75, c = 1.62/2.62
    a = Truth(0.7, 0.81 / 1.81)
    b = Truth(0.8, 0.81 / 1.81)
    r = tf.revision(a, b)
    assert r.f == pytest.approx(0.75)
    assert r.c == pytest.approx(1.62 / 2.62)
    assert f"{r.c:f}" == "0.618321"


def test_single_premise_functions() -> None:
    assert tuple(tf.negation(B)) == pytest.approx((0.3, 0.8))
    assert tuple(tf.conversion(B)) == pytest.approx((1.0, 0.56 / 1.56))
    assert tuple(tf.contraposition(B)) == pytest.approx((0.0, 0.24 / 1.24))
    assert tuple(tf.structural_deduction(B)) == pytest.approx((0.7, 0.7 * 0.8 * 0.9))
    assert tuple(tf.structural_deduction_negated(B)) == pytest.approx((0.3, 0.7 * 0.8 * 0.9))
    assert tuple(tf.structural_intersection(B)) == pytest.approx((0.7, 0.72))
    assert tuple(tf.eternalize(B)) == pytest.approx((0.7, 0.8 / 1.8))
    assert tf.expectation(B) == pytest.approx(0.8 * 0.2 + 0.5)


def test_projection_decays_by_point_eight_per_cycle() -> None:
    assert tuple(tf.projection(A, 10, 13)) == pytest.approx((1.0, 0.9 * 0.8**3))
    assert tf.projection(A, -1, 13) == A


def test_goal_deduction_takes_the_more_confident_reading() -> None:
    g = Truth(0.0, 0.9)  # a goal to avoid
    got = tf.goal_deduction(g, A)
    # deduction gives c = 0; the negated reading gives f = 1 - 0 = 1 ... negated back: 0
    assert tuple(got) == pytest.approx((0.0, 0.81))


def test_frequency_comparisons() -> None:
    assert tuple(tf.frequency_greater(A, B)) == pytest.approx((1.0, 0.72))
    assert tuple(tf.frequency_greater(B, A)) == (0.0, 0.0)
    assert tuple(tf.frequency_equal(A, A)) == pytest.approx((1.0, 0.81))


unit = st.floats(0.0, 1.0)
conf = st.floats(0.01, 0.99)


@given(unit, conf, unit, conf)
def test_revision_never_loses_confidence(f1: float, c1: float, f2: float, c2: float) -> None:
    r = tf.revision(Truth(f1, c1), Truth(f2, c2))
    assert r.c >= max(c1, c2) - 1e-12
    assert min(f1, f2) - 1e-9 <= r.f <= max(f1, f2) + 1e-9


def _bits(t: Truth) -> tuple[str, str]:
    return (t.f.hex(), t.c.hex())


# confidences of every size, 0 and 1 included (weights 0 and infinite), and frequencies
# outside [0, 1], where the frequency cap and the confidence cap both act
_any_c = st.one_of(st.sampled_from([0.0, 0.5, 0.99, 1.0]), st.floats(0.0, 1.0))
_any_f = st.one_of(unit, st.floats(-2.0, 3.0))


@given(_any_f, _any_c, _any_f, _any_c)
def test_revision_is_the_plain_definition_to_the_bit(f1, c1, f2, c2) -> None:  # noqa: ANN001
    """min/max are spelled out in ``pooled``: the same floats as the builtins give."""
    a, b = Truth(f1, c1), Truth(f2, c2)
    w1 = tf.HORIZON * c1 / (1.0 - c1) if c1 < 1.0 else float("inf")
    w2 = tf.HORIZON * c2 / (1.0 - c2) if c2 < 1.0 else float("inf")
    w = w1 + w2
    f = min(1.0, (w1 * f1 + w2 * f2) / w) if w > 0 else 0.0
    c = min(tf.MAX_CONFIDENCE, max(w / (w + tf.HORIZON), c1, c2))
    assert _bits(tf.pooled(a, b, w1, w2)) == (f.hex(), c.hex())
    if c1 < 1.0 and c2 < 1.0:
        assert _bits(tf.revision(a, b)) == (f.hex(), c.hex())


@given(unit, conf, unit, conf)
def test_syllogisms_stay_in_range_and_below_premises(f1, c1, f2, c2) -> None:  # noqa: ANN001
    for name in ("deduction", "abduction", "induction", "analogy", "comparison"):
        r = getattr(tf, name)(Truth(f1, c1), Truth(f2, c2))
        assert 0.0 <= r.f <= 1.0
        assert 0.0 <= r.c <= min(c1, c2) + 1e-12


def test_stamps() -> None:
    assert merge((1, 3, 5), (2, 4)) == (1, 2, 3, 4, 5)
    assert merge(tuple(range(10)), tuple(range(10, 20))) == (0, 10, 1, 11, 2, 12, 3, 13, 4, 14)
    assert overlap((1, 2), (3, 2))
    assert not overlap((1, 2), (3, 4))
    assert has_duplicate((1, 2, 1))
