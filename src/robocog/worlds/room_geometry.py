"""Plane geometry for the room world: wall segments, ray casting and line of sight.

The room is a handful of line segments, so plain Python is fast enough and keeps the
world free of numerical dependencies.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Segment:
    """A wall, a door leaf or the side of a box, from (ax, ay) to (bx, by), in metres."""

    ax: float
    ay: float
    bx: float
    by: float

    def point(self, t: float) -> tuple[float, float]:
        """The point at fraction ``t`` (0..1) along the segment."""
        return (self.ax + (self.bx - self.ax) * t, self.ay + (self.by - self.ay) * t)

    @property
    def length(self) -> float:
        """Length in metres."""
        return math.hypot(self.bx - self.ax, self.by - self.ay)


def wrap(angle: float) -> float:
    """An angle in radians brought into (-pi, pi]."""
    a = math.fmod(angle + math.pi, 2.0 * math.pi)
    if a <= 0.0:
        a += 2.0 * math.pi
    return a - math.pi


def ray_hit(ox: float, oy: float, angle: float, seg: Segment) -> float | None:
    """Distance along a ray from (ox, oy) at ``angle`` to ``seg``, or None if it misses."""
    dx, dy = math.cos(angle), math.sin(angle)
    ex, ey = seg.bx - seg.ax, seg.by - seg.ay
    denom = dx * ey - dy * ex
    if abs(denom) < 1e-12:
        return None
    wx, wy = seg.ax - ox, seg.ay - oy
    t = (wx * ey - wy * ex) / denom
    u = (wx * dy - wy * dx) / denom
    if t >= 0.0 and -1e-9 <= u <= 1.0 + 1e-9:
        return t
    return None


def cast(ox: float, oy: float, angle: float, segments: list[Segment], limit: float) -> float:
    """Distance to the nearest segment along a ray, capped at ``limit``."""
    best = limit
    for seg in segments:
        t = ray_hit(ox, oy, angle, seg)
        if t is not None and t < best:
            best = t
    return best


def point_segment_distance(px: float, py: float, seg: Segment) -> float:
    """Shortest distance from a point to a segment."""
    ex, ey = seg.bx - seg.ax, seg.by - seg.ay
    length2 = ex * ex + ey * ey
    if length2 == 0.0:
        return math.hypot(px - seg.ax, py - seg.ay)
    t = max(0.0, min(1.0, ((px - seg.ax) * ex + (py - seg.ay) * ey) / length2))
    return math.hypot(px - (seg.ax + t * ex), py - (seg.ay + t * ey))


def _orient(ax: float, ay: float, bx: float, by: float, cx: float, cy: float) -> float:
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def segments_cross(p: tuple[float, float], q: tuple[float, float], seg: Segment) -> bool:
    """True when the open segment p-q properly crosses ``seg`` (touching ends do not count)."""
    d1 = _orient(seg.ax, seg.ay, seg.bx, seg.by, p[0], p[1])
    d2 = _orient(seg.ax, seg.ay, seg.bx, seg.by, q[0], q[1])
    d3 = _orient(p[0], p[1], q[0], q[1], seg.ax, seg.ay)
    d4 = _orient(p[0], p[1], q[0], q[1], seg.bx, seg.by)
    return d1 * d2 < 0.0 and d3 * d4 < 0.0


def line_of_sight(p: tuple[float, float], q: tuple[float, float], segments: list[Segment]) -> bool:
    """True when nothing in ``segments`` lies between p and q."""
    return not any(segments_cross(p, q, seg) for seg in segments)
