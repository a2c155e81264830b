"""What a long command shows while it works, on a terminal and in a pipe.

A command that runs for more than a few seconds says first what it runs and about how
long that takes (``header``), then shows its progress (``Steps``): on a terminal a rich
progress bar, one line per phase; when the output is piped or redirected, plain lines, one
per finished step (at most one a second) and, while a step is still running, one at least
every few seconds, so that a log or a CI job never sits silent. Every package may use this module: it imports
nothing of robocog.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field
from types import TracebackType
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rich.console import Console

#: the longest a piped command stays silent, in seconds (less than the promised 5 s)
QUIET_LIMIT = 3.5
#: the least time between two plain lines for steps of the same phase, in seconds
STEP_LINE_SECONDS = 1.0


def duration(seconds: float) -> str:
    """A rough, readable span of time: ``about 20 s``, ``about 3 min``."""
    if seconds < 60:
        return f"about {max(5, int(round(seconds / 5.0)) * 5)} s"
    if seconds < 3600:
        return f"about {max(1, int(round(seconds / 60.0)))} min"
    return f"about {seconds / 3600:.1f} h"


def header(console: Console, command: str, what: str, expected: str | None = None) -> None:
    """Print ``command: what`` and, when known, how long it is expected to take."""
    from rich.markup import escape

    line = f"{command}: {what}"
    if expected:
        line += f" ({expected})"
    console.print(escape(line), highlight=False)


@dataclass
class _Task:
    description: str
    total: int | None
    done: int = 0
    detail: str = ""
    said: bool = False
    rich_id: int | None = None
    started: float = field(default_factory=time.monotonic)

    def line(self, elapsed: float, still: bool = False) -> str:
        count = f"{self.done}/{self.total}" if self.total is not None else f"{self.done}"
        detail = f", {self.detail}" if self.detail else ""
        running = ", still running" if still else ""
        return f"{self.description}: {count}{detail}{running} ({int(elapsed)} s)"


class Steps:
    """Progress of one command's phases: ``add`` a phase, ``advance`` it, ``note`` what
    it is doing now. On a terminal a transient rich bar per phase; otherwise plain lines
    (a phase's first and last step, others at most one a second, and a ``still running``
    line whenever ``QUIET_LIMIT`` seconds passed without one). Use as a context manager."""

    def __init__(self, console: Console, quiet_limit: float = QUIET_LIMIT) -> None:
        self.console = console
        self.quiet_limit = quiet_limit
        self.terminal = bool(console.is_terminal)
        self._tasks: list[_Task] = []
        self._current: _Task | None = None
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._last = time.monotonic()
        self._start = self._last
        self._rich = None
        self._thread: threading.Thread | None = None

    def __enter__(self) -> Steps:
        if self.terminal:
            from rich.progress import (
                BarColumn,
                MofNCompleteColumn,
                Progress,
                TextColumn,
                TimeElapsedColumn,
                TimeRemainingColumn,
            )

            self._rich = Progress(
                "[progress.description]{task.description}",
                BarColumn(),
                MofNCompleteColumn(),
                TimeElapsedColumn(),
                TimeRemainingColumn(),
                TextColumn("{task.fields[detail]}"),
                console=self.console,
                transient=True,
            )
            self._rich.__enter__()
        else:
            self._thread = threading.Thread(target=self._heartbeat, daemon=True)
            self._thread.start()
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        if self._rich is not None:
            self._rich.__exit__(kind, exc, tb)

    def add(self, description: str, total: int | None) -> int:
        """A new phase of ``total`` steps (None: unknown); its number for ``advance``."""
        task = _Task(description, total)
        with self._lock:
            self._tasks.append(task)
            current = self._current
            if current is None or (current.total is not None and current.done >= current.total):
                self._current = task  # else it waits for its first step or for ``start``
        if self._rich is not None:
            task.rich_id = int(self._rich.add_task(description, total=total, detail=""))
        return len(self._tasks) - 1

    def start(self, number: int) -> None:
        """Phase ``number`` is the one running now (a plain line says so, once)."""
        task = self._tasks[number]
        with self._lock:
            self._current = task
            begun, task.said = task.said, True
        if self._rich is None and not begun:
            self._say(task)

    def done(self, number: int) -> bool:
        """Whether phase ``number`` has done all its steps."""
        task = self._tasks[number]
        return task.total is not None and task.done >= task.total

    def advance(self, number: int, steps: int = 1) -> None:
        """``steps`` more steps of phase ``number`` are done."""
        task = self._tasks[number]
        with self._lock:
            task.done += steps
            self._current = task
        if self._rich is not None and task.rich_id is not None:
            self._rich.advance(task.rich_id, steps)  # type: ignore[arg-type]
        elif steps and self._worth_a_line(task):
            self._say(task)

    def _worth_a_line(self, task: _Task) -> bool:
        """A step gets its own plain line when it is its phase's first or last, or a
        second has passed since the last line: a log of a thousand quick steps stays short."""
        with self._lock:
            first, task.said = not task.said, True
            recent = time.monotonic() - self._last < STEP_LINE_SECONDS
        finished = task.total is not None and task.done >= task.total
        return first or finished or not recent

    def note(self, number: int, detail: str) -> None:
        """What phase ``number`` is doing now (shown beside its count)."""
        task = self._tasks[number]
        with self._lock:
            task.detail = detail
            self._current = task
        if self._rich is not None and task.rich_id is not None:
            self._rich.update(task.rich_id, detail=detail)  # type: ignore[arg-type]

    def say(self, text: str) -> None:
        """A line of its own (above the bars on a terminal)."""
        from rich.markup import escape

        with self._lock:
            self._last = time.monotonic()
        self.console.print(escape(text), highlight=False, soft_wrap=True)

    def _say(self, task: _Task, still: bool = False) -> None:
        with self._lock:
            now = time.monotonic()
            self._last = now
            text = task.line(now - self._start, still)
        self.console.print(text, markup=False, highlight=False, soft_wrap=True)

    def _heartbeat(self) -> None:
        while not self._stop.wait(0.25):
            with self._lock:
                quiet = time.monotonic() - self._last
                task = self._current
            if task is not None and quiet >= self.quiet_limit:
                self._say(task, still=True)
