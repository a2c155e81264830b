"""``robocog plan``: plan a pick-and-place task from sentences or from PDDL.

Examples::

    robocog plan --objects screw bolt washer workbench \\
        --facts "The workbench is a fixed object." \\
        --goal "The washer is on the screw. The bolt is on the washer."
    robocog plan --pddl domain.pddl task01.pddl --json

The planner knows no paper: ``--thesis TABLE`` (a table of Thiella 2021) is added to
this command by :mod:`robocog.experiments.plan_cli`, beside the tables it reads.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from robocog.argtypes import EXISTING_FILE, NEW_FILE, positive_int, seconds
from robocog.atomic import write_text
from robocog.planning.english import EnglishError
from robocog.planning.pddl import PDDLError, ground, read_domain, read_problem, scene_problem
from robocog.planning.pddl import read_file as read_pddl
from robocog.planning.planner import (
    ALL_MODES,
    Planner,
    PlanningError,
    PlanResult,
    goal_from_english,
    scene_from_english,
    solve_task,
)


def configure(parser: argparse.ArgumentParser) -> None:
    """Declare the arguments of ``robocog plan``."""
    parser.add_argument("--objects", nargs="+", default=[], help="names of the objects seen")
    parser.add_argument("--facts", default="", help="sentences of the learning phase")
    parser.add_argument("--goal", default=None, help="sentences of the request")
    parser.add_argument(
        "--pddl",
        nargs=2,
        type=EXISTING_FILE,
        metavar=("DOMAIN", "PROBLEM"),
        help="plan a PDDL task instead",
    )
    parser.add_argument("--mode", choices=ALL_MODES, default="astar", help="search (default astar)")
    parser.add_argument(
        "--max-iterations", type=positive_int(), default=None, help="for --mode bounded"
    )
    parser.add_argument(
        "--prune",
        choices=("global", "branch"),
        default="global",
        help="BFS: drop states seen anywhere (global) or only on the same branch (branch)",
    )
    parser.add_argument(
        "--goal-test",
        choices=("created", "taken"),
        default="created",
        help="BFS: test the goal when a state is created (default) or taken from the queue",
    )
    parser.add_argument("--max-seconds", type=seconds(), default=None, help="time limit for A*")
    parser.add_argument("--json", action="store_true", help="print the result as JSON")
    parser.add_argument(
        "--write-pddl",
        metavar="FILE",
        type=NEW_FILE,
        help="also write the scene and request as a 4-operator blocks PDDL problem",
    )


def _print(result: PlanResult, as_json: bool) -> None:
    if as_json:
        print(json.dumps(result.to_json()))
        return
    for line in result.lines():
        print(line)
    status = "optimal" if result.optimal else "not proven optimal"
    if not result.found:
        print(f"; {result.message}")
    print(
        f"; {result.length} actions, {status}, {result.iterations} iterations, "
        f"{result.seconds:.4f} s ({result.mode})"
    )


def run(args: argparse.Namespace) -> int:
    """Plan and print; exit status 0 with a plan, 1 without one, 2 on bad input."""
    try:
        if args.pddl:
            dom_path, prob_path = (Path(p) for p in args.pddl)
            domain = read_domain(read_pddl(dom_path), str(dom_path))
            problem = read_problem(read_pddl(prob_path), str(prob_path))
            task = ground(domain, problem)
            names = {a for lit in problem.goal for a in lit[1][1:]}
            result = solve_task(
                task,
                mode=args.mode,
                max_iterations=args.max_iterations,
                prune=args.prune,
                quick_names=names,
                max_seconds=args.max_seconds,
                style="pddl",
                goal_test=args.goal_test,
            )
        else:
            objects, facts, goal = list(args.objects), args.facts, args.goal
            if goal is None:
                print("robocog plan: give --goal sentences or --pddl", file=sys.stderr)
                return 2
            planner = Planner(max_seconds=args.max_seconds)
            scene = scene_from_english(objects, facts)
            if args.write_pddl:
                write_text(args.write_pddl, scene_problem(scene, goal_from_english(goal)))
            result = planner.plan(
                scene,
                goal,
                mode=args.mode,
                max_iterations=args.max_iterations,
                prune=args.prune,
                goal_test=args.goal_test,
            )
    except (PlanningError, EnglishError, PDDLError, OSError, KeyError) as exc:
        print(f"robocog plan: {exc}", file=sys.stderr)
        return 2
    learnt = result.extra.get("learnt_objects")
    if learnt:
        print(f"robocog plan: new objects from the request: {', '.join(learnt)}", file=sys.stderr)
    _print(result, args.json)
    return 0 if result.found else 1
