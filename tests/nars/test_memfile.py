"""Saved memories: a data format read with checks, never code; saves that go on exactly
as the run that never stopped; files that are refused with one line."""

from __future__ import annotations

import gzip
import json
import os
import pickle
import random
import subprocess
import sys
from pathlib import Path

import pytest

from robocog.nars import NAR, NarseseError, memfile
from robocog.nars.memfile import MemoryFileError

REPO = Path(__file__).resolve().parents[2]


def _workload(seed: int) -> list[str]:
    """Declarative, temporal and procedural input with babbling: the continuation
    depends on concepts, tables, queues, goal layers, time and the random draws."""
    rng = random.Random(seed)
    lines = ["*setopname 1 ^left", "*setopname 2 ^right", "*babblingops=2", "*motorbabbling=0.3"]
    for i in range(1, 40):
        lines.append(f"<n{i} --> n{rng.randrange(max(0, i - 6), i)}>.")
    for _ in range(60):
        lines.append(rng.choice(["good", "a", "b", "<x --> [on]>"]) + ". :|:")
        lines.append(rng.choice(["good! :|:", "<n30 --> n2>?", "<(a &/ ^left) =/> good>?", "2"]))
    lines += ["<(a &/ ^left) =/> good>.", "a. :|:", "good! :|:", "5", "<n35 --> ?1>?"]
    return lines


def _run(lines: list[str], cut: int | None, tmp: Path, **config: object) -> list[str]:
    nar = NAR(**config)
    out: list[str] = []
    nar.output = out.append
    nar.config.print_derivations = True
    for i, line in enumerate(lines):
        if i == cut:
            nar.save(tmp / "m.nar")
            nar = NAR.load(tmp / "m.nar")
            nar.output = out.append
        nar.add_input(line)
    return out


@pytest.mark.parametrize(
    "config",
    [
        pytest.param({}, marks=pytest.mark.slow),
        {"concepts_max": 48, "cycling_belief_events_max": 8},
    ],
)
def test_the_continuation_after_save_and_load_equals_the_uninterrupted_run(
    tmp_path: Path, config: dict[str, object]
) -> None:
    lines = _workload(5)
    whole = _run(lines, None, tmp_path, **config)
    assert sum(" executed with args" in x for x in whole) > 3
    assert sum(x.startswith("Answer:") for x in whole) > 10
    for cut in (10, 45, 90, 131, len(lines) - 3):
        assert _run(lines, cut, tmp_path, **config) == whole, f"cut at line {cut}"


def test_a_save_is_gzip_json_with_a_header_and_terms_as_narsese(tmp_path: Path) -> None:
    nar = NAR()
    for line in ["<a --> b>.", "<(x &/ ^left) =/> g>.", "x. :|:"]:
        nar.add_input(line)
    nar.save(tmp_path / "m.nar")
    doc = json.loads(gzip.decompress((tmp_path / "m.nar").read_bytes()))
    assert (doc["format"], doc["version"]) == ("robocog-nar-memory", 1)
    assert doc["robocog"] and doc["config"]["concepts_max"] == 4096
    assert "<a --> b>" in doc["terms"] and "<(x &/ ^left) =/> g>" in doc["terms"]
    assert doc["reasoner"]["time"] == nar.time
    assert (tmp_path / "m.nar").stat().st_mode & 0o777 == 0o600
    assert not list(tmp_path.glob("*.tmp")) and not list(tmp_path.glob(".*.tmp"))


def test_equal_states_save_to_equal_bytes(tmp_path: Path) -> None:
    a, b = NAR(), NAR()
    for nar in (a, b):
        for line in ["<a --> b>.", "<b --> c>.", "3"]:
            nar.add_input(line)
    assert memfile.encode(a) == memfile.encode(b)


def _saved(tmp_path: Path) -> dict:
    nar = NAR()
    for line in ["<a --> b>.", "<b --> c>.", "<(x &/ ^left) =/> g>.", "x. :|:", "g! :|:"]:
        nar.add_input(line)
    nar.save(tmp_path / "good.nar")
    return json.loads(gzip.decompress((tmp_path / "good.nar").read_bytes()))


def _refused(tmp_path: Path, doc: object, expect: str) -> None:
    bad = tmp_path / "bad.nar"
    bad.write_bytes(gzip.compress(json.dumps(doc).encode()))
    with pytest.raises(MemoryFileError) as info:
        NAR.load(bad)
    message = str(info.value)
    assert "\n" not in message and expect in message, message


def test_a_damaged_field_is_refused_naming_it(tmp_path: Path) -> None:
    doc = _saved(tmp_path)
    cases = [
        (("reasoner", "time"), 0, "reasoner.time"),
        (("reasoner", "time"), 10**30, "reasoner.time"),
        (("reasoner", "time"), "5", "reasoner.time"),
        (("config", "concepts_max"), -1, "config.concepts_max"),
        (("config", "decision_threshold"), 7.5, "config.decision_threshold"),
        (("config", "print_derivations"), 1, "config.print_derivations"),
        (("events", 0, "truth"), [0.5, 1.5], "events[0].truth[1]"),
        (("events", 0, "type"), "?", "events[0].type"),
        (("events", 0, "term"), 10**6, "events[0].term"),
        (("concepts", 0, "belief"), 10**6, "concepts[0].belief"),
        (("terms", 0), "<a -->", "terms[0]"),
        (("terms", 0), "<a-->b>", "canonical"),
        (("operations", 0), "left; rm -rf", "operations[0]"),
        (("format",), "something-else", "format"),
        (("version",), 99, "version 99"),
    ]
    for path, value, expect in cases:
        d = json.loads(json.dumps(doc))
        node = d
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
        _refused(tmp_path, d, expect)
    d = json.loads(json.dumps(doc))
    d["events"][0]["stamp"] = list(range(5000))
    _refused(tmp_path, d, "events[0].stamp")
    d = json.loads(json.dumps(doc))
    del d["concepts"]
    _refused(tmp_path, d, "lacks concepts")
    d = json.loads(json.dumps(doc))
    d["extra"] = 1
    _refused(tmp_path, d, "unknown fields extra")


def test_nan_infinity_and_deep_nesting_are_refused(tmp_path: Path) -> None:
    doc = _saved(tmp_path)
    text = json.dumps(doc).replace('"concept_threshold":', '"concept_threshold": NaN, "x":', 1)
    p = tmp_path / "nan.nar"
    p.write_bytes(text.encode())
    with pytest.raises(MemoryFileError, match="NaN"):
        NAR.load(p)
    p.write_bytes(b'{"format":"robocog-nar-memory",' + b"[" * 100_000 + b"]" * 100_000 + b"}")
    with pytest.raises(MemoryFileError):
        NAR.load(p)
    deep = "(" * 5000 + "a" + ")" * 5000
    doc["terms"][0] = deep
    _refused(tmp_path, doc, "terms[0]")


def test_truncated_empty_text_and_pickle_files_are_refused(tmp_path: Path) -> None:
    nar = NAR()
    nar.add_input("<a --> b>.")
    nar.save(tmp_path / "m.nar")
    data = (tmp_path / "m.nar").read_bytes()
    cases = {
        "truncated": (data[: len(data) // 2], "truncated"),
        "empty": (b"", "empty file"),
        "text": (b"<a --> b>.\n", "not a robocog memory"),
        "pickle": (pickle.dumps({"format": "robocog-nar-3"}), "convert_pickle_memory.py"),
        "json": (b'{"a": 1}', "not a robocog memory"),
        "gzip-junk": (gzip.compress(b"hello"), "not a robocog memory"),
    }
    for name, (content, expect) in cases.items():
        p = tmp_path / f"{name}.nar"
        p.write_bytes(content)
        with pytest.raises(MemoryFileError, match=expect):
            NAR.load(p)


class _Payload:
    """A pickle that, when read, creates the file named ``marker``."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self) -> tuple[object, ...]:
        return (open, (str(self.marker), "w"))


def _cli(args: list[str], text: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(REPO / "src"))
    return subprocess.run(
        [sys.executable, "-m", "robocog", "nar", *args],
        input=text,
        capture_output=True,
        text=True,
        timeout=120,
        cwd=cwd,
        env=env,
    )


def test_a_pickle_payload_is_refused_by_load_and_runs_nothing(tmp_path: Path) -> None:
    marker = tmp_path / "marker"
    evil = tmp_path / "evil.nar"
    evil.write_bytes(pickle.dumps(_Payload(marker)))
    with pytest.raises(MemoryFileError, match="pickle"):
        NAR.load(evil)
    nar = NAR()
    nar.memory_dir = tmp_path
    nar.add_input("<a --> b>.")
    with pytest.raises(NarseseError, match="pickle"):
        nar.add_input("*load evil.nar")
    assert nar.ask("<a --> b>?") is not None
    r = _cli(["--load", str(evil)], "", tmp_path)
    assert r.returncode == 2 and "pickle" in r.stderr and "Traceback" not in r.stderr
    r = _cli(["--memory-dir", str(tmp_path), "--quiet"], "*load evil.nar\n<a --> b>.\n", tmp_path)
    assert r.returncode == 0
    assert "Error: line 1, column 7: *load:" in r.stdout and "pickle" in r.stdout
    assert "Input: <a --> b>." in r.stdout
    assert not marker.exists()


def test_the_converter_turns_a_trusted_format_3_save_into_a_memory_file(tmp_path: Path) -> None:
    nar = NAR()
    for line in ["<a --> b>.", "<b --> c>.", "<(x &/ ^left) =/> g>."]:
        nar.add_input(line)
    # a save as robocog wrote them before memory files: the reasoner's fields, pickled
    state = {
        "format": "robocog-nar-3",
        "config": nar.config.as_dict(),
        "seed": nar.seed,
        "rand": nar.random_state(),
        "memory": nar.memory,
        "time": nar.time,
        "stamp_base": nar.stamp_base,
        "concept_threshold": nar.concept_threshold,
        "matched_total": nar.matched_total,
        "op_names": nar.op_names,
        "stats": nar.stats,
        "pending": nar.pending_questions,
        "time_index": nar.time_index,
        "table_index": nar.table_index,
        "links_by_subject": nar.links_by_subject,
        "general_links": nar.general_links,
        "goal_layers": nar.goal_layers,
        "recent_goal_concepts": nar.recent_goal_concepts,
    }
    old = tmp_path / "old.nar"
    old.write_bytes(pickle.dumps(state))
    tool = REPO / "tools" / "convert_pickle_memory.py"
    env = dict(os.environ, PYTHONPATH=str(REPO / "src"))
    run = [sys.executable, str(tool)]
    refused = subprocess.run(
        run + [str(old), str(tmp_path / "x.nar")], capture_output=True, env=env
    )
    assert refused.returncode == 2 and not (tmp_path / "x.nar").exists()
    done = subprocess.run(run + ["--trust", str(old), str(tmp_path / "new.nar")], env=env)
    assert done.returncode == 0
    again = NAR.load(tmp_path / "new.nar")
    again.process_id = nar.process_id  # the one field format 3 did not keep
    assert memfile.encode(again) == memfile.encode(nar)
    answer = again.ask("<a --> c>?")
    assert answer is not None and answer.truth.c == pytest.approx(0.81)


def test_no_module_of_the_package_reads_pickles() -> None:
    src = REPO / "src" / "robocog"
    for path in src.rglob("*.py"):
        text = path.read_text()
        assert "pickle.load" not in text and "pickle.Unpickler" not in text, path


# ---------------------------------------------------------------- the memory directory
def test_save_and_load_lines_stay_inside_the_memory_directory(tmp_path: Path) -> None:
    box = tmp_path / "box"
    box.mkdir()
    outside = tmp_path / "outside.txt"
    outside.write_text("keep me")
    (box / "link.nar").symlink_to(outside)
    (box / "notes.txt").write_text("not a memory")
    (box / "sub").mkdir()
    nar = NAR()
    nar.add_input("<a --> b>.")
    with pytest.raises(NarseseError, match="memory directory"):
        nar.add_input("*save m.nar")  # no directory named: refused
    nar.memory_dir = box
    for name, why in [
        ("../outside.txt", "'..'"),
        (str(outside), "absolute"),
        ("link.nar", "symbolic link"),
        ("notes.txt", "not a robocog memory"),
        ("sub", "directory"),
        ("", "file name"),
    ]:
        with pytest.raises(NarseseError, match=why):
            nar.add_input(f"*save {name}")
    assert outside.read_text() == "keep me" and (box / "notes.txt").read_text() == "not a memory"
    nar.add_input("*save sub/m.nar")
    nar.add_input("*save sub/m.nar")  # a memory may be replaced by a newer one
    assert (box / "sub" / "m.nar").stat().st_mode & 0o777 == 0o600
    other = NAR()
    other.memory_dir = box
    other.add_input("*load sub/m.nar")
    assert other.ask("<a --> b>?") is not None
    (box / "escape").symlink_to(tmp_path)
    with pytest.raises(NarseseError, match="leads out"):
        nar.add_input("*save escape/m.nar")
    assert not (tmp_path / "m.nar").exists()


def test_a_save_killed_midway_leaves_its_temporary_file_to_the_next_save(tmp_path: Path) -> None:
    stale = tmp_path / ".m.nar.abc123.tmp"
    stale.write_bytes(b"half a save")
    old = 1_000_000_000
    os.utime(stale, (old, old))
    fresh = tmp_path / ".m.nar.def456.tmp"  # maybe another save under way: kept
    fresh.write_bytes(b"")
    NAR().save(tmp_path / "m.nar")
    assert not stale.exists() and fresh.exists()


@pytest.mark.parametrize("seed", [-5, 0, 666, (1 << 63) - 1])
def test_any_seed_the_shell_accepts_survives_a_save(tmp_path: Path, seed: int) -> None:
    nar = NAR(seed=seed)
    nar.add_input("<a --> b>.")
    nar.save(tmp_path / "m.nar")
    again = NAR.load(tmp_path / "m.nar")
    assert (again.seed, again.random_state()) == (seed, nar.random_state())
    assert [again.rand() for _ in range(3)] == [nar.rand() for _ in range(3)]
