"""What a robot senses, as small immutable values in SI units and radians.

A Body returns a list of these each cycle; a Mind turns them into its engine's input.
They carry no middleware type, so the same mind runs in a simulator or on ROS.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Sector = Literal["left", "front", "right", "none"]


@dataclass(frozen=True, slots=True)
class Detection:
    """An object seen by a camera: bearing is positive to the left of the optical axis."""

    label: str
    bearing: float
    distance: float
    confidence: float = 1.0
    instance: str | None = None


@dataclass(frozen=True, slots=True)
class Obstacle:
    """The nearest obstacle, by sector; sector ``none`` means nothing within range."""

    sector: Sector
    distance: float


def sonar_obstacle(left: float, right: float, reach: float) -> Obstacle:
    """The obstacle two ultrasonic sensors, left and right of the heading, report: in
    ``front`` when both meet something nearer than ``reach``, on the side of the one that
    does, else ``none``; at the nearer of the two distances. The simulated rooms and the
    Q.bo bridge read their sensors by this one rule."""
    if left < reach and right < reach:
        sector: Sector = "front"
    elif left < reach:
        sector = "left"
    elif right < reach:
        sector = "right"
    else:
        sector = "none"
    return Obstacle(sector, min(left, right))


@dataclass(frozen=True, slots=True)
class Pose:
    """Where the robot is; ``place`` names a known location (a checkpoint) if it is at one."""

    x: float
    y: float
    theta: float
    place: str | None = None


@dataclass(frozen=True, slots=True)
class Gripper:
    """What the gripper holds; None when it is open and empty."""

    holding: str | None = None


@dataclass(frozen=True, slots=True)
class Tag:
    """A fiducial (AprilTag) seen by the camera, with the name the task gives it."""

    id: int
    name: str


@dataclass(frozen=True, slots=True)
class Resting:
    """What the camera sees an object resting on: ``obj`` stands on ``on``.

    A body that sees where its tags are (a stack from heights and overlap, a cube over a
    bin) reports it; a mind may plan from it instead of being told in sentences.
    """

    obj: str
    on: str


@dataclass(frozen=True, slots=True)
class Range:
    """One range sensor's reading (an ultrasonic sensor, for instance)."""

    sensor: str
    distance: float


Percept = Detection | Obstacle | Pose | Gripper | Tag | Resting | Range
