"""A small s-expression reader for the planner's Atomese rules and for PDDL.

Both languages are parenthesised lists of symbols and strings; the planner needs only
that tree plus the line and column of every element so that a bad rule file or a bad
PDDL task is reported where the mistake is.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from robocog.limits import MESSAGE_CHARS, clip

#: how deep lists may nest: the readers above walk them recursively, and no domain,
#: problem or rule file a person writes comes near it
MAX_DEPTH = 200


class SexprError(ValueError):
    """Malformed s-expression input, with the line and column (1-based) of the fault."""

    def __init__(self, message: str, line: int, column: int, source: str = "<input>") -> None:
        super().__init__(f"{clip(source)}:{line}:{column}: {clip(message, MESSAGE_CHARS)}")
        self.line = line
        self.column = column
        self.source = source


@dataclass(frozen=True)
class Symbol:
    """A bare word (``pick-up``, ``?x``, ``ConceptNode``) and where it was read."""

    name: str
    line: int = field(default=0, compare=False)
    column: int = field(default=0, compare=False)


@dataclass(frozen=True)
class String:
    """A double-quoted string and where it was read."""

    value: str
    line: int = field(default=0, compare=False)
    column: int = field(default=0, compare=False)


@dataclass(frozen=True)
class SList:
    """A parenthesised list and the position of its opening parenthesis."""

    items: tuple[Symbol | String | SList, ...]
    line: int = field(default=0, compare=False)
    column: int = field(default=0, compare=False)

    def head(self) -> str:
        """The lower-cased name of the first element if it is a symbol, else ''."""
        if self.items and isinstance(self.items[0], Symbol):
            return self.items[0].name.lower()
        return ""


Sexpr = Symbol | String | SList


def parse(text: str, source: str = "<input>") -> list[Sexpr]:
    """Read every top-level expression of *text*; ``;`` starts a comment to end of line."""
    stack: list[tuple[list[Sexpr], int, int]] = [([], 0, 0)]
    i, line, col, n = 0, 1, 1, len(text)
    while i < n:
        ch = text[i]
        if ch == "\n":
            i, line, col = i + 1, line + 1, 1
            continue
        if ch.isspace():
            i, col = i + 1, col + 1
            continue
        if ch == ";":
            while i < n and text[i] != "\n":
                i += 1
            continue
        if ch == "(":
            if len(stack) > MAX_DEPTH:
                raise SexprError(
                    f"lists nested deeper than {MAX_DEPTH} (MAX_DEPTH)", line, col, source
                )
            stack.append(([], line, col))
            i, col = i + 1, col + 1
            continue
        if ch == ")":
            if len(stack) == 1:
                raise SexprError("unexpected ')'", line, col, source)
            items, l0, c0 = stack.pop()
            stack[-1][0].append(SList(tuple(items), l0, c0))
            i, col = i + 1, col + 1
            continue
        if ch == '"':
            l0, c0 = line, col
            j = i + 1
            chars: list[str] = []
            while j < n and text[j] != '"':
                if text[j] == "\\" and j + 1 < n:
                    j += 1
                if text[j] == "\n":
                    line, col = line + 1, 0
                chars.append(text[j])
                j += 1
                col += 1
            if j >= n:
                raise SexprError("unterminated string", l0, c0, source)
            stack[-1][0].append(String("".join(chars), l0, c0))
            col += 2
            i = j + 1
            continue
        j = i
        while j < n and not text[j].isspace() and text[j] not in '();"':
            j += 1
        stack[-1][0].append(Symbol(text[i:j], line, col))
        col += j - i
        i = j
    if len(stack) > 1:
        _, l0, c0 = stack[-1]
        raise SexprError("'(' is never closed", l0, c0, source)
    return stack[0][0]


def render(expr: Sexpr) -> str:
    """Write *expr* back as text (strings quoted); parse(render(e)) == [e]."""
    if isinstance(expr, Symbol):
        return expr.name
    if isinstance(expr, String):
        escaped = expr.value.replace("\\", "\\\\").replace('"', '\\"')
        return f'"{escaped}"'
    return "(" + " ".join(render(item) for item in expr.items) + ")"
