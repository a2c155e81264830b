"""The convergence property of Fujita et al., Section 4, checked by simulation.

Section 4.1 models the robot's ``fwQ`` (``forward_Qbo``) by assumption A: from x0 the
robot lands according to N(x1, sigma^2 I) with x1 = x0 (|x0| - r) / |x0| and
sigma^2 = r^2 / 2, where r = |x0|/2 near the target (|x0| < 2k), k in the middle and
k|x0|/R far away. With D = E|x|^2 and alpha = 1 - 2k(R - k)/R^2, Section 4.3 claims
that one ``fwQ`` takes D to at most alpha D. That is what makes the robot come
arbitrarily close to the target, formula (3).

Here a cloud of particles (the distribution f of the robot's position) is stepped and D
is measured before and after every step, in three worlds:

* ``A``: assumption A exactly. The ratio must stay at or below alpha at every step.
* ``constant-step``: ``forward_Qbo`` as the robot really runs it, a constant length k
  whatever the distance left (Section 2.4). Far from the target it behaves like A;
  within about k of it the robot overshoots and D grows: the property fails there.
* ``obstacle``: assumption A, but a wall stands across the way. A step that meets the
  wall stops at it (``fOb`` becomes true) and the next action is ``srQ``, a move along
  the wall; those steps do not shrink D by alpha, and assumption B (finitely many
  ``srQ``) is what still lets the robot converge once past the wall.

Each step is reported twice: the ratio of the sampled D values, and, where the model
gives it in closed form, the ratio of the expected D after the step (|x1|^2 + 2 sigma^2
averaged over the particles) to the sampled D before it. The second has no sampling
noise in the step itself, so it shows exactly where alpha is respected.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from dataclasses import dataclass

SCENARIOS = ("A", "constant-step", "obstacle")


@dataclass(frozen=True)
class Model:
    """The constants of assumption A: mean step k and the far radius R (R >> 2k)."""

    k: float = 0.5
    R: float = 10.0

    @property
    def alpha(self) -> float:
        """alpha = 1 - 2k(R - k)/R^2, the promised per-step contraction of D."""
        return 1.0 - 2.0 * self.k * (self.R - self.k) / self.R**2

    def radius(self, distance: float) -> float:
        """r of assumption A for a robot at ``distance`` from the target."""
        if distance < 2.0 * self.k:
            return distance / 2.0
        if distance <= self.R:
            return self.k
        return self.k * distance / self.R

    def expected_square_after(self, distance: float) -> float:
        """E|x'|^2 after one fwQ from ``distance``: |x1|^2 + 2 sigma^2 = (d - r)^2 + r^2."""
        r = self.radius(distance)
        return (distance - r) ** 2 + r**2


@dataclass(frozen=True)
class StepRecord:
    """D before and after one step of the particle cloud, and how it compares with alpha."""

    scenario: str
    step: int
    mean_distance: float
    d_before: float
    d_after: float
    ratio: float
    expected_ratio: float | None
    alpha: float
    blocked: float

    @property
    def holds(self) -> bool:
        """True when D shrank by alpha at this step (expected ratio where known)."""
        measured = self.expected_ratio if self.expected_ratio is not None else self.ratio
        return measured <= self.alpha + 1e-12


Point = tuple[float, float]


def _toward(p: Point, step: float) -> Point:
    """The point ``step`` metres nearer the origin along the line to it (may overshoot)."""
    d = math.hypot(*p)
    if d == 0.0:
        return p
    f = (d - step) / d
    return (p[0] * f, p[1] * f)


@dataclass(frozen=True)
class Wall:
    """A wall across the way: the segment x = ``x``, |y| <= ``half_width``."""

    x: float = 3.0
    half_width: float = 2.0


def _crossing(p: Point, q: Point, wall: Wall) -> float | None:
    """Fraction along p->q where it meets the wall, or None."""
    if (p[0] - wall.x) * (q[0] - wall.x) >= 0.0 or p[0] == q[0]:
        return None
    t = (p[0] - wall.x) / (p[0] - q[0])
    y = p[1] + t * (q[1] - p[1])
    return t if abs(y) <= wall.half_width else None


class Cloud:
    """A particle cloud standing for the distribution f of the robot's position."""

    def __init__(self, start: Point, particles: int, rng: random.Random) -> None:
        self.points: list[Point] = [start] * particles
        self.rng = rng
        self.against_wall: list[bool] = [False] * particles

    def d(self) -> float:
        """D = E|x|^2 over the particles."""
        return sum(x * x + y * y for x, y in self.points) / len(self.points)

    def mean_distance(self) -> float:
        """Mean distance to the target."""
        return sum(math.hypot(x, y) for x, y in self.points) / len(self.points)


def _gauss2(rng: random.Random, centre: Point, sigma: float) -> Point:
    return (centre[0] + rng.gauss(0.0, sigma), centre[1] + rng.gauss(0.0, sigma))


def _step_a(model: Model, p: Point, rng: random.Random) -> Point:
    d = math.hypot(*p)
    r = model.radius(d)
    return _gauss2(rng, _toward(p, r), r / math.sqrt(2.0))


def _step_constant(model: Model, p: Point, rng: random.Random) -> Point:
    k = model.k
    return _gauss2(rng, _toward(p, k), k / math.sqrt(2.0))


def simulate(
    scenario: str,
    model: Model | None = None,
    steps: int = 40,
    particles: int = 2000,
    start: float = 8.0,
    seed: int = 0,
    wall: Wall | None = None,
) -> list[StepRecord]:
    """Step a cloud from a point ``start`` metres from the target; one record per step."""
    if scenario not in SCENARIOS:
        raise ValueError(f"unknown scenario {scenario!r}; choose from {', '.join(SCENARIOS)}")
    model = model or Model()
    wall = wall or Wall()
    rng = random.Random(seed)
    cloud = Cloud((start, 0.0), particles, rng)
    records: list[StepRecord] = []
    stepper: Callable[[Model, Point, random.Random], Point] = (
        _step_constant if scenario == "constant-step" else _step_a
    )
    for i in range(steps):
        before = cloud.d()
        mean = cloud.mean_distance()
        expected = 0.0
        blocked = 0
        new: list[Point] = []
        for j, p in enumerate(cloud.points):
            d = math.hypot(*p)
            if scenario == "obstacle" and cloud.against_wall[j]:
                # srQ: turn away from the wall and move k along it, towards its nearer end
                side = 1.0 if p[1] >= 0.0 else -1.0
                q = (p[0] + rng.gauss(0.0, 0.05), p[1] + side * model.k)
                cloud.against_wall[j] = abs(q[1]) <= wall.half_width
                blocked += 1
                new.append(q)
                expected += q[0] ** 2 + q[1] ** 2
                continue
            q = stepper(model, p, rng)
            if scenario == "obstacle":
                t = _crossing(p, q, wall)
                if t is not None:
                    # fwQ stops at the obstacle a little before touching it
                    t = max(0.0, t - 0.05 / max(1e-9, math.hypot(q[0] - p[0], q[1] - p[1])))
                    q = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
                    cloud.against_wall[j] = True
                    blocked += 1
                    expected += q[0] ** 2 + q[1] ** 2
                    new.append(q)
                    continue
            if scenario == "constant-step":
                expected += (d - model.k) ** 2 + model.k**2
            else:
                expected += model.expected_square_after(d)
            new.append(q)
        cloud.points = new
        after = cloud.d()
        exp_ratio = (expected / len(new)) / before if before > 0 else 0.0
        records.append(
            StepRecord(
                scenario=scenario,
                step=i + 1,
                mean_distance=mean,
                d_before=before,
                d_after=after,
                ratio=after / before if before > 0 else 0.0,
                expected_ratio=exp_ratio,
                alpha=model.alpha,
                blocked=blocked / len(new),
            )
        )
    return records


def summary(records: list[StepRecord]) -> dict[str, object]:
    """How many steps kept D below alpha, and where (by distance) the others were."""
    failing = [r for r in records if not r.holds]
    return {
        "scenario": records[0].scenario if records else "",
        "steps": len(records),
        "alpha": records[0].alpha if records else float("nan"),
        "steps_holding": len(records) - len(failing),
        "max_ratio": max((r.expected_ratio or r.ratio) for r in records) if records else 0.0,
        "max_sampled_ratio": max(r.ratio for r in records) if records else 0.0,
        "failing_steps": [r.step for r in failing],
        "failing_distances": [round(r.mean_distance, 3) for r in failing],
        "final_d": records[-1].d_after if records else float("nan"),
    }
