"""Small parts of the physical garbage robot, kept apart from its body: the arm's
inverse kinematics and poses, the camera's object tracks, and the run's cost counters."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from robocog.worlds.physics import field_scene as fs
from robocog.worlds.physics.mobile_base import wrap


def arm_angles(x: float, z: float, pitch: float = 0.0) -> tuple[float, float, float]:
    """Shoulder, elbow and wrist angles that put the grasp point at ``(x, z)`` in the
    base's frame with the hand pointing at ``pitch`` below the horizon (elbow up).

    Joint angles are positive downwards (rotation about the base's y axis).
    """
    sx, _sy, sz = fs.SHOULDER
    wx = x - fs.PALM_TO_GRASP * math.cos(pitch) - sx
    wz = z + fs.PALM_TO_GRASP * math.sin(pitch) - (sz)
    down = -wz
    r2 = wx * wx + down * down
    c2 = (r2 - fs.UPPER**2 - fs.FORE**2) / (2 * fs.UPPER * fs.FORE)
    c2 = max(-1.0, min(1.0, c2))
    q2 = math.acos(c2)
    q1 = math.atan2(down, wx) - math.atan2(fs.FORE * math.sin(q2), fs.UPPER + fs.FORE * c2)
    q3 = pitch - q1 - q2
    return q1, q2, wrap(q3)


#: the arm's poses: folded over the chassis out of the camera's view, carrying, and
#: over the tray (hand pointing back)
STOW = (0.12, 0.40, math.pi)
CARRY = (0.45, 0.42, 0.0)
TRAY = (-0.12, 0.5, math.pi)


@dataclass
class Track:
    """An object the camera has seen: its label and estimated place on the field."""

    instance: str
    label: str
    x: float
    y: float
    seen: int = 1
    #: where the latest frame put it (the approach aims at this, not the average)
    last: tuple[float, float] = (0.0, 0.0)


@dataclass
class Costs:
    """Where the wall-clock time went."""

    frames: int = 0
    render_seconds: float = 0.0
    detections: int = 0
    detect_seconds: float = 0.0
    scans: int = 0
    scan_seconds: float = 0.0
    steps: int = 0
    step_seconds: float = 0.0
    extra: dict[str, float] = field(default_factory=dict)
