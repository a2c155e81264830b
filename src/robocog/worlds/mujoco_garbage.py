"""The garbage field of Hammer et al. in physics: pixels, a learned detector, a lidar, an arm.

:class:`MujocoGarbageField` is the 2D :class:`~robocog.worlds.garbage.GarbageField`
made physical, for the same minds: the same checkpoints, the same objects placed with
the same hotspot weights and seeds (so a seed gives the same layout in both), the same
commands and the same kinds of percepts. What differs is where each comes from:

* **Detections** come from pixels: every frame (4 a second, as the paper's Jetson
  Nano) is rendered offscreen from the robot's mast camera (640 x 480, 60 degrees
  across) and given to the learned detector
  (:mod:`robocog.worlds.physics.trash_detector`) or a user's ONNX model. A box's
  bearing comes from its column, its distance from where its bottom meets the ground
  (the camera's height and pitch are its calibration). Instance names come from a
  tracker that keeps each detection's estimated place on the field.
* **Obstacles** come from the 2D lidar (360 rays by ray casting, 10 a second): the
  nearest return within ``lidar_range`` and its sector.
* **Pose** comes from the localiser: wheel odometry (which slips) and the IMU's yaw
  rate, corrected by matching lidar scans to the known fence; ``Pose.place`` is the
  checkpoint the estimate is at. The lidar sees the fence only near it, so the
  estimate drifts in the middle of the field.
* **The pick** is a motion: drive to a stand-off, lower the arm (three joints, by
  inverse kinematics), drive the open fingers around the object, close them (force-
  limited), lift, and read the fingers' joint sensors: a hand that closed on nothing
  holds nothing. A bottle lying down is below the fingers; a misaimed approach knocks
  a standing one over. **Drop** swings the arm over the tray and opens the hand.

The light is a MuJoCo light (:data:`~robocog.worlds.physics.field_scene.LIGHTING`);
detection rates come out of the detector and the pixels, never from a table.
The simulator's state is read only for the experiment's bookkeeping (which object was
collected, why another was not), never for a percept.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from robocog.robot.commands import Outcome
from robocog.robot.percepts import Detection, Gripper, Obstacle, Percept, Pose
from robocog.worlds.garbage import GarbageConfig, GarbageField, Trash
from robocog.worlds.physics.gl import choose_gl

choose_gl()

import mujoco  # noqa: E402

from robocog.worlds.physics import field_scene as fs  # noqa: E402
from robocog.worlds.physics.field_parts import (  # noqa: E402
    CARRY,
    STOW,
    TRAY,
    Costs,
    Track,
    arm_angles,
)
from robocog.worlds.physics.mobile_base import (  # noqa: E402
    BaseSpec,
    LidarSpec,
    MobileBase,
    Scan,
    steer,
    turn_law,
    wrap,
)
from robocog.worlds.physics.trash_detector import Box  # noqa: E402

#: half the depth of a bottle or cup: from the near edge a box's bottom shows to the middle
OBJECT_DEPTH = 0.037


class Detector(Protocol):
    """What the field needs of a detector: boxes in an RGB frame."""

    def detect(self, image: np.ndarray) -> list[Box]: ...


@dataclass(frozen=True)
class PhysicalConfig:
    """The physical robot's settings (the field's rules stay in ``GarbageConfig``)."""

    width: int = 640
    height: int = 480
    lidar_rays: int = 360
    lidar_rate: float = 10.0
    lidar_range_max: float = 8.0  # the scanner's range limit (metres)
    slip: float = 0.03
    #: share of objects placed upright, leaning on a stone, lying down
    poses: tuple[float, float, float] = (0.7, 0.15, 0.15)
    shadow_size: int = 1024
    grasp_height: float = 0.085
    grasp_reach: float = 0.62  # from the base's centre to the point between the pads
    #: how much further than the estimate the hand is driven: the approach stops a
    #: few centimetres short (the wheels' rolling radius, the stopping tolerance)
    overdrive: float = 0.025
    stand_off: float = 1.3  # where the approach stops to look again (the whole object in view)
    track_radius: float = 0.6  # detections closer than this on the field are one object
    camera: fs.CameraModel = field(default_factory=fs.CameraModel)


class MujocoGarbageField(GarbageField):
    """The garbage field in MuJoCo: a ``Body`` with ``percepts()``, ``execute()``,
    ``time()``, and the 2D field's bookkeeping for the experiment's report."""

    #: The MuJoCo base is larger than the 2D robot's disc: it keeps further off the fence.
    fence_margin = 0.5

    def __init__(
        self,
        config: GarbageConfig | None = None,
        seed: int = 0,
        physical: PhysicalConfig | None = None,
        detector: Detector | None = None,
    ) -> None:
        self.physical = physical or PhysicalConfig()
        self._built = False
        super().__init__(config, seed)
        self._detector = detector
        self.costs = Costs()
        self.tracks: list[Track] = []
        self._holding_track: Track | None = None
        self._pose_rng = random.Random(seed * 7919 + 17)
        self.placed: list[fs.Placed] = []
        for t in self.trash:
            pose = self._pose_rng.choices(("upright", "leaning", "lying"), self.physical.poses)[0]
            self.placed.append(
                fs.Placed(t.instance, t.label, t.x, t.y, self._pose_rng.uniform(-3.14, 3.14), pose)
            )
        self._by_name = {t.instance: t for t in self.trash}
        self.spec = BaseSpec(name="robot")
        start = (self.x, self.y, self.theta)
        xml = fs.field_xml(
            self.config.size,
            self.checkpoints,
            self.placed,
            start,
            self.spec,
            shadow_size=self.physical.shadow_size,
        )
        self.model = mujoco.MjModel.from_xml_string(xml)
        self.data = mujoco.MjData(self.model)
        fs.set_light(self.model, self.config.light)
        self._set_arm(*STOW)
        self._set_fingers(fs.FINGER_OPEN)
        # start with the arm where it rests, so it does not swing up at the first step
        q = arm_angles(*STOW)
        for name, angle in zip(("shoulder", "elbow", "wrist"), q, strict=True):
            self.data.qpos[self.model.joint(name).qposadr[0]] = angle
        mujoco.mj_forward(self.model, self.data)
        lidar = LidarSpec(
            rays=self.physical.lidar_rays,
            range_max=self.physical.lidar_range_max,
            rate=self.physical.lidar_rate,
        )
        self.base = MobileBase(
            self.model,
            self.data,
            self.spec,
            start,
            fs.fence(self.config.size),
            lidar,
            slip=self.physical.slip,
            seed=seed,
        )
        self._renderer: mujoco.Renderer | None = None
        self._noise = np.random.default_rng(seed + 104729)
        self._dt = float(self.model.opt.timestep)
        self._next_scan = 0.0
        self._scan: Scan | None = None
        self._v = 0.0
        self._w = 0.0
        #: the lidar corrects the estimate, except while a pick approaches by odometry
        self._correcting = True
        self._built = True
        self._settle(1.0)
        for t in self.trash:  # the lying ones are the 2D field's "tipped"
            t.upright = self._upright(t)
        self.last_frame: np.ndarray | None = None
        self.last_boxes: list[Box] = []
        #: the last frame's detections, each with the box it came from (for a robot
        #: that publishes the boxes, as a ROS detector node does)
        self.last_detections: list[tuple[Detection, Box]] = []
        #: called with every camera frame the percepts come from (a recorder's hook)
        self.on_frame: Callable[[np.ndarray], None] | None = None

    # ---- the detector -------------------------------------------------------------

    @property
    def detector(self) -> Detector:
        """The camera's detector (the cached learned model, trained on first use)."""
        if self._detector is None:
            from robocog.worlds.physics.trash_detector import load_or_train

            self._detector, _report = load_or_train()
        return self._detector

    # ---- the physics --------------------------------------------------------------

    def new_round(self) -> list[Trash]:
        """The physical field holds one round's objects (a mission); a new round needs a
        new field."""
        if getattr(self, "_built", False):
            raise NotImplementedError("the physical field runs one round per field")
        return super().new_round()

    def _joint_ctrl(self, name: str, value: float) -> None:
        self.data.ctrl[self.model.actuator(name).id] = value

    def _set_arm(self, x: float, z: float, pitch: float) -> None:
        for name, angle in zip(
            ("shoulder", "elbow", "wrist"), arm_angles(x, z, pitch), strict=True
        ):
            self._joint_ctrl(name, angle)

    def _move_arm(self, x: float, z: float, pitch: float, seconds: float) -> None:
        """Move the arm to a pose along a smooth joint path of ``seconds`` (a thrown
        bottle is what a servo jumping to its goal would give)."""
        names = ("shoulder", "elbow", "wrist")
        begin = [float(self.data.ctrl[self.model.actuator(n).id]) for n in names]
        end = arm_angles(x, z, pitch)
        steps = max(1, int(seconds / (4 * self._dt)))
        for i in range(1, steps + 1):
            s = 0.5 - 0.5 * math.cos(math.pi * i / steps)
            for n, a, b in zip(names, begin, end, strict=True):
                self._joint_ctrl(n, a + (b - a) * s)
            self._step(4)
        self._settle(0.2)

    def _set_fingers(self, opening: float) -> None:
        self._joint_ctrl("finger_left", opening)
        self._joint_ctrl("finger_right", opening)

    def joint_positions(self) -> dict[str, float]:
        """The arm's joint sensors (radians; the fingers in metres from the middle)."""
        out = {}
        for name in ("shoulder", "elbow", "wrist", "finger_left", "finger_right"):
            out[name] = float(self.data.sensordata[self.model.sensor(f"{name}_pos").adr[0]])
        return out

    def _step(self, n: int = 1) -> None:
        import time as _time

        t0 = _time.perf_counter()
        for _ in range(n):
            self.base.drive(self._v, self._w)
            mujoco.mj_step(self.model, self.data)
            self.base.sense(self._dt)
            self.clock += self._dt
            if self.data.time >= self._next_scan:
                self._next_scan = self.data.time + 1.0 / self.physical.lidar_rate
                s0 = _time.perf_counter()
                self._scan = self.base.scan(self.clock, correct=self._correcting)
                self.costs.scans += 1
                self.costs.scan_seconds += _time.perf_counter() - s0
        self.costs.steps += n
        self.costs.step_seconds += _time.perf_counter() - t0

    def _settle(self, seconds: float) -> None:
        """Let the physics run with the wheels still."""
        self._v = self._w = 0.0
        self._step(max(1, int(round(seconds / self._dt))))

    def _advance(self, seconds: float) -> None:
        self._settle(seconds)

    def drive(self, v: float, w: float) -> None:
        """Command the base's speed and turn rate until changed (for a driver of its
        own, such as a ROS bridge or a benchmark; the commands do it themselves)."""
        self._v, self._w = v, w

    def step(self, n: int = 1) -> None:
        """Advance the physics ``n`` steps with the sensors at their rates."""
        self._step(n)

    def detect(self, image: np.ndarray) -> list[Box]:
        """Run the detector on a frame, counting its cost."""
        import time as _time

        t0 = _time.perf_counter()
        boxes = self.detector.detect(image)
        self.costs.detect_seconds += _time.perf_counter() - t0
        self.costs.detections += 1
        return boxes

    def wait(self, seconds: float) -> None:
        """Let ``seconds`` of simulated time pass with the robot standing still."""
        self._settle(seconds)

    def _drive_to(
        self,
        x: float,
        y: float,
        speed: float | None = None,
        timeout: float | None = None,
        tolerance: float = 0.06,
    ) -> bool:
        """Drive to (x, y) on the estimate; False if it did not arrive in time."""
        spec = self.spec
        if speed is not None:
            spec = BaseSpec(**{**spec.__dict__, "max_speed": speed})
        start = self.base.estimate
        distance = math.hypot(x - start[0], y - start[1])
        limit = timeout or (3.0 * distance / spec.max_speed + 10.0)
        ends = self.clock + limit
        arrived = False
        while self.clock < ends and not self.out_of_time:
            v, w, arrived = steer(self.base.estimate, (x, y), spec, tolerance=tolerance)
            if arrived:
                break
            self._v, self._w = v, w
            self._step(4)
            tx, ty, _ = self.base.true_pose()
            if (
                not self.trajectory
                or math.hypot(tx - self.trajectory[-1][0], ty - self.trajectory[-1][1]) > 0.5
            ):
                self.trajectory.append((tx, ty))
        self._v = self._w = 0.0
        self._sync()
        return arrived

    def _face(self, heading: float, timeout: float = 12.0, tolerance: float = 0.02) -> None:
        ends = self.clock + timeout
        while self.clock < ends and not self.out_of_time:
            w = turn_law(self.base.estimate[2], heading, self.spec, tolerance)
            if w == 0.0:
                break
            self._v, self._w = 0.0, w
            self._step(4)
        self._v = self._w = 0.0
        self._sync()

    def _back_to(self, x: float, y: float, timeout: float = 20.0) -> None:
        """Reverse in a straight line to (x, y), keeping the heading."""
        ends = self.clock + timeout
        while self.clock < ends and not self.out_of_time:
            ex, ey, et = self.base.estimate
            dx, dy = x - ex, y - ey
            along = dx * math.cos(et) + dy * math.sin(et)
            if along > -0.04:
                break
            self._v = max(-0.25, 1.2 * along - 0.03)
            self._w = 0.0
            self._step(4)
        self._v = self._w = 0.0
        self._sync()

    def _sync(self) -> None:
        """Keep the 2D bookkeeping's pose (used in the report) at the estimate."""
        self.x, self.y, self.theta = self.base.estimate

    # ---- sensing -------------------------------------------------------------------

    def render(self) -> np.ndarray:
        """One camera frame (RGB, height x width x 3)."""
        import time as _time

        t0 = _time.perf_counter()
        if self._renderer is None:
            self._renderer = fs.prepare_renderer(
                mujoco.Renderer(self.model, self.physical.height, self.physical.width)
            )
        self._renderer.update_scene(self.data, camera="camera")
        image = self.physical.camera.expose(self._renderer.render(), self._noise)
        self.costs.frames += 1
        self.costs.render_seconds += _time.perf_counter() - t0
        return image

    def close(self) -> None:
        """Free the renderer's GL context."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    def camera_ray(self, u: float, v: float) -> tuple[np.ndarray, np.ndarray]:
        """Origin and direction, in the base's frame, of the ray through pixel (u, v)."""
        f = (self.physical.height / 2) / math.tan(math.radians(fs.CAMERA_FOVY) / 2)
        xc = (u - self.physical.width / 2) / f
        yc = -(v - self.physical.height / 2) / f
        p = fs.CAMERA_PITCH
        right = np.array([0.0, -1.0, 0.0])
        up = np.array([math.sin(p), 0.0, math.cos(p)])
        back = np.array([-math.cos(p), 0.0, math.sin(p)])
        return np.array(fs.CAMERA_AT), xc * right + yc * up - back

    def locate(self, box: Box) -> tuple[float, float] | None:
        """Where a box's bottom meets the ground, in the base's frame (None above the
        horizon)."""
        origin, direction = self.camera_ray(*box.bottom_centre)
        if direction[2] >= -1e-6:
            return None
        t = -origin[2] / direction[2]
        point = origin + t * direction
        # the box's bottom is the object's near edge: its middle lies a radius further
        flat = math.hypot(direction[0], direction[1])
        return (
            float(point[0] + OBJECT_DEPTH * direction[0] / flat),
            float(point[1] + OBJECT_DEPTH * direction[1] / flat),
        )

    def _detections(self) -> list[Detection]:

        image = self.render()
        boxes = self.detect(image)
        self.last_frame, self.last_boxes = image, boxes
        if self.on_frame is not None:
            self.on_frame(image)
        ex, ey, et = self.base.estimate
        out = []
        self.last_detections = []
        for box in boxes:
            at = self.locate(box)
            if at is None:
                continue
            bx, by = at
            distance = math.hypot(bx, by)
            if distance > self.config.camera_range:
                continue
            bearing = math.atan2(by, bx)
            wx = ex + bx * math.cos(et) - by * math.sin(et)
            wy = ey + bx * math.sin(et) + by * math.cos(et)
            track = self._track(box.label, wx, wy)
            self._book_sighting(wx, wy)
            detection = Detection(
                label=box.label,
                bearing=round(bearing, 4),
                distance=round(distance, 3),
                confidence=box.confidence,
                instance=track.instance,
            )
            out.append(detection)
            self.last_detections.append((detection, box))
        return out

    def _track(self, label: str, x: float, y: float) -> Track:
        best = None
        for t in self.tracks:
            if t is self._holding_track:
                continue
            d = math.hypot(t.x - x, t.y - y)
            if (
                t.label == label
                and d < self.physical.track_radius
                and (best is None or d < best[0])
            ):
                best = (d, t)
        if best is not None:
            t = best[1]
            t.x += (x - t.x) / (t.seen + 1)
            t.y += (y - t.y) / (t.seen + 1)
            t.seen += 1
            t.last = (x, y)
            return t
        t = Track(f"{label}{len(self.tracks) + 1}", label, x, y, last=(x, y))
        self.tracks.append(t)
        return t

    def lidar_scan(self) -> Scan:
        """The lidar's latest scan (it scans at its own rate as the physics steps)."""
        return self._scan or self.base.scan(self.clock)

    def _lidar_percept(self) -> Obstacle:
        scan = self.lidar_scan()
        c = self.config
        ok = np.isfinite(scan.ranges) & (scan.ranges <= c.lidar_range)
        if not ok.any():
            return Obstacle("none", c.lidar_range)
        i = int(np.argmin(np.where(ok, scan.ranges, np.inf)))
        b = float(scan.angles[i])
        sector = "front" if abs(b) <= math.radians(30) else ("left" if b > 0 else "right")
        return Obstacle(sector, round(float(scan.ranges[i]), 3))

    def _gripper_holds(self) -> bool:
        j = self.joint_positions()
        return j["finger_left"] > 0.012 and j["finger_right"] > 0.012

    def percepts(self) -> list[Percept]:
        """One camera frame's detections, the lidar's nearest obstacle, the gripper, and
        the estimated pose once a second."""
        c = self.config
        self._settle(c.frame_seconds)
        out: list[Percept] = list(self._detections())
        out.append(self._lidar_percept())
        out.append(Gripper(self.in_gripper()))
        if self.clock - self._last_pose_time >= c.localisation_period - 1e-9:
            self._last_pose_time = self.clock
            x, y, theta = self.base.estimate
            out.append(Pose(round(x, 3), round(y, 3), round(theta, 4), self.place()))
        return out

    def in_gripper(self) -> str | None:
        """The track the gripper closed on, as the detections named it (the fingers'
        sensors said it holds; which object that is, only the simulator knows)."""
        return self._holding_track.instance if self._holding_track else None

    def place(self) -> str | None:
        """The checkpoint the estimated pose is at, if any."""
        x, y, _ = self.base.estimate if self._built else (self.x, self.y, 0.0)
        for name, (px, py) in self.checkpoints.items():
            if math.hypot(px - x, py - y) <= self.config.place_radius:
                return name
        return None

    # ---- bookkeeping from the simulator (reports only, never percepts) --------------

    def _true_xy(self, t: Trash) -> tuple[float, float, float]:
        p = self.data.body(t.instance).xpos
        return float(p[0]), float(p[1]), float(p[2])

    def _upright(self, t: Trash) -> bool:
        """Whether the object stands (its axis within 40 degrees of vertical)."""
        zz = float(self.data.body(t.instance).xmat[8])
        return zz > math.cos(math.radians(40))

    def _book_sighting(self, x: float, y: float) -> None:
        t = self._nearest_true(x, y)
        if t is not None:
            t.times_seen += 1

    def _nearest_true(self, x: float, y: float, radius: float = 0.7) -> Trash | None:
        best = None
        for t in self.trash:
            if not t.on_field:
                continue
            tx, ty, _ = self._true_xy(t)
            d = math.hypot(tx - x, ty - y)
            if d < radius and (best is None or d < best[0]):
                best = (d, t)
        return best[1] if best else None

    def detection_probability(self, t: Trash) -> float:
        """For the report's count of arrivals with trash in view: 1 when the object is
        on the field within the camera's range and field of view (simulator state; no
        percept uses it)."""
        if not self._built or not t.on_field:
            return 0.0
        tx, ty, _ = self._true_xy(t)
        x, y, theta = self.base.true_pose()
        d = math.hypot(tx - x, ty - y)
        b = wrap(math.atan2(ty - y, tx - x) - theta)
        return (
            1.0 if d <= self.config.camera_range and abs(b) <= self.config.camera_fov / 2 else 0.0
        )

    # ---- acting ---------------------------------------------------------------------

    def _move_to(self, x: float, y: float, turn: bool = True) -> float:
        sx, sy, _ = self.base.estimate
        if turn:
            self._drive_to(x, y)
        else:
            self._back_to(x, y)
        ex, ey, _ = self.base.estimate
        return math.hypot(ex - sx, ey - sy)

    def _forward(self, distance: float) -> Outcome:
        ex, ey, et = self.base.estimate
        x, y = ex + distance * math.cos(et), ey + distance * math.sin(et)
        return self._fenced_move(x, y, turn=distance >= 0)

    def _turn(self, angle: float) -> Outcome:
        self._face(wrap(self.base.estimate[2] + angle))
        return Outcome.success()

    def _reach_checkpoint(self, index: int) -> Outcome:
        arrived = self._drive_to(*self.checkpoints[self.route[index]])
        self._face(self._heading_at(index))
        self._book_arrival(index, "" if arrived else " (not reached)")
        if self.out_of_time:
            return Outcome.failure("battery spent")
        return Outcome.success()

    def _aim(self, target: str) -> Track | None:
        """Look (one frame) and choose the nearest seen object ``target`` names."""
        self._settle(self.config.frame_seconds)
        seen = self._detections()
        ex, ey, _ = self.base.estimate
        names = [d.instance for d in seen if target in ("", "trash", "any", d.label, d.instance)]
        candidates = [t for t in self.tracks if t.instance in names]
        if not candidates:
            return None
        return min(candidates, key=lambda t: math.hypot(t.x - ex, t.y - ey))

    def _pick(self, target: str) -> Outcome:
        """Approach, look again, lower the arm, drive the fingers around it, close,
        lift, and read the fingers; then back off to where the pick began."""
        c = self.config
        pc = self.physical
        if self._holding_track is not None:
            return Outcome.failure("the gripper is already holding something")
        track = self._aim(target)
        if track is None:
            self._advance(1.0)
            return Outcome.failure(f"no {target or 'object'} in view")
        truth = self._nearest_true(track.x, track.y)
        if truth is not None:
            truth.pick_attempts += 1
        was_upright = truth.upright if truth is not None else True
        ex, ey, et = self.base.estimate
        distance = math.hypot(track.x - ex, track.y - ey)
        if distance > c.pick_reach + pc.stand_off:
            self._advance(2.0)
            self._log("pick", f"{track.instance}: too far")
            return Outcome.failure("too far away to grab")
        home, facing, began = (ex, ey), et, self.clock
        # the approach is measured by odometry alone: a correction jumping the estimate
        # in between would move the aim against the object
        self._correcting = False
        try:
            return self._grasp(track, truth, was_upright, home, facing, began)
        finally:
            self._correcting = True

    def _grasp(
        self,
        track: Track,
        truth: Trash | None,
        was_upright: bool,
        home: tuple[float, float],
        facing: float,
        began: float,
    ) -> Outcome:
        pc = self.physical
        ex, ey, _ = self.base.estimate
        distance = math.hypot(track.x - ex, track.y - ey)
        # 1. to the stand-off, facing the object, and look again
        if distance > pc.stand_off:
            k = (distance - pc.stand_off) / distance
            self._drive_to(ex + (track.x - ex) * k, ey + (track.y - ey) * k)
        ex, ey, _ = self.base.estimate
        self._face(math.atan2(track.y - ey, track.x - ex))
        if distance < pc.stand_off - 0.1:
            # too near to see where it stands on the ground (the frame cuts its foot
            # off): back away to the stand-off first
            k = pc.stand_off / max(distance, 1e-6)
            self._back_to(track.x - (track.x - ex) * k, track.y - (track.y - ey) * k)
        again = self._aim(track.instance)
        if again is not None:
            track = again
        aim = track.last
        # 2. arm down, fingers open, then drive the hand around the object
        self._set_fingers(fs.FINGER_OPEN)
        self._move_arm(pc.grasp_reach, pc.grasp_height, 0.0, 1.2)
        ex, ey, _ = self.base.estimate
        self._face(math.atan2(aim[1] - ey, aim[0] - ex), tolerance=0.008)
        ex, ey, _ = self.base.estimate
        d = math.hypot(aim[0] - ex, aim[1] - ey)
        if d > pc.grasp_reach - pc.overdrive:
            k = (d - pc.grasp_reach + pc.overdrive) / d
            self._drive_to(
                ex + (aim[0] - ex) * k, ey + (aim[1] - ey) * k, speed=0.2, tolerance=0.015
            )
        # 3. close, lift, feel
        self._set_fingers(fs.FINGER_CLOSED)
        self._settle(0.8)
        self._move_arm(*CARRY, 1.2)
        held = self._gripper_holds()
        if held:
            self._holding_track = track
            grabbed = self._in_hand()
            if grabbed is not None:
                grabbed.held = True
                self.holding = grabbed
            outcome = Outcome.success()
            self._log("pick", f"{track.instance}: held")
        else:
            self._set_fingers(fs.FINGER_OPEN)
            self._move_arm(*STOW, 1.0)
            if truth is not None and was_upright and not self._upright(truth):
                truth.upright = False
                truth.tipped_at = self.clock
                self._log("tip", truth.instance)
            if truth is not None and not was_upright:
                truth.picks_while_tipped += 1
            outcome = Outcome.failure(
                "slipped: the object is lying over" if not was_upright else "missed the grasp"
            )
            self._log("pick", f"{track.instance}: missed")
        # 4. back to where the pick began, facing the same way
        self._back_to(*home)
        self._face(facing)
        if not was_upright:
            self.futile_seconds += self.clock - began
        return outcome

    def _in_hand(self) -> Trash | None:
        """Which object is between the fingers (bookkeeping)."""
        site = self.data.site("grasp").xpos
        best = None
        for t in self.trash:
            if t.collected or t.cleared:
                continue
            p = self.data.body(t.instance).xipos
            d = float(np.linalg.norm(p - site))
            if d < 0.15 and (best is None or d < best[0]):
                best = (d, t)
        return best[1] if best else None

    def _drop(self) -> Outcome:
        if self._holding_track is None:
            self._advance(1.0)
            return Outcome.failure("the gripper is empty")
        self._move_arm(*TRAY, 2.0)
        self._set_fingers(fs.FINGER_OPEN)
        self._settle(0.6)
        self._move_arm(*STOW, 1.0)
        track = self._holding_track
        self._holding_track = None
        if track in self.tracks:
            self.tracks.remove(track)
        t = self.holding
        self.holding = None
        if t is not None:
            t.held = False
            x, y, z = self._true_xy(t)
            rx, ry, _ = self.base.true_pose()
            if z > 0.15 and math.hypot(x - rx, y - ry) < 0.5:
                t.collected = True
                self._park(t)
                self._log("drop", t.instance)
            else:
                self._log("drop", f"{t.instance}: fell beside the tray")
        return Outcome.success()

    def _park(self, t: Trash) -> None:
        """The trailer takes a collected object away: move it off the field."""
        j = self.model.joint(t.instance)
        adr = j.qposadr[0]
        k = len([x for x in self.trash if x.collected])
        self.data.qpos[adr : adr + 7] = [-5.0 - 0.5 * k, -5.0, 0.1, 1, 0, 0, 0]
        self.data.qvel[j.dofadr[0] : j.dofadr[0] + 6] = 0.0
        mujoco.mj_forward(self.model, self.data)

    def snapshot(self) -> dict[str, Any]:
        """Costs so far (for benchmarks)."""
        return dict(self.costs.__dict__)
