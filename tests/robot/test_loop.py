"""The loop wires a body to a mind: percepts in, commands out, outcomes back."""

from __future__ import annotations

from collections.abc import Sequence

import pytest

from robocog.robot import Body, Command, Forward, Mind, Obstacle, Outcome, Percept, Turn
from robocog.robot.loop import Loop, percentile


class Corridor:
    """A body with a wall 1 m ahead: forward fails once it is reached."""

    def __init__(self) -> None:
        self.x = 0.0
        self.clock = 0.0

    def percepts(self) -> list[Percept]:
        gap = 1.0 - self.x
        return [Obstacle("front", gap) if gap < 2.0 else Obstacle("none", 2.0)]

    def execute(self, command: Command) -> Outcome:
        self.clock += 1.0
        if isinstance(command, Forward):
            if self.x + command.distance > 1.0:
                return Outcome.failure("blocked")
            self.x += command.distance
        return Outcome.success()

    def time(self) -> float:
        return self.clock


class Cautious:
    """Goes forward while the front is clear beyond 0.5 m, else turns."""

    def __init__(self) -> None:
        self.gap = 2.0
        self.outcomes: list[tuple[Command, Outcome]] = []

    def perceive(self, percepts: Sequence[Percept]) -> None:
        for p in percepts:
            if isinstance(p, Obstacle):
                self.gap = p.distance

    def decide(self) -> list[Command]:
        return [Forward(0.4)] if self.gap > 0.5 else [Turn(1.57)]

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        self.outcomes.append((command, outcome))


def test_body_and_mind_satisfy_the_protocols() -> None:
    assert isinstance(Corridor(), Body)
    assert isinstance(Cautious(), Mind)


def test_loop_runs_cycles_and_feeds_outcomes_back() -> None:
    body, mind = Corridor(), Cautious()
    loop = Loop(body, mind)
    assert loop.run(5) == 5
    kinds = [type(c).__name__ for c, _ in mind.outcomes]
    assert kinds == ["Forward", "Forward", "Turn", "Turn", "Turn"]
    assert abs(body.x - 0.8) < 1e-9
    summary = loop.stats.summary()
    assert summary["cycles"] == 5.0
    assert summary["cycle_p99_ms"] >= summary["cycle_p50_ms"] >= 0.0
    # the CPU time of each cycle is kept beside its wall time
    assert len(loop.stats.cycle_cpu) == 5
    assert summary["cycle_cpu_p99_ms"] >= summary["cycle_cpu_p50_ms"] >= 0.0


def test_loop_stops_when_asked() -> None:
    body, mind = Corridor(), Cautious()
    loop = Loop(body, mind)
    assert loop.run(100, until=lambda: body.x > 0.5) == 2


def test_percentile_interpolates() -> None:
    assert percentile([], 50) == 0.0
    assert percentile([1.0, 2.0, 3.0, 4.0], 50) == 2.5
    assert percentile([5.0], 99) == 5.0
    assert percentile([0.0, 10.0], 90) == 9.0


def test_stats_keep_a_bounded_window_but_count_every_cycle() -> None:
    from robocog.robot.loop import CycleStats

    stats = CycleStats(window=10)
    for i in range(25):
        stats.record(i / 1000, 2 * i / 1000)
    assert len(stats.cycle) == 10 and len(stats.reason) == 10
    summary = stats.summary()
    assert summary["cycles"] == 25.0
    # only the last ten cycles (15..24 ms of reasoning) are in the figures
    assert abs(summary["reason_p50_ms"] - 19.5) < 1e-9


def test_cycle_collector_is_paused_during_decisions_and_restored_after() -> None:
    """Garbage is collected between cycles, never in the middle of a decision, and the
    interpreter's own policy is back once the loop ends (also when a mind raises)."""
    import gc

    seen: list[bool] = []

    class Watching(Cautious):
        def decide(self) -> list[Command]:
            seen.append(gc.isenabled())
            return super().decide()

    class Failing(Cautious):
        def decide(self) -> list[Command]:
            raise RuntimeError("mind failed")

    assert gc.isenabled()
    Loop(Corridor(), Watching()).run(3)
    assert seen == [False, False, False]
    assert gc.isenabled()
    with pytest.raises(RuntimeError):
        Loop(Corridor(), Failing()).run(3)
    assert gc.isenabled()


def test_between_cycles_collects_the_generations_due_and_leaves_the_collector_as_found(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The youngest generation after each cycle, the middle one every tenth, the whole
    heap every two hundredth; a collector paused before stays paused."""
    import gc

    from robocog.robot.loop import GC_FULL_EVERY, GC_MIDDLE_EVERY, BetweenCycles

    collected: list[int] = []
    monkeypatch.setattr(gc, "collect", lambda generation=2: collected.append(generation))
    with BetweenCycles() as collector:
        assert not gc.isenabled()
        for _ in range(2 * GC_FULL_EVERY):
            collector.collect()
    assert gc.isenabled()
    assert collected.count(2) == 2
    assert collected.count(1) == 2 * (GC_FULL_EVERY // GC_MIDDLE_EVERY - 1)
    assert collected[GC_MIDDLE_EVERY - 1] == 1 and collected[GC_FULL_EVERY - 1] == 2
    assert collected.count(0) == 2 * GC_FULL_EVERY - collected.count(1) - 2
    gc.disable()
    try:
        with BetweenCycles() as collector:
            collector.collect()
        assert not gc.isenabled()
    finally:
        gc.enable()


def test_the_minds_upkeep_runs_between_cycles_outside_their_timing() -> None:
    """A mind's optional ``tidy()`` runs once after each cycle, never inside one."""
    events: list[str] = []

    class Tidy(Cautious):
        def decide(self) -> list[Command]:
            events.append("decide")
            return super().decide()

        def tidy(self) -> None:
            events.append("tidy")

    loop = Loop(Corridor(), Tidy())
    steps: list[object] = []
    loop.run(3, on_step=steps.append)
    assert events == ["decide", "tidy"] * 3
    assert len(steps) == 3
    # a mind without one runs as before
    assert Loop(Corridor(), Cautious()).run(2) == 2
