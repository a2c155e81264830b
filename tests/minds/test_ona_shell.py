"""ONA 0.9.2 behind NarsMind's calls (only where its NAR command is installed)."""

from __future__ import annotations

import pytest

from robocog.minds.nars_mind import background
from robocog.minds.ona_shell import (
    ONA_GOTO_RULE,
    PRINTED_GOTO_RULE,
    OnaShell,
    ona_knowledge,
    unavailable,
)

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
