"""``robocog replay FILE.mcap --mind nars|bdi``: a recorded run's percepts fed to a mind.

The recording's sensor messages (``/scan``, ``/detections``, ``/amcl_pose`` or
``/odom``, ``/gripper/state``) go through the same conversion as on a robot (a
``RobotBody``), one decision per scan, and the mind's commands are printed beside the
commands recorded in the same frame (the NavigateToPose and Grasp goals sent before
the next scan). Nothing is executed: a GoTo and a Drop are told they succeeded, a Pick
that it succeeded when the recorded gripper holds something at the next frame, so a
mind that waits for its outcomes carries on as it did in the run.
"""

from __future__ import annotations

import argparse
import logging
import math
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from robocog.argtypes import EXISTING_FILE, SEED
from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.robot.commands import Command, Drop, GoTo, Outcome, Pick

#: the most messages a replay reads (a recording is a file a user hands over)
MAX_MESSAGES = 5_000_000


@dataclass
class Frame:
    """One scan and what came before it, and the commands recorded after it."""

    stamp: float
    readings: list[tuple[str, Any]] = field(default_factory=list)
    recorded: list[Command] = field(default_factory=list)
    holding_after: str | None = None


class _NoLink:
    """A link that sends nothing: a replay only reads."""

    def start(self, body: RobotBody) -> None:
        return

    def close(self) -> None:
        return

    def send_velocity(self, linear: float, angular: float) -> None:
        return

    def send_goal(self, x: float, y: float, yaw: float) -> int:
        return 0

    def cancel_goals(self) -> None:
        return

    def send_gripper(self, text: str) -> int | None:
        return None


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the replay's arguments."""
    parser.add_argument("recording", type=EXISTING_FILE, help="an MCAP file written with --record")
    parser.add_argument("--mind", default="nars", help="nars, bdi or module:factory")
    parser.add_argument("--robot", default="garbage", help="the robot configuration (places)")
    parser.add_argument("--config", type=EXISTING_FILE, help="a TOML bridge configuration instead")
    parser.add_argument("--seed", type=SEED, default=0, help="the mind's seed")
    parser.add_argument("--all", action="store_true", help="print frames without commands too")


def read_frames(path: Path, config: BridgeConfig) -> list[Frame]:
    """The recording cut into frames at each scan, with the commands recorded."""
    from mcap.reader import make_reader

    from robocog.bridges.ros2 import messages as m

    kinds: dict[str, type] = {
        "sensor_msgs/msg/LaserScan": m.LaserScan,
        "vision_msgs/msg/Detection2DArray": m.Detection2DArray,
        "geometry_msgs/msg/PoseWithCovarianceStamped": m.PoseWithCovarianceStamped,
        "nav_msgs/msg/Odometry": m.Odometry,
        "std_msgs/msg/String": m.String,
        "nav2_msgs/action/NavigateToPose_Goal": m.NavigateToPoseGoal,
        "robocog_msgs/action/Grasp_Goal": m.GraspGoal,
    }
    tp = config.topics
    wanted = {
        tp.scan,
        tp.detections,
        tp.gripper_state,
        tp.amcl_pose if config.pose_source == "amcl" else tp.odom,
        tp.navigate_action.rstrip("/") + "/_action/send_goal",
        tp.grasp_action.rstrip("/") + "/_action/send_goal",
    }
    frames: list[Frame] = []
    pending: list[tuple[str, Any]] = []
    with open(path, "rb") as stream:
        reader = make_reader(stream)
        for count, (schema, channel, message) in enumerate(
            reader.iter_messages(log_time_order=True)
        ):
            if count >= MAX_MESSAGES:
                raise ValueError(f"{path}: more than {MAX_MESSAGES} messages")
            if channel.topic not in wanted or schema is None or schema.name not in kinds:
                continue
            try:
                msg = kinds[schema.name].deserialize(message.data)
            except Exception as exc:  # noqa: BLE001 - a damaged record: say which
                raise ValueError(
                    f"{path}: message {count} on {channel.topic} does not decode: {exc}"
                ) from exc
            if schema.name.endswith("_Goal"):
                if frames:
                    frames[-1].recorded.append(_command_of(msg, config))
                continue
            if channel.topic == tp.gripper_state and frames and frames[-1].holding_after is None:
                frames[-1].holding_after = msg.data
            if channel.topic == tp.scan:
                stamp = m.seconds_of(msg.header.stamp)
                if frames and stamp == frames[-1].stamp and not pending:
                    continue  # the same scan sent again (a lock-step sim's resend)
                pending.append((channel.topic, msg))
                frames.append(Frame(stamp, pending))
                pending = []
                continue
            pending.append((channel.topic, msg))
    return frames


def _command_of(goal: Any, config: BridgeConfig) -> Command:
    from robocog.bridges.perception import place_at

    if hasattr(goal, "command"):
        return Pick(goal.target) if goal.command == "pick" else Drop()
    p = goal.pose.pose.position
    place = place_at(p.x, p.y, config.places, config.place_radius)
    if place is None and config.start is not None:
        sx, sy, _ = config.start
        if math.hypot(p.x - sx, p.y - sy) <= config.place_radius:
            place = "start"
    return GoTo(place or f"({p.x:.2f}, {p.y:.2f})")


def feed(body: RobotBody, topic: str, msg: Any) -> None:
    """Hand one recorded message to the body, as the ROS 2 link would."""
    from robocog.bridges.perception import PoseReading, ScanReading, yaw_of
    from robocog.bridges.ros2 import messages as m

    tp = body.config.topics
    if topic == tp.scan:
        body.on_scan(
            ScanReading(
                msg.angle_min, msg.angle_increment, msg.range_min, msg.range_max, list(msg.ranges)
            ),
            m.seconds_of(msg.header.stamp),
        )
    elif topic == tp.detections:
        from robocog.bridges.ros2.link import boxes_of

        body.on_boxes(boxes_of(msg), m.seconds_of(msg.header.stamp))
    elif topic == tp.gripper_state:
        body.on_gripper(msg.data)
    else:
        pose = msg.pose.pose
        q = pose.orientation
        body.on_pose(PoseReading(pose.position.x, pose.position.y, yaw_of(q.x, q.y, q.z, q.w)))


def replay(
    frames: list[Frame], config: BridgeConfig, mind: Any
) -> list[tuple[Frame, list[Command]]]:
    """Each frame's percepts to the mind; its decisions beside the recorded ones."""
    body = RobotBody(_NoLink(), config)
    out = []
    for frame in frames:
        for topic, msg in frame.readings:
            feed(body, topic, msg)
        mind.perceive(body.percepts())
        commands = list(mind.decide())
        for command in commands:
            if isinstance(command, Pick):
                held = (frame.holding_after or "").strip()
                outcome = Outcome.success() if held else Outcome.failure("the gripper stayed empty")
            else:
                outcome = Outcome.success()
            mind.on_outcome(command, outcome)
        out.append((frame, commands))
    return out


def run(args: argparse.Namespace) -> int:
    """Print, frame by frame, the recorded commands and the mind's."""
    from robocog.bridges.cli import MindUnavailable, make_mind

    logging.basicConfig(level=logging.WARNING, stream=sys.stderr)
    try:
        config = (
            BridgeConfig.from_toml(args.config) if args.config else BridgeConfig.preset(args.robot)
        )
        mind = make_mind(args.mind, config, None, args.seed)
    except (ValueError, OSError, MindUnavailable) as exc:
        print(f"robocog replay: {exc}", file=sys.stderr)
        return 2
    try:
        frames = read_frames(args.recording, config)
    except OSError as exc:
        print(f"robocog replay: {exc}", file=sys.stderr)
        return 2
    except Exception as exc:  # noqa: BLE001 - the MCAP reader's errors have no common base
        print(
            f"robocog replay: {args.recording}: not an MCAP recording that can be read "
            f"({type(exc).__name__}: {exc})",
            file=sys.stderr,
        )
        return 2
    same = differ = 0
    print(f"{'frame':>5} {'time':>8}  {'recorded':40} {args.mind}")
    for i, (frame, commands) in enumerate(replay(frames, config, mind)):
        recorded = ", ".join(_show(c) for c in frame.recorded)
        decided = ", ".join(_show(c) for c in commands)
        if recorded or decided or args.all:
            print(f"{i:>5} {frame.stamp:>8.2f}  {recorded or '-':40} {decided or '-'}")
        if frame.recorded or commands:
            if [_kind(c) for c in frame.recorded] == [_kind(c) for c in commands]:
                same += 1
            else:
                differ += 1
    print(f"{len(frames)} frames; frames with commands: {same} alike, {differ} different")
    return 0


def _show(command: Command) -> str:
    match command:
        case GoTo(place):
            return f"GoTo({place})"
        case Pick(target):
            return f"Pick({target})"
        case _:
            return type(command).__name__ + "()"


def _kind(command: Command) -> str:
    """What a command is, without what 'next' or 'trash' resolved to."""
    return type(command).__name__
