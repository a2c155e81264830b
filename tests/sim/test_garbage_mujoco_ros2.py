"""The physical garbage field as a ROS 2 robot: a NARS bridge in another process drives it
over DDS on 127.0.0.1 and collects an object, and what the sim sent (camera images and
calibration, the ray-cast lidar, odometry, tf, the arm's joints, the detector's boxes)
decodes with rosbags as the ROS 2 messages it claims to be."""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from robocog.worlds.physics.gl import choose_gl

choose_gl()  # offscreen GL chosen before mujoco loads
pytest.importorskip("cyclonedds", reason="the ROS 2 sim needs the ros2 extra (cyclonedds)")
pytest.importorskip("mujoco", reason="the physics extra (mujoco) is not installed")
pytest.importorskip("sklearn", reason="the physics extra (scikit-learn) is not installed")
pytest.importorskip("rosbags", reason="the recording test needs the ros2 extra (rosbags)")

from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402
from mcap.reader import make_reader  # noqa: E402
from rosbags.typesys import Stores, get_types_from_msg, get_typestore  # noqa: E402

from robocog.bridges.ros2 import messages as m  # noqa: E402
from robocog.bridges.ros2.link import RELIABLE, SENSOR, typed  # noqa: E402
from robocog.bridges.ros2.loopback import LOOPBACK_URI, use_loopback  # noqa: E402
from robocog.bridges.ros2.record import Recorder  # noqa: E402
from robocog.sim.field_mujoco import IMAGE_TOPIC, MujocoGarbageRobot  # noqa: E402
from robocog.worlds.garbage import GarbageConfig  # noqa: E402
from robocog.worlds.mujoco_garbage import MujocoGarbageField  # noqa: E402
from robocog.worlds.physics import trash_detector as td  # noqa: E402
from tests.bridges.conftest import random_domain  # noqa: E402
from tests.bridges.procs import Child, child_env  # noqa: E402

#: wall seconds the bridge gets to collect its first object (it takes about ten)
COLLECT_WITHIN = 45.0


@pytest.fixture(scope="module")
def detector() -> td.TrashDetector:
    """A small detector trained here (seeded) on the renderer's own labels."""
    return td.train(td.TrainingSettings(frames=16, held_out=2, seed=3))[0]


def _decoded(path: Path) -> dict[str, list[Any]]:
    """Every recorded message by topic, decoded by rosbags from the file alone: the
    Jazzy store's types, and those it lacks (vision_msgs) from the schemas in the file."""
    store = get_typestore(Stores.ROS2_JAZZY)
    out: dict[str, list[Any]] = {}
    with open(path, "rb") as stream:
        for schema, channel, message in make_reader(stream).iter_messages():
            if schema.name not in store.fielddefs:
                blocks = schema.data.decode().split("=" * 80 + "\n")
                types = get_types_from_msg(blocks[0], schema.name)
                for block in blocks[1:]:
                    head, _, body = block.partition("\n")
                    types.update(get_types_from_msg(body, head.removeprefix("MSG: ").strip()))
                store.register({k: v for k, v in types.items() if k not in store.fielddefs})
            decoded = store.deserialize_cdr(message.data, schema.name)
            out.setdefault(channel.topic, []).append((schema.name, decoded))
    return out


@pytest.mark.slow
def test_a_nars_bridge_collects_on_the_physical_field_over_dds(
    tmp_path: Path, detector: td.TrashDetector
) -> None:
    use_loopback()
    domain = random_domain()
    world = MujocoGarbageField(GarbageConfig(), seed=3, detector=detector)
    path = tmp_path / "field.mcap"
    recorder = Recorder(path)
    robot = MujocoGarbageRobot(
        world, domain, lockstep=True, max_frames=80, on_message=recorder.write
    )
    # a viewer of the camera, as Foxglove or rviz would be
    dp = DomainParticipant(domain)
    viewer = DataReader(
        dp,
        Topic(dp, m.topic_name(IMAGE_TOPIC), m.Image, qos=RELIABLE),
        qos=typed(SENSOR, m.Image),
    )
    env = child_env({"CYCLONEDDS_URI": LOOPBACK_URI})
    bridge = Child(
        [sys.executable, "-m", "robocog.cli", "bridge", "ros2", "--loopback"]
        + ["--domain", str(domain), "--mind", "nars", "-v"],
        env,
        "bridge",
    )
    started = time.monotonic()
    try:
        # here: the camera renders on the thread that made its GL context
        robot.run(
            until=lambda: (
                world.collected() >= 1
                or time.monotonic() - started > COLLECT_WITHIN
                or bridge.proc.poll() is not None
            )
        )
        seen = viewer.take(8)
    finally:
        robot.close()
        bridge.stop(timeout=30)
        recorder.close()
        world.close()
    said = bridge.stderr_text()
    assert world.collected() >= 1, said[-3000:]
    assert "Pick(target='trash') -> succeeded" in said and "Drop() -> succeeded" in said
    assert seen and len(seen[-1].data) == 640 * 480 * 3

    got = _decoded(path)
    kinds = {topic: items[0][0] for topic, items in got.items()}
    assert kinds["/camera/image_raw"] == "sensor_msgs/msg/Image"
    assert kinds["/camera/camera_info"] == "sensor_msgs/msg/CameraInfo"
    assert kinds["/scan"] == "sensor_msgs/msg/LaserScan"
    assert kinds["/odom"] == "nav_msgs/msg/Odometry"
    assert kinds["/detections"] == "vision_msgs/msg/Detection2DArray"
    # one detection array a frame; a scan may have been sent again while the bridge thought
    assert len(got["/detections"]) == robot.frames >= 3
    assert len(got["/scan"]) >= robot.frames
    image = got["/camera/image_raw"][-1][1]
    assert (image.width, image.height, image.encoding) == (640, 480, "rgb8")
    assert len(image.data) == image.step * image.height == 640 * 480 * 3
    assert image.data.std() > 5  # a picture, not a blank
    info = got["/camera/camera_info"][-1][1]
    # the pinhole of a 60 degree camera 640 pixels wide
    assert info.k[0] == pytest.approx(320 / math.tan(math.radians(30)))
    assert (info.width, info.height, info.k[2], info.k[5]) == (640, 480, 320, 240)
    scan = got["/scan"][-1][1]
    assert len(scan.ranges) == 360
    assert scan.angle_increment == pytest.approx(2 * math.pi / 360)
    assert scan.range_max == pytest.approx(world.physical.lidar_range_max)
    finite = [r for r in scan.ranges if math.isfinite(r)]
    assert finite and all(scan.range_min <= r <= scan.range_max for r in finite)
    # the wheel odometry: from the start corner to the first checkpoint, 5 m on
    first, last = (got["/odom"][i][1].pose.pose.position for i in (0, -1))
    assert (first.x, first.y) == pytest.approx(world.start, abs=0.05)
    assert math.hypot(last.x - first.x, last.y - first.y) > 3.0
    imu = got["/imu/data_raw"][-1][1]
    assert kinds["/imu/data_raw"] == "sensor_msgs/msg/Imu"
    assert imu.orientation_covariance[0] == -1  # no orientation, as REP 145 marks it
    assert imu.linear_acceleration.z == pytest.approx(9.81, abs=0.5)  # standing: gravity
    tf = got["/tf"][-1][1]
    assert [t.child_frame_id for t in tf.transforms] == ["odom", "base_link", "base_scan", "camera"]
    joints = got["/joint_states"][-1][1]
    assert list(joints.name) == ["shoulder", "elbow", "wrist", "finger_left", "finger_right"]
    boxes = [d for _, a in got["/detections"] for d in a.detections]
    assert boxes, "the camera saw the objects at p0"
    for d in boxes:
        assert d.results[0].hypothesis.class_id in ("bottle", "cup")
        assert 0 <= d.bbox.center.position.x <= 640 and 0 <= d.bbox.center.position.y <= 480
        assert 0 < d.bbox.size_x <= 640 and 0 < d.bbox.size_y <= 480
        assert d.id  # the track's name: what a pick may ask for
    assert got["/gripper/grasp/_action/send_goal"]
    assert got["/navigate_to_pose/_action/send_goal"]


def test_the_sim_refuses_a_detector_without_the_physical_field(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from robocog.cli import main

    model = tmp_path / "model.onnx"
    model.write_bytes(b"")
    assert main(["sim", "garbage", "--ros2", "--detector", str(model)]) == 2
    assert main(["sim", "garbage", "--ros1", "--world", "mujoco"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [
        "robocog sim: --detector is for the physical field (--world mujoco)",
        "robocog sim: the physical field is served over ROS 2 (--ros2)",
    ]
