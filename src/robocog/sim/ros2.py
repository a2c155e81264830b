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

The world is driven from one thread, the one that runs :meth:`GarbageRobot.run`: a goal,
a grasp or a Twist is handed to it as a job, done between frames (a physical field's
camera renders in a GL context that belongs to that thread).
:class:`~robocog.sim.field_mujoco.MujocoGarbageRobot` serves the physical field with the
same topics and actions, its camera images and its ray-cast lidar besides.

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
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
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
class _Job:
    """Work on the world, handed to the thread that runs the world."""

    work: Callable[[], Any]
    done: threading.Event = field(default_factory=threading.Event)
    result: Any = None
    error: BaseException | None = None


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
        self._jobs: deque[_Job] = deque()
        self._ended = threading.Event()  # run() is over: no job will be done any more
        self._sending = threading.Lock()  # a frame, or a scan sent again, goes out whole
        self._last: Frame | None = None
        self.dp = dp = DomainParticipant(domain_id)
        self._ns = ns = "/" + namespace.strip("/") if namespace.strip("/") else ""
        tp = Topics()

        def name(ros: str) -> str:
            return ns + ros

        writer = self._writer

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

    def _writer(self, ros: str, kind: type, qos: Any = RELIABLE) -> DataWriter:
        """A writer of ``kind`` on the ROS topic ``ros`` (under the namespace)."""
        topic = Topic(self.dp, m.topic_name(self._ns + ros), kind, qos=RELIABLE)
        return DataWriter(self.dp, topic, qos=typed(qos, kind))

    # -- running -------------------------------------------------------------------

    def run(self, until: Callable[[], bool] | None = None) -> None:
        """Publish frames until the mission ends (route done, battery spent, ``max_frames``),
        ``until()`` holds or ``stop()`` is called."""
        if not self._listener.is_alive():
            self._listener.start()
        # the mission's clock starts when a controller listens to the scan: a mind that
        # takes a while to start does not find its battery half spent
        waited = False
        while not self._stop.is_set() and not self.w_scan.get_matched_subscriptions():
            if not waited:
                log.info("waiting for a controller to subscribe to the scan")
                waited = True
            if until is not None and until():
                self._ended.set()
                return
            self._pause(0.05)
        try:
            self._frames(until)
        finally:
            self._ended.set()
            self._run_jobs()  # those handed over meanwhile end, refused (see _in_world)

    def _frames(self, until: Callable[[], bool] | None) -> None:
        c = self.world.config
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
                    frame = self._frame([Gripper(self.world.in_gripper())], camera=False)
                else:
                    self._drive()
                    frame = self._frame(self.world.percepts())
                    self.frames += 1
                self._publish(frame)
            if self.lockstep:
                self._wait_for_ack(frame)
            else:
                self._pause(c.frame_seconds / self.rate)

    # -- the world's thread ------------------------------------------------------------

    def _in_world(self, work: Callable[[], Any]) -> Any:
        """Run ``work`` on the thread that runs the world, under the lock, and return
        what it returns; None when the sim stops (or its mission ends) first."""
        job = _Job(work)
        with self._acked:
            self._jobs.append(job)
            self._acked.notify_all()
        beat = time.monotonic() + RESEND
        while not job.done.wait(0.05):
            if self._stop.is_set() or self._ended.is_set():
                with self._acked:
                    if job in self._jobs:
                        self._jobs.remove(job)
                        return None
            if time.monotonic() >= beat:
                # the world is busy (a physical drive or grasp takes a while): the last
                # scan again keeps the controller's watchdog fed, as in a lock-step wait
                self._resend()
                beat = time.monotonic() + RESEND
        if job.error is not None:
            raise job.error
        return job.result

    def _run_jobs(self) -> None:
        """Do the jobs handed over (on the world's thread); after ``run`` they are refused."""
        while True:
            with self._acked:
                if not self._jobs:
                    return
                job = self._jobs.popleft()
            try:
                if not self._ended.is_set():
                    with self.lock:
                        job.result = job.work()
            except Exception as exc:  # noqa: BLE001 - handed back to the job's own thread
                job.error = exc
            finally:
                job.done.set()

    def _pause(self, seconds: float) -> None:
        """Let ``seconds`` of wall time pass, doing the jobs that come meanwhile."""
        end = time.monotonic() + seconds
        while not self._stop.is_set():
            self._run_jobs()
            left = end - time.monotonic()
            if left <= 0:
                return
            with self._acked:
                self._acked.wait_for(lambda: bool(self._jobs) or self._stop.is_set(), left)

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
            self._run_jobs()  # the controller's goal for this frame comes before its ack
            with self._acked:
                if self._acked.wait_for(
                    lambda: (
                        self._ack >= frame.seconds - 1e-6 or self._stop.is_set() or bool(self._jobs)
                    ),
                    RESEND,
                ):
                    if self._jobs:
                        continue
                    return
            # the scan again, unchanged: it may have been lost (best effort), and it keeps
            # a slow controller's watchdog fed; the reliable rest of the frame arrived, and
            # sent again after the controller acted it would tell of a world gone by
            self._resend()

    # -- frames --------------------------------------------------------------------

    def _frame(self, percepts: list[Percept], camera: bool = True) -> Frame:
        """The messages of one frame: the clock, where the base is, the percepts (a
        camera frame's detections when ``camera``), the joints, and the scan last."""
        t = self.world.time()
        now = m.stamp_now(t)
        messages: list[tuple[DataWriter, Any]] = [(self.w_clock, m.Clock(now))]
        messages.extend(self._motion(now))
        holding = ""
        boxes: list[m.Detection2D] = []
        for p in percepts:
            if isinstance(p, Pose):
                qx, qy, qz, qw = quaternion_of(p.theta)
                pose = m.Pose(m.Point(p.x, p.y, 0.0), m.Quaternion(qx, qy, qz, qw))
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
                boxes.append(self._box(p, now))
        messages.append((self.w_joints, self._joints(now, holding)))
        messages.append((self.w_gripper, m.String(holding)))
        if camera:
            messages.extend(self._camera(now))
        messages.append((self.w_dets, m.Detection2DArray(m.Header(now, "camera"), boxes)))
        messages.append((self.w_scan, self._scan(now)))  # last: it closes the frame
        return Frame(t, messages)

    def _motion(self, now: m.Time) -> list[tuple[DataWriter, Any]]:
        """``/tf`` (map -> odom -> base_link) and ``/odom``: the field's pose is exact, so
        odom coincides with the map."""
        w = self.world
        qx, qy, qz, qw = quaternion_of(w.theta)
        pose = m.Pose(m.Point(w.x, w.y, 0.0), m.Quaternion(qx, qy, qz, qw))
        base = m.Transform(m.Vector3(w.x, w.y, 0.0), m.Quaternion(qx, qy, qz, qw))
        tf = m.TFMessage(
            [
                m.TransformStamped(m.Header(now, "map"), "odom", m.Transform()),
                m.TransformStamped(m.Header(now, "odom"), "base_link", base),
            ]
        )
        return [(self.w_tf, tf), (self.w_odom, self._odometry(now, pose))]

    def _odometry(self, now: m.Time, pose: m.Pose) -> m.Odometry:
        """An Odometry at ``pose`` moving at the last commanded velocity."""
        v, omega, _at = self._twist
        twist = m.TwistWithCovariance(m.Twist(m.Vector3(x=v), m.Vector3(z=omega)))
        return m.Odometry(m.Header(now, "odom"), "base_link", m.PoseWithCovariance(pose), twist)

    def _joints(self, now: m.Time, holding: str) -> m.JointState:
        """The gripper's one joint: open, or closed with effort on what it holds."""
        return m.JointState(
            m.Header(now, "base_link"),
            [GRIPPER_JOINT],
            [0.0 if holding else GRIPPER_OPEN],
            [0.0],
            [10.0 if holding else 0.0],
        )

    def _camera(self, now: m.Time) -> list[tuple[DataWriter, Any]]:
        """The camera's own messages of a frame (the field has detections only)."""
        return []

    def _scan(self, now: m.Time) -> m.LaserScan:
        """360 beams cast against the fence from the robot's pose."""
        w = self.world
        return m.LaserScan(
            m.Header(now, "base_scan"),
            angle_min=-math.pi,
            angle_max=math.pi - 2 * math.pi / BEAMS,
            angle_increment=2 * math.pi / BEAMS,
            scan_time=w.config.frame_seconds,
            range_min=0.05,
            range_max=RANGE_MAX,
            ranges=fence_ranges(w.x, w.y, w.theta, w.config.size),
        )

    def _box(self, d: Detection, now: m.Time) -> m.Detection2D:
        """A detection as a box in the image: its column from its bearing (a pinhole
        camera of the field's field of view), its position the object's offset."""
        column = column_of(d.bearing, self.world.config.camera_fov)
        box = m.BoundingBox2D(m.Pose2D(m.Point2D(column, IMAGE_HEIGHT / 2)), 40.0, 80.0)
        return detection_2d(d, now, box)

    def _publish(self, frame: Frame) -> None:
        """Send a frame; its scan is what ``_resend`` sends again."""
        with self._sending:
            self._send(frame)
            self._last = frame

    def _resend(self) -> None:
        """The last frame's scan again, unchanged (a controller in lock-step acknowledges
        it and decides on nothing new)."""
        with self._sending:
            if self._last is not None:
                self._send(Frame(self._last.seconds, self._last.messages[-1:]))

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
            self._in_world(lambda: self._apply_twist(v, omega, TWIST_PERIOD))

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

        def drive() -> tuple[Outcome, float, float]:
            w = self.world
            x0, y0, began = w.x, w.y, w.time()
            place = target_place(w, x, y)
            if place is not None:
                outcome = w.execute(GoTo(place))
            else:
                outcome = w.drive_to(x, y, yaw)
            return outcome, w.time() - began, math.hypot(w.x - x0, w.y - y0)

        done = self._in_world(drive)
        if done is None:
            server.finish(goal, m.STATUS_ABORTED, m.NavigateToPoseResult(1, "the sim stopped"))
            return
        outcome, took, distance = done
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

        def act() -> tuple[Outcome, float, str]:
            began = self.world.time()
            if command == "pick":
                outcome = self.world.execute(Pick(target or "trash"))
            elif command == "drop":
                outcome = self.world.execute(Drop())
            else:
                outcome = Outcome.failure(f"unknown gripper command {command!r}")
            return outcome, self.world.time() - began, self.world.in_gripper() or ""

        done = self._in_world(act)
        if done is None:
            server.finish(goal, m.STATUS_ABORTED, m.GraspResult(False, "the sim stopped", ""))
            return
        outcome, took, holding = done
        if not self.lockstep:
            self._busy_while(lambda: self._stop.wait(took / self.rate))
        with self.lock:
            self._busy -= 0 if self.lockstep else 1
            server.finish(
                goal, m.STATUS_SUCCEEDED, m.GraspResult(outcome.ok, outcome.reason, holding)
            )


def detection_2d(d: Detection, now: m.Time, box: m.BoundingBox2D) -> m.Detection2D:
    """A Detection2D of ``box``: the class and score, the object's position from the
    robot (bearing and distance), its track as the id."""
    position = m.Point(d.distance * math.cos(d.bearing), d.distance * math.sin(d.bearing), 0.0)
    hypothesis = m.ObjectHypothesisWithPose(
        m.ObjectHypothesis(d.label, d.confidence),
        m.PoseWithCovariance(m.Pose(position)),
    )
    return m.Detection2D(m.Header(now, "camera"), [hypothesis], box, d.instance or "")


@dataclass
class _GoalRequest:
    """A received goal in the shape of a send_goal request (its ``goal`` part)."""

    goal: Any


def _duration(seconds: float) -> m.Duration:
    seconds = max(0.0, seconds)
    whole = int(seconds)
    return m.Duration(whole, int((seconds - whole) * 1e9))
