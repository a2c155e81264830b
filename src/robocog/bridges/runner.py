"""The bridge's sense-decide-act loop, with the watchdog that keeps a real robot safe.

A simulator can pause; a robot cannot. So beside the cycle runs a watchdog thread: when
the robot's readings stop for longer than ``watchdog_seconds`` (a cable, a crashed
driver, a lost Wi-Fi link) or the mind spends longer than ``mind_timeout`` on one
decision, the robot is stopped (zero velocity, navigation goal cancelled) and the event
is logged. When readings come back, the bridge resumes by itself. A mind that raises
stops the robot the same way; after ``max_mind_failures`` failures in a row the run ends.
"""

from __future__ import annotations

import logging
import threading
import time
from collections import deque
from collections.abc import Callable

from robocog.bridges.body import RobotBody
from robocog.robot.commands import Command, Outcome
from robocog.robot.loop import BetweenCycles, CycleStats, Step, tidy
from robocog.robot.protocols import Mind

log = logging.getLogger("robocog.bridges")

#: the method names under which a mind takes text input (Narsese lines), first found wins
TEXT_METHODS = ("hear", "tell")


def text_input_of(mind: Mind) -> Callable[[str], object] | None:
    """The mind's text input (for the ``/narsese`` topic), or None if it takes none."""
    for name in TEXT_METHODS:
        method = getattr(mind, name, None)
        if callable(method):
            return method
    return None


class BridgeRunner:
    """Runs a mind on a ``RobotBody`` until told to stop, guarded by a watchdog."""

    def __init__(
        self, body: RobotBody, mind: Mind, on_cycle: Callable[[Step], None] | None = None
    ) -> None:
        self.body = body
        self.mind = mind
        #: called after each cycle with what it did (the inspector's hook); it must not
        #: block, and an exception from it is logged, never stops the robot
        self.on_cycle = on_cycle
        self.config = body.config
        self.stats = CycleStats()
        self.cycles = 0
        #: the latest watchdog and failure events (bounded: a bridge may run for days)
        self.events: deque[tuple[float, str]] = deque(maxlen=1000)
        self._stop = threading.Event()
        self._done = threading.Event()  # the loop has ended: the watchdog ends too
        self._trip: str | None = None  # "percepts" | "mind" | "stop" | None
        self._mind_since: float | None = None
        self._trip_lock = threading.Lock()
        self._hear = text_input_of(mind)
        self._deaf_warned = False
        #: why the robot ended its mission, when that is what ended the run
        self.mission_ended: str | None = None

    # -- control -----------------------------------------------------------------

    def stop(self) -> None:
        """Ask the run to end. A command under way is cut short: the watchdog halts the
        robot (so a navigation goal whose navigator has gone does not hold the run for
        ``goto_timeout``), and the loop ends after the current cycle. Safe to call from a
        signal handler: it only sets a flag."""
        self._stop.set()

    def run(self, duration: float | None = None, max_cycles: int | None = None) -> int:
        """Run until ``stop()``, ``duration`` seconds or ``max_cycles``; returns an exit code.

        The exit code is 0 for a normal end and 1 when the mind failed too often.
        The robot is always left stopped. As in ``Loop.run``, Python's cycle collector
        runs between cycles, never during a decision (:class:`BetweenCycles`); it also
        runs while no cycle can (no readings yet, or stale ones), so the garbage of the
        middleware's threads is collected while the mind waits.
        """
        deadline = None if duration is None else time.monotonic() + duration
        watchdog = threading.Thread(target=self._watch, name="bridge-watchdog", daemon=True)
        watchdog.start()
        failures = 0
        code = 0
        frames, decided = 0, -1.0
        try:
            with BetweenCycles() as collector:
                while not self._stop.is_set():
                    # (after the last cycle or wait: the robot is busy with its commands)
                    collector.collect()
                    if deadline is not None and time.monotonic() >= deadline:
                        break
                    if max_cycles is not None and self.cycles >= max_cycles:
                        break
                    ended = self.body.mission_ended()
                    if ended is not None:
                        # the robot's word, not a silence: no watchdog alarm, the run ends
                        self.mission_ended = ended
                        self._event(f"the robot ended its mission: {ended}", logging.INFO)
                        break
                    if self.config.lockstep:
                        frames, stamp = self.body.wait_for_frame(frames, self.config.cycle_period)
                        if stamp <= decided:  # no new frame, or one sent again: acknowledge
                            if decided >= 0 and stamp == decided:
                                self.body.frame_done(stamp)
                            continue
                    else:
                        self.body.wait_for_readings(self.config.cycle_period)
                    if self._trip == "percepts":
                        continue
                    if self.body.stale() is not None:
                        continue  # nothing (fresh) to decide on yet; the watchdog will act
                    ok = self._cycle()
                    if self.config.lockstep:
                        decided = stamp
                        # the next decision is on a scan taken after this cycle's commands
                        # ended, never on one sent while the robot was still carrying them
                        frames = self.body.scans
                        self.body.frame_done(stamp)
                    if ok:
                        self._tidy()  # (the robot has its commands: nothing waits on this)
                        failures = 0
                    else:
                        failures += 1
                        if failures >= self.config.max_mind_failures:
                            self._event(f"the mind failed {failures} times in a row; giving up")
                            code = 1
                            break
        finally:
            self._done.set()
            self._stop.set()
            watchdog.join(timeout=1.0)
            self.body.stop()
        return code

    # -- one cycle ---------------------------------------------------------------

    def _cycle(self) -> bool:
        """One perception-reason-action cycle; False when the mind failed."""
        start = time.perf_counter()
        try:
            self._mind_since = time.monotonic()
            lines = self.body.texts()
            if self._hear is not None:
                for line in lines:
                    self._hear(line)
            elif lines and not self._deaf_warned:
                self._deaf_warned = True
                log.warning("this mind takes no text input; lines from the robot are dropped")
            percepts = self.body.percepts()
            self.mind.perceive(percepts)
            commands = self.mind.decide()
        except Exception as exc:  # noqa: BLE001 - any failure of the mind stops the robot
            self._mind_failed(exc)
            return False
        finally:
            self._mind_since = None
        reasoned = time.perf_counter()
        if self._trip == "mind":
            self._clear("the mind answers again; resuming")
        actions: list[tuple[Command, Outcome]] = []
        for command in commands:
            outcome = self.body.execute(command)
            actions.append((command, outcome))
            log.debug("%s -> %s %s", command, outcome.status.value, outcome.reason)
            try:
                self.mind.on_outcome(command, outcome)
            except Exception as exc:  # noqa: BLE001
                self._mind_failed(exc)
                return False
        end = time.perf_counter()
        self.cycles += 1
        self.stats.record(reasoned - start, end - start)
        if self.on_cycle is not None:
            try:
                self.on_cycle(Step(actions, reasoned - start, end - start))
            except Exception as exc:  # noqa: BLE001 - an observer never stops the robot
                log.error("the cycle's observer failed: %s: %s", type(exc).__name__, exc)
        return True

    def _tidy(self) -> None:
        """The mind's between-cycles upkeep (:func:`robocog.robot.loop.tidy`); a failure
        of it is logged and never stops the robot."""
        try:
            tidy(self.mind)
        except Exception as exc:  # noqa: BLE001
            log.error("the mind's upkeep failed: %s: %s", type(exc).__name__, exc)

    def _mind_failed(self, exc: BaseException) -> None:
        log.error("the mind failed: %s: %s", type(exc).__name__, exc, exc_info=exc)
        self._halt("mind", f"the mind failed ({type(exc).__name__}: {exc})")

    # -- the watchdog --------------------------------------------------------------

    def _watch(self) -> None:
        period = min(0.05, self.config.watchdog_seconds / 4)
        while not self._done.wait(period):
            if self.body.mission_ended() is not None:
                continue  # the loop ends on it; silence after the end is no fault
            if self._stop.is_set():
                if self._trip != "stop":  # (halted here, not in a signal handler)
                    self._halt("stop", "the run was asked to stop")
                continue
            since = self._mind_since
            if since is not None and time.monotonic() - since > self.config.mind_timeout:
                if self._trip is None:
                    self._halt("mind", f"the mind took longer than {self.config.mind_timeout:g} s")
                continue
            reason = self.body.stale()
            if reason is not None:
                if self._trip != "percepts":
                    self._halt("percepts", reason)
            elif self._trip == "percepts":
                self._clear("percepts are back; resuming")

    def _halt(self, kind: str, reason: str) -> None:
        with self._trip_lock:  # the trip and the body's halt change together
            self._trip = kind
            self.body.halt(reason)
        self._event(f"watchdog: robot stopped: {reason}")

    def _clear(self, message: str) -> None:
        with self._trip_lock:
            self._trip = None
            self.body.resume()
        self._event(message)

    def _event(self, message: str, level: int = logging.WARNING) -> None:
        self.events.append((time.time(), message))
        log.log(level, "%s", message)
