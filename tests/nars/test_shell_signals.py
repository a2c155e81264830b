"""SIGINT and SIGTERM at any moment of a ``robocog nar`` session: the session is saved
and the process ends promptly, with no traceback and no temporary file left behind.

Each test runs ten sessions (five at a time) in subprocesses. The time from the signal
to the end is asserted loosely here (the suite shares its cores); the 2 s the project
promises is measured on a quiet machine (docs/fuzzing.md)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robocog.nars.nar import NAR

REPO = Path(__file__).resolve().parents[2]
TRIALS = 10
#: generous: the promise is 2 s, the suite's machine may be busy
PATIENCE = 20.0


def _start(save: Path) -> subprocess.Popen[bytes]:
    return subprocess.Popen(
        [sys.executable, "-m", "robocog", "nar", "--quiet", "--save", str(save)],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=dict(os.environ, PYTHONPATH=str(REPO / "src")),
    )


def _wait_for(proc: subprocess.Popen[bytes], text: bytes, count: int = 1) -> None:
    assert proc.stdout is not None
    seen = b""
    deadline = time.monotonic() + 120
    while seen.count(text) < count and time.monotonic() < deadline:
        line = proc.stdout.readline()
        if not line:
            break
        seen += line
    assert seen.count(text) >= count, seen[-500:]


def _check_saved(proc: subprocess.Popen[bytes], save: Path, signalled_at: float) -> float:
    proc.wait(timeout=PATIENCE + 60)
    took = time.monotonic() - signalled_at
    assert proc.stderr is not None
    err = proc.stderr.read()
    assert b"Traceback" not in err, err[-2000:]
    assert save.exists(), err[-500:]
    assert not list(save.parent.glob(".*.tmp"))
    assert NAR.load(save).ask("<a --> c>?") is not None
    return took


@pytest.mark.slow
def test_sigterm_with_the_end_of_input_saves_every_time(tmp_path: Path) -> None:
    took = []
    for batch in range(0, TRIALS, 5):
        runs = []
        for i in range(batch, batch + 5):
            save = tmp_path / str(i) / "m.nar"
            save.parent.mkdir()
            proc = _start(save)
            assert proc.stdin is not None
            proc.stdin.write(b"<a --> b>.\n<b --> c>.\n")
            proc.stdin.flush()
            runs.append((proc, save))
        for i, (proc, save) in enumerate(runs):
            _wait_for(proc, b"Input:", 2)
            assert proc.stdin is not None
            proc.stdin.close()  # the end of the input ...
            if i % 2:
                time.sleep(0.001 * i)
            at = time.monotonic()
            proc.send_signal(signal.SIGTERM)  # ... and a signal with it
            took.append(_check_saved(proc, save, at))
            assert proc.returncode in (0, 128 + signal.SIGTERM)
    assert max(took) < PATIENCE


@pytest.mark.slow
def test_a_second_sigint_during_a_long_cycles_line_still_saves(tmp_path: Path) -> None:
    took = []
    for batch in range(0, TRIALS, 5):
        runs = []
        for i in range(batch, batch + 5):
            save = tmp_path / str(i) / "m.nar"
            save.parent.mkdir()
            proc = _start(save)
            assert proc.stdin is not None
            proc.stdin.write(b"<a --> b>.\n<b --> c>.\n10000000\n")
            proc.stdin.flush()
            runs.append((proc, save))
        for proc, save in runs:
            _wait_for(proc, b"performing 10000000")
            at = time.monotonic()
            proc.send_signal(signal.SIGINT)
            time.sleep(0.05)
            proc.send_signal(signal.SIGINT)
            took.append(_check_saved(proc, save, at))
            assert proc.returncode == 128 + signal.SIGINT
    assert max(took) < PATIENCE


def test_a_temporary_file_of_a_killed_save_goes_at_the_next_start(tmp_path: Path) -> None:
    save = tmp_path / "m.nar"
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"],
        capture_output=True,
        text=True,
        check=True,
    )
    left = tmp_path / f".m.nar.{int(dead.stdout)}.abc123.tmp"
    left.write_bytes(b"x" * 1000)  # as a save killed by SIGKILL leaves it
    proc = _start(save)
    out, err = proc.communicate(b"<a --> b>.\n<b --> c>.\n", timeout=120)
    assert proc.returncode == 0, err
    assert not left.exists() and save.exists()
