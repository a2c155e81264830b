"""Pong and Pong2: keep a bat under a ball that falls towards the bat's row.

Rules (those of ONA's Pong system tests): a 50 x 20 field, the bat on row 0. Each step
the reasoner is told on which side of the bat the ball is, and gets the goal
``good_nar``; then the ball moves one cell (bouncing off the walls), and when it reaches
row 0 it is a hit if it is within the bat's half-width of the bat's centre (then
``good_nar`` is input as an event) and a miss otherwise; after row 0 or a side wall the
ball respawns at a random cell of the lower half of the field. Operations executed since
the last step then set the bat's velocity, which persists; the bat moves; five free
cycles follow.

Pong2 differs: a wider bat (half-width 6) that moves faster (9 cells a step), a third
operation ``^stop``, a third observation ``ball_equal`` when the ball is within reach,
and a ball that only moves vertically (ONA's Pong2 advances the ball's column under a
condition that never holds).
"""

from __future__ import annotations

from collections.abc import Iterator

from .base import Feed, ProcedureEnv, event, goal

WIDTH = 50
HEIGHT = 20


class Pong(ProcedureEnv):
    """ONA's ``pong``: two operations, half-width 4, success ratio = hits / (hits + misses)."""

    name = "pong"
    operations = ("^left", "^right")
    half_width = 4
    #: Velocity an operation sets; the bat moves velocity * half_width // 2 cells a step.
    op_velocity = {"^left": -2, "^right": 2}
    bat_range = (0, WIDTH - 1)
    ball_moves_sideways = True
    free_cycles = 5

    def _reset_world(self) -> None:
        self.ball_x = WIDTH // 2
        self.ball_y = HEIGHT // 5
        self.bat_x = 20
        self.bat_v = 0
        self.vx = 1
        self.vy = 1
        self.fired: list[str] = []
        self.score.extra.update(hits=0, misses=0)

    def observation(self) -> str | None:
        """Where the ball is relative to the bat, or None when directly above it."""
        if self.bat_x < self.ball_x:
            return "ball_right"
        if self.ball_x < self.bat_x:
            return "ball_left"
        return None

    def step(self) -> Iterator[Feed]:
        """Observation and goal, ball move (and reward), bat move, free cycles."""
        self.steps += 1
        seen = self.observation()
        yield ([event(seen)] if seen else []) + [goal("good_nar")]
        if self._move_ball():
            yield [event("good_nar")]
        self._move_bat()
        yield [self.free_cycles]

    def execute(self, op: str) -> None:
        """Operations only raise a flag; the bat reacts at its fixed point of the step."""
        if op in self.op_velocity:
            self.fired.append(op)

    def _move_ball(self) -> bool:
        """Advance the ball; return True on a hit. Counts hits and misses on row 0."""
        if self.ball_x <= 0:
            self.vx = 1
        if self.ball_x >= WIDTH - 1:
            self.vx = -1
        if self.ball_y <= 0:
            self.vy = 1
        if self.ball_y >= HEIGHT - 1:
            self.vy = -1
        if self.ball_moves_sideways:
            self.ball_x += self.vx
        self.ball_y += self.vy
        hit = False
        if self.ball_y == 0:
            hit = abs(self.ball_x - self.bat_x) <= self.half_width
            self.score.trials += 1
            if hit:
                self.score.successes += 1
                self.score.extra["hits"] += 1
            else:
                self.score.extra["misses"] += 1
        if self.ball_y == 0 or self.ball_x == 0 or self.ball_x >= WIDTH - 1:
            self.ball_y = HEIGHT // 2 + self.rng.randrange(HEIGHT // 2)
            self.ball_x = self.rng.randrange(WIDTH)
            self.vx = 1 if self.rng.randrange(2) == 0 else -1
        return hit

    def _move_bat(self) -> None:
        """Apply the flagged operations in ONA's order (the last listed wins), then move."""
        fired = set(self.fired)
        self.fired.clear()
        for op in self.operations:
            if op in fired:
                self.bat_v = self.op_velocity[op]
        low, high = self.bat_range
        self.bat_x = max(low, min(high, self.bat_x + self.bat_v * self.half_width // 2))


class Pong2(Pong):
    """ONA's ``pong2``: ``^stop`` added, ``ball_equal`` observed, a wider and faster bat."""

    name = "pong2"
    operations = ("^left", "^right", "^stop")
    half_width = 6
    op_velocity = {"^left": -3, "^right": 3, "^stop": 0}
    bat_range = (-2 * 6, WIDTH - 1 + 6)
    ball_moves_sideways = False

    def observation(self) -> str | None:
        """Right or left only when the ball is out of the bat's reach, else equal."""
        if self.bat_x <= self.ball_x - self.half_width:
            return "ball_right"
        if self.ball_x + self.half_width < self.bat_x:
            return "ball_left"
        return "ball_equal"
