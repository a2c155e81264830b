"""What long commands show: plain lines at least every few seconds when piped."""

from __future__ import annotations

import io
import re
import time

from rich.console import Console

from robocog.progress import Steps, duration, header


def _piped() -> tuple[Console, io.StringIO]:
    out = io.StringIO()
    return Console(file=out, force_terminal=False, width=80), out


def test_piped_steps_print_a_line_per_step_and_one_while_a_step_runs_long() -> None:
    console, out = _piped()
    with Steps(console, quiet_limit=0.2) as steps:
        runs = steps.add("garbage runs", 2)
        steps.advance(runs)
        steps.note(runs, "NARS run 2")
        time.sleep(0.7)  # a long step: the progress must speak meanwhile
        steps.advance(runs)
        assert steps.done(runs)
    lines = out.getvalue().splitlines()
    assert lines[0] == "garbage runs: 1/2 (0 s)"
    still = [line for line in lines if "still running" in line]
    assert still and all(line.startswith("garbage runs: 1/2, NARS run 2,") for line in still)
    assert lines[-1].startswith("garbage runs: 2/2, NARS run 2 (")


def test_a_new_phase_is_announced_and_silence_ends_with_the_steps() -> None:
    console, out = _piped()
    with Steps(console, quiet_limit=0.1) as steps:
        runs = steps.add("garbage runs", 1)
        rounds = steps.add("NARS learning rounds", 3)
        steps.advance(runs)
        steps.start(rounds)
        time.sleep(0.35)
    text = out.getvalue()
    assert "NARS learning rounds: 0/3 (" in text
    assert re.search(r"NARS learning rounds: 0/3, still running \(\d+ s\)", text)
    after = len(out.getvalue())
    time.sleep(0.3)  # nothing more once the block is left
    assert len(out.getvalue()) == after


def test_long_lines_are_not_wrapped_when_piped() -> None:
    console, out = _piped()
    with Steps(console) as steps:
        task = steps.add("modules compiled", 22)
        steps.note(task, "compiling " + ", ".join(["matchers", "decision"] * 8))
        steps.advance(task)
    assert len(out.getvalue().splitlines()) == 1


def test_a_terminal_gets_a_bar_and_no_plain_lines() -> None:
    out = io.StringIO()
    console = Console(file=out, force_terminal=True, width=80)
    with Steps(console, quiet_limit=0.05) as steps:
        task = steps.add("garbage runs", 3)
        steps.advance(task)
        time.sleep(0.2)
    assert "still running" not in out.getvalue()
    assert "garbage runs" in out.getvalue()


def test_the_header_and_rough_durations() -> None:
    console, out = _piped()
    header(console, "robocog demo", "six runs per mind", duration(17))
    assert out.getvalue() == "robocog demo: six runs per mind (about 15 s)\n"
    assert duration(1) == "about 5 s"
    assert duration(130) == "about 2 min"
    assert duration(5400) == "about 1.5 h"


def test_quick_steps_are_summed_up_in_a_few_lines() -> None:
    console, out = _piped()
    with Steps(console) as steps:
        task = steps.add("missions", 500)
        for _ in range(500):
            steps.advance(task)
    lines = out.getvalue().splitlines()
    assert lines[0].startswith("missions: 1/500") and lines[-1].startswith("missions: 500/500")
    assert len(lines) <= 4
