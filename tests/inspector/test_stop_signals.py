"""Ctrl-C and SIGTERM as the inspector's commands take them, in this process.

A signal raises in the main thread wherever it happens to be; when that is a ``__del__``
or a weakref callback, the interpreter only reports the exception and goes on. These
tests make that happen and check that the stop is raised again where the work can stop.
"""

from __future__ import annotations

import signal
import sys
import threading
from collections.abc import Iterator
from typing import Any

import pytest

from robocog.inspector.cli import Session, Stopped, StopSignals
from robocog.inspector.hub import Inspector
from robocog.minds.bdi_mind import BdiMind
from robocog.robot.loop import Loop
from robocog.worlds.garbage import GarbageConfig, GarbageField


class _SignalledWhileDropped:
    """An object whose ``__del__`` is where the signal lands."""

    def __init__(self, sig: int) -> None:
        self.sig = sig

    def __del__(self) -> None:
        signal.raise_signal(self.sig)


@pytest.fixture
def main_thread() -> Iterator[None]:
    """Python handles signals in its main thread only. The tests start from Python's own
    handling of SIGINT and SIGTERM, whatever an earlier test of the same process (or a
    library it started) left in place, and leave it as they found it."""
    if threading.current_thread() is not threading.main_thread():
        pytest.skip("signal handlers are set from the main thread only")
    before = {sig: signal.getsignal(sig) for sig in (signal.SIGINT, signal.SIGTERM)}
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        yield
    finally:
        for sig, handler in before.items():
            if handler is not None:  # (None: set outside Python, which cannot set it back)
                signal.signal(sig, handler)


@pytest.fixture
def unraisable(monkeypatch: pytest.MonkeyPatch, main_thread: None) -> list[Any]:
    """What reached the interpreter's "Exception ignored" report (here recorded, and
    otherwise dropped): a lost stop must not, the signals count it instead."""
    seen: list[Any] = []
    monkeypatch.setattr(sys, "unraisablehook", lambda u: seen.append(u.exc_type))
    return seen


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_stop_whose_raise_was_lost_is_raised_again_when_checked(
    unraisable: list[Any], sig: int
) -> None:
    before = signal.getsignal(sig)
    with StopSignals() as signals:
        assert not signals.asked
        signals.check()  # nothing asked yet
        _SignalledWhileDropped(sig)  # dropped at once: the raise in its __del__ is lost
        # lost, and not printed: counted, then raised again at the check below
        assert signals.lost == 1 and unraisable == []
        assert signals.asked
        with pytest.raises(Stopped) as stop:
            signals.check()
        assert stop.value.signum == sig and isinstance(stop.value, KeyboardInterrupt)
        # a second signal is taken as the stop already under way: nothing is raised
        signal.raise_signal(sig)
    assert signal.getsignal(sig) is before


def test_a_run_watched_through_the_session_ends_at_the_next_cycle(unraisable: list[Any]) -> None:
    world = GarbageField(GarbageConfig(), seed=3)
    mind = BdiMind()
    loop = Loop(world, mind)
    with StopSignals() as signals:
        session = Session(Inspector(), server=None, signals=signals)
        on_step = session.watch(world, mind, loop, "test")
        loop.run(3, on_step=on_step)
        assert loop.cycles == 3  # no signal: the hook only watches
        _SignalledWhileDropped(signal.SIGINT)
        assert signals.lost == 1 and unraisable == []
        with pytest.raises(Stopped):
            loop.run(100, on_step=on_step)
    assert loop.cycles == 4


def test_sigterm_is_left_to_a_command_that_handles_it(main_thread: None) -> None:
    calls: list[int] = []
    previous = signal.signal(signal.SIGTERM, lambda signum, _frame: calls.append(signum))
    try:
        with StopSignals() as signals:
            signal.raise_signal(signal.SIGTERM)  # the command's own handler (a bridge's)
            assert calls == [signal.SIGTERM] and not signals.asked
            with pytest.raises(Stopped):
                signal.raise_signal(signal.SIGINT)
    finally:
        signal.signal(signal.SIGTERM, previous)


def test_a_stop_lost_while_the_page_holds_the_loop_paused_ends_the_pause(
    unraisable: list[Any],
) -> None:
    world = GarbageField(GarbageConfig(), seed=4)
    mind = BdiMind()
    loop = Loop(world, mind)
    inspector = Inspector()
    applied = inspector.apply_commands

    def apply_commands() -> bool:  # the signal lands in a __del__ while paused
        if inspector.paused:
            _SignalledWhileDropped(signal.SIGINT)
        return applied()

    inspector.apply_commands = apply_commands  # type: ignore[method-assign]
    # (should the pause never end, the test closes the inspector rather than hang)
    guard = threading.Timer(20, inspector.close)
    guard.start()
    try:
        with StopSignals() as signals:
            inspector.interrupted = lambda: signals.asked
            on_step = Session(inspector, server=None, signals=signals).watch(world, mind, loop)
            inspector.submit("pause")
            with pytest.raises(Stopped):
                loop.run(100, on_step=on_step)
    finally:
        guard.cancel()
    assert signals.lost == 1 and unraisable == []
    assert not inspector.closed, "the pause only ended when the test closed it"
    assert loop.cycles == 2  # paused after the first, stopped before the third


def test_an_ignored_sigint_stays_ignored(main_thread: None) -> None:
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with StopSignals() as signals:
            signal.raise_signal(signal.SIGINT)  # a job in the background: nothing happens
            assert not signals.asked
            assert signal.getsignal(signal.SIGINT) == signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, previous)
