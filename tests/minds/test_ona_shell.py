"""ONA 0.9.2 behind NarsMind's calls (only where its NAR command is installed)."""

from __future__ import annotations

import sys

import pytest

from robocog.minds.nars_mind import background
from robocog.minds.ona_shell import (
    ONA_GOTO_RULE,
    PRINTED_GOTO_RULE,
    OnaShell,
    ona_knowledge,
    unavailable,
)
from robocog.nars import parse_sentence, parse_term
from robocog.ona_process import OnaError, OnaUnavailable

needs_ona = pytest.mark.skipif(unavailable() is not None, reason=str(unavailable()))


def test_only_the_goto_rule_is_rewritten_for_ona() -> None:
    printed, ona = background(), ona_knowledge()
    assert PRINTED_GOTO_RULE in printed and ONA_GOTO_RULE in ona
    assert [a for a, b in zip(printed, ona, strict=True) if a != b] == [PRINTED_GOTO_RULE]


@needs_ona
def test_executions_call_the_registered_operation_and_answers_come_back() -> None:
    shell = OnaShell()
    calls: list[str | None] = []
    shell.register_operation("^left", calls.append)
    try:
        for line in ("<(a &/ ^left) =/> g>.", "a. :|:", "g! :|:"):
            shell.add_input(line)
        shell.cycles(2)
        assert calls == [None]
        shell.add_input("<x --> y>.")
        answer = shell.ask("<x --> ?1>?")
        assert answer is not None and answer.term == "<x --> y>"
        assert (answer.truth.f, answer.truth.c) == (1.0, 0.9)
        assert shell.ask("<nothing --> known>?") is None
    finally:
        shell.close()
    assert shell.proc.poll() is not None


@needs_ona
def test_sentences_go_in_and_arguments_and_answers_come_back_as_terms() -> None:
    shell = OnaShell()
    calls: list[object] = []
    shell.register_operation("^pick", calls.append)
    try:
        shell.add_input("<(a &/ <({SELF} * {cup1}) --> ^pick>) =/> g>.")
        shell.add_sentence(parse_sentence("a. :|:"))
        shell.add_sentence(parse_sentence("g! :|:"))
        shell.cycles(2)
        assert calls == [parse_term("({SELF} * {cup1})")]
        shell.add_sentence(parse_sentence("<x --> y>. {1.0 0.9}"))
        answer = shell.answer(parse_term("<x --> ?1>"))
        assert answer is not None and answer.term is parse_term("<x --> y>")
        assert shell.answer(parse_term("<nothing --> ?1>")) is None
    finally:
        shell.close()


def test_a_missing_or_dying_ona_is_an_error_that_names_the_command() -> None:
    assert "no-such-nar" in str(unavailable("no-such-nar"))
    with pytest.raises(OnaUnavailable, match="`no-such-nar shell`"):
        OnaShell("no-such-nar")
    shell = OnaShell(sys.executable, timeout=10)  # `python shell`: no such script, it exits
    try:
        with pytest.raises(OnaError, match=f"`{sys.executable} shell` (exited|closed its input)"):
            shell.cycles(1)
    finally:
        shell.close()
    assert shell.proc.returncode is not None  # reaped, no zombie left
