"""Atomese: reading and writing atoms as the s-expressions OpenCog's Scheme shell uses.

The reader accepts what the thesis's knowledge bases and rule patterns contain:
full and short type names (``ConceptNode``/``Concept``), ``(stv s c)`` truth values
anywhere among an atom's arguments, ``;`` comments, quoted symbols as names
(``(Type 'ConceptNode)``), bare numbers as NumberNode names, ``(define name atom)``
to name an atom for later use, and ``(cog-execute! atom)`` to ask for a query's result.
Scheme procedures are not Atomese and are refused; the functions that rules call are
registered from Python instead.

The grammar is the s-expression grammar, small enough that a hand-written reader is
both clear and the fastest way to load 10^6 atoms; it is iterative, so deep nesting
cannot exhaust the stack. Every error carries the line and column where it was found.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import (
    Atom,
    Node,
    _raw_link,
    _raw_node,
    atom_text,
    bulk,
    deep,
    quote,
)
from robocog.atomspace.values import TruthValue, Value

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace


#: deepest nesting of parentheses the reader accepts
MAX_NESTING = 1000
#: most atoms one link may hold when read from text (adding a link costs time in
#: proportion to its arity for each atom it holds, so arity is bounded)
MAX_ARITY = 4096
#: most atoms an atom may hold once the named atoms it repeats are unfolded: atoms are
#: hashed and compared by content, so ``(define a (List x x)) (define b (List a a))``...
#: doubles the work at each level
MAX_UNFOLDED = 1_000_000
#: longest text read at once (characters)
MAX_TEXT = 64 * 1024 * 1024
#: longest error message (a 10 MB symbol is not echoed whole)
MAX_MESSAGE = 400


class AtomeseError(ValueError):
    """Malformed Atomese, with the place where it was found."""

    def __init__(self, message: str, line: int, column: int, source: str = "<string>") -> None:
        if len(message) > MAX_MESSAGE:
            message = message[: MAX_MESSAGE - 3] + "..."
        if len(source) > 200:
            source = source[:197] + "..."
        super().__init__(f"{source}:{line}:{column}: {message}")
        self.message = message
        self.line = line
        self.column = column
        self.source = source


@dataclass(slots=True)
class Form:
    """One top-level form of an Atomese text."""

    atom: Atom
    execute: bool  # written as (cog-execute! ...)
    line: int
    column: int


@dataclass(slots=True)
class Parsed:
    """The result of reading a text: top-level forms and every truth value written."""

    forms: list[Form] = field(default_factory=list)
    tvs: list[tuple[Atom, TruthValue]] = field(default_factory=list)
    names: dict[str, Atom] = field(default_factory=dict)

    @property
    def atoms(self) -> list[Atom]:
        """The top-level atoms in order."""
        return [f.atom for f in self.forms]


# strings are written as an unrolled loop (runs of plain characters between escapes, the
# loop possessive): ``(?:[^"\\]|\\.)*`` made the regex engine keep a backtracking mark per
# character, some 150 bytes each, so a 10 MB string took gigabytes to read
_TOKEN = re.compile(
    r"""
    (?P<ws>[ \t\r\f\v]+)
  | (?P<nl>\n)
  | (?P<comment>;[^\n]*)
  | (?P<open>\()
  | (?P<close>\))
  | (?P<string>"[^"\\]*(?:\\.[^"\\]*)*+")
  | (?P<badstring>"[^"\\]*(?:\\.[^"\\]*)*+\\?\Z)
  | (?P<quote>'[^\s()";']+)
  | (?P<symbol>[^\s()";']+)
  | (?P<other>.)
    """,
    re.VERBOSE | re.DOTALL,
)
_ESCAPE = re.compile(r"\\(.)", re.DOTALL)
_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")

# token kinds inside a frame
_STR, _NUM, _SYM, _QSYM = 0, 1, 2, 3


class _Tok:
    __slots__ = ("kind", "text", "line", "col")

    def __init__(self, kind: int, text: str, line: int, col: int) -> None:
        self.kind = kind
        self.text = text
        self.line = line
        self.col = col


class _Exec:
    __slots__ = ("atom",)

    def __init__(self, atom: Atom) -> None:
        self.atom = atom


class _Define:
    __slots__ = ()


def parse(text: str, source: str = "<string>", env: dict[str, Atom] | None = None) -> Parsed:
    """Read Atomese text into atoms without adding them anywhere.

    ``env`` names atoms that bare symbols in the text stand for (as the thesis's rules
    use ``args`` or ``ob``); ``(define name atom)`` adds to it for the rest of the text.
    """
    if not isinstance(text, str):
        raise TypeError("Atomese text must be a str")
    if len(text) > MAX_TEXT:
        raise AtomeseError(f"text longer than {MAX_TEXT} characters", 1, 1, source)
    with deep():  # equal deep atoms compare by recursion
        return _parse(text, source, env)


def _parse(text: str, source: str, env: dict[str, Atom] | None) -> Parsed:
    names: dict[str, Atom] = dict(env or {})
    result = Parsed(names=names)
    tvs = result.tvs
    memo: dict[Atom, Atom] = {}
    sizes: dict[int, int] = {}  # id of a link read here -> its size with shared parts unfolded
    # a frame: [items, line, col]; items hold Atom | TruthValue | _Tok | _Exec
    stack: list[list] = []
    line, line_start = 1, 0

    def err(msg: str, ln: int, col: int) -> AtomeseError:
        return AtomeseError(msg, ln, col, source)

    for m in _TOKEN.finditer(text):
        kind = m.lastgroup
        if kind == "ws" or kind == "comment":
            continue
        start = m.start()
        col = start - line_start + 1
        if kind == "nl":
            line += 1
            line_start = m.end()
            continue
        if kind == "open":
            if len(stack) >= MAX_NESTING:
                raise err(f"nesting deeper than {MAX_NESTING} levels", line, col)
            stack.append([[], line, col])
            continue
        if kind == "close":
            if not stack:
                raise err("unexpected ')'", line, col)
            items, fl, fc = stack.pop()
            value = _reduce(items, fl, fc, names, tvs, err, bool(stack), memo, sizes)
            if stack:
                if len(stack[-1][0]) > MAX_ARITY:
                    raise err(
                        f"a link holding more than {MAX_ARITY} atoms", stack[-1][1], stack[-1][2]
                    )
                stack[-1][0].append(value)
            elif isinstance(value, _Exec):
                result.forms.append(Form(value.atom, True, fl, fc))
            elif isinstance(value, Atom):
                result.forms.append(Form(value, False, fl, fc))
            elif isinstance(value, _Define):
                pass
            else:
                raise err("a truth value must follow the atom it belongs to", fl, fc)
            continue
        if kind == "string":
            raw = m.group()
            body = raw[1:-1]
            value_text = _ESCAPE.sub(lambda e: e.group(1), body) if "\\" in body else body
            tok = _Tok(_STR, value_text, line, col)
            nls = raw.count("\n")
            if nls:
                line += nls
                line_start = start + raw.rfind("\n") + 1
        elif kind == "badstring":
            raise err("unterminated string", line, col)
        elif kind == "quote":
            tok = _Tok(_QSYM, m.group()[1:], line, col)
        elif kind == "symbol":
            s = m.group()
            tok = _Tok(_NUM if _NUMBER.match(s) else _SYM, s, line, col)
        else:
            raise err(f"unexpected character {m.group()!r}", line, col)
        if stack and len(stack[-1][0]) > MAX_ARITY:
            raise err(f"a link holding more than {MAX_ARITY} atoms", stack[-1][1], stack[-1][2])
        if not stack:
            if tok.kind == _SYM and tok.text in names:
                continue  # a bare reference at top level evaluates to itself: no-op
            raise err(f"expected '(' but found {tok.text!r}", tok.line, tok.col)
        stack[-1][0].append(tok)
    if stack:
        _items, fl, fc = stack[-1]
        raise err("unclosed '(' (missing ')')", fl, fc)
    return result


def _reduce(items: list, fl: int, fc: int, names, tvs, err, nested: bool, memo: dict, sizes: dict):  # noqa: ANN001, ANN202, C901
    """Turn one parenthesised frame into an Atom, a TruthValue or a special form."""
    if not items:
        raise err("empty expression '()'", fl, fc)
    head = items[0]
    if not isinstance(head, _Tok) or head.kind != _SYM:
        raise err("expected a type name after '('", fl, fc)
    h = head.text
    args = items[1:]
    if h == "stv":
        if len(args) != 2 or any(not isinstance(a, _Tok) or a.kind != _NUM for a in args):
            raise err("stv takes two numbers: (stv strength confidence)", fl, fc)
        try:
            return TruthValue(float(args[0].text), float(args[1].text))
        except ValueError as exc:
            raise err(str(exc), fl, fc) from None
    if h == "define":
        if nested:
            raise err("define is only allowed at top level", fl, fc)
        if len(args) != 2 or not isinstance(args[0], _Tok) or args[0].kind != _SYM:
            raise err(
                "only (define name atom) is Atomese; procedures are registered from Python",
                fl,
                fc,
            )
        value = _arg_atom(args[1], names, err, fl, fc)
        names[args[0].text] = value
        return _Define()
    if h in ("cog-execute!", "cog-evaluate!"):
        if nested:
            raise err(f"{h} is only allowed at top level", fl, fc)
        if len(args) != 1:
            raise err(f"{h} takes one atom", fl, fc)
        return _Exec(_arg_atom(args[0], names, err, fl, fc))
    full = _t.resolve(h)
    if full is None:
        if h in ("lambda", "let", "if", "car", "cdr", "equal?"):
            raise err(f"Scheme form {h!r} is not Atomese", head.line, head.col)
        raise err(f"unknown atom type {h!r}", head.line, head.col)
    tv: TruthValue | None = None
    rest = []
    for a in args:
        if isinstance(a, TruthValue):
            if tv is not None:
                raise err("more than one truth value", fl, fc)
            tv = a
        elif isinstance(a, _Exec | _Define):
            raise err("special form inside an atom", fl, fc)
        else:
            rest.append(a)
    if full in _t.NODE_TYPES:
        if len(rest) != 1 or not isinstance(rest[0], _Tok) or rest[0].kind == _SYM:
            if len(rest) == 1 and isinstance(rest[0], _Tok) and rest[0].kind == _SYM:
                if rest[0].text not in names:
                    raise err(
                        f"a node name must be a string, not the symbol {rest[0].text!r}",
                        rest[0].line,
                        rest[0].col,
                    )
            raise err(f'{full} takes one name: ({full} "name")', fl, fc)
        atom: Atom = _raw_node(full, rest[0].text)
    else:
        out = tuple(_arg_atom(a, names, err, fl, fc) for a in rest)
        size = 1 + sum(sizes.get(id(x), 1) for x in out)
        if size > MAX_UNFOLDED:
            raise err(
                f"an atom of more than {MAX_UNFOLDED} atoms once its named parts are unfolded",
                fl,
                fc,
            )
        atom = _raw_link(full, out)
    atom = memo.setdefault(atom, atom)  # one object per distinct atom: less memory
    if atom.__class__ is not Node:
        sizes[id(atom)] = size  # memo keeps the atom alive, so its id stays its own
    if tv is not None:
        tvs.append((atom, tv))
    return atom


def _arg_atom(a, names, err, fl: int, fc: int) -> Atom:  # noqa: ANN001
    if isinstance(a, Atom):
        return a
    if isinstance(a, _Tok):
        if a.kind == _SYM:
            found = names.get(a.text)
            if found is None:
                raise err(f"unknown name {a.text!r}", a.line, a.col)
            return found
        raise err(f"expected an atom, found {a.text!r}", a.line, a.col)
    if isinstance(a, TruthValue):
        raise err("a truth value is not an atom", fl, fc)
    raise err("expected an atom", fl, fc)


def load(
    text: str,
    space: AtomSpace,
    source: str = "<string>",
    env: dict[str, Atom] | None = None,
) -> list[Atom]:
    """Parse ``text`` and add its atoms and truth values to ``space``.

    The whole text is parsed first, so a malformed text leaves ``space`` unchanged.
    Returns the top-level atoms (as added to the space).
    """
    with bulk(), deep():
        parsed = parse(text, source=source, env=env)
        return add_parsed(parsed, space, source)


def _check_defines(parsed: Parsed, space: AtomSpace, source: str) -> None:
    """A name a DefineLink defines may be defined once (OpenCog refuses a second
    definition): refuse the text before anything is added."""
    seen: dict[Atom, Atom] = {}
    for f in parsed.forms:
        atom = f.atom
        if atom[0] != "DefineLink" or len(atom[1]) != 2:
            continue
        key = atom[1][0]
        earlier = seen.get(key)
        if earlier is None and key in space:
            for d in space.incoming(key, "DefineLink"):
                if d[1] and d[1][0] == key:
                    earlier = d
        if earlier is not None and earlier != atom:
            raise AtomeseError(
                f"{str(key)[:200]} is already defined (a DefineLink defines a name once)",
                f.line,
                f.column,
                source,
            )
        seen[key] = atom


def add_parsed(parsed: Parsed, space: AtomSpace, source: str = "<string>") -> list[Atom]:
    """Add what :func:`parse` read to ``space``; returns the top-level atoms.

    A second DefineLink of a name is an :class:`AtomeseError` and adds nothing."""
    _check_defines(parsed, space, source)
    added = []
    with deep():
        for f in parsed.forms:
            try:
                added.append(space.add(f.atom))
            except ValueError as exc:
                raise AtomeseError(str(exc), f.line, f.column, source) from None
    out = [a for a in added if a is not None]  # a closed DeleteLink removes, adds nothing
    for atom, tv in parsed.tvs:
        space.set_tv(atom, tv)
    return out


def read_atom(text: str, env: dict[str, Atom] | None = None) -> Atom:
    """Read exactly one atom from ``text``."""
    parsed = parse(text, env=env)
    if len(parsed.forms) != 1:
        raise AtomeseError(f"expected one atom, found {len(parsed.forms)}", 1, 1)
    return parsed.forms[0].atom


# ---------------------------------------------------------------------- writing
def write(atom: Atom | Value, tv: TruthValue | None = None) -> str:
    """One-line Atomese for an atom (or a Value)."""
    if isinstance(atom, Value):
        return atom.to_atomese()
    text = atom_text(atom)
    if tv is not None:
        text = f"{text[:-1]} {tv.to_atomese()})"
    return text


def write_pretty(atom: Atom | Value, space: AtomSpace | None = None, indent: int = 0) -> str:
    """Multi-line Atomese, indented as OpenCog prints it; with ``space``, truth values
    that differ from the default are written too."""
    if isinstance(atom, Value):
        return " " * indent + atom.to_atomese()
    lines: list[str] = []
    _write_pretty(atom, space, indent, lines)
    return "\n".join(lines)


def _write_pretty(atom: Atom, space: AtomSpace | None, indent: int, lines: list[str]) -> None:
    pad = " " * indent
    tv = space.get_tv_or_none(atom) if space is not None else None
    tvs = f" {tv.to_atomese()}" if tv is not None else ""
    if isinstance(atom, Node):
        lines.append(f"{pad}({atom[0]} {quote(atom[1])}{tvs})")
        return
    if not atom[1]:
        lines.append(f"{pad}({atom[0]}{tvs})")
        return
    lines.append(f"{pad}({atom[0]}{tvs}")
    for a in atom[1]:
        _write_pretty(a, space, indent + 2, lines)
    lines[-1] += ")"


def dump(space: AtomSpace) -> str:
    """The whole space as Atomese text that :func:`load` reads back: every atom that is
    not held by another (the rest are written inside them), with its truth values."""
    roots = [a for a in space if not space.incoming(a)]
    roots.sort()
    chunks = [write_pretty(a, space) for a in roots]
    return "\n".join(chunks) + ("\n" if chunks else "")


__all__ = [
    "MAX_ARITY",
    "MAX_NESTING",
    "MAX_TEXT",
    "MAX_UNFOLDED",
    "AtomeseError",
    "Form",
    "Parsed",
    "add_parsed",
    "dump",
    "load",
    "parse",
    "quote",
    "read_atom",
    "write",
    "write_pretty",
]
