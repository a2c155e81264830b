"""Tables that read at any terminal width, with no cell cut short.

rich shrinks a table that is wider than the terminal by cutting cells to ``…`` once
wrapping at spaces is not enough, which on an 80-column terminal made the assembly
table unreadable. ``fit`` chooses instead, for the width at hand:

1. the table as it is, when its natural width fits (a wide terminal shows it whole);
2. else the same columns wrapped at spaces, each column at least as wide as its longest
   word, and as many as the room allows as wide as their longest line;
3. else, when even the longest words do not fit side by side, one record per row,
   vertically: the column names down the left, the values beside them.
"""

from __future__ import annotations

from typing import Any

from rich.table import Table
from rich.text import Text


def plain(cell: Any) -> str:
    """The text a cell shows (a str cell is rich markup)."""
    if isinstance(cell, Text):
        return cell.plain
    if isinstance(cell, str):
        return Text.from_markup(cell).plain
    return str(cell)


def _longest_word(text: str) -> int:
    return max((len(w) for w in text.split()), default=0)


def _longest_line(text: str) -> int:
    return max((len(line) for line in text.splitlines()), default=0)


def _overhead(table: Table) -> int:
    """Columns of a table's width that are not cell text: padding and rules."""
    n = len(table.columns)
    return 2 * n + n + 1  # one space each side of a cell, a rule between and at the edges


def fit(table: Table, width: int) -> Table:
    """``table`` made to read at ``width`` columns with no cell cut (see the module)."""
    columns = table.columns
    texts = [[plain(c.header)] + [plain(cell) for cell in c.cells] for c in columns]
    widest = [max(_longest_line(t) for t in col) for col in texts]
    narrowest = [max(_longest_word(t) for t in col) for col in texts]
    room = width - _overhead(table)
    if sum(widest) <= room:
        return table
    if sum(narrowest) <= room:
        # the cells first, then the headers: the columns that need least to show whole
        # get it first, so that as few wrap as the width allows
        cells = [
            max([n] + [_longest_line(t) for t in col[1:]])
            for n, col in zip(narrowest, texts, strict=True)
        ]
        spare = room - sum(narrowest)
        sizes = list(narrowest)
        for goal in (cells, widest):
            for i in sorted(range(len(columns)), key=lambda i: goal[i] - sizes[i]):
                extra = max(0, min(goal[i] - sizes[i], spare))
                sizes[i] += extra
                spare -= extra
        for column, size in zip(columns, sizes, strict=True):
            column.width = max(1, size)
            column.overflow = "fold"
            column.no_wrap = False
        return table
    return vertical(table)


def vertical(table: Table) -> Table:
    """One record per row of ``table``: its first cell as a heading line, then each other
    column's name and value; the records apart by rules."""
    columns = table.columns
    out = Table(title=table.title, show_header=False, box=table.box, show_lines=False)
    out.add_column(style="bold", overflow="fold")  # never cut, even on a very narrow terminal
    out.add_column(overflow="fold")
    cells = [list(c.cells) for c in columns]
    rows = len(cells[0]) if cells else 0
    for r in range(rows):
        out.add_row(plain(columns[0].header), cells[0][r])
        for i in range(1, len(columns)):
            last = i == len(columns) - 1
            out.add_row(plain(columns[i].header), cells[i][r], end_section=last)
    return out
