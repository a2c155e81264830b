"""The sense-decide-act loop that joins a Body and a Mind, and measures every cycle.

One cycle: read the body's percepts, let the mind perceive and decide, execute each
command on the body and hand its outcome back to the mind. The loop keeps the time the
mind took (perceive + decide) and the time of the whole cycle, because the first is what
a reasoner costs and the second is what the robot feels.
"""

from __future__ import annotations

import gc
import statistics
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from robocog.robot.commands import Command, Outcome
from robocog.robot.protocols import Body, Mind


def percentile(values: list[float], q: float) -> float:
    """The q-th percentile (0..100) by linear interpolation; 0.0 for no values."""
    if not values:
        return 0.0
    ordered = sorted(values)
    k = (len(ordered) - 1) * q / 100.0
    lo = int(k)
    hi = min(lo + 1, len(ordered) - 1)
    return ordered[lo] + (ordered[hi] - ordered[lo]) * (k - lo)


#: how many recent cycles the figures are taken over: a bridge may run for days, so the
#: record is a sliding window rather than a list that grows with every cycle
STATS_WINDOW = 100_000


#: between-cycle collections (see :class:`BetweenCycles`)
GC_MIDDLE_EVERY = 10
GC_FULL_EVERY = 200


class BetweenCycles:
    """Python's cycle collector, paused while a loop runs and run between its cycles.

    The collector starts whenever allocation counts say so, which is in the middle of a
    decision, and a full collection over a reasoner's memory takes longer than a
    decision. Inside ``with BetweenCycles() as gc_:`` it is paused (for the whole
    process, as it only can be), and ``gc_.collect()``, called after each cycle,
    collects the youngest generation, the middle one every ``GC_MIDDLE_EVERY`` calls
    and the whole heap every ``GC_FULL_EVERY``. On leaving, the collector is left as it
    was found.
    """

    def __init__(self) -> None:
        self.calls = 0
        self._automatic = False

    def __enter__(self) -> BetweenCycles:
        self._automatic = gc.isenabled()
        gc.disable()
        return self

    def __exit__(self, *_: object) -> None:
        if self._automatic:
            gc.enable()

    def collect(self) -> None:
        """One between-cycles collection, of the generations due."""
        self.calls += 1
        if self.calls % GC_FULL_EVERY == 0:
            gc.collect()
        elif self.calls % GC_MIDDLE_EVERY == 0:
            gc.collect(1)
        else:
            gc.collect(0)


@dataclass
class CycleStats:
    """Wall-clock figures of the most recent cycles (up to ``window``), in seconds."""

    window: int = STATS_WINDOW
    reason: deque[float] = field(init=False)
    cycle: deque[float] = field(init=False)
    #: the whole cycle in this process's CPU time: on a shared machine, wall time also
    #: counts the time other processes held the processor
    cycle_cpu: deque[float] = field(init=False)
    total: int = field(default=0, init=False)

    def __post_init__(self) -> None:
        self.reason = deque(maxlen=self.window)
        self.cycle = deque(maxlen=self.window)
        self.cycle_cpu = deque(maxlen=self.window)

    def record(
        self, reason_seconds: float, cycle_seconds: float, cycle_cpu_seconds: float | None = None
    ) -> None:
        """Add one cycle: the mind's share and the whole cycle (and its CPU time)."""
        self.reason.append(reason_seconds)
        self.cycle.append(cycle_seconds)
        if cycle_cpu_seconds is not None:
            self.cycle_cpu.append(cycle_cpu_seconds)
        self.total += 1

    def summary(self) -> dict[str, float]:
        """p50/p99/mean of the mind's share and of the whole cycle, in milliseconds.

        ``cycles`` counts every cycle recorded; the figures cover the last ``window``.
        """
        out: dict[str, float] = {"cycles": float(self.total)}
        for name, values in (
            ("reason", list(self.reason)),
            ("cycle", list(self.cycle)),
            ("cycle_cpu", list(self.cycle_cpu)),
        ):
            out[f"{name}_p50_ms"] = percentile(values, 50) * 1e3
            out[f"{name}_p99_ms"] = percentile(values, 99) * 1e3
            out[f"{name}_mean_ms"] = statistics.fmean(values) * 1e3 if values else 0.0
        return out


@dataclass(frozen=True)
class Step:
    """What one cycle did: the commands executed and how each ended."""

    actions: list[tuple[Command, Outcome]]
    reason_seconds: float
    cycle_seconds: float


def tidy(mind: object) -> None:
    """Run ``mind``'s upkeep between two cycles, if it has any: an optional ``tidy()``
    method (see :class:`~robocog.robot.protocols.Mind`) for work that would otherwise
    pause a decision, such as a reasoner's sweep of its term table. (Any object: a mind
    calls it on its reasoner too.)"""
    upkeep = getattr(mind, "tidy", None)
    if callable(upkeep):
        upkeep()


class Loop:
    """Runs a mind on a body, one perception-reason-action cycle at a time."""

    def __init__(self, body: Body, mind: Mind) -> None:
        self.body = body
        self.mind = mind
        self.stats = CycleStats()
        self.cycles = 0

    def step(self) -> Step:
        """Run one cycle and record its timing."""
        start = time.perf_counter()
        start_cpu = time.process_time()
        percepts = self.body.percepts()
        self.mind.perceive(percepts)
        commands = self.mind.decide()
        reasoned = time.perf_counter()
        actions: list[tuple[Command, Outcome]] = []
        for command in commands:
            outcome = self.body.execute(command)
            actions.append((command, outcome))
            self.mind.on_outcome(command, outcome)
        end = time.perf_counter()
        self.cycles += 1
        self.stats.record(reasoned - start, end - start, time.process_time() - start_cpu)
        return Step(actions, reasoned - start, end - start)

    def run(
        self,
        max_cycles: int,
        until: Callable[[], bool] | None = None,
        on_step: Callable[[Step], None] | None = None,
    ) -> int:
        """Run at most ``max_cycles`` cycles, stopping early when ``until()`` is true.

        Garbage is collected between cycles, never during one (:class:`BetweenCycles`),
        and a mind's own upkeep, if it has any (:func:`tidy`), runs there too. Returns
        the number of cycles run.
        """
        ran = 0
        with BetweenCycles() as collector:
            while ran < max_cycles and not (until and until()):
                step = self.step()
                ran += 1
                collector.collect()
                tidy(self.mind)
                if on_step:
                    on_step(step)
        return ran
