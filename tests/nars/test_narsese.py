"""Reading and printing Narsese: ONA's canonical form, interning, errors with position."""

from __future__ import annotations

import glob
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.nars.narsese import NarseseError, parse_sentence, parse_term
from robocog.nars.terms import atom, compound
from robocog.nars.truth import Truth

EXAMPLES = Path(__file__).resolve().parents[3] / "shared" / "nal" / "ona-examples"


def _narsese_lines() -> list[str]:
    out = []
    for f in sorted(glob.glob(str(EXAMPLES / "*.nal"))):
        for line in Path(f).read_text().splitlines():
            s = line.strip()
            if s and not s.startswith(("//", "*")) and not s.isdigit() and s != "quit":
                out.append(s)
    return out


@pytest.mark.skipif(not EXAMPLES.exists(), reason="ONA examples not present")
def test_every_example_line_parses_and_round_trips() -> None:
    lines = _narsese_lines()
    assert len(lines) > 100
    for line in lines:
        s = parse_sentence(line)
        assert parse_term(str(s.term)) is s.term, line


@pytest.mark.parametrize(
    ("text", "printed"),
    [
        ("<a-->b>", "<a --> b>"),
        ("<(a * b) --> r>", "<(a * b) --> r>"),
        ("<(&&, <a --> b>, <c --> d>) ==> e>", "<(<a --> b> && <c --> d>) ==> e>"),
        ("(a &/ b &/ c)", "((a &/ b) &/ c)"),
        ("<{a b} --> [c d]>", "<{a b} --> [c d]>"),
        ("(! <a --> b>)", "(! <a --> b>)"),
        ("<a --> (r /1 b)>", "<a --> (r /1 b)>"),
        ("<(r \\2 a) --> b>", "<(r \\2 a) --> b>"),
        ("<<$x --> a> ==> <$x --> b>>", "<<$1 --> a> ==> <$1 --> b>>"),
        ("<(#y * ?z) --> r>", "<(#1 * ?1) --> r>"),
        ("<({SELF} * x) --> ^go>", "<({SELF} * x) --> ^go>"),
        ("<B_0.1 --> c>", "<B_0.1 --> c>"),
        ("((a || b) && c)", "((a || b) && c)"),
        ("<a |-> b>", "<a |-> b>"),
    ],
)
def test_canonical_printing(text: str, printed: str) -> None:
    assert str(parse_term(text)) == printed


def test_variables_numbered_in_breadth_first_order() -> None:
    # ONA numbers by array position: the shallower $c comes before the deeper $a
    t = parse_term("<(<$a --> x> && <$b --> y>) ==> <$c --> z>>")
    assert str(t) == "<(<$2 --> x> && <$3 --> y>) ==> <$1 --> z>>"


def test_interning_makes_equal_terms_identical() -> None:
    a = parse_term("<(a * b) --> r>")
    b = compound("-->", (compound("*", (atom("a"), atom("b"))), atom("r")))
    assert a is b
    assert hash(a) == hash(b)


def test_sentence_parts() -> None:
    s = parse_sentence("<a --> b>. :|: {0.25 0.5}")
    assert (s.punctuation, s.tense, tuple(s.truth)) == (".", ":|:", (0.25, 0.5))
    s = parse_sentence("<a --> b>. %0.7%")
    assert s.truth == Truth(0.7, 0.9)
    s = parse_sentence("dt=3 <a =/> b>.")
    assert s.dt == 3.0


@pytest.mark.parametrize(
    ("text", "column"),
    [("<a --> b", 9), ("<a --> b>. {2 0.9}", 12), ("<a -> b>.", 5), ("(a & b | c).", 8)],
)
def test_errors_name_the_column(text: str, column: int) -> None:
    with pytest.raises(NarseseError) as info:
        parse_sentence(text)
    assert info.value.line == 1
    assert info.value.column == column


NAMES = st.sampled_from(["a", "b", "cat", "x1", "SELF", "$1", "#1", "?1", "^op", "0.5"])


def _terms() -> st.SearchStrategy:
    def extend(children: st.SearchStrategy) -> st.SearchStrategy:
        cop = st.sampled_from(["-->", "<->", "==>", "<=>", "=/>"])
        inf = st.sampled_from(["*", "&", "|", "-", "~", "&&", "||", "&/", "/1", "\\2"])
        return st.one_of(
            st.builds(lambda s, c, p: compound(c, (s, p)), children, cop, children),
            st.builds(lambda s, c, p: compound(c, (s, p)), children, inf, children),
            st.builds(lambda a: compound("!", (a,)), children),
            st.builds(lambda a: compound("*", (a,)), children),
            st.builds(
                lambda xs, k: compound(k, tuple(dict.fromkeys(xs))),
                st.lists(children, min_size=1, max_size=3),
                st.sampled_from(["{}", "[]"]),
            ),
        )

    return st.recursive(NAMES.map(atom), extend, max_leaves=12)


@settings(max_examples=300, deadline=None)
@given(_terms())
def test_print_then_parse_is_identity(t) -> None:  # noqa: ANN001 - hypothesis value
    from robocog.nars.terms import normalize_variables

    t = normalize_variables(t)
    assert parse_term(str(t)) is t


def test_hostile_lines_are_errors_not_crashes() -> None:
    for text in ["<" * 3000 + "a", "(" * 300 + "a" + ")" * 300 + ".", "x" * 5000 + ".", "\x00."]:
        with pytest.raises(NarseseError):
            parse_sentence(text)


@settings(max_examples=300, deadline=None)
@given(
    st.sampled_from(["a", "B7", "n_12", "0", "SELF", "dt", "x1y"]),
    st.sampled_from(["-->", "<->"]),
    st.sampled_from(["b", "n3", "_", "42", "see", "at"]),
    st.sampled_from(".!?"),
    st.sampled_from(["", " :|:"]),
)
def test_plain_statements_read_as_the_grammar_reads_them(
    s: str, cop: str, p: str, punct: str, tense: str
) -> None:
    """``<a --> b>.`` lines skip the parser; they must come out as the grammar makes them."""
    from robocog.nars import narsese

    line = f"<{s} {cop} {p}>{punct}{tense}"
    assert narsese._SIMPLE.fullmatch(line) is not None
    fast = narsese._parse_sentence.__wrapped__(line)
    slow = narsese._BUILD.transform(narsese._SENTENCE.parse(line))
    assert fast == slow
    assert fast.term is slow.term
    assert str(fast) == str(slow) == line


@pytest.mark.parametrize(
    "line",
    [
        "<a --> b>",
        "<a -->b>.",
        "<$1 --> b>.",
        "<a.b --> c>.",
        "<a --> b>. %1.0;0.9%",
        "<a --> b>.  :|:",
    ],
)
def test_lines_near_the_plain_shape_go_to_the_parser(line: str) -> None:
    from robocog.nars import narsese

    assert narsese._SIMPLE.fullmatch(line) is None
