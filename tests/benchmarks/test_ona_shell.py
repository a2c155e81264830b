"""The worlds driven by ONA's shell through pipes, against ONA's own built-in tests."""

from __future__ import annotations

import sys

import pytest

from robocog.experiments.procedures.ona_builtin import parse_status, run_builtin
from robocog.experiments.procedures.reasoners import OnaShell, ReasonerError
from robocog.worlds.procedures import Alien, Cartpole, Robot, run

needs_ona = pytest.mark.skipif(
    OnaShell.unavailable_reason() is not None, reason=str(OnaShell.unavailable_reason())
)


@needs_ona
def test_cartpole_through_the_shell_replays_onas_own_cartpole() -> None:
    # The cartpole world draws no random number, so ONA's shell (seeded like ONA's
    # binary) driven by this world must reproduce `NAR cartpole N` count for count.
    steps = 400
    ours = run(Cartpole(0), OnaShell(), steps)
    theirs = run_builtin("cartpole", steps)
    assert ours.metrics["successes"] == theirs.metrics["successes"]
    assert ours.metrics["failures"] == theirs.metrics["failures"]
    assert sum(ours.operations.values()) > 0


@needs_ona
@pytest.mark.parametrize("env", [Alien(0), Robot(0)], ids=["alien", "robot"])
def test_the_shell_accepts_every_event_and_executes_only_the_worlds_operations(
    env: Alien | Robot,
) -> None:
    result = run(env, OnaShell(), 150)
    assert sum(result.operations.values()) > 10
    assert set(result.operations) == set(env.operations)


def test_a_shell_that_dies_is_reported_with_its_last_output() -> None:
    shell = OnaShell(command=[sys.executable, "-c", "print('bye')"])
    with pytest.raises(ReasonerError, match="(?s)exited.*bye"):
        run(Alien(0), shell, 5)


def test_a_shell_that_does_not_answer_times_out() -> None:
    shell = OnaShell(timeout=0.3, command=[sys.executable, "-c", "import time; time.sleep(5)"])
    with pytest.raises(ReasonerError, match="no reply"):
        run(Alien(0), shell, 5)


def test_status_lines_of_onas_tests_are_read() -> None:
    assert parse_status("pong", "Hits=485 misses=104 ratio=0.823430 time=10001") == {
        "hits": 485.0,
        "misses": 104.0,
        "ratio": pytest.approx(0.82343),
        "time": 10001.0,
    }
    robot = parse_status("robot", "time=1200 moves=361 move_success_ratio=0.300833 eaten=54 x=1")
    assert robot is not None and robot["eaten"] == 54 and robot["ratio"] == pytest.approx(0.300833)
    assert parse_status("alien", "shots=0 hits=0 ratio=-nan time=2")["ratio"] != 0.5  # type: ignore[index]
    assert parse_status("cartpole", "position=0.0, velocity=0.0") is None
