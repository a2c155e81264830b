"""Procedure learning: ONA's system-test worlds driven by robocog's NAR and by ONA.

Runs each world of ``robocog.worlds.procedures`` for the number of steps of ONA's reference
runs with every reasoner in the same process: ONA's ``NAR shell`` through pipes,
robocog's ``NAR`` (skipped, with the reason, while it cannot execute learned
procedures), and, as a reference, ONA's own built-in test (``NAR pong 10000`` ...).
Prints a table of success figures and wall times with the ratio of each reasoner's time
to the ONA shell's. See docs/procedure_learning.md.

    python benchmarks/procedure_learning.py                       # the five reference runs
    python benchmarks/procedure_learning.py --envs pong,alien --steps 2000 --json out.json
    python benchmarks/procedure_learning.py --runs 3              # seeds 0, 1, 2: mean ± sd
"""

from __future__ import annotations

import argparse
import json
import platform
import random
import statistics
import time
from dataclasses import asdict
from pathlib import Path
from typing import Any

from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from robocog.experiments.procedures.ona_builtin import has_builtin, run_builtin
from robocog.experiments.procedures.reasoners import (
    OnaShell,
    PolicyReasoner,
    Reasoner,
    ReasonerError,
    ReasonerUnavailable,
    RobocogNar,
    TracingReasoner,
)
from robocog.worlds.procedures import ENVIRONMENTS, ProcedureEnv, run

#: ONA's published figures for these worlds: steps, headline figure, other figures.
REFERENCE: dict[str, tuple[int, float | None, dict[str, float]]] = {
    "pong": (10_000, 0.82, {}),
    "pong2": (10_000, 0.95, {}),
    "alien": (10_000, 0.99, {}),
    "cartpole": (10_000, 0.83, {}),
    "robot": (1_200, 0.27, {"eaten": 46}),
    "bandrobot": (2_000, None, {}),
}
DEFAULT_ENVS = ("pong", "pong2", "alien", "cartpole", "robot")
REASONERS = ("ona-shell", "robocog", "ona-builtin", "random")
DEFAULT_REASONERS = ("ona-shell", "robocog", "ona-builtin")
BASELINE = "ona-shell"


def _random_policy(seed: int) -> PolicyReasoner:
    """Each goal answered by a random operation or none: the chance level of a world."""
    rng = random.Random(seed)

    def choose(env: ProcedureEnv) -> str | None:
        return rng.choice([*env.operations, None])

    return PolicyReasoner(choose, name="random")


def _make(reasoner: str, seed: int) -> Reasoner:
    if reasoner == "ona-shell":
        return OnaShell()
    if reasoner == "robocog":
        return RobocogNar()
    if reasoner == "random":
        return _random_policy(seed)
    raise ValueError(reasoner)


def _unavailable(reasoner: str) -> str | None:
    if reasoner in ("ona-shell", "ona-builtin"):
        return OnaShell.unavailable_reason()
    if reasoner == "robocog":
        return RobocogNar.unavailable_reason()
    return None


def describe(env: str, metrics: dict[str, float]) -> str:
    """The counts behind the headline figure, the way ONA's test prints them."""
    m = {k: v for k, v in metrics.items() if isinstance(v, int | float)}
    if env in ("pong", "pong2"):
        hits = m.get("hits", m.get("successes", 0))
        return f"hits={hits:.0f} misses={m.get('misses', 0):.0f}"
    if env == "alien":
        return f"hits={m.get('hits', 0):.0f} shots={m.get('shots', 0):.0f}"
    if env == "cartpole":
        return f"successes={m.get('successes', 0):.0f} failures={m.get('failures', 0):.0f}"
    if env == "robot":
        return f"moves={m.get('moves', 0):.0f} eaten={m.get('eaten', 0):.0f}"
    if env == "bandrobot":
        return f"deliveries={m.get('ratio', 0):.0f}"
    return ""


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    """Command-line options."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--envs",
        default=",".join(DEFAULT_ENVS),
        help=f"comma-separated environments among {', '.join(ENVIRONMENTS)} (default: %(default)s)",
    )
    parser.add_argument(
        "--steps",
        type=int,
        default=None,
        help="steps per run (default: the steps of ONA's reference run of each world)",
    )
    parser.add_argument(
        "--seed", type=int, default=0, help="seed of the worlds (both NARs keep ONA's seed, 666)"
    )
    parser.add_argument(
        "--reasoners",
        default=",".join(DEFAULT_REASONERS),
        help=f"comma-separated among {', '.join(REASONERS)} (default: %(default)s)",
    )
    parser.add_argument(
        "--runs", type=int, default=1, help="runs per world and reasoner, seeds seed, seed+1, ..."
    )
    parser.add_argument(
        "--time-limit",
        type=float,
        default=None,
        help="stop a run after this many seconds and report the figures reached",
    )
    parser.add_argument(
        "--trace",
        type=Path,
        default=None,
        help="write each run's inputs and executed operations to DIR/<world>-<reasoner>-<seed>.nal",
    )
    parser.add_argument(
        "--json", type=Path, default=None, help="also write the results to this file"
    )
    args = parser.parse_args(argv)
    args.envs = [e.strip() for e in args.envs.split(",") if e.strip()]
    args.reasoners = [r.strip() for r in args.reasoners.split(",") if r.strip()]
    for env in args.envs:
        if env not in ENVIRONMENTS:
            parser.error(f"unknown environment {env!r}; known: {', '.join(ENVIRONMENTS)}")
    for reasoner in args.reasoners:
        if reasoner not in REASONERS:
            parser.error(f"unknown reasoner {reasoner!r}; known: {', '.join(REASONERS)}")
    if args.steps is not None and args.steps <= 0:
        parser.error("--steps must be positive")
    if args.runs <= 0:
        parser.error("--runs must be positive")
    return args


def _run_one(
    env_name: str,
    reasoner_name: str,
    steps: int,
    seed: int,
    advance: Any,
    trace: Path | None = None,
    time_limit: float | None = None,
) -> dict[str, Any]:
    """One run as a JSON-ready row (ONA's built-in test has its own fixed seed)."""
    if reasoner_name == "ona-builtin":
        built = run_builtin(env_name, steps, on_step=advance)
        return {
            "env": env_name,
            "reasoner": reasoner_name,
            "steps": steps,
            "seed": None,
            "metrics": built.metrics,
            "wall_time": built.wall_time,
            "operations": {},
            "completed_steps": steps,
        }
    env = ENVIRONMENTS[env_name](seed)
    reasoner = _make(reasoner_name, seed)
    if trace is not None:
        trace.mkdir(parents=True, exist_ok=True)
        reasoner = TracingReasoner(reasoner, trace / f"{env_name}-{reasoner_name}-{seed}.nal")
    return asdict(run(env, reasoner, steps, seed, advance, time_limit))


def run_all(args: argparse.Namespace, console: Console) -> dict[str, Any]:
    """Every environment with every available reasoner; returns the report as data."""
    skipped = {r: why for r in args.reasoners if (why := _unavailable(r))}
    for reasoner, why in skipped.items():
        console.print(f"[yellow]skipping {reasoner}:[/] {why}")
    plan = [
        (env, reasoner, args.steps or REFERENCE[env][0])
        for env in args.envs
        for reasoner in args.reasoners
        if reasoner not in skipped and (reasoner != "ona-builtin" or has_builtin(env))
    ]
    results: list[dict[str, Any]] = []
    columns = (
        TextColumn("{task.description:<24}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=console, transient=False) as progress:
        seeds = {key: _seeds(args, key[1]) for key in plan}
        tasks = {
            key: progress.add_task(f"{key[0]} / {key[1]}", total=key[2] * len(seeds[key]))
            for key in plan
        }
        for key in plan:
            env_name, reasoner_name, steps = key
            task = tasks[key]
            for done, seed in enumerate(seeds[key]):

                def advance(k: int, task: Any = task, steps: int = steps, done: int = done) -> None:
                    if k % 50 == 0 or k == steps:
                        progress.update(task, completed=done * steps + k)

                try:
                    row = _run_one(
                        env_name, reasoner_name, steps, seed, advance, args.trace, args.time_limit
                    )
                except (ReasonerError, ReasonerUnavailable, RuntimeError) as exc:
                    console.print(f"[red]{env_name} / {reasoner_name} failed:[/] {exc}")
                    row = {"env": env_name, "reasoner": reasoner_name, "steps": steps}
                    row.update(seed=seed, error=str(exc))
                results.append(row)
            progress.update(task, completed=steps * len(seeds[key]))
    return {
        "benchmark": "procedure_learning",
        "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "python": platform.python_version(),
        "machine": platform.machine(),
        "seed": args.seed,
        "runs": args.runs,
        "skipped": skipped,
        "reference": {k: {"steps": v[0], "ratio": v[1], **v[2]} for k, v in REFERENCE.items()},
        "results": results,
    }


def _seeds(args: argparse.Namespace, reasoner: str) -> list[int]:
    """The seeds of a reasoner's runs; ONA's built-in tests have one fixed seed."""
    if reasoner == "ona-builtin":
        return [args.seed]
    return [args.seed + i for i in range(args.runs)]


def summarise(report: dict[str, Any]) -> list[dict[str, Any]]:
    """One entry per world and reasoner: mean figures over its runs, spread, mean time."""
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row in report["results"]:
        groups.setdefault((row["env"], row["reasoner"]), []).append(row)
    summary = []
    for (env, reasoner), rows in groups.items():
        good = [r for r in rows if "error" not in r]
        entry: dict[str, Any] = {"env": env, "reasoner": reasoner, "steps": rows[0]["steps"]}
        entry["runs"] = len(good)
        if not good:
            entry["error"] = rows[0]["error"]
            summary.append(entry)
            continue
        keys = [k for k, v in good[0]["metrics"].items() if isinstance(v, int | float)]
        entry["metrics"] = {k: statistics.fmean(float(r["metrics"][k]) for r in good) for k in keys}
        figures = [float(r["metrics"]["ratio"]) for r in good]
        entry["figures"] = figures
        entry["spread"] = statistics.stdev(figures) if len(figures) > 1 else 0.0
        entry["wall_time"] = statistics.fmean(r["wall_time"] for r in good)
        entry["completed_steps"] = min(r.get("completed_steps", r["steps"]) for r in good)
        summary.append(entry)
    baseline = {
        e["env"]: e["wall_time"] for e in summary if e["reasoner"] == BASELINE and "wall_time" in e
    }
    for entry in summary:
        base = baseline.get(entry["env"])
        if base and "wall_time" in entry:
            entry["time_ratio"] = entry["wall_time"] / base
    return summary


def render(summary: list[dict[str, Any]]) -> Table:
    """The results table: one row per world and reasoner."""
    table = Table(title="Procedure learning (ONA system-test worlds)")
    for header, justify in (
        ("world", "left"),
        ("steps", "right"),
        ("reasoner", "left"),
        ("runs", "right"),
        ("figure", "right"),
        ("counts (mean)", "left"),
        ("ONA ref.", "right"),
        ("wall s", "right"),
        (f"t / {BASELINE}", "right"),
    ):
        table.add_column(header, justify=justify)  # type: ignore[arg-type]
    for entry in summary:
        env = entry["env"]
        ref_steps, ref_ratio, ref_extra = REFERENCE[env]
        reference = "" if ref_ratio is None else f"{ref_ratio:.2f}"
        if ref_extra:
            reference += " " + " ".join(f"{k}={v:g}" for k, v in ref_extra.items())
        if ref_steps != entry["steps"]:
            reference += f" @{ref_steps}"
        steps = str(entry["steps"])
        if entry.get("completed_steps", entry["steps"]) < entry["steps"]:
            steps = f"{entry['completed_steps']} of {steps}, stopped"
        head = [env, steps, entry["reasoner"], str(entry["runs"])]
        if "error" in entry:
            table.add_row(*head, "failed", entry["error"][:60], reference, "", "")
            continue
        digits = 0 if env == "bandrobot" else 3
        figure = f"{entry['metrics']['ratio']:.{digits}f}"
        if entry["runs"] > 1:
            figure += f" ± {entry['spread']:.{digits}f}"
        speed = f"{entry['time_ratio']:.2f}" if "time_ratio" in entry else ""
        table.add_row(
            *head,
            figure,
            describe(env, entry["metrics"]),
            reference,
            f"{entry['wall_time']:.1f}",
            speed,
        )
    return table


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark, print the table, optionally save JSON."""
    args = parse_args(argv)
    console = Console()
    if not console.is_terminal:
        console = Console(width=132)
    report = run_all(args, console)
    report["summary"] = summarise(report)
    console.print(render(report["summary"]))
    for reasoner, why in report["skipped"].items():
        console.print(f"{reasoner}: not run ({why})")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        tmp = args.json.with_suffix(args.json.suffix + ".tmp")
        tmp.write_text(json.dumps(report, indent=2) + "\n")
        tmp.replace(args.json)
        console.print(f"results written to {args.json}")
    return 1 if any("error" in r for r in report["results"]) else 0


if __name__ == "__main__":
    raise SystemExit(main())
