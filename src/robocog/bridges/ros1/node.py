"""The rospy node of the ROS 1 bridge, run by the Python that has rospy.

Debian ships rospy for its own Python (/usr/bin/python3), which need not be the Python
robocog runs on. So this file is a script for that Python alone: it imports rospy and
the message packages, never robocog, and speaks JSON lines with its parent, the bridge.

To the parent (stdout), one object per line, ``k`` naming the kind::

    {"k": "ready"}
    {"k": "scan", "angle_min": .., "angle_increment": .., "range_min": .., "range_max": .., "ranges": [..], "stamp": s}
    {"k": "boxes", "items": [{"label": .., "score": .., "cx": .., "pos": [x, y, z]}], "stamp": s}
    {"k": "pose", "x": .., "y": .., "q": [x, y, z, w]}
    {"k": "gripper", "text": ..}    {"k": "text", "text": ..}
    {"k": "goal", "id": n, "status": "succeeded|aborted|preempted|recalled|rejected|lost"}
    {"k": "error", "text": ..}

From the parent (stdin)::

    {"op": "twist", "linear": .., "angular": ..}
    {"op": "goal", "id": n, "x": .., "y": .., "q": [x, y, z, w], "frame": "map"}
    {"op": "cancel"}    {"op": "gripper", "text": ..}    {"op": "quit"}

ROS 1 detections are vision_msgs/Detection2DArray (the ROS 1 layout, integer class
ids); Debian has no vision_msgs, so when it is missing the classes are generated from
the message definitions below, which gives them the same checksum as the real package.
nav_msgs/Odometry is generated the same way when nav_msgs is not installed (Debian's
python3-nav-msgs brings the C++ message headers and Boost's with it).
"""

import json
import math
import os
import sys
import threading
from typing import IO, Any

SEPARATOR = "=" * 80 + "\n"

VISION_MSGS_ROS1 = {
    "vision_msgs/Detection2DArray": "Header header\nDetection2D[] detections\n",
    "vision_msgs/Detection2D": (
        "Header header\n"
        "ObjectHypothesisWithPose[] results\n"
        "BoundingBox2D bbox\n"
        "sensor_msgs/Image source_img\n"
    ),
    "vision_msgs/ObjectHypothesisWithPose": (
        "int64 id\nfloat64 score\ngeometry_msgs/PoseWithCovariance pose\n"
    ),
    "vision_msgs/BoundingBox2D": "geometry_msgs/Pose2D center\nfloat64 size_x\nfloat64 size_y\n",
}

#: nav_msgs/Odometry as ROS 1 defines it (comments left out: they do not change its MD5)
ODOMETRY_ROS1 = (
    "Header header\n"
    "string child_frame_id\n"
    "geometry_msgs/PoseWithCovariance pose\n"
    "geometry_msgs/TwistWithCovariance twist\n"
)

GOAL_STATUS = {
    2: "preempted",
    3: "succeeded",
    4: "aborted",
    5: "rejected",
    8: "recalled",
    9: "lost",
}


def vision_classes() -> dict[str, type]:
    """vision_msgs' Detection2DArray, Detection2D and ObjectHypothesisWithPose classes:
    the installed ones, else ones generated here from the definitions above."""
    names = ("Detection2DArray", "Detection2D", "ObjectHypothesisWithPose")
    try:
        import vision_msgs.msg

        return {name: getattr(vision_msgs.msg, name) for name in names}
    except ImportError:
        pass
    import genpy.dynamic
    from geometry_msgs.msg import Pose2D, PoseWithCovariance
    from sensor_msgs.msg import Image
    from std_msgs.msg import Header

    sections = [VISION_MSGS_ROS1["vision_msgs/Detection2DArray"]]
    for name in (
        "vision_msgs/Detection2D",
        "vision_msgs/ObjectHypothesisWithPose",
        "vision_msgs/BoundingBox2D",
    ):
        sections.append("MSG: " + name + "\n" + VISION_MSGS_ROS1[name])
    for cls in (Header, Image, PoseWithCovariance, Pose2D):
        sections.append("MSG: " + cls._type + "\n" + cls._full_text)
    classes = genpy.dynamic.generate_dynamic(
        "vision_msgs/Detection2DArray", SEPARATOR.join(sections)
    )
    return {name: classes["vision_msgs/" + name] for name in names}


def odometry_class() -> type:
    """nav_msgs/Odometry: the installed class, else one generated from its definition
    (the same MD5, so it talks to any ROS 1 node publishing odometry)."""
    try:
        from nav_msgs.msg import Odometry

        return Odometry
    except ImportError:
        pass
    import genpy.dynamic
    from geometry_msgs.msg import PoseWithCovariance, TwistWithCovariance
    from std_msgs.msg import Header

    sections = [ODOMETRY_ROS1]
    for cls in (Header, PoseWithCovariance, TwistWithCovariance):
        sections.append("MSG: " + cls._type + "\n" + cls._full_text)
    classes = genpy.dynamic.generate_dynamic("nav_msgs/Odometry", SEPARATOR.join(sections))
    return classes["nav_msgs/Odometry"]


class Node:
    """The rospy side: subscribers feed the parent, the parent's requests are published."""

    def __init__(self, settings: dict[str, Any], out: IO[str]) -> None:
        import actionlib
        import rospy
        from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
        from move_base_msgs.msg import MoveBaseAction
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import String

        self.rospy = rospy
        self.out = out
        self.out_lock = threading.Lock()
        self.settings = settings
        self.class_names = settings.get("class_names", [])
        topics = settings["topics"]
        rospy.init_node(
            settings.get("node_name", "robocog_bridge"), anonymous=True, disable_signals=True
        )
        self.Twist = Twist
        self.String = String
        self.cmd_vel = rospy.Publisher(topics["cmd_vel"], Twist, queue_size=10)
        self.gripper = rospy.Publisher(topics["gripper_command"], String, queue_size=10)
        rospy.Subscriber(topics["scan"], LaserScan, self.on_scan, queue_size=5)
        rospy.Subscriber(
            topics["detections"], vision_classes()["Detection2DArray"], self.on_boxes, queue_size=5
        )
        rospy.Subscriber(topics["gripper_state"], String, self.on_gripper, queue_size=10)
        rospy.Subscriber(topics["narsese"], String, self.on_text, queue_size=100)
        if topics.get("mission"):
            rospy.Subscriber(topics["mission"], String, self.on_mission, queue_size=10)
        if settings.get("pose_source", "amcl") == "odom":
            rospy.Subscriber(topics["odom"], odometry_class(), self.on_pose_message, queue_size=5)
        else:
            rospy.Subscriber(
                topics["amcl_pose"], PoseWithCovarianceStamped, self.on_pose_message, queue_size=5
            )
        self.client = actionlib.SimpleActionClient(topics["move_base"], MoveBaseAction)
        self.goal_id = None

    # -- to the parent ---------------------------------------------------------------

    def emit(self, obj: dict[str, Any]) -> None:
        """Send one JSON line to the parent (callbacks run on rospy's threads)."""
        line = json.dumps(obj, allow_nan=True)
        with self.out_lock:
            self.out.write(line + "\n")
            self.out.flush()

    def on_scan(self, msg: Any) -> None:
        """A LaserScan; infinite ranges go out as null, which JSON can carry."""
        ranges = [r if math.isfinite(r) else None for r in msg.ranges]
        self.emit(
            {
                "k": "scan",
                "angle_min": msg.angle_min,
                "angle_increment": msg.angle_increment,
                "range_min": msg.range_min,
                "range_max": msg.range_max,
                "ranges": ranges,
                "stamp": msg.header.stamp.to_sec(),
            }
        )

    def on_boxes(self, msg: Any) -> None:
        """A Detection2DArray: each detection's best hypothesis, its class id named."""
        items = []
        for det in msg.detections:
            if not det.results:
                continue
            best = max(det.results, key=lambda r: r.score)
            if 0 <= best.id < len(self.class_names):
                label = self.class_names[best.id]
            else:
                label = str(best.id)
            p = best.pose.pose.position
            items.append(
                {
                    "label": label,
                    "score": best.score,
                    "cx": det.bbox.center.x,
                    "pos": [p.x, p.y, p.z],
                }
            )
        self.emit({"k": "boxes", "items": items, "stamp": msg.header.stamp.to_sec()})

    def on_pose_message(self, msg: Any) -> None:
        """An amcl pose or an odometry message: both carry the pose at ``pose.pose``."""
        self.on_pose(msg.pose.pose)

    def on_pose(self, pose: Any) -> None:
        """A geometry_msgs/Pose: position and orientation quaternion."""
        q = pose.orientation
        self.emit(
            {"k": "pose", "x": pose.position.x, "y": pose.position.y, "q": [q.x, q.y, q.z, q.w]}
        )

    def on_gripper(self, msg: Any) -> None:
        """The gripper's state, as a std_msgs/String."""
        self.emit({"k": "gripper", "text": msg.data})

    def on_text(self, msg: Any) -> None:
        """Text for the mind (Narsese), as a std_msgs/String."""
        self.emit({"k": "text", "text": msg.data})

    def on_mission(self, msg: Any) -> None:
        """The robot's mission state (``ended: WHY`` at its end), as a std_msgs/String."""
        self.emit({"k": "mission", "text": msg.data})

    # -- from the parent -------------------------------------------------------------

    def handle(self, request: dict[str, Any]) -> None:
        """Carry out one request of the parent; an unknown one is reported, not fatal."""
        op = request.get("op")
        if op == "twist":
            twist = self.Twist()
            twist.linear.x = float(request["linear"])
            twist.angular.z = float(request["angular"])
            self.cmd_vel.publish(twist)
        elif op == "gripper":
            self.gripper.publish(self.String(str(request["text"])))
        elif op == "goal":
            self.send_goal(request)
        elif op == "cancel":
            self.client.cancel_all_goals()
        else:
            self.emit({"k": "error", "text": f"unknown request {op!r}"})

    def send_goal(self, request: dict[str, Any]) -> None:
        """Send a move_base goal; its end comes back as a ``goal`` event with its id."""
        from move_base_msgs.msg import MoveBaseGoal

        token = request["id"]
        if not self.client.wait_for_server(self.rospy.Duration(2.0)):
            self.emit(
                {
                    "k": "goal",
                    "id": token,
                    "status": "rejected",
                    "text": "no move_base action server",
                }
            )
            return
        goal = MoveBaseGoal()
        goal.target_pose.header.frame_id = request.get("frame", "map")
        goal.target_pose.header.stamp = self.rospy.Time.now()
        goal.target_pose.pose.position.x = float(request["x"])
        goal.target_pose.pose.position.y = float(request["y"])
        q = request["q"]
        o = goal.target_pose.pose.orientation
        o.x, o.y, o.z, o.w = (float(v) for v in q)

        def done(status: int, _result: Any) -> None:
            self.emit({"k": "goal", "id": token, "status": GOAL_STATUS.get(status, str(status))})

        self.client.send_goal(goal, done_cb=done)


def main() -> int:
    """Read the settings from argv[1], then serve the parent until stdin closes."""
    # The protocol owns the real stdout; anything rospy prints goes to stderr.
    out = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    settings = json.loads(sys.argv[1])
    import rosgraph

    if not rosgraph.is_master_online():
        uri = rosgraph.get_master_uri()
        out.write(json.dumps({"k": "error", "text": f"no ROS master at {uri}"}) + "\n")
        out.flush()
        return 1
    node = Node(settings, out)
    node.emit({"k": "ready"})
    try:
        for line in sys.stdin:
            line = line.strip()
            if not line:
                continue
            try:
                request = json.loads(line)
            except ValueError as exc:
                node.emit({"k": "error", "text": f"bad request: {exc}"})
                continue
            if request.get("op") == "quit":
                break
            try:
                node.handle(request)
            except Exception as exc:  # a bad request must not end the node
                node.emit({"k": "error", "text": f"{type(exc).__name__}: {exc}"})
    finally:
        node.rospy.signal_shutdown("parent closed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
