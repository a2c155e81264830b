"""The ROS 2 side of a bridge: Cyclone DDS readers and writers on the ROS 2 topics.

One thread waits on all readers at once and hands every sample, turned into a plain
reading, to the ``RobotBody``. Velocity goes out on ``/cmd_vel``; GoTo is a goal of the
Nav2 action ``navigate_to_pose`` whose result (succeeded, aborted, canceled) is the
command's outcome; Pick and Drop are goals of the gripper action (``Grasp``). The QoS
follows ROS 2's: reliable and volatile by default, best effort for the laser scan
(sensor data), plain CDR (XCDR1) as rmw_cyclonedds writes it. A reading with a NaN or
an infinite value where a number is needed is dropped and counted, never handed on.
"""

from __future__ import annotations

import itertools
import logging
import os
import threading
import time
from collections.abc import Callable
from typing import Any

from cyclonedds.core import (
    InstanceState,
    Policy,
    Qos,
    ReadCondition,
    SampleState,
    ViewState,
    WaitSet,
)
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader, InvalidSample
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import BoxReading, PoseReading, ScanReading, quaternion_of, yaw_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.actions import ActionClient

log = logging.getLogger("robocog.bridges.ros2")

#: ROS 2's default profile: reliable, volatile, keep last 10
RELIABLE = Qos(
    Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
    Policy.Durability.Volatile,
    Policy.History.KeepLast(10),
    Policy.DataRepresentation(use_cdrv0_representation=True),
)
#: ROS 2's sensor-data profile: best effort, keep last 5
SENSOR = Qos(
    Policy.Reliability.BestEffort,
    Policy.Durability.Volatile,
    Policy.History.KeepLast(5),
    Policy.DataRepresentation(use_cdrv0_representation=True),
)


def serve_readers(
    dp: DomainParticipant,
    readers: list[tuple[DataReader, Callable[[Any], None]]],
    stop: threading.Event,
    logger: logging.Logger,
    *,
    guard: bool = False,
) -> None:
    """Hand every sample of ``readers`` to its handler as it comes, until ``stop`` is set.

    The one reading loop of the robot ends (the simulators and the Q.bo bridge): a sample
    that cannot be read is logged and skipped, an invalid one (a writer left) is passed
    over; with ``guard`` a handler's error is logged instead of ending the loop, for a
    simulator that must outlive one bad request.
    """
    waitset = WaitSet(dp)
    mask = SampleState.NotRead | ViewState.Any | InstanceState.Any
    for r, _handler in readers:
        waitset.attach(ReadCondition(r, mask))
    while not stop.is_set():
        waitset.wait(duration(milliseconds=50))
        for r, handler in readers:
            try:
                samples = r.take(32)
            except Exception as exc:  # noqa: BLE001 - a malformed sample
                logger.warning("could not read %s: %s", r.topic.name, exc)
                continue
            for sample in samples:
                if isinstance(sample, InvalidSample):
                    continue  # a writer left or an instance was disposed: no data
                if not guard:
                    handler(sample)
                    continue
                try:
                    handler(sample)
                except Exception:  # noqa: BLE001 - a bad request must not stop the sim
                    logger.exception("could not use a message from %s", r.topic.name)


def typed(qos: Qos, kind: type) -> Qos:
    """``qos`` with the type's hash in USER_DATA (``typehash=RIHS01_...;``), as
    rmw_cyclonedds announces each endpoint since ROS 2 Iron."""
    from robocog.bridges.ros2.definitions import DEFINITIONS, ros_type_of, type_hash

    name = ros_type_of(kind.__idl_typename__)
    if name not in DEFINITIONS:
        return qos
    return Qos(*qos, Policy.Userdata(f"typehash={type_hash(name)};".encode()))


class Ros2Link:
    """A ``Link`` speaking ROS 2 over Cyclone DDS on one domain."""

    def __init__(
        self, config: BridgeConfig, domain_id: int | None = None, recorder: Any = None
    ) -> None:
        self.config = config
        #: gets (DDS topic, message) of every sample read or written, to record a run
        self.recorder = recorder
        if domain_id is None:
            domain_id = int(os.environ.get("ROS_DOMAIN_ID", "0"))
        self.domain_id = domain_id
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._tokens = itertools.count(1)
        self._dp: DomainParticipant | None = None
        self._warned: set[str] = set()
        #: how long a first goal waits for the action server to be discovered (s)
        self.server_wait = 10.0

    def start(self, body: RobotBody) -> None:
        """Create the participant, readers and writers, and start the reading thread."""
        tp = self.config.topics
        dp = self._dp = DomainParticipant(self.domain_id)

        def topic(name: str, kind: type, prefix: str = "rt", suffix: str = "") -> Topic:
            return Topic(dp, m.topic_name(name, prefix) + suffix, kind, qos=RELIABLE)

        self._cmd_vel = DataWriter(dp, topic(tp.cmd_vel, m.Twist), qos=typed(RELIABLE, m.Twist))
        self._gripper = DataWriter(
            dp, topic(tp.gripper_command, m.String), qos=typed(RELIABLE, m.String)
        )
        self._frame_done = DataWriter(dp, topic(tp.frame_done, m.Time), qos=typed(RELIABLE, m.Time))
        record = self.recorder.write if self.recorder is not None else None
        self._navigate = ActionClient(
            dp, tp.navigate_action, m.NAVIGATE_TO_POSE, RELIABLE, on_write=record
        )
        self._grasp = ActionClient(dp, tp.grasp_action, m.GRASP, RELIABLE, on_write=record)
        # the scan is read last: a robot (or a lock-step simulator) that sends a frame's
        # pose and detections before its scan has them all read when the scan is
        readers: list[tuple[DataReader, Any]] = [
            (
                DataReader(
                    dp,
                    topic(tp.detections, m.Detection2DArray),
                    qos=typed(RELIABLE, m.Detection2DArray),
                ),
                self._on_dets,
            ),
            (
                DataReader(dp, topic(tp.gripper_state, m.String), qos=typed(RELIABLE, m.String)),
                self._on_gripper,
            ),
            (
                DataReader(dp, topic(tp.narsese, m.String), qos=typed(RELIABLE, m.String)),
                self._on_text,
            ),
            (
                DataReader(dp, topic(tp.mission, m.String), qos=typed(RELIABLE, m.String)),
                self._on_mission,
            ),
        ]
        if self.config.pose_source == "odom":
            readers.append(
                (
                    DataReader(dp, topic(tp.odom, m.Odometry), qos=typed(RELIABLE, m.Odometry)),
                    self._on_odom,
                )
            )
        elif self.config.pose_source == "amcl":
            pose_qos = RELIABLE  # amcl publishes transient-local; volatile readers match it
            kind = m.PoseWithCovarianceStamped
            readers.append(
                (
                    DataReader(dp, topic(tp.amcl_pose, kind), qos=typed(pose_qos, kind)),
                    self._on_amcl,
                )
            )
        else:
            raise ValueError(
                f"pose_source must be 'amcl' or 'odom', not {self.config.pose_source!r}"
            )
        readers += self._navigate.handlers + self._grasp.handlers
        readers.append(
            (
                DataReader(dp, topic(tp.scan, m.LaserScan), qos=typed(SENSOR, m.LaserScan)),
                self._on_scan,
            )
        )
        #: (reader, handler) pairs the reading thread serves, scan last
        self.readers = readers
        self._body = body
        self._stop.clear()
        self._thread = threading.Thread(
            target=self._read, args=(dp, self.readers), name="ros2-link", daemon=True
        )
        self._thread.start()

    def close(self) -> None:
        """Stop the reading thread and drop the participant (and all its entities)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
            self._thread = None
        if self.recorder is not None:
            self.recorder.close()
        self._dp = None

    # -- requests ------------------------------------------------------------------

    def send_velocity(self, linear: float, angular: float) -> None:
        """Publish a Twist on ``cmd_vel``."""
        self._write(self._cmd_vel, m.Twist(m.Vector3(x=linear), m.Vector3(z=angular)))

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        """Send a NavigateToPose goal in the map frame; its result ends the token."""
        token = next(self._tokens)
        if not self._navigate.wait_for_server(self.server_wait):
            self._body.on_goal_result(token, "no navigation action server")
            return token
        qx, qy, qz, qw = quaternion_of(yaw)
        header = m.Header(m.stamp_now(time.time()), self.config.map_frame)
        pose = m.Pose(m.Point(x, y, 0.0), m.Quaternion(qx, qy, qz, qw))
        goal = m.NavigateToPoseGoal(m.PoseStamped(header, pose))

        def done(status: str, _result: Any) -> None:
            self._body.on_goal_result(token, status)

        self._navigate.send_goal(goal, done)
        return token

    def cancel_goals(self) -> None:
        """Cancel every navigation goal (the action's cancel service, zero goal id)."""
        self._navigate.cancel_all()

    def send_gripper(self, text: str) -> int | None:
        """A Grasp goal when the robot serves the gripper action, else a
        std_msgs/String request on ``gripper_command`` (the state then tells)."""
        if not self._grasp.server_ready():
            self._write(self._gripper, m.String(text))
            return None
        token = next(self._tokens)
        command, _, target = text.partition(" ")

        def done(status: str, result: Any) -> None:
            if result is None:
                self._body.on_gripper_result(token, False, f"gripper goal {status}", None)
                return
            ok = status == "succeeded" and bool(result.success)
            self._body.on_gripper_result(token, ok, result.message, result.holding)

        self._grasp.send_goal(m.GraspGoal(command, target.strip()), done)
        return token

    def frame_done(self, stamp: float) -> None:
        """Acknowledge the frame stamped ``stamp`` (a lock-step simulator steps on)."""
        self._write(self._frame_done, m.stamp_now(stamp))

    def _write(self, writer: DataWriter, message: Any) -> None:
        # recorded before it is sent: what the robot does about it is recorded after it
        if self.recorder is not None:
            self.recorder.write(writer.topic.name, message)
        writer.write(message)

    # -- readings ------------------------------------------------------------------

    def _read(self, dp: DomainParticipant, readers: list[tuple[DataReader, Any]]) -> None:
        waitset = WaitSet(dp)
        mask = SampleState.NotRead | ViewState.Any | InstanceState.Any
        for reader, _handler in readers:
            waitset.attach(ReadCondition(reader, mask))
        while not self._stop.is_set():
            waitset.wait(duration(milliseconds=50))
            for reader, handler in readers:
                try:
                    samples = reader.take(32)
                except Exception as exc:  # noqa: BLE001 - a malformed sample, say
                    self._once(reader.topic.name, "could not read %s: %s", exc)
                    continue
                for sample in samples:
                    if isinstance(sample, InvalidSample):
                        continue  # a writer left or an instance was disposed: no data
                    if self.recorder is not None:
                        self.recorder.write(reader.topic.name, sample)
                    try:
                        handler(sample)
                    except Exception as exc:  # noqa: BLE001 - a bad message must not stop the link
                        self._once(reader.topic.name, "could not use a message from %s: %s", exc)

    def _once(self, key: str, message: str, exc: BaseException) -> None:
        """Log a reading problem once per topic (a broken sender repeats itself)."""
        if key not in self._warned:
            self._warned.add(key)
            log.warning(message, key, exc)

    def _on_scan(self, s: m.LaserScan) -> None:
        self._body.on_scan(
            ScanReading(s.angle_min, s.angle_increment, s.range_min, s.range_max, list(s.ranges)),
            m.seconds_of(s.header.stamp),
        )

    def _on_dets(self, a: m.Detection2DArray) -> None:
        self._body.on_boxes(boxes_of(a), m.seconds_of(a.header.stamp))

    def _on_amcl(self, msg: m.PoseWithCovarianceStamped) -> None:
        self._on_pose(msg.pose.pose)

    def _on_odom(self, msg: m.Odometry) -> None:
        self._on_pose(msg.pose.pose)

    def _on_pose(self, pose: m.Pose) -> None:
        q = pose.orientation
        self._body.on_pose(
            PoseReading(pose.position.x, pose.position.y, yaw_of(q.x, q.y, q.z, q.w))
        )

    def _on_gripper(self, msg: m.String) -> None:
        self._body.on_gripper(msg.data)

    def _on_text(self, msg: m.String) -> None:
        self._body.on_text(msg.data)

    def _on_mission(self, msg: m.String) -> None:
        self._body.on_mission(msg.data)


def boxes_of(a: m.Detection2DArray) -> list[BoxReading]:
    """Each detection's best hypothesis as a box (a detection without one is skipped):
    what the bridge reads from a live Detection2DArray and from a recorded one."""
    boxes = []
    for d in a.detections:
        if not d.results:
            continue
        best = max(d.results, key=lambda r: r.hypothesis.score)
        p = best.pose.pose.position
        boxes.append(
            BoxReading(
                best.hypothesis.class_id,
                best.hypothesis.score,
                d.bbox.center.position.x,
                (p.x, p.y, p.z),
                d.id or None,
            )
        )
    return boxes
