from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.planning.sexpr import SexprError, SList, String, Symbol, parse, render

symbols = st.from_regex(r"[A-Za-z?:\-][A-Za-z0-9?\-_]{0,6}", fullmatch=True).map(Symbol)
strings = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=8).map(String)
exprs = st.recursive(
    symbols | strings,
    lambda kids: st.lists(kids, max_size=4).map(lambda x: SList(tuple(x))),
    max_leaves=12,
)


@given(exprs)
def test_render_then_parse_gives_the_same_expression(expr) -> None:
    assert parse(render(expr)) == [expr]


def test_positions_are_recorded() -> None:
    (top,) = parse('(a\n  (b "c"))')
    inner = top.items[1]
    assert (inner.line, inner.column) == (2, 3)
    assert inner.items[1] == String("c")


@pytest.mark.parametrize(
    ("text", "where", "what"),
    [
        ("(a (b)", (1, 1), "never closed"),
        ("(a))", (1, 4), "unexpected ')'"),
        ('(a "b', (1, 4), "unterminated"),
    ],
)
def test_errors_name_line_and_column(text: str, where: tuple[int, int], what: str) -> None:
    with pytest.raises(SexprError) as info:
        parse(text)
    assert (info.value.line, info.value.column) == where
    assert what in str(info.value)
