"""The Q.bo's room (Fujita et al., Fig. 3) in physics: MuJoCo, a camera head, an SVM, sonar.

:class:`MujocoRoom` is a ``Body`` like :class:`~robocog.worlds.room.RoomWorld` and takes
the same commands, so the same minds (:mod:`robocog.minds.qbo`) and the same plans run on
it; but nothing is drawn by chance from geometry:

* ``Look("around")`` turns the head (a position servo on the pan joint) to +55, 0 and
  -55 degrees, renders the head camera at each, splits each image into 3 x 2 areas and
  asks the SVMs of :mod:`~robocog.worlds.physics.room_vision` whether each shows a door
  or the entry. Areas whose certainty passes the threshold become ``Detection``
  percepts (bearing of the area's column, relative to the body) until the robot moves.
* ``Forward(d)`` drives the base at 0.15 m/s. It stops when an ultrasonic sensor reads
  under the stop distance (``failed: obstacle ahead``) or when the body stops making
  way (``failed: bumped``): a jamb between the two sensors' beams catches the body
  without either sensor seeing it.
* ``Turn(a)`` turns in place (``failed: blocked`` when the body cannot turn).
* Percepts every cycle: ``Pose`` (odometry), ``Range("us_left")``, ``Range("us_right")``
  (each the nearest echo among the rays that sample its cone, with noise) and
  ``Obstacle``.

What varies between seeds: the start pose, how far the door stands open, a small
imbalance between the wheels (the path curves a little), the sonar's noise and the
camera's pixel noise. The world keeps a trajectory, marks and the ground truth behind
each look (which door the best "door" area showed, from the renderer's segmentation)
for the experiment's reports; the mind never sees these.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

import numpy as np

from robocog.robot.commands import Look, Outcome
from robocog.robot.percepts import Detection, Pose
from robocog.worlds.physics.gl import choose_gl
from robocog.worlds.room import RoomBody, Seen, Target, TrajectoryPoint
from robocog.worlds.room_geometry import Segment, wrap

choose_gl()

import mujoco  # noqa: E402

from robocog.worlds.physics import room_vision as vision  # noqa: E402
from robocog.worlds.physics.mobile_base import MobileBase, RangeCone, cast_rays  # noqa: E402
from robocog.worlds.physics.room_scene import (  # noqa: E402
    BODY_RADIUS,
    QBO_BASE,
    SONAR_ANGLE,
    SONAR_OFFSET,
    RoomPlan,
    scene_xml,
)

SONARS = (("us_left", 1.0), ("us_right", -1.0))


@dataclass(frozen=True)
class MujocoRoomConfig:
    """Figures of the physical room and robot (metres, degrees where named, seconds)."""

    plan: RoomPlan = field(default_factory=RoomPlan)
    door_open_degrees: tuple[float, float] = (70.0, 90.0)
    start_x: float = 0.8
    start_y: tuple[float, float] = (1.2, 2.4)
    start_heading_sd_degrees: float = 5.0
    speed: float = 0.15
    turn_speed: float = 0.6
    control_period: float = 0.05
    sonar_range: float = 1.5
    sonar_cone_degrees: float = 12.0
    sonar_rays: int = 13
    sonar_noise: float = 0.01
    stop_distance: float = 0.25
    obstacle_range: float = 0.45
    threshold: float = 0.5
    stall_seconds: float = 1.0
    stall_progress: float = 0.02
    wheel_imbalance_sd: float = 0.03
    wheel_slip: float = 0.03
    svm_seed: int = 0
    svm_images: int = vision.TRAIN_IMAGES


class MujocoRoom(RoomBody):
    """The physical room, corridor and Q.bo; implements ``Body``."""

    def __init__(
        self,
        seed: int = 0,
        config: MujocoRoomConfig | None = None,
        classifier: vision.AreaClassifier | None = None,
        start: tuple[float, float, float] | None = None,
        door_open_degrees: float | None = None,
    ) -> None:
        self.config = c = config or MujocoRoomConfig()
        self.seed = seed
        self.rng = random.Random(seed)
        self.plan = c.plan
        self.model = mujoco.MjModel.from_xml_string(scene_xml(c.plan))
        self.data = mujoco.MjData(self.model)
        self.classifier = classifier or vision.shared_classifier(c.svm_seed, c.svm_images)
        self.camera = vision.HeadCamera(self.model)
        self._pan_q = self._adr("head_pan")
        self._pan_v = self._dof("head_pan")
        self._door_q = self._adr("door_hinge")
        self._pan_act = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, "pan")
        self._robot = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, QBO_BASE.name)
        self._names = [
            mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_GEOM, g) or ""
            for g in range(self.model.ngeom)
        ]
        self.door_angle = math.radians(
            door_open_degrees
            if door_open_degrees is not None
            else self.rng.uniform(*c.door_open_degrees)
        )
        if start is None:
            start = (
                c.start_x,
                self.rng.uniform(*c.start_y),
                self.rng.gauss(0.0, math.radians(c.start_heading_sd_degrees)),
            )
        self.imbalance = self.rng.gauss(0.0, c.wheel_imbalance_sd)
        vision.pose_robot(self.model, self.data, *start, 0.0, self.door_angle)
        self.walls = [Segment(*s) for s in c.plan.wall_segments()]
        self.base = MobileBase(
            self.model,
            self.data,
            QBO_BASE,
            start,
            walls=[((w.ax, w.ay), (w.bx, w.by)) for w in self.walls],
            slip=c.wheel_slip,
            seed=self.rng.getrandbits(32),
        )
        self.sonar = {
            name: RangeCone(
                self.model,
                f"sonar_{name[3:]}",
                half_angle=math.radians(c.sonar_cone_degrees),
                range_max=c.sonar_range,
                rays=c.sonar_rays,
                noise=c.sonar_noise,
                rng=self.rng,
            )
            for name, _ in SONARS
        }
        self.boxes: list[list[Segment]] = []
        self.phase = ""
        self.trajectory: list[TrajectoryPoint] = []
        self.marks: list[tuple[float, float, str]] = []
        self.detections: list[Detection] = []
        self.last_seen: dict[str, Seen] = {}
        self.commands = 0
        self.looks = 0
        self.physics_steps = 0
        self._record()

    # -- model access -----------------------------------------------------------------

    def _adr(self, joint: str) -> int:
        j = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, joint)
        return int(self.model.jnt_qposadr[j])

    def _dof(self, joint: str) -> int:
        j = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, joint)
        return int(self.model.jnt_dofadr[j])

    @property
    def x(self) -> float:
        """The base's true x (for reports; the mind reads odometry)."""
        return self.base.true_pose()[0]

    @property
    def y(self) -> float:
        """The base's true y."""
        return self.base.true_pose()[1]

    @property
    def theta(self) -> float:
        """The base's true heading, radians in (-pi, pi]."""
        return wrap(self.base.true_pose()[2])

    @property
    def pan(self) -> float:
        """The head's pan, radians."""
        return float(self.data.qpos[self._pan_q])

    @property
    def clock(self) -> float:
        """Simulated seconds (the 2D room's name for it, which the inspector reads)."""
        return self.time()

    @property
    def solids(self) -> list[Segment]:
        """The walls and the door leaf as segments, for the inspector's plan of the room."""
        return [*self.walls, self.door.face]

    # -- Body ------------------------------------------------------------------------

    def time(self) -> float:
        """Simulated seconds since the start."""
        return float(self.data.time)

    def _pose(self) -> Pose:
        """The odometry's estimate: the physical robot knows only what its wheels tell."""
        x, y, heading = self.base.odometry.pose
        return Pose(x, y, heading, None)

    def image(self) -> np.ndarray:
        """What the head camera sees now (height x width x 3, with the camera's noise)."""
        return self.camera.render(self.data, self.rng)

    def joints(self) -> dict[str, float]:
        """The head's pan and the wheels' angles (radians), as a JointState reports them."""
        left, right = self.base.encoders()
        return {"head_pan": self.pan, "qbo_left_wheel": left, "qbo_right_wheel": right}

    def close(self) -> None:
        """Free the camera's GL context."""
        self.camera.close()

    # -- motion ----------------------------------------------------------------------

    def drive(self, v: float, w: float, pan: float | None = None) -> None:
        """One control period with body speed ``v`` (m/s) and turn rate ``w`` (rad/s),
        the head's servo aimed at ``pan`` (radians) when given. The commands use it; so
        does a ROS 2 server that takes velocities instead of commands."""
        self.base.drive(v, w)
        if pan is not None:
            self.data.ctrl[self._pan_act] = pan
        n = max(1, round(self.config.control_period / self.model.opt.timestep))
        mujoco.mj_step(self.model, self.data, nstep=n)
        self.base.sense(n * self.model.opt.timestep)
        self.physics_steps += n

    def _settle(self, seconds: float = 0.2) -> None:
        for _ in range(max(1, round(seconds / self.config.control_period))):
            self.drive(0.0, 0.0)

    def _forward(self, distance: float) -> Outcome:
        c = self.config
        sign = 1.0 if distance >= 0 else -1.0
        total = abs(distance)
        odometry = self.base.odometry
        start = odometry.travelled
        limit = self.time() + total / c.speed * 1.5 + 2.0
        window: list[tuple[float, float]] = []
        outcome = Outcome.success()
        next_sample = self.time() + 0.5
        while True:
            travelled = odometry.travelled - start
            if travelled >= total - 0.005:
                break
            if sign > 0 and min(self.sonars()) < c.stop_distance:
                outcome = Outcome.failure("obstacle ahead")
                break
            t = self.time()
            window.append((t, travelled))
            while window and window[0][0] < t - c.stall_seconds:
                window.pop(0)
            if (
                t - window[0][0] >= c.stall_seconds * 0.95
                and travelled - window[0][1] < c.stall_progress
            ):  # the encoders stopped turning: the body is caught
                outcome = Outcome.failure("bumped")
                break
            if t > limit:
                outcome = Outcome.failure("too slow")
                break
            v = sign * min(c.speed, max(0.05, (total - travelled) * 2.0))
            self.drive(v, self.imbalance * v / 0.3)
            if self.time() >= next_sample:
                next_sample += 0.5
                self._record()
        self._settle()
        self.detections = []
        return outcome

    def _turn(self, angle: float) -> Outcome:
        c = self.config
        odometry = self.base.odometry
        target = wrap(odometry.theta + angle)
        limit = self.time() + abs(angle) / c.turn_speed * 2.0 + 2.0
        outcome = Outcome.success()
        while True:
            remaining = wrap(target - odometry.theta)
            if abs(remaining) < math.radians(0.5):
                break
            if self.time() > limit:
                outcome = Outcome.failure("blocked")
                break
            w = max(-c.turn_speed, min(c.turn_speed, 3.0 * remaining))
            if abs(w) < 0.08:
                w = math.copysign(0.08, remaining)
            self.drive(0.0, w)
        self._settle(0.1)
        self.detections = []
        return outcome

    # -- sensors ---------------------------------------------------------------------

    def sonars(self, noise: bool = True) -> tuple[float, float]:
        """Left and right ultrasonic readings: the nearest echo within each cone, capped
        at the sensors' range."""
        c = self.config
        out = []
        for name, _ in SONARS:
            cone = self.sonar[name]
            saved = cone.noise
            cone.noise = saved if noise else 0.0
            out.append(min(c.sonar_range, cone.read(self.data)))
            cone.noise = saved
        return out[0], out[1]

    def _fan(self, side: float) -> tuple[np.ndarray, np.ndarray]:
        """A sensor's origin and a horizontal fan of directions across its cone."""
        c = self.config
        site = mujoco.mj_name2id(
            self.model, mujoco.mjtObj.mjOBJ_SITE, "sonar_left" if side > 0 else "sonar_right"
        )
        axis = self.theta + side * math.radians(SONAR_ANGLE)
        half = math.radians(c.sonar_cone_degrees)
        angles = axis + np.linspace(-half, half, 7)
        directions = np.column_stack((np.cos(angles), np.sin(angles), np.zeros(len(angles))))
        return self.data.site_xpos[site].copy(), directions

    def facing(self) -> str:
        """What the ultrasonic beams meet first: ``door``, ``jamb``, ``wall`` or ``nothing``."""
        best, what = self.config.sonar_range, "nothing"
        for _, side in SONARS:
            origin, directions = self._fan(side)
            dist, geoms = cast_rays(self.model, self.data, origin, directions, best, self._robot)
            for d, geom in zip(dist, geoms, strict=True):
                if d < best:
                    best = d
                    name = self._names[int(geom)]
                    if name.startswith("door_"):
                        what = "door"
                    elif name.startswith("jamb"):
                        what = "jamb"
                    elif name.startswith("opposite"):
                        what = "opposite door"
                    else:
                        what = "wall"
        return what

    def _look(self, look: Look) -> Outcome:
        pans = dict(zip(("left", "front", "right"), vision.PANS, strict=True))
        images = look.views(pans)
        if images is None:
            return Outcome.failure(f"unknown look direction {look.direction!r}")
        self.looks += 1
        self.detections = []
        self.last_seen = {}
        for image_name in images:
            self._pan_to(math.radians(pans[image_name]))
            image = self.camera.render(self.data, self.rng)
            feats = np.array([vision.area_features(a) for a in vision.split_areas(image)])
            certainty = self.classifier.certainty(feats)
            coverage = self.camera.coverage(self.camera.segment(self.data))
            pan_deg = math.degrees(self.pan)
            for i in range(vision.ROWS * vision.COLUMNS):
                row, col = divmod(i, vision.COLUMNS)
                bearing = vision.area_bearing(pan_deg, col)
                for label in vision.TARGETS:
                    value = float(certainty[label][i])
                    if value <= self.config.threshold:
                        continue
                    self.detections.append(
                        Detection(label, bearing, 0.0, value, f"{image_name}:{row}:{col}")
                    )
                    best = self.last_seen.get(label)
                    if best is None or value > best.certainty:
                        source = self._source(label, coverage[i])
                        self.last_seen[label] = Seen(label, source, value, bearing)
        self._pan_to(0.0)
        return Outcome.success()

    @staticmethod
    def _source(label: str, coverage: np.ndarray) -> str:
        """What an area really showed, from the segmentation: which door, or the doorway."""
        if label == "door":
            if coverage[0] <= 0.0:
                return "noise"
            return "door" if coverage[2] >= coverage[0] / 2 else "opposite_door"
        return "doorway" if coverage[1] > 0.0 else "noise"

    def _pan_to(self, target: float, tolerance: float = math.radians(1.0)) -> None:
        """Turn the head with its servo until it is within tolerance (or a second passed)."""
        limit = self.time() + 1.5
        while self.time() < limit:
            self.drive(0.0, 0.0, pan=target)
            speed = abs(float(self.data.qvel[self._pan_v]))
            if abs(self.pan - target) < tolerance and speed < 0.05:
                break

    # -- records and ground truth ----------------------------------------------------

    def _record(self) -> None:
        self.trajectory.append(TrajectoryPoint(self.time(), self.x, self.y, self.theta, self.phase))

    @property
    def door(self) -> Target:
        """The room's door leaf where it stands now (the robot may have pushed it)."""
        p = self.plan
        q = float(self.data.qpos[self._door_q])
        hx, hy = p.doorway_x + p.doorway_width - 0.01, p.depth
        w = p.doorway_width - 0.03
        face = Segment(hx, hy, hx - w * math.cos(q), hy - w * math.sin(q))
        return Target("door", "door", face, math.atan2(math.cos(q), -math.sin(q)), 1.0)

    @property
    def targets(self) -> list[Target]:
        """The door leaf, the opposite room's door and the doorway, as the 2D room has them."""
        p = self.plan
        o0 = p.opposite_door_x
        opposite = Segment(o0, p.top, o0 + p.doorway_width, p.top)
        doorway = Segment(p.doorway_x, p.depth, p.doorway_x + p.doorway_width, p.depth)
        return [
            self.door,
            Target("opposite_door", "door", opposite, -math.pi / 2, 1.0),
            Target("doorway", "entry", doorway, -math.pi / 2, 1.0),
        ]

    def exited(self) -> bool:
        """True once the whole body is through the doorway, in the corridor."""
        return self.y > self.plan.depth + BODY_RADIUS + SONAR_OFFSET
