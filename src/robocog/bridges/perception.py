"""From raw sensor readings to percepts, with no middleware type in sight.

Both bridges turn their messages into the small readings below and hand them to the
same functions, so a laser scan means the same obstacle on ROS 2 as on ROS 1 and the
conversions are tested once, without a middleware running.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from robocog.robot.percepts import Detection, Obstacle, Pose, Sector


@dataclass(frozen=True, slots=True)
class ScanReading:
    """The part of a planar laser scan that matters here (sensor_msgs/LaserScan)."""

    angle_min: float
    angle_increment: float
    range_min: float
    range_max: float
    ranges: Sequence[float]


@dataclass(frozen=True, slots=True)
class BoxReading:
    """One 2D detection: its class, score, the box centre in pixels, and the hypothesis
    position (camera frame, metres) when the detector gives one, else all zeros."""

    label: str
    score: float
    center_x: float
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    instance: str | None = None


@dataclass(frozen=True, slots=True)
class PoseReading:
    """A planar pose: position in metres and heading (yaw) in radians."""

    x: float
    y: float
    yaw: float


def nearest_obstacle(
    scan: ScanReading,
    within: float = 2.0,
    front_half_width: float = math.pi / 6,
    half_width: float = math.pi / 2,
) -> Obstacle:
    """The sector of the nearest valid return closer than ``within`` metres.

    A return is valid when it is finite and inside the scanner's own limits. Bearings
    within ``front_half_width`` of straight ahead are ``front``, larger positive ones
    ``left`` and negative ones ``right`` (ROS angles grow counter-clockwise). Returns
    beyond ``half_width`` (by default behind the robot, beyond +-90 degrees) are
    ignored: a robot cannot drive into them.
    With nothing in range the sector is ``none`` at distance ``within``.
    """
    best = within
    best_angle: float | None = None
    for i, r in enumerate(scan.ranges):
        if not math.isfinite(r) or r < scan.range_min or r > scan.range_max:
            continue
        raw = scan.angle_min + i * scan.angle_increment
        if not math.isfinite(raw):
            continue  # (absurd angles: a ray with no direction)
        angle = _wrap(raw)
        if abs(angle) > half_width:
            continue
        if r < best:
            best, best_angle = r, angle
    if best_angle is None:
        return Obstacle("none", within)
    return Obstacle(sector_of(best_angle, front_half_width), best)


def sector_of(angle: float, front_half_width: float = math.pi / 6) -> Sector:
    """``left``, ``front`` or ``right`` for a bearing in radians, positive to the left."""
    if abs(angle) <= front_half_width:
        return "front"
    return "left" if angle > 0 else "right"


def bearing_of(center_x: float, image_width: float, horizontal_fov: float) -> float:
    """The bearing of a pixel column, positive to the left, for a pinhole camera.

    The centre column is straight ahead; the image edges are at half the field of view.
    """
    if image_width <= 0:
        raise ValueError("image width must be positive")
    focal = (image_width / 2) / math.tan(horizontal_fov / 2)
    return math.atan2(image_width / 2 - center_x, focal)


def detection_of(box: BoxReading, image_width: float, horizontal_fov: float) -> Detection:
    """A Detection from a box: bearing from the column, distance from the hypothesis
    position when the detector supplied one (NaN when it did not)."""
    x, y, z = box.position
    distance = math.sqrt(x * x + y * y + z * z) if (x or y or z) else math.nan
    return Detection(
        label=box.label,
        bearing=bearing_of(box.center_x, image_width, horizontal_fov),
        distance=distance,
        confidence=box.score,
        instance=box.instance,
    )


def yaw_of(qx: float, qy: float, qz: float, qw: float) -> float:
    """The heading (rotation about z) of a unit quaternion."""
    return math.atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))


def quaternion_of(yaw: float) -> tuple[float, float, float, float]:
    """The unit quaternion (x, y, z, w) of a rotation by ``yaw`` about z."""
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


def place_at(
    x: float, y: float, places: Mapping[str, tuple[float, float, float]], radius: float
) -> str | None:
    """The name of the nearest known place within ``radius`` metres, if any."""
    best: str | None = None
    best_d = radius
    for name, (px, py, _theta) in places.items():
        d = math.hypot(px - x, py - y)
        if d <= best_d:
            best, best_d = name, d
    return best


def pose_of(
    reading: PoseReading, places: Mapping[str, tuple[float, float, float]], radius: float
) -> Pose:
    """A Pose percept, naming the place the robot is at when it is near one."""
    return Pose(reading.x, reading.y, reading.yaw, place_at(reading.x, reading.y, places, radius))


def _wrap(angle: float) -> float:
    return math.atan2(math.sin(angle), math.cos(angle))
