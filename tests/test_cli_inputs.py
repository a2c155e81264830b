"""Every option of every ``robocog`` command refuses a bad value with one line.

The commands are found from the parser itself (every subcommand, nested ones too), so a
command or option added later is walked as well. For each option that takes a number or
a path the test gives values outside what its type accepts (negative, zero, NaN,
infinity, huge, not a number, a missing folder) and expects: a non-zero exit, one line
on stderr naming the option, and no traceback. The values are refused while the command
line is read, so no command starts any work; the walk runs in this process.
"""

from __future__ import annotations

import argparse
import contextlib
import io
from collections.abc import Iterator
from pathlib import Path

import pytest

from robocog import argtypes, cli

#: values tried on every number option: each is tried only where its type's range
#: excludes it (a seed of 0 is fine, a count of 0 is not)
NUMBERS = ("-1", "0", "-0.5", "0.5", "1.5", "nan", "inf", "-inf", "1e400", "1" + "0" * 20)
WRONG = ("abc", "", "1,5", "0x10", "1e3x")


def _commands() -> Iterator[tuple[tuple[str, ...], argparse.ArgumentParser]]:
    """(path of names, parser) of every command and subcommand."""

    def walk(path: tuple[str, ...], parser: argparse.ArgumentParser):  # noqa: ANN202
        yield path, parser
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    yield from walk((*path, name), sub)

    for name in cli.COMMANDS:
        top = cli.build_parser([name])
        for path, parser in walk((), top):
            if path and path[0] == name:
                yield path, parser


def _options() -> list[tuple[tuple[str, ...], argparse.Action]]:
    found = []
    for path, parser in _commands():
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction | argparse._HelpAction):
                continue
            if action.nargs == 0 or action.help == argparse.SUPPRESS:
                continue  # a flag, or a hidden catch-all
            found.append((path, action))
    return found


OPTIONS = _options()


def _id(item: tuple[tuple[str, ...], argparse.Action]) -> str:
    path, action = item
    return (
        " ".join(path) + " " + (action.option_strings[0] if action.option_strings else action.dest)
    )


def _in_range(kind: argparse.Action, text: str) -> bool:
    try:
        kind.type(text)  # type: ignore[misc]
    except argparse.ArgumentTypeError:
        return False
    return True


def _bad_values(action: argparse.Action, tmp: Path) -> list[str]:
    kind = action.type
    if isinstance(kind, argtypes.IntRange | argtypes.FloatRange):
        extra = [str(kind.lo - 1), str(kind.hi + 1)] if isinstance(kind, argtypes.IntRange) else []
        if isinstance(kind, argtypes.FloatRange):
            extra = [repr(kind.hi * 2 + 1), repr(kind.lo - 1)]
        return [v for v in (*NUMBERS, *WRONG, *extra) if not _in_range(action, v)]
    if isinstance(kind, argtypes.PathType):
        if tmp.is_dir():
            (tmp / "a-file").write_text("x")
        bad = [str(tmp / "a-file" / "x"), ""]
        if kind.kind != "new-dir":  # a folder to write is made with its parents
            bad.append(str(tmp / "missing-folder" / "x"))
        if kind.kind in ("file", "dir"):
            bad.append(str(tmp / "missing"))
        if kind.kind in ("file", "new-dir"):
            bad.append(str(tmp / "a-file") if kind.kind == "new-dir" else str(tmp))
        return bad
    return list(getattr(kind, "bad_values", ()))


def _argv(path: tuple[str, ...], parser: argparse.ArgumentParser, action: argparse.Action,
          value: str) -> list[str]:  # fmt: skip
    """A command line with ``value`` for ``action`` (positionals before it filled in with
    their first choice, so that argparse reaches the option)."""
    argv = list(path)
    for other in parser._actions:
        if other is action or other.option_strings or other.nargs == 0:
            continue
        if isinstance(other, argparse._SubParsersAction):
            continue
        if other.choices:
            argv.append(next(iter(other.choices)))
    if action.option_strings:
        # the --opt=value form, so that a value starting with '-' stays a value
        flag = next(o for o in action.option_strings if o.startswith("--"))
        n = action.nargs if isinstance(action.nargs, int) else 1
        if n == 1:
            return [*argv, f"{flag}={value}"]
        return [*argv, flag, *([value] * n)]
    if action.choices:
        return [*argv, value]
    return [*argv, "--", value] if value.startswith("-") else [*argv, value]


def _parser_of(path: tuple[str, ...]) -> argparse.ArgumentParser:
    return dict(_commands())[path]


def _run(argv: list[str]) -> tuple[int, str, str]:
    """Read ``argv`` as ``robocog`` does, without running the command it names: (exit
    status, stdout, stderr); 0 when the line was accepted."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            cli.build_parser(argv).parse_args(argv)
            code = 0
        except SystemExit as stop:
            code = stop.code if isinstance(stop.code, int) else 1
    return int(code or 0), out.getvalue(), err.getvalue()


def test_the_walk_finds_the_commands_and_their_options() -> None:
    paths = {path for path, _ in _commands()}
    assert set(cli.COMMANDS) <= {p[0] for p in paths}
    assert ("experiment", "garbage") in paths and ("experiment", "assembly") in paths
    checked = [o for o in OPTIONS if _bad_values(o[1], Path("/nonexistent"))]
    assert len(checked) > 60


@pytest.mark.parametrize("item", OPTIONS, ids=_id)
def test_no_option_takes_a_number_or_path_unchecked(
    item: tuple[tuple[str, ...], argparse.Action],
) -> None:
    """An option with a number default, a number or path type, or a FILE/DIR/PATH name
    has one of the checked types (or lists the values it refuses)."""
    _, action = item
    kind = action.type
    checked = isinstance(kind, argtypes.IntRange | argtypes.FloatRange | argtypes.PathType)
    checked = checked or bool(getattr(kind, "bad_values", ()))
    names = " ".join([*action.option_strings, action.dest, str(action.metavar or "")]).upper()
    numeric_default = isinstance(action.default, int | float) and not isinstance(
        action.default, bool
    )
    wants_check = (
        kind in (int, float, Path)
        or numeric_default
        or isinstance(action.default, Path)
        or any(w in names for w in ("FILE", "DIR", "PATH", "FOLDER"))
    )
    if wants_check and not action.choices:
        assert checked, f"{_id(item)} takes {kind} with no range or path check"


@pytest.mark.parametrize(
    "item", [o for o in OPTIONS if _bad_values(o[1], Path("/nonexistent"))], ids=_id
)
def test_every_bad_value_is_one_line_and_a_failure(
    item: tuple[tuple[str, ...], argparse.Action], tmp_path: Path
) -> None:
    path, action = item
    parser = _parser_of(path)
    name = action.option_strings[0] if action.option_strings else (action.metavar or action.dest)
    for value in _bad_values(action, tmp_path):
        argv = _argv(path, parser, action, value)
        code, _out, err = _run(argv)
        lines = err.strip().splitlines()
        assert code != 0, f"{argv} was accepted"
        assert "Traceback" not in err, argv
        assert len(lines) == 1, f"{argv}: {err}"
        assert f"argument {name}" in lines[0], f"{argv}: {lines[0]}"


def test_the_messages_name_the_range() -> None:
    code, _, err = _run(["agent", "--max-cycles=0", "x.asl"])
    assert code == 2
    assert "--max-cycles: expected a whole number from 1 to" in err
    code, _, err = _run(["plan", "--max-seconds=nan"])
    assert code == 2 and "--max-seconds: expected a number above 0" in err and "'nan'" in err
    code, _, err = _run(["plan", "--thesis=9.9"])
    assert code == 2 and "'5.2'" in err and "BlockC" in err


def test_a_missing_folder_of_a_file_to_write_is_named(tmp_path: Path) -> None:
    source = tmp_path / "a.scm"
    source.write_text('(Concept "a")\n')
    code, _, err = _run(["atomese", str(source), "--save", str(tmp_path / "missing" / "x.db")])
    assert code == 2
    assert "Traceback" not in err
    assert f"{tmp_path / 'missing'} does not exist" in err


def test_the_installed_command_prints_one_line_and_exits_2() -> None:
    """The same through the ``robocog`` program a user runs (a process of its own)."""
    import subprocess
    import sys

    src = str(Path(cli.__file__).resolve().parents[1])
    for argv in (["demo", "--runs", "-1"], ["nar", "--memory", "-5GB"]):
        done = subprocess.run(
            [
                sys.executable,
                "-c",
                "import sys; from robocog.cli import main; sys.exit(main())",
                *argv,
            ],
            capture_output=True,
            text=True,
            timeout=60,
            env={"PYTHONPATH": src, "PATH": "/usr/bin:/bin"},
        )
        assert done.returncode == 2, done.stderr
        assert done.stdout == "" and len(done.stderr.strip().splitlines()) == 1, done.stderr
        assert f"argument {argv[1]}" in done.stderr and "Traceback" not in done.stderr
