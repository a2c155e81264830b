"""The CPU time of the NARS engine's declarative inference on a selected event, in the
robot loop's work.

Runs NarsMind on the garbage field (the missions of ``robot_loop.py``, seeds 0..N-1)
and measures, in CPU time, the whole run and the part spent in
``cycle.semantic_inference`` (the rules on the selected event and the related
concepts' beliefs, and the storing of what they conclude), which was a third of an
input cycle. The input cycles and the plain cycles that NarsMind asks for are timed
too. To compare two builds, run it alternately with each on the path, e.g.

    PYTHONPATH=src python benchmarks/nars_inference.py
    PYTHONPATH=/path/to/other/checkout/src python benchmarks/nars_inference.py

and read the ratio of the inference figures (the machine's load moves both alike).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from typing import Any

import robocog.nars as nars
from robocog.minds import registry
from robocog.nars import cycle
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig, GarbageField

clock = time.process_time


class _Timed:
    """Wraps the reasoner of a mind, adding the CPU time of its inputs and cycles."""

    def __init__(self, nar: Any, totals: dict[str, float]) -> None:
        self._nar = nar
        self._totals = totals

    def __getattr__(self, name: str) -> Any:
        return getattr(self._nar, name)

    def _timed(self, key: str, f: Callable[..., Any], *args: Any) -> Any:
        start = clock()
        try:
            return f(*args)
        finally:
            self._totals[key] += clock() - start
            self._totals[key + " calls"] += 1

    def add_sentence(self, sentence: Any) -> Any:
        return self._timed("input", self._nar.add_sentence, sentence)

    def cycles(self, n: int) -> Any:
        return self._timed("cycles", self._nar.cycles, n)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="missions (seeds 0..runs-1)")
    args = parser.parse_args()
    totals = dict.fromkeys(["inference", "input", "cycles"], 0.0)
    totals.update(dict.fromkeys(["inference calls", "input calls", "cycles calls"], 0.0))
    inner = cycle.semantic_inference

    def timed_inference(*a: Any) -> None:
        start = clock()
        inner(*a)
        totals["inference"] += clock() - start
        totals["inference calls"] += 1

    # ``cycle.cycle`` finds the step by its module's name at each call
    cycle.semantic_inference = timed_inference
    config = GarbageConfig(light="sunny")
    start = clock()
    frames = 0
    for seed in range(args.runs):
        world = GarbageField(config, seed=seed)
        mind = registry.make(registry.MindConfig("nars", seed, places=tuple(world.route)))
        mind.nar = _Timed(mind.nar, totals)
        steps = int(config.mission_time / config.frame_seconds) + 10
        frames += Loop(world, mind).run(steps, until=lambda w=world: w.done)
    whole = clock() - start
    print(f"engine: {nars.ENGINE}; {args.runs} missions, {frames} frames, CPU seconds")
    print(f"  whole run {whole:.2f}")
    for key in ("inference", "input", "cycles"):
        n = int(totals[key + " calls"])
        print(
            f"  {key:<9} {totals[key]:.2f} in {n} calls ({totals[key] / max(n, 1) * 1e6:.0f} us each)"
        )


if __name__ == "__main__":
    main()
