"""Sweep throughput: missions per second in this process, in a local process pool and on
a local Ray cluster with one and two workers, over the same missions.

Each executor runs the same sweep (BDI missions on the garbage field unless ``--minds``
says otherwise) into a fresh table; the in-process run is the reference, and an
executor's overhead per task is its wall time per mission times its workers minus the
reference's time per mission (what a task costs beyond the mission itself: shipping it,
starting workers, returning the row). Every executor's table must equal the
reference's, or the benchmark stops.

    python benchmarks/sweep.py                       # 40 BDI missions per executor
    python benchmarks/sweep.py --minds nars --runs 10
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

from robocog.experiments.sweep import (
    Executor,
    SweepSpec,
    in_process,
    parse_axis,
    process_pool,
    ray_cluster,
    run_sweep,
)


def measure(spec: SweepSpec, execute: Executor, folder: Path, name: str) -> tuple[float, list]:
    """Wall seconds of the whole sweep with ``execute``, and its table."""
    start = time.perf_counter()
    rows = run_sweep(spec, folder / f"{name}.jsonl", execute)
    return time.perf_counter() - start, rows


def main() -> None:
    """Run the executors one after another and print a table of their figures."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minds", default="nars,bdi")
    parser.add_argument("--runs", type=int, default=10, help="missions per mind and level")
    parser.add_argument("--no-ray", action="store_true")
    args = parser.parse_args()
    spec = SweepSpec(
        "garbage",
        (parse_axis("detection=0.6,0.9"),),
        tuple(args.minds.split(",")),
        args.runs,
        1,
        fixed=(("light", "sunny"),),
    )
    executors: list[tuple[str, int, Executor]] = [
        ("this process", 1, in_process),
        ("process pool, 1 worker", 1, process_pool(1)),
        ("process pool, 2 workers", 2, process_pool(2)),
    ]
    ray = None
    if not args.no_ray:
        try:
            import ray
        except ImportError:
            print("Ray is not installed: pip install 'robocog[cluster]'")
    print(f"{spec.missions} missions ({args.minds}) per executor, {os.cpu_count()} CPUs")
    print(f"{'executor':26} {'wall s':>8} {'missions/s':>11} {'overhead ms/task':>17}")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        run_sweep(spec, folder / "warm.jsonl", in_process)  # imports and first-use costs
        reference: list | None = None
        per_mission = 0.0

        def report(name: str, workers: int, execute: Executor, index: int) -> None:
            nonlocal reference, per_mission
            wall, rows = measure(spec, execute, folder, f"t{index}")
            if reference is None:
                reference, per_mission = rows, wall / spec.missions
            elif rows != reference:
                raise SystemExit(f"{name}: the table differs from the in-process one")
            overhead = (wall * workers / spec.missions - per_mission) * 1000
            print(f"{name:26} {wall:8.2f} {spec.missions / wall:11.2f} {overhead:17.1f}")

        for i, (name, workers, execute) in enumerate(executors):
            report(name, workers, execute, i)
        if ray is not None:
            for workers in (1, 2):
                start = time.perf_counter()
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
                ray.get(ray.remote(lambda: None).remote())  # a first task starts a worker
                started = time.perf_counter() - start
                report(
                    f"Ray (local), {workers} worker(s)", workers, ray_cluster(None), 10 + workers
                )
                ray.shutdown()
                print(f"{'':26} (Ray's start-up, not counted above: {started:.1f} s)")


if __name__ == "__main__":
    main()
