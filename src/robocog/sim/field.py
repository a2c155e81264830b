"""What a sensor of the garbage field reads, for the simulators of every middleware.

The ROS 2 sim (Cyclone DDS, this Python) and the ROS 1 sim (rospy, the system's Python)
both serve the field; the geometry of the laser, the camera's pinhole model and the
reading of a navigation goal as a place live here, in plain Python that either can
import, so the two robots read alike.
"""

from __future__ import annotations

import math

from robocog.worlds.garbage import GarbageField

#: the camera image the detections are drawn in (px)
IMAGE_WIDTH = 640.0
IMAGE_HEIGHT = 480.0
#: beams of the simulated laser, all around, and its reach (m)
BEAMS = 360
RANGE_MAX = 12.0


def column_of(bearing: float, fov: float, width: float = IMAGE_WIDTH) -> float:
    """The image column of a bearing (positive to the left) for a pinhole camera."""
    focal = (width / 2) / math.tan(fov / 2)
    return width / 2 - focal * math.tan(bearing)


def fence_ranges(x: float, y: float, theta: float, size: float, beams: int = BEAMS) -> list[float]:
    """Ranges of ``beams`` rays all around (from -pi) to the square fence [0, size]^2."""
    out: list[float] = []
    for i in range(beams):
        a = theta - math.pi + 2 * math.pi * i / beams
        dx, dy = math.cos(a), math.sin(a)
        best = math.inf
        if dx > 1e-12:
            best = min(best, (size - x) / dx)
        elif dx < -1e-12:
            best = min(best, -x / dx)
        if dy > 1e-12:
            best = min(best, (size - y) / dy)
        elif dy < -1e-12:
            best = min(best, -y / dy)
        out.append(best if best <= RANGE_MAX else math.inf)
    return out


def target_place(world: GarbageField, x: float, y: float) -> str | None:
    """The place a navigation goal at (x, y) means: a checkpoint within the field's
    radius, the start corner, or None (a drive to the point)."""
    radius = world.config.place_radius
    sx, sy = world.start
    best, best_d = None, radius
    for name, (px, py) in world.checkpoints.items():
        d = math.hypot(px - x, py - y)
        if d <= best_d:
            best, best_d = name, d
    if best is None and math.hypot(sx - x, sy - y) <= radius:
        return "start"
    return best
