"""What a mind asks a body to do, and how each request ended.

Every command ends with exactly one Outcome; a mind learns from outcomes (NARS turns
them into events, a BDI agent completes the pending action with them).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from enum import Enum


@dataclass(frozen=True, slots=True)
class Forward:
    """Drive straight ahead by ``distance`` metres (negative backs up)."""

    distance: float


@dataclass(frozen=True, slots=True)
class Turn:
    """Turn in place by ``angle`` radians, positive to the left."""

    angle: float


@dataclass(frozen=True, slots=True)
class GoTo:
    """Navigate to a named place (a checkpoint, a door, a bin)."""

    place: str


@dataclass(frozen=True, slots=True)
class Cancel:
    """Stop whatever motion is under way."""


@dataclass(frozen=True, slots=True)
class Pick:
    """Grasp an object in front of the robot, by label or by instance."""

    target: str


@dataclass(frozen=True, slots=True)
class Drop:
    """Open the gripper and release what it holds."""


@dataclass(frozen=True, slots=True)
class Look:
    """Point the camera (or the head) in a direction: left, front, right, or an angle name."""

    direction: str

    def views(self, names: Iterable[str]) -> list[str] | None:
        """The views of ``names`` (a head's pans, in order) this look takes: all of them
        for ``around``, the one named, or None for a direction the head has not."""
        names = list(names)
        if self.direction == "around":
            return names
        return [self.direction] if self.direction in names else None


@dataclass(frozen=True, slots=True)
class PickUp:
    """Manipulator: take ``obj`` from the table."""

    obj: str


@dataclass(frozen=True, slots=True)
class PutDown:
    """Manipulator: put the held ``obj`` on ``on`` (the table by default)."""

    obj: str
    on: str = "table"


@dataclass(frozen=True, slots=True)
class Stack:
    """Manipulator: put the held ``obj`` on top of ``on``."""

    obj: str
    on: str


@dataclass(frozen=True, slots=True)
class Unstack:
    """Manipulator: take ``obj`` from the top of ``frm``."""

    obj: str
    frm: str


Command = Forward | Turn | GoTo | Cancel | Pick | Drop | Look | PickUp | PutDown | Stack | Unstack


class Status(Enum):
    """How a command ended."""

    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"


@dataclass(frozen=True, slots=True)
class Outcome:
    """The end of one command; ``reason`` says why it failed or was cancelled."""

    status: Status
    reason: str = ""

    @property
    def ok(self) -> bool:
        """True when the command succeeded."""
        return self.status is Status.SUCCEEDED

    @classmethod
    def success(cls) -> Outcome:
        """The outcome of a command that did what was asked."""
        return cls(Status.SUCCEEDED)

    @classmethod
    def failure(cls, reason: str) -> Outcome:
        """The outcome of a command that could not be done, and why."""
        return cls(Status.FAILED, reason)

    @classmethod
    def cancelled(cls, reason: str = "") -> Outcome:
        """The outcome of a command stopped before it ended."""
        return cls(Status.CANCELLED, reason)
