"""``robocog sim room --world mujoco --ros2``: the physical Q.bo room as a ROS 2 robot.

What a Q.bo's ROS drivers offer, from :class:`~robocog.worlds.mujoco_room.MujocoRoom`:
``/camera/image_raw`` (sensor_msgs/Image, ``rgb8``, the head camera, five a second),
``/range/us_left`` and ``/range/us_right`` (sensor_msgs/Range, ultrasound, each the
nearest echo in its cone), ``/odom`` (nav_msgs/Odometry from the wheel encoders and the
IMU), ``/tf`` (odom -> base_link -> head_link), ``/joint_states`` (the head's pan and
the wheels), ``/clock`` (simulated time); the sensors twenty times a second. It takes
``/cmd_vel`` (geometry_msgs/Twist; the base stops when none came for half a second) and
``/head/command`` (std_msgs/Float64, the head's pan in radians).

The physics runs in steps of the world's control period, paced at ``rate`` times real
time. The robot does no thinking of its own: looking around, stopping at an obstacle
and the rest are the controller's to do from these topics.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from typing import Any

from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from robocog.bridges.perception import quaternion_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.link import RELIABLE, SENSOR, serve_readers, typed
from robocog.worlds.mujoco_room import MujocoRoom

log = logging.getLogger("robocog.sim")

#: the base stops when no velocity came for this long (simulated seconds)
TWIST_TIMEOUT = 0.5
#: images a simulated second, and sensor frames a simulated second
IMAGE_RATE, SENSOR_RATE = 5.0, 20.0
#: the largest speeds a Twist may ask for (m/s, rad/s); more is clipped
MAX_SPEED, MAX_TURN = 0.3, 1.0

TOPICS = {
    "image": "/camera/image_raw",
    "us_left": "/range/us_left",
    "us_right": "/range/us_right",
    "odom": "/odom",
    "tf": "/tf",
    "joints": "/joint_states",
    "clock": "/clock",
    "cmd_vel": "/cmd_vel",
    "head": "/head/command",
}


class QboRoomRobot:
    """A ``MujocoRoom`` behind ROS 2 topics on its own participant."""

    def __init__(
        self,
        world: MujocoRoom,
        domain_id: int,
        *,
        rate: float = 1.0,
        namespace: str = "",
        max_seconds: float | None = None,
        on_message: Callable[[str, str, Any], None] | None = None,
    ) -> None:
        if rate <= 0:
            raise ValueError("rate must be positive")
        self.world = world
        self.rate = rate
        self.max_seconds = max_seconds
        self.on_message = on_message
        self.frames = 0
        self.images = 0
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._twist = (0.0, 0.0, -math.inf)
        self._pan = 0.0
        self.dp = dp = DomainParticipant(domain_id)
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""

        def writer(key: str, kind: type, qos: Any = RELIABLE) -> DataWriter:
            topic = Topic(dp, m.topic_name(ns + TOPICS[key]), kind, qos=RELIABLE)
            return DataWriter(dp, topic, qos=typed(qos, kind))

        def reader(key: str, kind: type) -> DataReader:
            topic = Topic(dp, m.topic_name(ns + TOPICS[key]), kind, qos=RELIABLE)
            return DataReader(dp, topic, qos=typed(RELIABLE, kind))

        self.w_image = writer("image", m.Image, SENSOR)
        self.w_range = {
            "us_left": writer("us_left", m.Range, SENSOR),
            "us_right": writer("us_right", m.Range, SENSOR),
        }
        self.w_odom = writer("odom", m.Odometry)
        self.w_tf = writer("tf", m.TFMessage)
        self.w_joints = writer("joints", m.JointState)
        self.w_clock = writer("clock", m.Clock, SENSOR)
        self._readers: list[tuple[DataReader, Callable[[Any], None]]] = [
            (reader("cmd_vel", m.Twist), self._on_twist),
            (reader("head", m.Float64), self._on_head),
        ]
        self._listener = threading.Thread(target=self._listen, daemon=True, name="room-listen")

    # -- running -----------------------------------------------------------------------

    def run(self, until: Callable[[], bool] | None = None) -> None:
        """Step and publish until ``stop()``, ``until()`` or ``max_seconds`` of sim time."""
        if not self._listener.is_alive():
            self._listener.start()
        w = self.world
        period = w.config.control_period
        every_image = max(1, round(1.0 / (IMAGE_RATE * period)))
        every_frame = max(1, round(1.0 / (SENSOR_RATE * period)))
        tick = 0
        next_wall = time.monotonic()
        while not self._stop.is_set():
            if until is not None and until():
                break
            if self.max_seconds is not None and w.time() >= self.max_seconds:
                break
            with self._lock:
                v, omega, at = self._twist
                pan = self._pan
            if w.time() - at > TWIST_TIMEOUT:
                v = omega = 0.0
            w.drive(v, omega, pan=pan)
            tick += 1
            if tick % every_frame == 0:
                self._publish_sensors()
            if tick % every_image == 0:
                self._publish_image()
            next_wall += period / self.rate
            delay = next_wall - time.monotonic()
            if delay > 0:
                self._stop.wait(delay)
            else:
                next_wall = time.monotonic()  # behind: do not try to catch up in a burst

    def stop(self) -> None:
        """End ``run`` and the listener."""
        self._stop.set()

    def close(self) -> None:
        """Stop, and wait for the listener."""
        self.stop()
        if self._listener.is_alive():
            self._listener.join(timeout=2.0)

    # -- messages ----------------------------------------------------------------------

    def _send(self, writer: DataWriter, message: Any) -> None:
        if self.on_message is not None:
            self.on_message(writer.topic.name, type(message).__name__, message)
        writer.write(message)

    def _publish_sensors(self) -> None:
        w = self.world
        now = m.stamp_now(w.time())
        self._send(self.w_clock, m.Clock(now))
        c = w.config
        for (name, writer), reading in zip(self.w_range.items(), w.sonars(), strict=True):
            self._send(
                writer,
                m.Range(
                    m.Header(now, f"{name}_link"),
                    m.ULTRASOUND,
                    2 * math.radians(c.sonar_cone_degrees),
                    0.02,
                    c.sonar_range,
                    reading,
                    c.sonar_noise**2,
                ),
            )
        x, y, theta = w.base.odometry.pose
        qx, qy, qz, qw = quaternion_of(theta)
        pose = m.Pose(m.Point(x, y, 0.0), m.Quaternion(qx, qy, qz, qw))
        with self._lock:
            v, omega, _ = self._twist
        twist = m.TwistWithCovariance(m.Twist(m.Vector3(x=v), m.Vector3(z=omega)))
        self._send(
            self.w_odom,
            m.Odometry(m.Header(now, "odom"), "base_link", m.PoseWithCovariance(pose), twist),
        )
        hx, hy, hz, hw = quaternion_of(w.pan)
        self._send(
            self.w_tf,
            m.TFMessage(
                [
                    m.TransformStamped(
                        m.Header(now, "odom"),
                        "base_link",
                        m.Transform(m.Vector3(x, y, 0.0), m.Quaternion(qx, qy, qz, qw)),
                    ),
                    m.TransformStamped(
                        m.Header(now, "base_link"),
                        "head_link",
                        m.Transform(m.Vector3(0.02, 0.0, 0.33), m.Quaternion(hx, hy, hz, hw)),
                    ),
                ]
            ),
        )
        joints = w.joints()
        self._send(
            self.w_joints,
            m.JointState(m.Header(now, "base_link"), list(joints), list(joints.values()), [], []),
        )
        self.frames += 1

    def _publish_image(self) -> None:
        w = self.world
        self._send(self.w_image, m.rgb8(m.Header(m.stamp_now(w.time()), "camera_link"), w.image()))
        self.images += 1

    # -- commands ----------------------------------------------------------------------

    def _on_twist(self, msg: m.Twist) -> None:
        v = max(-MAX_SPEED, min(MAX_SPEED, float(msg.linear.x)))
        omega = max(-MAX_TURN, min(MAX_TURN, float(msg.angular.z)))
        if not (math.isfinite(v) and math.isfinite(omega)):
            return
        with self._lock:
            self._twist = (v, omega, self.world.time())

    def _on_head(self, msg: m.Float64) -> None:
        pan = float(msg.data)
        if not math.isfinite(pan):
            return
        with self._lock:
            self._pan = max(-math.radians(95.0), min(math.radians(95.0), pan))

    def _listen(self) -> None:
        serve_readers(self.dp, self._readers, self._stop, log)


def run_room(args: Any) -> int:
    """``robocog sim room``: serve the physical room until stopped (or ``--max-frames``)."""
    import os
    import signal
    import sys

    from robocog.signals import handling

    if getattr(args, "world_kind", None) not in (None, "mujoco"):
        print(
            "robocog sim room: only the physical room (--world mujoco) is served", file=sys.stderr
        )
        return 2
    if not args.ros2 or args.ros1:
        print("robocog sim room: served over ROS 2 only (--ros2)", file=sys.stderr)
        return 2
    if args.loopback:
        from robocog.bridges.ros2.loopback import loopback_unless_configured

        loopback_unless_configured()
    domain = args.domain if args.domain is not None else int(os.environ.get("ROS_DOMAIN_ID", "0"))
    world = MujocoRoom(args.seed)
    recorder: Any = None
    if args.record is not None:
        from robocog.bridges.ros2.record import Recorder

        recorder = Recorder(args.record)
    robot = QboRoomRobot(
        world,
        domain,
        rate=args.rate,
        namespace=args.namespace,
        on_message=recorder.write if recorder is not None else None,
    )
    limit = args.max_frames

    def _terminate(_signum: int, _frame: object) -> None:
        robot.stop()

    print(
        f"robocog sim: the Q.bo's room in MuJoCo (seed {args.seed}, door open "
        f"{math.degrees(world.door_angle):.0f} degrees) on ROS 2 domain {domain}"
        f"{' (loopback)' if args.loopback else ''}",
        file=sys.stderr,
        flush=True,
    )
    try:
        with handling(signal.SIGTERM, _terminate):
            robot.run(until=(lambda: robot.frames >= limit) if limit is not None else None)
    except KeyboardInterrupt:
        pass
    finally:
        robot.close()
        world.close()
        if recorder is not None:
            recorder.close()
    if world.exited():
        where = "out of the room"
    elif world.at_entrance():
        where = "in the doorway"
    else:
        where = "in the room"
    where += f" at ({world.x:.2f}, {world.y:.2f})"
    print(
        f"robocog sim: {world.time():.0f} simulated seconds, {robot.frames} sensor frames, "
        f"{robot.images} images; the robot is {where}",
        flush=True,
    )
    return 0
