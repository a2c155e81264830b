"""The Q.bo over ROS 2, as a ``Body``: what ``robocog bridge ros2 --mind qbo`` drives.

The topics are the Q.bo's (those ``robocog sim room --world mujoco --ros2`` serves): the
head camera's ``sensor_msgs/Image``, a ``sensor_msgs/Range`` per ultrasonic sensor,
``/odom``, ``/joint_states`` and ``/clock`` in; ``/cmd_vel`` and the head's pan
(``std_msgs/Float64``) out. The Commands of :mod:`robocog.minds.qbo` become what the
paper's Python side did with ROS calls:

* ``Look("around")``: turn the head to +55, 0 and -55 degrees (waiting until the joint
  state says it is there), take the next image at each, split it into 3 x 2 areas and
  classify each with the SVMs of ``robocog.worlds.physics.room_vision`` (the physics
  extra); areas above the threshold become ``Detection`` percepts until the robot moves.
  The bridges know no world, so that module is handed in (``vision``), and the bridge's
  command loads it by name, as it loads the inspector.
* ``Forward(d)``: publish a forward velocity until the odometry has gone ``d``, an
  ultrasonic reading drops under the stop distance (``obstacle ahead``) or the odometry
  stops advancing (``bumped``).
* ``Turn(a)``: publish a turn rate until the odometry's heading has turned ``a``.

Durations are measured on the robot's clock (the stamps of its messages), so the body
works the same whether the simulator runs in real time or faster.
"""

from __future__ import annotations

import logging
import math
import os
import threading
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import yaw_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.link import RELIABLE, SENSOR, serve_readers, typed
from robocog.robot.commands import Command, Forward, Look, Outcome, Turn
from robocog.robot.percepts import Detection, Percept, Pose, Range, sonar_obstacle

log = logging.getLogger("robocog.bridges")

TOPICS = {
    "image": "/camera/image_raw",
    "us_left": "/range/us_left",
    "us_right": "/range/us_right",
    "odom": "/odom",
    "joints": "/joint_states",
    "clock": "/clock",
    "cmd_vel": "/cmd_vel",
    "head": "/head/command",
}
SPEED, TURN_SPEED = 0.15, 0.6
STOP_DISTANCE, OBSTACLE_RANGE = 0.25, 0.45
STALL_SECONDS, STALL_PROGRESS = 1.0, 0.02
THRESHOLD = 0.5
#: the largest image accepted (pixels), and the period (wall s) of the velocity commands
MAX_PIXELS = 4096 * 4096
COMMAND_PERIOD = 0.02


def _wrap(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


def _stamp(header: Any) -> float:
    return float(header.stamp.sec) + float(header.stamp.nanosec) * 1e-9


class QboRos2Body:
    """The Q.bo's topics as a ``Body`` the bridge's runner drives."""

    def __init__(
        self,
        domain_id: int | None = None,
        config: BridgeConfig | None = None,
        namespace: str = "",
        vision: Any = None,
        classifier: Any = None,
        on_message: Callable[[str, str, Any], None] | None = None,
        recorder: Any = None,
    ) -> None:
        self.config = config or BridgeConfig(pose_source="odom")
        #: a ``Recorder`` given every message and closed with the body, as ``Ros2Link``'s
        self.recorder = recorder
        if on_message is None and recorder is not None:
            on_message = recorder.write
        #: the image areas' classification (``robocog.worlds.physics.room_vision``)
        self.vision = vision
        self.classifier = classifier
        self.on_message = on_message
        self._lock = threading.Condition()
        self._stop = threading.Event()
        self._halted: str | None = None
        self.pose: tuple[float, float, float, float] | None = None  # x, y, theta, stamp
        self.ranges: dict[str, float] = {}
        self.image: tuple[float, np.ndarray] | None = None
        self.pan: tuple[float, float] | None = None  # pan, stamp
        self.clock = 0.0
        self.detections: list[Detection] = []
        self.readings = 0
        if domain_id is None:
            domain_id = int(os.environ.get("ROS_DOMAIN_ID", "0"))
        self.dp = dp = DomainParticipant(domain_id)
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""

        def reader(key: str, kind: type, qos: Any) -> DataReader:
            topic = Topic(dp, m.topic_name(ns + TOPICS[key]), kind, qos=RELIABLE)
            return DataReader(dp, topic, qos=typed(qos, kind))

        def writer(key: str, kind: type) -> DataWriter:
            topic = Topic(dp, m.topic_name(ns + TOPICS[key]), kind, qos=RELIABLE)
            return DataWriter(dp, topic, qos=typed(RELIABLE, kind))

        self._readers: list[tuple[DataReader, Callable[[Any], None]]] = [
            (reader("odom", m.Odometry, RELIABLE), self._on_odom),
            (reader("us_left", m.Range, SENSOR), lambda s: self._on_range("us_left", s)),
            (reader("us_right", m.Range, SENSOR), lambda s: self._on_range("us_right", s)),
            (reader("image", m.Image, SENSOR), self._on_image),
            (reader("joints", m.JointState, RELIABLE), self._on_joints),
            (reader("clock", m.Clock, SENSOR), self._on_clock),
        ]
        self.w_cmd = writer("cmd_vel", m.Twist)
        self.w_head = writer("head", m.Float64)
        self._listener = threading.Thread(target=self._listen, daemon=True, name="qbo-listen")

    # -- the runner's side ---------------------------------------------------------------

    def start(self) -> QboRos2Body:
        """Begin listening."""
        if not self._listener.is_alive():
            self._listener.start()
        return self

    def close(self) -> None:
        """Stop the robot and the listener."""
        if self._listener.is_alive():
            self.stop()
        self._stop.set()
        with self._lock:
            self._lock.notify_all()
        if self._listener.is_alive():
            self._listener.join(timeout=2.0)
        if self.recorder is not None:
            self.recorder.close()

    def time(self) -> float:
        """The robot's clock (seconds)."""
        return self.clock

    @property
    def scans(self) -> int:
        """Readings received (the runner's frame count)."""
        return self.readings

    def wait_for_readings(self, timeout: float) -> bool:
        """Wait up to ``timeout`` seconds for a new reading."""
        with self._lock:
            seen = self.readings
            return self._lock.wait_for(lambda: self.readings > seen, timeout)

    def wait_for_frame(self, seen: int, timeout: float) -> tuple[int, float]:
        """Lock-step is not served by the Q.bo: the latest count and clock."""
        self.wait_for_readings(timeout)
        return self.readings, self.clock

    def frame_done(self, stamp: float) -> None:
        """Lock-step is not served by the Q.bo."""

    def texts(self) -> list[str]:
        """The Q.bo takes no text input."""
        return []

    def mission_ended(self) -> str | None:
        """Always None: the room's robot publishes no mission state; its run ends when
        the Q.bo's plans end (the runner asks every body)."""
        return None

    def stale(self) -> str | None:
        """Why the percepts cannot be trusted yet, or None."""
        if self.pose is None:
            return "no odometry yet"
        if len(self.ranges) < 2:
            return "no ultrasonic readings yet"
        return None

    def halt(self, reason: str) -> None:
        """Stop and refuse motion until :meth:`resume`."""
        self._halted = reason
        self.stop()

    def resume(self) -> None:
        """Accept motion again."""
        self._halted = None

    def stop(self) -> None:
        """Zero velocity."""
        self._send(self.w_cmd, m.Twist())

    # -- Body --------------------------------------------------------------------------

    def percepts(self) -> list[Percept]:
        """Odometry, each ultrasonic sensor, the obstacle ahead, the last look's areas."""
        out: list[Percept] = []
        with self._lock:
            pose, ranges = self.pose, dict(self.ranges)
            detections = list(self.detections)
        if pose is not None:
            out.append(Pose(pose[0], pose[1], pose[2], None))
        for name in ("us_left", "us_right"):
            if name in ranges:
                out.append(Range(name, ranges[name]))
        if len(ranges) == 2:
            out.append(sonar_obstacle(ranges["us_left"], ranges["us_right"], OBSTACLE_RANGE))
        out.extend(detections)
        return out

    def execute(self, command: Command) -> Outcome:
        """Carry out a Look, Forward or Turn over the topics."""
        if self._halted is not None:
            return Outcome.failure(f"halted: {self._halted}")
        try:
            if isinstance(command, Look):
                return self._look(command)
            if isinstance(command, Forward):
                return self._forward(command.distance)
            if isinstance(command, Turn):
                return self._turn(command.angle)
        finally:
            if not isinstance(command, Look):
                self.stop()
        return Outcome.failure(f"the Q.bo cannot {type(command).__name__}")

    # -- commands ----------------------------------------------------------------------

    def _wait_clock(self, seconds: float, during: Callable[[], None] | None = None) -> None:
        """Let ``seconds`` of the robot's time pass (publishing ``during`` meanwhile)."""
        end = self.clock + seconds
        wall_end = time.monotonic() + 10.0 + seconds * 5
        while self.clock < end and time.monotonic() < wall_end and not self._stop.is_set():
            if during is not None:
                during()
            time.sleep(COMMAND_PERIOD)

    def _forward(self, distance: float) -> Outcome:
        if self.pose is None:
            return Outcome.failure("no odometry")
        sign = 1.0 if distance >= 0 else -1.0
        total = abs(distance)
        x0, y0 = self.pose[0], self.pose[1]
        start = self.clock
        limit = start + total / SPEED * 1.5 + 2.0
        history: list[tuple[float, float]] = []
        wall_limit = time.monotonic() + 60.0
        outcome = Outcome.success()
        while not self._stop.is_set():
            with self._lock:
                x, y, _theta, _stamp_ = self.pose
                nearest = min(self.ranges.values())
                now = self.clock
            travelled = math.hypot(x - x0, y - y0)
            if travelled >= total - 0.005:
                break
            if sign > 0 and nearest < STOP_DISTANCE:
                outcome = Outcome.failure("obstacle ahead")
                break
            history.append((now, travelled))
            while history and history[0][0] < now - STALL_SECONDS:
                history.pop(0)
            if (
                now - history[0][0] >= STALL_SECONDS * 0.95
                and travelled - history[0][1] < STALL_PROGRESS
            ):
                outcome = Outcome.failure("bumped")
                break
            if now > limit or time.monotonic() > wall_limit:
                outcome = Outcome.failure("too slow")
                break
            v = sign * min(SPEED, max(0.05, (total - travelled) * 2.0))
            self._send(self.w_cmd, m.Twist(m.Vector3(x=v), m.Vector3()))
            time.sleep(COMMAND_PERIOD)
        self.stop()
        self._wait_clock(0.2, self.stop)
        self._moved()
        return outcome

    def _turn(self, angle: float) -> Outcome:
        if self.pose is None:
            return Outcome.failure("no odometry")
        target = _wrap(self.pose[2] + angle)
        limit = self.clock + abs(angle) / TURN_SPEED * 2.0 + 2.0
        wall_limit = time.monotonic() + 60.0
        outcome = Outcome.success()
        while not self._stop.is_set():
            remaining = _wrap(target - self.pose[2])
            if abs(remaining) < math.radians(0.5):
                break
            if self.clock > limit or time.monotonic() > wall_limit:
                outcome = Outcome.failure("blocked")
                break
            w = max(-TURN_SPEED, min(TURN_SPEED, 3.0 * remaining))
            if abs(w) < 0.08:
                w = math.copysign(0.08, remaining)
            self._send(self.w_cmd, m.Twist(m.Vector3(), m.Vector3(z=w)))
            time.sleep(COMMAND_PERIOD)
        self.stop()
        self._wait_clock(0.1, self.stop)
        self._moved()
        return outcome

    def _moved(self) -> None:
        with self._lock:
            self.detections = []

    def _pan_to(self, target: float) -> float:
        """Command the head until the joint state says it is there; the time it was."""
        wall_limit = time.monotonic() + 10.0
        settled = 0
        while not self._stop.is_set() and time.monotonic() < wall_limit:
            self._send(self.w_head, m.Float64(target))
            pan = self.pan
            if pan is not None and abs(pan[0] - target) < math.radians(1.0):
                settled += 1
                if settled >= 3:
                    return pan[1]
            else:
                settled = 0
            time.sleep(COMMAND_PERIOD)
        return self.clock

    def _image_after(self, stamp: float) -> np.ndarray | None:
        """The first image taken at or after ``stamp`` (robot time)."""
        wall_limit = time.monotonic() + 10.0
        with self._lock:
            while not self._stop.is_set() and time.monotonic() < wall_limit:
                if self.image is not None and self.image[0] >= stamp:
                    return self.image[1]
                self._lock.wait(0.05)
        return None

    def _look(self, look: Look) -> Outcome:
        vision = self.vision
        if vision is None:
            return Outcome.failure("this body was given no image classifier")
        pans = dict(zip(("left", "front", "right"), vision.PANS, strict=True))
        names = look.views(pans)
        if names is None:
            return Outcome.failure(f"unknown look direction {look.direction!r}")
        if self.classifier is None:
            self.classifier = vision.shared_classifier()
        found: list[Detection] = []
        for name in names:
            at = self._pan_to(math.radians(pans[name]))
            image = self._image_after(at)
            if image is None:
                return Outcome.failure("no image from the camera")
            if image.shape[:2] != (vision.HEIGHT, vision.WIDTH):
                return Outcome.failure(
                    f"the camera's images are {image.shape[1]} x {image.shape[0]}, "
                    f"the classifiers' {vision.WIDTH} x {vision.HEIGHT}"
                )
            feats = np.array([vision.area_features(a) for a in vision.split_areas(image)])
            certainty = self.classifier.certainty(feats)
            pan_deg = math.degrees(self.pan[0]) if self.pan else pans[name]
            for i in range(vision.ROWS * vision.COLUMNS):
                row, col = divmod(i, vision.COLUMNS)
                for label in vision.TARGETS:
                    value = float(certainty[label][i])
                    if value > THRESHOLD:
                        bearing = vision.area_bearing(pan_deg, col)
                        found.append(Detection(label, bearing, 0.0, value, f"{name}:{row}:{col}"))
        self._pan_to(0.0)
        with self._lock:
            self.detections = found
        return Outcome.success()

    # -- readings ----------------------------------------------------------------------

    def _send(self, writer: DataWriter, message: Any) -> None:
        if self.on_message is not None:
            self.on_message(writer.topic.name, type(message).__name__, message)
        writer.write(message)

    def _tick(self, stamp: float) -> None:
        self.clock = max(self.clock, stamp)
        self.readings += 1
        self._lock.notify_all()

    def _on_odom(self, msg: m.Odometry) -> None:
        p = msg.pose.pose
        q = p.orientation
        values = (float(p.position.x), float(p.position.y), yaw_of(q.x, q.y, q.z, q.w))
        if not all(math.isfinite(v) for v in values):
            return
        stamp = _stamp(msg.header)
        with self._lock:
            self.pose = (*values, stamp)
            self._tick(stamp)

    def _on_range(self, name: str, msg: m.Range) -> None:
        value = float(msg.range)
        if math.isnan(value):
            return
        with self._lock:
            self.ranges[name] = min(value, float(msg.max_range) or value)
            self._tick(_stamp(msg.header))

    def _on_image(self, msg: m.Image) -> None:
        h, w = int(msg.height), int(msg.width)
        if msg.encoding != "rgb8" or h * w > MAX_PIXELS or len(msg.data) != h * w * 3:
            return
        image = np.frombuffer(bytes(msg.data), dtype=np.uint8).reshape(h, w, 3)
        with self._lock:
            self.image = (_stamp(msg.header), image)
            self._lock.notify_all()

    def _on_joints(self, msg: m.JointState) -> None:
        names = list(msg.name)
        if "head_pan" in names and len(msg.position) == len(names):
            pan = float(msg.position[names.index("head_pan")])
            with self._lock:
                self.pan = (pan, _stamp(msg.header))

    def _on_clock(self, msg: m.Clock) -> None:
        with self._lock:
            self.clock = max(self.clock, float(msg.clock.sec) + float(msg.clock.nanosec) * 1e-9)

    def _listen(self) -> None:
        serve_readers(self.dp, self._readers, self._stop, log)
