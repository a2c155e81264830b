"""PDDL in and out: STRIPS domains with typing (the 4-operator blocks world) and problems.

``read_domain`` and ``read_problem`` parse the text into plain data, ``ground`` turns a
domain and a problem into a ``Task`` that the same searches run on, and
``write_problem`` writes a problem from a state (a PDDL task's state, or the planner's
scene in the blocks vocabulary). PDDL is case-insensitive; names are read in lower case.
Supported: ``:strips``, ``:typing`` (object types with ``either``-free hierarchies),
``:negative-preconditions``; preconditions, effects and goals are conjunctions of atoms
and negated atoms. Errors name the line and column.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from itertools import product

from robocog.limits import MESSAGE_CHARS, clip
from robocog.planning.sexpr import Sexpr, SexprError, SList, Symbol, parse
from robocog.planning.task import PLACE, TAKE, Fact, Operator, Task, fact_text, intern_bit

Literal = tuple[bool, tuple[str, ...]]  # (positive?, (predicate, terms...))


class PDDLError(ValueError):
    """PDDL text the reader cannot take; the message starts with source:line:column.

    A message is at most ``MESSAGE_CHARS`` long: names from the input (a 10 MB one, say)
    are not repeated whole."""

    def __init__(self, message: str) -> None:
        super().__init__(clip(message, MESSAGE_CHARS))


#: the longest PDDL text (file) read: the domains and problems this planner solves are a
#: few kilobytes, and the reader takes about a second for this many characters
MAX_PDDL_BYTES = 128 << 10
#: the most ground actions :func:`ground` makes; a domain and problem past it (three
#: parameters over 200 objects: eight million) are refused before any is made; a search
#: over more would not end in useful time anyway
MAX_GROUND_ACTIONS = 50_000


@dataclass
class Action:
    """A parameterised STRIPS action."""

    name: str
    parameters: list[tuple[str, str]]  # (variable, type)
    precondition: list[Literal]
    effect: list[Literal]


@dataclass
class Domain:
    """A STRIPS domain: types, predicates and actions."""

    name: str
    requirements: list[str] = field(default_factory=list)
    types: dict[str, str] = field(default_factory=dict)  # type -> parent
    predicates: dict[str, int] = field(default_factory=dict)  # name -> arity
    actions: list[Action] = field(default_factory=list)


@dataclass
class Problem:
    """A problem: typed objects, initial facts and goal literals."""

    name: str
    domain: str
    objects: list[tuple[str, str]] = field(default_factory=list)  # (name, type)
    init: list[Fact] = field(default_factory=list)
    goal: list[Literal] = field(default_factory=list)


def _err(message: str, expr: object, source: str) -> PDDLError:
    return PDDLError(f"{source}:{getattr(expr, 'line', 0)}:{getattr(expr, 'column', 0)}: {message}")


def _sym(expr: Sexpr, source: str, what: str) -> str:
    if not isinstance(expr, Symbol):
        raise _err(f"expected {what}", expr, source)
    return expr.name.lower()


def _typed_list(
    items: Sequence[Sexpr], source: str, default: str = "object"
) -> list[tuple[str, str]]:
    """``a b - t c`` -> [(a, t), (b, t), (c, object)]."""
    out: list[tuple[str, str]] = []
    pending: list[str] = []
    i = 0
    while i < len(items):
        word = _sym(items[i], source, "a name")
        if word == "-":
            if i + 1 >= len(items):
                raise _err("a type must follow '-'", items[i], source)
            typ = _sym(items[i + 1], source, "a type name")
            out.extend((p, typ) for p in pending)
            pending = []
            i += 2
            continue
        pending.append(word)
        i += 1
    out.extend((p, default) for p in pending)
    return out


def _atom(expr: Sexpr, source: str) -> tuple[str, ...]:
    if not isinstance(expr, SList) or not expr.items:
        raise _err("expected an atom such as (on ?x ?y)", expr, source)
    return tuple(_sym(e, source, "a predicate or term") for e in expr.items)


def _literals(expr: Sexpr, source: str) -> list[Literal]:
    if not isinstance(expr, SList):
        raise _err("expected a condition", expr, source)
    if not expr.items:
        return []
    head = expr.head()
    if head == "and":
        out: list[Literal] = []
        for item in expr.items[1:]:
            out.extend(_literals(item, source))
        return out
    if head == "not":
        if len(expr.items) != 2:
            raise _err("(not ...) takes one atom", expr, source)
        return [(False, _atom(expr.items[1], source))]
    if head in ("or", "imply", "forall", "exists", "when"):
        raise _err(f"'{head}' is not supported (STRIPS conditions only)", expr, source)
    return [(True, _atom(expr, source))]


def read_domain(text: str, source: str = "<domain>") -> Domain:
    """Parse a STRIPS domain (at most ``MAX_PDDL_BYTES`` characters)."""
    if len(text) > MAX_PDDL_BYTES:
        raise PDDLError(f"{clip(source)}: longer than {MAX_PDDL_BYTES} characters (MAX_PDDL_BYTES)")
    try:
        exprs = parse(text, source)
    except SexprError as exc:
        raise PDDLError(str(exc)) from None
    if len(exprs) != 1 or not isinstance(exprs[0], SList) or exprs[0].head() != "define":
        raise _err("expected one (define (domain NAME) ...)", exprs[0] if exprs else None, source)
    top = exprs[0]
    header = top.items[1] if len(top.items) > 1 else top
    if not (isinstance(header, SList) and header.head() == "domain" and len(header.items) == 2):
        raise _err("expected (domain NAME)", header, source)
    domain = Domain(_sym(header.items[1], source, "the domain name"))
    for section in top.items[2:]:
        if not isinstance(section, SList) or not section.items:
            raise _err("expected a section such as (:predicates ...)", section, source)
        key = section.head()
        if key == ":requirements":
            domain.requirements = [_sym(r, source, "a requirement") for r in section.items[1:]]
        elif key == ":types":
            for name, parent in _typed_list(section.items[1:], source):
                domain.types[name] = parent
        elif key == ":predicates":
            for p in section.items[1:]:
                if not isinstance(p, SList) or not p.items:
                    raise _err("expected (predicate ?x ...)", p, source)
                name = _sym(p.items[0], source, "a predicate name")
                domain.predicates[name] = len(_typed_list(p.items[1:], source))
        elif key == ":action":
            domain.actions.append(_read_action(section, source))
        elif key in (":constants", ":functions"):
            raise _err(f"'{key}' is not supported", section, source)
        else:
            raise _err(f"unknown section {key!r}", section, source)
    return domain


def _read_action(section: SList, source: str) -> Action:
    if len(section.items) < 2:
        raise _err("an action needs a name", section, source)
    name = _sym(section.items[1], source, "the action name")
    params: list[tuple[str, str]] = []
    pre: list[Literal] = []
    eff: list[Literal] = []
    items = section.items[2:]
    if len(items) % 2:
        raise _err("expected :keyword value pairs", section, source)
    for key_expr, value in zip(items[::2], items[1::2], strict=True):
        key = _sym(key_expr, source, "a keyword")
        if key == ":parameters":
            if not isinstance(value, SList):
                raise _err("expected a parameter list", value, source)
            params = _typed_list(value.items, source)
        elif key == ":precondition":
            pre = _literals(value, source)
        elif key == ":effect":
            eff = _literals(value, source)
        else:
            raise _err(f"unknown action keyword {key!r}", key_expr, source)
    declared = {p for p, _ in params}
    for _pos, atom in pre + eff:
        for term in atom[1:]:
            if term.startswith("?") and term not in declared:
                raise _err(f"{name}: undeclared variable {term}", section, source)
    return Action(name, params, pre, eff)


def read_problem(text: str, source: str = "<problem>") -> Problem:
    """Parse a problem (at most ``MAX_PDDL_BYTES`` characters)."""
    if len(text) > MAX_PDDL_BYTES:
        raise PDDLError(f"{clip(source)}: longer than {MAX_PDDL_BYTES} characters (MAX_PDDL_BYTES)")
    try:
        exprs = parse(text, source)
    except SexprError as exc:
        raise PDDLError(str(exc)) from None
    if len(exprs) != 1 or not isinstance(exprs[0], SList) or exprs[0].head() != "define":
        raise _err("expected one (define (problem NAME) ...)", exprs[0] if exprs else None, source)
    top = exprs[0]
    header = top.items[1] if len(top.items) > 1 else top
    if not (isinstance(header, SList) and header.head() == "problem" and len(header.items) == 2):
        raise _err("expected (problem NAME)", header, source)
    problem = Problem(_sym(header.items[1], source, "the problem name"), "")
    for section in top.items[2:]:
        if not isinstance(section, SList) or not section.items:
            raise _err("expected a section such as (:init ...)", section, source)
        key = section.head()
        if key == ":domain":
            if len(section.items) != 2:
                raise _err("expected (:domain NAME)", section, source)
            problem.domain = _sym(section.items[1], source, "the domain name")
        elif key == ":objects":
            problem.objects = _typed_list(section.items[1:], source)
        elif key == ":init":
            problem.init = [_atom(a, source) for a in section.items[1:]]
        elif key == ":goal":
            if len(section.items) != 2:
                raise _err("(:goal ...) takes one condition", section, source)
            problem.goal = _literals(section.items[1], source)
        elif key == ":requirements":
            continue
        else:
            raise _err(f"unknown section {key!r}", section, source)
    return problem


def read_file(path: str | os.PathLike[str]) -> str:
    """The text of a PDDL file: at most ``MAX_PDDL_BYTES``, UTF-8 (a byte that is not
    is a PDDLError naming its line and column)."""
    name = str(path)
    try:
        with open(path, "rb") as f:
            if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
                raise PDDLError(f"{name}: not a regular file")
            data = f.read(MAX_PDDL_BYTES + 1)
    except OSError as exc:
        raise PDDLError(f"{name}: cannot be read: {exc.strerror or exc}") from None
    if len(data) > MAX_PDDL_BYTES:
        raise PDDLError(f"{name}: larger than {MAX_PDDL_BYTES} bytes (MAX_PDDL_BYTES)")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        before = data[: exc.start].decode("utf-8", "replace")
        line = before.count("\n") + 1
        column = len(before) - (before.rfind("\n") + 1) + 1
        raise PDDLError(
            f"{name}:{line}:{column}: not UTF-8 (byte 0x{data[exc.start]:02x})"
        ) from None


def _subtypes(domain: Domain) -> dict[str, set[str]]:
    """type -> the set of types it includes (itself and its descendants)."""
    out: dict[str, set[str]] = {"object": {"object"}}
    for t in domain.types:
        out.setdefault(t, set()).add(t)
    for t in list(domain.types):
        cur, seen = t, set()
        while cur in domain.types and cur not in seen:
            seen.add(cur)
            parent = domain.types[cur]
            out.setdefault(parent, {parent}).add(t)
            cur = parent
    return out


def ground(domain: Domain, problem: Problem, hand: str = "holding") -> Task:
    """Instantiate every action over the problem's objects as a bit-mask ``Task``.

    Actions that add a *hand* fact take an object, those that delete one place it; the
    search alternates them as in the thesis (the domain's own ``handempty`` does too).
    """
    if problem.domain and problem.domain != domain.name:
        raise PDDLError(f"the problem is for domain {problem.domain!r}, not {domain.name!r}")
    for fact in problem.init:
        if fact[0] not in domain.predicates:
            raise PDDLError(f"unknown predicate in :init: {fact[0]}")
    for _p, fact in problem.goal:
        if fact[0] not in domain.predicates:
            raise PDDLError(f"unknown predicate in :goal: {fact[0]}")
    sub = _subtypes(domain)
    objects = [name for name, _ in problem.objects]
    of_type: dict[str, list[str]] = {}
    for typ in sub:
        of_type[typ] = [n for n, t in problem.objects if t in sub[typ] or typ == "object"]
    total = 0
    for action in domain.actions:
        count = 1
        for _, t in action.parameters:
            count *= len(of_type.get(t, []))
            if count > MAX_GROUND_ACTIONS:
                break
        total += count
        if total > MAX_GROUND_ACTIONS:
            raise PDDLError(
                f"grounding would make more than {MAX_GROUND_ACTIONS} actions "
                f"(MAX_GROUND_ACTIONS; action {clip(action.name)} over "
                f"{len(objects)} objects): give fewer objects or parameters"
            )
    facts: list[Fact] = []
    index: dict[Fact, int] = {}

    def bit(fact: Fact) -> int:
        return intern_bit(index, facts, fact)

    for fact in problem.init:
        bit(fact)
    ops: list[Operator] = []
    for action in domain.actions:
        domains = [of_type.get(t, []) for _, t in action.parameters]
        names = [v for v, _ in action.parameters]
        for values in product(*domains):
            binding = dict(zip(names, values, strict=True))

            def inst(atom: tuple[str, ...], binding: dict[str, str] = binding) -> Fact:
                return tuple(binding.get(t, t) for t in atom)

            pre = absent = add = delete = 0
            for positive, atom in action.precondition:
                if positive:
                    pre |= bit(inst(atom))
                else:
                    absent |= bit(inst(atom))
            for positive, atom in action.effect:
                if positive:
                    add |= bit(inst(atom))
                else:
                    delete |= bit(inst(atom))
            if pre & absent:
                continue
            kind = None
            hand_add = any(inst(a)[0] == hand for p, a in action.effect if p)
            hand_del = any(inst(a)[0] == hand for p, a in action.effect if not p)
            if hand_add and not hand_del:
                kind = TAKE
            elif hand_del and not hand_add:
                kind = PLACE
            ops.append(Operator(action.name, tuple(values), pre, absent, add, delete & ~add, kind))
    goal = absent_goal = 0
    for positive, atom in problem.goal:
        if positive:
            goal |= bit(atom)
        else:
            absent_goal |= bit(atom)
    init = sum(1 << index[f] for f in problem.init)
    busy = sum(1 << i for i, f in enumerate(facts) if f[0] == hand)
    return Task(
        facts=facts,
        operators=ops,
        init=init,
        goal=goal,
        goal_absent=absent_goal,
        busy=busy,
        objects=tuple(objects),
        fixed=(),
        index=index,
    )


def write_problem(
    name: str,
    domain: str,
    objects: Sequence[str],
    init: Iterable[Fact],
    goal: Iterable[Fact],
    object_type: str = "block",
    comment: str = "",
) -> str:
    """A PDDL problem text; ``read_problem`` reads it back to the same data."""
    lines = [f"; {line}" for line in comment.splitlines()] if comment else []
    lines.append(f"(define (problem {name})")
    lines.append(f"  (:domain {domain})")
    typed = f" - {object_type}" if object_type else ""
    lines.append(f"  (:objects {' '.join(objects)}{typed})")
    lines.append("  (:init " + " ".join(fact_text(f) for f in init) + ")")
    lines.append("  (:goal (and " + " ".join(fact_text(f) for f in goal) + ")))")
    return "\n".join(lines) + "\n"


def task_state_problem(task: Task, state: int, name: str, domain: str) -> str:
    """Write a problem for a grounded PDDL task starting from *state* (its goal kept)."""
    init = task.state_facts(state)
    goal = task.state_facts(task.goal)
    return write_problem(name, domain, list(task.objects), init, goal)


def scene_problem(scene: object, goal: Iterable[Fact], name: str = "scene") -> str:
    """Write the planner's scene as a 4-operator blocks problem.

    The blocks world has one table: an object on a fixed object or resting where it was
    found is ``ontable``; a goal "X on a fixed object" becomes ``(ontable x)``.
    """
    from robocog.planning.world import Scene

    if not isinstance(scene, Scene):
        raise TypeError("scene_problem needs a Scene")
    lower = {n: n.lower() for n in scene.names()}
    init: list[Fact] = []
    covered = {b for b in scene.on.values() if b in scene.objects}
    for obj in scene.objects:
        under = scene.on.get(obj)
        if scene.held == obj:
            init.append(("holding", lower[obj]))
        elif under is None or under in scene.fixed:
            init.append(("ontable", lower[obj]))
        else:
            init.append(("on", lower[obj], lower[under]))
        if obj not in covered and scene.held != obj:
            init.append(("clear", lower[obj]))
    if scene.held is None:
        init.append(("handempty",))
    out_goal: list[Fact] = []
    for fact in goal:
        if fact[0] == "on" and fact[2] in scene.fixed:
            out_goal.append(("ontable", lower[fact[1]]))
        elif fact[0] == "in-hand":
            out_goal.append(("holding", lower[fact[1]]))
        else:
            out_goal.append((fact[0], *(lower.get(a, a) for a in fact[1:])))
    comment = ""
    if scene.fixed:
        comment = "fixed objects (" + ", ".join(scene.fixed) + ") are the table here"
    return write_problem(
        name, "blocks", [lower[o] for o in scene.objects], init, out_goal, comment=comment
    )
