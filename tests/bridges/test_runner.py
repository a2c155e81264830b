"""The watchdog stops the robot when percepts stop or the mind fails, and resumes."""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import ScanReading
from robocog.bridges.runner import BridgeRunner, text_input_of
from robocog.robot import Command, Outcome, Percept, Turn
from tests.bridges.fakes import FakeLink
from tests.bridges.procs import wait_until
from tests.bridges.reflex import ReflexMind

LEFT = ScanReading(0.8, 0.0, 0.1, 10.0, [1.0])
CONFIG = BridgeConfig(watchdog_seconds=0.3, angular_speed=3.0, command_rate=50.0, cycle_period=0.02)


class Feeder:
    """Sends a scan every 20 ms while ``on`` is set, as a robot's driver would."""

    def __init__(self, body: RobotBody) -> None:
        self.body = body
        self.on = threading.Event()
        self.on.set()
        self.done = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        while not self.done.wait(0.02):
            if self.on.is_set():
                self.body.on_scan(LEFT)

    def close(self) -> None:
        self.done.set()
        self.thread.join()


def start(mind: object, config: BridgeConfig = CONFIG, **run: float):
    link = FakeLink()
    body = RobotBody(link, config).start()
    feeder = Feeder(body)
    runner = BridgeRunner(body, mind)  # type: ignore[arg-type]
    result: list[int] = []
    thread = threading.Thread(target=lambda: result.append(runner.run(**run)), daemon=True)
    thread.start()
    return link, body, feeder, runner, thread, result


def test_silence_stops_the_robot_within_the_watchdog_time_and_it_resumes() -> None:
    mind = ReflexMind()
    link, body, feeder, runner, thread, _ = start(mind, duration=10.0)
    try:
        assert wait_until(lambda: any(a[1] < 0 for a in link.of("twist")), 5)
        feeder.on.clear()
        silent_at = time.monotonic()
        assert wait_until(lambda: body.halted is not None, 3)
        [stopped_at] = link.times("cancel")[:1]
        assert stopped_at - silent_at <= CONFIG.watchdog_seconds + 0.5
        assert link.of("twist")[-1] == (0.0, 0.0)
        assert any("no percepts" in text for _t, text in runner.events)
        moves_while_halted = len(link.of("twist"))
        time.sleep(0.3)
        # the interrupted move may still say "zero velocity" once more; nothing else moves
        assert all(t == (0.0, 0.0) for t in link.of("twist")[moves_while_halted:])
        moves_while_halted = len(link.of("twist"))
        feeder.on.set()
        assert wait_until(lambda: body.halted is None, 3)
        assert wait_until(
            lambda: any(t != (0.0, 0.0) for t in link.of("twist")[moves_while_halted:]), 3
        )
        assert any("resuming" in text for _t, text in runner.events)
    finally:
        runner.stop()
        thread.join(5)
        feeder.close()
    assert link.of("twist")[-1] == (0.0, 0.0)


class FailingMind(ReflexMind):
    """Raises in decide while ``failing`` is set."""

    def __init__(self) -> None:
        super().__init__()
        self.failing = threading.Event()

    def decide(self) -> list[Command]:
        if self.failing.is_set():
            raise RuntimeError("reasoner crashed")
        return super().decide()


def test_a_failing_mind_stops_the_robot_and_its_recovery_resumes_it() -> None:
    mind = FailingMind()
    config = BridgeConfig(
        watchdog_seconds=1.0, angular_speed=3.0, cycle_period=0.02, max_mind_failures=1000
    )
    link, body, feeder, runner, thread, _ = start(mind, config, duration=10.0)
    try:
        assert wait_until(lambda: link.of("twist"), 5)
        mind.failing.set()
        assert wait_until(lambda: body.halted is not None, 3)
        assert "reasoner crashed" in str(body.halted)
        assert link.of("cancel")
        mind.failing.clear()
        assert wait_until(lambda: body.halted is None, 3)
        assert any("answers again" in text for _t, text in runner.events)
    finally:
        runner.stop()
        thread.join(5)
        feeder.close()


def test_a_mind_that_keeps_failing_ends_the_run_with_the_robot_stopped() -> None:
    mind = FailingMind()
    mind.failing.set()
    link, _body, feeder, _runner, thread, result = start(mind, duration=10.0)
    thread.join(5)
    feeder.close()
    assert result == [1]
    assert link.of("twist")[-1] == (0.0, 0.0)
    assert link.of("cancel")


class SlowMind(ReflexMind):
    def __init__(self, delay: float) -> None:
        super().__init__()
        self.delay = delay

    def perceive(self, percepts: Sequence[Percept]) -> None:
        time.sleep(self.delay)
        super().perceive(percepts)


def test_a_stalled_mind_trips_the_watchdog() -> None:
    config = BridgeConfig(watchdog_seconds=5.0, mind_timeout=0.2, cycle_period=0.02)
    link, body, feeder, runner, thread, _ = start(SlowMind(0.8), config, max_cycles=1)
    thread.join(5)
    feeder.close()
    assert any("longer than 0.2 s" in text for _t, text in runner.events)
    assert link.of("cancel")


def test_a_stop_cuts_short_a_navigation_goal_that_gets_no_answer() -> None:
    """Stopped (SIGTERM) while the robot waits for a goal whose navigator has gone, the
    run ends at once with the robot stopped, not after ``goto_timeout``."""
    from robocog.robot import GoTo

    class Going(ReflexMind):
        def decide(self) -> list[Command]:
            return [GoTo("bin")]

    config = BridgeConfig(
        watchdog_seconds=5.0, cycle_period=0.02, goto_timeout=120.0, places={"bin": (1.0, 0, 0)}
    )
    link, body, feeder, runner, thread, result = start(Going(), config, duration=60.0)
    try:
        assert wait_until(lambda: link.of("goal"), 5)  # no result will come for it
        asked = time.monotonic()
        runner.stop()
        thread.join(5)
        assert not thread.is_alive(), "the run waited for the goal's result"
        assert time.monotonic() - asked < 2.0
        assert result == [0]
        assert link.of("cancel")
        assert any("asked to stop" in text for _t, text in runner.events)
    finally:
        feeder.close()


def run_cycles(mind: object, cycles: int, text: str | None = None) -> int:
    """Run ``mind`` for ``cycles`` cycles on a body fed scans (and ``text`` from the
    robot first); the run's exit code."""
    body = RobotBody(FakeLink(), CONFIG).start()
    if text is not None:
        body.on_text(text)
    feeder = Feeder(body)
    try:
        return BridgeRunner(body, mind).run(max_cycles=cycles)  # type: ignore[arg-type]
    finally:
        feeder.close()


def test_text_reaches_a_mind_that_hears_and_outcomes_come_back() -> None:
    mind = ReflexMind()
    code = run_cycles(mind, 3, text="<obstacle --> [left]>. :|:\n<a --> b>.")
    assert code == 0
    assert mind.heard == ["<obstacle --> [left]>. :|:", "<a --> b>."]
    assert [c for c, _o in mind.outcomes] == [Turn(-0.3)] * 3
    assert all(o == Outcome.success() for _c, o in mind.outcomes)


def test_the_minds_upkeep_runs_after_each_cycle_and_its_failure_stops_nothing() -> None:
    class Tidy(ReflexMind):
        def __init__(self) -> None:
            super().__init__()
            self.tidied = 0

        def tidy(self) -> None:
            self.tidied += 1
            if self.tidied == 2:
                raise RuntimeError("upkeep failed")

    mind = Tidy()
    assert run_cycles(mind, 4) == 0
    assert mind.tidied == 4
    assert len(mind.outcomes) == 4


def test_the_cycle_collector_runs_between_cycles_never_during_a_decision() -> None:
    """As in ``Loop.run``: paused while the mind decides, yet the garbage in cycles that
    one decision leaves is gone before the next, and the collector is back after."""
    import gc
    import weakref

    class Node:
        def __init__(self) -> None:
            self.me = self  # garbage only the cycle collector frees

    class Watching(ReflexMind):
        def __init__(self) -> None:
            super().__init__()
            self.enabled: list[bool] = []
            self.previous_freed: list[bool] = []
            self.last: weakref.ref[Node] | None = None

        def decide(self) -> list[Command]:
            self.enabled.append(gc.isenabled())
            if self.last is not None:
                self.previous_freed.append(self.last() is None)
            self.last = weakref.ref(Node())
            return super().decide()

    assert gc.isenabled()
    mind = Watching()
    assert run_cycles(mind, 4) == 0
    assert mind.enabled == [False] * 4
    assert mind.previous_freed == [True] * 3
    assert gc.isenabled()


def test_text_input_is_found_by_name() -> None:
    class Deaf:
        def perceive(self, percepts: Sequence[Percept]) -> None: ...
        def decide(self) -> list[Command]:
            return []

        def on_outcome(self, command: Command, outcome: Outcome) -> None: ...

    assert text_input_of(Deaf()) is None  # type: ignore[arg-type]
    mind = ReflexMind()
    hear = text_input_of(mind)
    assert hear is not None
    hear("x")
    assert mind.heard == ["x"]


def test_the_robots_end_of_mission_ends_the_run_saying_why_with_no_watchdog_alarm() -> None:
    mind = ReflexMind()
    link, body, feeder, runner, thread, result = start(mind, duration=30.0)
    try:
        assert wait_until(lambda: runner.cycles > 2, 5)
        body.on_mission("running")  # a state other than the end changes nothing
        time.sleep(0.1)
        assert thread.is_alive() and body.mission_ended() is None
        body.on_mission("ended: route complete; collected 3 of 5 objects")
        feeder.on.clear()  # the robot falls silent once its mission is over
        thread.join(3)
        assert not thread.is_alive()  # long before the 30 s of the run
    finally:
        runner.stop()
        thread.join(5)
        feeder.close()
    assert result == [0]
    assert runner.mission_ended == "route complete; collected 3 of 5 objects"
    assert any("the robot ended its mission: route complete" in t for _t, t in runner.events)
    assert runner.events[-1][1].startswith("the robot ended its mission")
    assert link.of("twist")[-1] == (0.0, 0.0)  # left stopped, as at any end


def test_every_body_the_runner_drives_has_what_it_calls() -> None:
    """The runner asks its body for these by name; a body without one fails mid-run
    (the Q.bo's body once lacked ``mission_ended`` and ended every run over ROS 2)."""
    import re
    from pathlib import Path

    import robocog.bridges.runner as runner_module
    from robocog.bridges.body import RobotBody
    from robocog.bridges.qbo import QboRos2Body

    source = Path(runner_module.__file__).read_text()
    called = set(re.findall(r"self\.body\.([a-z_]+)\(", source))
    assert {"mission_ended", "percepts", "execute", "stale"} <= called
    for body in (RobotBody, QboRos2Body):
        missing = sorted(name for name in called if not callable(getattr(body, name, None)))
        assert missing == [], f"{body.__name__} lacks {missing}"
