"""Reader for ONA's Narsese dialect.

A lark LALR grammar turns one line into a :class:`Sentence`. Infix compounds with more
than two components (``(a &/ b &/ c)``) and prefix forms (``(&&, a, b, c)``) become
left-nested binary terms, which is how ONA stores them; variables are renamed to
``$1 #1 ?1`` by first occurrence. Errors are :class:`NarseseError` with line and column,
so a person typing into the shell sees where the line went wrong.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from lark import Lark, Token, Transformer, UnexpectedEOF, UnexpectedInput, UnexpectedToken, v_args

from robocog.limits import MESSAGE_CHARS, clip

from .config import MAX_TIME
from .terms import (
    EXT_SET,
    INT_SET,
    STATEMENT_COPULAS,
    Term,
    atom,
    compound,
    normalize_variables,
)
from .truth import Truth

GRAMMAR = r"""
start: dt? term PUNCT TENSE? truth?
dt: DT
truth: TRUTH_BRACES | TRUTH_PERCENT

?term: name
     | "<" term COPULA term ">"          -> statement
     | "<" term (INFIX term)+ COPULA term ">"  -> statement_infix
     | "<" term (INFIX term)+ ">"        -> infix
     | "<" term ">"
     | "(" term COPULA term ")"          -> statement
     | "(" term (INFIX term)+ ")"        -> infix
     | "(" prefix_op ("," term)+ ")"     -> prefix
     | "(" UNARY term ")"                -> unary
     | "(" INFIX term ")"                -> unary
     | "{" term+ "}"                     -> extset
     | "[" term+ "]"                     -> intset

prefix_op: INFIX | "--"
name: NAME

COPULA: "-->" | "<->" | "==>" | "<=>" | "=/>" | "|->"
INFIX: "*" | "&&" | "||" | "&/" | "&" | "|" | "-" | "~" | "/1" | "/2" | "\\1" | "\\2"
UNARY: "!" | "+" | "="
NAME: /[\^$#?]?[A-Za-z0-9_\u00c0-\uffff]+(\.[A-Za-z0-9_\u00c0-\uffff]+)*/
PUNCT: "." | "!" | "?"
TENSE: ":|:" | ":\\:" | ":/:"
TRUTH_BRACES: /\{\s*[0-9]*\.?[0-9]+\s+[0-9]*\.?[0-9]+\s*\}/
TRUTH_PERCENT: /%[0-9]*\.?[0-9]+(;[0-9]*\.?[0-9]+)?%/
DT.2: /dt=-?[0-9]+(\.[0-9]+)?/

%ignore /[ \t]+/
"""

TERM_GRAMMAR_START = "term"
#: ONA reads at most 1023 characters a line; longer terms are beyond its term size too
MAX_LINE = 4096


class NarseseError(ValueError):
    """A line that is not Narsese; ``line`` and ``column`` are 1-based."""

    def __init__(self, line: int, column: int, message: str) -> None:
        message = clip(message, MESSAGE_CHARS)
        super().__init__(f"line {line}, column {column}: {message}")
        self.line = line
        self.column = column
        self.message = message


@dataclass(frozen=True, slots=True)
class Sentence:
    """One parsed input: term, punctuation (``.``, ``!``, ``?``), tense, truth and dt."""

    term: Term
    punctuation: str
    tense: str | None = None
    truth: Truth | None = None
    dt: float | None = None

    def __str__(self) -> str:
        out = f"{self.term}{self.punctuation}"
        if self.tense:
            out += f" {self.tense}"
        if self.truth is not None:
            out += f" {{{self.truth.f:g} {self.truth.c:g}}}"
        return out


class _Positioned(ValueError):
    """A semantic error found while building, at the column of the offending token."""

    def __init__(self, column: int, message: str) -> None:
        super().__init__(message)
        self.column = column


class _Build(Transformer):
    """Builds interned terms bottom-up from the parse tree."""

    def name(self, items: list[Token]) -> Term:
        return atom(str(items[0]))

    def statement(self, items: list[object]) -> Term:
        s, cop, p = items
        return compound(str(cop), (s, p))  # type: ignore[arg-type]

    def statement_infix(self, items: list[object]) -> Term:
        """``<a &/ b =/> c>``: an unbracketed compound as subject, as the seed writes it."""
        subject = self.infix(items[:-2])
        return compound(str(items[-2]), (subject, items[-1]))  # type: ignore[arg-type]

    def infix(self, items: list[object]) -> Term:
        left = items[0]
        ops = {str(items[i]) for i in range(1, len(items), 2)}
        if len(ops) != 1:
            col = next(
                items[i].column  # type: ignore[union-attr]
                for i in range(3, len(items), 2)
                if str(items[i]) != str(items[1])
            )
            raise _Positioned(col, "mixed connectors in one compound: " + " ".join(sorted(ops)))
        op = ops.pop()
        for i in range(2, len(items), 2):
            left = compound(op, (left, items[i]))  # type: ignore[arg-type]
        return left  # type: ignore[return-value]

    def prefix_op(self, items: list[Token]) -> str:
        return str(items[0]) if items else "!"

    def prefix(self, items: list[object]) -> Term:
        op = items[0]
        terms = items[1:]
        if op == "!" or len(terms) == 1:
            if op == "!" and len(terms) != 1:
                raise ValueError("negation takes one term")
            if op not in ("!", "*"):
                # ONA has no one-component conjunction, sequence, intersection or image:
                # ``(&&, a)`` would be a term its rules index out of (refused, as the
                # infix ``(&& a)`` is)
                raise ValueError(f"{op} needs two components")
            return compound(op, (terms[0],))  # type: ignore[arg-type]
        left = terms[0]
        for t in terms[1:]:
            left = compound(op, (left, t))  # type: ignore[arg-type]
        return left  # type: ignore[return-value]

    def unary(self, items: list[object]) -> Term:
        op = items[0]
        if str(op) not in ("!", "+", "=", "*"):
            column = op.column if isinstance(op, Token) and op.column is not None else 1
            raise _Positioned(column, f"{op} needs two components")
        return compound(str(items[0]), (items[1],))  # type: ignore[arg-type]

    def extset(self, items: list[Term]) -> Term:
        return compound(EXT_SET, _dedupe(items))

    def intset(self, items: list[Term]) -> Term:
        return compound(INT_SET, _dedupe(items))

    def dt(self, items: list[Token]) -> float:
        dt = float(str(items[0])[3:])
        if abs(dt) > MAX_TIME:
            raise _Positioned(
                items[0].column,  # type: ignore[arg-type]
                f"dt={str(items[0])[3:][:30]} is out of range [-{MAX_TIME}, {MAX_TIME}]",
            )
        return dt

    def truth(self, items: list[Token]) -> Truth:
        s = str(items[0])
        if s.startswith("%"):
            parts = s.strip("%").split(";")
            f = float(parts[0])
            c = float(parts[1]) if len(parts) > 1 else 0.9
        else:
            f_s, c_s = s.strip("{} \t").split()
            f, c = float(f_s), float(c_s)
        if not (0.0 <= f <= 1.0 and 0.0 <= c < 1.0):
            raise _Positioned(
                items[0].column,  # type: ignore[arg-type]
                f"truth out of range: frequency {f}, confidence {c}",
            )
        return Truth(f, min(c, 0.99))

    @v_args(inline=False)
    def start(self, items: list[object]) -> Sentence:
        dt = None
        i = 0
        if isinstance(items[0], float):
            dt = items[0]
            i = 1
        term = items[i]
        punct = str(items[i + 1])
        tense = None
        truth = None
        for x in items[i + 2 :]:
            if isinstance(x, Truth):
                truth = x
            else:
                tense = str(x)
        return Sentence(normalize_variables(term), punct, tense, truth, dt)  # type: ignore[arg-type]


def _dedupe(items: list[Term]) -> tuple[Term, ...]:
    seen: list[Term] = []
    for t in items:
        if t not in seen:
            seen.append(t)
    return tuple(seen)


_SENTENCE = Lark(GRAMMAR, parser="lalr", start="start")
_TERM = Lark(GRAMMAR, parser="lalr", start="term")
_BUILD = _Build()


def _error(text: str, exc: Exception, line: int) -> NarseseError:
    if isinstance(exc, UnexpectedToken) and exc.token.type == "$END":
        return NarseseError(line, len(text.rstrip()) + 1, "unexpected end of line")
    if isinstance(exc, UnexpectedEOF):
        return NarseseError(line, len(text.rstrip()) + 1, "unexpected end of line")
    if isinstance(exc, UnexpectedInput):
        col = exc.column if isinstance(exc.column, int) and exc.column > 0 else 1
        got = text[col - 1 : col + 9] if col - 1 < len(text) else "end of line"
        return NarseseError(line, col, f"unexpected {got!r}")
    cause = getattr(exc, "orig_exc", exc)
    if isinstance(cause, _Positioned):
        return NarseseError(line, cause.column, str(cause))
    return NarseseError(line, 1, str(cause))


def parse_sentence(text: str, line: int = 1) -> Sentence:
    """Parse one Narsese sentence such as ``<a --> b>. :|: {1.0 0.9}``.

    A robot's sensors send the same few lines over and over, so the sentences of recent
    lines are kept (they are immutable and their terms interned): a repeated line costs
    a dictionary lookup instead of a parse."""
    try:
        return _parse_sentence(text)
    except NarseseError as exc:
        if line == 1:
            raise
        raise NarseseError(line, exc.column, exc.message) from None


#: the commonest line, ``<a --> b>.`` between two plain names (no variable, no dot), with
#: ``:|:`` or nothing after it: read without the parser, into the same sentence the
#: grammar makes of it (a taxonomy of 10,000 such lines spent a twentieth of its time
#: in the parser)
_SIMPLE = re.compile(r"<([A-Za-z0-9_]+) (-->|<->) ([A-Za-z0-9_]+)>([.!?])( :\|:)?")


@lru_cache(maxsize=4096)
def _parse_sentence(text: str) -> Sentence:
    if len(text) > MAX_LINE:
        raise NarseseError(1, MAX_LINE + 1, f"line longer than {MAX_LINE} characters")
    simple = _SIMPLE.fullmatch(text)
    if simple is not None:
        s, cop, p, punct, tense = simple.groups()
        term = compound(cop, (atom(s), atom(p)))
        return Sentence(term, punct, tense[1:] if tense else None, None, None)
    try:
        tree = _SENTENCE.parse(text)
        return _BUILD.transform(tree)  # type: ignore[no-any-return]
    except RecursionError:
        raise NarseseError(1, 1, "term nested too deeply") from None
    except UnexpectedInput as exc:
        raise _error(text, exc, 1) from None
    except Exception as exc:  # noqa: BLE001 - a transformer check, reported with position
        raise _error(text, exc, 1) from None


def parse_term(text: str, line: int = 1) -> Term:
    """Parse one Narsese term such as ``<(a * b) --> r>``."""
    try:
        return normalize_variables(_BUILD.transform(_TERM.parse(text)))
    except UnexpectedInput as exc:
        raise _error(text, exc, line) from None
    except Exception as exc:  # noqa: BLE001
        raise _error(text, exc, line) from None


def parse_pattern(text: str) -> Term:
    """Parse a rule pattern without renaming its variables."""
    return _BUILD.transform(_TERM.parse(text))  # type: ignore[no-any-return]


# ----------------------------------------------------------------- the printed form
#: one name, as the grammar's NAME reads it
_NAME_RE = re.compile(r"[\^$#?]?[A-Za-z0-9_\u00c0-\uffff]+(?:\.[A-Za-z0-9_\u00c0-\uffff]+)*")
_COPULA_AT = frozenset(c for c in STATEMENT_COPULAS)
_INFIX_AT = frozenset({"*", "&&", "||", "&/", "&", "|", "-", "~", "/1", "/2", "\\1", "\\2"})
#: connectors printed ``(op A)``: what the grammar takes with one component
_UNARY_AT = frozenset({"!", "*", "+", "="})


class _NotCanonical(ValueError):
    pass


_NAME_TEXT = _NAME_RE.pattern
#: the commonest term of a memory, a statement between two names, read in one match
_SIMPLE_TERM = re.compile(f"<({_NAME_TEXT}) (-->|<->|==>|<=>|=/>|\\|->) ({_NAME_TEXT})>")


def read_canonical(text: str) -> Term:
    """The term whose printed form (``str(term)``) is exactly ``text``, without the
    grammar: what a saved memory holds, read at a few microseconds a term.

    It takes what ``parse_pattern`` takes and prints back unchanged, and nothing else
    (any other text, Narsese or not, raises ValueError): variables keep their names,
    compounds are binary, sets hold distinct elements. Terms nested past Python's
    recursion limit raise RecursionError, as the grammar's builder does."""
    simple = _SIMPLE_TERM.fullmatch(text)
    if simple is not None:
        a, cop, b = simple.groups()
        return compound(cop, (atom(a), atom(b)))
    try:
        term, end = _read_at(text, 0)
    except IndexError:
        raise _NotCanonical("the term ends early") from None
    if end != len(text):
        raise _NotCanonical(f"unexpected text at column {end + 1}")
    # (what this reads prints back as the same text by construction: one space where
    # the printer puts one, binary compounds only, sets of distinct elements; the
    # tests compare it with the grammar on mutated texts)
    return term


def _read_at(s: str, i: int) -> tuple[Term, int]:
    c = s[i]
    if c == "<":
        a, i = _read_at(s, i + 1)
        cop = s[i + 1 : i + 4]
        if s[i] != " " or cop not in _COPULA_AT or s[i + 4] != " ":
            raise _NotCanonical(f"a copula expected at column {i + 1}")
        b, i = _read_at(s, i + 5)
        if s[i] != ">":
            raise _NotCanonical(f"'>' expected at column {i + 1}")
        return compound(cop, (a, b)), i + 1
    if c == "(":
        op = s[i + 1]
        if op in _UNARY_AT and s[i + 2] == " ":
            a, i = _read_at(s, i + 3)
            if s[i] != ")":
                raise _NotCanonical(f"')' expected at column {i + 1}")
            return compound(op, (a,)), i + 1
        a, i = _read_at(s, i + 1)
        j = s.find(" ", i + 1)
        op = s[i + 1 : j]
        if s[i] != " " or j < 0 or op not in _INFIX_AT:
            raise _NotCanonical(f"a connector expected at column {i + 1}")
        b, i = _read_at(s, j + 1)
        if s[i] != ")":
            raise _NotCanonical(f"')' expected at column {i + 1}")
        return compound(op, (a, b)), i + 1
    if c == "{" or c == "[":
        close = "}" if c == "{" else "]"
        items: list[Term] = []
        i += 1
        while True:
            t, i = _read_at(s, i)
            items.append(t)
            if s[i] == close:
                break
            if s[i] != " ":
                raise _NotCanonical(f"'{close}' expected at column {i + 1}")
            i += 1
        if len(set(items)) != len(items):
            raise _NotCanonical("a set holds an element twice")
        return compound(EXT_SET if c == "{" else INT_SET, tuple(items)), i + 1
    m = _NAME_RE.match(s, i)
    if m is None:
        raise _NotCanonical(f"a term expected at column {i + 1}")
    return atom(m.group()), m.end()


__all__ = [
    "read_canonical",
    "NarseseError",
    "Sentence",
    "parse_sentence",
    "parse_term",
    "parse_pattern",
    "STATEMENT_COPULAS",
]
