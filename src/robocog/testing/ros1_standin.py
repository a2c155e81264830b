"""A stand-in ROS 1 robot with a stand-in move_base, for the Python that has rospy.

Like the ROS 2 stand-in, it publishes a scan with one obstacle, detections, the amcl
pose and the gripper state, and records what it is told: velocity, gripper requests,
and move_base goals and cancels through a real actionlib action server that reaches a
goal after ``--goal-seconds`` unless it is cancelled first.

With ``--listen-only`` it publishes nothing and serves no move_base: an observer that
outlives the robot. Scene changes come as JSON lines on stdin (``{"obstacle": [bearing, distance]}``,
``{"detections": [{"label": "bottle", "x": 320}]}``, ``{"alive": false}``, ...); every
request received goes out as a JSON line on stdout. Run it with /usr/bin/python3.
"""

import argparse
import json
import math
import os
import sys
import threading
import time
from typing import IO, Any

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(_HERE), "bridges", "ros1"))

from node import vision_classes  # noqa: E402 - the bridge's node script, by path


class StandIn:
    """The robot's side of the ROS 1 topics plus a move_base action server."""

    def __init__(
        self,
        class_names: list[str],
        goal_seconds: float,
        out: IO[str],
        serve_move_base: bool = True,
    ) -> None:
        import actionlib
        import rospy
        from actionlib_msgs.msg import GoalID
        from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
        from move_base_msgs.msg import MoveBaseAction
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import String

        self.rospy = rospy
        self.out = out
        self.lock = threading.Lock()
        self.class_names = class_names
        self.goal_seconds = goal_seconds
        self.obstacle = None
        self.detections = []
        self.pose = (0.0, 0.0, 0.0)
        self.holding = ""
        self.alive = True
        rospy.init_node("standin_robot", anonymous=True, disable_signals=True)
        self.LaserScan = LaserScan
        self.vision = vision_classes()
        self.Detections = self.vision["Detection2DArray"]
        self.PoseMsg = PoseWithCovarianceStamped
        self.String = String
        self.scan_pub = rospy.Publisher("/scan", LaserScan, queue_size=5)
        self.det_pub = rospy.Publisher("/detections", self.Detections, queue_size=5)
        self.pose_pub = rospy.Publisher("/amcl_pose", PoseWithCovarianceStamped, queue_size=5)
        self.grip_pub = rospy.Publisher("/gripper/state", String, queue_size=5)
        self.text_pub = rospy.Publisher("/narsese", String, queue_size=10)
        self.mission_pub = rospy.Publisher("/mission/state", String, queue_size=1, latch=True)
        rospy.Subscriber("/cmd_vel", Twist, self.on_twist)
        rospy.Subscriber("/gripper/command", String, self.on_grip)
        # beside the action server: every cancel request, even with no goal under way
        rospy.Subscriber("/move_base/cancel", GoalID, self.on_cancel_request)
        self.server = None
        if serve_move_base:
            self.server = actionlib.SimpleActionServer(
                "/move_base", MoveBaseAction, execute_cb=self.on_goal, auto_start=False
            )
            self.server.start()

    def emit(self, obj: dict[str, Any]) -> None:
        """Record one event as a timestamped JSON line (callbacks run on rospy's threads)."""
        obj["t"] = time.time()
        with self.lock:
            self.out.write(json.dumps(obj) + "\n")
            self.out.flush()

    # -- requests ------------------------------------------------------------------

    def on_twist(self, msg: Any) -> None:
        """Record a velocity command."""
        self.emit({"event": "cmd_vel", "linear": msg.linear.x, "angular": msg.angular.z})

    def on_cancel_request(self, msg: Any) -> None:
        """Record a move_base cancel request, even one with no goal under way."""
        self.emit({"event": "cancel_request", "all": msg.id == ""})

    def on_grip(self, msg: Any) -> None:
        """Record a gripper request and hold (or let go of) what it names."""
        self.emit({"event": "gripper", "text": msg.data})
        words = msg.data.split()
        if words[:1] == ["pick"] and len(words) > 1:
            self.holding = words[1]
        elif words[:1] == ["drop"]:
            self.holding = ""

    def on_goal(self, goal: Any) -> None:
        """Serve a move_base goal: reached after ``goal_seconds`` unless preempted first."""
        p = goal.target_pose.pose.position
        self.emit({"event": "goal", "frame": goal.target_pose.header.frame_id, "x": p.x, "y": p.y})
        end = time.time() + self.goal_seconds
        while time.time() < end:
            if self.server.is_preempt_requested():
                self.emit({"event": "cancel"})
                self.server.set_preempted()
                return
            time.sleep(0.02)
        self.pose = (p.x, p.y, self.pose[2])
        self.server.set_succeeded()

    # -- the scene -----------------------------------------------------------------

    def update(self, data: dict[str, Any]) -> None:
        """Change the scene from one JSON object of the test (only the keys it names)."""
        if "obstacle" in data:
            self.obstacle = None if data["obstacle"] is None else tuple(data["obstacle"])
        if "detections" in data:
            self.detections = [
                (d["label"], float(d.get("x", 320.0)), float(d.get("score", 0.9)))
                for d in data["detections"]
            ]
        if "pose" in data:
            self.pose = tuple(float(v) for v in data["pose"])
        if "holding" in data:
            self.holding = data["holding"] or ""
        if "alive" in data:
            self.alive = bool(data["alive"])
        if "goal_seconds" in data:
            self.goal_seconds = float(data["goal_seconds"])
        if "narsese" in data:
            self.text_pub.publish(self.String(str(data["narsese"])))
        if "mission" in data:
            self.mission_pub.publish(self.String(str(data["mission"])))

    def publish(self) -> None:
        """Publish one round of scan, detections, amcl pose and gripper state."""
        if not self.alive:
            return
        rospy = self.rospy
        now = rospy.Time.now()
        scan = self.LaserScan()
        scan.header.stamp = now
        scan.header.frame_id = "base_scan"
        beams = 181
        scan.angle_min, scan.angle_max = -math.pi / 2, math.pi / 2
        scan.angle_increment = math.pi / (beams - 1)
        scan.range_min, scan.range_max = 0.05, 10.0
        ranges = [float("inf")] * beams
        if self.obstacle is not None:
            bearing, distance = self.obstacle
            centre = round((bearing + math.pi / 2) / scan.angle_increment)
            for i in range(max(0, centre - 2), min(beams, centre + 3)):
                ranges[i] = distance
        scan.ranges = ranges
        self.scan_pub.publish(scan)
        array = self.Detections()
        array.header.stamp = now
        for label, column, score in self.detections:
            detection = self.vision["Detection2D"]()
            hypothesis = self.vision["ObjectHypothesisWithPose"]()
            hypothesis.id = self.class_names.index(label) if label in self.class_names else 0
            hypothesis.score = score
            detection.results.append(hypothesis)
            detection.bbox.center.x = column
            detection.bbox.size_x, detection.bbox.size_y = 40.0, 80.0
            array.detections.append(detection)
        self.det_pub.publish(array)
        pose = self.PoseMsg()
        pose.header.stamp = now
        pose.header.frame_id = "map"
        pose.pose.pose.position.x, pose.pose.pose.position.y = self.pose[0], self.pose[1]
        pose.pose.pose.orientation.z = math.sin(self.pose[2] / 2)
        pose.pose.pose.orientation.w = math.cos(self.pose[2] / 2)
        self.pose_pub.publish(pose)
        self.grip_pub.publish(self.String(self.holding))


def main() -> int:
    """Serve the topics and move_base until stdin closes, taking scene changes from it."""
    parser = argparse.ArgumentParser(description="a stand-in ROS 1 robot with move_base")
    parser.add_argument("--rate", type=float, default=20.0)
    parser.add_argument("--goal-seconds", type=float, default=1.0)
    parser.add_argument("--class-names", default="bottle,cup")
    parser.add_argument("--scene", default="{}")
    parser.add_argument(
        "--listen-only",
        action="store_true",
        help="publish nothing and serve no move_base: only record what the robot is told",
    )
    args = parser.parse_args()
    out = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    robot = StandIn(
        args.class_names.split(","), args.goal_seconds, out, serve_move_base=not args.listen_only
    )
    if args.listen_only:
        robot.alive = False
    robot.update(json.loads(args.scene))
    stop = threading.Event()

    def publish_loop() -> None:
        while not stop.wait(1.0 / args.rate):
            try:
                robot.publish()
            except Exception as exc:  # keep publishing; report once per failure
                robot.emit({"event": "error", "text": f"{type(exc).__name__}: {exc}"})

    threading.Thread(target=publish_loop, daemon=True).start()
    robot.emit({"event": "ready"})
    try:
        for line in sys.stdin:
            if line.strip():
                robot.update(json.loads(line))
    finally:
        stop.set()
        robot.rospy.signal_shutdown("stdin closed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
