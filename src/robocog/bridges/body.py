"""A robot reached through middleware, as a ``Body``.

The middleware side (a ``Link``: ROS 2 over DDS, ROS 1 through a rospy node) only moves
plain readings in and plain requests out; everything else lives here once: the latest
percepts with their age, the mapping of Commands onto velocity, navigation goals and the
gripper, and the halt that the watchdog pulls. The logic never sees a message type.
"""

from __future__ import annotations

import logging
import math
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Protocol

from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import (
    BoxReading,
    PoseReading,
    ScanReading,
    detection_of,
    nearest_obstacle,
    pose_of,
)
from robocog.robot.commands import (
    Cancel,
    Command,
    Drop,
    Forward,
    GoTo,
    Look,
    Outcome,
    Pick,
    Turn,
)
from robocog.robot.percepts import Gripper, Percept

log = logging.getLogger("robocog.bridges")

#: what the gripper reports when it holds nothing
EMPTY_GRIPPER = ("", "open", "empty", "none")
#: lock-step: how long (s) a new scan waits for the detections stamped with its time
FRAME_PARTS_WAIT = 1.0


class Link(Protocol):
    """The middleware side of a bridge: starts feeding a ``RobotBody``, sends requests."""

    def start(self, body: RobotBody) -> None:
        """Connect and begin handing readings to ``body``'s ``on_*`` methods."""
        ...

    def close(self) -> None:
        """Disconnect and release every resource (threads, processes, sockets)."""
        ...

    def send_velocity(self, linear: float, angular: float) -> None:
        """Publish one velocity command (m/s forward, rad/s counter-clockwise)."""
        ...

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        """Send a navigation goal in the map frame; returns a token for its result,
        which the link hands to ``RobotBody.on_goal_result`` when the goal ends."""
        ...

    def cancel_goals(self) -> None:
        """Cancel every navigation goal under way."""
        ...

    def send_gripper(self, text: str) -> int | None:
        """Send a gripper request: ``pick <target>`` or ``drop``. Returns a token when
        the link reports the request's result (``RobotBody.on_gripper_result``), None
        when only the gripper's state tells."""
        ...


class RobotBody:
    """A ``Body`` over a ``Link``: percepts from the latest readings, commands as requests.

    Readings arrive on the link's thread through the ``on_*`` methods; the loop's thread
    reads them through ``percepts()``. ``halt()`` stops the robot from any thread and
    makes motion commands end cancelled until ``resume()``.
    """

    def __init__(self, link: Link, config: BridgeConfig | None = None) -> None:
        self.link = link
        self.config = config or BridgeConfig()
        self._lock = threading.Condition()
        self._scan: ScanReading | None = None
        self._boxes: list[BoxReading] = []
        self._boxes_at = -math.inf
        self._pose: PoseReading | None = None
        self._gripper: str | None = None
        self._texts: deque[str] = deque(maxlen=1000)
        self._goal_results: dict[int, str] = {}
        self._gripper_results: dict[int, tuple[bool, str]] = {}
        self._last_place: str | None = None  # the last route place reached
        self._warned_places: set[str] = set()
        self._scans = 0  # laser scans received: the frames of lock-step operation
        self._heard: dict[str, float] = {}  # sensor -> when it last reported
        self._scan_stamp = 0.0
        self._boxes_stamp = 0.0  # header time of the latest stamped detection array
        #: readings dropped because they held NaN or infinite values, by sensor
        self.dropped: dict[str, int] = {}
        self._last_reading = -math.inf
        self._generation = 0
        self._halted: str | None = None
        self._started = False
        self._mission_ended: str | None = None

    # -- lifecycle -------------------------------------------------------------

    def start(self) -> RobotBody:
        """Connect the link; readings start arriving."""
        if not self._started:
            self.link.start(self)
            self._started = True
        return self

    def close(self) -> None:
        """Stop the robot and disconnect."""
        if self._started:
            try:
                self.link.send_velocity(0.0, 0.0)
            finally:
                self.link.close()
                self._started = False

    def __enter__(self) -> RobotBody:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- readings, from the link's thread -------------------------------------

    def on_scan(self, scan: ScanReading, stamp: float = 0.0) -> None:
        """A laser scan arrived (``stamp``: its header time, which names the frame).

        A scan whose angles or limits are not finite, or with a NaN range, is dropped
        and counted: it cannot say where an obstacle is (+inf ranges are ROS's "no
        return" and stay)."""
        numbers = (scan.angle_min, scan.angle_increment, scan.range_min, scan.range_max)
        if (
            not all(math.isfinite(v) for v in numbers)
            or any(math.isnan(r) for r in scan.ranges)
            or not _sane_scan(scan)
        ):
            self.drop_reading("scan")
            return
        with self._lock:
            self._scan = scan
            self._scans += 1
            self._scan_stamp = stamp
            self._heard["scan"] = time.monotonic()
            self._touch()

    def on_boxes(self, boxes: list[BoxReading], stamp: float = 0.0) -> None:
        """A detection array arrived (possibly empty: nothing seen); a box with a value
        that is not finite is dropped and counted. ``stamp`` is the array's header time
        (0 when the robot does not stamp it)."""
        kept = [b for b in boxes if _finite_box(b)]
        for _ in range(len(boxes) - len(kept)):
            self.drop_reading("detection")
        with self._lock:
            self._boxes = kept
            if stamp > 0 and math.isfinite(stamp):
                self._boxes_stamp = stamp
            self._boxes_at = time.monotonic()
            self._heard["detections"] = self._boxes_at
            self._touch()

    def on_pose(self, pose: PoseReading) -> None:
        """The robot's pose arrived; one that is not finite is dropped and counted."""
        values = (pose.x, pose.y, pose.yaw)
        if not all(math.isfinite(v) for v in values) or max(map(abs, values)) > MAX_COORDINATE:
            self.drop_reading("pose")
            return
        with self._lock:
            self._pose = pose
            self._heard["pose"] = time.monotonic()
            self._touch()

    def on_gripper(self, state: str) -> None:
        """The gripper reported what it holds (empty or ``open`` when nothing)."""
        with self._lock:
            state = state.strip()
            self._gripper = None if state.lower() in EMPTY_GRIPPER else state
            self._touch()

    def on_text(self, text: str) -> None:
        """Narsese (or other text) for the mind arrived; kept until ``texts()``."""
        with self._lock:
            for line in text.splitlines():
                if line.strip():
                    self._texts.append(line.strip())
            self._lock.notify_all()

    def on_mission(self, state: str) -> None:
        """The robot's mission state arrived: ``ended`` or ``ended: WHY`` ends the run
        (other states, such as ``running``, are only logged)."""
        head, _, why = state.strip().partition(":")
        if head.strip().lower() != "ended":
            log.info("mission state: %s", state.strip()[:200])
            return
        with self._lock:
            if self._mission_ended is None:
                self._mission_ended = why.strip()[:500] or "no reason given"
            self._generation += 1  # wakes a wait for readings
            self._lock.notify_all()

    def mission_ended(self) -> str | None:
        """Why the robot ended its mission (None while it goes on)."""
        with self._lock:
            return self._mission_ended

    def on_goal_result(self, token: int, status: str) -> None:
        """A navigation goal ended: ``succeeded``, ``aborted``, ``canceled``, ..."""
        with self._lock:
            self._goal_results[token] = status
            self._lock.notify_all()

    def on_gripper_result(self, token: int, ok: bool, reason: str, holding: str | None) -> None:
        """A gripper request ended; ``holding`` is what the gripper holds now."""
        with self._lock:
            self._gripper_results[token] = (ok, reason)
            state = (holding or "").strip()
            self._gripper = None if state.lower() in EMPTY_GRIPPER else state
            self._lock.notify_all()

    def drop_reading(self, sensor: str) -> None:
        """Count a reading refused for NaN, infinite or absurd values (it never reaches
        a mind)."""
        with self._lock:
            count = self.dropped.get(sensor, 0) + 1
            self.dropped[sensor] = count
        if count == 1:
            log.warning(
                "dropped a %s reading with NaN, infinite or out-of-range values (counted)",
                sensor,
            )

    def _touch(self) -> None:
        self._last_reading = time.monotonic()
        self._generation += 1
        self._lock.notify_all()

    # -- the Body protocol ------------------------------------------------------

    def time(self) -> float:
        """Wall-clock time: a real robot lives in it."""
        return time.time()

    def percept_age(self) -> float:
        """Seconds since the robot last sent anything (infinite before the first)."""
        with self._lock:
            return time.monotonic() - self._last_reading

    def stale(self) -> str | None:
        """Why the robot's readings are too old to act on, or None while they are fresh.

        Every sensor that has reported once must keep reporting within its own limit
        (``scan_timeout``, ``pose_timeout``, ``detections_timeout``; 0 watches it not):
        a scan that stops while poses still arrive stops the robot all the same.
        """
        c = self.config
        now = time.monotonic()
        with self._lock:
            age = now - self._last_reading
            heard = dict(self._heard)
        if age > c.watchdog_seconds:
            if math.isinf(age):
                return "no percepts from the robot yet"
            return f"no percepts for {c.watchdog_seconds:g} s (last {age:.2f} s ago)"
        limits = {
            "scan": c.watchdog_seconds if c.scan_timeout is None else c.scan_timeout,
            "pose": c.pose_timeout,
            "detections": c.detections_timeout,
        }
        for sensor, limit in limits.items():
            if limit > 0 and sensor in heard and now - heard[sensor] > limit:
                return f"no {sensor} for {limit:g} s (last {now - heard[sensor]:.2f} s ago)"
        return None

    def wait_for_readings(self, timeout: float) -> bool:
        """Block until a new reading arrives or ``timeout`` passes; True if one came."""
        with self._lock:
            seen = self._generation
            return self._lock.wait_for(lambda: self._generation != seen, timeout)

    @property
    def scans(self) -> int:
        """How many laser scans have arrived (the frames of ``lockstep`` operation)."""
        with self._lock:
            return self._scans

    def wait_for_frame(self, seen: int, timeout: float) -> tuple[int, float]:
        """Block until a scan newer than the ``seen``-th arrives or ``timeout`` passes;
        returns the count of scans and the latest one's stamp."""
        with self._lock:
            self._lock.wait_for(lambda: self._scans != seen, timeout)
            if 0 < self._boxes_stamp < self._scan_stamp:
                # The frame's detections were sent before its scan, but DDS delivers a
                # reliable topic through a queue that a best-effort scan can overtake:
                # a robot that stamps its detections gets them waited for, briefly.
                self._lock.wait_for(lambda: self._boxes_stamp >= self._scan_stamp, FRAME_PARTS_WAIT)
            return self._scans, self._scan_stamp

    def frame_done(self, stamp: float) -> None:
        """Tell the robot the frame stamped ``stamp`` is decided (if its link can)."""
        send = getattr(self.link, "frame_done", None)
        if callable(send):
            send(stamp)

    def texts(self) -> list[str]:
        """The text lines received since the last call, oldest first."""
        with self._lock:
            lines = list(self._texts)
            self._texts.clear()
            return lines

    def percepts(self) -> list[Percept]:
        """The detections still fresh, the latest obstacle, the gripper and the pose,
        in the order the embedded worlds give them."""
        c = self.config
        with self._lock:
            scan, pose, gripper = self._scan, self._pose, self._gripper
            if c.pose_on_arrival:
                pose, self._pose = self._pose, None
            fresh = time.monotonic() - self._boxes_at <= c.detection_ttl
            boxes = list(self._boxes) if fresh else []
        out: list[Percept] = []
        out.extend(detection_of(b, c.image_width, c.horizontal_fov) for b in boxes)
        if scan is not None:
            out.append(
                nearest_obstacle(scan, c.obstacle_range, c.front_half_width, c.obstacle_half_width)
            )
        out.append(Gripper(gripper))
        if pose is not None:
            percept = pose_of(pose, c.places, c.place_radius)
            if percept.place in c.route_places:
                with self._lock:
                    self._last_place = percept.place
            out.append(percept)
        return out

    def execute(self, command: Command) -> Outcome:
        """Carry out one command on the robot; every command ends with an Outcome."""
        if self._halted is not None and not isinstance(command, Cancel):
            return self._halted_outcome()
        match command:
            case Forward(distance):
                speed = math.copysign(self.config.linear_speed, distance)
                return self._move(speed, 0.0, abs(distance) / self.config.linear_speed)
            case Turn(angle):
                speed = math.copysign(self.config.angular_speed, angle)
                return self._move(0.0, speed, abs(angle) / self.config.angular_speed)
            case GoTo(place):
                return self._goto(place)
            case Cancel():
                self.stop()
                return Outcome.success()
            case Pick(target):
                return self._gripper_request(f"pick {target}", lambda held: held is not None)
            case Drop():
                return self._gripper_request("drop", lambda held: held is None)
            case Look():
                return Outcome.failure("this robot has no camera to point")
            case _:
                return Outcome.failure(f"{type(command).__name__} needs a manipulator bridge")

    # -- halting ---------------------------------------------------------------

    @property
    def halted(self) -> str | None:
        """Why the robot is halted, or None when it may move."""
        return self._halted

    def stop(self) -> None:
        """Zero velocity and cancel navigation, now."""
        self.link.send_velocity(0.0, 0.0)
        self.link.cancel_goals()

    def halt(self, reason: str) -> None:
        """Stop the robot and refuse motion until ``resume()``; safe from any thread."""
        with self._lock:
            self._halted = reason
            self._lock.notify_all()
        self.stop()

    def resume(self) -> None:
        """Allow motion again."""
        with self._lock:
            self._halted = None

    # -- command helpers -------------------------------------------------------

    def _halted_outcome(self) -> Outcome:
        """How a command ends while the robot is halted: cancelled, with the reason."""
        return Outcome.cancelled(f"robot halted: {self._halted}")

    def _move(self, linear: float, angular: float, seconds: float) -> Outcome:
        if seconds <= 0:
            return Outcome.success()  # nothing to drive: no velocity goes out
        seconds = min(seconds, self.config.max_motion_seconds)
        period = 1.0 / self.config.command_rate
        end = time.monotonic() + seconds
        try:
            while True:
                # checked and sent under the lock: a halt from another thread either
                # comes first and is seen here, or comes after and its zero velocity
                # is the last word
                with self._lock:
                    if self._halted is not None:
                        return self._halted_outcome()
                    self.link.send_velocity(linear, angular)
                left = end - time.monotonic()
                if left <= 0:
                    return Outcome.success()
                with self._lock:
                    self._lock.wait_for(lambda: self._halted is not None, min(period, left))
        finally:
            self.link.send_velocity(0.0, 0.0)

    def _goto(self, place: str) -> Outcome:
        """Send the place's pose as a navigation goal and wait for the goal's result:
        a GoTo never succeeds before the navigator says the robot arrived."""
        with self._lock:
            last = self._last_place
        target = self.config.resolve(place, last)
        if target is None:
            if place not in self._warned_places:
                self._warned_places.add(place)
                known = ", ".join([*self.config.places, "next", "start"])
                log.warning("GoTo(%r): unknown place; known places: %s", place, known)
            return Outcome.failure(f"unknown place {place!r}")
        name, (x, y, yaw) = target
        token = self.link.send_goal(x, y, yaw)
        deadline = time.monotonic() + self.config.goto_timeout
        with self._lock:
            while True:
                status = self._goal_results.pop(token, None)
                if status is not None:
                    outcome = _goal_outcome(status)
                    if outcome.ok:
                        self._last_place = name if name in self.config.route_places else None
                    return outcome
                if self._halted is not None:
                    return self._halted_outcome()
                left = deadline - time.monotonic()
                if left <= 0:
                    break
                self._lock.wait(min(left, 0.1))
        self.link.cancel_goals()
        limit = self.config.goto_timeout
        return Outcome.failure(f"no navigation result for {name} within {limit:g} s")

    def _gripper_request(self, text: str, done: Callable[[str | None], bool]) -> Outcome:
        token = self.link.send_gripper(text)
        with self._lock:
            if token is not None:  # the link reports the request's own result
                ok = self._lock.wait_for(
                    lambda: token in self._gripper_results or self._halted is not None,
                    self.config.grasp_timeout,
                )
                result = self._gripper_results.pop(token, None)
                if result is not None:
                    success, reason = result
                    return Outcome.success() if success else Outcome.failure(reason or text)
            else:
                ok = self._lock.wait_for(
                    lambda: done(self._gripper) or self._halted is not None,
                    self.config.gripper_timeout,
                )
            if self._halted is not None:
                return self._halted_outcome()
        if ok and token is None:
            return Outcome.success()
        return Outcome.failure(f"the gripper did not confirm {text!r}")


#: the largest coordinate (metres, pixels) a reading may hold: a robot's world and its
#: camera are far smaller; a value past it is a fault of the sender, dropped and counted
MAX_COORDINATE = 1e6
#: the largest scan angle (radians) taken, for the first ray and for the step between rays
MAX_SCAN_ANGLE = 4 * math.pi


def _finite_box(box: BoxReading) -> bool:
    """A detection a mind may get: finite, a score (confidence) in [0, 1], coordinates
    within ``MAX_COORDINATE``."""
    values = (box.score, box.center_x, *box.position)
    if not all(math.isfinite(v) for v in values):
        return False
    return 0.0 <= box.score <= 1.0 and max(map(abs, values)) <= MAX_COORDINATE


def _sane_scan(scan: ScanReading) -> bool:
    """Scan angles within ``MAX_SCAN_ANGLE`` (the last ray's angle finite), limits within
    ``MAX_COORDINATE``."""
    last = abs(scan.angle_min) + abs(scan.angle_increment) * max(0, len(scan.ranges) - 1)
    return (
        abs(scan.angle_min) <= MAX_SCAN_ANGLE
        and abs(scan.angle_increment) <= MAX_SCAN_ANGLE
        and math.isfinite(last)
        and 0.0 <= scan.range_min <= MAX_COORDINATE
        and abs(scan.range_max) <= MAX_COORDINATE
    )


def _goal_outcome(status: str) -> Outcome:
    if status == "succeeded":
        return Outcome.success()
    if status in ("preempted", "recalled", "cancelled", "canceled"):
        return Outcome.cancelled(f"navigation goal {status}")
    return Outcome.failure(f"navigation goal {status}")
