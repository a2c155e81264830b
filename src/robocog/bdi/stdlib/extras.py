"""The rest of Jason's library: ``.asserta``/``.assertz``, ``.puts``, ``.printf``,
``.prefix``/``.suffix``/``.sublist``, ``.replace``, ``.copy_term``, ``.add_annot``, ``.eval``,
``.shuffle``, ``.set_random_seed``, ``.drop_event``."""

from __future__ import annotations

import random
import zlib
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from robocog.bdi import plans as P
from robocog.bdi.logic import ActionError
from robocog.bdi.stdlib.base import (
    arg_list,
    arg_number,
    arg_text,
    belief_event,
    bind,
    bind_each,
    internal,
    need_args,
    unifies,
)
from robocog.bdi.terms import (
    NIL,
    NS_SEP,
    Literal,
    Term,
    Var,
    is_list,
    iter_list,
    make_list,
    print_str,
)
from robocog.bdi.unifier import resolve, undo

if TYPE_CHECKING:
    from robocog.bdi.agent import Agent


@internal("asserta")
def _asserta(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "asserta")
    return _assert(ag, resolve(args[0], s), at_end=False)


@internal("assertz")
def _assertz(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "assertz")
    return _assert(ag, resolve(args[0], s), at_end=True)


def _assert(ag: Agent, lit: Term, at_end: bool) -> bool:
    from robocog.bdi.terms import SOURCE_SELF

    if lit.__class__ is not Literal:
        raise ActionError("assert: argument must be a literal")
    if not lit.sources():
        lit = lit.add_annots((SOURCE_SELF,))
    if ag.bb.add(lit, at_end=at_end) is not None:
        ag.post(belief_event("+", P.BELIEF, lit))
    return True


@internal("puts")
def _puts(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    import re

    need_args(args, 1, "puts", 2)
    text = resolve(args[0], s)
    if text.__class__ is not str:
        raise ActionError(".puts expects a string")
    values = {v.name: v for v in s if v.__class__ is Var}

    def sub(m: re.Match) -> str:
        from robocog.bdi.parser import ParseError, parse_term

        src = m.group(1)
        try:
            t = parse_term(src)
        except ParseError:
            return m.group(0)
        from robocog.bdi.unifier import variables

        mapping = {v: values[v.name] for v in variables(t) if v.name in values}
        t = resolve(resolve(t, mapping), s)
        return print_str(t)

    out = re.sub(r"#\{([^}]*)\}", sub, text)
    if len(args) > 1:
        return bind(out, args[1], s, trail)
    ag.print(out)
    return True


#: the widest field .printf pads to (a huge width would allocate gigabytes)
MAX_FORMAT_WIDTH = 10_000
#: how long a regular expression of .replace may run before it is stopped
REGEX_SECONDS = 1.0


@internal("printf")
def _printf(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    import re

    if not args:
        raise ActionError(".printf needs a format")
    fmt = resolve(args[0], s)
    if fmt.__class__ is not str:
        raise ActionError(".printf: the format must be a string")
    vals = [resolve(a, s) for a in args[1:]]
    k = 0

    def sub(m: re.Match) -> str:
        nonlocal k
        spec = m.group(0)
        if spec == "%%":
            return "%"
        if spec == "%n":
            return "\n"
        if k >= len(vals):
            raise ActionError(".printf: not enough arguments")
        v = vals[k]
        k += 1
        conv = spec[-1]
        sizes = [int(n) for n in re.findall(r"\d+", spec)]
        if any(n > MAX_FORMAT_WIDTH for n in sizes):
            raise ActionError(f".printf: a width or precision over {MAX_FORMAT_WIDTH} in {spec}")
        try:
            if conv == "s":
                return spec % print_str(v)
            if conv == "d":
                return spec % int(v)
            if conv in "feg":
                return spec % float(v)
        except (TypeError, ValueError) as exc:
            raise ActionError(f".printf: {exc}") from exc
        return spec

    ag.print(re.sub(r"%[-#+ 0,(]*\d*(?:\.\d+)?[sdfegn%]", sub, fmt))
    return True


def _sublists(items: list) -> Iterator[Term]:
    for i in range(len(items)):
        for j in range(len(items), i, -1):
            yield make_list(items[i:j])
    yield NIL


@internal("prefix")
def _prefix(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 2, "prefix")
    v = resolve(args[1], s)
    if v.__class__ is str:
        return bind_each((v[:j] for j in range(len(v), -1, -1)), args[0], s, trail)
    items = arg_list(v, s, "prefix")
    return bind_each((make_list(items[:j]) for j in range(len(items), -1, -1)), args[0], s, trail)


@internal("suffix")
def _suffix(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 2, "suffix")
    v = resolve(args[1], s)
    if v.__class__ is str:
        return bind_each((v[j:] for j in range(len(v) + 1)), args[0], s, trail)
    items = arg_list(v, s, "suffix")
    return bind_each((make_list(items[j:]) for j in range(len(items) + 1)), args[0], s, trail)


@internal("sublist")
def _sublist(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    need_args(args, 2, "sublist")
    return bind_each(_sublists(arg_list(args[1], s, "sublist")), args[0], s, trail)


@internal("replace")
def _replace(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    """``.replace(S, Regex, New, R)``, with Java's regular expressions; a pattern that
    backtracks for longer than REGEX_SECONDS is stopped with an error."""
    import regex

    need_args(args, 4, "replace")
    text = arg_text(args[0], s)
    pattern = arg_text(args[1], s)
    repl = arg_text(args[2], s)
    try:
        out = regex.sub(pattern, repl.replace("\\", "\\\\"), text, timeout=REGEX_SECONDS)
    except regex.error as exc:
        raise ActionError(f".replace: {exc}") from exc
    except TimeoutError as exc:
        raise ActionError(f".replace: the pattern ran longer than {REGEX_SECONDS} s") from exc
    return bind(out, args[3], s, trail)


@internal("copy_term")
def _copy_term(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "copy_term")
    return bind(resolve(args[0], s, {}), args[1], s, trail)


@internal("add_annot")
def _add_annot(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 3, "add_annot")
    t = resolve(args[0], s)
    a = resolve(args[1], s)
    if t.__class__ is Literal:
        extra = list(iter_list(a)) if is_list(a) else [a]
        t = t.add_annots(extra)
    elif is_list(t):
        extra = list(iter_list(a)) if is_list(a) else [a]
        t = make_list([x.add_annots(extra) if x.__class__ is Literal else x for x in iter_list(t)])
    return bind(t, args[2], s, trail)


@internal("eval")
def _eval(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "eval")
    from robocog.bdi.logic import holds

    mark = len(trail)
    ok = holds(ag, args[1], s, trail)
    undo(s, trail, mark)
    return bind(Literal("true" if ok else "false"), args[0], s, trail)


@internal("shuffle")
def _shuffle(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 2, "shuffle")
    items = arg_list(args[0], s, "shuffle")
    rng = getattr(ag, "rng", None)
    if rng is None:
        # each agent its own sequence (agents from one program differ), reproducible
        rng = ag.rng = random.Random(zlib.crc32(ag.name.encode()))
    rng.shuffle(items)
    return bind(make_list(items), args[1], s, trail)


@internal("set_random_seed")
def _set_random_seed(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "set_random_seed")
    ag.rng = random.Random(int(arg_number(args[0], s, "set_random_seed")))
    return True


@internal("drop_event")
def _drop_event(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> bool:
    need_args(args, 1, "drop_event")
    goal = resolve(args[0], s)
    ag.C.keep_events(lambda e: not (e.intention is None and unifies(goal, e.trigger.literal)))
    return True


@internal("namespace")
def _namespace(ag: Agent, args: tuple, s: dict, trail: list, ctx: Any) -> Iterator[None]:
    """``.namespace(NS)``: each namespace the agent knows (Jason's ``kqml`` and
    ``default`` first, then those of its beliefs and plans as they were met); local
    namespaces are the file's own and are not listed."""
    need_args(args, 1, "namespace")
    names = ["kqml", "default"]
    found = [b.functor for b in ag.bb] + [
        p.trigger.literal.functor
        for p in ag.pl
        if p.trigger is not None and p.trigger.literal.__class__ is Literal
    ]
    for f in found:
        ns, sep, _name = f.rpartition(NS_SEP)
        if sep and not ns.startswith("#") and ns not in names:
            names.append(ns)
    return bind_each((Literal(n) for n in names), args[0], s, trail)
