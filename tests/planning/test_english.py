from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.planning.english import EnglishError, Statement, read_sentence, read_sentences

KEYWORDS = {"the", "is", "a", "an", "on", "in", "hand", "fixed", "object", "clear", "top", "of"}
names = st.from_regex(r"[A-Z][A-Za-z0-9]{0,8}", fullmatch=True).filter(
    lambda s: s.lower() not in KEYWORDS
)


@pytest.mark.parametrize(
    ("sentence", "fact"),
    [
        ("The table is a fixed object.", ("fixed-object", "table")),
        ("The screw is an object.", ("object", "screw")),
        ("The SnapRing1 is on the SnapRing2.", ("on", "SnapRing1", "SnapRing2")),
        ("The bolt is on top of the washer.", ("on", "bolt", "washer")),
        ("The bolt is in the hand.", ("in-hand", "bolt")),
        ("the bolt is clear", ("clear", "bolt")),
        ("The induction hardened rod is on the table.", ("on", "induction hardened rod", "table")),
    ],
)
def test_each_sentence_form(sentence: str, fact: tuple[str, ...]) -> None:
    assert read_sentence(sentence).fact() == fact


def test_several_sentences_on_several_lines() -> None:
    text = "The table is a fixed object. The A is on the B.\nThe C is in the hand."
    got = [s.fact() for s in read_sentences(text)]
    assert got == [("fixed-object", "table"), ("on", "A", "B"), ("in-hand", "C")]


@pytest.mark.parametrize(
    ("text", "number", "column", "hint"),
    [
        ("The a is an object. The b is on.", 2, 32, "expected"),
        ("The a is a fixed.", 1, 17, "'object'"),
        ("The a is on the a.", 1, 1, "on itself"),
        ("Put the a on the b.", 1, 1, "'is'"),
    ],
)
def test_errors_name_the_sentence_and_column(
    text: str, number: int, column: int, hint: str
) -> None:
    with pytest.raises(EnglishError) as info:
        read_sentences(text)
    err = info.value
    assert err.number == number
    assert hint in str(err)
    assert err.sentence in text
    if hint != "'is'":
        assert err.column == column


@given(st.sampled_from(["fixed", "movable", "on", "in-hand", "clear"]), names, names)
def test_statements_round_trip_through_sentences(kind: str, a: str, b: str) -> None:
    if kind == "on" and a == b:
        return
    st_ = Statement(kind, a, b if kind == "on" else None)
    back = read_sentence(st_.sentence())
    assert (back.kind, back.subject, back.other) == (st_.kind, st_.subject, st_.other)
