"""The garbage field as a ROS 2 robot on Cyclone DDS.

What a mobile manipulator running Nav2 offers, with the field's own numbers:
``/scan`` (sensor_msgs/LaserScan, best effort: 360 beams cast against the fence from
the robot's pose), ``/detections`` (vision_msgs/Detection2DArray: the field's camera
frame, each box's centre column from its bearing by a pinhole camera of the field's
field of view, its hypothesis position the object's offset from the robot),
``/odom`` (nav_msgs/Odometry, every frame), ``/amcl_pose``
(geometry_msgs/PoseWithCovarianceStamped, when the field's localisation reports,
once a simulated second), ``/tf`` (map -> odom -> base_link), ``/joint_states``
(sensor_msgs/JointState of the gripper), ``/gripper/state`` (std_msgs/String: what it
holds), ``/clock`` (rosgraph_msgs/Clock, simulated time). It takes ``/cmd_vel``
(geometry_msgs/Twist), serves ``navigate_to_pose`` (nav2_msgs/action/NavigateToPose:
a goal at a checkpoint is the field's GoTo of that checkpoint, at the start corner the
end of the route, elsewhere a drive there) and ``/gripper/grasp``
(robocog_msgs/action/Grasp, ``interfaces/Grasp.action`` beside the bridge).

The field moves in steps: a goal's drive happens at once in simulated time, and the
action then plays its duration back at ``rate`` times real time with feedback
(``distance_remaining``) before it answers. In lock-step mode (``lockstep``) the sim
publishes a frame and waits until the controller acknowledges it on
``/sim/frame_done`` (builtin_interfaces/Time, the frame's stamp), as a simulator in
synchronous mode waits for its controller; goals then answer at once. A frame not
acknowledged has its scan sent again (the same message) so that a lost scan or a slow
controller never stalls the mission, and the controller's watchdog stays fed.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from robocog.bridges.config import Topics
from robocog.bridges.perception import quaternion_of
from robocog.bridges.ros2 import messages as m
from robocog.bridges.ros2.actions import ActionServer, ServerGoal
from robocog.bridges.ros2.link import RELIABLE, SENSOR, serve_readers, typed
from robocog.robot.commands import Drop, Forward, GoTo, Outcome, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Percept, Pose
from robocog.sim.field import (
    BEAMS,
    IMAGE_HEIGHT,
    RANGE_MAX,
    column_of,
    fence_ranges,
    target_place,
)
from robocog.worlds.garbage import GarbageField

log = logging.getLogger("robocog.sim")

#: a frame not acknowledged is sent again after this many seconds (lock-step)
RESEND = 0.2
#: a Twist moves the base for this long (s) in lock-step (a controller's command period)
TWIST_PERIOD = 0.1
GRIPPER_JOINT = "gripper_finger_joint"
GRIPPER_OPEN = 0.08  # m between the fingers


@dataclass
class Frame:
    """The messages of one frame, kept to be sent again unchanged."""

    seconds: float
    messages: list[tuple[DataWriter, Any]]


class GarbageRobot:
    """A ``GarbageField`` behind ROS 2 topics and actions on its own participant."""

    def __init__(
        self,
        world: GarbageField,
        domain_id: int,
        *,
        rate: float = 1.0,
        lockstep: bool = False,
        namespace: str = "",
        max_frames: int | None = None,
        stall: bool = False,
        on_message: Callable[[str, str, Any], None] | None = None,
    ) -> None:
        self.world = world
        self.rate = rate
        self.lockstep = lockstep
        self.max_frames = max_frames
        #: a stalled base accepts goals and never gets there (until cancelled)
        self.stall = stall
        self.on_message = on_message
        self.frames = 0
        self.goals = 0
        self.lock = threading.RLock()  # the world is not thread-safe
        self._stop = threading.Event()
        self._acked = threading.Condition()
        self._ack = -math.inf
        self._twist = (0.0, 0.0, -math.inf)
        self._busy = 0  # goals playing back their duration (real time)
        self.dp = dp = DomainParticipant(domain_id)
        ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
        tp = Topics()

        def name(ros: str) -> str:
            return ns + ros

        def writer(ros: str, kind: type, qos: Any = RELIABLE) -> DataWriter:
            topic = Topic(dp, m.topic_name(name(ros)), kind, qos=RELIABLE)
            return DataWriter(dp, topic, qos=typed(qos, kind))

        def reader(ros: str, kind: type) -> DataReader:
            topic = Topic(dp, m.topic_name(name(ros)), kind, qos=RELIABLE)
            return DataReader(dp, topic, qos=typed(RELIABLE, kind))

        self.w_scan = writer(tp.scan, m.LaserScan, SENSOR)
        self.w_dets = writer(tp.detections, m.Detection2DArray)
        self.w_odom = writer(tp.odom, m.Odometry)
        self.w_amcl = writer(tp.amcl_pose, m.PoseWithCovarianceStamped)
        self.w_tf = writer("/tf", m.TFMessage)
        self.w_joints = writer("/joint_states", m.JointState)
        self.w_gripper = writer(tp.gripper_state, m.String)
        self.w_clock = writer("/clock", m.Clock, SENSOR)
        self.w_mission = writer(tp.mission, m.String)
        #: why the mission ended (None while it runs, or when the sim was stopped)
        self.ended: str | None = None
        self.navigate = ActionServer(
            dp,
            name(tp.navigate_action),
            m.NAVIGATE_TO_POSE,
            m.NavigateToPoseResult,
            RELIABLE,
            self._navigate,
        )
        self.grasp = ActionServer(
            dp, name(tp.grasp_action), m.GRASP, m.GraspResult, RELIABLE, self._grasp
        )
        self._readers: list[tuple[DataReader, Callable[[Any], None]]] = [
            (reader(tp.cmd_vel, m.Twist), self._on_twist),
            (reader(tp.frame_done, m.Time), self._on_ack),
            *self.navigate.handlers,
            *self.grasp.handlers,
        ]
        self._listener = threading.Thread(target=self._listen, daemon=True, name="sim-listen")

    # -- running -------------------------------------------------------------------

    def run(self, until: Callable[[], bool] | None = None) -> None:
        """Publish frames until the mission ends (route done, battery spent, ``max_frames``),
        ``until()`` holds or ``stop()`` is called."""
        if not self._listener.is_alive():
            self._listener.start()
        c = self.world.config
        # the mission's clock starts when a controller listens to the scan: a mind that
        # takes a while to start does not find its battery half spent
        waited = False
        while not self._stop.is_set() and not self.w_scan.get_matched_subscriptions():
            if not waited:
                log.info("waiting for a controller to subscribe to the scan")
                waited = True
            if until is not None and until():
                return
            self._stop.wait(0.05)
        while not self._stop.is_set():
            if until is not None and until():
                break
            if self.world.done or (self.max_frames is not None and self.frames >= self.max_frames):
                self._end_mission()
                break
            with self.lock:  # sent under the lock: a result sent after it is seen after it
                if self._busy:
                    # a goal plays back a move that already happened: the clock has
                    # moved on, so no camera frame is taken, only the base reports
                    held = self.world.holding
                    frame = self._frame([Gripper(held.instance if held else None)])
                else:
                    self._drive()
                    frame = self._frame(self.world.percepts())
                    self.frames += 1
                self._send(frame)
            if self.lockstep:
                self._wait_for_ack(frame)
            else:
                self._stop.wait(c.frame_seconds / self.rate)

    def _end_mission(self) -> None:
        """Tell the controller the mission is over (``ended: WHY`` on the mission topic),
        so that a bridge ends with it instead of waiting for frames that never come."""
        w = self.world
        if w.route_complete:
            why = "route complete"
        elif w.out_of_time:
            why = "battery spent"
        else:
            why = f"{self.frames} frames (--max-frames)"
        self.ended = f"{why}; collected {w.collected()} of {len(w.objects())} objects"
        with self.lock:
            self.w_mission.write(m.String(f"ended: {self.ended}"))
        try:  # reliable: the controller has it before the participant goes
            self.w_mission.wait_for_acks(duration(seconds=2))
        except Exception:  # noqa: BLE001 - no controller left to tell: nothing to wait for
            log.debug("the mission's end was not acknowledged")

    def stop(self) -> None:
        """End ``run`` and the listener."""
        self._stop.set()
        with self._acked:
            self._acked.notify_all()

    def close(self) -> None:
        """Stop, and let the participant go."""
        self.stop()
        if self._listener.is_alive():
            self._listener.join(timeout=2.0)

    def _wait_for_ack(self, frame: Frame) -> None:
        while not self._stop.is_set():
            with self._acked:
                if self._acked.wait_for(
                    lambda: self._ack >= frame.seconds - 1e-6 or self._stop.is_set(), RESEND
                ):
                    return
            # the scan again, unchanged: it may have been lost (best effort), and it keeps
            # a slow controller's watchdog fed; the reliable rest of the frame arrived, and
            # sent again after the controller acted it would tell of a world gone by
            self._send(Frame(frame.seconds, frame.messages[-1:]))

    # -- frames --------------------------------------------------------------------

    def _frame(self, percepts: list[Percept]) -> Frame:
        w = self.world
        c = w.config
        t = w.time()
        now = m.stamp_now(t)
        messages: list[tuple[DataWriter, Any]] = [(self.w_clock, m.Clock(now))]
        qx, qy, qz, qw = quaternion_of(w.theta)
        pose = m.Pose(m.Point(w.x, w.y, 0.0), m.Quaternion(qx, qy, qz, qw))
        identity = m.Transform()
        base = m.Transform(m.Vector3(w.x, w.y, 0.0), m.Quaternion(qx, qy, qz, qw))
        messages.append(
            (
                self.w_tf,
                m.TFMessage(
                    [
                        m.TransformStamped(m.Header(now, "map"), "odom", identity),
                        m.TransformStamped(m.Header(now, "odom"), "base_link", base),
                    ]
                ),
            )
        )
        v, omega, _at = self._twist
        twist = m.TwistWithCovariance(m.Twist(m.Vector3(x=v), m.Vector3(z=omega)))
        messages.append(
            (
                self.w_odom,
                m.Odometry(m.Header(now, "odom"), "base_link", m.PoseWithCovariance(pose), twist),
            )
        )
        holding = ""
        boxes: list[m.Detection2D] = []
        for p in percepts:
            if isinstance(p, Pose):
                messages.append(
                    (
                        self.w_amcl,
                        m.PoseWithCovarianceStamped(
                            m.Header(now, "map"), m.PoseWithCovariance(pose)
                        ),
                    )
                )
            elif isinstance(p, Gripper):
                holding = p.holding or ""
            elif isinstance(p, Detection):
                boxes.append(self._box(p, now, c.camera_fov))
        opening = 0.0 if holding else GRIPPER_OPEN
        messages.append(
            (
                self.w_joints,
                m.JointState(
                    m.Header(now, "base_link"),
                    [GRIPPER_JOINT],
                    [opening],
                    [0.0],
                    [10.0 if holding else 0.0],
                ),
            )
        )
        messages.append((self.w_gripper, m.String(holding)))
        messages.append((self.w_dets, m.Detection2DArray(m.Header(now, "camera"), boxes)))
        ranges = fence_ranges(w.x, w.y, w.theta, c.size)
        scan = m.LaserScan(
            m.Header(now, "base_scan"),
            angle_min=-math.pi,
            angle_max=math.pi - 2 * math.pi / BEAMS,
            angle_increment=2 * math.pi / BEAMS,
            scan_time=c.frame_seconds,
            range_min=0.05,
            range_max=RANGE_MAX,
            ranges=ranges,
        )
        messages.append((self.w_scan, scan))  # last: it closes the frame
        return Frame(t, messages)

    @staticmethod
    def _box(d: Detection, now: m.Time, fov: float) -> m.Detection2D:
        position = m.Point(d.distance * math.cos(d.bearing), d.distance * math.sin(d.bearing), 0.0)
        hypothesis = m.ObjectHypothesisWithPose(
            m.ObjectHypothesis(d.label, d.confidence),
            m.PoseWithCovariance(m.Pose(position)),
        )
        column = column_of(d.bearing, fov)
        box = m.BoundingBox2D(m.Pose2D(m.Point2D(column, IMAGE_HEIGHT / 2)), 40.0, 80.0)
        return m.Detection2D(m.Header(now, "camera"), [hypothesis], box, d.instance or "")

    def _send(self, frame: Frame) -> None:
        for writer, message in frame.messages:
            # recorded before it is sent: the controller's answer to it, recorded by the
            # action server's thread, must come after it in the recording
            if self.on_message is not None:
                self.on_message(writer.topic.name, type(message).__name__, message)
            writer.write(message)

    # -- commands --------------------------------------------------------------------

    def _listen(self) -> None:
        serve_readers(self.dp, self._readers, self._stop, log, guard=True)

    def _on_ack(self, stamp: m.Time) -> None:
        with self._acked:
            self._ack = max(self._ack, m.seconds_of(stamp))
            self._acked.notify_all()

    def _on_twist(self, msg: m.Twist) -> None:
        v, omega = msg.linear.x, msg.angular.z
        if not (math.isfinite(v) and math.isfinite(omega)):
            return
        self._twist = (v, omega, time.monotonic())
        if self.lockstep and (v or omega):
            with self.lock:
                self._apply_twist(v, omega, TWIST_PERIOD)

    def _drive(self) -> None:
        """Real time: the last Twist, if fresh (0.5 s, as a base controller's time-out),
        moves the base for one frame."""
        v, omega, at = self._twist
        if self.lockstep or time.monotonic() - at > 0.5 or not (v or omega):
            return
        self._apply_twist(v, omega, self.world.config.frame_seconds)

    def _apply_twist(self, v: float, omega: float, seconds: float) -> None:
        if omega:
            self.world.execute(Turn(omega * seconds))
        if v:
            self.world.execute(Forward(v * seconds))

    def _navigate(self, goal: ServerGoal, server: ActionServer) -> None:
        self.goals += 1
        self._heard(server, "send_goal", goal)
        p = goal.goal.pose.pose
        x, y = p.position.x, p.position.y
        q = p.orientation
        yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
        if not all(math.isfinite(v) for v in (x, y, yaw)):
            server.finish(goal, m.STATUS_ABORTED, m.NavigateToPoseResult(1, "not a finite pose"))
            return
        if self.stall:
            while not goal.cancel_requested and not self._stop.wait(0.05):
                server.feedback(goal, m.NavigateToPoseFeedback(distance_remaining=1.0))
            server.finish(goal, m.STATUS_CANCELED, m.NavigateToPoseResult())
            return
        with self.lock:
            w = self.world
            x0, y0, began = w.x, w.y, w.time()
            place = target_place(w, x, y)
            if place is not None:
                outcome = w.execute(GoTo(place))
            else:
                outcome = w.drive_to(x, y, yaw)
            took = w.time() - began
            distance = math.hypot(w.x - x0, w.y - y0)
        if not self.lockstep:
            self._busy_while(lambda: self._feed_back(goal, server, took, distance))

        def finish() -> None:
            if goal.cancel_requested:
                server.finish(goal, m.STATUS_CANCELED, m.NavigateToPoseResult())
            elif outcome.ok:
                server.finish(goal, m.STATUS_SUCCEEDED, m.NavigateToPoseResult())
            else:
                server.finish(goal, m.STATUS_ABORTED, m.NavigateToPoseResult(1, outcome.reason))

        with self.lock:  # no frame of the playback can be sent after the result
            self._busy -= 0 if self.lockstep else 1
            finish()

    def _busy_while(self, wait: Callable[[], None]) -> None:
        """Mark a playback under way (its frames take no camera image) while ``wait``
        runs; the caller ends it, under the lock, with the result."""
        with self.lock:
            self._busy += 1
        wait()

    def _feed_back(self, goal: ServerGoal, server: ActionServer, took: float, dist: float) -> None:
        """Let the move's simulated duration pass at ``rate``, with feedback."""
        wall = took / self.rate
        end = time.monotonic() + wall
        while not goal.cancel_requested and not self._stop.is_set():
            left = end - time.monotonic()
            if left <= 0:
                break
            share = left / wall if wall > 0 else 0.0
            remaining = share * took
            server.feedback(
                goal,
                m.NavigateToPoseFeedback(
                    navigation_time=_duration(took - remaining),
                    estimated_time_remaining=_duration(remaining),
                    distance_remaining=share * dist,
                ),
            )
            self._stop.wait(min(left, 0.1))

    def _heard(self, server: ActionServer, service: str, goal: ServerGoal) -> None:
        """Tell ``on_message`` of a goal received (recorded as the action's goal)."""
        if self.on_message is not None:
            topic = "rq" + m.topic_name(server.action + f"/_action/{service}", "") + "Request"
            self.on_message(topic, "goal", _GoalRequest(goal.goal))

    def _grasp(self, goal: ServerGoal, server: ActionServer) -> None:
        self._heard(server, "send_goal", goal)
        command, target = goal.goal.command.strip(), goal.goal.target.strip()
        with self.lock:
            began = self.world.time()
            if command == "pick":
                outcome = self.world.execute(Pick(target or "trash"))
            elif command == "drop":
                outcome = self.world.execute(Drop())
            else:
                outcome = Outcome.failure(f"unknown gripper command {command!r}")
            took = self.world.time() - began
            holding = self.world.holding.instance if self.world.holding else ""
        if not self.lockstep:
            self._busy_while(lambda: self._stop.wait(took / self.rate))
        with self.lock:
            self._busy -= 0 if self.lockstep else 1
            server.finish(
                goal, m.STATUS_SUCCEEDED, m.GraspResult(outcome.ok, outcome.reason, holding)
            )


@dataclass
class _GoalRequest:
    """A received goal in the shape of a send_goal request (its ``goal`` part)."""

    goal: Any


def _duration(seconds: float) -> m.Duration:
    seconds = max(0.0, seconds)
    whole = int(seconds)
    return m.Duration(whole, int((seconds - whole) * 1e9))
