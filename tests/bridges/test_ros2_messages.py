"""The ROS 2 wire layouts: type names, topic names and the plain-CDR bytes that
rmw_cyclonedds reads and writes."""

from __future__ import annotations

import struct

import pytest

pytest.importorskip("cyclonedds", reason="the ROS 2 bridge needs the ros2 extra (cyclonedds)")

from robocog.bridges.ros2 import messages as m  # noqa: E402

CDR_LE = b"\x00\x01\x00\x00"


def cdr(message: object) -> bytes:
    return message.serialize(use_version_2=False)  # type: ignore[attr-defined]


def ros_string(text: str, offset: int) -> tuple[bytes, int]:
    """A CDR string at ``offset`` (4-aligned): length with NUL, bytes, NUL."""
    pad = (-offset) % 4
    data = b"\x00" * pad + struct.pack("<I", len(text) + 1) + text.encode() + b"\x00"
    return data, offset + len(data)


def align(offset: int, n: int) -> bytes:
    return b"\x00" * ((-offset) % n)


@pytest.mark.parametrize(
    ("kind", "name"),
    [
        (m.String, "std_msgs::msg::dds_::String_"),
        (m.Header, "std_msgs::msg::dds_::Header_"),
        (m.Time, "builtin_interfaces::msg::dds_::Time_"),
        (m.LaserScan, "sensor_msgs::msg::dds_::LaserScan_"),
        (m.Twist, "geometry_msgs::msg::dds_::Twist_"),
        (m.PoseStamped, "geometry_msgs::msg::dds_::PoseStamped_"),
        (m.PoseWithCovarianceStamped, "geometry_msgs::msg::dds_::PoseWithCovarianceStamped_"),
        (m.Odometry, "nav_msgs::msg::dds_::Odometry_"),
        (m.Detection2DArray, "vision_msgs::msg::dds_::Detection2DArray_"),
        (m.CancelGoalRequest, "action_msgs::srv::dds_::CancelGoal_Request_"),
    ],
)
def test_type_names_are_the_ros2_ones(kind: type, name: str) -> None:
    assert kind.__idl_typename__ == name  # type: ignore[attr-defined]


def test_topic_names_take_the_ros2_prefixes() -> None:
    assert m.topic_name("/scan") == "rt/scan"
    assert m.topic_name("robot1/cmd_vel") == "rt/robot1/cmd_vel"
    assert m.topic_name("/navigate_to_pose/_action/cancel_goal", "rq") == (
        "rq/navigate_to_pose/_action/cancel_goal"
    )
    for bad in ("", "~/private", "/a//b"):
        with pytest.raises(ValueError):
            m.topic_name(bad)


def test_string_and_twist_bytes() -> None:
    assert cdr(m.String("hi")) == CDR_LE + struct.pack("<I", 3) + b"hi\x00"
    twist = m.Twist(m.Vector3(0.5, 0.0, 0.0), m.Vector3(0.0, 0.0, -1.25))
    assert cdr(twist) == CDR_LE + struct.pack("<6d", 0.5, 0, 0, 0, 0, -1.25)


def test_pose_stamped_aligns_doubles_to_eight_after_the_frame_id() -> None:
    msg = m.PoseStamped(
        m.Header(m.Time(5, 7), "base"),
        m.Pose(m.Point(1.0, 2.0, 0.0), m.Quaternion(0.0, 0.0, 0.6, 0.8)),
    )
    body = struct.pack("<iI", 5, 7)
    frame, offset = ros_string("base", len(body))
    body += frame
    body += align(offset, 8) + struct.pack("<7d", 1.0, 2.0, 0.0, 0.0, 0.0, 0.6, 0.8)
    assert cdr(msg) == CDR_LE + body


def test_laser_scan_bytes() -> None:
    msg = m.LaserScan(m.Header(m.Time(1, 2), "laser"), -1.5, 1.5, 0.5, 0.0, 0.1, 0.05, 8.0)
    msg.ranges = [1.0, 2.0]
    body = struct.pack("<iI", 1, 2)
    frame, offset = ros_string("laser", len(body))
    body += frame + align(offset, 4)
    body += struct.pack("<7f", -1.5, 1.5, 0.5, 0.0, 0.1, 0.05, 8.0)
    body += struct.pack("<I2f", 2, 1.0, 2.0) + struct.pack("<I", 0)
    assert cdr(msg) == CDR_LE + body


def test_cancel_request_is_the_request_header_then_a_zero_goal() -> None:
    msg = m.CancelGoalRequest(client_guid=0x0102, sequence_number=3)
    expected = struct.pack("<Qq", 0x0102, 3) + bytes(16) + struct.pack("<iI", 0, 0)
    assert cdr(msg) == CDR_LE + expected


def test_detections_round_trip() -> None:
    hypothesis = m.ObjectHypothesisWithPose(m.ObjectHypothesis("bottle", 0.75))
    box = m.BoundingBox2D(m.Pose2D(m.Point2D(100.0, 50.0), 0.0), 20.0, 40.0)
    array = m.Detection2DArray(
        m.Header(m.Time(3, 4), "camera"), [m.Detection2D(m.Header(), [hypothesis], box, "b1")]
    )
    back = m.Detection2DArray.deserialize(cdr(array))
    assert back == array
    assert back.detections[0].results[0].hypothesis.class_id == "bottle"


def test_stamps_split_seconds_and_nanoseconds() -> None:
    stamp = m.stamp_now(12.25)
    assert (stamp.sec, stamp.nanosec) == (12, 250_000_000)
