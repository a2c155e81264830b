"""The saved memory's term reader agrees with the grammar on every text: it takes what
the grammar takes and prints back unchanged, and refuses the rest."""

from __future__ import annotations

import random

import pytest

from robocog.nars.narsese import parse_pattern, parse_sentence, read_canonical

LINES = [
    "<a --> b>.",
    "<{cat} --> [black]>.",
    "<(a &/ ^left) =/> g>.",
    "<($1 * #2) --> r>?",
    "(&&, a, b, c).",
    "<(! a) ==> b>.",
    "<(a | b) --> (c - d)>.",
    "<(a ~ b) <-> (c & d)>.",
    "<(r /1 a) --> b>.",
    "<(* a) --> (+ b)>.",
    "<{a b c} --> [x y]>.",
    "<(a.b || c) <=> <d |-> e>>.",
    "<(x \\1 y) --> (z /2 w)>.",
    "<(= p) --> q>.",
]


def _grammar(text: str):  # noqa: ANN202 - a term or None
    try:
        t = parse_pattern(text)
    except Exception:  # noqa: BLE001 - refused by the grammar
        return None
    return t if str(t) == text else None


def _mine(text: str):  # noqa: ANN202
    try:
        return read_canonical(text)
    except ValueError:
        return None


@pytest.mark.parametrize("line", LINES)
def test_printed_terms_read_back_as_themselves(line: str) -> None:
    term = parse_sentence(line).term
    for sub in term.walk():
        assert read_canonical(str(sub)) is sub


def test_mutated_texts_are_judged_as_the_grammar_judges_them() -> None:
    rng = random.Random(7)
    pieces = ["<", ">", "(", ")", "{", "}", "[", "]", " ", "-->", "&&", "*", "!", "a", "$1", "  "]
    texts = [str(parse_sentence(line).term) for line in LINES]
    checked = 0
    for _ in range(10000):
        s = rng.choice(texts)
        i = rng.randrange(len(s) + 1)
        if rng.random() < 0.5:
            s = s[:i] + rng.choice(pieces) + s[i:]
        else:
            s = s[:i] + s[i + rng.randint(1, 3) :]
        want = _grammar(s)
        got = _mine(s)
        assert got is want, s
        checked += want is not None
    assert checked > 50  # some mutations stay terms


@pytest.mark.parametrize(
    "text", ["(&& a)", "{a a}", "<a-->b>", "(a && b && c)", "<a --> b> ", "", "((a * b))"]
)
def test_what_is_not_printed_form_is_refused(text: str) -> None:
    with pytest.raises(ValueError):
        read_canonical(text)
