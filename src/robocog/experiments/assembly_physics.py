"""``robocog experiment assembly --world mujoco``: the assemblies on the physical tabletop.

The same sequences as the symbolic run (Tables 5.2-5.10 one request at a time, and the
whole BlockB and BlockC assemblies), each once as it is (``--perturb`` moves a cube by
hand in one request) and ``--runs`` times with slips at ``--failure-rate``. Per
request the report gives the plan, the replans and why, the planning time, and the
execution time (simulated and on the wall clock); the first run of each sequence is
filmed (an animated GIF) and a key frame is kept after each request.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robocog.atomic import write_json, write_text
from robocog.experiments.report import provenance, provenance_lines

#: a sequence's run (``robocog.experiments.assembly.SequenceRun``, handed in by it)
SequenceRun = Any


def _same_as_thesis(table: str, plan: Any) -> bool | None:
    """Whether the first plan is the thesis's for a table (None for a whole assembly)."""
    from robocog.experiments.assembly_thesis import experiment

    try:
        exp = experiment(table)
    except (KeyError, ValueError):
        return None
    if not exp.plan or plan is None:
        return None
    return tuple(plan.lines()) == exp.plan


def _row(req: Any) -> dict[str, Any]:
    plan = req.record.first_plan
    return {
        "same_plan_as_thesis": _same_as_thesis(req.table, plan),
        "table": req.table,
        "request": req.record.request,
        "plan": [" ".join((st.name, *st.args)) for st in plan.steps] if plan else [],
        "executed": req.record.executed,
        "replans": req.record.replans,
        "why": req.record.failures,
        "planning_ms": req.record.planning_seconds * 1e3,
        "sim_seconds": req.arm_seconds,
        "wall_seconds": req.wall_seconds,
        "failed_grasps": req.failed_grasps,
        "perturbed": req.perturbed,
        "reached": req.reached,
        "status": req.record.status,
        "message": req.record.message,
    }


def save_video(frames: list[Any], path: Path, fps: float = 8.0) -> str | None:
    """Write frames as an animated GIF (every other pixel: small enough to keep)."""
    if not frames:
        return None
    import imageio.v3 as iio

    small = [f[::2, ::2] for f in frames]
    iio.imwrite(path, small, duration=1000.0 / fps, loop=0)
    return path.name


def run_physical(
    args: argparse.Namespace,
    sequences: dict[str, Any],
    make_world: Callable[..., Any],
    run_sequence: Callable[..., Any],
) -> int:
    """Run the sequences on the physical tabletop; print, report, write JSON.

    The assembly module hands in its sequences and runners (it imports this module,
    so this one does not import it back).
    """
    import imageio.v3 as iio
    from rich.console import Console

    from robocog.progress import Steps, duration, header

    console = Console()
    n = len(sequences)
    filmed = FILMED_SECONDS * n
    slipping = SLIP_RUN_SECONDS * n * args.runs
    later = (
        f", then {args.runs} run{'s' if args.runs != 1 else ''} of each with grasps slipping at {args.failure_rate:.0%} "
        f"({duration(slipping)}; --runs 0 leaves them out)"
        if args.runs
        else ""
    )
    header(
        console,
        "robocog experiment assembly --world mujoco",
        f"the {n} assembly sequences on the MuJoCo arm, planned from AprilTags seen in "
        f"rendered frames: once each{' with a cube moved by hand' if args.perturb else ''}"
        f"{', filmed' if not args.no_video else ''} ({duration(filmed)}){later}",
        f"{duration(filmed + slipping)} in all on a 2-core machine shared with other work",
    )
    with Steps(console) as steps:
        return _run_physical(args, sequences, make_world, run_sequence, console, steps, iio)


#: wall seconds of one filmed sequence and of one run with slips, measured on this
#: project's 2-core machine shared with other work (the rendering and the tag detection
#: take most of them; an idle machine takes about a third)
FILMED_SECONDS = 55.0
SLIP_RUN_SECONDS = 40.0


def _run_physical(
    args: argparse.Namespace,
    sequences: dict[str, Any],
    make_world: Callable[..., Any],
    run_sequence: Callable[..., Any],
    console: Any,
    steps: Any,
    iio: Any,
) -> int:
    """``run_physical`` once its header is out, with ``steps`` showing the progress."""
    first = steps.add("filmed sequences", len(sequences))
    later = steps.add("runs with slips", len(sequences) * args.runs) if args.runs else None
    report_dir = Path(args.report)
    report_dir.mkdir(parents=True, exist_ok=True)
    video = not args.no_video
    clean: dict[str, SequenceRun] = {}
    films: dict[str, str | None] = {}
    frames: dict[str, list[str]] = {}
    stats: dict[str, dict[str, float]] = {}
    for name in sequences:
        world = make_world("mujoco", args.seed, 0.0, record=video)
        world.frame_every = 0.5
        keys: list[str] = []

        def key_frame(table: str, w: Any, name: str = name, keys: list[str] = keys) -> None:
            steps.note(first, f"{name}: table {table} done")
            if video:
                file = f"{name}_{table}.png"
                iio.imwrite(report_dir / file, w.snapshot())
                keys.append(file)

        start = time.perf_counter()
        run = run_sequence(
            name,
            args.seed,
            0.0,
            args.mode,
            world_kind="mujoco",
            perturb=args.perturb,
            world=world,
            on_request=key_frame,
        )
        wall = time.perf_counter() - start
        clean[name] = run
        frames[name] = keys
        films[name] = save_video(world.frames, report_dir / f"{name}.gif") if video else None
        stats[name] = {
            "sim_seconds": world.time(),
            "wall_seconds": wall,
            "looks": world.looks,
            "render_seconds": world.eyes.render_seconds,
            "detect_seconds": world.eyes.detect_seconds,
        }
        world.close()
        steps.say(_summary_line(name, run, stats[name]))
        steps.advance(first)
    failing: dict[str, list[SequenceRun]] = {name: [] for name in sequences}
    for name in sequences:
        for i in range(args.runs):
            assert later is not None
            steps.start(later)

            def note(
                table: str, _world: Any, name: str = name, seed: int = args.seed + 1 + i
            ) -> None:
                steps.note(later, f"{name}, seed {seed}: table {table} done")

            run = run_sequence(
                name,
                args.seed + 1 + i,
                args.failure_rate,
                args.mode,
                world_kind="mujoco",
                perturb=args.perturb,
                on_request=note,
            )
            failing[name].append(run)
            steps.say(
                f"  slips at {args.failure_rate:.0%}, seed {args.seed + 1 + i}: "
                + _summary_line(name, run, None)
            )
            steps.advance(later)
    rows = {name: [_row(r) for r in run.requests] for name, run in clean.items()}
    write_report(report_dir / "assembly.md", args, rows, failing, films, frames, stats)
    console.print(f"report: {report_dir / 'assembly.md'}")
    if args.json:
        write_json(
            Path(args.json),
            {
                "experiment": "assembly",
                "world": "mujoco",
                **provenance(args),
                "requests": rows,
                "with_slips": {
                    n: [[_row(r) for r in run.requests] for run in runs]
                    for n, runs in failing.items()
                },
                "runs": stats,
            },
        )
    ok = all(r.reached for r in clean.values()) and all(
        r.reached for runs in failing.values() for r in runs
    )
    return 0 if ok else 1


def _summary_line(name: str, run: SequenceRun, stats: dict[str, float] | None) -> str:
    reached = sum(r.reached for r in run.requests)
    replans = sum(r.record.replans for r in run.requests)
    line = f"{name}: {reached}/{len(run.requests)} requests reached, {replans} replans"
    if run.stopped:
        line += f", stopped at {run.stopped}"
    if stats:
        rtf = stats["sim_seconds"] / stats["wall_seconds"] if stats["wall_seconds"] else 0.0
        line += (
            f", {stats['sim_seconds']:.0f} s simulated in {stats['wall_seconds']:.0f} s "
            f"(x{rtf:.1f}), {stats['looks']:.0f} looks"
        )
    return line


def write_report(
    path: Path,
    args: argparse.Namespace,
    rows: dict[str, list[dict[str, Any]]],
    failing: dict[str, list[SequenceRun]],
    films: dict[str, str | None],
    frames: dict[str, list[str]],
    stats: dict[str, dict[str, float]],
) -> None:
    """The markdown report of the physical run."""
    lines = [
        "# Assembly on the physical tabletop (Thiella 2021, Chapter 5)",
        "",
        "MuJoCo arm, two cameras and AprilTags; PlannerMind plans from what the cameras "
        f"see (search mode `{args.mode}`, seed {args.seed}"
        + (", one cube moved by hand in one request" if args.perturb else "")
        + "). *reached*: every goal sentence held in the simulator afterwards.",
        "",
    ]
    for name, table_rows in rows.items():
        st = stats[name]
        lines += [
            f"## Sequence `{name}`",
            "",
            f"{st['sim_seconds']:.0f} s of arm time simulated in {st['wall_seconds']:.0f} s "
            f"({st['looks']:.0f} looks: {st['render_seconds']:.1f} s rendering, "
            f"{st['detect_seconds']:.1f} s detecting).",
            "",
            "| table | first plan | thesis's plan | executed | replans (why) | planning | "
            "arm time | wall time | reached |",
            "|---|---|---|---|---|---|---|---|---|",
        ]
        for r in table_rows:
            why = "<br>".join(r["why"]) if r["why"] else ""
            if r["perturbed"]:
                why = f"*{r['perturbed']}*<br>{why}"
            lines.append(
                f"| {r['table']} | {'<br>'.join(r['plan'])} | "
                f"{ {True: 'same', False: 'other', None: '-'}[r['same_plan_as_thesis']] } | "
                f"{len(r['executed'])} steps | "
                f"{r['replans']} {why} | {r['planning_ms']:.1f} ms | {r['sim_seconds']:.0f} s | "
                f"{r['wall_seconds']:.1f} s | {'yes' if r['reached'] else 'NO ' + r['message']} |"
            )
        lines.append("")
        if films.get(name):
            lines += [f"![{name}]({films[name]})", ""]
        for file in frames.get(name, []):
            lines.append(f"![after {file}]({file})")
        lines.append("")
    if any(failing.values()):
        lines += [
            f"## With slips ({args.failure_rate:.0%} of grasps drop their cube)",
            "",
            "| sequence | runs | every request reached | requests reached | slips | replans |",
            "|---|---|---|---|---|---|",
        ]
        for name, runs in failing.items():
            reqs = [r for run in runs for r in run.requests]
            lines.append(
                f"| {name} | {len(runs)} | {sum(run.reached for run in runs)}/{len(runs)} | "
                f"{sum(r.reached for r in reqs)}/{len(reqs)} | "
                f"{sum(r.failed_grasps for r in reqs)} | {sum(r.record.replans for r in reqs)} |"
            )
    lines += ["", *provenance_lines(provenance(args))]
    write_text(path, "\n".join(lines) + "\n")
