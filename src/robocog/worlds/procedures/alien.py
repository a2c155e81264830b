"""Alien: move a defender under an alien and shoot it.

Rules (those of ONA's ``alien`` system test): the alien and the defender live on
[0, 1]. Each step the reasoner learns whether the alien is to the right (``r0``), to the
left (``l0``) or in reach (``c0``, within 0.18 of the defender), then gets the goal
``s0``. Operations fired so far then take effect: ``^shoot`` counts a shot, and when the
alien was in reach it is a hit: ``s0`` is input as an event and the alien reappears at a
random place (a multiple of 0.001); then ``^left``/``^right`` (including one fired while
``s0`` was input) move the defender by 0.1, clamped to [0, 1]; a shot fired while ``s0``
was input counts in the next step. There are no free cycles: each input is the only reasoning time.
Success ratio = hits / shots.
"""

from __future__ import annotations

from collections.abc import Iterator

from .base import Feed, ProcedureEnv, event, goal


class Alien(ProcedureEnv):
    """ONA's ``alien`` test."""

    name = "alien"
    operations = ("^left", "^right", "^shoot")
    reach = 0.18
    move = 0.1

    def _reset_world(self) -> None:
        self.alien_x = 0.5
        self.defender_x = 0.5
        self.fired: set[str] = set()
        self.score.extra.update(shots=0, hits=0)

    def relation(self) -> str:
        """``r0``, ``l0`` or ``c0``: where the alien is seen from the defender."""
        if self.defender_x <= self.alien_x - self.reach:
            return "r0"
        if self.defender_x > self.alien_x + self.reach:
            return "l0"
        return "c0"

    def step(self) -> Iterator[Feed]:
        """Observation and goal, then shot, then movement."""
        self.steps += 1
        seen = self.relation()
        yield [event(seen), goal("s0")]
        if "^shoot" in self.fired:
            self.fired.discard("^shoot")
            self.score.trials += 1
            self.score.extra["shots"] += 1
            if seen == "c0":
                self.score.successes += 1
                self.score.extra["hits"] += 1
                self.alien_x = self.rng.randrange(1000) / 1000.0
                yield [event("s0")]  # a move fired meanwhile still acts this step
        if "^left" in self.fired:
            self.defender_x = max(0.0, self.defender_x - self.move)
        if "^right" in self.fired:
            self.defender_x = min(1.0, self.defender_x + self.move)
        self.fired -= {"^left", "^right"}

    def execute(self, op: str) -> None:
        """Flag the operation; it acts at the step's fixed point."""
        if op in self.operations:
            self.fired.add(op)
