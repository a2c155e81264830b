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
    #: ROS 2: the Nav2 action ``nav2_msgs/action/NavigateToPose`` that takes GoTo goals
    navigate_action: str = "/navigate_to_pose"
    #: ROS 2: the gripper action (``robocog_msgs/action/Grasp``: pick or drop)
    grasp_action: str = "/gripper/grasp"
    #: ROS 2: the simulator's lock-step acknowledgement (builtin_interfaces/Time)
    frame_done: str = "/sim/frame_done"
    #: ROS 1: the move_base action namespace.
    move_base: str = "/move_base"
    #: the robot's mission state (std_msgs/String): ``ended: WHY`` when the robot (or the
    #: simulator) has ended its mission; the bridge then ends too, saying why
    mission: str = "/mission/state"


#: settings where 0 means "not watched"
_MAY_BE_ZERO = {"scan_timeout", "pose_timeout", "detections_timeout"}
#: settings that are angles (rad)
_ANGLES = {"front_half_width", "obstacle_half_width", "horizontal_fov"}


@dataclass(frozen=True)
class BridgeConfig:
    """All settings of a bridge; the defaults suit a Nav2 / move_base robot."""

    topics: Topics = field(default_factory=Topics)
    #: name -> (x, y, theta) in the map frame
    places: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    #: the places in the order a patrol visits them: ``GoTo("next")`` is the place after
    #: the last one reached (empty: the order of ``places``)
    route: tuple[str, ...] = ()
    #: where the route begins and ends, ``GoTo("start")`` (None: the route's first place);
    #: not a place the pose is named after, as the garbage field's start corner is not
    start: tuple[float, float, float] | None = None
    #: how close (m) the robot must be to a place to be "at" it
    place_radius: float = 0.5
    #: ``amcl`` reads /amcl_pose (PoseWithCovarianceStamped), ``odom`` reads /odom
    pose_source: str = "amcl"
    map_frame: str = "map"
    #: obstacles farther than this (m) are not reported, as in the paper's 2 m lidar
    obstacle_range: float = 2.0
    #: half width (rad) of the front sector of the scan
    front_half_width: float = math.pi / 6
    #: returns farther off the heading than this (rad) are ignored (pi: all around)
    obstacle_half_width: float = math.pi / 2
    #: a Pose percept only in the cycle after a pose arrived (localisation as an event),
    #: rather than the latest pose every cycle
    pose_on_arrival: bool = False
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
    #: wait this long (s) for the result of the gripper action (a grasp approaches first)
    grasp_timeout: float = 60.0
    #: a GoTo waits this long (s) for the navigation result, then cancels and fails
    goto_timeout: float = 120.0
    #: percepts older than this (s) trip the watchdog and stop the robot
    watchdog_seconds: float = 1.0
    #: a sensor that has reported must report again within its limit (s), else the
    #: watchdog stops the robot; None: ``watchdog_seconds``; 0: not watched
    scan_timeout: float | None = None
    pose_timeout: float = 0.0
    detections_timeout: float = 0.0
    #: a mind that takes longer than this (s) for one cycle trips the watchdog
    mind_timeout: float = 5.0
    #: this many mind failures in a row end the run (the robot stays stopped)
    max_mind_failures: int = 3
    #: the cycle waits at most this long (s) for new percepts before deciding anyway
    cycle_period: float = 0.1
    #: one decision per laser scan (the frame of a robot or a simulator), acknowledged
    #: on ``frame_done`` so that a lock-step simulator can step on
    lockstep: bool = False

    def __post_init__(self) -> None:
        """Every number finite and in its range, so that a typo in a robot's file is an
        error naming the setting, not a watchdog that never trips or a NaN velocity."""
        for f in fields(self):
            value = getattr(self, f.name)
            kind = str(f.type)
            if kind in ("float", "float | None", "int"):
                if value is None and kind == "float | None":
                    continue
                if isinstance(value, bool) or not isinstance(value, int | float):
                    raise ValueError(f"{f.name} must be a number, not {value!r}")
                if not math.isfinite(value):
                    raise ValueError(f"{f.name} must be a finite number, not {value!r}")
                if f.name in _MAY_BE_ZERO:
                    if value < 0:
                        raise ValueError(f"{f.name} must be 0 (not watched) or more, not {value!r}")
                elif f.name in _ANGLES:
                    if not 0 < value <= 2 * math.pi:
                        raise ValueError(f"{f.name} is an angle above 0 up to 2 pi, not {value!r}")
                elif value <= 0:
                    raise ValueError(f"{f.name} must be above 0, not {value!r}")
            elif kind == "bool" and not isinstance(value, bool):
                raise ValueError(f"{f.name} must be true or false, not {value!r}")
        poses = [(f"place {n!r}", p) for n, p in self.places.items()]
        if self.start is not None:
            poses.append(("start", self.start))
        for what, pose in poses:
            if not all(isinstance(v, int | float) and math.isfinite(v) for v in pose):
                raise ValueError(f"{what} must be finite numbers, not {list(pose)}")
        if self.pose_source not in ("amcl", "odom"):
            raise ValueError(f"pose_source is amcl or odom, not {self.pose_source!r}")

    @classmethod
    def preset(cls, name: str) -> BridgeConfig:
        """A configuration shipped with robocog (``robocog/bridges/robots/NAME.toml``)."""
        import importlib.resources

        if not name.replace("_", "").replace("-", "").isalnum():
            raise ValueError(f"not a robot name: {name!r}")
        resource = importlib.resources.files("robocog.bridges").joinpath("robots", f"{name}.toml")
        if not resource.is_file():
            raise ValueError(f"no shipped robot configuration {name!r}")
        return cls.from_dict(tomllib.loads(resource.read_text()), source=f"robot {name}")

    @classmethod
    def from_toml(cls, path: str | Path) -> BridgeConfig:
        """Read a configuration file; unknown keys are an error that names them."""
        with open(path, "rb") as handle:
            try:
                data = tomllib.load(handle)
            except tomllib.TOMLDecodeError as exc:
                raise ValueError(f"{path}: not TOML: {exc}") from None
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
        if "route" in data:
            data["route"] = tuple(str(n) for n in data["route"])
            missing = [n for n in data["route"] if n not in places]
            if missing:
                raise ValueError(f"{source}: route names unknown places {missing}")
        if "start" in data:
            value = data["start"]
            if not isinstance(value, list | tuple) or len(value) not in (2, 3):
                raise ValueError(f"{source}: start must be [x, y] or [x, y, theta]")
            x, y, *rest = (float(v) for v in value)
            data["start"] = (x, y, rest[0] if rest else 0.0)
        try:
            config = cls(topics=Topics(**topics_data), places=places)
            return replace(config, **data)
        except ValueError as exc:
            raise ValueError(f"{source}: {exc}") from None

    @property
    def route_places(self) -> tuple[str, ...]:
        """The patrol's places in order: ``route``, else every place as configured."""
        return self.route or tuple(self.places)

    def resolve(
        self, place: str, last: str | None
    ) -> tuple[str, tuple[float, float, float]] | None:
        """Where ``GoTo(place)`` leads: its name and map pose, or None for an unknown place.

        ``next`` is the route's place after ``last`` (the last route place reached; the
        route's first when none), and after the route's end the start; ``start`` is the
        configured start, else the route's first place. A configured place of either
        name wins over the meaning.
        """
        if place in self.places:
            return place, self.places[place]
        route = self.route_places
        if place in ("next", ""):
            if not route:
                return None
            i = route.index(last) + 1 if last in route else 0
            if i < len(route):
                return route[i], self.places[route[i]]
            place = "start"
        if place == "start":
            if self.start is not None:
                return "start", self.start
            if route:
                return route[0], self.places[route[0]]
        return None
