"""``robocog nar`` keeps the session: the save path is checked before the work, signals
save before ending, bad bytes and bad memory files are error lines, not tracebacks."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robocog.nars import NAR

REPO = Path(__file__).resolve().parents[2]


def _env(**extra: str) -> dict[str, str]:
    return dict(os.environ, PYTHONPATH=str(REPO / "src"), **extra)


def _nar(args: list[str], data: bytes, **env: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "robocog", "nar", "--quiet", *args],
        input=data,
        capture_output=True,
        timeout=120,
        env=_env(**env),
    )


def test_a_save_path_in_a_missing_folder_is_refused_before_any_work(tmp_path: Path) -> None:
    r = _nar(["--save", str(tmp_path / "no" / "dir" / "m.nar")], b"<a --> b>.\n")
    assert r.returncode == 2
    assert b"does not exist" in r.stderr and b"Traceback" not in r.stderr
    assert b"Input:" not in r.stdout  # nothing was processed


def test_a_save_path_that_is_a_folder_or_another_file_is_refused(tmp_path: Path) -> None:
    other = tmp_path / "notes.txt"
    other.write_text("precious")
    for path, why in [(tmp_path, b"is a directory"), (other, b"not a robocog memory")]:
        r = _nar(["--save", str(path)], b"<a --> b>.\n")
        assert r.returncode == 2 and why in r.stderr and b"Input:" not in r.stdout
    assert other.read_text() == "precious"


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_a_save_path_in_a_read_only_folder_is_refused(tmp_path: Path) -> None:
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        r = _nar(["--save", str(ro / "m.nar")], b"<a --> b>.\n")
        assert r.returncode == 2 and b"not writable" in r.stderr
    finally:
        ro.chmod(0o700)


def test_invalid_utf8_is_an_error_line_and_the_shell_goes_on(tmp_path: Path) -> None:
    data = b"<a --> b>.\n<a \xff--> c>.\n\xc3\n<b --> c>.\n<a --> c>?\n"
    for env in ({"LC_ALL": "C"}, {"LC_ALL": "C", "PYTHONCOERCECLOCALE": "0"}, {}):
        r = _nar([], data, **env)
        assert r.returncode == 0, r.stderr
        out = r.stdout.decode()
        assert "Error: line 2, column 4: invalid UTF-8 byte 0xff" in out
        assert "Error: line 3, column 1: invalid UTF-8 byte 0xc3" in out
        assert "Answer: <a --> c>." in out


def test_unicode_names_pass_through_a_strict_locale() -> None:
    r = _nar([], "<café --> bar>.\n<café --> bar>?\n".encode(), LC_ALL="C")
    assert r.returncode == 0 and "Answer: <café --> bar>.".encode() in r.stdout


@pytest.mark.parametrize(
    ("content", "why"),
    [
        (b"", b"empty file"),
        (b"<a --> b>.\n", b"not a robocog memory"),
        (b"\x80\x04\x95junk", b"pickle"),
        (b"\x1f\x8b\x08\x00\x00\x00\x00\x00", b"truncated"),
    ],
)
def test_unreadable_memories_are_refused_by_load(
    tmp_path: Path, content: bytes, why: bytes
) -> None:
    bad = tmp_path / "bad.nar"
    bad.write_bytes(content)
    r = _nar(["--load", str(bad)], b"")
    assert r.returncode == 2 and why in r.stderr and b"Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1


def test_a_truncated_save_is_refused(tmp_path: Path) -> None:
    nar = NAR()
    nar.add_input("<a --> b>.")
    nar.save(tmp_path / "m.nar")
    data = (tmp_path / "m.nar").read_bytes()
    (tmp_path / "cut.nar").write_bytes(data[:-20])
    r = _nar(["--load", str(tmp_path / "cut.nar")], b"")
    assert r.returncode == 2 and b"truncated" in r.stderr


def test_a_missing_memory_directory_is_refused(tmp_path: Path) -> None:
    r = _nar(["--memory-dir", str(tmp_path / "none")], b"")
    assert r.returncode == 2 and b"not a directory" in r.stderr


def test_save_and_load_lines_work_in_the_memory_directory(tmp_path: Path) -> None:
    r = _nar(["--memory-dir", str(tmp_path)], b"<a --> b>.\n<b --> c>.\n*save m.nar\n")
    assert r.returncode == 0 and b"Error" not in r.stdout
    r = _nar(["--memory-dir", str(tmp_path)], b"*load m.nar\n<a --> c>?\n")
    assert b"Answer: <a --> c>." in r.stdout
    assert (tmp_path / "m.nar").stat().st_mode & 0o777 == 0o600


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_saves_the_memory_then_ends(tmp_path: Path, sig: signal.Signals) -> None:
    save = tmp_path / "m.nar"
    proc = subprocess.Popen(
        [sys.executable, "-m", "robocog", "nar", "--quiet", "--save", str(save)],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env=_env(),
    )
    assert proc.stdin is not None and proc.stdout is not None
    proc.stdin.write(b"<a --> b>.\n<b --> c>.\n")
    proc.stdin.flush()
    # wait until both lines are in (the shell then blocks reading the next one)
    seen = b""
    deadline = time.monotonic() + 60
    while seen.count(b"Input:") < 2 and time.monotonic() < deadline:
        seen += proc.stdout.readline()
    assert seen.count(b"Input:") == 2
    proc.send_signal(sig)
    proc.wait(timeout=60)
    assert proc.returncode == 128 + sig
    assert save.exists() and not list(tmp_path.glob(".*.tmp"))
    again = NAR.load(save)
    assert again.ask("<a --> c>?") is not None


def _capacity(args: list[str]) -> int:
    r = _nar(args, b"*stats\n")
    assert r.returncode == 0, r.stderr
    line = next(x for x in r.stdout.decode().splitlines() if x.startswith("concept capacity"))
    return int(line.split()[-1])


def test_the_concept_capacity_follows_the_memory_budget() -> None:
    from robocog.nars.config import BYTES_PER_CONCEPT, ENGINE_BYTES

    assert _capacity([]) == ((256 << 20) - ENGINE_BYTES) // BYTES_PER_CONCEPT  # 256 MB
    assert _capacity(["--memory", "500MB"]) == ((500 << 20) - ENGINE_BYTES) // BYTES_PER_CONCEPT
    assert _capacity(["--memory", "ona"]) == 4096  # ONA 0.9.2's
    assert _capacity(["--memory", "2GB", "--set", "concepts_max=300"]) == 300
    # the default leaves room for the 10,000-link taxonomy (about 12,000 concepts)
    assert _capacity([]) >= 12_000


@pytest.mark.parametrize("size", ["10MB", "lots", "-5GB", "nanMB", "1e400GB"])
def test_a_memory_budget_that_is_no_size_or_too_small_is_refused(size: str) -> None:
    r = _nar(["--memory", size], b"")
    assert r.returncode == 2 and b"--memory" in r.stderr and b"Traceback" not in r.stderr


def test_a_session_run_in_process_leaves_the_collector_as_it_found_it(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The shell raises the cycle collector's threshold for its session only."""
    import argparse
    import gc
    import io

    from robocog.nars import shell

    parser = argparse.ArgumentParser()
    shell.configure(parser)
    args = parser.parse_args(["--quiet"])
    args.exit_when_done = False  # as a caller running it in its own process would
    before = gc.get_threshold()
    lines = io.TextIOWrapper(io.BytesIO(b"<a --> b>.\n<a --> b>?\n"))
    monkeypatch.setattr(sys, "stdin", lines)
    assert shell.run(args) == 0
    assert "Answer: <a --> b>." in capsys.readouterr().out
    assert gc.get_threshold() == before


def test_a_memory_larger_than_the_engine_holds_is_taken_and_said() -> None:
    r = _nar(["--memory", "99999TB"], b"5\n")
    assert r.returncode == 0 and b"done with 5 additional inference steps" in r.stdout
    assert b"holds at most 100,000,000 concepts" in r.stderr
    r = _nar(["--memory", "-1GB"], b"")
    assert r.returncode == 2 and b"argument --memory" in r.stderr and b"Traceback" not in r.stderr


def test_a_twenty_digit_number_of_cycles_is_too_many_not_a_misspelling() -> None:
    r = _nar([], b"12345678901234567890\n3\n")
    assert b"at most" in r.stdout and b"cycles per line" in r.stdout
    assert b"written in digits" not in r.stdout
    assert b"done with 3 additional inference steps" in r.stdout


#: a compound operation whose first operation reads where the object is from the input
_COMPOUND = [
    "*volume=0",
    "*motorbabbling=false",
    "*setopname 1 ^remember",
    "*setopstdin 1",
    "*setopname 3 ^goto",
    "<((tick &/ <({SELF} * ($1 * #1)) --> ^remember>) &/ <({SELF} * #1) --> ^goto>)"
    " =/> <$1 --> [see]>>.",
    "tick. :|:",
    "<fridge --> [see]>! :|:",
]


def test_an_operation_takes_its_result_from_the_input() -> None:
    # ONA's *setopstdin: after ^remember runs, the shell reads a line 0 and the result,
    # which binds #1 for ^goto (the lines ONA 0.9.3 prints for it when built with room
    # for two operations in a decision, MAX_COMPOUND_OP_LEN 2; it stops at 1)
    data = "\n".join([*_COMPOUND, "0", "(fridge * 10_20)", "<a --> b>?", ""]).encode()
    out = _nar(["--set", "max_compound_op_len=2"], data).stdout.decode().splitlines()
    i = out.index("^remember executed with args ({SELF} * (fridge * #1))")
    assert out[i + 1] == "//Operation result product expected: "
    assert out[i + 2].startswith(
        "Input: <({SELF} * (fridge * 10_20)) --> ^remember>. :|: occurrenceTime=3 "
    )
    assert out[i + 3] == "^goto executed with args ({SELF} * 10_20)"
    assert out[i + 4].startswith("Input: <({SELF} * 10_20) --> ^goto>. :|: occurrenceTime=4 ")
    # the two lines were the operation's, not Narsese: the next line is input again
    assert "Input: <a --> b>?" in out
    assert not any(line.startswith("Error:") for line in out)


def test_an_operation_whose_result_is_missing_ends_the_compound_operation() -> None:
    for rest in (["1", "(fridge * 10_20)"], ["0", "(fridge * 10_20"], []):
        data = "\n".join([*_COMPOUND, *rest, ""]).encode()
        out = _nar(["--set", "max_compound_op_len=2"], data).stdout.decode().splitlines()
        assert "//Operation result product expected: " in out
        assert not any(line.startswith("^goto executed") for line in out)
