"""The shape every procedure-learning environment shares.

ONA's system tests interleave the world and the reasoner tightly: some inputs go in,
the world moves, an operation fired during one of those inputs takes effect at a fixed
point of the step, and then the reasoner gets a few free cycles. To keep that order
exact whatever reasoner drives the world, a step is a generator of *feeds*: each feed is
what the reasoner receives next (Narsese lines, each of which costs one cycle as in ONA's
shell, or a number of free cycles), and every operation the reasoner executes while
digesting a feed is handed back through :meth:`ProcedureEnv.execute` before the
generator resumes.
"""

from __future__ import annotations

import random
from abc import ABC, abstractmethod
from collections.abc import Iterator
from dataclasses import dataclass, field

#: One feed: Narsese lines (one reasoning cycle each) and cycle counts, in order.
Feed = list[str | int]


@dataclass
class Score:
    """Success counts of one run, named the way ONA's own test prints them."""

    successes: int = 0
    trials: int = 0
    extra: dict[str, float] = field(default_factory=dict)

    @property
    def ratio(self) -> float:
        """Successes over trials (0 before the first trial), ONA's `ratio=` figure."""
        return self.successes / self.trials if self.trials else 0.0


class ProcedureEnv(ABC):
    """A seeded world that feeds a reasoner events and a goal and scores its operations.

    Subclasses fill in the class attributes and the three methods. ``reset(seed)`` puts
    the world in its initial state; ``step()`` yields the feeds of one step;
    ``execute(op)`` receives each operation the reasoner fired; ``score`` holds the
    success counter.
    """

    #: Short name used on the command line (``pong``, ``alien`` ...).
    name: str = ""
    #: Operations in the order ONA registers them (this order fixes the op ids).
    operations: tuple[str, ...] = ()
    #: ONA's motor babbling chance for this test (0.2 unless the test changes it).
    babbling_chance: float = 0.2
    #: Extra shell commands the test issues before it starts.
    shell_setup: tuple[str, ...] = ()
    #: Number of steps of ONA's reference run.
    reference_steps: int = 10_000

    def __init__(self, seed: int = 0) -> None:
        self.rng = random.Random(seed)
        self.score = Score()
        self.steps = 0
        self.reset(seed)

    def reset(self, seed: int) -> None:
        """Restart the world with a fresh random stream, so a seed replays a run exactly."""
        self.rng = random.Random(seed)
        self.score = Score()
        self.steps = 0
        self._reset_world()

    @abstractmethod
    def _reset_world(self) -> None:
        """Put the world into its initial state (the counters are already cleared)."""

    @abstractmethod
    def step(self) -> Iterator[Feed]:
        """Yield the feeds of one step; operations arrive through :meth:`execute`."""

    @abstractmethod
    def execute(self, op: str) -> None:
        """Take note of (or apply) an operation the reasoner executed."""

    def metrics(self) -> dict[str, float]:
        """The figures to report for this run: the ratio plus environment-specific ones."""
        out = {"ratio": self.score.ratio, "successes": self.score.successes}
        out["trials"] = self.score.trials
        out.update(self.score.extra)
        return out


def event(term: str) -> str:
    """A present-tense belief event, as the tests input their observations."""
    return f"{term}. :|:"


def goal(term: str) -> str:
    """A present-tense goal event."""
    return f"{term}! :|:"
