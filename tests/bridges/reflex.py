"""A small deterministic mind for the bridge tests: turn away from obstacles, pick what
is seen, otherwise creep forward. It stands in for the engines' minds so the bridges are
tested on their own."""

from __future__ import annotations

from collections.abc import Sequence

from robocog.minds.registry import MindConfig
from robocog.robot import (
    Cancel,
    Command,
    Detection,
    Forward,
    GoTo,
    Obstacle,
    Outcome,
    Percept,
    Pick,
    Turn,
)
from robocog.robot.percepts import Gripper


class ReflexMind:
    """Obstacle left -> turn right, obstacle right or front -> turn left, a seen target
    with an empty gripper -> pick it. It understands two lines of text: ``goto PLACE``
    and ``cancel``, obeyed first. It records what it hears and every outcome."""

    def __init__(self, target: str = "bottle", creep: float = 0.0) -> None:
        self.target = target
        self.creep = creep
        self.percepts: list[Percept] = []
        self.heard: list[str] = []
        self.outcomes: list[tuple[Command, Outcome]] = []
        self.orders: list[Command] = []

    def hear(self, text: str) -> None:
        self.heard.append(text)
        words = text.split()
        if words[:1] == ["goto"] and len(words) == 2:
            self.orders.append(GoTo(words[1]))
        elif words == ["cancel"]:
            self.orders.append(Cancel())

    def perceive(self, percepts: Sequence[Percept]) -> None:
        self.percepts = list(percepts)

    def decide(self) -> list[Command]:
        if self.orders:
            return [self.orders.pop(0)]
        holding = next((p.holding for p in self.percepts if isinstance(p, Gripper)), None)
        for p in self.percepts:
            if isinstance(p, Obstacle) and p.sector == "left":
                return [Turn(-0.3)]
            if isinstance(p, Obstacle) and p.sector in ("right", "front"):
                return [Turn(0.3)]
        for p in self.percepts:
            if isinstance(p, Detection) and p.label == self.target and holding is None:
                return [Pick(self.target)]
        return [Forward(self.creep)] if self.creep else []

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        self.outcomes.append((command, outcome))


def make(config: MindConfig) -> ReflexMind:
    """The factory the command line names as ``--mind tests.bridges.reflex:make``: the
    source file, when one is given, names the target."""
    text = config.text()
    return ReflexMind() if text is None else ReflexMind(text.strip())
