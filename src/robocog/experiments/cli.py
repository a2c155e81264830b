"""``robocog experiment NAME``: the papers' case studies as seeded runs with reports.

``robocog experiment garbage|room-exit|assembly [options]``: each case study has its
own arguments. A study whose module is not in this build says so instead of running.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.argtypes import EXISTING_FILE, NEW_DIR, NEW_FILE, SEED, count, positive_int
from robocog.worlds.garbage import LIGHTS

if TYPE_CHECKING:
    from robocog.experiments.garbage import ExperimentResult, MindSpec, Watch

#: experiment name -> (module with configure/run, or None for the garbage field here, help)
EXPERIMENTS: dict[str, tuple[str | None, str]] = {
    "garbage": (None, "Hammer et al.: NARS and BDI collecting garbage (Table II, Fig. 6)"),
    "room-exit": ("robocog.experiments.room_exit", "Fujita et al.: the Q.bo leaving a room"),
    "assembly": ("robocog.experiments.assembly", "Thiella 2021: the manipulator's assemblies"),
}


def configure(parser: argparse.ArgumentParser) -> None:
    """One sub-command per case study, each with its own arguments."""
    sub = parser.add_subparsers(dest="experiment", metavar="NAME")
    for name, (module, help_text) in EXPERIMENTS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        if module is None:
            configure_garbage(p)
            continue
        try:
            importlib.import_module(module).configure(p)
        except Exception as exc:  # an optional part missing or broken: say so when it is run
            p.set_defaults(unavailable=f"{type(exc).__name__}: {exc}")
            p.add_argument("rest", nargs=argparse.REMAINDER, help=argparse.SUPPRESS)


def configure_garbage(parser: argparse.ArgumentParser) -> None:
    """The garbage experiment's arguments."""
    parser.add_argument(
        "--runs",
        type=positive_int(100_000),
        default=30,
        help="runs per mind (default 30, as Table II)",
    )
    parser.add_argument("--seed", type=SEED, default=0, help="seed of the first run (default 0)")
    parser.add_argument("--light", choices=LIGHTS, default="sunny", help="lighting (default sunny)")
    parser.add_argument(
        "--minds",
        default="nars,bdi",
        help="comma-separated: nars, bdi, ona (NARS on ONA 0.9.2, the peer) (default nars,bdi)",
    )
    parser.add_argument(
        "--rounds",
        type=count(10_000),
        default=8,
        help="rounds NARS collects before it is asked where trash accumulates (0: skip)",
    )
    parser.add_argument("--json", type=NEW_FILE, metavar="FILE", help="write the results as JSON")
    parser.add_argument(
        "--world",
        choices=("2d", "mujoco"),
        default="2d",
        help="2d: the field of probability tables (default); mujoco: the physical field "
        "(camera, learned detector, lidar, arm; needs the physics extra)",
    )
    parser.add_argument(
        "--detection-frames",
        type=count(100_000),
        default=300,
        metavar="N",
        help="--world mujoco: frames rendered per light to measure Table I (default 300; 0 skips)",
    )
    parser.add_argument(
        "--detector",
        type=EXISTING_FILE,
        metavar="MODEL.onnx",
        help="--world mujoco: a YOLO model in ONNX (run by onnxruntime) in place of the "
        "learned detector",
    )
    parser.add_argument(
        "--over",
        choices=("process", "ros2"),
        default="process",
        help="ros2: the world and the mind in separate processes over DDS (ROS 2 messages), "
        "reported beside the in-process run of the same seeds",
    )
    parser.add_argument(
        "--record", type=NEW_DIR, metavar="DIR", help="--over ros2: one MCAP recording per mission"
    )
    parser.add_argument(
        "--out", type=NEW_DIR, default=Path("reports/garbage"), metavar="DIR", help="report folder"
    )
    parser.add_argument("--no-report", action="store_true", help="skip the markdown and plots")
    from robocog.inspector.cli import add_arguments

    add_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """Run the chosen experiment."""
    name = getattr(args, "experiment", None)
    if name is None:
        print("robocog experiment: name one of " + ", ".join(EXPERIMENTS), file=sys.stderr)
        return 2
    if getattr(args, "unavailable", None):
        print(
            f"robocog experiment {name}: not available in this build ({args.unavailable})",
            file=sys.stderr,
        )
        return 2
    module = EXPERIMENTS[name][0]
    if module is not None:
        return int(importlib.import_module(module).run(args) or 0)
    return run_garbage_args(args)


def run_garbage_args(args: argparse.Namespace) -> int:
    """``robocog experiment garbage``: 0 when every mind ran, 1 when some could not."""
    if args.runs < 1:
        print("robocog experiment: --runs must be at least 1", file=sys.stderr)
        return 2
    from robocog.experiments.garbage import default_minds

    try:
        specs = default_minds([m.strip() for m in args.minds.split(",") if m.strip()])
    except ValueError as exc:
        print(f"robocog experiment: {exc}", file=sys.stderr)
        return 2
    if getattr(args, "over", "process") == "ros2":
        return run_garbage_over_ros2(args, specs)
    from robocog.inspector.cli import session
    from robocog.progress import duration

    seconds, note = garbage_estimate([s.name for s in specs], args.runs, args.rounds)
    learning = f", then {args.rounds} learning rounds for NARS" if args.rounds else ""
    print(
        "robocog experiment garbage: Table II of Hammer et al., "
        f"{args.runs} runs per mind ({', '.join(s.name for s in specs)}) from seed {args.seed} "
        f"in {args.light} light{learning} ({duration(seconds)} on an idle machine{note})",
        flush=True,
    )

    world = getattr(args, "world", "2d")
    if world == "mujoco":
        try:
            import robocog.worlds.mujoco_garbage  # noqa: F401
        except ImportError as exc:
            print(
                f"robocog experiment: --world mujoco needs the physics extra ({exc})",
                file=sys.stderr,
            )
            return 2
    with session(args, "robocog experiment garbage") as inspecting:
        result = run_garbage(
            specs,
            runs=args.runs,
            seed=args.seed,
            light=args.light,
            rounds=args.rounds if world == "2d" else 0,
            json_path=args.json,
            out=None if args.no_report else args.out,
            watch=inspecting.watcher() if inspecting else None,
            world=world,
            detection_frames=getattr(args, "detection_frames", 0),
            detector_path=getattr(args, "detector", None),
        )
    return 0 if all(m.ok for m in result.minds.values()) else 1


#: CPU seconds of one mission per mind and of one NARS learning round, measured with
#: ``robocog demo`` piped through ``cat`` on this project's 2-core machine (the rounds grow
#: slower as the memory fills; this is their mean over 12)
MISSION_SECONDS = {"BDI": 0.05, "NARS": 0.25, "ONA": 0.5}
ROUND_SECONDS = 0.6
#: how much slower the pure-Python NARS engine is than the compiled one
PURE_FACTOR = 4.5


def garbage_estimate(names: list[str], runs: int, rounds: int) -> tuple[float, str]:
    """Seconds the garbage missions and the learning rounds are expected to take on an
    idle machine, and a note on the NARS engine that runs them (the pure one is slower)."""
    import robocog.nars

    pure = robocog.nars.ENGINE != "compiled"
    factor = PURE_FACTOR if pure else 1.0
    seconds = 1.0 + rounds * ROUND_SECONDS * factor
    for name in names:
        cost = MISSION_SECONDS.get(name, 0.25)
        seconds += runs * cost * (factor if name == "NARS" else 1.0)
    note = ""
    if pure and "NARS" in names:
        note = "; NARS runs as pure Python: `robocog build` makes it about 4 times faster"
    return seconds, note


def run_garbage(
    specs: list[MindSpec],
    runs: int,
    seed: int,
    light: str,
    rounds: int,
    json_path: Path | None,
    out: Path | None,
    config_overrides: dict[str, float] | None = None,
    watch: Watch | None = None,
    world: str = "2d",
    detection_frames: int = 0,
    detector_path: Path | None = None,
) -> ExperimentResult:
    """Shared by ``experiment garbage`` and ``demo``: run, print the table, write files
    (``watch`` hooks every loop, for ``--inspect``). ``world="mujoco"`` runs the
    physical field and measures Table I over ``detection_frames`` renders per light."""
    from rich.console import Console
    from rich.markup import escape

    from robocog.experiments.garbage import run_experiment
    from robocog.experiments.report import mind_status, summary_table, write_json, write_report
    from robocog.experiments.tables import fit
    from robocog.progress import Steps
    from robocog.worlds.garbage import GarbageConfig

    console = Console()
    config = GarbageConfig(light=light, **(config_overrides or {}))  # type: ignore[arg-type]
    make_world = None
    detector = None
    if world == "mujoco":
        from robocog.experiments.garbage_physics import world_factory
        from robocog.worlds.physics.onnx_detector import camera_detector

        try:
            detector, report = camera_detector(detector_path, console.print)
        except ImportError as exc:
            raise SystemExit(f"robocog experiment: --detector needs onnxruntime ({exc})") from None
        except ValueError as exc:  # a model onnxruntime cannot load: say so in a line
            raise SystemExit(f"robocog experiment: --detector {exc}") from None
        if report is not None:
            console.print(
                escape(
                    f"detector: recall {report.recall:.1%}, labels {report.label_accuracy:.1%} "
                    f"on {report.frames} held-out renders"
                )
            )
        film: list[object] = []
        make_world = world_factory(detector, film=film if out is not None else None)
    learner = next((s.name for s in specs if s.name in ("NARS", "ONA")), None)
    with Steps(console) as steps:
        missions = steps.add("garbage runs", runs * len(specs))
        learning = steps.add(f"{learner} learning rounds", rounds) if rounds and learner else None

        def advance() -> None:
            steps.advance(missions)
            if learning is not None and steps.done(missions):
                steps.start(learning)  # the learning phase begins

        result = run_experiment(
            specs,
            runs=runs,
            seed=seed,
            config=config,
            rounds=rounds,
            advance=advance,
            watch=watch,
            on_round=None if learning is None else lambda _r: steps.advance(learning),
            make_world=make_world,
        )
        if world == "mujoco":
            result.world = "mujoco"
            if detection_frames > 0:
                from robocog.experiments.garbage_physics import measure_detection

                frames_task = steps.add("Table I frames", 3 * detection_frames)
                steps.start(frames_task)
                rates = measure_detection(
                    detector,
                    detection_frames,
                    seed=seed + 1,
                    camera_range=config.camera_range,
                    progress=lambda _light, _n, _total: steps.advance(frames_task),
                )
                result.extra["detection_rates"] = {k: round(v.rate, 4) for k, v in rates.items()}
                result.extra["detection"] = {k: v.as_dict() for k, v in rates.items()}
    if world == "mujoco" and out is not None and film:
        from robocog.experiments.garbage_physics import write_gif

        write_gif(film, out / "mission.gif")
        console.print(escape(f"the first mission's camera: {out / 'mission.gif'}"))
    console.print(fit(summary_table(result), console.width))
    if "detection" in result.extra:
        console.print("Table I, measured from rendered frames (paper beside):")
        for light_name, row in result.extra["detection"].items():
            console.print(
                f"  {light_name:8} {row['rate']:6.1%}  ({row['detected']}/{row['in_view']} "
                f"objects in view over {row['frames']} frames)   paper {row['paper']:.0%}"
            )
    for m in result.minds.values():
        console.print(escape(mind_status(m)))
    acc = result.accumulation
    if acc is not None and acc.unavailable is None:
        places = ", ".join(p for p, *_ in acc.ranking) or "no place hypothesis formed yet"
        console.print(
            escape(
                f"{acc.mind}, after {acc.rounds} rounds, ranks the checkpoints by trash seen: "
                f"{places} (hotspots: {', '.join(acc.hotspots)})"
            )
        )
    if json_path is not None:
        write_json(json_path, result)
        console.print(escape(f"results: {json_path}"))
    if out is not None:
        page = write_report(result, out, lambda line: console.print(escape(line)))
        console.print(escape(f"report: {page}"))
    return result


def run_garbage_over_ros2(args: argparse.Namespace, specs: list[MindSpec]) -> int:
    """``--over ros2``: each mission in process and over DDS, the rates side by side."""
    from rich.console import Console

    from robocog.experiments.garbage import mission_seeds
    from robocog.progress import Steps, duration, header
    from robocog.worlds.garbage import GarbageConfig

    config = GarbageConfig(light=args.light)
    seeds = mission_seeds(args.seed, args.runs)
    doc: dict[str, object] = {"experiment": "garbage", "over": "ros2", "seeds": seeds, "minds": {}}
    code = 0
    console = Console()
    ran = [s for s in specs if s.name.lower() in ("nars", "bdi")]
    physical = getattr(args, "world", "2d") == "mujoco"
    mission = PHYSICAL_ROS2_MISSION_SECONDS if physical else ROS2_MISSION_SECONDS
    header(
        console,
        "robocog experiment garbage --over ros2",
        f"{args.runs} missions per mind ({', '.join(s.name for s in ran)}) in this process, "
        "then the same missions with the mind in a `robocog bridge ros2` process over DDS",
        f"{duration(len(ran) * args.runs * mission)} on an idle machine",
    )
    with Steps(console) as steps:
        return _over_ros2(args, specs, config, seeds, doc, code, steps)


def _physical_over_ros2(args: argparse.Namespace, say: Any) -> tuple[Any, Any] | str:
    """The physical field's maker and the robot that serves it over ROS 2, or why not."""
    try:
        from robocog.experiments.garbage_physics import world_factory
        from robocog.sim.field_mujoco import MujocoGarbageRobot
        from robocog.worlds.physics.onnx_detector import camera_detector
    except ImportError as exc:
        return f"--world mujoco --over ros2 needs the physics and ros2 extras ({exc})"
    try:
        detector, _report = camera_detector(getattr(args, "detector", None), say)
    except ImportError as exc:
        return f"--detector needs onnxruntime ({exc})"
    except ValueError as exc:
        return f"--detector {exc}"
    return world_factory(detector), MujocoGarbageRobot


#: wall seconds of one garbage mission in process and over ROS 2 together
ROS2_MISSION_SECONDS = 3.0
#: the same on the physical field (measured: 20-25 s each way for NARS)
PHYSICAL_ROS2_MISSION_SECONDS = 50.0


def _over_ros2(
    args: argparse.Namespace,
    specs: list[MindSpec],
    config: Any,
    seeds: list[int],
    doc: dict[str, object],
    code: int,
    steps: Any,
) -> int:
    """``run_garbage_over_ros2`` once its header is out, ``steps`` showing the missions."""
    import json

    from robocog.experiments.garbage import run_once
    from robocog.experiments.over_ros2 import pooled, run_mission

    make_world = serve = None
    if getattr(args, "world", "2d") == "mujoco":
        made = _physical_over_ros2(args, steps.say)
        if isinstance(made, str):
            print(f"robocog experiment: {made}", file=sys.stderr)
            return 2
        make_world, serve = made
        doc["world"] = "mujoco"
    steps.say(f"{'mind':6} {'in process':>10} {'over ROS 2':>10} {'difference':>11}  missions")
    for spec in specs:
        key = spec.name.lower()
        if key not in ("nars", "bdi"):
            print(f"{spec.name:6} skipped: only nars and bdi run over ROS 2", file=sys.stderr)
            continue
        why = spec.probe()
        if why:
            print(f"{spec.name:6} unavailable: {why}", file=sys.stderr)
            code = 1
            continue
        here = steps.add(f"{spec.name} in process", len(seeds))
        steps.start(here)
        local = []
        for seed in seeds:
            local.append(run_once(spec, config, seed, make_world=make_world))
            steps.advance(here)
        remote = []
        there = steps.add(f"{spec.name} over ROS 2", len(seeds))
        steps.start(there)
        for seed in seeds:
            record = None
            if args.record is not None:
                args.record.mkdir(parents=True, exist_ok=True)
                record = args.record / f"{key}-{seed}.mcap"
            run = run_mission(key, config, seed, record=record, make_world=make_world, serve=serve)
            if run.error:
                print(f"{spec.name} seed {seed}: {run.error}", file=sys.stderr)
                code = 1
            remote.append(run)
            steps.advance(there)
        placed = sum(r.objects for r in local)
        rate_local = sum(r.collected for r in local) / placed if placed else 0.0
        rate_remote = pooled(remote) or 0.0
        same = sum(a.collected == b.collected for a, b in zip(local, remote, strict=True))
        steps.say(
            f"{spec.name:6} {rate_local:>10.1%} {rate_remote:>10.1%} "
            f"{(rate_remote - rate_local) * 100:>+10.1f}p  "
            f"{same}/{len(seeds)} collected the same"
        )
        doc["minds"][spec.name] = {  # type: ignore[index]
            "in_process": {"success_rate": rate_local, "collected": [r.collected for r in local]},
            "over_ros2": {
                "success_rate": rate_remote,
                "collected": [r.collected for r in remote],
                "frames": [r.frames for r in remote],
                "wall_seconds": [round(r.wall_seconds, 2) for r in remote],
                "errors": [r.error for r in remote if r.error],
                "watchdog_trips": sum(r.watchdog_trips for r in remote),
            },
        }
    if args.json is not None:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(doc, indent=2))
    return code
