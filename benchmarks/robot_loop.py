"""The NARS mind's perception-reason-action cycle on the garbage task, beside ONA's.

Runs NarsMind on the garbage field of Hammer et al. through ``robocog.robot.loop.Loop`` and
reports the p50 and p99 of the whole cycle (percepts, perceive + decide, the actions and
the mind's handling of their outcomes, which feeds the reasoner too) and of its first
part up to the decision ("reason"); the goal is on the whole cycle. In the same run the
same mind drives the same fields with ONA 0.9.2 (PyPI ``ona``, ``NAR shell`` as a child
process) as its reasoner, so the ratio compares the reasoners under the same encodings,
goals and world; ONA's figures include the pipe to its process. Both minds' success
rates are printed too, since they come out of the same runs.

ONA is driven through ``robocog.minds.ona_shell`` (which gives it the first background
rule with the brackets its reader needs; see there).

    python benchmarks/robot_loop.py                 # 5 missions each
    python benchmarks/robot_loop.py --runs 30 --json robot_loop.json
    python benchmarks/robot_loop.py --again         # and robocog's missions once more

The first missions of a process meet every term, premise pair and premise shape for the
first time; what the engine works out about them once (a term's properties and variable
forms, a pair's conclusions, a shape's rules) is kept for the process's reasoners. With
``--again`` robocog's missions run a second time in the same process, as a robot that has
run for a while would, and that pass is reported on a row of its own; the goal is read on
the first pass.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

from robocog.minds import registry
from robocog.nars import ENGINE
from robocog.robot.loop import Loop, percentile
from robocog.worlds.garbage import GarbageConfig, GarbageField


def measure(  # noqa: ANN001
    name: str, make, runs: int, seed: int, config: GarbageConfig, in_process: bool = True
) -> dict:
    """Missions of one reasoner: cycle-time percentiles over all cycles, and the rate."""
    reason: list[float] = []
    cycle: list[float] = []
    cycle_cpu: list[float] = []
    collected = placed = 0
    start = time.perf_counter()
    for i in range(runs):
        world = GarbageField(config, seed=seed + i)
        mind, close = make(world, seed + i)
        loop = Loop(world, mind)
        loop.run(int(config.mission_time / config.frame_seconds) + 10, until=lambda w=world: w.done)
        close()
        reason += loop.stats.reason
        cycle += loop.stats.cycle
        cycle_cpu += loop.stats.cycle_cpu
        collected += world.collected()
        placed += len(world.objects())
    return {
        "reasoner": name,
        "runs": runs,
        "cycles": len(cycle),
        "reason_p50_ms": percentile(reason, 50) * 1e3,
        "reason_p99_ms": percentile(reason, 99) * 1e3,
        "cycle_p50_ms": percentile(cycle, 50) * 1e3,
        "cycle_p99_ms": percentile(cycle, 99) * 1e3,
        # this process's CPU time: meaningless for a reasoner in another process
        "cycle_cpu_p99_ms": percentile(cycle_cpu, 99) * 1e3 if in_process else None,
        "success_rate": collected / placed if placed else None,
        "wall_seconds": time.perf_counter() - start,
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="missions per reasoner")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--light", default="sunny", choices=("sunny", "cloudy", "evening"))
    parser.add_argument("--json", type=Path, help="write the figures as JSON")
    parser.add_argument(
        "--again", action="store_true", help="run robocog's missions a second time, warm"
    )
    args = parser.parse_args(argv)
    config = GarbageConfig(light=args.light)
    results = []

    why = registry.probe("nars")
    if why:
        print(f"robocog NARS: cannot run yet - {why}")
    else:

        def make_robocog(world: GarbageField, seed: int):  # noqa: ANN202
            config = registry.MindConfig("nars", seed, places=tuple(world.route))
            return registry.make(config), lambda: None

        results.append(measure("robocog", make_robocog, args.runs, args.seed, config))
        if args.again:
            again = measure("robocog", make_robocog, args.runs, args.seed, config)
            again["reasoner"] = "  again"

    why_not_ona = registry.probe("ona")
    if why_not_ona is None:

        def make_ona(world: GarbageField, seed: int):  # noqa: ANN202
            mind = registry.make(registry.MindConfig("ona", seed, places=tuple(world.route)))
            return mind, mind.close  # type: ignore[attr-defined]

        results.append(
            measure("ONA 0.9.2", make_ona, args.runs, args.seed, config, in_process=False)
        )
    else:
        print(f"ONA: {why_not_ona}")
    ona = results[-1] if results and results[-1]["reasoner"].startswith("ONA") else None
    if not why and args.again:
        results.insert(1, again)

    print(f"garbage field, {args.light} light, {args.runs} missions per reasoner")
    print(f"robocog NARS engine: {ENGINE}")
    print(
        f"{'reasoner':<12}{'cycles':>8}{'reason p50':>12}{'reason p99':>12}"
        f"{'cycle p50':>11}{'cycle p99':>11}{'CPU p99':>10}{'success':>9}"
    )
    for r in results:
        rate = "-" if r["success_rate"] is None else f"{100 * r['success_rate']:.0f}%"
        cpu = "-" if r["cycle_cpu_p99_ms"] is None else f"{r['cycle_cpu_p99_ms']:.2f}ms"
        print(
            f"{r['reasoner']:<12}{r['cycles']:>8}{r['reason_p50_ms']:>10.2f}ms"
            f"{r['reason_p99_ms']:>10.2f}ms{r['cycle_p50_ms']:>9.2f}ms"
            f"{r['cycle_p99_ms']:>9.2f}ms{cpu:>10}{rate:>9}"
        )
    if ona is not None and results[0]["reasoner"] == "robocog":
        ratio = ona["cycle_p99_ms"] / max(1e-9, results[0]["cycle_p99_ms"])
        print(f"cycle p99 ratio ONA / robocog: {ratio:.2f} (above 1: robocog is faster)")
    if results and results[0]["reasoner"] == "robocog":
        # the whole cycle: percepts, the mind's reasoning on them, the actions and the
        # mind's reasoning on their outcomes (the world's own step costs ~0.1 ms)
        goal = "met" if results[0]["cycle_p99_ms"] < 20 else "not met"
        print(f"goal: whole-cycle p99 < 20 ms: {goal}")
    if args.json:
        args.json.write_text(json.dumps(results, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
