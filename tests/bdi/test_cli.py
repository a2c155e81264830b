"""``robocog agent FILE.asl``."""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest

from robocog.bdi import cli


def _run(path: Path, capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    parser = argparse.ArgumentParser()
    cli.configure(parser)
    code = cli.run(parser.parse_args([str(path)]))
    got = capsys.readouterr()
    return code, got.out, got.err


def test_prints_as_jason_with_the_file_stem_as_name(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    f = tmp_path / "hello.asl"
    f.write_text('!start.\n+!start <- .print("Hello, ", world, "!"); .print(g("s", 1.0)).\n')
    code, out, err = _run(f, capsys)
    assert code == 0
    assert out.splitlines() == ["[hello] Hello, world!", '[hello] g("s",1)']


def test_parse_errors_go_to_stderr_with_line_and_column(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    f = tmp_path / "bad.asl"
    f.write_text("!start.\n+!start <- .print(.\n")
    code, out, err = _run(f, capsys)
    assert code == 1 and out == ""
    assert "bad.asl:2:19:" in err


def test_warnings_stay_off_stdout(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    f = tmp_path / "w.asl"
    f.write_text("!start.\n+!start <- .print(a); !missing; .print(b).\n")
    code, out, err = _run(f, capsys)
    assert out.splitlines() == ["[w] a"]
    assert "missing" in err


# Jason's conformance cases live beside the repository (../shared/asl/conformance)
CONFORMANCE = Path(__file__).resolve().parents[3] / "shared" / "asl" / "conformance"


@pytest.mark.skipif(not CONFORMANCE.exists(), reason="conformance cases not available")
@pytest.mark.parametrize(
    "case", sorted(p.name for p in CONFORMANCE.glob("*.asl")) if CONFORMANCE.exists() else []
)
def test_conformance_cases(case: str, capsys) -> None:  # noqa: ANN001
    path = CONFORMANCE / case
    expected = [
        line.strip()[len("// expect:") :].removeprefix(" ").rstrip()
        for line in path.read_text().splitlines()
        if line.strip().startswith("// expect:")
    ]
    _code, out, _err = _run(path, capsys)
    prefix = f"[{path.stem}] "
    got = [line.removeprefix(prefix).rstrip() for line in out.splitlines() if line.startswith("[")]
    assert got == expected


@pytest.mark.parametrize("two_agents", [False, True])
def test_max_cycles_cuts_a_program_that_never_ends_with_exit_3(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], two_agents: bool
) -> None:
    loop = tmp_path / "loop.asl"
    loop.write_text("!loop.\n+!loop <- !loop.\n")
    done = tmp_path / "done.asl"
    done.write_text("!g.\n+!g <- .print(hi).\n")
    files = [str(done), str(loop)] if two_agents else [str(loop)]
    parser = argparse.ArgumentParser()
    cli.configure(parser)
    assert cli.run(parser.parse_args([*files, "--max-cycles", "200"])) == 3
    assert "stopped after 200 cycles (--max-cycles)" in capsys.readouterr().err
    # a program that ends within the bound ends as usual
    assert cli.run(parser.parse_args([str(done), "--max-cycles", "200"])) == 0
    assert capsys.readouterr().err == ""
