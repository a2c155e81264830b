"""What a bridge needs to know about one robot: topic names, places, speeds, limits.

Every topic name is configurable because no two robots name them alike; the places map
names a mind uses (``GoTo("bin")``) to map coordinates that a navigator accepts. The
configuration is read from a TOML file so that it can sit beside a robot's launch files.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any


@dataclass(frozen=True)
class Topics:
    """ROS topic names, written as ROS writes them (``/scan``, ``/robot1/cmd_vel``)."""

    narsese: str = "/narsese"
    scan: str = "/scan"
    detections: str = "/detections"
    amcl_pose: str = "/amcl_pose"
    odom: str = "/odom"
    gripper_state: str = "/gripper/state"
    gripper_command: str = "/gripper/command"
    cmd_vel: str = "/cmd_vel"
    goal_pose: str = "/goal_pose"
    #: ROS 2: the Nav2 action whose goals a cancel stops (its cancel service is used).
    navigate_action: str = "/navigate_to_pose"
    #: ROS 1: the move_base action namespace.
    move_base: str = "/move_base"


@dataclass(frozen=True)
class BridgeConfig:
    """All settings of a bridge; the defaults suit a Nav2 / move_base robot."""

    topics: Topics = field(default_factory=Topics)
    #: name -> (x, y, theta) in the map frame
    places: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    #: how close (m) the robot must be to a place to be "at" it
    place_radius: float = 0.5
    #: ``amcl`` reads /amcl_pose (PoseWithCovarianceStamped), ``odom`` reads /odom
    pose_source: str = "amcl"
    map_frame: str = "map"
    #: obstacles farther than this (m) are not reported, as in the paper's 2 m lidar
    obstacle_range: float = 2.0
    #: half width (rad) of the front sector of the scan
    front_half_width: float = math.pi / 6
    #: camera image width (px) and horizontal field of view (rad) for bearings
    image_width: float = 640.0
    horizontal_fov: float = math.radians(60.0)
    #: ROS 1 detections carry integer class ids; this list names them
    class_names: tuple[str, ...] = ()
    #: detections older than this (s) are no longer seen
    detection_ttl: float = 0.5
    linear_speed: float = 0.2
    angular_speed: float = 0.6
    #: a single Forward/Turn never drives longer than this (s)
    max_motion_seconds: float = 5.0
    #: how often (Hz) velocity is re-published while a motion runs
    command_rate: float = 10.0
    #: wait this long (s) for the gripper to report the grasp or the release
    gripper_timeout: float = 3.0
    #: 0 returns from GoTo once the goal is sent; more waits that long for arrival
    goto_wait: float = 0.0
    #: percepts older than this (s) trip the watchdog and stop the robot
    watchdog_seconds: float = 1.0
    #: a mind that takes longer than this (s) for one cycle trips the watchdog
    mind_timeout: float = 5.0
    #: this many mind failures in a row end the run (the robot stays stopped)
    max_mind_failures: int = 3
    #: the cycle waits at most this long (s) for new percepts before deciding anyway
    cycle_period: float = 0.1

    @classmethod
    def from_toml(cls, path: str | Path) -> BridgeConfig:
        """Read a configuration file; unknown keys are an error that names them."""
        with open(path, "rb") as handle:
            data = tomllib.load(handle)
        return cls.from_dict(data, source=str(path))

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str = "configuration") -> BridgeConfig:
        """Build a configuration from plain data (``[topics]`` and ``[places]`` tables)."""
        data = dict(data)
        topics_data = data.pop("topics", {})
        places_data = data.pop("places", {})
        known_topics = {f.name for f in fields(Topics)}
        unknown = set(topics_data) - known_topics
        if unknown:
            raise ValueError(f"{source}: unknown topic keys {sorted(unknown)}")
        known = {f.name for f in fields(cls)} - {"topics", "places"}
        unknown = set(data) - known
        if unknown:
            raise ValueError(f"{source}: unknown keys {sorted(unknown)}")
        places: dict[str, tuple[float, float, float]] = {}
        for name, value in places_data.items():
            if not isinstance(value, list | tuple) or len(value) not in (2, 3):
                raise ValueError(f"{source}: place {name!r} must be [x, y] or [x, y, theta]")
            x, y, *rest = (float(v) for v in value)
            places[name] = (x, y, rest[0] if rest else 0.0)
        if "class_names" in data:
            data["class_names"] = tuple(str(n) for n in data["class_names"])
        config = cls(topics=Topics(**topics_data), places=places)
        return replace(config, **data)
