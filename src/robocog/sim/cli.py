"""``robocog sim garbage --ros2|--ros1``: an embedded world served as a ROS robot.

``robocog sim tabletop --physics`` runs the physical tabletop on its own instead (see
:mod:`robocog.sim.tabletop`); ``robocog sim room --world mujoco --ros2`` serves the
physical Q.bo room (:mod:`robocog.sim.room`), ``robocog sim garbage --world mujoco
--ros2`` the physical garbage field (:mod:`robocog.sim.field_mujoco`: camera images,
the learned detector's boxes, the ray-cast lidar, the arm's joints).

Run it in one terminal and ``robocog bridge ros2 --loopback --mind nars`` (or ``bdi``)
in another; any ROS 2 node on rmw_cyclonedds in the same domain sees the robot too.
With ``--ros1`` the field is a rospy node (run by the Python that has rospy) serving
move_base through actionlib, for ``robocog bridge ros1`` and a roscore.
"""

from __future__ import annotations

import argparse
import logging
import os
import signal
import sys
from pathlib import Path
from typing import Any

from robocog.argtypes import (
    DDS_DOMAIN,
    EXISTING_FILE,
    EXISTING_FILE_STR,
    NEW_DIR_STR,
    NEW_FILE,
    SEED,
    FloatRange,
    positive_int,
)
from robocog.signals import handling

WORLDS = ("garbage", "tabletop", "room")


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the simulator's arguments."""
    from robocog.worlds.garbage import LIGHTS

    parser.add_argument("world", choices=WORLDS, help="which embedded world to serve")
    parser.add_argument(
        "--world",
        dest="world_kind",
        choices=("2d", "mujoco"),
        default=None,
        help="garbage: 2d, the field of probability tables (default), or mujoco, the "
        "physical field (camera, learned detector, lidar, arm; the physics extra); "
        "room: mujoco, the only one served",
    )
    parser.add_argument("--ros2", action="store_true", help="serve it over ROS 2 (Cyclone DDS)")
    parser.add_argument(
        "--ros1", action="store_true", help="serve it over ROS 1 (rospy, move_base; a roscore)"
    )
    parser.add_argument(
        "--ros1-python",
        type=EXISTING_FILE_STR,
        default="/usr/bin/python3",
        help="ROS 1: the Python that has rospy (default /usr/bin/python3)",
    )
    parser.add_argument(
        "--loopback",
        action="store_true",
        help="keep DDS traffic on 127.0.0.1 (unless CYCLONEDDS_URI is set)",
    )
    parser.add_argument(
        "--domain", type=DDS_DOMAIN, help="the DDS domain (default ROS_DOMAIN_ID or 0)"
    )
    parser.add_argument("--namespace", default="", help="prefix of every topic and action")
    parser.add_argument("--seed", type=SEED, default=0, help="the field's seed (default 0)")
    parser.add_argument("--light", choices=LIGHTS, default="sunny", help="lighting")
    parser.add_argument(
        "--rate",
        type=FloatRange(0.0, 1000.0, "x real time", lo_open=True),
        default=1.0,
        help="simulated seconds per wall second (default 1: real time)",
    )
    parser.add_argument(
        "--lockstep",
        action="store_true",
        help="publish a frame, then wait for the controller's /sim/frame_done",
    )
    parser.add_argument("--record", type=NEW_FILE, metavar="FILE.mcap", help="record every message")
    parser.add_argument("--max-frames", type=positive_int(), help="end after this many frames")
    parser.add_argument("-v", "--verbose", action="store_true", help="log more")
    garbage = parser.add_argument_group("garbage")
    garbage.add_argument(
        "--detector",
        type=EXISTING_FILE,
        metavar="MODEL.onnx",
        help="garbage --world mujoco: a YOLO model in ONNX (run by onnxruntime) in place of "
        "the learned detector",
    )
    tabletop = parser.add_argument_group("tabletop")
    tabletop.add_argument(
        "--physics", action="store_true", help="tabletop: the MuJoCo arm, cameras and tags"
    )
    tabletop.add_argument(
        "--do",
        default=None,
        metavar="SCRIPT",
        help="tabletop: commands such as 'PickUp A; Stack A B' (default: Table 5.2's plan)",
    )
    tabletop.add_argument(
        "--perturb", action="store_true", help="tabletop: move a cube by hand halfway through"
    )
    tabletop.add_argument("--no-video", action="store_true", help="tabletop: no GIF or frame")
    tabletop.add_argument(
        "--out",
        type=NEW_DIR_STR,
        default="reports/sim_tabletop",
        metavar="DIR",
        help="tabletop: film folder",
    )


def run(args: argparse.Namespace) -> int:
    """Serve the world until its mission ends or the process is stopped."""
    if args.world == "room":
        try:
            from robocog.sim.room import run_room
        except ImportError as exc:
            print(f"robocog sim room: needs the physics and ros2 extras ({exc})", file=sys.stderr)
            return 2
        return run_room(args)
    if args.world == "tabletop":
        from robocog.sim.tabletop import DEFAULT_SCRIPT, run_tabletop

        if args.do is None:
            args.do = DEFAULT_SCRIPT
        return run_tabletop(args)
    logging.basicConfig(
        level=logging.DEBUG if args.verbose else logging.INFO,
        format="%(asctime)s %(levelname)s %(name)s: %(message)s",
        stream=sys.stderr,
    )
    logging.getLogger("OpenGL").setLevel(logging.WARNING)  # its INFO line on every start
    if args.ros2 == args.ros1:
        print("robocog sim: choose one middleware (--ros2 or --ros1)", file=sys.stderr)
        return 2
    physical = args.world_kind == "mujoco"
    if args.detector is not None and not physical:
        print("robocog sim: --detector is for the physical field (--world mujoco)", file=sys.stderr)
        return 2
    if args.ros1:
        if physical:
            print("robocog sim: the physical field is served over ROS 2 (--ros2)", file=sys.stderr)
            return 2
        return run_ros1(args)
    if args.loopback:
        from robocog.bridges.ros2.loopback import loopback_unless_configured

        loopback_unless_configured()
    try:
        from robocog.sim.ros2 import GarbageRobot
    except ImportError as exc:
        print(f"robocog sim: ROS 2 needs the ros2 extra ({exc})", file=sys.stderr)
        return 2
    from robocog.worlds.garbage import GarbageConfig, GarbageField

    domain = args.domain if args.domain is not None else int(os.environ.get("ROS_DOMAIN_ID", "0"))
    config = GarbageConfig(light=args.light)
    if physical:
        made = _physical_field(args, config)
        if isinstance(made, str):
            print(f"robocog sim: {made}", file=sys.stderr)
            return 2
        world, serve = made
    else:
        world, serve = GarbageField(config, seed=args.seed), GarbageRobot
    recorder: Any = None
    if args.record is not None:
        from robocog.bridges.ros2.record import Recorder

        recorder = Recorder(args.record)
    robot = serve(
        world,
        domain,
        rate=args.rate,
        lockstep=args.lockstep,
        namespace=args.namespace,
        max_frames=args.max_frames,
        on_message=recorder.write if recorder is not None else None,
    )

    def _terminate(_signum: int, _frame: object) -> None:
        robot.stop()

    mission = world.config.mission_time
    pace = (
        "as fast as the controller answers (--lockstep)"
        if args.lockstep
        else f"about {mission / args.rate:.0f} s of wall time at --rate {args.rate:g}"
    )
    kind = "the physical garbage field (MuJoCo)" if physical else "garbage field"
    print(
        f"robocog sim: {kind} (seed {args.seed}, {args.light}) on ROS 2 domain {domain}"
        f"{' (loopback)' if args.loopback else ''}; {len(world.objects())} objects; serving "
        f"until the mission's {mission:.0f} simulated seconds are over ({pace}) or Ctrl-C",
        file=sys.stderr,
        flush=True,
    )
    try:
        with handling(signal.SIGTERM, _terminate):
            robot.run()
    except KeyboardInterrupt:
        pass
    finally:
        robot.close()
        release = getattr(world, "close", None)
        if release is not None:
            release()  # the camera's GL context
        if recorder is not None:
            recorder.close()
    print(
        f"robocog sim: collected {world.collected()} of {len(world.objects())} objects in "
        f"{world.time():.0f} simulated seconds ({robot.frames} frames, {robot.goals} goals)",
        flush=True,
    )
    return 0


def _physical_field(args: argparse.Namespace, config: Any) -> tuple[Any, Any] | str:
    """The physical field of ``args`` and the robot class that serves it, or why not."""
    try:
        from robocog.sim.field_mujoco import MujocoGarbageRobot
        from robocog.worlds.mujoco_garbage import MujocoGarbageField
        from robocog.worlds.physics.onnx_detector import camera_detector
    except ImportError as exc:
        return f"--world mujoco needs the physics extra ({exc})"
    say = lambda text: print(f"robocog sim: {text}", file=sys.stderr, flush=True)  # noqa: E731
    try:
        detector, report = camera_detector(args.detector, say)
    except ImportError as exc:
        return f"--detector needs onnxruntime ({exc})"
    except ValueError as exc:
        return f"--detector {exc}"
    if report is not None:
        say(
            f"detector: recall {report.recall:.1%}, labels {report.label_accuracy:.1%} on "
            f"{report.frames} held-out renders"
        )
    return MujocoGarbageField(config, args.seed, detector=detector), MujocoGarbageRobot


def run_ros1(args: argparse.Namespace) -> int:
    """Serve the field as a rospy node under the Python that has rospy, until the
    mission is over or this process is stopped; the node prints what was collected."""
    import subprocess
    import tempfile

    import robocog

    if args.lockstep or args.record is not None or args.namespace:
        print("robocog sim: --lockstep, --record and --namespace are for ROS 2", file=sys.stderr)
        return 2
    if not Path(args.ros1_python).exists():
        print(f"robocog sim: {args.ros1_python} is missing (ROS 1 needs rospy)", file=sys.stderr)
        return 2
    check = subprocess.run(
        [args.ros1_python, "-c", "import rosgraph, sys; sys.exit(not rosgraph.is_master_online())"],
        capture_output=True,
        text=True,
        env=_ros1_env(None),
    )
    if check.returncode != 0:
        uri = os.environ.get("ROS_MASTER_URI", "http://localhost:11311")
        reason = check.stderr.strip().splitlines()[-1:] or [f"no ROS master at {uri}"]
        print(f"robocog sim: {reason[0]}", file=sys.stderr)
        return 2
    package = Path(robocog.__file__).resolve().parent
    with tempfile.TemporaryDirectory(prefix="robocog-ros1-") as path:
        # robocog alone on the other Python's path: not the site-packages it was installed
        # in, whose compiled modules belong to this Python
        (Path(path) / "robocog").symlink_to(package, target_is_directory=True)
        argv = [
            args.ros1_python,
            str(package / "sim" / "ros1_node.py"),
            "--seed",
            str(args.seed),
            "--light",
            args.light,
            "--rate",
            str(args.rate),
        ]
        node = subprocess.Popen(argv, env=_ros1_env(path))
        try:
            with handling(signal.SIGTERM, lambda _signum, _frame: node.terminate()):
                return node.wait()
        except KeyboardInterrupt:
            node.send_signal(signal.SIGINT)
            return node.wait()
        finally:
            if node.poll() is None:
                node.terminate()
                node.wait()


def _ros1_env(path: str | None) -> dict[str, str]:
    """This environment for the other Python: its own path, robocog's folder when given."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    if path is not None:
        env["PYTHONPATH"] = path
    env["PYTHONUNBUFFERED"] = "1"
    return env
