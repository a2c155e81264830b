"""Bandrobot: pick an object on a conveyor line and deliver it to a goal position.

Rules (those of ONA's ``bandrobot`` system test): positions 0..20 on a line; the robot
starts at 0, the object at 1, the goal at 3. Operations fired during the previous step
act at the start of the next: ``^left``/``^right`` move the robot by one (clamped),
a held object moves with the robot, ``^pick`` takes the object when the robot is on it,
``^drop`` lets go. Then the reasoner hears two numeric properties, the robot's position
and the target's (the object's while the robot's hand is empty, the goal's while it
holds the object), as ``<{position} |-> [pickPosX]>. :|: %v%`` with v = position / 20
(``dropPosX`` while holding). ``picked`` is input when the object is taken; when the
object is let go on the goal position ``delivered`` is input, it counts as a success and
object and goal move to new random positions. The goal is ``delivered`` every step.
The figure ONA prints is the number of deliveries.

ONA's test also asks a question each step for its own display, with question priming
off so that it does not steer attention; it is left out here.
"""

from __future__ import annotations

from collections.abc import Iterator

from .base import Feed, ProcedureEnv, event, goal

LOW, HIGH = 0, 20


def _property(subject: str, name: str, position: int) -> str:
    """A numeric property event in ONA's ``|->`` shorthand with the value as frequency."""
    value = min(1.0, max(0.0, (position - LOW) / (HIGH - LOW)))
    return f"<{{{subject}}} |-> [{name}]>. :|: %{value:.6f}%"


class Bandrobot(ProcedureEnv):
    """ONA's ``bandrobot`` test."""

    name = "bandrobot"
    operations = ("^left", "^right", "^pick", "^drop")
    shell_setup = ("*questionpriming=0.0",)
    reference_steps = 2_000

    def _reset_world(self) -> None:
        self.position = 0
        self.target = 1
        self.goal_position = 3
        self.picked = False
        self.was_picked = False
        self.holding = False
        self.fired: set[str] = set()
        self.score.extra.update(deliveries=0)

    def step(self) -> Iterator[Feed]:
        """Act on last step's operations, report the positions, reward, goal."""
        self.steps += 1
        self._act()
        name = "dropPosX" if self.holding else "pickPosX"
        aim = self.goal_position if self.holding else self.target
        feed: Feed = [
            _property("position", name, self.position),
            _property("targetposition", name, aim),
        ]
        if self.picked and not self.was_picked:
            feed.append(event("picked"))
        elif not self.picked and self.was_picked and self.position == self.goal_position:
            feed.append(event("delivered"))
            self.target = int(self.rng.random() * HIGH)
            self.goal_position = int(self.rng.random() * HIGH)
            self.score.successes += 1
            self.score.extra["deliveries"] += 1
        self.was_picked = self.picked
        feed.append(goal("delivered"))
        self.score.trials = self.steps
        yield feed

    def _act(self) -> None:
        fired, self.fired = self.fired, set()
        if "^left" in fired:
            self.position -= 1
        if "^right" in fired:
            self.position += 1
        self.position = min(HIGH, max(LOW, self.position))
        if self.picked:
            self.target = self.position
        if "^pick" in fired and self.position == self.target:
            self.picked = self.holding = True
        if "^drop" in fired:
            self.picked = self.holding = False

    def execute(self, op: str) -> None:
        """Flag the operation; it acts at the start of the next step."""
        if op in self.operations:
            self.fired.add(op)

    def metrics(self) -> dict[str, float]:
        """Deliveries: ONA prints this count as its ``ratio=`` figure for this test."""
        return {
            "ratio": self.score.extra["deliveries"],
            "deliveries": self.score.extra["deliveries"],
            "steps": self.steps,
        }
