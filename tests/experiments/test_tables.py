"""Every table robocog prints reads at 80 columns with no cell cut to an ellipsis."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from rich.console import Console
from rich.table import Table

from robocog import cli
from robocog.experiments.tables import fit, plain

CUT = ("…", "...")


def _render(table: Table, width: int) -> str:
    out = io.StringIO()
    Console(file=out, width=width, force_terminal=False).print(fit(table, width))
    return out.getvalue()


def _table(cells: list[list[str]], headers: list[str]) -> Table:
    table = Table(title="t")
    for h in headers:
        table.add_column(h)
    for row in cells:
        table.add_row(*row)
    return table


def _words(table: Table) -> set[str]:
    return {w for c in table.columns for cell in [c.header, *c.cells] for w in plain(cell).split()}


def test_a_table_that_fits_is_left_as_it_is() -> None:
    table = _table([["bdi", "57%"], ["nars", "67%"]], ["mind", "success rate"])
    assert fit(table, 80) is table
    assert all(c.width is None for c in table.columns)


def test_a_wide_table_wraps_at_spaces_and_keeps_every_word_whole() -> None:
    long = "0.50, 0.48, 0.52, 0.51, 0.50, 0.53, 0.49, 0.47, 0.46"
    table = _table([["constant-step", "0.905", long, long]], ["scenario", "alpha", "a", "b"])
    words = _words(table)
    text = _render(table, 80)
    assert not any(c in text for c in CUT)
    assert max(len(line) for line in text.splitlines()) <= 80
    assert "─" in text and all(w in text for w in words)
    assert table.columns[0].width == len("constant-step")  # the cells first: no wrap there


def test_a_table_whose_words_cannot_sit_side_by_side_goes_vertical() -> None:
    headers = [f"column number {i}" for i in range(8)]
    row = [f"RecirculatingBallSleeve{i}" for i in range(8)]
    table = _table([row, row], headers)
    text = _render(table, 80)
    assert not any(c in text for c in CUT)
    assert all(w in text for w in _words(table))
    assert text.count("RecirculatingBallSleeve7") == 2  # one record per row
    assert max(len(line) for line in text.splitlines()) <= 80


@pytest.mark.parametrize(
    "argv",
    [
        ["demo", "--runs", "1", "--rounds", "1", "--out", "{tmp}/demo"],
        ["experiment", "room-exit", "--runs", "2", "--particles", "200", "--no-plots",
         "--report", "{tmp}/room"],
        ["experiment", "assembly", "--runs", "1", "--no-plots", "--report", "{tmp}/assembly"],
    ],
)  # fmt: skip
def test_the_commands_tables_read_at_80_columns(
    argv: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys
) -> None:  # noqa: ANN001
    monkeypatch.setenv("COLUMNS", "80")
    cli.main([a.replace("{tmp}", str(tmp_path)) for a in argv])
    text = capsys.readouterr().out
    assert "┃" in text or "│" in text  # a table was printed
    tables = [line for line in text.splitlines() if line[:1] in "┏┃│┡└┌├"]
    assert tables and max(len(line) for line in tables) <= 80
    assert not any(c in line for line in tables for c in CUT)


def test_a_wide_terminal_shows_the_assembly_table_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys
) -> None:  # noqa: ANN001
    monkeypatch.setenv("COLUMNS", "220")
    argv = ["experiment", "assembly", "--runs", "1", "--no-plots", "--report", str(tmp_path)]
    cli.main(argv)
    text = capsys.readouterr().out
    header = next(line for line in text.splitlines() if line.startswith("┃ table"))
    assert "thesis iters" in header and len(header) > 120  # one row across, not vertical


@pytest.mark.parametrize("width", [30, 40, 60])
def test_even_a_narrow_terminal_cuts_no_cell(width: int) -> None:
    headers = ["mind", "success rate", "missed: detection/grasp/decision/time"]
    table = _table([["NARS", "67%", "11/6/3/0"], ["BDI", "57%", "8/7/4/7"]], headers)
    text = _render(table, width)
    assert not any(c in text for c in CUT)
    assert max(len(line) for line in text.splitlines()) <= width
    assert "11/6/3/0" in text and "8/7/4/7" in text
