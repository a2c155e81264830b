"""Run one environment with one reasoner for a number of steps, timing the whole run.

A reasoner is anything with the :class:`Reasoner` protocol: the worlds know no engine,
and the reasoners that run one (robocog's NAR, ONA's shell) are in
:mod:`robocog.experiments.procedures.reasoners`.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from .base import Feed, ProcedureEnv


class Reasoner(Protocol):
    """What the runner needs from a reasoner."""

    name: str

    def start(self, env: ProcedureEnv, seed: int) -> None:
        """Prepare a fresh reasoner for ``env`` (operations, babbling, settings)."""
        ...

    def feed(self, feed: Feed) -> list[str]:
        """Input the feed in order; return the operations executed meanwhile."""
        ...

    def close(self) -> None:
        """Release the reasoner (end a child process)."""
        ...


@dataclass
class RunResult:
    """Figures of one run: the environment's metrics, wall time, operations executed."""

    env: str
    reasoner: str
    steps: int
    seed: int
    metrics: dict[str, float]
    wall_time: float
    operations: dict[str, int] = field(default_factory=dict)
    #: Steps actually run: fewer than ``steps`` when the time limit stopped the run.
    completed_steps: int = 0

    @property
    def ratio(self) -> float:
        """The environment's headline figure (see each environment's ``metrics``)."""
        return float(self.metrics["ratio"])


def run(
    env: ProcedureEnv,
    reasoner: Reasoner,
    steps: int,
    seed: int = 0,
    on_step: Callable[[int], None] | None = None,
    time_limit: float | None = None,
) -> RunResult:
    """Reset ``env`` with ``seed``, drive it for ``steps`` steps, and close the reasoner.

    The wall time covers the reasoner's start-up too, as a run of ONA's own test does.
    ``on_step(k)`` is called after step k (for a progress bar). With ``time_limit``
    (seconds) a slow reasoner is stopped after the step that exceeds it, and the figures
    are those reached (``completed_steps`` tells how far it got).
    """
    env.reset(seed)
    counts = dict.fromkeys(env.operations, 0)
    started = time.perf_counter()
    done = 0
    try:
        reasoner.start(env, seed)
        for done in range(1, steps + 1):
            for feed in env.step():
                for op in reasoner.feed(feed):
                    counts[op] = counts.get(op, 0) + 1
                    env.execute(op)
            if on_step is not None:
                on_step(done)
            if time_limit is not None and time.perf_counter() - started > time_limit:
                break
    finally:
        reasoner.close()
    wall = time.perf_counter() - started
    return RunResult(env.name, reasoner.name, steps, seed, env.metrics(), wall, counts, done)
