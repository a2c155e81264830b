"""``robocog demo``: seed 000's garbage collection, NARS against BDI, in a minute or two.

A few runs of the garbage experiment with both minds, the comparison table on the
terminal and the report (markdown and plots) in ``--out``. A mind whose engine cannot
run yet is reported as such and the other one still runs.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from robocog.worlds.garbage import LIGHTS


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the demo's arguments."""
    parser.add_argument("--runs", type=int, default=6, help="runs per mind (default 6)")
    parser.add_argument("--seed", type=int, default=0, help="seed (default 0)")
    parser.add_argument("--light", choices=LIGHTS, default="sunny")
    parser.add_argument(
        "--rounds", type=int, default=12, help="NARS's learning rounds (default 12)"
    )
    parser.add_argument("--out", type=Path, default=Path("robocog-demo"), metavar="DIR")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the results as JSON")
    parser.add_argument(
        "--budget",
        type=float,
        default=90.0,
        help="seconds of wall time for all runs (default 90): a slow mind runs fewer",
    )


def run(args: argparse.Namespace) -> int:
    """Run the demo; 0 when at least one mind ran (the demo says which could not, and why)."""
    from robocog.experiments.cli import run_garbage
    from robocog.experiments.garbage import default_minds

    print("robocog demo: seed 000's garbage field, NARS and a BDI agent with the same knowledge")
    result = run_garbage(
        default_minds(["bdi", "nars"]),  # the quick one first
        runs=max(1, args.runs),
        seed=args.seed,
        light=args.light,
        rounds=args.rounds,
        json_path=args.json,
        out=args.out,
        budget=args.budget if args.budget > 0 else None,
    )
    return 0 if any(m.runs for m in result.minds.values()) else 1
