"""The choice between the compiled and the pure-Python engine, and their agreement."""

from __future__ import annotations

import hashlib
import json
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest

import robocog.nars as nars
from robocog.nars import _choose_engine


def _package(tmp_path: Path, tag: str = sys.implementation.cache_tag) -> Path:
    """A package folder with two sources and a build manifest matching them."""
    (tmp_path / "terms.py").write_text("X = 1\n")
    (tmp_path / "nar.py").write_text("Y = 2\n")
    folder = tmp_path / "_compiled"
    folder.mkdir()
    sources = {
        name: hashlib.sha256((tmp_path / name).read_bytes()).hexdigest()
        for name in ("terms.py", "nar.py")
    }
    (folder / "manifest.json").write_text(json.dumps({"cache_tag": tag, "sources": sources}))
    return folder


def test_a_build_of_the_present_sources_is_used(tmp_path: Path, monkeypatch) -> None:  # noqa: ANN001
    monkeypatch.delenv("ROBOCOG_PURE_PYTHON", raising=False)
    folder = _package(tmp_path)
    assert _choose_engine(tmp_path) == ("compiled", folder)


def test_an_edited_source_falls_back_to_python(tmp_path: Path, monkeypatch) -> None:  # noqa: ANN001
    monkeypatch.delenv("ROBOCOG_PURE_PYTHON", raising=False)
    _package(tmp_path)
    (tmp_path / "nar.py").write_text("Y = 3\n")
    engine, folder = _choose_engine(tmp_path)
    assert folder is None and engine.startswith("python") and "nar.py changed" in engine


def test_other_interpreter_missing_or_broken_manifest_fall_back(
    tmp_path: Path, monkeypatch
) -> None:  # noqa: ANN001
    monkeypatch.delenv("ROBOCOG_PURE_PYTHON", raising=False)
    assert _choose_engine(tmp_path)[1] is None  # nothing built
    folder = _package(tmp_path, tag="cpython-0")
    engine, chosen = _choose_engine(tmp_path)
    assert chosen is None and "cpython-0" in engine
    (folder / "manifest.json").write_text("{not json")
    assert _choose_engine(tmp_path)[1] is None


def test_the_environment_can_ask_for_python(tmp_path: Path, monkeypatch) -> None:  # noqa: ANN001
    _package(tmp_path)
    monkeypatch.setenv("ROBOCOG_PURE_PYTHON", "1")
    engine, folder = _choose_engine(tmp_path)
    assert folder is None and "ROBOCOG_PURE_PYTHON" in engine


def _workload() -> str:
    """Declarative and sensorimotor input at full volume: every derivation is printed.

    A chain of 29 names and six questions: each question asked before its answer is
    derived chains backward over every pair of beliefs about its two names, and the
    shell's declarative pass (ONA 0.9.3's) derives from every belief, so twice the
    chain and four more questions of the same kind cost the two engines more than a
    minute between them.
    """
    rng = random.Random(7)
    lines = []
    for i in range(1, 30):
        lines.append(f"<n{i} --> n{rng.randrange(max(0, i - 8), i)}>.")
    lines += [f"<n{rng.randrange(15, 30)} --> n{rng.randrange(0, 10)}>?" for _ in range(6)]
    for _ in range(12):
        lines += ["<a --> [on]>. :|:", "^left. :|:", "<b --> [on]>. :|:", "5"]
    lines += ["<b --> [on]>! :|:", "10", "<(<a --> [on]> &/ ^left) =/> <b --> [on]>>?"]
    return "\n".join(lines) + "\n"


#: ``python -m robocog`` as if Cython were not installed
WITHOUT_CYTHON = (
    "import runpy, sys; sys.modules['cython'] = None; sys.argv[0] = 'robocog';"
    " runpy.run_module('robocog', run_name='__main__')"
)


def _shell(
    text: str, pure: bool, memory_dir: Path | None = None, without_cython: bool = False
) -> str:
    """What ``robocog nar`` prints for ``text`` with the compiled or the pure engine
    (``without_cython``: the pure one with Cython's import refused)."""
    env = dict(os.environ)
    env.pop("ROBOCOG_PURE_PYTHON", None)
    if pure:
        env["ROBOCOG_PURE_PYTHON"] = "1"
    run = subprocess.run(
        [sys.executable, *(["-c", WITHOUT_CYTHON] if without_cython else ["-m", "robocog"])]
        + ["nar"]
        + ([] if memory_dir is None else ["--memory-dir", str(memory_dir)]),
        input=text,
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    return run.stdout


@pytest.mark.slow
@pytest.mark.skipif(nars.ENGINE != "compiled", reason=f"engine in use: {nars.ENGINE}")
def test_compiled_and_python_engines_print_the_same() -> None:
    text = _workload()
    outs = [_shell(text, pure) for pure in (False, True)]
    assert outs[0].count("Derived:") > 500 and "Answer:" in outs[0]
    assert outs[0] == outs[1]


@pytest.mark.slow
def test_the_python_engine_runs_without_cython_and_prints_the_same() -> None:
    """Without Cython installed the engine's class decorators come from
    ``robocog.nars.cy`` (no-ops): the same output as with Cython's own module."""
    text = _workload()
    without = _shell(text, pure=True, without_cython=True)
    assert "Answer:" in without
    assert without == _shell(text, pure=True)


@pytest.mark.slow
@pytest.mark.skipif(nars.ENGINE != "compiled", reason=f"engine in use: {nars.ENGINE}")
def test_each_engine_continues_from_the_others_save(tmp_path: Path) -> None:
    lines = _workload().splitlines()
    first, rest = "\n".join(lines[:-16]), "\n".join(lines[-16:]) + "\n"
    continued = []
    for saver_is_pure in (False, True):
        name = f"saved-{saver_is_pure}.nar"
        _shell(f"{first}\n*save {name}\n", saver_is_pure, tmp_path)
        continued.append(_shell(f"*load {name}\n{rest}", not saver_is_pure, tmp_path))
    # read by either engine, the saved state goes on exactly as the run that never stopped
    whole = _shell(_workload(), False)
    for out in continued:
        assert "Answer:" in out and out.count("Derived:") > 100
        assert whole.endswith(out)
