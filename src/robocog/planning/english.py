"""Controlled English for the learning and request phases of the planner.

The thesis passed sentences through Link Grammar, RelEx and Relex2Logic and then matched
the result with rules; the sentences it needs are few and regular, so a small grammar
(``data/english.lark``) reads them directly:

* ``The table is a fixed object.``   -> the table is fixed (cannot be moved, stays clear)
* ``The screw is an object.``        -> the screw can be moved
* ``The screw is on the bolt.``      -> ``on(screw, bolt)`` (also ``on top of``)
* ``The bolt is in the hand.``       -> ``in-hand(bolt)``
* ``The bolt is clear.``             -> ``clear(bolt)`` (useful in a request)

A name is one or more words (``BettClamp``, ``induction hardened rod``). A sentence that
does not fit raises ``EnglishError`` with the sentence, its number, and the line and
column where reading stopped.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from lark import Lark, Transformer, UnexpectedInput, v_args

from robocog.limits import clip


@dataclass(frozen=True)
class Statement:
    """One understood sentence: ``kind`` is fixed, movable, on, in-hand or clear."""

    kind: str
    subject: str
    other: str | None = None
    text: str = ""

    def fact(self) -> tuple[str, ...]:
        """The AtomSpace fact the sentence states (types as unary facts)."""
        if self.kind == "fixed":
            return ("fixed-object", self.subject)
        if self.kind == "movable":
            return ("object", self.subject)
        if self.kind == "on":
            assert self.other is not None
            return ("on", self.subject, self.other)
        return (self.kind, self.subject)

    def sentence(self) -> str:
        """The statement written back as a sentence of the same grammar."""
        if self.kind == "fixed":
            return f"The {self.subject} is a fixed object."
        if self.kind == "movable":
            return f"The {self.subject} is an object."
        if self.kind == "on":
            return f"The {self.subject} is on the {self.other}."
        if self.kind == "in-hand":
            return f"The {self.subject} is in the hand."
        return f"The {self.subject} is clear."


class EnglishError(ValueError):
    """A sentence the grammar cannot read; says which sentence and where."""

    def __init__(self, message: str, sentence: str, number: int, line: int, column: int) -> None:
        shown = clip(sentence)
        super().__init__(f"line {line}, column {column}: sentence {number} {shown!r}: {message}")
        self.sentence = sentence
        self.number = number
        self.line = line
        self.column = column


@lru_cache(maxsize=1)
def _parser() -> Lark:
    grammar = resources.files("robocog.planning").joinpath("data/english.lark").read_text()
    return Lark(grammar, parser="lalr")


@v_args(inline=True)
class _ToStatement(Transformer):
    def name(self, *words: object) -> str:
        return " ".join(str(w) for w in words)

    def subject(self, name: str) -> str:
        return name

    def fixed(self) -> tuple[str, None]:
        return ("fixed", None)

    def movable(self) -> tuple[str, None]:
        return ("movable", None)

    def on(self, name: str) -> tuple[str, str]:
        return ("on", name)

    def in_hand(self) -> tuple[str, None]:
        return ("in-hand", None)

    def clear(self) -> tuple[str, None]:
        return ("clear", None)

    def start(self, subject: str, predicate: tuple[str, str | None]) -> tuple[str, str, str | None]:
        return (predicate[0], subject, predicate[1])


#: the longest sentence and the longest text read (a request a person types)
MAX_SENTENCE_CHARS = 1_000
MAX_TEXT_CHARS = 100_000
_SENTENCE = re.compile(r"[^.]*\.|[^.]+$")


def _describe(exc: UnexpectedInput) -> str:
    expected = sorted(getattr(exc, "expected", None) or getattr(exc, "allowed", None) or [])
    token = getattr(exc, "token", None)
    words = {
        "IS": "'is'",
        "ON": "'on'",
        "A": "'a'",
        "AN": "'an'",
        "FIXED": "'fixed'",
        "OBJECT": "'object'",
        "IN": "'in'",
        "HAND": "'hand'",
        "CLEAR": "'clear'",
        "WORD": "a name",
        "THE": "'the'",
        "DOT": "'.'",
        "$END": "the end",
    }
    want = ", ".join(dict.fromkeys(words.get(e, e.lower()) for e in expected)) or "something else"
    if token is not None and str(token):
        return f"cannot read {clip(str(token), 40)!r} here; expected {want}"
    return f"the sentence stops too early; expected {want}"


def read_sentence(text: str, number: int = 1, line: int = 1, column: int = 1) -> Statement:
    """Read one sentence; *line*/*column* say where it starts in a longer text."""
    stripped = text.strip()
    if len(stripped) > MAX_SENTENCE_CHARS:
        raise EnglishError(
            f"longer than {MAX_SENTENCE_CHARS} characters (MAX_SENTENCE_CHARS)",
            stripped,
            number,
            line,
            column,
        )
    try:
        tree = _parser().parse(stripped)
    except UnexpectedInput as exc:
        col = getattr(exc, "column", 1)
        lead = len(text) - len(text.lstrip())
        raise EnglishError(
            _describe(exc), stripped, number, line, column + lead + col - 1
        ) from None
    kind, subject, other = _ToStatement().transform(tree)
    if other is not None and other == subject:
        raise EnglishError(f"the {subject} cannot be on itself", stripped, number, line, column)
    return Statement(kind, subject, other, stripped)


def read_sentences(text: str) -> list[Statement]:
    """Read every sentence of *text* (sentences end with a full stop)."""
    if len(text) > MAX_TEXT_CHARS:
        raise EnglishError(
            f"the text is longer than {MAX_TEXT_CHARS} characters (MAX_TEXT_CHARS)", text, 1, 1, 1
        )
    out: list[Statement] = []
    number = 0
    for lineno, line in enumerate(text.splitlines() or [text], start=1):
        for match in _SENTENCE.finditer(line):
            chunk = match.group(0)
            if not chunk.strip():
                continue
            number += 1
            out.append(read_sentence(chunk, number, lineno, match.start() + 1))
    return out
