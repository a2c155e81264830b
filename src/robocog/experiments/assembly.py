"""``robocog experiment assembly``: the torque-reaction-arm assembly of Thiella (2021, Chapter 5).

The thesis planned Tables 5.2-5.10 one request at a time and sent each plan to a
simulated arm; between stages, finished stacks were replaced by hand with one cube
(BlockA, BlockB, BlockC). Here :class:`~robocog.minds.planner_mind.PlannerMind` does
the same on :class:`~robocog.worlds.tabletop.TabletopWorld`, in two sequences:

* ``tables``: the nine requests of Tables 5.2-5.10 as the thesis split them;
* ``whole``: BlockB and BlockC each in one request (the thesis had to split them).

Each sequence runs once without grasp failures and ``--runs`` times with failures
injected at ``--failure-rate`` (seeded), which the mind must recover from by
replanning. Every request's plan, iterations and search time are set beside the
thesis's, and the world is checked: each request's goal must hold on the tabletop.

``--world mujoco`` runs the same on the physical tabletop
(:mod:`robocog.worlds.mujoco_tabletop`): the arm moves in MuJoCo, the mind plans from
what the cameras see (``PlannerMind(perceive_scene=True)``), a slip drops the cube
where physics lets it fall, and ``--perturb`` moves one of a request's cubes by hand
in the middle of it. The report adds replans, planning and execution time per request,
an animated GIF of the run and a key frame after each request.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

from robocog.argtypes import fraction
from robocog.atomic import write_json, write_text
from robocog.experiments.assembly_thesis import EXPERIMENTS, WHOLE_ASSEMBLIES, experiment
from robocog.experiments.report import add_run_arguments, provenance, provenance_lines
from robocog.minds import registry
from robocog.minds.planner_mind import PlannerMind, RequestRecord
from robocog.robot.loop import Loop
from robocog.worlds.tabletop import BLOCK_C_BINS, TabletopWorld

BLOCK_A = ["BettClamp", "InductionHardenedRod"]
BLOCK_B = ["SnapRing1", "BearingSleeve1", "RecirculatingBallSleeve", "BearingSleeve2", "SnapRing2"]
BLOCK_C = ["BlockC", "UpperBearingBracket", "Bearing", "RotatingBalancerSupport", "TCEIScrew"]

#: a stage is ("request", table) | ("merge", parts, block) | ("add", parts)
Stage = tuple[Any, ...]

SEQUENCES: dict[str, list[Stage]] = {
    "tables": [
        ("request", "5.2"),
        ("merge", BLOCK_A, "BlockA"),
        ("request", "5.3"),
        ("request", "5.4"),
        ("request", "5.5"),
        ("request", "5.6"),
        ("merge", BLOCK_B, "BlockB"),
        ("request", "5.7"),
        ("add", BLOCK_C_BINS),
        ("request", "5.8"),
        ("request", "5.9"),
        ("merge", BLOCK_C, "BlockC"),
        ("request", "5.10"),
    ],
    "whole": [
        ("request", "5.2"),
        ("merge", BLOCK_A, "BlockA"),
        ("request", "5.3"),
        ("request", "BlockB"),
        ("merge", BLOCK_B, "BlockB"),
        ("request", "5.7"),
        ("add", BLOCK_C_BINS),
        ("request", "BlockC"),
        ("merge", BLOCK_C, "BlockC"),
        ("request", "5.10"),
    ],
}


@dataclass
class RequestRun:
    """One request executed on the tabletop."""

    table: str
    record: RequestRecord
    reached: bool
    arm_seconds: float
    failed_grasps: int
    wall_seconds: float = 0.0
    perturbed: str | None = None


@dataclass
class SequenceRun:
    """One sequence of requests on one tabletop."""

    sequence: str
    seed: int
    failure_rate: float
    requests: list[RequestRun] = field(default_factory=list)
    stopped: str | None = None

    @property
    def reached(self) -> bool:
        """True when every request's goal held on the tabletop (and none was left out)."""
        return self.stopped is None and all(r.reached for r in self.requests)


def make_world(kind: str, seed: int, failure_rate: float, record: bool = False) -> Any:
    """The tabletop to run on: ``symbolic`` (instant) or ``mujoco`` (physics, cameras)."""
    if kind == "mujoco":
        from robocog.worlds.mujoco_tabletop import MujocoTabletop

        return MujocoTabletop(seed=seed, slip_rate=failure_rate, record=record)
    if kind != "symbolic":
        raise ValueError(f"unknown world {kind!r}")
    return TabletopWorld(seed=seed, grasp_failure=failure_rate)


def run_sequence(
    sequence: str,
    seed: int = 0,
    failure_rate: float = 0.0,
    mode: str = "astar",
    max_cycles: int = 200,
    world_kind: str = "symbolic",
    perturb: bool = False,
    world: Any = None,
    on_request: Any = None,
    watch: Callable[..., Any] | None = None,
) -> SequenceRun:
    """Run one sequence of stages on a fresh tabletop with one PlannerMind.

    On the physical world the mind plans from what it sees; with ``perturb`` one
    request, drawn by the seed among those of two steps or more, has one of its cubes
    moved by hand after a random number of steps. ``on_request(table, world)`` is
    called after each request (for key frames). ``watch``, given the world, the mind
    and the loop, returns the loop's ``on_step`` (the inspector's hook).
    """
    import random
    import time

    physical = world_kind == "mujoco"
    if world is None:
        world = make_world(world_kind, seed, failure_rate)
        try:
            return run_sequence(
                sequence,
                seed,
                failure_rate,
                mode,
                max_cycles,
                world_kind,
                perturb,
                world,
                on_request,
                watch,
            )
        finally:
            if hasattr(world, "close"):  # the physical world's renderers hold GL contexts
                world.close()
    options = {"mode": mode, "perceive_scene": physical}
    mind = cast(PlannerMind, registry.make(registry.MindConfig("planner", seed, options=options)))
    loop = Loop(world, mind)
    on_step = watch(world, mind, loop) if watch else None
    out = SequenceRun(sequence, seed, failure_rate)
    rng = random.Random(seed * 7919 + 17)
    requests = [st[1] for st in SEQUENCES[sequence] if st[0] == "request"]
    candidates = [t for t in requests if len(experiment(t).plan) >= 2 or t in SPLITS]
    perturb_at = rng.choice(candidates) if perturb and physical and candidates else None
    for stage in SEQUENCES[sequence]:
        try:
            if stage[0] == "merge":
                world.replace_with_block(stage[1], stage[2])
                continue
            if stage[0] == "add":
                world.add_parts(stage[1])
                continue
        except ValueError as exc:  # a request before it failed: the stage cannot be done
            out.stopped = f"{stage[0]} {stage[-1]}: {exc}"
            break
        exp = experiment(stage[1])
        start_clock, start_failed = world.time(), world.failed_grasps
        start_wall = time.perf_counter()
        record = mind.request(exp.request, facts=exp.facts)
        moved: list[str] = []
        if stage[1] == perturb_at:
            after = rng.randint(1, max(1, len(exp.plan) - 1) if exp.plan else 3)
            parts = {f[i] for f in record.goal for i in range(1, len(f))}

            def disturb(
                step: Any,
                after: int = after,
                parts: set[str] = parts,
                moved: list[str] = moved,
                record: RequestRecord = record,
            ) -> None:
                if not moved and len(record.executed) >= after:
                    moved.append(world.perturb(parts) or "nothing could be moved")
                if on_step is not None:
                    on_step(step)

            loop.run(max_cycles, until=lambda: not mind.busy, on_step=disturb)
        else:
            loop.run(max_cycles, until=lambda: not mind.busy, on_step=on_step)
        reached = record.status == "reached" and all(world.holds(f) for f in record.goal)
        out.requests.append(
            RequestRun(
                exp.table,
                record,
                reached,
                world.time() - start_clock,
                world.failed_grasps - start_failed,
                time.perf_counter() - start_wall,
                moved[0] if moved else None,
            )
        )
        if on_request is not None:
            on_request(exp.table, world)
    return out


#: the thesis's split requests that a whole assembly stands for
SPLITS = {"BlockB": ("5.4", "5.5", "5.6"), "BlockC": ("5.8", "5.9")}


def thesis_figures(table: str) -> tuple[tuple[str, ...], int, float]:
    """The thesis's plan, iterations and seconds for a table, or summed over its splits."""
    if table in SPLITS:
        parts = [experiment(t) for t in SPLITS[table]]
        plan = tuple(step for e in parts for step in e.plan)
        return plan, sum(e.iterations for e in parts), sum(e.seconds for e in parts)
    exp = experiment(table)
    return exp.plan, exp.iterations, exp.seconds


def configure(parser: argparse.ArgumentParser) -> None:
    """Arguments of ``robocog experiment assembly``."""
    add_run_arguments(
        parser, 10, "runs with grasp failures (0: only the two sequences)", "reports/assembly", 0
    )
    parser.add_argument(
        "--failure-rate", type=fraction(), default=0.25, help="chance that a grasp slips"
    )
    parser.add_argument(
        "--mode",
        default="astar",
        choices=("astar", "first", "quick"),
        help="search mode: astar (default), or the thesis's BFS first/quick",
    )
    parser.add_argument("--no-plots", action="store_true", help="skip the PNG plot")
    parser.add_argument(
        "--world",
        default="symbolic",
        choices=("symbolic", "mujoco"),
        help="symbolic tabletop (default) or the physical one in MuJoCo (the physics extra)",
    )
    parser.add_argument(
        "--perturb",
        action="store_true",
        help="physical world: move one of a request's cubes by hand mid-run",
    )
    parser.add_argument(
        "--no-video", action="store_true", help="physical world: skip the GIF and key frames"
    )
    from robocog.inspector.cli import add_arguments

    add_arguments(parser)


def _row(req: RequestRun) -> dict[str, Any]:
    thesis_plan, thesis_iterations, thesis_seconds = thesis_figures(req.table)
    plan = req.record.first_plan
    lines = plan.lines() if plan else []
    short = [" ".join((st.name, *st.args)) for st in plan.steps] if plan else []
    return {
        "plan_short": short,
        "table": req.table,
        "request": req.record.request,
        "plan": lines,
        "length": len(lines),
        "iterations": plan.iterations if plan else None,
        "seconds": plan.seconds if plan else None,
        "optimal": plan.optimal if plan else False,
        "same_plan_as_thesis": tuple(lines) == thesis_plan,
        "thesis_plan": list(thesis_plan),
        "thesis_length": len(thesis_plan),
        "thesis_iterations": thesis_iterations,
        "thesis_seconds": thesis_seconds,
        "reached": req.reached,
        "replans": req.record.replans,
        "failed_grasps": req.failed_grasps,
        "arm_seconds": req.arm_seconds,
        "planning_seconds": req.record.planning_seconds,
        "wall_seconds": req.wall_seconds,
        "perturbed": req.perturbed,
        "failures": req.record.failures,
        "executed": req.record.executed,
    }


def _mind_summary(runs: list[SequenceRun]) -> dict[str, Any]:
    requests = [r for run in runs for r in run.requests]
    return {
        "runs": len(runs),
        "success_rate": sum(run.reached for run in runs) / len(runs) if runs else 0.0,
        "requests": len(requests),
        "requests_reached": sum(r.reached for r in requests),
        "failed_grasps": sum(r.failed_grasps for r in requests),
        "replans": sum(r.record.replans for r in requests),
    }


#: wall seconds of one sequence on the symbolic tabletop, on this project's 2-core machine
SEQUENCE_SECONDS = 0.25


def run(args: argparse.Namespace) -> int:
    """Run both sequences with and without failures; print, report, write JSON."""
    if getattr(args, "world", "symbolic") == "mujoco":
        from robocog.experiments.assembly_physics import run_physical

        return run_physical(args, SEQUENCES, make_world, run_sequence)
    from rich.console import Console
    from rich.table import Table

    from robocog.experiments.tables import fit
    from robocog.progress import Steps, duration, header

    console = Console()
    clean: dict[str, SequenceRun] = {}
    failing: dict[str, list[SequenceRun]] = {name: [] for name in SEQUENCES}
    total = len(SEQUENCES) * (1 + args.runs)
    from robocog.inspector.cli import session

    header(
        console,
        "robocog experiment assembly",
        f"Thiella's Tables 5.2-5.10 and the whole assemblies ({len(SEQUENCES)} sequences) "
        f"planned and executed on the symbolic tabletop, once and {args.runs} times with "
        f"grasps slipping at {args.failure_rate:.0%}",
        f"{duration(SEQUENCE_SECONDS * total)} on an idle machine",
    )
    with (
        session(args, "robocog experiment assembly") as inspecting,
        Steps(console) as steps,
    ):
        watch = inspecting.watcher() if inspecting else None
        task = steps.add("sequences", total)
        for name in SEQUENCES:
            clean[name] = run_sequence(name, args.seed, 0.0, args.mode, watch=watch)
            steps.advance(task)
            for i in range(args.runs):
                failing[name].append(
                    run_sequence(name, args.seed + 1 + i, args.failure_rate, args.mode, watch=watch)
                )
                steps.advance(task)

    rows = {name: [_row(r) for r in run.requests] for name, run in clean.items()}
    recovery: dict[str, dict[str, dict[str, Any]]] = {}
    for name, runs in failing.items():
        per: dict[str, dict[str, Any]] = {}
        for run_ in runs:
            for req in run_.requests:
                d = per.setdefault(
                    req.table, {"runs": 0, "reached": 0, "failed_grasps": 0, "replans": 0}
                )
                d["runs"] += 1
                d["reached"] += int(req.reached)
                d["failed_grasps"] += req.failed_grasps
                d["replans"] += req.record.replans
        recovery[name] = per

    for name in SEQUENCES:
        table = Table(title=f"assembly: {name} (search mode {args.mode})")
        for col in (
            "table",
            "plan (ours)",
            "len",
            "iters",
            "time",
            "thesis len",
            "thesis iters",
            "thesis time",
            "reached",
            f"with failures ({args.failure_rate:.0%})",
        ):
            table.add_column(col)
        for row in rows[name]:
            rec = recovery[name].get(row["table"], {})
            table.add_row(
                row["table"],
                "\n".join(row["plan_short"]),
                str(row["length"]),
                str(row["iterations"]),
                f"{row['seconds'] * 1e3:.1f} ms" if row["seconds"] is not None else "-",
                str(row["thesis_length"] or "-"),
                str(row["thesis_iterations"]),
                f"{row['thesis_seconds']:g} s",
                "yes" if row["reached"] else "NO",
                f"{rec.get('reached', 0)}/{rec.get('runs', 0)} reached, "
                f"{rec.get('failed_grasps', 0)} slips, {rec.get('replans', 0)} replans",
            )
        console.print(fit(table, console.width))

    minds = {
        "planner": _mind_summary(list(clean.values())),
        "planner_grasp_failures": _mind_summary([r for runs in failing.values() for r in runs]),
    }
    for key, s in minds.items():
        console.print(
            f"{key}: {s['requests_reached']}/{s['requests']} requests reached, "
            f"{s['failed_grasps']} failed grasps, {s['replans']} replans"
        )
    report_dir = Path(args.report)
    report_dir.mkdir(parents=True, exist_ok=True)
    plot = None if args.no_plots else write_plot(rows, report_dir)
    write_report(report_dir / "assembly.md", args, rows, recovery, minds, plot)
    console.print(f"report: {report_dir / 'assembly.md'}")
    if args.json:
        payload = {
            "experiment": "assembly",
            **provenance(args),
            "seed": args.seed,
            "runs": args.runs,
            "failure_rate": args.failure_rate,
            "mode": args.mode,
            "minds": minds,
            "requests": rows,
            "with_failures": recovery,
        }
        write_json(Path(args.json), payload)
    everything = all(run_.reached for run_ in clean.values()) and all(
        run_.reached for runs in failing.values() for run_ in runs
    )
    return 0 if everything else 1


def write_plot(rows: dict[str, list[dict[str, Any]]], out: Path) -> str:
    """Search time per request, ours against the thesis's, on a log scale."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    seen: dict[str, dict[str, Any]] = {}
    for name in SEQUENCES:
        for row in rows[name]:
            seen.setdefault(row["table"], row)
    labels = list(seen)
    ours = [max(seen[t]["seconds"] or 0.0, 1e-4) for t in labels]
    theirs = [max(seen[t]["thesis_seconds"], 0.5) for t in labels]
    fig, ax = plt.subplots(figsize=(8, 4))
    xs = range(len(labels))
    ax.bar([x - 0.2 for x in xs], theirs, width=0.4, label="thesis (0 s shown as 0.5 s)")
    ax.bar([x + 0.2 for x in xs], ours, width=0.4, label="robocog")
    ax.set_yscale("log")
    ax.set_xticks(list(xs), labels, rotation=30)
    ax.set_ylabel("search time (s)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "assembly_times.png", dpi=110)
    plt.close(fig)
    return "assembly_times.png"


def write_report(
    path: Path,
    args: argparse.Namespace,
    rows: dict[str, list[dict[str, Any]]],
    recovery: dict[str, dict[str, dict[str, Any]]],
    minds: dict[str, dict[str, Any]],
    plot: str | None,
) -> None:
    """The markdown report: one table per sequence, thesis figures alongside."""
    lines = [
        "# Assembly (Thiella 2021, Chapter 5)",
        "",
        f"Planner search mode `{args.mode}`. Each sequence ran once without failures and "
        f"{args.runs} times with grasps slipping at {args.failure_rate:.0%} (seeds "
        f"{args.seed + 1}..{args.seed + args.runs}). *reached* means every goal sentence "
        "held on the tabletop afterwards.",
        "",
    ]
    for name in SEQUENCES:
        lines += [
            f"## Sequence `{name}`",
            "",
            "| table | plan (ours) | length | iterations | search time | thesis length | "
            "thesis iterations | thesis time | same plan | reached | with failures |",
            "|---|---|---|---|---|---|---|---|---|---|---|",
        ]
        for row in rows[name]:
            rec = recovery[name].get(row["table"], {})
            secs = f"{row['seconds'] * 1e3:.1f} ms" if row["seconds"] is not None else "-"
            lines.append(
                f"| {row['table']} | {'<br>'.join(row['plan'])} | {row['length']} | "
                f"{row['iterations']} | {secs} | {row['thesis_length'] or '-'} | "
                f"{row['thesis_iterations']} | {row['thesis_seconds']:g} s | "
                f"{'yes' if row['same_plan_as_thesis'] else 'no'} | "
                f"{'yes' if row['reached'] else 'NO'} | "
                f"{rec.get('reached', 0)}/{rec.get('runs', 0)} reached, "
                f"{rec.get('failed_grasps', 0)} slips, {rec.get('replans', 0)} replans |"
            )
        lines.append("")
    lines += [
        "The thesis could not plan BlockB and BlockC in one request; for the whole "
        "assemblies its columns add up the split requests (BlockB: Tables 5.4-5.6, "
        "BlockC: Tables 5.8-5.9), and *same plan* compares with their concatenation.",
        "",
        "| mind | sequences | all goals reached | requests reached | failed grasps | replans |",
        "|---|---|---|---|---|---|",
    ]
    for key, s in minds.items():
        lines.append(
            f"| {key} | {s['runs']} | {s['success_rate']:.0%} | "
            f"{s['requests_reached']}/{s['requests']} | {s['failed_grasps']} | {s['replans']} |"
        )
    if plot:
        lines += ["", f"![search time per request]({plot})", ""]
    lines += ["", *provenance_lines(provenance(args))]
    write_text(path, "\n".join(lines) + "\n")


__all__ = ["EXPERIMENTS", "WHOLE_ASSEMBLIES", "configure", "run", "run_sequence"]
