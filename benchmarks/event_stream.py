"""An endless sensorimotor stream: is robocog's NARS still bounded after 10^6 events?

A small seeded world feeds the reasoner what a robot's sensors would: each step one to
three present-tense events (where it is, trash in view, and now and then a reading under
a name never seen before, so the concept store must forget), now and then a goal, and
whatever operation the reasoner executes (or babbles) changes what it senses next, so
temporal and procedural implications are learned, revised and anticipated all along.
Every input runs one cycle, as in ONA's shell. The benchmark reports the p50/p99 time
of an input (its cycle included) over the first and the last ``--window`` events, the
most concepts ever held against the capacity, the implications held, and the peak
resident memory every tenth of the run.

    python benchmarks/event_stream.py --events 1000000
    python benchmarks/event_stream.py --events 50000 --window 5000   # a quick look
"""

from __future__ import annotations

import argparse
import gc
import random
import resource
import statistics
import sys
import time

from robocog.nars import ENGINE, NAR

OPERATIONS = ("^left", "^right", "^pick")


class SensorWorld:
    """Places on a ring; ``^left``/``^right`` move, ``^pick`` clears trash; now and then
    a reading with a name never seen before, so concepts must be forgotten for good."""

    def __init__(self, seed: int, places: int = 12, readings: int = 16, fresh: float = 0.0) -> None:
        self.rng = random.Random(seed)
        self.places = places
        self.readings = readings
        self.fresh_rate = fresh
        self.fresh = 0
        self.at = 0
        self.trash = set(self.rng.sample(range(places), places // 4))

    def act(self, op: str) -> None:
        """Apply an executed operation."""
        if op == "^left":
            self.at = (self.at - 1) % self.places
        elif op == "^right":
            self.at = (self.at + 1) % self.places
        elif op == "^pick" and self.at in self.trash and self.rng.random() < 0.85:
            self.trash.discard(self.at)
        if self.rng.random() < 0.02:  # trash keeps arriving
            self.trash.add(self.rng.randrange(self.places))

    def events(self) -> list[str]:
        """What the sensors report at this step."""
        out = [f"<p{self.at} --> [at]>. :|:"]
        if self.at in self.trash:
            out.append("<trash --> [seen]>. :|:")
        if self.rng.random() < 0.5:  # one of the sensors' usual readings
            out.append(f"<r{self.rng.randrange(self.readings)} --> [on]>. :|:")
        if self.rng.random() < self.fresh_rate:  # a name never seen before, and never again
            self.fresh += 1
            out.append(f"<r{self.fresh} --> [on]>. :|:")
        return out


def p(xs: list[float], q: int) -> float:
    """The ``q``-th percentile in milliseconds."""
    return statistics.quantiles(xs, n=100)[q - 1] * 1e3 if len(xs) >= 100 else max(xs) * 1e3


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--events", type=int, default=1_000_000)
    ap.add_argument("--window", type=int, default=10_000, help="events timed at each end")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument(
        "--fresh", type=float, default=0.0, help="chance per step of a reading never seen before"
    )
    args = ap.parse_args(argv)

    gc.set_threshold(50_000, 20, 100)  # fewer cycle collections than the default
    world = SensorWorld(args.seed, fresh=args.fresh)
    nar = NAR(seed=args.seed)
    nar.output = None
    executed: list[str] = []
    for op in OPERATIONS:
        nar.register_operation(op, lambda *_a, op=op: executed.append(op))
    first: list[float] = []
    last: list[float] = []
    biggest = implications = 0
    fed = goals = 0
    t0 = time.perf_counter()
    report_every = max(1, args.events // 10)
    next_report = report_every
    while fed < args.events:
        lines = world.events()
        if fed % 7 == 0:
            lines.append("<trash --> [seen]>! :|:")
            goals += 1
        for line in lines:
            t = time.perf_counter()
            nar.add_input(line)
            dt = time.perf_counter() - t
            if fed < args.window:
                first.append(dt)
            elif fed >= args.events - args.window:
                last.append(dt)
            fed += 1
        for op in executed:
            world.act(op)
        executed.clear()
        biggest = max(biggest, len(nar.memory))
        if fed >= next_report:
            next_report += report_every
            implications = sum(
                len(t) for c in nar.memory if c.precondition_beliefs for t in c.precondition_beliefs
            )
            rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
            print(
                f"{fed:>9} events  {len(nar.memory):>5} concepts  {implications:>6} implications"
                f"  peak RSS {rss:.0f} MB  {time.perf_counter() - t0:.0f} s",
                flush=True,
            )
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"robocog NARS engine: {ENGINE}")
    print(f"events {fed} ({goals} goals), wall {time.perf_counter() - t0:.0f} s")
    print(f"concepts max {biggest} (capacity {nar.memory.capacity}), peak RSS {rss:.0f} MB")
    print(
        f"time per event, its cycle included: first {len(first)}: p50 {p(first, 50):.2f} ms"
        f" p99 {p(first, 99):.2f} ms; last {len(last)}: p50 {p(last, 50):.2f} ms"
        f" p99 {p(last or first, 99):.2f} ms"
    )
    return 0 if biggest <= nar.memory.capacity else 1


if __name__ == "__main__":
    sys.exit(main())
