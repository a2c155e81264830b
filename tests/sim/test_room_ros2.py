"""The physical Q.bo room as a ROS 2 robot: its sensors arrive, it obeys cmd_vel and the
head command, and its recording decodes with rosbags."""

from __future__ import annotations

import math
import threading
import time
from pathlib import Path
from typing import Any

import pytest

import robocog.worlds.physics  # noqa: F401  (chooses the offscreen GL before mujoco loads)

pytest.importorskip("cyclonedds", reason="the ROS 2 sim needs the ros2 extra (cyclonedds)")
pytest.importorskip("mujoco", reason="the physics extra (mujoco) is not installed")
pytest.importorskip("sklearn", reason="the physics extra (scikit-learn) is not installed")
pytest.importorskip("rosbags", reason="the recording test needs the ros2 extra (rosbags)")

from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402
from mcap.reader import make_reader  # noqa: E402
from rosbags.typesys import Stores, get_typestore  # noqa: E402

from robocog.bridges.ros2 import messages as m  # noqa: E402
from robocog.bridges.ros2.link import RELIABLE, SENSOR, typed  # noqa: E402
from robocog.bridges.ros2.loopback import use_loopback  # noqa: E402
from robocog.bridges.ros2.record import Recorder  # noqa: E402
from robocog.sim.room import TOPICS, QboRoomRobot  # noqa: E402
from robocog.worlds.mujoco_room import MujocoRoom  # noqa: E402
from robocog.worlds.physics import room_vision  # noqa: E402
from tests.bridges.conftest import random_domain  # noqa: E402


@pytest.fixture(scope="module")
def classifier(tmp_path_factory: pytest.TempPathFactory) -> room_vision.AreaClassifier:
    """A classifier trained on fewer renders than the default, cached in a temporary folder."""
    return room_vision.trained(
        seed=3, images=240, test_images=30, directory=tmp_path_factory.mktemp("svm")
    )


def test_the_room_serves_its_sensors_and_obeys_velocity_and_head(
    tmp_path: Path, classifier: room_vision.AreaClassifier
) -> None:
    use_loopback()
    domain = random_domain()
    world = MujocoRoom(2, classifier=classifier, start=(1.0, 2.0, 0.0))
    path = tmp_path / "room.mcap"
    recorder = Recorder(path)
    robot = QboRoomRobot(world, domain, rate=8.0, on_message=recorder.write)
    dp = DomainParticipant(domain)

    def reader(key: str, kind: type, qos: Any) -> DataReader:
        topic = Topic(dp, m.topic_name(TOPICS[key]), kind, qos=RELIABLE)
        return DataReader(dp, topic, qos=typed(qos, kind))

    def writer(key: str, kind: type) -> DataWriter:
        topic = Topic(dp, m.topic_name(TOPICS[key]), kind, qos=RELIABLE)
        return DataWriter(dp, topic, qos=typed(RELIABLE, kind))

    ranges = reader("us_left", m.Range, SENSOR)
    images = reader("image", m.Image, SENSOR)
    odom = reader("odom", m.Odometry, RELIABLE)
    joints = reader("joints", m.JointState, RELIABLE)
    cmd = writer("cmd_vel", m.Twist)
    head = writer("head", m.Float64)
    got: dict[str, Any] = {}
    done = threading.Event()

    def controller() -> None:
        try:
            start = time.monotonic()
            while time.monotonic() - start < 3.0:
                cmd.write(m.Twist(m.Vector3(x=0.15), m.Vector3()))
                head.write(m.Float64(0.5))
                for sample in odom.take(16):
                    got.setdefault("first_x", sample.pose.pose.position.x)
                    got["x"] = sample.pose.pose.position.x
                for sample in joints.take(16):
                    got["pan"] = dict(zip(sample.name, sample.position, strict=True))["head_pan"]
                time.sleep(0.05)
            got["ranges"] = ranges.take(16)
            got["images"] = images.take(16)
        finally:
            done.set()

    thread = threading.Thread(target=controller, daemon=True)
    thread.start()
    try:
        robot.run(until=done.is_set)  # here: the camera renders on the thread that made it
    finally:
        robot.close()
        thread.join(timeout=5)
        recorder.close()
        world.close()
    assert got["ranges"] and all(0.0 < r.range <= 1.5 for r in got["ranges"])
    assert got["ranges"][-1].radiation_type == m.ULTRASOUND
    image = got["images"][-1]
    assert (image.width, image.height, image.encoding) == (96, 64, "rgb8")
    assert len(image.data) == image.step * image.height == 96 * 64 * 3
    # forward at 0.15 m/s for several simulated seconds, by the wheel odometry
    assert got["x"] - got["first_x"] > 0.5
    assert got["pan"] == pytest.approx(0.5, abs=0.05)

    store = get_typestore(Stores.ROS2_JAZZY)
    decoded: dict[str, Any] = {}
    with open(path, "rb") as stream:
        for schema, channel, message in make_reader(stream).iter_messages():
            decoded[channel.topic] = store.deserialize_cdr(message.data, schema.name)
    assert decoded["/range/us_right"].max_range == pytest.approx(1.5)
    assert len(decoded["/camera/image_raw"].data) == 96 * 64 * 3
    assert math.isfinite(decoded["/odom"].pose.pose.position.x)


def test_the_bridges_qbo_body_looks_and_stops_over_dds(
    classifier: room_vision.AreaClassifier,
) -> None:
    """The bridge's Q.bo body on the served room: a look finds the door in the image
    that faces it, and a forward stops on the ultrasonic sensors before a wall."""
    from robocog.bridges.qbo import QboRos2Body
    from robocog.robot.commands import Forward, Look, Turn

    use_loopback()
    domain = random_domain()
    # at (3.0, 2.5) the open leaf (80 degrees) lies about 28 degrees left of east
    world = MujocoRoom(
        4, classifier=classifier, start=(3.0, 2.5, math.radians(28.0)), door_open_degrees=80.0
    )
    robot = QboRoomRobot(world, domain, rate=6.0)
    body = QboRos2Body(domain, vision=room_vision, classifier=classifier).start()
    got: dict[str, Any] = {}
    done = threading.Event()

    def bridge() -> None:
        try:
            start = time.monotonic()
            while body.stale() is not None and time.monotonic() - start < 20:
                time.sleep(0.05)
            got["look"] = body.execute(Look("around"))
            got["doors"] = [p for p in body.percepts() if getattr(p, "label", None) == "door"]
            got["turn"] = body.execute(Turn(-math.radians(118.0)))  # to face south
            got["forward"] = body.execute(Forward(4.0))
        finally:
            done.set()

    thread = threading.Thread(target=bridge, daemon=True)
    thread.start()
    try:
        robot.run(until=done.is_set)
    finally:
        robot.close()
        body.close()
        thread.join(timeout=5)
    try:
        assert got["look"].ok
        best = max(got["doors"], key=lambda d: d.confidence)
        assert best.instance is not None and best.instance.startswith("front:")
        assert got["turn"].ok
        assert not got["forward"].ok and got["forward"].reason == "obstacle ahead"
        assert 0.3 < world.y < 0.75  # stopped short of the south wall, not against it
    finally:
        world.close()
