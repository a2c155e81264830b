"""Jason's AgentSpeak syntax read with a lark LALR grammar (``agentspeak.lark``).

The transformer builds terms, plans and compiled bodies while parsing. Variables with
the same name inside one clause (belief, rule, goal or plan) are the same
:class:`~robocog.bdi.terms.Var`; ``_`` is a new variable at each occurrence.

Every failure, whatever the input, is a :class:`ParseError` naming the line and column.
"""

from __future__ import annotations

import re
import threading
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import lark
from lark import Token, Transformer, v_args
from lark.tree import Meta

from robocog.bdi import plans as P
from robocog.bdi.clauses import Program, Rule
from robocog.bdi.er import with_goal_condition, with_subplans
from robocog.bdi.functions import function_directive
from robocog.bdi.namespaces import (
    BEGIN_NS,
    DECLARE_NS,
    DEFAULT_NS,
    END_NS,
    in_namespace,
)
from robocog.bdi.nsterm import NsLiteral
from robocog.bdi.terms import (
    NIL,
    NS_SEP,
    And,
    AnnotTail,
    Arith,
    Body,
    Cons,
    Literal,
    Not,
    Or,
    PlanTerm,
    Rel,
    RuleTerm,
    Term,
    Var,
    sort_annots,
    term_str,
)
from robocog.limits import MESSAGE_CHARS, clip


class ParseError(ValueError):
    """Bad AgentSpeak text; ``line`` and ``column`` are 1-based."""

    def __init__(self, message: str, line: int, column: int, source: str = "") -> None:
        self.line = line
        self.column = column
        self.source = source
        self.reason = message = clip(message, MESSAGE_CHARS)
        where = f"{clip(source, 200)}:" if source else ""
        super().__init__(f"{where}{line}:{column}: {message}")


def _unescape(s: str) -> str:
    out = []
    i = 0
    while i < len(s):
        c = s[i]
        if c == "\\" and i + 1 < len(s):
            n = s[i + 1]
            out.append({"n": "\n", "t": "\t", "r": "\r"}.get(n, n))
            i += 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


class _Builder(Transformer):
    """Builds AgentSpeak objects bottom-up from the parse tree; each method is named
    after the grammar rule it handles (lark's convention)."""

    def __init__(self) -> None:
        super().__init__(visit_tokens=False)
        self.vars: dict[str, Var] = {}
        self.source = ""
        #: the namespace of the ``{ begin namespace(...) }`` block being read, if any
        self.namespace: str | None = None
        self._local_names = 0
        #: the namespace the file is read into (``include(f, ns)``), None for default
        self.file_ns: str | None = None
        #: what ``this_ns`` names here (the file's namespace, or the block's, unmapped)
        self.this_ns: str | None = None
        self.in_block = False
        #: the file's local namespaces: the name written -> the name no other file has
        self.local_ns: dict[str, str] = {}
        self.functions: dict[str, tuple[str, int, str]] = {}  # register_function's

    def _clause_done(self) -> None:
        self.vars = {}

    # ---- items
    def start(self, items: list) -> list:
        return items

    def belief(self, items: list) -> tuple:
        self._clause_done()
        return ("belief", self._ns(items[0]))

    def rule(self, items: list) -> tuple:
        self._clause_done()
        return ("rule", self._ns(Rule(items[0], items[1])))

    def initial_goal(self, items: list) -> tuple:
        self._clause_done()
        return ("goal", self._ns(items[0]))

    def _ns(self, item: Any) -> Any:
        return item if self.namespace is None else in_namespace(item, self.namespace)

    @v_args(meta=True)
    def directive(self, meta: Meta, items: list) -> tuple:
        self._clause_done()
        text = str(items[0])
        m = BEGIN_NS.match(text) or DECLARE_NS.match(text)
        if m is not None:
            if self.in_block:
                raise ValueError("a namespace block inside another")
            name, scope = m.group(1), m.group(2) or "global"
            if scope == "local":
                # a local namespace is the file's own: a name no other file can write
                self._local_names += 1
                self.local_ns[name] = f"#{self._local_names}{name}"
            if m.re is DECLARE_NS:  # ``{ namespace(ns, local) }`` declares, opens nothing
                return ("namespace", None)
            self.namespace, self.this_ns = self.local_ns.get(name, name), name
            self.in_block = True
            return ("namespace", name)
        if END_NS.match(text):
            if not self.in_block:
                raise ValueError("{ end } without { begin namespace(...) }")
            self.namespace = self.this_ns = self.file_ns
            self.in_block = False
            return ("namespace", None)
        try:
            fn = function_directive(text)
        except ValueError as exc:
            raise ParseError(str(exc), meta.line, meta.column, self.source) from None
        if fn is not None:
            self.functions[fn[0]] = fn
            return ("function", fn)
        return ("directive", (text, meta.line, meta.column, self.namespace))

    def directive_body(self, items: list) -> str:
        return str(items[0])

    @v_args(meta=True)
    def plan(self, meta: Meta, items: list) -> tuple:
        self._clause_done()
        label = None
        context = None
        body = None
        trigger = goal_cond = None
        for it in items:
            if isinstance(it, tuple) and it[0] == "label":
                label = it[1]
            elif isinstance(it, tuple) and it[0] == "context":
                context = it[1]
            elif isinstance(it, tuple) and it[0] == "body":
                body = it[1]
            elif isinstance(it, P.Trigger):
                trigger = it
            elif isinstance(it, tuple) and it[0] == "goal_cond":
                goal_cond = it[1]
        line = getattr(meta, "line", 0) if not getattr(meta, "empty", True) else 0
        if self.namespace is not None:
            trigger, context, body = in_namespace((trigger, context, body), self.namespace)
            label = in_namespace(label, self.namespace)  # Jason: a label is in one too
        plan = P.Plan(trigger, context, body, label, self.source, line)
        # Jason's line for a plan (its ``code_line``): the label's, else where the
        # context or the body begins, else the plan's end
        parts = [it[2] for it in items if isinstance(it, tuple) and len(it) == 3 and it[2]]
        end = getattr(meta, "end_line", line)
        plan.code_line = line if label is not None else (parts[0] if parts else end)
        return ("plan", plan if goal_cond is None else with_goal_condition(plan, goal_cond))

    def goal_cond(self, items: list) -> tuple:
        return ("goal_cond", items[0])

    @v_args(meta=True)
    def subplans(self, meta: Meta, items: list) -> tuple:
        # a block of sub-plans belongs to the plan before it
        plans: list = []
        for kind, value in items:
            if kind == "subplans":
                if not plans:
                    msg = "sub-plans in braces must follow a plan"
                    raise ParseError(msg, value[1], value[2], self.source)
                plans[-1] = with_subplans(plans[-1], value[0])
            else:
                plans.append(value)
        return ("subplans", (plans, meta.line, meta.column))

    def label(self, items: list) -> tuple:
        return ("label", items[0])

    def label_var(self, items: list) -> tuple:
        return ("label", self._var(str(items[0])))

    @v_args(meta=True)
    def context(self, meta: Meta, items: list) -> tuple:
        ctx = items[0]
        if ctx.__class__ is Literal and ctx.functor == "true" and not ctx.args:
            ctx = None
        return ("context", ctx, getattr(meta, "line", 0))

    @v_args(meta=True)
    def plan_body(self, meta: Meta, items: list) -> tuple:
        body = items[0]
        if body is not None and body[0].kind == P.ACTION and _is_true(body[0].term):
            body = body[1]  # a plan body's first ``true`` is no formula, as in Jason
        return ("body", body, getattr(meta, "line", 0))

    def trigger(self, items: list) -> P.Trigger:
        op = items[0]
        kind = items[1] if len(items) == 3 else P.BELIEF
        lit = items[-1]
        if isinstance(lit, Token):
            lit = self._var(str(lit))
        return P.Trigger(op, kind, lit)

    def trig_op(self, items: list) -> str:
        return str(items[0])

    def trig_kind(self, items: list) -> str:
        return str(items[0])

    # ---- bodies
    def body(self, items: list) -> P.Chain:
        steps = [s for s in items if s is not None]
        return P.chain(steps)

    def _step(self, kind: int, meta: Meta, term: Term) -> P.Step:
        line = meta.line if not getattr(meta, "empty", True) else 0
        if isinstance(term, Token):
            term = self._var(str(term))
        return P.Step(kind, term, line=line)

    @v_args(meta=True)
    def achieve(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.ACHIEVE_STEP, meta, items[0])

    @v_args(meta=True)
    def achieve_nf(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.ACHIEVE_NF, meta, items[0])

    @v_args(meta=True)
    def test(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.TEST_STEP, meta, items[0])

    @v_args(meta=True)
    def add_plan_step(self, meta: Meta, items: list) -> P.Step:
        return self._add_plan(meta, items[0], "begin")

    @v_args(meta=True)
    def add_plan_end(self, meta: Meta, items: list) -> P.Step:
        return self._add_plan(meta, items[0], "end")

    def _add_plan(self, meta: Meta, plan: PlanTerm, where: str) -> P.Step:
        # Jason reads ``+{ plan }`` as ``.add_plan(plan, self, begin)``
        lit = Literal(".add_plan", (plan, Literal("self"), Literal(where)))
        return self._step(P.INTERNAL, meta, lit)

    @v_args(meta=True)
    def del_plan_step(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.INTERNAL, meta, Literal(".remove_plan", (items[0],)))

    def plan_term_add(self, items: list, op: str = "+") -> PlanTerm:
        return self.plan_term([self.trigger([op, items[0]]), *items[1:]])

    def plan_term_del(self, items: list) -> PlanTerm:
        return self.plan_term_add(items, "-")

    @v_args(meta=True)
    def add_bel(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.ADD_BEL, meta, items[0])

    @v_args(meta=True)
    def add_bel_nf(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.ADD_BEL_NF, meta, items[0])

    @v_args(meta=True)
    def add_bel_end(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.ADD_BEL_END, meta, items[0])

    @v_args(meta=True)
    def del_bel(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.DEL_BEL, meta, items[0])

    @v_args(meta=True)
    def del_bel_nf(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.DEL_BEL_NF, meta, items[0])

    @v_args(meta=True)
    def del_add_bel(self, meta: Meta, items: list) -> P.Step:
        return self._step(P.DEL_ADD_BEL, meta, items[0])

    @v_args(meta=True)
    def formula(self, meta: Meta, items: list) -> P.Step | None:
        t = items[0]
        c = t.__class__
        if c is Literal:
            # ``true`` anywhere but first in a plan's body is an environment action,
            # as Jason reads it
            # ``.print`` and ``mylib.act`` (a library's) are internal actions, as in Jason
            kind = P.INTERNAL if "." in t.functor else P.ACTION
            return self._step(kind, meta, t)
        if c is Var:
            return self._step(P.ACTION, meta, t)
        return self._step(P.CONSTRAINT, meta, t)

    @v_args(meta=True)
    def fork_and(self, meta: Meta, items: list) -> P.Step:
        return self._fork("and", meta, items)

    @v_args(meta=True)
    def fork_or(self, meta: Meta, items: list) -> P.Step:
        return self._fork("or", meta, items)

    def _fork(self, how: str, meta: Meta, items: list) -> P.Step:
        line = meta.line if not getattr(meta, "empty", True) else 0
        branches = tuple(None if st is None else (st, None) for st in items)
        return P.Step(P.FORK, how, branches, line=line)

    @v_args(meta=True)
    def if_stmt(self, meta: Meta, items: list) -> P.Step:
        cond, then = items[0], items[1]
        branches = [(cond, then)]
        orelse = None
        for it in items[2:]:
            if it[0] == "elif":
                branches.append((it[1], it[2]))
            else:
                orelse = it[1]
        line = meta.line if not getattr(meta, "empty", True) else 0
        return P.Step(P.IF, cond, tuple(branches), line=line, state=orelse)

    def elif_part(self, items: list) -> tuple:
        return ("elif", items[0], items[1])

    def else_part(self, items: list) -> tuple:
        return ("else", items[0])

    @v_args(meta=True)
    def while_stmt(self, meta: Meta, items: list) -> P.Step:
        line = meta.line if not getattr(meta, "empty", True) else 0
        return P.Step(P.WHILE, items[0], (items[1],), line=line)

    @v_args(meta=True)
    def for_stmt(self, meta: Meta, items: list) -> P.Step:
        line = meta.line if not getattr(meta, "empty", True) else 0
        return P.Step(P.FOR, items[0], (items[1],), line=line)

    # ---- formulas
    def or_(self, items: list) -> Or:
        return Or(items[0], items[1])

    def and_(self, items: list) -> And:
        return And(items[0], items[1])

    def not_(self, items: list) -> Not:
        return Not(items[0])

    def rel(self, items: list) -> Rel:
        return Rel(items[1], items[0], items[2])

    def relop(self, items: list) -> str:
        return str(items[0])

    def addop(self, items: list) -> str:
        return str(items[0])

    def mulop(self, items: list) -> str:
        return str(items[0])

    def arith(self, items: list) -> Term:
        if len(items) == 2:
            left, op, right = items[0], "**", items[1]
        else:
            left, op, right = items
        return Arith(op, left, right)

    def neg(self, items: list) -> Term:
        x = items[0]
        if x.__class__ is int or x.__class__ is float:
            return -x
        return Arith("-", x)

    # ---- terms
    def number(self, items: list) -> int | float:
        s = str(items[0])
        if "." in s or "e" in s or "E" in s:
            return float(s)
        return int(s)

    def string(self, items: list) -> str:
        return _unescape(str(items[0])[1:-1])

    def _var(self, name: str) -> Var:
        v = self.vars.get(name)
        if v is None:
            v = self.vars[name] = Var(name)
        return v

    def var(self, items: list) -> Var:
        return self._var(str(items[0]))

    def unnamed(self, items: list) -> Var:
        return Var("_")

    def var_annots(self, items: list) -> Var:
        return self._var(str(items[0]))

    def plan_term(self, items: list) -> PlanTerm:
        label = context = body = trigger = None
        if isinstance(items[0], str):  # { +!g ... }: the trigger's parts, unassembled
            items = [self.trigger(items[:3]), *items[3:]]
        for it in items:
            if isinstance(it, tuple) and it[0] == "label":
                label = it[1]
            elif isinstance(it, tuple) and it[0] == "context":
                context = it[1]
            elif isinstance(it, tuple) and it[0] == "body":
                body = it[1]
            elif isinstance(it, P.Trigger):
                trigger = it
        plan = P.Plan(trigger, context, body, label, self.source, 0)
        lab = f"@{term_str(label)} " if label is not None else ""
        ctx = f" : {term_str(context)}" if context is not None else ""
        steps = "; ".join(repr(st) for st in P.chain_steps(body)) if body is not None else ""
        return PlanTerm(plan, f"{lab}{trigger!r}{ctx}" + (f" <- {steps}" if steps else ""))

    def rule_term(self, items: list) -> RuleTerm:
        return RuleTerm(items[0], items[1])

    def body_term(self, items: list) -> Body:
        return Body(tuple(P.chain_steps(items[0])))

    def functor(self, items: list) -> str:
        s = str(items[0])
        if s.startswith("'"):
            s = s[1:-1]
        return s

    def literal(self, items: list) -> Literal:
        neg = False
        i = 0
        ns = ns_var = None
        if isinstance(items[0], Token) and items[0].type in ("ATOM", "VAR", "NSSEP"):
            if items[0].type == "NSSEP":  # ``::b``: the namespace of the file or block
                ns = self.this_ns or DEFAULT_NS
            elif items[0].type == "VAR":
                ns_var = self._var(str(items[0]))
            else:
                ns = str(items[0]).strip("'")
                ns = (self.this_ns or DEFAULT_NS) if ns == "this_ns" else ns
            ns = self.local_ns.get(ns, ns) if ns is not None else None
            i = 1 if items[0].type == "NSSEP" else 2
        if isinstance(items[i], Token) and items[i].type == "NEG":
            neg = True
            i += 1
        functor = items[i]
        if ns is not None and (ns != DEFAULT_NS or self.namespace is not None):
            # an explicit ``default::`` matters only inside a namespace block, where
            # it keeps the literal out of the block's namespace (see in_namespace)
            functor = f"{ns}{NS_SEP}{functor}"
        args: tuple = ()
        annots: tuple = ()
        for it in items[i + 1 :]:
            if isinstance(it, tuple) and it and it[0] == "args":
                args = it[1]
            elif isinstance(it, tuple) and it and it[0] == "annots":
                annots = sort_annots(it[1])
        lit = Literal(functor, args, annots, neg)
        if ns_var is not None:
            return NsLiteral(ns_var, lit)
        if functor == "this_ns" and not args and not annots and not neg and ns is None:
            return Literal(self.this_ns or DEFAULT_NS)  # Jason: the namespace it is read in
        fn = self.functions.get(functor)
        if (
            not neg
            and not annots
            and (
                (fn is not None and fn[1] == len(args))
                or functor.startswith("math.")
                or (functor in (".length", ".count") and len(args) == 1)
                or (functor == "system.time" and not args)
            )
        ):
            return Arith("call", lit)
        return lit

    def args(self, items: list) -> tuple:
        # an argument is a term, never moved into a namespace: ``default::k`` is ``k``
        return ("args", tuple(_plain_default(x) for x in items if x is not None))

    def annot_tail(self, items: list) -> AnnotTail:
        name = str(items[0])
        return AnnotTail(Var("_") if name == "_" else self._var(name))

    def annots(self, items: list) -> tuple:
        return ("annots", tuple(x for x in items if x is not None))

    def empty_list(self, items: list) -> Term:
        return NIL

    def list(self, items: list) -> Term:
        elems = items[0]
        tail = items[1] if len(items) > 1 else NIL
        out = tail
        for e in reversed(elems):
            out = Cons(e, out)
        return out

    def list_items(self, items: list) -> list:
        return items


def _plain_default(t: Term) -> Term:
    if t.__class__ is Literal and t.functor.startswith(_DEFAULT_PREFIX):
        return Literal(t.functor[len(_DEFAULT_PREFIX) :], t.args, t.annots, t.neg)
    return t


_DEFAULT_PREFIX = DEFAULT_NS + NS_SEP


def _is_true(t: Term) -> bool:
    return t.__class__ is Literal and t.functor == "true" and not t.args and not t.neg


_GRAMMAR = Path(__file__).with_name("agentspeak.lark")
_lock = threading.Lock()
_parsers: dict[str, tuple[lark.Lark, _Builder]] = {}


def _parser() -> tuple[lark.Lark, _Builder]:
    got = _parsers.get("lalr")
    if got is None:
        builder = _Builder()
        p = lark.Lark(
            _GRAMMAR.read_text(encoding="utf-8"),
            parser="lalr",
            start=["start", "term_entry"],
            propagate_positions=True,
            maybe_placeholders=False,
            cache=True,
        )
        got = _parsers["lalr"] = (p, builder)
    return got


def _position(text: str, pos: int) -> tuple[int, int]:
    line = text.count("\n", 0, pos) + 1
    col = pos - (text.rfind("\n", 0, pos) + 1) + 1
    return line, col


def _describe(exc: lark.exceptions.UnexpectedInput) -> str:
    if isinstance(exc, lark.exceptions.UnexpectedEOF):
        return "unexpected end of input"
    if isinstance(exc, lark.exceptions.UnexpectedToken):
        tok = exc.token
        if tok.type == "$END":
            return "unexpected end of input"
        text = str(tok).split()[0] if str(tok).split() else str(tok)
        return f"unexpected {text[:20]!r}"
    if isinstance(exc, lark.exceptions.UnexpectedCharacters):
        ch = exc.char if hasattr(exc, "char") else "?"
        return f"unexpected character {ch!r}"
    return "syntax error"


#: the longest line the reader takes; a string literal cannot span lines, so this bounds
#: every literal (a 10 MB one would otherwise take gigabytes in the lexer)
MAX_LINE_CHARS = 1024 * 1024


def _run(start: str, text: str, source: str, namespace: str | None = None):  # noqa: ANN202 - parse result
    if not isinstance(text, str):
        raise ParseError("source text must be a string", 1, 1, source)
    if len(text) > MAX_LINE_CHARS:
        for number, line in enumerate(text.split("\n"), start=1):
            if len(line) > MAX_LINE_CHARS:
                raise ParseError(f"line longer than {MAX_LINE_CHARS} characters", number, 1, source)
    with _lock:
        parser, builder = _parser()
        builder.vars = {}
        builder.source = source
        builder.namespace = builder.file_ns = builder.this_ns = namespace
        builder.in_block = False
        builder.local_ns = {}
        builder.functions = {}
        try:
            tree = parser.parse(text, start=start)
            return builder.transform(tree)
        except lark.exceptions.UnexpectedInput as exc:
            line, col = getattr(exc, "line", -1), getattr(exc, "column", -1)
            at_end = isinstance(exc, lark.exceptions.UnexpectedEOF) or (
                isinstance(exc, lark.exceptions.UnexpectedToken) and exc.token.type == "$END"
            )
            if at_end or not isinstance(line, int) or line < 1:
                line, col = _position(text, len(text))
            raise ParseError(_describe(exc), line, col, source) from None
        except RecursionError:
            raise ParseError("nesting too deep", 1, 1, source) from None
        except lark.exceptions.VisitError as exc:
            inner = exc.orig_exc
            if isinstance(inner, ParseError):
                raise inner from None
            if isinstance(inner, RecursionError):
                raise ParseError("nesting too deep", 1, 1, source) from None
            raise ParseError(f"malformed input ({inner})", 1, 1, source) from None
        except lark.exceptions.LarkError as exc:
            raise ParseError(f"syntax error ({exc.__class__.__name__})", 1, 1, source) from None
        except (ValueError, TypeError, AttributeError, IndexError) as exc:
            raise ParseError(f"malformed input ({exc})", 1, 1, source) from None
        finally:
            builder.vars = {}


#: how deep includes may nest before the reader refuses (a file including itself, say)
MAX_INCLUDE_DEPTH = 32
_INCLUDE = re.compile(r'\s*include\s*\(\s*"((?:[^"\\]|\\.)*)"\s*(?:,\s*(\w+)\s*)?\)\s*\Z')


#: the longest program (one file) the reader takes: an agent's program is a few
#: kilobytes, and the parser reads a dense one of this size in about a second (time
#: grows with the size; a megabyte would take half a minute)
MAX_PROGRAM_CHARS = 64 * 1024


def parse_program(
    text: str,
    source: str = "",
    search_path: Sequence[str | Path] = (),
    _depth: int = 0,
    namespace: str | None = None,
) -> Program:
    """Parse a whole ``.asl`` program.

    ``{ include("f.asl") }`` reads ``f.asl`` where it stands, as Jason does: relative to
    the including file's folder first, then to each folder of ``search_path`` (a
    project's ``aslSourcePath``). A file that is not found, or a directive robocog does
    not know, is an error naming it, so nothing goes missing without a word.
    """
    if isinstance(text, str) and len(text) > MAX_PROGRAM_CHARS:
        for number, line in enumerate(text.split("\n"), start=1):
            if len(line) > MAX_LINE_CHARS:  # (the more precise error first)
                raise ParseError(f"line longer than {MAX_LINE_CHARS} characters", number, 1, source)
        raise ParseError(
            f"a program is at most {MAX_PROGRAM_CHARS} characters (MAX_PROGRAM_CHARS); "
            f"this one has {len(text)}",
            1,
            1,
            source,
        )
    items = _run("start", text, source, None if namespace == DEFAULT_NS else namespace)
    prog = Program()
    for kind, value in items:
        if kind == "belief":
            prog.beliefs.append(value)
        elif kind == "rule":
            prog.beliefs.append(value)
        elif kind == "goal":
            prog.goals.append(value)
        elif kind == "plan":
            prog.plans.append(value)
        elif kind == "function":
            prog.functions[value[0]] = value
        elif kind == "namespace":
            continue
        elif kind == "subplans":
            subs, line, column = value
            if not prog.plans:
                raise ParseError("sub-plans in braces must follow a plan", line, column, source)
            prog.plans[-1] = with_subplans(prog.plans[-1], subs)
        elif kind == "directive":
            body, line, column, here = value
            included = _include(body, line, column, source, search_path, _depth, here)
            prog.beliefs += included.beliefs
            prog.goals += included.goals
            prog.plans += included.plans
            prog.functions.update(included.functions)
    return prog


def _include(
    body: str,
    line: int,
    column: int,
    source: str,
    search_path: Sequence[str | Path],
    depth: int,
    ns_here: str | None = None,
) -> Program:
    """The program an ``include`` directive names, read into its namespace (by default
    the one the directive stands in)."""
    m = _INCLUDE.match(body)
    if m is None:
        text = " ".join(body.split())
        shown = text if len(text) <= 60 else text[:57] + "..."
        raise ParseError(f"not supported: directive {{ {shown} }}", line, column, source)
    if depth >= MAX_INCLUDE_DEPTH:
        raise ParseError(f"includes nested deeper than {MAX_INCLUDE_DEPTH}", line, column, source)
    name = m.group(1).replace('\\"', '"')
    here = Path(source).parent if source else Path(".")
    candidates = [here / name, *(Path(d) / name for d in search_path)]
    if Path(name).is_absolute():
        candidates = [Path(name)]
    for path in candidates:
        try:
            found = path.is_file()
        except OSError:  # a name too long for the file system, say: no such file
            found = False
        if found:
            # ``include("f.asl", ns)``: the file read as if in a block of ns, as Jason does
            text = read_source(path)
            return parse_program(text, str(path), search_path, depth + 1, m.group(2) or ns_here)
    looked = ", ".join(str(c) for c in candidates)
    raise ParseError(
        f"include: no file {clip(name)!r} (looked at {clip(looked, 300)})", line, column, source
    )


#: the largest source file the reader takes (a program is text a person wrote)
MAX_SOURCE_BYTES = 16 * 1024 * 1024


def read_source(path: str | Path) -> str:
    """An ``.asl`` file's text; a file that is too large or not UTF-8 is a ParseError."""
    p = Path(path)
    try:
        data = p.read_bytes()
    except OSError as exc:
        raise ParseError(f"cannot read {p}: {exc.strerror}", 1, 1, str(p)) from None
    if len(data) > MAX_SOURCE_BYTES:
        raise ParseError(f"larger than {MAX_SOURCE_BYTES} bytes", 1, 1, str(p))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        prefix = data[: exc.start].decode("utf-8", "replace")
        line, col = _position(prefix, len(prefix))
        raise ParseError("not valid UTF-8", line, col, str(p)) from None


def parse_file(path: str | Path) -> Program:
    """Parse a program from a file; the file name is used in error messages."""
    return parse_program(read_source(path), str(path))


def parse_term(text: str) -> Term:
    """Parse one term or logical formula, e.g. ``"p(X) & X > 2"``."""
    return _run("term_entry", text, "")


def parse_literal(text: str) -> Literal:
    """Parse one literal, e.g. ``"at(room1)[source(percept)]"``."""
    t = parse_term(text)
    if t.__class__ is not Literal:
        raise ParseError(f"not a literal: {text!r}", 1, 1)
    return t


def parse_plan(text: str, source: str = "") -> P.Plan:
    """Parse one plan (with or without the final dot)."""
    text = text.strip()
    if not text.endswith("."):
        text += "."
    prog = parse_program(text, source)
    if len(prog.plans) != 1 or prog.beliefs or prog.goals:
        raise ParseError("expected exactly one plan", 1, 1, source)
    return prog.plans[0]
