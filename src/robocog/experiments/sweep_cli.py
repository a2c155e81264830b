"""``robocog sweep EXPERIMENT --vary NAME=START:STOP:STEP ...``: many seeded missions over
a grid of settings, locally or on a Ray cluster, resumable, with a report.

Examples::

    robocog sweep garbage --vary detection=0.5:0.95:0.05 --minds nars,bdi --runs 30
    robocog sweep garbage --vary grasp=0.6:0.95:0.05 --vary detection=0.6,0.8 --seeds 5
    robocog sweep room-exit --vary detector_noise=0.05:0.3:0.05 --minds bdi,reference
    robocog sweep assembly --vary failure_rate=0:0.5:0.1 --minds astar,quick
    robocog sweep garbage --vary detection=0.5:0.95:0.05 --ray auto   # a running cluster
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from robocog.argtypes import NEW_DIR, int_range, positive_int

if TYPE_CHECKING:
    from rich.console import Console

    from robocog.experiments.sweep import Executor, SweepSpec

DEFAULT_MINDS = {"garbage": "nars,bdi", "room-exit": "bdi,reference", "assembly": "astar"}


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the sweep's arguments."""
    parser.add_argument("experiment", choices=tuple(DEFAULT_MINDS), help="what to sweep")
    parser.add_argument(
        "--vary",
        action="append",
        default=[],
        metavar="NAME=START:STOP:STEP",
        help="a setting and its values (START:STOP:STEP, both ends included, or V1,V2,...); "
        "repeat for a grid",
    )
    parser.add_argument("--minds", help="comma-separated minds (garbage: nars, bdi, ona; "
                        "room-exit: bdi, reference; assembly: the search modes astar, first, quick)")  # fmt: skip
    parser.add_argument(
        "--runs",
        type=positive_int(100_000),
        default=30,
        help="missions per seed block (default 30)",
    )
    parser.add_argument(
        "--seeds", type=positive_int(10_000), default=1, help="seed blocks per point (default 1)"
    )
    parser.add_argument(
        "--seed", type=int_range(0, 10**6), default=0, help="the first seed block (default 0)"
    )
    parser.add_argument("--light", default="sunny", help="garbage: the light (default sunny)")
    parser.add_argument("--sequence", default="tables", help="assembly: tables or whole")
    parser.add_argument("--compare", metavar="A,B", help="the two minds to difference "
                        "(default: the first two)")  # fmt: skip
    parser.add_argument("--out", type=NEW_DIR, metavar="DIR", help="table and report folder "
                        "(default reports/sweep-EXPERIMENT)")  # fmt: skip
    parser.add_argument(
        "--jobs",
        type=positive_int(1024),
        default=os.cpu_count() or 1,
        help="local worker processes",
    )
    parser.add_argument(
        "--ray",
        nargs="?",
        const="",
        metavar="ADDRESS",
        help="run on Ray: a cluster's address (auto: the one `ray start` runs here), or none "
        "for a local Ray of --jobs CPUs",
    )
    parser.add_argument("--fresh", action="store_true", help="start the table over")
    parser.add_argument(
        "--report-only", action="store_true", help="write the report from the table as it is"
    )


def run(args: argparse.Namespace) -> int:
    """Run (or resume) the sweep and write its report; 2 on a bad request."""
    from rich.console import Console

    from robocog.experiments.sweep import (
        SweepError,
        SweepSpec,
        check,
        in_process,
        parse_axis,
        process_pool,
        ray_cluster,
        read_table,
        sorted_rows,
    )
    from robocog.experiments.sweep_report import summarise, write_report

    console = Console(stderr=True)
    out: Path = args.out or Path("reports") / f"sweep-{args.experiment}"
    table = out / "results.jsonl"
    try:
        fixed = {"garbage": {"light": args.light}, "assembly": {"sequence": args.sequence}}
        spec = SweepSpec(
            experiment=args.experiment,
            axes=tuple(parse_axis(v) for v in args.vary),
            minds=tuple(m.strip() for m in (args.minds or DEFAULT_MINDS[args.experiment]).split(",") if m.strip()),
            runs=args.runs,
            seeds=args.seeds,
            first_seed=args.seed,
            fixed=tuple(sorted(fixed.get(args.experiment, {}).items())),
        )  # fmt: skip
        check(spec)
        compare = None
        if args.compare:
            pair = tuple(m.strip() for m in args.compare.split(","))
            if len(pair) != 2 or not set(pair) <= set(spec.minds):
                raise SweepError("--compare names two of the sweep's minds, A,B")
            compare = (pair[0], pair[1])
        if args.jobs < 1:
            raise SweepError("--jobs must be at least 1")
        if args.report_only:
            spec, rows = read_table(table, spec)
            rows = sorted_rows(spec, rows)
        else:
            if args.ray is not None:
                execute = ray_cluster(args.ray or None, args.jobs)
                where = f"Ray ({args.ray or f'local, {args.jobs} CPUs'})"
            elif args.jobs > 1:
                execute, where = process_pool(args.jobs), f"{args.jobs} local processes"
            else:
                execute, where = in_process, "this process"
            rows = _run_with_progress(spec, table, execute, args.fresh, where, console)
    except SweepError as exc:
        # plain lines, never wrapped: an error is one line however narrow the console
        print(f"robocog sweep: {exc}", file=sys.stderr)
        return 2
    except FileNotFoundError as exc:
        print(f"robocog sweep: no table to report on: {exc.filename}", file=sys.stderr)
        return 2
    page = write_report(summarise(spec, rows, compare), out)
    print(f"table: {table}")
    print(f"report: {page}")
    return 0


def _run_with_progress(
    spec: SweepSpec, table: Path, execute: Executor, fresh: bool, where: str, console: Console
) -> list[dict[str, Any]]:
    """The sweep with a progress bar on the terminal, plain lines when stderr is not one;
    a table that already holds missions is resumed, and says so."""
    from robocog.experiments.sweep import run_sweep
    from robocog.progress import Steps, duration, header

    expected = _expected_seconds(spec) / max(1, _workers(where))
    header(
        console,
        f"robocog sweep {spec.experiment}",
        f"{spec.missions} missions on {where}; table {table}",
        f"{duration(expected)} for all of them on an idle machine",
    )
    with Steps(console) as steps:
        task = steps.add("missions", spec.missions)
        first = [True]

        def advance(n: int) -> None:
            if first[0]:  # run_sweep first says how many the table already holds
                first[0] = False
                if n == spec.missions:
                    steps.say(f"resumed: all {n} missions are already in {table}; none to run")
                elif n:
                    steps.say(
                        f"resuming: {n} of {spec.missions} missions are already in {table}; "
                        f"running the other {spec.missions - n} (--fresh starts over)"
                    )
            steps.advance(task, n)

        return run_sweep(spec, table, execute, fresh, advance)


#: wall seconds of one room-exit or assembly mission in one worker (a garbage mission's
#: depends on the mind and on the NARS engine: ``garbage_estimate``)
MISSION_SECONDS = {"room-exit": 0.1, "assembly": 0.1}


def _expected_seconds(spec: SweepSpec) -> float:
    """CPU seconds of the whole sweep on one worker, roughly."""
    per_mind = spec.missions // max(1, len(spec.minds))
    if spec.experiment == "garbage":
        from robocog.experiments.cli import garbage_estimate

        return garbage_estimate([m.upper() for m in spec.minds], per_mind, 0)[0]
    return spec.missions * MISSION_SECONDS.get(spec.experiment, 0.1)


def _workers(where: str) -> int:
    """The number of local processes ``where`` names (1 when it names none)."""
    first = where.split()[0]
    return int(first) if first.isdigit() else 1
