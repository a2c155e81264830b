"""The wrapper around robocog's NAR: configured like ONA's shell, skipped when not ready."""

from __future__ import annotations

import re

import pytest

import robocog.nars
from robocog.experiments.procedures.reasoners import ReasonerError, ReasonerUnavailable, RobocogNar
from robocog.worlds.procedures import Alien, Pong, run


class FakeNar:
    """Executes ``^left`` at every goal; counts a cycle per input like ONA's shell."""

    made: list[FakeNar] = []

    def __init__(self, seed: int = 666) -> None:
        self.seed = seed
        self.inputs: list[str] = []
        self.ops: dict[str, object] = {}
        self.time = 1
        FakeNar.made.append(self)

    def register_operation(self, name: str, fn: object) -> None:
        self.ops[name] = fn

    def add_input(self, line: str) -> None:
        self.inputs.append(line)
        if line.startswith("*"):
            return
        self.time += 1
        if line.endswith("! :|:") and "^left" in self.ops:
            self.ops["^left"](None)  # type: ignore[operator]

    def cycles(self, n: int) -> None:
        self.time += n


@pytest.fixture
def fake_nar(monkeypatch: pytest.MonkeyPatch) -> type[FakeNar]:
    monkeypatch.setattr(robocog.nars, "NAR", FakeNar, raising=False)
    monkeypatch.setattr(RobocogNar, "_probe", False)
    FakeNar.made.clear()
    return FakeNar


def test_the_nar_gets_the_tests_configuration_and_its_operations_act(
    fake_nar: type[FakeNar],
) -> None:
    assert RobocogNar.unavailable_reason() is None
    result = run(Alien(0), RobocogNar(seed=42), 20, seed=5)
    nar = fake_nar.made[-1]
    assert nar.seed == 42  # the reasoner's own seed, not the world's
    assert nar.inputs[:5] == [
        "*setopname 1 ^left",
        "*setopname 2 ^right",
        "*setopname 3 ^shoot",
        "*babblingops=3",
        "*motorbabbling=0.2",
    ]
    assert set(nar.ops) == {"^left", "^right", "^shoot"}
    assert result.operations["^left"] == 20
    assert "s0! :|:" in nar.inputs


def test_a_nar_that_never_acts_is_skipped_with_the_reason(
    fake_nar: type[FakeNar], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(FakeNar, "register_operation", lambda self, name, fn: None)
    reason = RobocogNar.unavailable_reason()
    assert reason is not None and "did not execute ^left" in reason
    with pytest.raises(ReasonerUnavailable, match=re.escape(reason)):
        RobocogNar().start(Alien(0), 0)


def test_the_real_nar_either_runs_a_world_or_says_why_not() -> None:
    reason = RobocogNar.unavailable_reason()
    if reason is not None:
        with pytest.raises(ReasonerUnavailable):
            RobocogNar().start(Alien(0), 0)
        return
    result = run(Alien(0), RobocogNar(), 50)
    assert set(result.operations) <= set(Alien.operations)


def test_an_engine_failure_becomes_a_reasoner_error_naming_the_input(
    fake_nar: type[FakeNar], monkeypatch: pytest.MonkeyPatch
) -> None:
    def refuse(self: FakeNar, n: int) -> None:
        raise KeyError("no such concept")

    assert RobocogNar.unavailable_reason() is None  # probed while the engine still works
    monkeypatch.setattr(FakeNar, "cycles", refuse)
    with pytest.raises(ReasonerError, match="failed on 5: KeyError"):
        run(Pong(0), RobocogNar(), 3)
