"""The manipulation planner against the thesis's figures and against two peer planners.

Part 1 plans Tables 5.2-5.10 of the thesis and the whole BlockB and BlockC assemblies
(one request each) and sets robocog's time and iterations beside the thesis's.

Part 2 solves the IPC-2000 4-operator blocks tasks with robocog (A* with its admissible
bound), pyperplan (A* with LM-cut) and Fast Downward (A* with LM-cut, the binary shipped
in the PyPI package up-fast-downward), one after the other in the same run, each with the
same time limit per task. Every plan is replayed by a validator written here from the
PDDL semantics (independent of the planner's grounding), and the table gives plan length,
expanded states and time, and the time ratios peer/robocog.

    python benchmarks/planner.py                 # everything, 60 s per task
    python benchmarks/planner.py --tasks 1-12 --timeout 10 --peers robocog,pyperplan
    python benchmarks/planner.py --json results.json
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from robocog.experiments.assembly_thesis import EXPERIMENTS, WHOLE_ASSEMBLIES
from robocog.planning.pddl import Domain, ground, read_domain, read_problem
from robocog.planning.planner import Planner, solve_task

ROOT = Path(__file__).resolve().parents[1]
BLOCKS = ROOT.parent / "shared" / "pddl" / "blocks"
MEMORY_LIMIT = 3 * 1024**3


@dataclass
class Run:
    """One planner on one task."""

    planner: str
    task: str
    solved: bool
    length: int | None
    expanded: int | None
    seconds: float
    valid: bool | None
    note: str = ""


# ------------------------------------------------------------------ validation


def validate(domain: Domain, problem_text: str, steps: list[str]) -> bool:
    """Replay *steps* (``(name arg ...)``) on sets of facts; True if the goal holds."""
    problem = read_problem(problem_text)
    state = set(problem.init)
    actions = {a.name: a for a in domain.actions}
    for step in steps:
        words = step.strip("() \n").lower().split()
        if not words or words[0] not in actions:
            return False
        action = actions[words[0]]
        if len(words) - 1 != len(action.parameters):
            return False
        bind = dict(zip((p for p, _ in action.parameters), words[1:], strict=True))

        def inst(atom: tuple[str, ...], bind: dict[str, str] = bind) -> tuple[str, ...]:
            return tuple(bind.get(t, t) for t in atom)

        for positive, atom in action.precondition:
            if (inst(atom) in state) != positive:
                return False
        state -= {inst(a) for p, a in action.effect if not p}
        state |= {inst(a) for p, a in action.effect if p}
    return all((atom in state) == positive for positive, atom in problem.goal)


# ------------------------------------------------------------------ planners


def _limit_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def run_robocog(domain: Domain, problem_text: str, name: str, timeout: float) -> Run:
    """robocog's A* in this process, with the time limit checked inside the search."""
    start = time.perf_counter()
    task = ground(domain, read_problem(problem_text))
    result = solve_task(task, "astar", max_seconds=timeout, style="pddl")
    seconds = time.perf_counter() - start
    steps = result.lines()
    return Run(
        "robocog",
        name,
        result.found,
        result.length if result.found else None,
        result.iterations,
        seconds,
        validate(domain, problem_text, steps) if result.found else None,
        "" if result.found else result.message,
    )


def run_pyperplan(
    domain_path: Path, problem_path: Path, name: str, timeout: float, domain: Domain
) -> Run:
    """pyperplan's A* with LM-cut in a subprocess (on copies: it writes a .soln file)."""
    exe = shutil.which("pyperplan")
    if exe is None:
        return Run("pyperplan", name, False, None, None, 0.0, None, "pyperplan not installed")
    with tempfile.TemporaryDirectory() as tmp:
        dom = Path(tmp) / "domain.pddl"
        prob = Path(tmp) / problem_path.name
        shutil.copy(domain_path, dom)
        shutil.copy(problem_path, prob)
        start = time.perf_counter()
        try:
            proc = subprocess.run(
                [exe, "-H", "lmcut", "-s", "astar", str(dom), str(prob)],
                capture_output=True,
                text=True,
                timeout=timeout,
                preexec_fn=_limit_memory,
            )
        except subprocess.TimeoutExpired:
            return Run("pyperplan", name, False, None, None, timeout, None, "timeout")
        seconds = time.perf_counter() - start
        soln = prob.with_suffix(prob.suffix + ".soln")
        log = proc.stdout + proc.stderr
        return _read_plan(
            "pyperplan", name, soln, seconds, log, r"(\d+) Nodes expanded", domain, problem_path
        )


def _read_plan(
    planner: str,
    name: str,
    plan_file: Path,
    seconds: float,
    log: str,
    expanded: str,
    domain: Domain,
    problem_path: Path,
) -> Run:
    """The run of a peer planner from the plan file it wrote and its log.

    Both peers write one ``(action args)`` line a step; their node counts are read from
    the log with *expanded* (one group), and their plans are replayed here, not trusted.
    """
    if not plan_file.exists():
        return Run(planner, name, False, None, None, seconds, None, "no plan")
    steps = [ln for ln in plan_file.read_text().splitlines() if ln.strip().startswith("(")]
    m = re.search(expanded, log)
    return Run(
        planner,
        name,
        True,
        len(steps),
        int(m.group(1)) if m else None,
        seconds,
        validate(domain, problem_path.read_text(), steps),
    )


def _downward_binary() -> Path | None:
    spec = importlib.util.find_spec("up_fast_downward")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(spec.submodule_search_locations[0]) / "downward/builds/release/bin/downward"
    return path if path.exists() else None


def run_downward(
    domain_path: Path, problem_path: Path, name: str, timeout: float, domain: Domain
) -> Run:
    """Fast Downward: its translator, then A* with LM-cut, within one time limit."""
    binary = _downward_binary()
    if binary is None or importlib.util.find_spec("fast_downward") is None:
        return Run("downward", name, False, None, None, 0.0, None, "up-fast-downward not installed")
    with tempfile.TemporaryDirectory() as tmp:
        sas = Path(tmp) / "output.sas"
        plan = Path(tmp) / "plan"
        start = time.perf_counter()
        try:
            subprocess.run(
                [
                    sys.executable,
                    "-m",
                    "fast_downward.translate",
                    str(domain_path),
                    str(problem_path),
                    "--sas-file",
                    str(sas),
                ],
                capture_output=True,
                text=True,
                timeout=timeout,
                check=True,
                cwd=tmp,
                preexec_fn=_limit_memory,
            )
            left = max(0.1, timeout - (time.perf_counter() - start))
            with sas.open() as stdin:
                proc = subprocess.run(
                    [str(binary), "--search", "astar(lmcut())", "--internal-plan-file", str(plan)],
                    stdin=stdin,
                    capture_output=True,
                    text=True,
                    timeout=left,
                    cwd=tmp,
                    preexec_fn=_limit_memory,
                )
        except subprocess.TimeoutExpired:
            return Run("downward", name, False, None, None, timeout, None, "timeout")
        except subprocess.CalledProcessError as exc:
            return Run("downward", name, False, None, None, 0.0, None, f"translate failed: {exc}")
        seconds = time.perf_counter() - start
        return _read_plan(
            "downward",
            name,
            plan,
            seconds,
            proc.stdout,
            r"Expanded (\d+) state",
            domain,
            problem_path,
        )


# ------------------------------------------------------------------ parts


def thesis_part() -> list[dict]:
    """Tables 5.2-5.10 and the whole assemblies: robocog against the thesis's figures."""
    rows = []
    planner = Planner()
    for exp in EXPERIMENTS + WHOLE_ASSEMBLIES:
        for mode in ("astar", "first", "quick"):
            best = math.inf
            result = None
            for _ in range(3):  # best of three, unless one run is already slow
                t0 = time.perf_counter()
                result = planner.plan_english(exp.objects, exp.facts, exp.request, mode=mode)
                best = min(best, time.perf_counter() - t0)
                if best > 1.0:
                    break
            assert result is not None
            rows.append(
                {
                    "table": exp.table,
                    "mode": mode,
                    "length": result.length,
                    "thesis_length": exp.length or None,
                    "same_plan": result.lines() == list(exp.plan) if exp.plan else None,
                    "optimal": result.optimal,
                    "iterations": result.iterations,
                    "thesis_iterations": exp.iterations,
                    "seconds": best,
                    "thesis_seconds": exp.seconds,
                }
            )
    return rows


def _parse_range(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def pddl_part(tasks: list[int], timeout: float, peers: list[str]) -> list[Run]:
    """Every task with every planner, sequentially, in this one run."""
    domain_path = BLOCKS / "domain.pddl"
    domain = read_domain(domain_path.read_text())
    runs: list[Run] = []
    for number in tasks:
        path = BLOCKS / f"task{number:02d}.pddl"
        name = f"task{number:02d}"
        text = path.read_text()
        for peer in peers:
            if peer == "robocog":
                run = run_robocog(domain, text, name, timeout)
            elif peer == "pyperplan":
                run = run_pyperplan(domain_path, path, name, timeout, domain)
            elif peer == "downward":
                run = run_downward(domain_path, path, name, timeout, domain)
            else:
                raise SystemExit(f"unknown planner {peer}")
            runs.append(run)
            print(
                f"  {name} {peer:9s} solved={run.solved!s:5s} len={run.length!s:4s} "
                f"expanded={run.expanded!s:8s} {run.seconds:8.3f}s valid={run.valid} {run.note}",
                file=sys.stderr,
                flush=True,
            )
    return runs


def _geomean(values: list[float]) -> float:
    values = [v for v in values if v > 0]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def report(thesis_rows: list[dict], runs: list[Run], peers: list[str]) -> str:
    """Markdown tables of both parts and the summary ratios."""
    out = ["## Thesis tables (robocog vs the thesis's OpenCog implementation)", ""]
    out.append(
        "| table | mode | length (thesis) | same plan | optimal | iterations (thesis) | time s (thesis) | speed-up |"
    )
    out.append("|---|---|---|---|---|---|---|---|")
    for r in thesis_rows:
        speed = f"{r['thesis_seconds'] / r['seconds']:.0f}x" if r["thesis_seconds"] else "-"
        out.append(
            f"| {r['table']} | {r['mode']} | {r['length']} ({r['thesis_length'] or '-'}) | "
            f"{r['same_plan'] if r['same_plan'] is not None else '-'} | {r['optimal']} | "
            f"{r['iterations']} ({r['thesis_iterations']}) | {r['seconds']:.4f} ({r['thesis_seconds']}) | {speed} |"
        )
    worst = max(r["seconds"] for r in thesis_rows if r["mode"] == "astar")
    out += ["", f"slowest table with A*: {worst * 1000:.1f} ms", ""]
    if not runs:
        return "\n".join(out)
    out += ["## IPC-2000 blocks, 4 operators", ""]
    head = "| task |" + "".join(f" {p} len | {p} expanded | {p} s |" for p in peers)
    out += [head, "|---|" + "---|---|---|" * len(peers)]
    by = {(r.task, r.planner): r for r in runs}
    names = sorted({r.task for r in runs})
    for name in names:
        row = f"| {name} |"
        for p in peers:
            r = by.get((name, p))
            if r is None or not r.solved:
                row += f" - | - | {r.note if r else ''} |"
            else:
                mark = "" if r.valid else " INVALID"
                row += f" {r.length}{mark} | {r.expanded} | {r.seconds:.3f} |"
        out.append(row)
    out.append("")
    for p in peers:
        solved = [by[(n, p)] for n in names if by[(n, p)].solved and by[(n, p)].valid]
        out.append(f"- {p}: {len(solved)}/{len(names)} solved with valid plans")
    # optimality: where a peer's A*+LM-cut (optimal) solved, lengths must agree
    mismatches = [
        n
        for n in names
        for p in peers
        if p != "robocog"
        and by[(n, p)].solved
        and by[(n, "robocog")].solved
        and by[(n, p)].length != by[(n, "robocog")].length
    ]
    out.append(f"- length disagreements with the optimal peers: {mismatches or 'none'}")
    for p in peers:
        if p == "robocog":
            continue
        both = [n for n in names if by[(n, p)].solved and by[(n, "robocog")].solved]
        if both:
            ratio = _geomean(
                [by[(n, p)].seconds / max(by[(n, "robocog")].seconds, 1e-6) for n in both]
            )
            out.append(
                f"- time {p}/robocog on the {len(both)} tasks both solved: geometric mean {ratio:.1f}x"
            )
    total = sum(by[(n, "robocog")].seconds for n in names)
    out.append(f"- robocog total time: {total:.2f} s")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    """Run both parts and print the report (and save JSON if asked)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tasks", default="1-35", help="task numbers, e.g. 1-35 or 1,5,9")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per task and planner")
    ap.add_argument("--peers", default="robocog,pyperplan,downward")
    ap.add_argument("--no-pddl", action="store_true", help="only the thesis tables")
    ap.add_argument("--json", type=Path, help="also write the raw results here")
    args = ap.parse_args(argv)
    peers = [p.strip() for p in args.peers.split(",") if p.strip()]
    if "robocog" not in peers:
        peers.insert(0, "robocog")
    thesis_rows = thesis_part()
    runs: list[Run] = []
    if not args.no_pddl:
        if not (BLOCKS / "domain.pddl").exists():
            print(f"no blocks tasks at {BLOCKS}", file=sys.stderr)
        else:
            runs = pddl_part(_parse_range(args.tasks), args.timeout, peers)
    print(report(thesis_rows, runs, peers))
    if args.json:
        args.json.write_text(
            json.dumps({"thesis": thesis_rows, "pddl": [asdict(r) for r in runs]}, indent=1)
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
