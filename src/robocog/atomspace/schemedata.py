"""The data and the reader of the Scheme layer: symbols, lists that remember where
they were read, pairs, characters, the iterative reader and the printer (the
evaluator is :mod:`robocog.atomspace.scheme`)."""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator
from fractions import Fraction
from typing import Any

from robocog.atomspace.atomese import AtomeseError

#: deepest nesting of parentheses the reader accepts
MAX_NESTING = 1000
#: the longest program text read at once (characters)
MAX_TEXT = 64 * 1024 * 1024
#: the Python recursion limit while evaluating: bounds non-tail recursion (about a third
#: of it in nested Scheme calls); deeper ends with a ``stack-overflow`` error
MAX_DEPTH = 12000
#: longest message text an error carries (names and values in it are shortened)
MAX_MESSAGE = 400


def shorten(text: str, limit: int = 120) -> str:
    """``text`` cut to ``limit`` characters (error messages stay small)."""
    return text if len(text) <= limit else text[: limit - 3] + "..."


class SchemeError(AtomeseError):
    """A Scheme error: Guile's key (``unbound-variable``...), a message and a place."""

    def __init__(
        self,
        key: str,
        message: str,
        line: int = 0,
        column: int = 0,
        source: str = "<string>",
        args: list | None = None,
    ) -> None:
        message = shorten(message, MAX_MESSAGE)
        super().__init__(message, line, column, source)
        self.key = key
        self.args_list = args if args is not None else []

    def located(self, line: int, column: int, source: str) -> SchemeError:
        """This error with its place set (the innermost form that had one)."""
        return SchemeError(self.key, self.message, line, column, source, self.args_list)

    def __str__(self) -> str:
        if self.line:
            return f"{self.source}:{self.line}:{self.column}: {self.key}: {self.message}"
        return f"{self.source}: {self.key}: {self.message}"


class ControlFlow(Exception):  # noqa: N818 - not an error: a jump
    """A non-local exit (throw, an escaping continuation) on its way up."""


class Throw(ControlFlow):
    """``(throw key args...)`` on its way to a ``catch``."""

    def __init__(self, key: Any, args: list) -> None:
        super().__init__(key)
        self.key = key
        self.args = args


# ---------------------------------------------------------------------- data
class Sym(str):
    """A Scheme symbol (interned: compare with ``is``)."""

    __slots__ = ()


_SYMBOLS: dict[str, Sym] = {}


def sym(name: str) -> Sym:
    """The symbol named ``name``."""
    s = _SYMBOLS.get(name)
    if s is None:
        s = _SYMBOLS[name] = Sym(name)
    return s


class Form(list):
    """A list read from text: remembers where it started."""

    __slots__ = ("line", "col")

    def __init__(self, items: list, line: int = 0, col: int = 0) -> None:
        super().__init__(items)
        self.line = line
        self.col = col


class Pair:
    """An improper pair ``(a . b)`` (proper lists are Python lists)."""

    __slots__ = ("car", "cdr")

    def __init__(self, car: Any, cdr: Any) -> None:
        self.car = car
        self.cdr = cdr

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Pair) and self.car == other.car and self.cdr == other.cdr

    def __hash__(self) -> int:
        return hash((self.car, self.cdr))


class Char(str):
    """A Scheme character."""

    __slots__ = ()


class Unspecified:
    """Guile's unspecified value (what ``define`` and ``display`` return)."""

    _it: Unspecified | None = None

    def __new__(cls) -> Unspecified:
        if cls._it is None:
            cls._it = super().__new__(cls)
        return cls._it

    def __repr__(self) -> str:
        return "#<unspecified>"


UNSPECIFIED = Unspecified()


class Keyword(str):
    """``#:name``."""

    __slots__ = ()


class Env:
    """A lexical frame: a dict of bindings and the enclosing frame."""

    __slots__ = ("vars", "parent")

    def __init__(self, vars: dict, parent: Env | None) -> None:
        self.vars = vars
        self.parent = parent

    def find(self, name: Sym) -> dict:
        e: Env | None = self
        while e is not None:
            if name in e.vars:
                return e.vars
            e = e.parent
        raise SchemeError("unbound-variable", f"Unbound variable: {shorten(name)}", args=[name])


class Procedure:
    """A procedure made by ``lambda`` or ``define``."""

    __slots__ = ("params", "rest", "body", "env", "name")

    def __init__(self, params: list, rest: Sym | None, body: list, env: Env, name: str) -> None:
        self.params = params
        self.rest = rest
        self.body = body
        self.env = env
        self.name = name

    def __repr__(self) -> str:
        return f"#<procedure {self.name}>"


class Primitive:
    """A procedure written in Python; ``fn`` takes the evaluated arguments."""

    __slots__ = ("fn", "name")

    def __init__(self, fn: Callable, name: str) -> None:
        self.fn = fn
        self.name = name

    def __repr__(self) -> str:
        return f"#<procedure {self.name}>"


class Parameter:
    """A place a ``set!`` can change from Python (``current-output-port``...)."""


# ---------------------------------------------------------------------- reader
# a string is an unrolled, possessive loop: no backtracking mark per character (see the
# Atomese reader's tokens)
_TOKEN = re.compile(
    r"""
    (?P<ws>[ \t\r\f\v]+)
  | (?P<nl>\n)
  | (?P<comment>;[^\n]*)
  | (?P<block>\#\|.*?\|\#)
  | (?P<block2>\#!.*?!\#)
  | (?P<badblock>\#\||\#!)
  | (?P<datumc>\#;)
  | (?P<open>[(\[])
  | (?P<close>[)\]])
  | (?P<vopen>\#\()
  | (?P<string>"[^"\\]*(?:\\.[^"\\]*)*+")
  | (?P<badstring>")
  | (?P<quote>'|`|,@|,)
  | (?P<char>\#\\(?:[A-Za-z]+|.))
  | (?P<atom>[^\s()\[\]";'`,]+)
    """,
    re.VERBOSE | re.DOTALL,
)
_QUOTES = {"'": "quote", "`": "quasiquote", ",": "unquote", ",@": "unquote-splicing"}
_STRING_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "a": "\a", "0": "\0", "\\": "\\", '"': '"'}
_CHAR_NAMES = {
    "space": " ",
    "newline": "\n",
    "tab": "\t",
    "nul": "\0",
    "null": "\0",
    "return": "\r",
    "linefeed": "\n",
}
_INT = re.compile(r"[+-]?\d+\Z")
_RATIO = re.compile(r"[+-]?\d+/\d+\Z")
_FLOAT = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")
_DOT = sym(".")


def _unescape(body: str) -> str:
    out: list[str] = []
    i = 0
    n = len(body)
    while i < n:
        c = body[i]
        if c == "\\" and i + 1 < n:
            nxt = body[i + 1]
            if nxt == "\n":
                i += 2
                while i < n and body[i] in " \t":
                    i += 1
                continue
            if nxt == "x":
                end = body.find(";", i)
                if end != -1:
                    try:
                        out.append(chr(int(body[i + 2 : end], 16)))
                        i = end + 1
                        continue
                    except ValueError:
                        pass
            out.append(_STRING_ESCAPES.get(nxt, nxt))
            i += 2
            continue
        out.append(c)
        i += 1
    return "".join(out)


def atom_value(text: str) -> Any:
    """A token that is not a list, string or character: a number, boolean or symbol."""
    c = text[0]
    if c.isdigit() or (c in "+-." and len(text) > 1):
        if _INT.match(text):
            return int(text)
        if _FLOAT.match(text):
            return float(text)
        if _RATIO.match(text):
            num, den = text.split("/")
            if int(den) == 0:
                return sym(text)
            f = Fraction(int(num), int(den))
            return f.numerator if f.denominator == 1 else f
    if c == "#":
        low = text.lower()
        if low in ("#t", "#true"):
            return True
        if low in ("#f", "#false"):
            return False
        if text.startswith("#:"):
            return Keyword(text[2:])
    return sym(text)


def read(text: str, source: str = "<string>") -> Iterator[Any]:
    """Read the data of a Scheme text one top-level datum at a time (iteratively)."""
    if not isinstance(text, str):
        raise TypeError("Scheme text must be a str")
    if len(text) > MAX_TEXT:
        raise SchemeError("read-error", f"text longer than {MAX_TEXT} characters", 1, 1, source)
    # a frame: [items, line, col, closer-kind, pending prefixes]
    stack: list[list] = []
    line, line_start = 1, 0
    prefixes: list[tuple[str, int, int]] = []  # quote marks waiting for their datum
    skip = 0  # datum comments waiting

    def err(msg: str, ln: int, col: int) -> SchemeError:
        return SchemeError("read-error", msg, ln, col, source)

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
        if kind == "block" or kind == "block2":
            raw = m.group()
            nls = raw.count("\n")
            if nls:
                line += nls
                line_start = start + raw.rfind("\n") + 1
            continue
        if kind == "badblock":
            raise err("unterminated block comment", line, col)
        if kind == "datumc":
            prefixes.append(("#;", line, col))
            continue
        if kind == "quote":
            prefixes.append((m.group(), line, col))
            continue
        if kind == "open" or kind == "vopen":
            if len(stack) >= MAX_NESTING:
                raise err(f"nesting deeper than {MAX_NESTING} levels", line, col)
            stack.append([[], line, col, kind, prefixes])
            prefixes = []
            continue
        if kind == "close":
            if not stack:
                raise err("unexpected ')'", line, col)
            if prefixes:
                raise err("a quote mark with nothing after it", line, col)
            items, fl, fc, okind, prefixes = stack.pop()
            if okind == "vopen":
                value: Any = Vector(items)
            else:
                value = _dotted(items, fl, fc, err)
        elif kind == "string":
            raw = m.group()
            body = raw[1:-1]
            value = _unescape(body) if "\\" in body else body
            nls = raw.count("\n")
            if nls:
                line += nls
                line_start = start + raw.rfind("\n") + 1
        elif kind == "badstring":
            raise err("unterminated string", line, col)
        elif kind == "char":
            name = m.group()[2:]
            if len(name) == 1:
                value = Char(name)
            elif name.lower() in _CHAR_NAMES:
                value = Char(_CHAR_NAMES[name.lower()])
            else:
                raise err(f"unknown character name {shorten(name)!r}", line, col)
        else:
            value = atom_value(m.group())
        # apply the quote marks and datum comments that were waiting for this datum
        while prefixes:
            mark, pl, pc = prefixes.pop()
            if mark == "#;":
                value = _SKIP
                break
            value = Form([sym(_QUOTES[mark]), value], pl, pc)
        if value is _SKIP:
            continue
        if stack:
            stack[-1][0].append(value)
        else:
            yield value
    del skip
    if stack:
        _items, fl, fc, _k, _p = stack[-1]
        raise err("unclosed '(' (missing ')')", fl, fc)
    if prefixes:
        _mark, pl, pc = prefixes[-1]
        raise err("a quote mark with nothing after it", pl, pc)


_SKIP = object()


class Vector(list):
    """``#(...)``: a Scheme vector."""

    __slots__ = ()


def _dotted(items: list, line: int, col: int, err: Callable) -> Any:
    """A read list, or an improper pair when written with a dot."""
    if _DOT in items:
        i = items.index(_DOT)
        if i == 0 or i != len(items) - 2:
            raise err("misplaced '.'", line, col)
        tail = items[-1]
        head = items[:i]
        if isinstance(tail, list) and not isinstance(tail, Vector):
            return Form(head + list(tail), line, col)
        value: Any = tail
        for x in reversed(head):
            value = Pair(x, value)
        value_form = DottedForm(head, tail, line, col)
        value_form.pair = value
        return value_form
    return Form(items, line, col)


class DottedForm(Form):
    """A read ``(a b . c)``: a parameter list with a rest name, or a quoted pair."""

    __slots__ = ("tail", "pair")

    def __init__(self, head: list, tail: Any, line: int, col: int) -> None:
        super().__init__(head, line, col)
        self.tail = tail
        self.pair: Any = None


# ---------------------------------------------------------------------- printing
def is_true(x: Any) -> bool:
    """Scheme truth: everything but #f."""
    return x is not False


def to_text(x: Any, write: bool = True) -> str:
    """``write`` (or with ``write=False``, ``display``) representation of a value."""
    parts: list[str] = []
    _text(x, write, parts, 0)
    return "".join(parts)


def _text(x: Any, write: bool, parts: list[str], depth: int) -> None:  # noqa: C901
    if depth > MAX_NESTING:
        parts.append("...")
        return
    if x is True:
        parts.append("#t")
    elif x is False:
        parts.append("#f")
    elif x.__class__ is Sym:
        parts.append(str.__str__(x))
    elif isinstance(x, Char):
        if write:
            names = {v: k for k, v in _CHAR_NAMES.items()}
            parts.append("#\\" + names.get(str(x), str(x)))
        else:
            parts.append(str(x))
    elif isinstance(x, Keyword):
        parts.append("#:" + str.__str__(x))
    elif isinstance(x, str):
        if write:
            parts.append(
                '"'
                + x.replace("\\", "\\\\")
                .replace('"', '\\"')
                .replace("\n", "\\n")
                .replace("\t", "\\t")
                + '"'
            )
        else:
            parts.append(x)
    elif isinstance(x, float):
        parts.append(_float_text(x))
    elif isinstance(x, int | Fraction):
        parts.append(str(x))
    elif isinstance(x, list):  # a vector (``#(...)``) or a proper list held as one
        parts.append("#(" if isinstance(x, Vector) else "(")
        for i, y in enumerate(x):
            if i:
                parts.append(" ")
            _text(y, write, parts, depth + 1)
        parts.append(")")
    elif isinstance(x, Pair):
        parts.append("(")
        _text(x.car, write, parts, depth + 1)
        y = x.cdr
        while isinstance(y, Pair):
            parts.append(" ")
            _text(y.car, write, parts, depth + 1)
            y = y.cdr
        if isinstance(y, list):
            for z in y:
                parts.append(" ")
                _text(z, write, parts, depth + 1)
        else:
            parts.append(" . ")
            _text(y, write, parts, depth + 1)
        parts.append(")")
    elif x is None or x is UNSPECIFIED:
        parts.append("#<unspecified>")
    else:
        hook = PRINTERS.get(type(x))
        if hook is None:
            for cls, h in PRINTERS.items():
                if isinstance(x, cls):
                    hook = h
                    break
        parts.append(hook(x) if hook is not None else repr(x))


#: type -> text, for values the Scheme layer does not own (atoms, truth values)
PRINTERS: dict[type, Callable[[Any], str]] = {}


def _float_text(x: float) -> str:
    if math.isnan(x):
        return "+nan.0"
    if math.isinf(x):
        return "+inf.0" if x > 0 else "-inf.0"
    if x.is_integer() and abs(x) < 1e21:
        return f"{x:.1f}"
    return repr(x)
