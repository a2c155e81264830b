"""The convergence property of Fujita et al., Section 4, on simulated steps."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.experiments.convergence import Model, Wall, simulate, summary


@given(
    k=st.floats(min_value=0.01, max_value=5.0),
    factor=st.floats(min_value=2.0, max_value=100.0),
    distance=st.floats(min_value=1e-3, max_value=1e4),
)
def test_one_step_of_assumption_a_shrinks_d_by_alpha(
    k: float, factor: float, distance: float
) -> None:
    model = Model(k=k, R=k * factor)
    assert 0.0 < model.alpha < 1.0
    assert model.expected_square_after(distance) <= model.alpha * distance**2 * (1 + 1e-9)


def test_alpha_is_the_papers_formula() -> None:
    model = Model(k=0.5, R=10.0)
    assert model.alpha == pytest.approx(1 - 2 * 0.5 * 9.5 / 100)
    assert model.radius(0.4) == pytest.approx(0.2)
    assert model.radius(5.0) == pytest.approx(0.5)
    assert model.radius(20.0) == pytest.approx(1.0)


def test_under_assumption_a_every_step_keeps_d_below_alpha() -> None:
    records = simulate("A", steps=30, particles=1500, seed=3)
    assert all(r.holds for r in records)
    # the sampled ratio too, within the sampling error of 1,500 particles
    assert max(r.ratio for r in records[:15]) <= records[0].alpha + 0.01
    assert records[-1].d_after < records[0].d_before * 1e-3


def test_constant_step_breaks_the_property_near_the_target() -> None:
    model = Model()
    records = simulate("constant-step", model=model, steps=30, particles=1500, seed=3)
    info = summary(records)
    assert info["failing_steps"], "a constant step must overshoot near the target"
    assert all(d < 2 * model.k for d in info["failing_distances"])
    assert all(r.holds for r in records if r.mean_distance > 2 * model.k)


def test_an_obstacle_breaks_the_property_where_the_robot_meets_it() -> None:
    wall = Wall(x=3.0, half_width=2.0)
    records = simulate("obstacle", steps=25, particles=1500, seed=3, wall=wall)
    failing = [r for r in records if not r.holds]
    assert failing
    assert all(r.blocked > 0.3 for r in failing)
    assert all(abs(r.mean_distance - wall.x) < 1.0 for r in failing)


def test_unknown_scenario_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown scenario"):
        simulate("teleport")
