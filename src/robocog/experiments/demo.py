"""``robocog demo``: the garbage collection of Hammer et al., NARS against BDI, in a minute.

A fixed number of runs of the garbage experiment with both minds, then a fixed number
of learning rounds, the comparison table on the terminal and the report (markdown and
plots) in ``--out``. Nothing is cut by the wall clock, so two demos with the same
arguments give the same report apart from the timings. A mind whose engine cannot run
is reported as such and the other one still runs.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from robocog.argtypes import NEW_DIR, NEW_FILE, SEED, count, positive_int
from robocog.worlds.garbage import LIGHTS


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the demo's arguments."""
    parser.add_argument(
        "--runs", type=positive_int(100_000), default=6, help="runs per mind (default 6)"
    )
    parser.add_argument("--seed", type=SEED, default=0, help="seed (default 0)")
    parser.add_argument("--light", choices=LIGHTS, default="sunny")
    parser.add_argument(
        "--rounds", type=count(10_000), default=12, help="NARS's learning rounds (default 12)"
    )
    parser.add_argument("--out", type=NEW_DIR, default=Path("robocog-demo"), metavar="DIR")
    parser.add_argument(
        "--json", type=NEW_FILE, metavar="FILE", help="also write the results as JSON"
    )
    from robocog.inspector.cli import add_arguments

    add_arguments(parser)


def run(args: argparse.Namespace) -> int:
    """Run the demo; 0 when at least one mind ran (the demo says which could not, and why)."""
    from robocog.experiments.cli import garbage_estimate, run_garbage
    from robocog.experiments.garbage import default_minds
    from robocog.progress import duration

    runs = max(1, args.runs)
    seconds, note = garbage_estimate(["BDI", "NARS"], runs, args.rounds)
    print(
        "robocog demo: the garbage field of Hammer et al., NARS and a BDI agent with the same "
        f"knowledge; {runs} runs per mind from seed {args.seed} in {args.light} light, then "
        f"{args.rounds} learning rounds for NARS ({duration(seconds)} on an idle machine{note})"
    )
    from robocog.inspector.cli import session

    with session(args, "robocog demo") as inspecting:
        result = run_garbage(
            default_minds(["bdi", "nars"]),  # the quick one first
            runs=runs,
            seed=args.seed,
            light=args.light,
            rounds=args.rounds,
            json_path=args.json,
            out=args.out,
            watch=inspecting.watcher() if inspecting else None,
        )
    return 0 if any(m.runs for m in result.minds.values()) else 1
