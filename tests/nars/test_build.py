"""``robocog build``: when a build is current, what it needs, what it refuses."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from robocog import cli
from robocog.nars import build


def _sources(tmp_path: Path) -> Path:
    for m in build.ENGINE_MODULES:
        (tmp_path / f"{m}.py").write_text(f"NAME = {m!r}\n")
    (tmp_path / "terms.pxd").write_text("cdef class Term:\n    pass\n")
    return tmp_path


def _built(here: Path) -> Path:
    folder = here / build.COMPILED
    folder.mkdir()
    for m in build.ENGINE_MODULES:
        (folder / f"{m}.{sys.implementation.cache_tag}-x.so").write_bytes(b"")
    manifest = {"cache_tag": sys.implementation.cache_tag, "sources": build.digests(here)}
    (folder / "manifest.json").write_text(json.dumps(manifest))
    return folder


def test_a_build_is_current_only_for_these_sources_this_python_and_every_module(
    tmp_path: Path,
) -> None:
    here = _sources(tmp_path)
    assert not build.is_current(here)  # nothing built
    folder = _built(here)
    assert build.is_current(here)
    (here / "terms.pxd").write_text("cdef class Term:\n    cdef int x\n")  # a declaration
    assert not build.is_current(here)
    (folder / "manifest.json").write_text(
        json.dumps({"cache_tag": sys.implementation.cache_tag, "sources": build.digests(here)})
    )
    assert build.is_current(here)
    next(folder.glob("nar.*")).unlink()
    assert not build.is_current(here)


def test_digests_cover_modules_and_declarations(tmp_path: Path) -> None:
    here = _sources(tmp_path)
    found = build.digests(here)
    assert set(found) == {f"{m}.py" for m in build.ENGINE_MODULES} | {"terms.pxd"}


def test_the_estimate_falls_with_cores_but_not_below_the_longest_module() -> None:
    one, two = build.estimate(1), build.estimate(2)
    assert one == build.CPU_SECONDS and two < one
    assert build.estimate(64) == build.LONGEST_SECONDS


def test_the_engine_modules_all_exist() -> None:
    here = build.package_dir()
    assert all((here / f"{m}.py").exists() for m in build.ENGINE_MODULES)


def test_a_missing_cython_is_named(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "Cython", None)
    why = build.missing_tools()
    assert why is not None and "Cython" in why


@pytest.mark.parametrize("jobs", ["0", "-3", "65"])
def test_bad_jobs_are_refused_before_anything_runs(jobs: str, capsys) -> None:  # noqa: ANN001
    with pytest.raises(SystemExit) as stop:
        cli.main(["build", "--jobs", jobs])
    assert stop.value.code == 2
    err = capsys.readouterr().err.strip()
    assert "--jobs" in err and "1 to 64" in err and len(err.splitlines()) == 1


def test_a_current_build_is_not_built_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys
) -> None:  # noqa: ANN001
    here = _sources(tmp_path)
    _built(here)
    monkeypatch.setattr(build, "package_dir", lambda: here)
    assert cli.main(["build"]) == 0
    assert "is current" in capsys.readouterr().out


def test_a_folder_it_cannot_write_is_named_before_any_compiling(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys
) -> None:  # noqa: ANN001
    here = _sources(tmp_path)
    monkeypatch.setattr(build, "package_dir", lambda: here)
    monkeypatch.setattr(build, "missing_tools", lambda: None)
    monkeypatch.setattr(build.os, "access", lambda path, mode: False)
    monkeypatch.setattr(build, "build", lambda *a, **k: pytest.fail("compiled anyway"))
    assert cli.main(["build"]) == 1
    out = capsys.readouterr().out
    assert "is not writable" in out and str(here) in out and len(out.splitlines()) == 1


@pytest.mark.slow
@pytest.mark.skipif(build.missing_tools() is not None, reason=f"{build.missing_tools()}")
def test_a_build_compiles_into_place_and_replaces_the_old_one(tmp_path: Path) -> None:
    """The whole path on two small modules of a package laid out as robocog's: Cython,
    the C compiler, the folder swapped in, the manifest; the modules then import."""
    import subprocess

    here = tmp_path / "robocog" / "nars"
    here.mkdir(parents=True)
    (here / "first.py").write_text("def double(x: int) -> int:\n    return 2 * x\n")
    (here / "second.py").write_text("from robocog.nars.first import double\nFOUR = double(2)\n")
    old = here / build.COMPILED
    old.mkdir()
    (old / "stale.txt").write_text("an older build")
    events: list[tuple[str, str]] = []
    folder = build.build(here, 2, lambda e, m: events.append((e, m)), ("first", "second"))
    assert folder == old and not (folder / "stale.txt").exists()
    assert sorted(events) == sorted(
        [("starts", "first"), ("done", "first"), ("starts", "second"), ("done", "second")]
    )
    manifest = json.loads((folder / "manifest.json").read_text())
    assert manifest["sources"] == build.digests(here, ("first", "second"))
    built = sorted(p.name.split(".")[0] for p in folder.iterdir() if p.suffix in (".so", ".pyd"))
    assert built == ["first", "second"]
    assert [p.name for p in here.iterdir() if p.name.startswith(build.COMPILED)] == [build.COMPILED]
    so = next(folder.glob("first.*"))
    code = (
        "import importlib.util\n"
        f"spec = importlib.util.spec_from_file_location('first', {str(so)!r})\n"
        "m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n"
        "print(m.double(21), m.__file__.endswith(('.so', '.pyd')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.split() == ["42", "True"], out.stderr
