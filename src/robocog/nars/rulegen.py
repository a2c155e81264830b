"""The generator of ``matchers.py``: a straight-line matcher for each row of the rule
table (:data:`~robocog.nars.rules.RULES`).

A matcher written out per rule tests the premises' connectors and components one by one,
with the pattern's variables as locals, and builds the conclusion directly: what the
generic :func:`~robocog.nars.rules.match` and :func:`~robocog.nars.rules.build` do,
without their recursion and dictionary of bindings. The matchers are generated into a
module that is checked in rather than made at import, so that the compiled engine
compiles them too (the rules run for every premise pair of every cycle).
``tools/nars_rule_matchers.py`` writes the module; a test fails while it differs from
what :func:`matcher_source` makes of the table. This module is not part of the engine
at run time.
"""

from __future__ import annotations

from .narsese import parse_pattern
from .rules import REDUCED_OPS, RULES, is_pattern_variable
from .terms import Term

#: the module the matchers are generated into, beside this one
MATCHERS_MODULE = "matchers.py"

_HEADER = '''"""The rule table's matchers: one straight-line function per row of ``rules.RULES``.

GENERATED from the rule table by ``rulegen.matcher_source()``: do not edit. After a
change to the table, ``python tools/nars_rule_matchers.py`` writes this file again;
tests/nars/test_rule_matchers.py fails while it does not match the table.

Each function matches the premises ``t1`` and ``t2`` against its rule's patterns, with
no recursion and no dictionary of bindings (a pattern variable is a local), and hands
the conclusion, its truth and whether variables are to be introduced to ``emit``. As a
module rather than code made at import, it is compiled with the rest of the engine.
"""

from __future__ import annotations

from . import truth as tf
from .rules import Emit, make
from .terms import Term, {terms}
from .truth import Truth
'''


def _quoted(text: str) -> str:
    """``text`` as a Python string literal in double quotes."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


class _Matcher:
    """The body of one matcher, written line by line."""

    def __init__(self, index: int, patterns: list[Term]) -> None:
        self.index = index
        self.lines: list[str] = []
        self.bound: set[str] = set()
        self.consts: dict[str, str] = {}
        self.count = 0
        # a variable named once in the premises and not in the conclusion is not bound
        self.mentions: dict[Term, int] = {}
        for p in patterns:
            for a in p.atoms():
                self.mentions[a] = self.mentions.get(a, 0) + 1

    def local(self, prefix: str) -> str:
        self.count += 1
        return f"{prefix}{self.count}"

    def const(self, p: Term) -> str:
        return self.consts.setdefault(str(p), f"_k{self.index}_{len(self.consts)}")

    @staticmethod
    def name(p: Term) -> str:
        """A pattern variable's local: its letter (but for names ruff finds ambiguous)."""
        letter = p.name or ""
        return f"v_{letter}" if letter in ("I", "O", "l") else letter

    def match(self, p: Term, expr: str) -> None:
        """Checks that ``expr`` matches ``p``, binding its variables, in the order the
        generic ``match`` visits them."""
        add = self.lines.append
        if p.op is None:
            if not is_pattern_variable(p):
                add(f"if {expr} is not {self.const(p)}:")
                add("    return")
            elif self.name(p) in self.bound:
                add(f"if {expr} is not {self.name(p)}:")
                add("    return")
            elif self.mentions[p] > 1:
                add(f"{self.name(p)}: Term = {expr}")
                self.bound.add(self.name(p))
            return
        if not expr.isidentifier():
            x = self.local("x")
            add(f"{x}: Term = {expr}")
            expr = x
        add(f"if {expr}.op != {_quoted(p.op)} or len({expr}.args) != {len(p.args)}:")
        add("    return")
        a = self.local("a")
        add(f"{a} = {expr}.args")
        for i, arg in enumerate(p.args):
            self.match(arg, f"{a}[{i}]")

    def build(self, p: Term) -> str:
        """Builds the conclusion bottom-up into locals, making its terms in the order
        the generic ``build`` makes them; returns the expression of ``p``."""
        if p.op is None:
            return self.name(p) if is_pattern_variable(p) else self.const(p)
        parts = [self.build(arg) for arg in p.args]
        inner = ", ".join(parts) + ("," if len(parts) == 1 else "")
        k = self.local("k")
        if p.op in REDUCED_OPS:
            self.lines.append(f"{k} = make({_quoted(p.op)}, ({inner}))")
        else:  # ``make`` would only forward it
            self.lines.append(f"{k} = compound({_quoted(p.op)}, ({inner}))")
        return k


def _function(index: int, row: tuple[str, str | None, str, str, bool, int]) -> str:
    """The source of the matcher of row ``index`` of the table."""
    p1, p2, c, fn, var_intro, level = row
    premise1 = parse_pattern(p1)
    premise2 = parse_pattern(p2) if p2 else None
    conclusion = parse_pattern(c)
    m = _Matcher(index, [x for x in (premise1, premise2, conclusion) if x is not None])
    m.match(premise1, "t1")
    if premise2 is not None:
        m.match(premise2, "t2")
    result = m.build(conclusion)
    m.lines.append(f"emit({result}, tf.{fn}(v1, v2), {var_intro})")
    premises = p1 if p2 is None else f"{p1}, {p2}"
    doc = f"{premises} |- {c} ({fn}, NAL-{level})".replace("\\", "\\\\")
    consts = [f"{k} = atom({_quoted(text)})\n" for text, k in m.consts.items()]
    return (
        "\n\n"
        + ("".join(consts) + "\n\n" if consts else "")
        + f"def r{index}(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:\n"
        + f'    """{doc}"""\n'
        + "".join(f"    {x}\n" for x in m.lines)
    )


def matcher_source() -> str:
    """The text of :data:`MATCHERS_MODULE`, generated from the rule table."""
    body = "".join(_function(i, row) for i, row in enumerate(RULES))
    terms = "atom, compound" if "= atom(" in body else "compound"  # atom for constants
    table = "".join(f"    r{i},\n" for i in range(len(RULES)))
    return (
        _HEADER.format(terms=terms)
        + body
        + "\n\n#: the matcher of each row of the rule table, in the table's order\n"
        + f"MATCHERS = (\n{table})\n"
    )
