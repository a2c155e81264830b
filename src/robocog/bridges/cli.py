"""``robocog bridge ros2|ros1 --mind nars|bdi``: drive a real robot with a robocog mind.

The bridge itself knows no engine. The mind is made by name through the minds'
registry (:mod:`robocog.minds.registry`: ``nars``, ``bdi``, the other shipped minds, or
any ``module:factory``), which imports a mind's engine only when that mind is made, so
the Body code in this package never imports an engine.
"""

from __future__ import annotations

import argparse
import importlib
import logging
import math
import signal
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

from robocog.argtypes import DDS_DOMAIN, EXISTING_FILE, EXISTING_FILE_STR, NEW_FILE, SEED, seconds
from robocog.bridges.config import BridgeConfig, Topics
from robocog.minds.registry import MindConfig, MindUnavailable, make, names
from robocog.robot.protocols import Mind
from robocog.signals import handling

log = logging.getLogger("robocog.bridges")


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the bridge's arguments."""
    parser.add_argument("middleware", choices=("ros2", "ros1"), help="which ROS the robot runs")
    parser.add_argument(
        "--mind",
        default="nars",
        help=f"{', '.join(names())}, or module:factory for a mind of your own "
        "(called with a robocog.minds.registry.MindConfig) (default: nars)",
    )
    parser.add_argument("--knowledge", type=EXISTING_FILE, help="Narsese file given to a NARS mind")
    parser.add_argument(
        "--program", type=EXISTING_FILE, help="AgentSpeak (.asl) program of a BDI mind"
    )
    parser.add_argument(
        "--config", type=EXISTING_FILE, help="TOML file: topics, places, speeds, limits"
    )
    parser.add_argument(
        "--robot",
        help="a robot configuration shipped with robocog (default: garbage, the field "
        "`robocog sim garbage --ros2` serves, when neither --config nor --place is given)",
    )
    parser.add_argument(
        "--place",
        action="append",
        default=[],
        metavar="NAME=X,Y[,THETA]",
        help="a named place in the map frame (repeatable)",
    )
    parser.add_argument(
        "--topic",
        action="append",
        default=[],
        metavar="KEY=NAME",
        help="rename a topic, e.g. scan=/front/scan (repeatable)",
    )
    parser.add_argument(
        "--watchdog", type=seconds(), help="stop the robot after this many seconds without percepts"
    )
    parser.add_argument(
        "--goto-timeout",
        type=seconds(),
        help="seconds a GoTo waits for the navigation result before it cancels and fails",
    )
    parser.add_argument("--seed", type=SEED, default=0, help="the mind's seed (default 0)")
    parser.add_argument(
        "--lockstep",
        action="store_true",
        help="decide once per scan and acknowledge it on /sim/frame_done (a lock-step sim)",
    )
    parser.add_argument("--namespace", default="", help="prefix of every topic and action")
    parser.add_argument("--record", type=NEW_FILE, metavar="FILE.mcap", help="record every message")
    parser.add_argument("--duration", type=seconds(), help="end after this many seconds")
    parser.add_argument(
        "--domain", type=DDS_DOMAIN, help="ROS 2: the DDS domain (default ROS_DOMAIN_ID or 0)"
    )
    parser.add_argument(
        "--loopback",
        action="store_true",
        help="ROS 2: keep DDS traffic on 127.0.0.1 (unless CYCLONEDDS_URI is set)",
    )
    parser.add_argument(
        "--ros1-python",
        type=EXISTING_FILE_STR,
        default="/usr/bin/python3",
        help="ROS 1: the Python that has rospy (default /usr/bin/python3)",
    )
    # by name, as the minds are: the inspector reads minds, and the bridges know none
    importlib.import_module("robocog.inspector.cli").add_arguments(parser)
    parser.add_argument("-v", "--verbose", action="store_true", help="log every command")


def run(args: argparse.Namespace) -> int:
    """Build the mind and the body, and run until interrupted, ``--duration`` ends or the
    robot ends its mission (``ended: WHY`` on its mission topic)."""
    logging.basicConfig(
        level=logging.DEBUG if args.verbose else logging.INFO,
        format="%(asctime)s %(levelname)s %(name)s: %(message)s",
        stream=sys.stderr,
    )
    try:
        config = build_config(args)
        mind = make_mind(args.mind, config, args.knowledge or args.program, args.seed)
    except (MindUnavailable, ValueError, OSError) as exc:
        print(f"robocog bridge: {exc}", file=sys.stderr)
        return 2
    from robocog.bridges.body import RobotBody
    from robocog.bridges.runner import BridgeRunner

    try:
        if args.mind == "qbo" and args.middleware == "ros2":
            body: Any = _qbo_body(args, config)
        else:
            body = RobotBody(_make_link(args, config), config)
    except ImportError as exc:
        print(f"robocog bridge: {exc}", file=sys.stderr)
        return 2
    runner = BridgeRunner(body, mind)

    def _terminate(_signum: int, _frame: object) -> None:
        runner.stop()

    inspector_cli = importlib.import_module("robocog.inspector.cli")
    args.inspect_exit = True  # the page closes with the bridge: its robot is stopped then
    try:
        with (
            handling(signal.SIGTERM, _terminate),
            inspector_cli.session(args, f"robocog bridge {args.middleware}") as inspecting,
        ):
            if inspecting is not None:
                label = f"{args.middleware} bridge, mind {args.mind}"
                runner.on_cycle = inspecting.watch(body, mind, runner, label)
            body.start()
            log.info("bridge %s up, mind %s", args.middleware, args.mind)
            code = runner.run(duration=args.duration)
    except KeyboardInterrupt:
        code = 0
    except (RuntimeError, OSError) as exc:
        print(f"robocog bridge: {exc}", file=sys.stderr)
        code = 1
    finally:
        body.close()
    if runner.mission_ended is not None:
        print(
            f"robocog bridge: the robot ended its mission ({runner.mission_ended}); "
            f"the bridge ends after {runner.cycles} cycles",
            file=sys.stderr,
        )
    summary = runner.stats.summary()
    log.info(
        "%d cycles, mind p50 %.2f ms, p99 %.2f ms",
        runner.cycles,
        summary["reason_p50_ms"],
        summary["reason_p99_ms"],
    )
    return code


def _ros2_setup(args: argparse.Namespace) -> None:
    """What every ROS 2 body needs first: loopback if asked, and cyclonedds (a one-line
    error without it)."""
    if args.loopback:
        from robocog.bridges.ros2.loopback import loopback_unless_configured

        loopback_unless_configured()
    try:
        importlib.import_module("cyclonedds")
    except ImportError as exc:
        raise ImportError(
            "ROS 2 needs the cyclonedds package: pip install 'robocog[ros2]'"
        ) from exc


def _recorder(args: argparse.Namespace) -> Any:
    """The MCAP recorder of ``--record``, or None."""
    if args.record is None:
        return None
    from robocog.bridges.ros2.record import Recorder

    return Recorder(args.record)


def _qbo_body(args: argparse.Namespace, config: BridgeConfig) -> Any:
    """The Q.bo's own body (camera head, ultrasonic sensors) over ROS 2; its images are
    classified by the physical room's SVMs, loaded by name: the bridges know no world."""
    _ros2_setup(args)
    from robocog.bridges.qbo import QboRos2Body

    try:
        importlib.import_module("sklearn")
        vision = importlib.import_module("robocog.worlds.physics.room_vision")
    except ImportError as exc:
        raise ImportError(
            f"the Q.bo's vision needs the physics extra: pip install 'robocog[physics]' ({exc})"
        ) from exc
    body = QboRos2Body(
        args.domain,
        config,
        namespace=getattr(args, "namespace", ""),
        vision=vision,
        recorder=_recorder(args),
    )
    return body


def _make_link(args: argparse.Namespace, config: BridgeConfig) -> Any:
    if args.middleware == "ros2":
        _ros2_setup(args)
        from robocog.bridges.ros2.link import Ros2Link

        return Ros2Link(config, args.domain, recorder=_recorder(args))
    from robocog.bridges.ros1.link import Ros1Link

    return Ros1Link(config, python=args.ros1_python)


def build_config(args: argparse.Namespace) -> BridgeConfig:
    """The configuration file (or a shipped robot's), then the command line's places,
    topics and limits on top."""
    robot = getattr(args, "robot", None)
    if args.config:
        config = BridgeConfig.from_toml(args.config)
    elif robot or not args.place:
        config = BridgeConfig.preset(robot or "garbage")
        if not robot:
            log.info("no places configured: using the garbage field's (--robot garbage)")
    else:
        config = BridgeConfig()
    places = dict(config.places)
    for item in args.place:
        name, _, coords = item.partition("=")
        try:
            values = [float(v) for v in coords.split(",")]
        except ValueError:
            values = []
        if not name or len(values) not in (2, 3) or not all(math.isfinite(v) for v in values):
            raise ValueError(f"--place {item!r}: expected NAME=X,Y[,THETA] (finite numbers)")
        places[name] = (values[0], values[1], values[2] if len(values) == 3 else 0.0)
    topics = config.topics
    for item in args.topic:
        key, _, name = item.partition("=")
        if key not in Topics.__dataclass_fields__ or not name:
            known = ", ".join(Topics.__dataclass_fields__)
            raise ValueError(f"--topic {item!r}: expected KEY=NAME with KEY one of {known}")
        topics = replace(topics, **{key: name})
    changes: dict[str, Any] = {"places": places, "topics": topics}
    namespace = getattr(args, "namespace", "").strip("/")
    if namespace:
        changes["topics"] = Topics(
            **{
                key: f"/{namespace}/{value.lstrip('/')}" if value.startswith("/") else value
                for key, value in vars(topics).items()
            }
        )
    if args.watchdog is not None:
        changes["watchdog_seconds"] = args.watchdog
    if getattr(args, "goto_timeout", None) is not None:
        changes["goto_timeout"] = args.goto_timeout
    if getattr(args, "lockstep", False):
        changes["lockstep"] = True
    return replace(config, **changes)


def make_mind(name: str, config: BridgeConfig, source: Path | None = None, seed: int = 0) -> Mind:
    """The mind ``name`` for the robot of ``config``, made by the minds' registry.

    The shipped minds are made as the garbage experiment makes them: the route's places,
    the seed, and the knowledge or program in ``source`` instead of the shipped one. Any
    failure to make it is a :class:`MindUnavailable` naming the mind.
    """
    try:
        return make(MindConfig(name, seed, source, tuple(config.route_places)))
    except MindUnavailable:
        raise
    except Exception as exc:  # noqa: BLE001 - an engine may refuse its input in any way
        raise MindUnavailable(
            f"mind {name!r} could not start: {type(exc).__name__}: {exc}"
        ) from exc
