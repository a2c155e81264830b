"""ONA's own system tests (``NAR pong 10000`` ...) as a reference run.

ONA's binary runs the same worlds in-process, with its reasoner's random generator also
driving the world. Its status line is parsed for the same figures the Python
environments report.
"""

from __future__ import annotations

import re
import subprocess
import time
from collections.abc import Callable
from dataclasses import dataclass

from robocog.ona_process import INSTALL_HINT, kill_group, line_buffered, ona_command, start_group

from .reasoners import ReasonerUnavailable

_NUMBER = r"(-?[0-9.]+|nan|-nan|inf)"
#: Status line of each test: the figures it carries, in the order they appear.
_STATUS: dict[str, tuple[re.Pattern[str], tuple[str, ...]]] = {
    "pong": (
        re.compile(rf"Hits={_NUMBER} misses={_NUMBER} ratio={_NUMBER} time={_NUMBER}"),
        ("hits", "misses", "ratio", "time"),
    ),
    "alien": (
        re.compile(rf"shots={_NUMBER} hits={_NUMBER} ratio={_NUMBER} time={_NUMBER}"),
        ("shots", "hits", "ratio", "time"),
    ),
    "cartpole": (
        re.compile(rf"successes={_NUMBER}, failures={_NUMBER}, ratio={_NUMBER}, time={_NUMBER}"),
        ("successes", "failures", "ratio", "time"),
    ),
    "robot": (
        re.compile(rf"time={_NUMBER} moves={_NUMBER} move_success_ratio={_NUMBER} eaten={_NUMBER}"),
        ("time", "moves", "ratio", "eaten"),
    ),
    "bandrobot": (
        re.compile(rf"ratio={_NUMBER} sleepInVisualization=\w+ time={_NUMBER}"),
        ("ratio", "time"),
    ),
}
_STATUS["pong2"] = _STATUS["pong"]


@dataclass
class BuiltinResult:
    """Figures printed by ONA's own test and the wall time of the whole process."""

    env: str
    steps: int
    metrics: dict[str, float]
    wall_time: float


def has_builtin(env: str) -> bool:
    """Whether ONA's binary has a system test of this name that prints a figure."""
    return env in _STATUS


def parse_status(env: str, line: str) -> dict[str, float] | None:
    """The figures of one status line of ONA's test ``env``, or None if it is not one."""
    pattern, names = _STATUS[env]
    found = pattern.search(line)
    if not found:
        return None
    values = {}
    for name, text in zip(names, found.groups(), strict=True):
        try:
            values[name] = float(text)
        except ValueError:
            values[name] = float("nan")
    return values


def run_builtin(
    env: str,
    steps: int,
    on_step: Callable[[int], None] | None = None,
    timeout: float = 3600.0,
) -> BuiltinResult:
    """Run ``NAR <env> <steps>`` and return the figures of its last status line."""
    command = ona_command()
    if command is None:
        raise ReasonerUnavailable(f"ONA is not installed ({INSTALL_HINT})")
    if not has_builtin(env):
        raise ReasonerUnavailable(f"ONA has no built-in test named {env!r} that prints a figure")
    started = time.perf_counter()
    last: dict[str, float] | None = None
    with start_group(
        line_buffered([*command, env, str(steps)]),
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        errors="replace",
    ) as proc:
        assert proc.stdout is not None
        try:
            for line in proc.stdout:
                if "time=" not in line:
                    continue
                figures = parse_status(env, line)
                if figures is None:
                    continue
                last = figures
                if on_step is not None:
                    on_step(min(steps, int(figures["time"])))
                if time.perf_counter() - started > timeout:
                    kill_group(proc)
                    break
        except BaseException:
            kill_group(proc)  # interrupted: do not wait for the whole test to finish
            raise
        proc.wait()
    wall = time.perf_counter() - started
    if last is None:
        raise RuntimeError(f"`NAR {env} {steps}` printed no status line")
    return BuiltinResult(env, steps, last, wall)
