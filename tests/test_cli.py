"""The ``robocog`` command's dispatch."""

from __future__ import annotations

import pytest

from robocog import cli


def test_help_lists_every_command(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exc:
        cli.main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    for name in cli.COMMANDS:
        assert name in out


def test_no_command_prints_help_and_fails(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main([]) == 2
    assert "usage: robocog" in capsys.readouterr().out


def test_an_unexpected_error_is_one_line_not_a_traceback(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    import types

    def run(_args: object) -> int:
        raise RuntimeError("the disk\nis gone")

    fake = types.SimpleNamespace(configure=lambda p: None, run=run)
    monkeypatch.setattr(cli, "_load", lambda name: fake)
    monkeypatch.delenv("ROBOCOG_TRACEBACK", raising=False)
    assert cli.main(["plan"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith("robocog plan: error: RuntimeError: the disk is gone")
    monkeypatch.setenv("ROBOCOG_TRACEBACK", "1")
    with pytest.raises(RuntimeError):
        cli.main(["plan"])
