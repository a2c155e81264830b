"""A stand-in ROS 2 robot: publishes what a robot senses, records what it is told.

It plays the robot's side of the bridge with the same wire types a real robot uses: a
laser scan with one obstacle, a detection array, the amcl pose and the gripper state go
out; velocity and gripper requests come in, and navigation goals through a Nav2
``navigate_to_pose`` action server that reaches each goal after ``goal_seconds``
(``{"goal_seconds": 30}`` stalls it) unless it is cancelled first. A pick makes the
gripper report the picked object, as a real gripper driver would. It serves to try the
bridge without a robot, in tests and in the latency benchmark.

Run as a process (``python -m robocog.testing.ros2_standin --domain N``) it reads scene
changes as JSON lines on stdin and writes every request it receives as a JSON line on
stdout, for example ``{"event": "cmd_vel", "linear": 0.0, "angular": -0.6}``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader, InvalidSample
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from robocog.bridges.config import Topics
from robocog.bridges.perception import quaternion_of, yaw_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.actions import ActionServer, ServerGoal
from robocog.bridges.ros2.link import RELIABLE, SENSOR


@dataclass
class Scene:
    """What the stand-in robot senses: one obstacle, boxes seen, its pose, its gripper."""

    #: (bearing rad, distance m) of one obstacle, or None for a clear scan
    obstacle: tuple[float, float] | None = None
    #: (label, box centre column px, score)
    detections: list[tuple[str, float, float]] = field(default_factory=list)
    pose: tuple[float, float, float] = (0.0, 0.0, 0.0)
    holding: str = ""
    #: when False the robot publishes nothing (a dead driver, a lost link)
    alive: bool = True
    #: how long a navigation goal takes to succeed (s)
    goal_seconds: float = 0.5

    def update(self, data: dict[str, Any]) -> None:
        """Apply a JSON scene change."""
        if "obstacle" in data:
            ob = data["obstacle"]
            self.obstacle = None if ob is None else (float(ob[0]), float(ob[1]))
        if "detections" in data:
            self.detections = [
                (str(d["label"]), float(d.get("x", 320.0)), float(d.get("score", 0.9)))
                for d in data["detections"]
            ]
        if "pose" in data:
            x, y, theta = (float(v) for v in data["pose"])
            self.pose = (x, y, theta)
        if "holding" in data:
            self.holding = str(data["holding"] or "")
        if "alive" in data:
            self.alive = bool(data["alive"])
        if "goal_seconds" in data:
            self.goal_seconds = float(data["goal_seconds"])


def scan_of(obstacle: tuple[float, float] | None, beams: int = 181) -> m.LaserScan:
    """A half-circle scan (-90..+90 degrees) that is clear (inf) except one obstacle."""
    inc = math.pi / (beams - 1)
    ranges = [math.inf] * beams
    if obstacle is not None:
        bearing, distance = obstacle
        centre = round((bearing + math.pi / 2) / inc)
        for i in range(max(0, centre - 2), min(beams, centre + 3)):
            ranges[i] = distance
    return m.LaserScan(
        m.Header(m.stamp_now(time.time()), "base_scan"),
        angle_min=-math.pi / 2,
        angle_max=math.pi / 2,
        angle_increment=inc,
        range_min=0.05,
        range_max=10.0,
        ranges=ranges,
    )


class StandInRobot:
    """The robot's side of the ROS 2 topics, on its own participant."""

    def __init__(
        self,
        domain_id: int,
        topics: Topics | None = None,
        on_event: Callable[[dict[str, Any]], None] | None = None,
        navigate_action: str | None = None,
    ) -> None:
        self.topics = tp = topics or Topics()
        self.scene = Scene()
        self.events: list[dict[str, Any]] = []
        self.on_event = on_event
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self.dp = dp = DomainParticipant(domain_id)

        def topic(name: str, kind: type, prefix: str = "rt", suffix: str = "") -> Topic:
            return Topic(dp, m.topic_name(name, prefix) + suffix, kind, qos=RELIABLE)

        self.scan_writer = DataWriter(dp, topic(tp.scan, m.LaserScan), qos=SENSOR)
        self.det_writer = DataWriter(dp, topic(tp.detections, m.Detection2DArray), qos=RELIABLE)
        self.pose_writer = DataWriter(
            dp, topic(tp.amcl_pose, m.PoseWithCovarianceStamped), qos=RELIABLE
        )
        self.gripper_writer = DataWriter(dp, topic(tp.gripper_state, m.String), qos=RELIABLE)
        self.narsese_writer = DataWriter(dp, topic(tp.narsese, m.String), qos=RELIABLE)
        self.mission_writer = DataWriter(dp, topic(tp.mission, m.String), qos=RELIABLE)
        self.navigate = ActionServer(
            dp,
            navigate_action or tp.navigate_action,
            m.NAVIGATE_TO_POSE,
            m.NavigateToPoseResult,
            RELIABLE,
            self._goal,
            on_cancel=self._cancel,
        )
        self._readers: list[tuple[DataReader, Callable[[Any], None]]] = [
            (DataReader(dp, topic(tp.cmd_vel, m.Twist), qos=RELIABLE), self._twist),
            (DataReader(dp, topic(tp.gripper_command, m.String), qos=RELIABLE), self._grip),
            *self.navigate.handlers,
        ]
        self._threads = [
            threading.Thread(target=self._listen, daemon=True, name="standin-listen"),
        ]

    # -- running -------------------------------------------------------------------

    def start(self, rate: float | None = 20.0) -> StandInRobot:
        """Start listening, and publishing the scene ``rate`` times a second (never when
        ``rate`` is None: the caller then publishes by itself)."""
        if rate:
            publisher = threading.Thread(
                target=self._publish_loop, args=(rate,), daemon=True, name="standin-publish"
            )
            self._threads.append(publisher)
        for thread in self._threads:
            thread.start()
        return self

    def close(self) -> None:
        """Stop both threads."""
        self._stop.set()
        for thread in self._threads:
            if thread.is_alive():
                thread.join(timeout=2.0)

    def publish_once(self) -> None:
        """Publish the current scene once (scan, detections, pose, gripper)."""
        with self._lock:
            scene = Scene(
                self.scene.obstacle,
                list(self.scene.detections),
                self.scene.pose,
                self.scene.holding,
                self.scene.alive,
            )
        if not scene.alive:
            return
        now = m.stamp_now(time.time())
        self.scan_writer.write(scan_of(scene.obstacle))
        dets = []
        for label, column, score in scene.detections:
            hypothesis = m.ObjectHypothesisWithPose(m.ObjectHypothesis(label, score))
            box = m.BoundingBox2D(m.Pose2D(m.Point2D(column, 240.0)), 40.0, 80.0)
            dets.append(m.Detection2D(m.Header(now, "camera"), [hypothesis], box, ""))
        self.det_writer.write(m.Detection2DArray(m.Header(now, "camera"), dets))
        x, y, theta = scene.pose
        qx, qy, qz, qw = quaternion_of(theta)
        pose = m.Pose(m.Point(x, y, 0.0), m.Quaternion(qx, qy, qz, qw))
        self.pose_writer.write(
            m.PoseWithCovarianceStamped(m.Header(now, "map"), m.PoseWithCovariance(pose))
        )
        self.gripper_writer.write(m.String(scene.holding))

    def update(self, data: dict[str, Any]) -> None:
        """Change the scene (see ``Scene.update``); ``narsese`` sends text to the mind,
        ``mission`` the robot's mission state."""
        with self._lock:
            self.scene.update(data)
        if "narsese" in data:
            self.narsese_writer.write(m.String(str(data["narsese"])))
        if "mission" in data:  # the robot's mission state, e.g. "ended: test over"
            self.mission_writer.write(m.String(str(data["mission"])))

    def _publish_loop(self, rate: float) -> None:
        while not self._stop.wait(1.0 / rate):
            self.publish_once()

    def _listen(self) -> None:
        waitset = WaitSet(self.dp)
        mask = SampleState.NotRead | ViewState.Any | InstanceState.Any
        for reader, _handler in self._readers:
            waitset.attach(ReadCondition(reader, mask))
        while not self._stop.is_set():
            waitset.wait(duration(milliseconds=50))
            for reader, handler in self._readers:
                for sample in reader.take(32):
                    if not isinstance(sample, InvalidSample):
                        handler(sample)

    # -- what the robot is told ----------------------------------------------------

    def _record(self, event: dict[str, Any]) -> None:
        event["t"] = time.time()
        with self._lock:
            self.events.append(event)
        if self.on_event is not None:
            self.on_event(event)

    def _twist(self, msg: m.Twist) -> None:
        self._record({"event": "cmd_vel", "linear": msg.linear.x, "angular": msg.angular.z})

    def _goal(self, goal: ServerGoal, server: ActionServer) -> None:
        """A NavigateToPose goal: recorded, then reached after ``goal_seconds``."""
        msg = goal.goal.pose
        q = msg.pose.orientation
        self._record(
            {
                "event": "goal",
                "frame": msg.header.frame_id,
                "x": msg.pose.position.x,
                "y": msg.pose.position.y,
                "yaw": yaw_of(q.x, q.y, q.z, q.w),
            }
        )
        end = time.monotonic() + self.scene.goal_seconds
        while not goal.cancel_requested and not self._stop.is_set():
            left = end - time.monotonic()
            if left <= 0:
                server.finish(goal, m.STATUS_SUCCEEDED, m.NavigateToPoseResult())
                return
            server.feedback(goal, m.NavigateToPoseFeedback(distance_remaining=left))
            self._stop.wait(min(left, 0.05))
        server.finish(goal, m.STATUS_CANCELED, m.NavigateToPoseResult())

    def _cancel(self, goal_id: bytes) -> None:
        self._record({"event": "cancel", "all": not any(goal_id)})

    def _grip(self, msg: m.String) -> None:
        self._record({"event": "gripper", "text": msg.data})
        words = msg.data.split()
        with self._lock:
            if words[:1] == ["pick"] and len(words) > 1:
                self.scene.holding = words[1]
            elif words[:1] == ["drop"]:
                self.scene.holding = ""


def main(argv: list[str] | None = None) -> int:
    """Run the stand-in robot as a process: scene JSON on stdin, events JSON on stdout."""
    parser = argparse.ArgumentParser(description="a stand-in ROS 2 robot on Cyclone DDS")
    parser.add_argument("--domain", type=int, default=0)
    parser.add_argument("--rate", type=float, default=20.0)
    parser.add_argument("--scene", default="{}", help="initial scene as JSON")
    args = parser.parse_args(argv)
    out_lock = threading.Lock()

    def emit(event: dict[str, Any]) -> None:
        with out_lock:
            sys.stdout.write(json.dumps(event) + "\n")
            sys.stdout.flush()

    robot = StandInRobot(args.domain, on_event=emit)
    robot.update(json.loads(args.scene))
    robot.start(args.rate)
    emit({"event": "ready"})
    try:
        for line in sys.stdin:
            line = line.strip()
            if not line:
                continue
            try:
                robot.update(json.loads(line))
            except (ValueError, KeyError, TypeError) as exc:
                emit({"event": "error", "text": str(exc)})
    finally:
        robot.close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
