"""The ROS 2 link in one process: every topic, renamed topics, odometry, and requests."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

pytest.importorskip("cyclonedds", reason="the ROS 2 bridge needs the ros2 extra (cyclonedds)")

from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402

from robocog.bridges.body import RobotBody  # noqa: E402
from robocog.bridges.config import BridgeConfig, Topics  # noqa: E402
from robocog.bridges.ros2 import messages as m  # noqa: E402
from robocog.bridges.ros2.link import RELIABLE, Ros2Link  # noqa: E402
from robocog.bridges.ros2.loopback import use_loopback  # noqa: E402
from robocog.robot import Detection, Gripper, Obstacle, Pick, Pose, Turn  # noqa: E402
from robocog.testing.ros2_standin import StandInRobot  # noqa: E402
from tests.bridges.conftest import random_domain  # noqa: E402
from tests.bridges.procs import wait_until  # noqa: E402

RENAMED = Topics(
    scan="/robot1/front/scan",
    detections="/robot1/detections",
    amcl_pose="/robot1/amcl_pose",
    cmd_vel="/robot1/cmd_vel",
    goal_pose="/robot1/goal_pose",
    gripper_state="/robot1/gripper/state",
    gripper_command="/robot1/gripper/command",
    narsese="/robot1/narsese",
    navigate_action="/robot1/navigate_to_pose",
)


@pytest.fixture
def domain() -> int:
    use_loopback()  # this process's participants stay on 127.0.0.1
    return random_domain()


@pytest.fixture
def pair(domain: int) -> Iterator[tuple[RobotBody, StandInRobot]]:
    config = BridgeConfig(
        topics=RENAMED,
        places={"bin": (2.0, 1.0, 0.0)},
        angular_speed=10.0,
        gripper_timeout=5.0,
    )
    robot = StandInRobot(domain, topics=RENAMED).start(rate=20.0)
    body = RobotBody(Ros2Link(config, domain), config).start()
    try:
        yield body, robot
    finally:
        body.close()
        robot.close()


def test_renamed_topics_carry_every_percept(pair: tuple[RobotBody, StandInRobot]) -> None:
    body, robot = pair
    robot.update(
        {
            "obstacle": [-1.0, 0.6],
            "detections": [{"label": "cup", "x": 480, "score": 0.7}],
            "pose": [2.1, 1.0, 0.5],
            "holding": "bottle",
        }
    )

    def complete() -> bool:
        kinds = {type(p) for p in body.percepts()}
        return {Obstacle, Detection, Pose} <= kinds

    assert wait_until(complete, 20)
    assert wait_until(lambda: Gripper("bottle") in body.percepts(), 5)
    percepts = body.percepts()
    [obstacle] = [p for p in percepts if isinstance(p, Obstacle)]
    assert obstacle.sector == "right" and obstacle.distance == pytest.approx(0.6)
    [seen] = [p for p in percepts if isinstance(p, Detection)]
    assert seen.label == "cup" and seen.bearing < 0 and seen.confidence == pytest.approx(0.7)
    [pose] = [p for p in percepts if isinstance(p, Pose)]
    assert (pose.place, pose.theta) == ("bin", pytest.approx(0.5))

    robot.update({"narsese": "<a --> b>."})
    assert wait_until(lambda: body.texts() == ["<a --> b>."], 5)


def test_requests_reach_the_robot_on_renamed_topics(
    pair: tuple[RobotBody, StandInRobot],
) -> None:
    body, robot = pair
    assert wait_until(lambda: body.percept_age() < 1.0, 20)
    assert body.execute(Turn(0.5)).ok
    assert body.execute(Pick("cup")).ok  # the stand-in's gripper reports the cup
    body.stop()
    assert wait_until(lambda: any(e["event"] == "cancel" for e in robot.events), 5)
    twists = [(e["linear"], e["angular"]) for e in robot.events if e["event"] == "cmd_vel"]
    assert (0.0, 10.0) in twists and twists[-1] == (0.0, 0.0)
    assert [e["text"] for e in robot.events if e["event"] == "gripper"] == ["pick cup"]


def test_odometry_gives_the_pose_when_configured(domain: int) -> None:
    config = BridgeConfig(pose_source="odom", topics=Topics(odom="/wheel/odom"))
    body = RobotBody(Ros2Link(config, domain + 1), config).start()
    dp = DomainParticipant(domain + 1)
    writer = DataWriter(dp, Topic(dp, "rt/wheel/odom", m.Odometry, qos=RELIABLE), qos=RELIABLE)
    odom = m.Odometry(m.Header(frame_id="odom"), "base_link")
    odom.pose.pose.position.x = 3.0
    odom.pose.pose.orientation = m.Quaternion(0.0, 0.0, math.sin(0.4), math.cos(0.4))
    try:

        def seen() -> bool:
            writer.write(odom)
            return any(isinstance(p, Pose) for p in body.percepts())

        assert wait_until(seen, 20, step=0.1)
        [pose] = [p for p in body.percepts() if isinstance(p, Pose)]
        assert (pose.x, pose.theta) == (3.0, pytest.approx(0.8))
    finally:
        body.close()


def test_an_unknown_pose_source_is_refused(domain: int) -> None:
    with pytest.raises(ValueError, match="pose_source"):  # by the configuration itself
        BridgeConfig(pose_source="gps")
    # and by the link, should a configuration get by
    config = BridgeConfig()
    object.__setattr__(config, "pose_source", "gps")
    link = Ros2Link(config, domain + 2)
    with pytest.raises(ValueError, match="pose_source"):
        RobotBody(link).start()
    link.close()
