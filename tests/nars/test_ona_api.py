"""ONA's Python interface: the dicts ``AddInput`` returns, held against ONA's binary."""

from __future__ import annotations

import pytest

from robocog.nars import ona_api
from robocog.ona_process import OnaProcess, unavailable_reason


def test_an_input_line_gives_onas_fields() -> None:
    proc = ona_api.spawnNAR()
    r = ona_api.AddInput("<a --> b>.", Print=False, usedNAR=proc)
    assert set(r) == {
        "input",
        "derivations",
        "answers",
        "executions",
        "reason",
        "selections",
        "raw",
        "requestOutputArgs",
    }
    assert r["input"] == [
        {
            "occurrenceTime": "eternal",
            "Stamp": [1],
            "punctuation": ".",
            "term": "<a --> b>",
            "truth": {"frequency": "1.000000", "confidence": "0.900000"},
            "Priority": "1.000000",
        }
    ]
    assert r["reason"] is None and r["executions"] == [] and r["requestOutputArgs"] is False
    assert r["raw"].startswith("Input: <a --> b>.")


def test_answers_executions_and_the_reason_of_a_decision() -> None:
    proc = ona_api.spawnNAR()
    for line in ["<a --> b>.", "<b --> c>.", "<(x &/ <({SELF} * y) --> ^go>) =/> h>.", "x. :|:"]:
        ona_api.AddInput(line, Print=False, usedNAR=proc)
    ans = ona_api.AddInput("<a --> c>?", Print=False, usedNAR=proc)["answers"]
    assert ans == [
        {
            "occurrenceTime": "eternal",
            "Stamp": [2, 1],
            "punctuation": ".",
            "term": "<a --> c>",
            "truth": {"frequency": "1.000000", "confidence": "0.810000"},
        }
    ]
    r = ona_api.AddInput("h! :|:", Print=False, usedNAR=proc)
    assert r["executions"] == [{"operator": "^go", "arguments": "y"}]
    reason = r["reason"]
    assert reason["desire"] == "0.791600"
    assert reason["hypothesis"]["term"] == "<(x &/ <({SELF} * y) --> ^go>) =/> h>"
    assert reason["hypothesis"]["occurrenceTime"] == "eternal"
    assert reason["precondition"]["term"] == "x"
    assert reason["precondition"]["punctuation"] == "."
    assert ona_api.AddInput("<nothing --> here>?", Print=False, usedNAR=proc)["answers"] == [
        {"occurrenceTime": "eternal", "punctuation": ".", "term": "None"}
    ]


def test_stats_reset_exit_and_a_bad_line() -> None:
    proc = ona_api.spawnNAR()
    ona_api.AddInput("<a --> b>.", Print=False, usedNAR=proc)
    stats = ona_api.GetStats(usedNAR=proc)
    assert stats["total_concepts"] >= 1 and stats["currentTime"] == 2.0
    assert ona_api.AddInput("*stats", Print=False, usedNAR=proc) == stats
    bad = ona_api.AddInput("<a --> ", Print=False, usedNAR=proc)
    assert bad["raw"].startswith("Error: line") and bad["input"] == []
    ona_api.Reset(usedNAR=proc)
    assert ona_api.GetStats(usedNAR=proc)["total_concepts"] == 0
    ona_api.Exit(usedNAR=proc)
    with pytest.raises(RuntimeError):
        ona_api.AddInput("<a --> b>.", Print=False, usedNAR=proc)


def test_print_echoes_the_raw_output(capsys: pytest.CaptureFixture[str]) -> None:
    proc = ona_api.spawnNAR()
    ona_api.AddInput("<a --> b>.", usedNAR=proc)
    assert "Input: <a --> b>." in capsys.readouterr().out


def test_the_default_reasoner_can_be_replaced() -> None:
    first = ona_api.getNAR()
    other = ona_api.spawnNAR()
    ona_api.setNAR(other)
    try:
        assert ona_api.getNAR() is other
    finally:
        ona_api.setNAR(first)


def _ona_output(ona: OnaProcess, line: str) -> list[str]:
    """ONA's output lines for one input line, stripped as ONA's wrapper strips them."""
    return [got.strip() for got in ona.exchange([line])]


SCRIPT = [
    "<(x &/ ^left) =/> g>.",
    "x. :|:",
    "g! :|:",
    "<(x &/ <({SELF} * y) --> ^go>) =/> h>.",
    "x. :|:",
    "h! :|:",
    "<a --> b>.",
    "<b --> c>.",
    "<a --> c>?",
    "<c --> a>?",
    "<a --> ?1>?",
    "a? :|:",
    "<(x &/ ^left) =/> g>?",
    "<{tom} --> cat>. %0.8;0.7%",
    "<{tom} --> cat>?",
    "<{tom} --> cat>. :|:",
]


@pytest.mark.skipif(unavailable_reason() is not None, reason=str(unavailable_reason()))
def test_the_same_dicts_as_ona_for_the_same_inputs() -> None:
    """ONA's own output lines read the same way give the same inputs, answers,
    executions and reasons (derivations in idle cycles differ with the engines, so
    they are compared only where no cycle runs on its own)."""
    ona = OnaProcess(timeout=30)
    ona.send("*volume=100")
    ours = ona_api.spawnNAR()
    try:
        for line in SCRIPT:
            theirs = ona_api.GetOutput(_ona_output(ona, line))
            mine = ona_api.AddInput(line, Print=False, usedNAR=ours)
            for key in ("input", "answers", "executions", "reason"):
                assert mine[key] == theirs[key], (line, key)
            assert [type(v) for v in mine.values()] == [type(v) for v in theirs.values()]
    finally:
        ona.close()
