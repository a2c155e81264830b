"""The ROS 2 side of a bridge: Cyclone DDS readers and writers on the ROS 2 topics.

One thread waits on all readers at once and hands every sample, turned into a plain
reading, to the ``RobotBody``. Writers publish velocity, goals, cancels and gripper
requests. The QoS follows ROS 2's: reliable and volatile by default, best effort for the
laser scan (sensor data), plain CDR (XCDR1) as rmw_cyclonedds writes it.
"""

from __future__ import annotations

import itertools
import logging
import os
import random
import threading
import time
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
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import BoxReading, PoseReading, ScanReading, quaternion_of, yaw_of
from robocog.bridges.ros2 import messages as m

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


class Ros2Link:
    """A ``Link`` speaking ROS 2 over Cyclone DDS on one domain."""

    def __init__(self, config: BridgeConfig, domain_id: int | None = None) -> None:
        self.config = config
        if domain_id is None:
            domain_id = int(os.environ.get("ROS_DOMAIN_ID", "0"))
        self.domain_id = domain_id
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._tokens = itertools.count(1)
        self._guid = random.getrandbits(63)
        self._seq = itertools.count(1)
        self._dp: DomainParticipant | None = None

    def start(self, body: RobotBody) -> None:
        """Create the participant, readers and writers, and start the reading thread."""
        tp = self.config.topics
        dp = self._dp = DomainParticipant(self.domain_id)

        def topic(name: str, kind: type, prefix: str = "rt", suffix: str = "") -> Topic:
            return Topic(dp, m.topic_name(name, prefix) + suffix, kind, qos=RELIABLE)

        self._cmd_vel = DataWriter(dp, topic(tp.cmd_vel, m.Twist), qos=RELIABLE)
        self._goal = DataWriter(dp, topic(tp.goal_pose, m.PoseStamped), qos=RELIABLE)
        self._gripper = DataWriter(dp, topic(tp.gripper_command, m.String), qos=RELIABLE)
        cancel_name = tp.navigate_action.rstrip("/") + "/_action/cancel_goal"
        self._cancel = DataWriter(
            dp, topic(cancel_name, m.CancelGoalRequest, "rq", "Request"), qos=RELIABLE
        )
        readers: list[tuple[DataReader, Any]] = [
            (DataReader(dp, topic(tp.scan, m.LaserScan), qos=SENSOR), self._on_scan),
            (DataReader(dp, topic(tp.detections, m.Detection2DArray), qos=RELIABLE), self._on_dets),
            (DataReader(dp, topic(tp.gripper_state, m.String), qos=RELIABLE), self._on_gripper),
            (DataReader(dp, topic(tp.narsese, m.String), qos=RELIABLE), self._on_text),
        ]
        if self.config.pose_source == "odom":
            readers.append(
                (DataReader(dp, topic(tp.odom, m.Odometry), qos=RELIABLE), self._on_odom)
            )
        elif self.config.pose_source == "amcl":
            pose_qos = RELIABLE  # amcl publishes transient-local; volatile readers match it
            kind = m.PoseWithCovarianceStamped
            readers.append((DataReader(dp, topic(tp.amcl_pose, kind), qos=pose_qos), self._on_amcl))
        else:
            raise ValueError(
                f"pose_source must be 'amcl' or 'odom', not {self.config.pose_source!r}"
            )
        self._body = body
        self._stop.clear()
        self._thread = threading.Thread(
            target=self._read, args=(dp, readers), name="ros2-link", daemon=True
        )
        self._thread.start()

    def close(self) -> None:
        """Stop the reading thread and drop the participant (and all its entities)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
            self._thread = None
        self._dp = None

    # -- requests ------------------------------------------------------------------

    def send_velocity(self, linear: float, angular: float) -> None:
        """Publish a Twist on ``cmd_vel``."""
        self._cmd_vel.write(m.Twist(m.Vector3(x=linear), m.Vector3(z=angular)))

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        """Publish a PoseStamped on ``goal_pose`` in the map frame, as Nav2 takes it."""
        qx, qy, qz, qw = quaternion_of(yaw)
        header = m.Header(m.stamp_now(time.time()), self.config.map_frame)
        pose = m.Pose(m.Point(x, y, 0.0), m.Quaternion(qx, qy, qz, qw))
        self._goal.write(m.PoseStamped(header, pose))
        return next(self._tokens)

    def cancel_goals(self) -> None:
        """Ask the navigation action server to cancel every goal (zero id, zero stamp)."""
        self._cancel.write(m.CancelGoalRequest(self._guid, next(self._seq)))

    def send_gripper(self, text: str) -> None:
        """Publish a gripper request as a std_msgs/String."""
        self._gripper.write(m.String(text))

    # -- readings ------------------------------------------------------------------

    def _read(self, dp: DomainParticipant, readers: list[tuple[DataReader, Any]]) -> None:
        waitset = WaitSet(dp)
        mask = SampleState.NotRead | ViewState.Any | InstanceState.Any
        for reader, _handler in readers:
            waitset.attach(ReadCondition(reader, mask))
        while not self._stop.is_set():
            waitset.wait(duration(milliseconds=50))
            for reader, handler in readers:
                for sample in reader.take(32):
                    try:
                        handler(sample)
                    except Exception:  # noqa: BLE001 - a bad message must not stop the link
                        log.exception("could not use a message from %s", reader.topic.name)

    def _on_scan(self, s: m.LaserScan) -> None:
        self._body.on_scan(
            ScanReading(s.angle_min, s.angle_increment, s.range_min, s.range_max, list(s.ranges))
        )

    def _on_dets(self, a: m.Detection2DArray) -> None:
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
        self._body.on_boxes(boxes)

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
