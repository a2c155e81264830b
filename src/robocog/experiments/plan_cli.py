"""``robocog plan``: the planner's command, with the thesis's tables at hand (``--thesis``).

The planner is a library that knows no paper, so its command
(:mod:`robocog.planning.cli`) plans sentences and PDDL only. The tables of Thiella
(2021) are the assembly experiment's data (:mod:`robocog.experiments.assembly_thesis`);
this module, which may import both, adds ``--thesis TABLE`` by filling in the table's
objects, facts and request, and hands the rest to the planner's command.
"""

from __future__ import annotations

import argparse
import sys

from robocog.experiments.assembly_thesis import EXPERIMENTS, WHOLE_ASSEMBLIES, experiment
from robocog.planning import cli as planning_cli


def configure(parser: argparse.ArgumentParser) -> None:
    """The planner's arguments and ``--thesis``."""
    planning_cli.configure(parser)
    parser.add_argument(
        "--thesis",
        metavar="TABLE",
        choices=[exp.table for exp in EXPERIMENTS + WHOLE_ASSEMBLIES],
        help="plan one of the thesis's tables (5.2 ... 5.10, BlockB, BlockC)",
    )


def run(args: argparse.Namespace) -> int:
    """Plan a table of the thesis, or whatever else the arguments ask for."""
    if args.thesis and not args.pddl:
        try:
            exp = experiment(args.thesis)
        except KeyError as exc:
            print(f"robocog plan: {exc}", file=sys.stderr)
            return 2
        args.objects, args.facts, args.goal = list(exp.objects), exp.facts, exp.request
    elif args.goal is None and not args.pddl:
        print("robocog plan: give --goal sentences, --pddl or --thesis", file=sys.stderr)
        return 2
    return planning_cli.run(args)
