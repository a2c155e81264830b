"""A room whose door opens inward, with a corridor and the opposite room's door beyond.

This is the scene of the Q.bo experiment (Fujita et al., Sections 2-3): the robot starts
inside a room, must reach the front of the open door leaf and from there find the
doorway and leave. Through the doorway the door of the room across the corridor can be
seen, and it looks like a door to the robot's detector, which is how the paper's robot
came to stop at the wrong place.

The body offers what the Q.bo offers:

* ``Look("around")``: three images taken with the head turned left, ahead and right
  (about 160 degrees in all), each split into 3 x 2 areas. A noisy detector gives every
  area a certainty per label (``door``, ``entry``); the areas above the certainty
  threshold come back as :class:`Detection` percepts until the robot next moves.
  ``Look("left"|"front"|"right")`` takes a single image.
* ``Forward(d)``: drive straight, stopping early when an ultrasonic sensor reads less
  than the stop distance, or when the body bumps into something (a door jamb is thin
  enough to slip between the two sensors' beams).
* ``Turn(a)``: turn in place.
* Percepts every cycle: the heading (``Pose``), the two ultrasonic sensors (``Range``)
  and the nearest obstacle in front (``Obstacle``).

The composite actions of the paper (``forward_Qbo``, ``search_Qbo``, ``looking_Qbo``)
are built from these in :mod:`robocog.minds.qbo`, the way the paper's Python side built
them from ROS calls. Everything random is drawn from one seeded generator, and the
world keeps a trajectory and the ground truth behind each look for the reports.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

from robocog.robot.commands import Command, Forward, Look, Outcome, Turn
from robocog.robot.percepts import Detection, Percept, Pose, Range, sonar_obstacle
from robocog.worlds.room_geometry import (
    Segment,
    cast,
    line_of_sight,
    point_segment_distance,
    ray_hit,
    wrap,
)

#: head pan of the three images of ``Look("around")``, radians, left to right
HEAD_PANS: dict[str, float] = {
    "left": math.radians(55.0),
    "front": 0.0,
    "right": math.radians(-55.0),
}

#: the two ultrasonic sensors, left (+1) and right (-1) of the heading
SONAR_SIDES = (1.0, -1.0)
#: where the rays that sample a sensor's cone lie, in cone half-widths from its axis
SONAR_SPREAD = (-1.0, -0.5, 0.0, 0.5, 1.0)


@dataclass(frozen=True)
class RoomConfig:
    """Dimensions and sensor figures of the room world (metres, radians, seconds)."""

    width: float = 6.0
    depth: float = 4.0
    doorway_x: float = 4.2
    doorway_width: float = 0.9
    door_open: float = math.radians(80.0)
    corridor_depth: float = 1.6
    opposite_door_x: float = 5.0
    robot_radius: float = 0.2
    image_fov: float = math.radians(54.0)
    vertical_rows: int = 2
    columns: int = 3
    threshold: float = 0.5
    detector_noise: float = 0.15
    detector_range: float = 5.0
    door_quality: float = 0.8
    opposite_door_quality: float = 1.0
    entry_quality: float = 0.9
    sonar_range: float = 1.5
    sonar_offset: float = 0.1
    sonar_angle: float = math.radians(10.0)
    sonar_cone: float = math.radians(12.0)
    sonar_noise: float = 0.01
    stop_distance: float = 0.25
    obstacle_range: float = 0.45
    motion_noise: float = 0.05
    turn_noise: float = 0.03
    drift: float = math.radians(2.0)
    speed: float = 0.15
    turn_speed: float = 0.6
    look_seconds: float = 0.8
    obstacles: int = 0
    start_x: float = 0.8
    start_y: tuple[float, float] = (1.2, 2.4)
    start_heading_sd: float = math.radians(5.0)


@dataclass(frozen=True, slots=True)
class Target:
    """Something the detector can recognise: a face (segment) with an outward normal."""

    id: str
    label: str
    face: Segment
    normal: float
    quality: float


@dataclass(frozen=True, slots=True)
class TrajectoryPoint:
    """Where the robot was after a command, and which phase the experiment was in."""

    t: float
    x: float
    y: float
    theta: float
    phase: str


@dataclass(frozen=True, slots=True)
class Seen:
    """Ground truth behind a look: the best area per label and what caused it."""

    label: str
    source: str
    certainty: float
    bearing: float


@dataclass
class Area:
    """One of the 3 x 2 areas of one image, with the certainty the detector gave it."""

    image: str
    row: int
    column: int
    bearing: float
    certainty: dict[str, float] = field(default_factory=dict)
    source: dict[str, str] = field(default_factory=dict)


class RoomBody:
    """The ``Body`` side both rooms share, the 2D one here and the MuJoCo one.

    Both read the same two ultrasonic sensors into the same percepts, take the same three
    commands, and answer an experiment's questions about the doorway and the door leaf the
    same way; a room supplies ``config.obstacle_range``, ``sonars()``, ``facing()``,
    ``_pose()``, the motions ``_look``, ``_forward`` and ``_turn``, ``_record()``, and
    ``x``, ``y``, ``door``, ``targets``, ``detections``, ``marks`` and ``commands``.
    """

    def _pose(self) -> Pose:
        """The pose the robot reports of itself (true or estimated, as the room has it)."""
        raise NotImplementedError

    def percepts(self) -> list[Percept]:
        """Pose, both ultrasonic sensors, the obstacle ahead, and the last look's areas."""
        left, right = self.sonars()  # type: ignore[attr-defined]
        reach = self.config.obstacle_range  # type: ignore[attr-defined]
        out: list[Percept] = [
            self._pose(),
            Range("us_left", left),
            Range("us_right", right),
            sonar_obstacle(left, right, reach),
        ]
        out.extend(self.detections)  # type: ignore[attr-defined]
        return out

    def execute(self, command: Command) -> Outcome:
        """Carry out a Look, Forward or Turn; any other command is refused."""
        self.commands += 1  # type: ignore[attr-defined]
        if isinstance(command, Look):
            outcome = self._look(command)  # type: ignore[attr-defined]
        elif isinstance(command, Forward):
            outcome = self._forward(command.distance)  # type: ignore[attr-defined]
        elif isinstance(command, Turn):
            outcome = self._turn(command.angle)  # type: ignore[attr-defined]
        else:
            outcome = Outcome.failure(f"the room robot cannot {type(command).__name__}")
        self._record()  # type: ignore[attr-defined]
        return outcome

    def mark(self, kind: str) -> None:
        """Note an event at the robot's position (drawn as a circle on the route plot)."""
        self.marks.append((self.x, self.y, kind))  # type: ignore[attr-defined]

    def at_entrance(self, reach: float = 0.5) -> bool:
        """True when the robot stands in or just before the doorway."""
        doorway = self.targets[2].face  # type: ignore[attr-defined]
        return point_segment_distance(self.x, self.y, doorway) < reach  # type: ignore[attr-defined]

    def in_front_of_door(self, reach: float = 0.8) -> bool:
        """True when the robot is close to the open door leaf and its sensors meet the leaf."""
        leaf = self.door.face  # type: ignore[attr-defined]
        close = point_segment_distance(self.x, self.y, leaf) < reach  # type: ignore[attr-defined]
        return close and self.facing() == "door"  # type: ignore[attr-defined]


class RoomWorld(RoomBody):
    """The room, the corridor and the Q.bo robot in it; implements ``Body``."""

    def __init__(self, seed: int = 0, config: RoomConfig | None = None) -> None:
        self.config = config or RoomConfig()
        self.rng = random.Random(seed)
        self.seed = seed
        c = self.config
        self.walls = self._build_walls()
        self.door = self._build_door()
        self.boxes = self._build_boxes(c.obstacles)
        self.solids = self.walls + [self.door.face] + [s for box in self.boxes for s in box]
        self.targets = self._build_targets()
        self.x = c.start_x
        self.y = self.rng.uniform(*c.start_y)
        self.theta = self.rng.gauss(0.0, c.start_heading_sd)
        self.clock = 0.0
        self.phase = ""
        self.trajectory: list[TrajectoryPoint] = []
        self.marks: list[tuple[float, float, str]] = []
        self.areas: list[Area] = []
        self.detections: list[Detection] = []
        self.last_seen: dict[str, Seen] = {}
        self.commands = 0
        self._record()

    # -- construction -------------------------------------------------------------

    def _build_walls(self) -> list[Segment]:
        c = self.config
        w, h, d0, d1 = c.width, c.depth, c.doorway_x, c.doorway_x + c.doorway_width
        top = h + c.corridor_depth
        o0, o1 = c.opposite_door_x, c.opposite_door_x + c.doorway_width
        left, right = -1.0, w + 1.0
        return [
            Segment(0.0, 0.0, w, 0.0),
            Segment(w, 0.0, w, h),
            Segment(0.0, h, 0.0, 0.0),
            Segment(0.0, h, d0, h),
            Segment(d1, h, w, h),
            # the corridor beyond the doorway, with the opposite room's (closed) door
            Segment(left, h, 0.0, h),
            Segment(w, h, right, h),
            Segment(left, h, left, top),
            Segment(right, h, right, top),
            Segment(left, top, o0, top),
            Segment(o0, top, o1, top),
            Segment(o1, top, right, top),
        ]

    def _build_door(self) -> Target:
        """The door leaf, hinged at the doorway's right jamb and opened into the room."""
        c = self.config
        hx, hy = c.doorway_x + c.doorway_width, c.depth
        a = c.door_open
        fx = hx - c.doorway_width * math.cos(a)
        fy = hy - c.doorway_width * math.sin(a)
        normal = math.atan2(math.cos(a), -math.sin(a))
        return Target("door", "door", Segment(hx, hy, fx, fy), normal, c.door_quality)

    def _build_targets(self) -> list[Target]:
        c = self.config
        top = c.depth + c.corridor_depth
        o0 = c.opposite_door_x
        opposite = Segment(o0, top, o0 + c.doorway_width, top)
        doorway = Segment(c.doorway_x, c.depth, c.doorway_x + c.doorway_width, c.depth)
        return [
            self.door,
            Target("opposite_door", "door", opposite, -math.pi / 2, c.opposite_door_quality),
            Target("doorway", "entry", doorway, -math.pi / 2, c.entry_quality),
        ]

    def _build_boxes(self, count: int) -> list[list[Segment]]:
        boxes: list[list[Segment]] = []
        for _ in range(count):
            cx = self.rng.uniform(1.8, 3.6)
            cy = self.rng.uniform(0.8, 3.2)
            s = 0.2
            corners = [(cx - s, cy - s), (cx + s, cy - s), (cx + s, cy + s), (cx - s, cy + s)]
            boxes.append([Segment(*corners[i], *corners[(i + 1) % 4]) for i in range(4)])
        return boxes

    # -- Body ---------------------------------------------------------------------

    def time(self) -> float:
        """Simulated seconds since the start."""
        return self.clock

    def _pose(self) -> Pose:
        """The true pose: the 2D room's robot knows where it is."""
        return Pose(self.x, self.y, self.theta, None)

    # -- motion -------------------------------------------------------------------

    def _turn(self, angle: float) -> Outcome:
        c = self.config
        actual = angle * (1.0 + self.rng.gauss(0.0, c.turn_noise))
        self.theta = wrap(self.theta + actual)
        self.clock += abs(angle) / c.turn_speed
        self._moved()
        return Outcome.success()

    def _forward(self, distance: float) -> Outcome:
        c = self.config
        sign = 1.0 if distance >= 0 else -1.0
        total = abs(distance) * max(0.0, 1.0 + self.rng.gauss(0.0, c.motion_noise))
        heading = self.theta + self.rng.gauss(0.0, c.drift) * min(1.0, total)
        step = 0.02
        travelled = 0.0
        outcome = Outcome.success()
        while travelled < total - 1e-9:
            if sign > 0 and min(self.sonars(noise=False)) < c.stop_distance:
                outcome = Outcome.failure("obstacle ahead")
                break
            ds = min(step, total - travelled)
            nx = self.x + sign * ds * math.cos(heading)
            ny = self.y + sign * ds * math.sin(heading)
            if self._collides(nx, ny):
                outcome = Outcome.failure("bumped")
                break
            self.x, self.y = nx, ny
            travelled += ds
        self.theta = wrap(heading)
        self.clock += travelled / c.speed
        self._moved()
        return outcome

    def _collides(self, x: float, y: float) -> bool:
        r = self.config.robot_radius
        return any(point_segment_distance(x, y, s) < r for s in self.solids)

    def _moved(self) -> None:
        """The images of the last look no longer match what the robot faces."""
        self.detections = []

    # -- sensors ------------------------------------------------------------------

    def sonars(self, noise: bool = True) -> tuple[float, float]:
        """Left and right ultrasonic readings: the nearest echo within each beam."""
        c = self.config
        readings = []
        for side in SONAR_SIDES:
            best = c.sonar_range
            for sx, sy, angle in self._sonar_rays(side):
                best = min(best, cast(sx, sy, angle, self.solids, c.sonar_range))
            if noise:
                best = min(c.sonar_range, max(0.0, best + self.rng.gauss(0.0, c.sonar_noise)))
            readings.append(best)
        return readings[0], readings[1]

    def _sonar_rays(self, side: float) -> list[tuple[float, float, float]]:
        """The rays, ``(x, y, angle)``, that sample one ultrasonic sensor's cone.

        ``side`` is 1.0 for the left sensor and -1.0 for the right; the readings and
        :meth:`facing` cast the same rays, so they agree on what the beams meet.
        """
        c = self.config
        cos_t, sin_t = math.cos(self.theta), math.sin(self.theta)
        sx = self.x + c.robot_radius * cos_t - side * c.sonar_offset * sin_t
        sy = self.y + c.robot_radius * sin_t + side * c.sonar_offset * cos_t
        axis = self.theta + side * c.sonar_angle
        return [(sx, sy, axis + k * c.sonar_cone) for k in SONAR_SPREAD]

    def _look(self, look: Look) -> Outcome:
        c = self.config
        images = look.views(HEAD_PANS)
        if images is None:
            return Outcome.failure(f"unknown look direction {look.direction!r}")
        self.areas = [area for image in images for area in self._image(image)]
        self.clock += c.look_seconds * len(images)
        self.detections = []
        self.last_seen = {}
        for area in self.areas:
            for label, certainty in area.certainty.items():
                if certainty <= c.threshold:
                    continue
                source = area.source.get(label, "noise")
                distance = self._apparent_distance(source)
                self.detections.append(
                    Detection(
                        label,
                        area.bearing,
                        distance,
                        certainty,
                        f"{area.image}:{area.row}:{area.column}",
                    )
                )
                best = self.last_seen.get(label)
                if best is None or certainty > best.certainty:
                    self.last_seen[label] = Seen(label, source, certainty, area.bearing)
        return Outcome.success()

    def _apparent_distance(self, source: str) -> float:
        """The detector's noisy range to a target, or a random one for a noise blob."""
        if any(target.id == source for target in self.targets):
            return max(0.1, self.distance_to(source) * (1.0 + self.rng.gauss(0.0, 0.1)))
        return self.rng.uniform(1.0, 5.0)

    def _image(self, image: str) -> list[Area]:
        """One image split into rows x columns areas, each with a certainty per label."""
        c = self.config
        pan = HEAD_PANS[image]
        width = c.image_fov / c.columns
        areas = []
        for row in range(c.vertical_rows):
            for col in range(c.columns):
                bearing = pan + c.image_fov / 2 - width * (col + 0.5)
                areas.append(Area(image, row, col, bearing))
        signals = {t.id: self._signal(t) for t in self.targets}
        for area in areas:
            for label in ("door", "entry"):
                best, source = 0.0, "noise"
                for target in self.targets:
                    if target.label != label:
                        continue
                    strength = self._in_area(signals[target.id], area, width)
                    if area.row == 0:
                        strength *= 0.6  # the slit under the knob sits in the lower row
                    if strength > best:
                        best, source = strength, target.id
                certainty = best + self.rng.gauss(0.0, c.detector_noise)
                area.certainty[label] = max(0.0, min(1.0, certainty))
                if best > 0.0:
                    area.source[label] = source
        return areas

    @staticmethod
    def _in_area(signal: dict[float, float], area: Area, width: float) -> float:
        """The strongest part of a target's signal whose bearing falls inside the area."""
        strongest = 0.0
        for bearing, strength in signal.items():
            if abs(wrap(bearing - area.bearing)) <= width / 2 and strength > strongest:
                strongest = strength
        return strongest

    def _signal(self, target: Target) -> dict[float, float]:
        """Bearing (relative to the body) -> detector strength, over points of the face.

        Strength falls with distance and with the angle at which the face is seen; a
        face seen from behind, or hidden by a wall or the door leaf, gives nothing.
        """
        c = self.config
        points = [target.face.point(t) for t in (0.1, 0.3, 0.5, 0.7, 0.9)]
        blockers = [s for s in self.solids if s != target.face]
        visible = [p for p in points if line_of_sight((self.x, self.y), p, blockers)]
        if not visible:
            return {}
        fraction = len(visible) / len(points)
        out: dict[float, float] = {}
        for px, py in visible:
            dist = math.hypot(px - self.x, py - self.y)
            if dist > c.detector_range or dist < 0.3:
                continue
            towards_robot = math.atan2(self.y - py, self.x - px)
            incidence = math.cos(wrap(towards_robot - target.normal))
            if incidence <= 0.0:
                continue
            if target.label == "entry" and (dist < 0.6 or self.y > c.depth):
                continue
            falloff = 1.0 / (1.0 + (dist / c.detector_range) ** 2)
            strength = target.quality * falloff * incidence * (0.5 + 0.5 * fraction)
            bearing = wrap(math.atan2(py - self.y, px - self.x) - self.theta)
            out[bearing] = max(out.get(bearing, 0.0), strength)
        return out

    # -- records and ground truth ------------------------------------------------

    def _record(self) -> None:
        self.trajectory.append(TrajectoryPoint(self.clock, self.x, self.y, self.theta, self.phase))

    def exited(self) -> bool:
        """True once the whole robot is through the doorway, in the corridor."""
        return self.y > self.config.depth + self.config.robot_radius

    def distance_to(self, target_id: str) -> float:
        """Distance from the robot to the middle of a target's face."""
        for target in self.targets:
            if target.id == target_id:
                fx, fy = target.face.point(0.5)
                return math.hypot(fx - self.x, fy - self.y)
        raise KeyError(target_id)

    def facing(self) -> str:
        """What the ultrasonic beams meet first: ``door``, ``wall``, ``box`` or ``nothing``."""
        c = self.config
        best, what = c.sonar_range, "nothing"
        for side in SONAR_SIDES:
            for sx, sy, angle in self._sonar_rays(side):
                for seg in self.solids:
                    t = ray_hit(sx, sy, angle, seg)
                    if t is not None and t < best:
                        best = t
                        if seg == self.door.face:
                            what = "door"
                        elif seg in self.walls:
                            what = "wall"
                        else:
                            what = "box"
        return what
