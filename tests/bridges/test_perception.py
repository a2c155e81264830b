"""Scans, boxes and poses become the contract's percepts the same way on every ROS."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.bridges.perception import (
    BoxReading,
    PoseReading,
    ScanReading,
    bearing_of,
    detection_of,
    nearest_obstacle,
    place_at,
    pose_of,
    quaternion_of,
    sector_of,
    yaw_of,
)
from robocog.robot import Obstacle


def scan_with(hits: dict[float, float], beams: int = 361) -> ScanReading:
    """A full-circle scan, clear except for returns at the given bearings (degrees)."""
    inc = 2 * math.pi / (beams - 1)
    ranges = [math.inf] * beams
    for degrees, distance in hits.items():
        ranges[round((math.radians(degrees) + math.pi) / inc)] = distance
    return ScanReading(-math.pi, inc, 0.1, 30.0, ranges)


def test_the_nearest_return_names_the_sector() -> None:
    assert nearest_obstacle(scan_with({50: 1.2, -60: 1.5})) == Obstacle("left", 1.2)
    assert nearest_obstacle(scan_with({50: 1.9, -60: 0.7})).sector == "right"
    assert nearest_obstacle(scan_with({10: 1.0, 60: 0.9})).sector == "left"
    assert nearest_obstacle(scan_with({-20: 0.4})).sector == "front"


def test_nothing_within_range_is_sector_none() -> None:
    assert nearest_obstacle(scan_with({30: 2.5})) == Obstacle("none", 2.0)
    assert nearest_obstacle(scan_with({30: 2.5}), within=3.0) == Obstacle("left", 2.5)


def test_invalid_and_rear_returns_are_ignored() -> None:
    inc = math.radians(1)
    rear = ScanReading(math.radians(120), inc, 0.1, 30.0, [0.5] * 10)
    assert nearest_obstacle(rear).sector == "none"
    bad = ScanReading(0.0, inc, 0.1, 30.0, [math.nan, 0.05, 40.0, -1.0, math.inf])
    assert nearest_obstacle(bad).sector == "none"


@given(st.floats(-math.pi / 2, math.pi / 2))
def test_sector_follows_the_sign_of_the_bearing(angle: float) -> None:
    sector = sector_of(angle)
    if abs(angle) <= math.pi / 6:
        assert sector == "front"
    else:
        assert sector == ("left" if angle > 0 else "right")


def test_bearing_is_zero_at_the_centre_and_half_the_fov_at_the_edges() -> None:
    fov = math.radians(60)
    assert bearing_of(320, 640, fov) == pytest.approx(0.0)
    assert bearing_of(0, 640, fov) == pytest.approx(fov / 2)
    assert bearing_of(640, 640, fov) == pytest.approx(-fov / 2)
    with pytest.raises(ValueError):
        bearing_of(1, 0, fov)


def test_a_box_becomes_a_detection() -> None:
    d = detection_of(BoxReading("bottle", 0.8, 100, (0.0, 0.0, 2.0), "b1"), 640, math.radians(60))
    assert (d.label, d.confidence, d.instance, d.distance) == ("bottle", 0.8, "b1", 2.0)
    assert d.bearing > 0  # left half of the image is to the left
    assert math.isnan(detection_of(BoxReading("cup", 0.5, 320), 640, 1.0).distance)


@given(st.floats(-3.1, 3.1))
def test_yaw_survives_the_quaternion_round_trip(yaw: float) -> None:
    assert yaw_of(*quaternion_of(yaw)) == pytest.approx(yaw, abs=1e-9)


def test_the_nearest_place_within_the_radius_is_named() -> None:
    places = {"bin": (2.0, 1.0, 0.0), "door": (2.3, 1.0, 0.0)}
    assert place_at(2.1, 1.0, places, 0.5) == "bin"
    assert place_at(2.25, 1.0, places, 0.5) == "door"
    assert place_at(5.0, 5.0, places, 0.5) is None
    assert pose_of(PoseReading(2.0, 1.1, 0.3), places, 0.5).place == "bin"
