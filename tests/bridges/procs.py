"""Child processes for the bridge tests: JSON-speaking stand-in robots, the bridge
command, roscore. Every process is started in its own session so that the whole group
it spawns (roscore's master and rosout) is ended with it, even when a test fails."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[2]
SRC = REPO / "src" / "robocog" / "bridges"
SYSTEM_PYTHON = "/usr/bin/python3"


class Child:
    """A child process whose stdout lines are collected (as JSON events when they parse)."""

    def __init__(self, argv: list[str], env: dict[str, str] | None = None, name: str = "") -> None:
        self.name = name or Path(argv[0]).name
        self.proc = subprocess.Popen(
            argv,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            bufsize=1,
            env=env,
            start_new_session=True,
        )
        self.events: list[dict[str, Any]] = []
        self.lines: list[str] = []
        self.errors: list[str] = []
        self._cond = threading.Condition()
        self._threads = [
            threading.Thread(target=self._read_out, daemon=True),
            threading.Thread(target=self._read_err, daemon=True),
        ]
        for thread in self._threads:
            thread.start()

    def _read_out(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with self._cond:
                self.lines.append(line)
                try:
                    event = json.loads(line)
                except ValueError:
                    event = None
                if isinstance(event, dict):
                    self.events.append(event)
                self._cond.notify_all()

    def _read_err(self) -> None:
        assert self.proc.stderr is not None
        for line in self.proc.stderr:
            with self._cond:
                self.errors.append(line)
                self._cond.notify_all()

    def send(self, obj: dict[str, Any]) -> None:
        """Write one JSON line to the child's stdin."""
        assert self.proc.stdin is not None
        self.proc.stdin.write(json.dumps(obj) + "\n")
        self.proc.stdin.flush()

    def wait_for(self, predicate: Callable[[], bool], timeout: float) -> bool:
        """Wait until ``predicate()`` (checked under the lock) holds, or the time is up."""
        with self._cond:
            return self._cond.wait_for(predicate, timeout)

    def wait_event(
        self, match: Callable[[dict[str, Any]], bool], timeout: float, since: int = 0
    ) -> dict[str, Any] | None:
        """The first event from index ``since`` on that matches, waiting up to ``timeout``."""
        found: list[dict[str, Any]] = []

        def check() -> bool:
            for event in self.events[since:]:
                if match(event):
                    found.append(event)
                    return True
            return False

        self.wait_for(check, timeout)
        return found[0] if found else None

    def stderr_text(self) -> str:
        with self._cond:
            return "".join(self.errors)

    def stop(self, timeout: float = 5.0) -> None:
        """End the child and everything it started (its process group)."""
        if self.proc.poll() is None:
            try:
                if self.proc.stdin is not None:
                    self.proc.stdin.close()
            except OSError:
                pass
            _signal_group(self.proc, signal.SIGTERM)
            try:
                self.proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                _signal_group(self.proc, signal.SIGKILL)
                self.proc.wait(timeout=timeout)
        for thread in self._threads:
            thread.join(timeout=2.0)

    def kill(self) -> None:
        """End the child at once, as a crash would."""
        _signal_group(self.proc, signal.SIGKILL)
        self.proc.wait(timeout=5.0)


def _signal_group(proc: subprocess.Popen[str], sig: signal.Signals) -> None:
    try:
        os.killpg(proc.pid, sig)  # the child leads its own session, so pgid == pid
    except ProcessLookupError:
        pass


def free_port() -> int:
    """A TCP port on 127.0.0.1 that is free now."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def child_env(extra: dict[str, str] | None = None) -> dict[str, str]:
    """The test process's environment, with the repository on PYTHONPATH (for the test
    mind) and ``extra`` on top."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(REPO), str(REPO / "src")])
    env["PYTHONUNBUFFERED"] = "1"
    env.update(extra or {})
    return env


def bridge_argv(middleware: str, *args: str) -> list[str]:
    """The ``robocog bridge`` command line, run on this test's Python."""
    return [sys.executable, "-m", "robocog.cli", "bridge", middleware, *args]


def wait_until(predicate: Callable[[], bool], timeout: float, step: float = 0.05) -> bool:
    """Poll ``predicate`` until it holds or ``timeout`` passes."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(step)
    return predicate()
