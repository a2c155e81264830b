"""The garbage field as a ROS 1 robot: a rospy node, run by the Python that has rospy.

Debian ships rospy for its own Python (/usr/bin/python3), which need not be the Python
robocog runs on, so ``robocog sim garbage --ros1`` runs this file under that Python with
robocog's source directory on its path. It imports only rospy, the message packages and
robocog's plain-Python parts (the field, its sensors' geometry, the ROS 1 detection
classes of the bridge's node), never an engine or DDS.

What it serves, with the field's numbers, as the ROS 2 sim does: ``/scan``
(sensor_msgs/LaserScan, all around), ``/detections`` (vision_msgs/Detection2DArray, the
ROS 1 layout: integer class ids in the order of ``--class-names``), ``/odom``
(nav_msgs/Odometry) every frame, ``/amcl_pose`` (geometry_msgs/PoseWithCovarianceStamped)
when the field's localisation reports, ``/gripper/state`` (std_msgs/String: what it
holds). It takes ``/cmd_vel`` (geometry_msgs/Twist), ``/gripper/command``
(std_msgs/String: ``pick TARGET`` or ``drop``) and serves move_base's ``MoveBaseAction``
through an actionlib ``SimpleActionServer``: a goal at a checkpoint is the field's GoTo
of that checkpoint, at the start corner the end of the route, elsewhere a drive there;
the drive then plays back at ``--rate`` times real time (no camera frames meanwhile)
before the result, and a preemption cancels it.

When the field's mission is over, or on SIGTERM or SIGINT, it prints one line,
``collected N of M objects in S simulated seconds (F frames, G goals)``, and ends.
"""

import argparse
import math
import os
import signal
import sys
import threading
import time
from typing import Any

from robocog.bridges.ros1.node import odometry_class, vision_classes
from robocog.robot.commands import Drop, Forward, GoTo, Pick, Turn
from robocog.robot.percepts import Detection, Gripper, Pose
from robocog.sim.field import BEAMS, RANGE_MAX, column_of, fence_ranges, target_place
from robocog.worlds.garbage import GarbageConfig, GarbageField

#: how long rospy's shutdown may take once the field has reported
SHUTDOWN_SECONDS = 5.0
#: how long the sim stays up after it announced the end of its mission: a subscriber
#: connected then gets the message before the node goes
MISSION_END_SECONDS = 1.0


class Ros1GarbageRobot:
    """A ``GarbageField`` behind ROS 1 topics and move_base."""

    def __init__(self, world: GarbageField, rate: float, class_names: list[str]) -> None:
        import actionlib
        import rospy
        from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
        from move_base_msgs.msg import MoveBaseAction
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import String

        self.rospy = rospy
        self.world = world
        self.rate = rate
        self.class_names = class_names
        self.lock = threading.Lock()
        self.stop = threading.Event()
        self.frames = 0
        self.goals = 0
        self.busy = 0  # goals playing back: their frames take no camera image
        self.twist = (0.0, 0.0, -math.inf)
        Odometry = odometry_class()
        self.LaserScan, self.Odometry, self.String = LaserScan, Odometry, String
        self.PoseMsg = PoseWithCovarianceStamped
        self.vision = vision_classes()
        rospy.init_node("robocog_sim", disable_signals=True)
        self.scan_pub = rospy.Publisher("/scan", LaserScan, queue_size=5)
        self.det_pub = rospy.Publisher("/detections", self.vision["Detection2DArray"], queue_size=5)
        self.odom_pub = rospy.Publisher("/odom", Odometry, queue_size=5)
        self.amcl_pub = rospy.Publisher("/amcl_pose", PoseWithCovarianceStamped, queue_size=5)
        self.grip_pub = rospy.Publisher("/gripper/state", String, queue_size=5)
        # latched: a controller that subscribes after the end still hears of it
        self.mission_pub = rospy.Publisher("/mission/state", String, queue_size=1, latch=True)
        rospy.Subscriber("/cmd_vel", Twist, self.on_twist)
        rospy.Subscriber("/gripper/command", String, self.on_gripper)
        self.server = actionlib.SimpleActionServer(
            "/move_base", MoveBaseAction, execute_cb=self.on_goal, auto_start=False
        )
        self.server.start()

    # -- requests ------------------------------------------------------------------

    def on_twist(self, msg: Any) -> None:
        """Keep the last finite velocity; the frame loop drives with it while it is fresh."""
        v, omega = msg.linear.x, msg.angular.z
        if math.isfinite(v) and math.isfinite(omega):
            self.twist = (v, omega, time.monotonic())

    def on_gripper(self, msg: Any) -> None:
        """``pick TARGET`` or ``drop``: done on the field at once, then the state is told."""
        words = msg.data.split()
        with self.lock:
            if words[:1] == ["pick"]:
                self.world.execute(Pick(words[1] if len(words) > 1 else "trash"))
            elif words[:1] == ["drop"]:
                self.world.execute(Drop())
            held = self.world.holding
            self.grip_pub.publish(self.String(held.instance if held else ""))

    def on_goal(self, goal: Any) -> None:
        """A move_base goal: the field's GoTo (or a drive), played back, then the result."""
        p = goal.target_pose.pose
        x, y = p.position.x, p.position.y
        q = p.orientation
        yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
        if not all(math.isfinite(v) for v in (x, y, yaw)):
            self.server.set_aborted(text="not a finite pose")
            return
        with self.lock:
            self.goals += 1
            w = self.world
            began = w.time()
            place = target_place(w, x, y)
            outcome = w.execute(GoTo(place)) if place is not None else w.drive_to(x, y, yaw)
            took = w.time() - began
            self.busy += 1
        try:
            end = time.monotonic() + took / self.rate
            while time.monotonic() < end and not self.stop.is_set():
                if self.server.is_preempt_requested():
                    self.server.set_preempted()
                    return
                time.sleep(min(0.02, max(0.0, end - time.monotonic())))
        finally:
            with self.lock:
                self.busy -= 1
        if outcome.ok:
            self.server.set_succeeded()
        else:
            self.server.set_aborted(text=outcome.reason or "")

    # -- frames --------------------------------------------------------------------

    def run(self) -> None:
        """Publish a frame every field frame, at ``rate``, until the mission is over."""
        period = self.world.config.frame_seconds / self.rate
        while not self.stop.is_set() and not self.world.done:
            with self.lock:
                self.drive()
                percepts = [] if self.busy else self.world.percepts()
                if not self.busy:
                    self.frames += 1
                self.publish(percepts, camera=not self.busy)
            self.stop.wait(period)

    def drive(self) -> None:
        """The last Twist, if fresh (0.5 s, a base controller's time-out), moves the base
        for one frame."""
        v, omega, at = self.twist
        if time.monotonic() - at > 0.5 or not (v or omega):
            return
        seconds = self.world.config.frame_seconds
        if omega:
            self.world.execute(Turn(omega * seconds))
        if v:
            self.world.execute(Forward(v * seconds))

    def publish(self, percepts: list[Any], camera: bool) -> None:
        """One frame's messages: odometry, the pose when localised, the gripper, the
        detections (when the camera looked) and the scan."""
        rospy, w = self.rospy, self.world
        now = rospy.Time.from_sec(w.time())
        qz, qw = math.sin(w.theta / 2), math.cos(w.theta / 2)
        odom = self.Odometry()
        odom.header.stamp, odom.header.frame_id, odom.child_frame_id = now, "odom", "base_link"
        odom.pose.pose.position.x, odom.pose.pose.position.y = w.x, w.y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = qz, qw
        self.odom_pub.publish(odom)
        boxes = []
        for p in percepts:
            if isinstance(p, Pose):
                pose = self.PoseMsg()
                pose.header.stamp, pose.header.frame_id = now, "map"
                pose.pose.pose = odom.pose.pose
                self.amcl_pub.publish(pose)
            elif isinstance(p, Gripper):
                self.grip_pub.publish(self.String(p.holding or ""))
            elif isinstance(p, Detection):
                boxes.append(self.box(p))
        if camera:
            array = self.vision["Detection2DArray"]()
            array.header.stamp, array.header.frame_id = now, "camera"
            array.detections = boxes
            self.det_pub.publish(array)
        scan = self.LaserScan()
        scan.header.stamp, scan.header.frame_id = now, "base_scan"
        scan.angle_min = -math.pi
        scan.angle_max = math.pi - 2 * math.pi / BEAMS
        scan.angle_increment = 2 * math.pi / BEAMS
        scan.range_min, scan.range_max = 0.05, RANGE_MAX
        scan.ranges = fence_ranges(w.x, w.y, w.theta, w.config.size)
        self.scan_pub.publish(scan)

    def box(self, d: Detection) -> Any:
        """One detection as ROS 1's Detection2D: class id, score, centre column, position."""
        detection = self.vision["Detection2D"]()
        hypothesis = self.vision["ObjectHypothesisWithPose"]()
        names = self.class_names
        hypothesis.id = names.index(d.label) if d.label in names else len(names)
        hypothesis.score = d.confidence
        position = hypothesis.pose.pose.position
        position.x = d.distance * math.cos(d.bearing)
        position.y = d.distance * math.sin(d.bearing)
        detection.results.append(hypothesis)
        detection.bbox.center.x = column_of(d.bearing, self.world.config.camera_fov)
        detection.bbox.size_x, detection.bbox.size_y = 40.0, 80.0
        return detection


def main() -> int:
    """Serve the field until its mission is over or the process is told to stop."""
    parser = argparse.ArgumentParser(description="the garbage field as a ROS 1 robot")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--light", default="sunny")
    parser.add_argument("--rate", type=float, default=1.0)
    parser.add_argument("--class-names", default="bottle,cup")
    args = parser.parse_args()
    world = GarbageField(GarbageConfig(light=args.light), seed=args.seed)
    robot = Ros1GarbageRobot(world, args.rate, args.class_names.split(","))

    def _stop(_signum: int, _frame: object) -> None:
        robot.stop.set()

    signal.signal(signal.SIGTERM, _stop)
    signal.signal(signal.SIGINT, _stop)
    print(
        f"robocog sim: garbage field (seed {args.seed}, {args.light}) on ROS 1; "
        f"{len(world.objects())} objects",
        file=sys.stderr,
        flush=True,
    )
    try:
        robot.run()
        if robot.world.done and not robot.stop.is_set():
            # the end of the mission, told to the controller (a bridge ends with it)
            w = robot.world
            why = "route complete" if w.route_complete else "battery spent"
            robot.mission_pub.publish(
                robot.String(
                    f"ended: {why}; collected {w.collected()} of {len(w.objects())} objects"
                )
            )
            robot.stop.wait(MISSION_END_SECONDS)  # time for the latched message to go out
    finally:
        robot.stop.set()
    # the report first: it is the field's own count, whatever rospy's shutdown does next
    print(
        f"robocog sim: collected {world.collected()} of {len(world.objects())} objects in "
        f"{world.time():.0f} simulated seconds ({robot.frames} frames, {robot.goals} goals)",
        flush=True,
    )
    # rospy's shutdown joins its connections' threads, which a peer that went away
    # mid-request can hold; a sim told to stop ends within SHUTDOWN_SECONDS regardless
    closing = threading.Thread(
        target=robot.rospy.signal_shutdown, args=("the mission is over",), daemon=True
    )
    closing.start()
    closing.join(SHUTDOWN_SECONDS)
    if closing.is_alive():
        sys.stderr.flush()
        os._exit(0)
    return 0


if __name__ == "__main__":
    sys.exit(main())
