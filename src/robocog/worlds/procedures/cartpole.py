"""Cartpole: keep a pole upright by pushing its cart.

Rules (those of ONA's ``cartpole`` system test, with its value of pi, 3.1415): the pole's
angle starts upright at -pi/2, angular velocity 0; gravity adds 0.2 cos(angle) to the
angular velocity each step, clamped to +-0.3, and the angle wraps at +-pi. The cart's
position (clamped to [0, 1]) moves by its velocity, which friction resets to 0 every
step. Each step: the world moves; when the angle is within 0.5 of upright the step is a
success and ``good`` is input as an event; when the pole hangs in the lower half
(angle in [0, pi]) it is a failure; other steps count for neither. Then the angle,
quantised into eight sectors, is input as the event ``0`` ... ``7`` (``8`` when a wrap
has left the angle exactly at pi, as in ONA), the goal ``good``, and three free cycles. ``^left``/``^right`` act at once: they push the angular velocity
by 0.2 (sign mirrored when the angle is positive) and the cart velocity by 0.1.
Success ratio = successes / (successes + failures).

The world is deterministic (ONA's test draws no random number); the seed is accepted so
every environment is reset the same way.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from .base import Feed, ProcedureEnv, event, goal

PI = 3.1415
UPRIGHT = -PI / 2.0


class Cartpole(ProcedureEnv):
    """ONA's ``cartpole`` test."""

    name = "cartpole"
    operations = ("^left", "^right")
    max_angular_velocity = 0.3
    free_cycles = 3

    def _reset_world(self) -> None:
        self.position = 0.0
        self.velocity = 0.0
        self.angle = UPRIGHT
        self.angular_velocity = 0.0
        self.score.extra.update(failures=0)

    def sector(self) -> int:
        """The angle quantised into eighths of a turn, as the event term."""
        return int((self.angle + PI) / (2 * PI) * 8)

    def step(self) -> Iterator[Feed]:
        """Physics, score (and reward event), sector event, goal, free cycles."""
        self.steps += 1
        self.position = max(0.0, min(1.0, self.position + self.velocity))
        self.angle += self.angular_velocity
        limit = self.max_angular_velocity
        self.angular_velocity = max(
            -limit, min(limit, self.angular_velocity + 0.2 * math.cos(self.angle))
        )
        if self.angle > PI:
            self.angle = -PI
        if self.angle < -PI:
            self.angle = PI
        self.velocity = 0.0
        feed: Feed = []
        if abs(self.angle - UPRIGHT) <= 0.5:
            self.score.successes += 1
            self.score.trials += 1
            feed.append(event("good"))
        elif 0 <= self.angle <= PI:
            self.score.trials += 1
            self.score.extra["failures"] += 1
        feed += [event(str(self.sector())), goal("good"), self.free_cycles]
        yield feed

    def execute(self, op: str) -> None:
        """Push at once, as ONA's callbacks do."""
        mirror = 1.0 if self.angle > 0 else -1.0
        if op == "^left":
            self.angular_velocity -= mirror * 0.2
            self.velocity -= 0.1
        elif op == "^right":
            self.angular_velocity += mirror * 0.2
            self.velocity += 0.1
