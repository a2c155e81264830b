"""Plane geometry of the room: angles, rays, distances and line of sight."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from robocog.worlds.room_geometry import (
    Segment,
    cast,
    line_of_sight,
    point_segment_distance,
    ray_hit,
    wrap,
)

coord = st.floats(min_value=-10.0, max_value=10.0, allow_nan=False)


@given(st.floats(min_value=-100.0, max_value=100.0, allow_nan=False))
def test_wrap_lands_in_the_half_open_circle_and_keeps_the_direction(angle: float) -> None:
    w = wrap(angle)
    assert -math.pi < w <= math.pi + 1e-12
    assert math.isclose(math.cos(w), math.cos(angle), abs_tol=1e-9)
    assert math.isclose(math.sin(w), math.sin(angle), abs_tol=1e-9)


@given(coord, coord, coord, coord, st.floats(min_value=0.05, max_value=0.95), coord, coord)
def test_a_ray_aimed_at_a_point_of_a_segment_hits_it_there(
    ax: float, ay: float, bx: float, by: float, t: float, ox: float, oy: float
) -> None:
    seg = Segment(ax, ay, bx, by)
    px, py = seg.point(t)
    d = math.hypot(px - ox, py - oy)
    if seg.length < 1e-3 or d < 1e-3:
        return
    angle = math.atan2(py - oy, px - ox)
    hit = ray_hit(ox, oy, angle, seg)
    ex, ey = bx - ax, by - ay
    along = abs(math.cos(angle) * ey - math.sin(angle) * ex) < 1e-6 * seg.length
    if hit is None:  # only when the ray runs along the segment
        assert along
        return
    if along:
        return  # a ray grazing along the segment meets it at no well-defined point
    hx, hy = ox + hit * math.cos(angle), oy + hit * math.sin(angle)
    assert point_segment_distance(hx, hy, seg) < 1e-6 * max(1.0, d)
    assert hit <= d + 1e-6 * max(1.0, d)


def test_cast_returns_the_nearest_wall_or_the_limit() -> None:
    walls = [Segment(2.0, -1.0, 2.0, 1.0), Segment(5.0, -1.0, 5.0, 1.0)]
    assert math.isclose(cast(0.0, 0.0, 0.0, walls, 10.0), 2.0)
    assert cast(0.0, 0.0, math.pi, walls, 10.0) == 10.0
    assert point_segment_distance(2.0, 3.0, walls[0]) == 2.0


def test_line_of_sight_is_blocked_by_a_crossing_wall_only() -> None:
    wall = [Segment(1.0, -1.0, 1.0, 1.0)]
    assert not line_of_sight((0.0, 0.0), (2.0, 0.0), wall)
    assert line_of_sight((0.0, 0.0), (2.0, 2.0), wall)
    assert line_of_sight((0.0, 0.0), (0.5, 0.0), wall)
