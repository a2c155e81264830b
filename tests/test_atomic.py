"""Atomic writes leave either the old file or the new one."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from robocog import atomic


def test_writes_replace_the_whole_file(tmp_path: Path) -> None:
    target = tmp_path / "deep" / "result.json"
    atomic.write_json(target, {"a": 1})
    assert json.loads(target.read_text()) == {"a": 1}
    atomic.write_text(target, "second")
    assert target.read_text() == "second"
    assert sorted(p.name for p in target.parent.iterdir()) == ["result.json"]


def test_a_failed_write_keeps_the_old_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "state.bin"
    atomic.write_bytes(target, b"old")

    def broken_replace(src: str, dst: str) -> None:
        raise OSError("disk gone")

    monkeypatch.setattr(os, "replace", broken_replace)
    with pytest.raises(OSError):
        atomic.write_bytes(target, b"new")
    assert target.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["state.bin"]


@pytest.mark.parametrize("mask", [0o022, 0o077, 0o002])
def test_a_new_file_gets_the_mode_the_umask_allows(tmp_path: Path, mask: int) -> None:
    before = os.umask(mask)
    try:
        atomic.write_text(tmp_path / "report.md", "# report\n")
        with open(tmp_path / "plot.png", "wb") as f:  # what a plotting library does
            f.write(b"png")
    finally:
        os.umask(before)
    mode = (tmp_path / "report.md").stat().st_mode & 0o777
    assert mode == 0o666 & ~mask
    assert mode == (tmp_path / "plot.png").stat().st_mode & 0o777


def test_a_replaced_file_keeps_its_own_mode(tmp_path: Path) -> None:
    target = tmp_path / "results.json"
    atomic.write_json(target, [1])
    target.chmod(0o640)
    atomic.write_json(target, [2])
    assert target.stat().st_mode & 0o777 == 0o640
    assert json.loads(target.read_text()) == [2]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.json"]


def test_a_private_file_is_the_owners_alone_whatever_the_umask(tmp_path: Path) -> None:
    before = os.umask(0o002)
    try:
        atomic.write_bytes(tmp_path / "memory.nar", b"x", mode=0o600)
    finally:
        os.umask(before)
    assert (tmp_path / "memory.nar").stat().st_mode & 0o777 == 0o600
