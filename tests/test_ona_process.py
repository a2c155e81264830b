"""ONA's child process: the exchange, the failures it names, and an end that leaves nothing.

The tests that need ONA's binary run where the ``ona`` package is installed (as in CI);
the failures are played by small Python children, which need nothing.
"""

from __future__ import annotations

import gc
import os
import signal
import sys
import time
from pathlib import Path

import pytest

from robocog.ona_process import (
    OnaError,
    OnaProcess,
    OnaUnavailable,
    ona_command,
    unavailable_reason,
)

needs_ona = pytest.mark.skipif(unavailable_reason() is not None, reason=str(unavailable_reason()))

PY = [sys.executable, "-c"]


def gone(pid: int, within: float = 5.0) -> bool:
    """Whether process ``pid`` has ended (gone, or a zombie left to its new parent)."""
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        try:
            state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except (FileNotFoundError, ProcessLookupError):
            return True
        if state in ("Z", "X"):
            return True
        time.sleep(0.05)
    return False


@needs_ona
def test_ona_is_found_as_its_binary_and_answers_up_to_the_marker() -> None:
    command = ona_command()
    assert command is not None and os.access(command[0], os.X_OK)
    seen: list[str] = []
    with OnaProcess() as ona:
        assert ona.name.endswith(" shell")
        ona.send("*volume=0")
        reply = ona.exchange(["<a --> b>."], on_line=seen.append)
        assert reply == seen
        assert [line for line in reply if line.startswith("Input:")] == [
            "Input: <a --> b>. Priority=1.000000 Stamp=[1] "
            "Truth: frequency=1.000000, confidence=0.900000"
        ]
        assert not any(line.startswith("Comment:") for line in reply)
        # the next exchange starts where the last one ended
        answer = ona.exchange(["<a --> ?1>?"])
        assert [line for line in answer if line.startswith("Answer:")][0].startswith(
            "Answer: <a --> b>."
        )
    assert ona.proc.returncode == 0  # it ended on `quit`, not by a kill


@needs_ona
def test_a_line_ona_cannot_read_is_an_error_with_onas_message() -> None:
    ona = OnaProcess(timeout=30)
    try:
        with pytest.raises(OnaError, match="(?s)shell` rejected an input.*Parsing error"):
            ona.exchange(["<a --> "])
    finally:
        ona.close()
    assert ona.proc.returncode is not None and gone(ona.proc.pid)


@needs_ona
def test_a_failing_line_handler_leaves_a_process_that_is_killed_not_asked() -> None:
    ona = OnaProcess(timeout=30)

    def refuse(line: str) -> None:
        raise ValueError(line)

    with pytest.raises(ValueError):
        ona.exchange(["<a --> b>."], on_line=refuse)
    ona.close()
    assert ona.proc.returncode == -signal.SIGKILL


def test_a_missing_binary_is_named_with_how_to_install_it() -> None:
    assert "no-such-ona-binary" in str(unavailable_reason(["no-such-ona-binary"]))
    assert unavailable_reason([sys.executable]) is None
    with pytest.raises(OnaUnavailable, match="no-such-ona-binary shell.*pip install ona"):
        OnaProcess(["no-such-ona-binary"])


def test_a_child_that_exits_is_reported_with_its_command_status_and_last_output() -> None:
    ona = OnaProcess([*PY, "import sys; print('first'); print('last words'); sys.exit(3)"])
    with pytest.raises(OnaError) as info:
        ona.exchange(["<a --> b>."])
    message = str(info.value)
    assert message.startswith(f"`{sys.executable} -c ")
    assert "exited (status 3)" in message and message.endswith("first\n  last words")
    ona.close()
    assert ona.proc.returncode == 3 and gone(ona.proc.pid)
    with pytest.raises(OnaError, match="closed"):
        ona.send("<a --> b>.")


def test_what_the_child_writes_to_stderr_is_in_the_error() -> None:
    ona = OnaProcess([*PY, "import sys; sys.exit('cannot go on')"])
    with pytest.raises(OnaError, match="(?s)exited .status 1.*cannot go on"):
        ona.exchange()
    ona.close()


def test_a_child_that_does_not_answer_times_out_and_is_killed() -> None:
    ona = OnaProcess([*PY, "import time; time.sleep(60)"], timeout=0.3)
    started = time.monotonic()
    with pytest.raises(OnaError, match="gave no reply within 0.3 s"):
        ona.exchange(["<a --> b>."])
    ona.close()
    assert time.monotonic() - started < 10  # killed, not waited for
    assert ona.proc.returncode == -signal.SIGKILL and gone(ona.proc.pid)


def test_closing_a_wrapper_ends_the_child_it_started_too() -> None:
    # as ONA's `NAR` script starts `NARexe`: the grandchild must not outlive the close
    wrapper = (
        "import subprocess, sys, time\n"
        "child = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(60)'])\n"
        "print(child.pid, flush=True)\n"
        "time.sleep(60)\n"
    )
    ona = OnaProcess([*PY, wrapper], timeout=0.5)
    with pytest.raises(OnaError, match="no reply") as info:
        ona.exchange()
    grandchild = int(str(info.value).rsplit("\n", 1)[1])
    assert not gone(grandchild, within=0)
    ona.close()
    assert gone(ona.proc.pid) and gone(grandchild)


def test_a_process_dropped_without_close_is_killed_and_reaped() -> None:
    ona = OnaProcess([*PY, "import time; time.sleep(60)"])
    proc = ona.proc
    del ona
    gc.collect()
    assert proc.returncode == -signal.SIGKILL and gone(proc.pid)


def test_closing_twice_is_harmless() -> None:
    ona = OnaProcess([*PY, "import sys; sys.stdin.read()"])
    ona.close()
    ona.close()
    assert ona.proc.returncode is not None and not ona.running
