"""The ring buffer of snapshots and the JSON-lines log: bounded, checked on reading."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from robocog.cli import main
from robocog.inspector.snapshot import (
    FORMAT,
    History,
    LogError,
    LogWriter,
    Snapshot,
    header,
    read_log,
)


def snap(seq: int, mind_seq: int = -1, mind: dict | None = None) -> Snapshot:
    return Snapshot(
        seq=seq,
        run="run 1",
        cycle=seq,
        wall=1000.0 + seq,
        world={"kind": "generic", "x": float(seq)},
        mind=mind,
        mind_seq=mind_seq,
        stats={"cycle_ms": 0.5},
        actions=[["Forward(distance=0.5)", "succeeded", ""]],
    )


def test_the_history_keeps_the_newest_and_counts_what_it_dropped() -> None:
    h = History(capacity=5)
    assert h.bounds() == (0, -1) and h.latest() is None
    for i in range(12):
        h.add(snap(i))
    assert len(h) == 5
    assert h.bounds() == (7, 11)
    assert h.dropped == 7
    assert h.get(6) is None and h.get(7).seq == 7 and h.get(11).seq == 11
    assert [s.seq for s in h.since(9)] == [10, 11]
    assert [s.seq for s in h.since(-1, limit=2)] == [10, 11]
    assert h.next_seq == 12


def test_a_history_holds_at_least_one() -> None:
    with pytest.raises(ValueError):
        History(0)


def test_the_log_round_trips_and_carries_the_mind_forward(tmp_path: Path) -> None:
    h = History(100)
    mind = {"kind": "nars", "concepts": []}
    writer = LogWriter(h, tmp_path / "run.jsonl", source="a test", period=0.01)
    h.add(snap(0, 0, mind))
    h.add(snap(1, 0, mind))
    time.sleep(0.05)
    h.add(snap(2, 2, {"kind": "nars", "concepts": [1]}))
    writer.close()
    lines = (tmp_path / "run.jsonl").read_text().splitlines()
    assert json.loads(lines[0])["format"] == FORMAT
    assert ["mind" in json.loads(line) for line in lines[1:]] == [True, False, True]
    head, back = read_log(tmp_path / "run.jsonl")
    assert head["source"] == "a test"
    assert [s.seq for s in back.all()] == [0, 1, 2]
    assert back.get(1).mind == mind, "a line without a mind keeps the last one"
    assert back.get(2).mind == {"kind": "nars", "concepts": [1]}
    assert back.get(1).world == {"kind": "generic", "x": 1.0}


def test_the_writer_stops_at_its_size_limit_and_says_so(tmp_path: Path) -> None:
    h = History(1000)
    writer = LogWriter(h, tmp_path / "big.jsonl", max_bytes=2000, period=0.01)
    for i in range(100):
        h.add(snap(i))
    writer.close()
    path = tmp_path / "big.jsonl"
    assert path.stat().st_size <= 2000 + 100
    head, back = read_log(path)
    assert head["end"] == "size limit"
    assert 0 < len(back) < 100
    assert writer.full


def test_writes_from_two_threads_do_not_interleave_or_repeat(tmp_path: Path) -> None:
    """``close`` writes the rest from the caller's thread, which may come while the
    writer's thread is still writing: each snapshot must still be written once."""
    import threading

    class Slow(History):
        def since(self, seq: int, limit: int = 10_000) -> list[Snapshot]:
            got = super().since(seq, limit)
            time.sleep(0.05)  # a wide window between reading what is new and writing it
            return got

    h = Slow(100)
    writer = LogWriter(h, tmp_path / "two.jsonl", period=100.0)
    for i in range(20):
        h.add(snap(i))
    threads = [threading.Thread(target=writer.flush) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    writer.close()
    writer.flush()  # after close: nothing, and no error
    seqs = [
        json.loads(line)["seq"] for line in (tmp_path / "two.jsonl").read_text().splitlines()[1:]
    ]
    assert seqs == list(range(20))


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        ([], "empty"),
        (['{"format": "something else"}'], "line 1: not a robocog-inspector log"),
        (['{"format": "robocog-inspector", "version": 99}'], "line 1: version 99"),
        (["HEAD", "not json"], "line 2: not JSON"),
        (["HEAD", "[1, 2]"], "line 2: not a JSON object"),
        (["HEAD", '{"seq": 0, "world": {}}', '{"seq": 0, "world": {}}'], "line 3: seq"),
        (["HEAD", '{"seq": 0, "world": []}'], "line 2: world"),
        (["HEAD", '{"seq": 0, "world": {}, "mind": 3}'], "line 2: mind"),
        (["HEAD", '{"seq": 0, "world": {}, "mind_seq": 5}'], "line 2: mind_seq"),
        (["HEAD", '{"seq": "0", "world": {}}'], "line 2: seq"),
    ],
)
def test_a_damaged_log_is_refused_naming_its_line(
    tmp_path: Path, lines: list[str], message: str
) -> None:
    head = json.dumps(header("x"))
    path = tmp_path / "bad.jsonl"
    path.write_text("".join((head if ln == "HEAD" else ln) + "\n" for ln in lines))
    with pytest.raises(LogError, match=message.replace("[", r"\[")):
        read_log(path)


def test_a_line_too_long_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import robocog.inspector.snapshot as snapshot

    monkeypatch.setattr(snapshot, "MAX_LINE", 200)
    path = tmp_path / "long.jsonl"
    path.write_text(
        json.dumps(header()) + "\n" + json.dumps({"seq": 0, "world": {"x": "y" * 500}}) + "\n"
    )
    with pytest.raises(LogError, match="line 2: longer than 200 bytes"):
        read_log(path)


def test_robocog_inspect_checks_a_log(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    h = History(10)
    writer = LogWriter(h, tmp_path / "r.jsonl", source="robocog demo")
    for i in range(3):
        h.add(snap(i))
    writer.close()
    assert main(["inspect", str(tmp_path / "r.jsonl"), "--check"]) == 0
    out = capsys.readouterr().out
    assert "3 snapshots (seq 0..2)" in out and "robocog demo" in out
    (tmp_path / "bad.jsonl").write_text("nothing\n")
    assert main(["inspect", str(tmp_path / "bad.jsonl"), "--check"]) == 2
    assert "line 1: not JSON" in capsys.readouterr().err
