"""Recordings read by implementations that are not robocog's, and ROS 2's type hashes."""

from __future__ import annotations

import math
import threading
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("cyclonedds", reason="the ROS 2 bridge needs the ros2 extra (cyclonedds)")
pytest.importorskip("mcap_ros2", reason="the recording test needs the ros2 extra (mcap)")
pytest.importorskip("rosbags", reason="the recording test needs the ros2 extra (rosbags)")

from mcap.reader import make_reader  # noqa: E402
from mcap_ros2.decoder import DecoderFactory  # noqa: E402
from rosbags.typesys import Stores, get_types_from_msg, get_typestore  # noqa: E402

from robocog.bridges.body import RobotBody  # noqa: E402
from robocog.bridges.config import BridgeConfig  # noqa: E402
from robocog.bridges.ros2.definitions import DEFINITIONS, schema_text, type_hash  # noqa: E402
from robocog.bridges.ros2.link import Ros2Link  # noqa: E402
from robocog.bridges.ros2.loopback import use_loopback  # noqa: E402
from robocog.bridges.ros2.record import Recorder  # noqa: E402
from robocog.robot import GoTo  # noqa: E402
from tests.bridges.conftest import random_domain  # noqa: E402
from tests.bridges.procs import wait_until  # noqa: E402


def test_type_hashes_are_those_ros2_jazzy_publishes() -> None:
    # geometry_msgs/msg/Twist: the ROS 2 documentation (Jazzy), Tutorials > Beginner: CLI
    # tools > Understanding topics, output of `ros2 topic info /turtle1/cmd_vel --verbose`
    # (ros2/ros2_documentation, source/Tutorials/Beginner-CLI-Tools/
    # Understanding-ROS2-Topics/Understanding-ROS2-Topics.rst: "Topic type hash").
    assert (
        type_hash("geometry_msgs/msg/Twist")
        == "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a"
    )
    # std_msgs/msg/String: the value ROS 2 nodes announce for /chatter, as asserted by
    # roslibrust's test of its ROS 2 hashes (roslibrust_test, "ros2_hash_checks") and by
    # rmw_zenoh's design notes (key expression 0/chatter/std_msgs::msg::dds_::String_/...).
    assert (
        type_hash("std_msgs/msg/String")
        == "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18"
    )


def test_every_standard_hash_agrees_with_the_rosbags_jazzy_typestore() -> None:
    store = get_typestore(Stores.ROS2_JAZZY)
    checked = 0
    for name in DEFINITIONS:
        if name in store.types:
            assert type_hash(name) == store.hash_rihs01(name), name
            checked += 1
    assert checked >= 18


@pytest.fixture
def recording(tmp_path: Path) -> tuple[Path, list[tuple[str, Any]]]:
    """A short run of the served field, recorded by the sim; what was sent is kept."""
    from robocog.sim.ros2 import GarbageRobot
    from robocog.worlds.garbage import GarbageConfig, GarbageField

    use_loopback()
    domain = random_domain()
    path = tmp_path / "run.mcap"
    recorder = Recorder(path)
    sent: list[tuple[str, Any]] = []

    def keep(topic: str, kind: str, message: Any) -> None:
        sent.append((topic, message))
        recorder.write(topic, kind, message)

    world = GarbageField(GarbageConfig(), seed=3)
    robot = GarbageRobot(world, domain, rate=50.0, on_message=keep)
    config = BridgeConfig.preset("garbage")
    body = RobotBody(Ros2Link(config, domain), config).start()
    thread = threading.Thread(target=robot.run, daemon=True)
    thread.start()
    try:
        assert wait_until(lambda: body.scans >= 1, 20)
        assert body.execute(GoTo("next")).ok  # p0, where trash lies in view
        after = robot.frames
        assert wait_until(lambda: robot.frames >= after + 3, 20)
    finally:
        robot.close()
        body.close()
        thread.join(timeout=5)
        recorder.close()
    return path, sent


def _recorded(path: Path) -> dict[str, list[tuple[str, bytes, Any]]]:
    """topic -> [(schema name, raw CDR, message decoded by mcap-ros2-support)]."""
    out: dict[str, list[tuple[str, bytes, Any]]] = {}
    with open(path, "rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for schema, channel, message, decoded in reader.iter_decoded_messages():
            assert channel.message_encoding == "cdr" and schema.encoding == "ros2msg"
            out.setdefault(channel.topic, []).append((schema.name, message.data, decoded))
    return out


def _last(sent: list[tuple[str, Any]], topic: str) -> Any:
    return [msg for t, msg in sent if t == topic][-1]


def test_a_recording_decodes_field_by_field_to_what_was_sent(
    recording: tuple[Path, list[tuple[str, Any]]],
) -> None:
    path, sent = recording
    got = _recorded(path)
    store = get_typestore(Stores.ROS2_JAZZY)

    # the laser scan, by mcap-ros2-support and by rosbags' Jazzy typestore
    schema, raw, scan = got["/scan"][-1]
    mine = _last(sent, "rt/scan")
    assert schema == "sensor_msgs/msg/LaserScan"
    assert (scan.header.stamp.sec, scan.header.stamp.nanosec, scan.header.frame_id) == (
        mine.header.stamp.sec,
        mine.header.stamp.nanosec,
        "base_scan",
    )
    for field in ("angle_min", "angle_max", "angle_increment", "range_min", "range_max"):
        assert getattr(scan, field) == pytest.approx(getattr(mine, field), rel=1e-7)
    assert len(scan.ranges) == len(mine.ranges) == 360
    assert all(
        (math.isinf(a) and math.isinf(b)) or a == pytest.approx(b, rel=1e-6)
        for a, b in zip(scan.ranges, mine.ranges, strict=True)
    )
    other = store.deserialize_cdr(raw, "sensor_msgs/msg/LaserScan")
    assert list(other.ranges[:5]) == pytest.approx(list(scan.ranges[:5]))

    # odometry and tf
    _schema, raw, odom = got["/odom"][-1]
    mine = _last(sent, "rt/odom")
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_link")
    assert (odom.pose.pose.position.x, odom.pose.pose.position.y) == (
        mine.pose.pose.position.x,
        mine.pose.pose.position.y,
    )
    assert odom.pose.pose.orientation.w == mine.pose.pose.orientation.w
    assert list(odom.pose.covariance) == list(mine.pose.covariance)
    assert store.deserialize_cdr(raw, "nav_msgs/msg/Odometry").pose.pose.position.x == (
        mine.pose.pose.position.x
    )
    _schema, raw, tf = got["/tf"][-1]
    mine = _last(sent, "rt/tf")
    assert [(t.header.frame_id, t.child_frame_id) for t in tf.transforms] == [
        ("map", "odom"),
        ("odom", "base_link"),
    ]
    assert tf.transforms[1].transform.translation.x == mine.transforms[1].transform.translation.x
    assert tf.transforms[1].transform.rotation.z == mine.transforms[1].transform.rotation.z
    decoded = store.deserialize_cdr(raw, "tf2_msgs/msg/TFMessage")
    assert decoded.transforms[1].child_frame_id == "base_link"

    # detections: vision_msgs is not in the Jazzy typestore, so rosbags reads its types
    # from the definitions the file carries
    frames = [(s, r, d) for s, r, d in got["/detections"] if d.detections]
    assert frames, "the field shows trash at p0"
    schema, raw, dets = frames[-1]
    sent_dets = [m for t, m in sent if t == "rt/detections" and m.detections]
    mine = sent_dets[-1]
    assert schema == "vision_msgs/msg/Detection2DArray"
    assert len(dets.detections) == len(mine.detections)
    for a, b in zip(dets.detections, mine.detections, strict=True):
        assert a.id == b.id
        assert a.bbox.center.position.x == b.bbox.center.position.x
        assert (a.bbox.size_x, a.bbox.size_y) == (b.bbox.size_x, b.bbox.size_y)
        assert a.results[0].hypothesis.class_id == b.results[0].hypothesis.class_id
        assert a.results[0].hypothesis.score == b.results[0].hypothesis.score
        assert a.results[0].pose.pose.position.x == b.results[0].pose.pose.position.x
    store.register(get_types_from_msg(_without_deps(schema), "vision_msgs/msg/Detection2DArray"))
    store.register(_deps_of(schema))
    other = store.deserialize_cdr(raw, "vision_msgs/msg/Detection2DArray")
    assert other.detections[0].id == mine.detections[0].id

    # the NavigateToPose goal the sim received
    schema, raw, goal = got["/navigate_to_pose/_action/send_goal"][0]
    assert schema == "nav2_msgs/action/NavigateToPose_Goal"
    mine = _last(sent, "rq/navigate_to_pose/_action/send_goalRequest").goal
    assert goal.pose.header.frame_id == "map"
    assert (goal.pose.pose.position.x, goal.pose.pose.position.y) == (
        mine.pose.pose.position.x,
        mine.pose.pose.position.y,
    )
    assert goal.pose.pose.position.x == pytest.approx(4.9896)
    assert goal.pose.pose.orientation.z == mine.pose.pose.orientation.z
    assert goal.behavior_tree == ""


def _without_deps(schema_name: str) -> str:
    return schema_text(schema_name).split("=" * 80)[0]


def _deps_of(schema_name: str) -> dict[str, Any]:
    from robocog.bridges.ros2.definitions import dependencies

    types: dict[str, Any] = {}
    for dep in dependencies(schema_name):
        types.update(get_types_from_msg(_without_deps(dep), dep))
    return types


def test_endpoints_announce_their_type_hash_in_user_data() -> None:
    from cyclonedds.core import Policy

    from robocog.bridges.ros2 import messages as m
    from robocog.bridges.ros2.link import RELIABLE, typed

    qos = typed(RELIABLE, m.Twist)
    [userdata] = [p for p in qos if isinstance(p, Policy.Userdata)]
    assert userdata.data == (
        b"typehash=RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a;"
    )
    assert typed(RELIABLE, m.NavigateToPoseSendGoalRequest) == RELIABLE  # service plumbing
