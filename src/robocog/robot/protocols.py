"""The two sides of the contract: a Body senses and acts, a Mind perceives and decides.

Worlds and bridges implement Body; the adapters in ``robocog.minds`` implement Mind.
Neither side knows the other's internals, so any mind can drive any body.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol, runtime_checkable

from robocog.robot.commands import Command, Outcome
from robocog.robot.percepts import Percept


@runtime_checkable
class Body(Protocol):
    """A robot, simulated or real."""

    def percepts(self) -> list[Percept]:
        """What the robot senses now."""
        ...

    def execute(self, command: Command) -> Outcome:
        """Carry out one command and report how it ended."""
        ...

    def time(self) -> float:
        """The body's clock in seconds (simulated time in a world, wall time on a robot)."""
        ...


@runtime_checkable
class Mind(Protocol):
    """A reasoning engine behind the contract.

    A mind may also have a ``tidy()`` method, not part of the protocol: upkeep that the
    robot's loop runs between cycles, outside their timing, so that it never pauses a
    decision (see :func:`robocog.robot.loop.tidy`).
    """

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Take in what the body senses this cycle."""
        ...

    def decide(self) -> list[Command]:
        """Reason, and return the commands to execute now (possibly none)."""
        ...

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Learn how a command ended."""
        ...
