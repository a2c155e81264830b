"""Clauses: a pattern body sorted into alternatives of mandatory, absent and
evaluatable clauses, each mandatory or absent clause compiled once with its index anchors."""

from __future__ import annotations

from collections.abc import Iterable

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import VARIABLE_TYPES, Atom, Link, Node
from robocog.atomspace.matcher.terms import (
    T_CHOICE,
    T_CONST,
    T_GLOB,
    T_LINK,
    T_ULINK,
    T_VAR,
    PatternTerm,
    term_closure,
)


class Clause:
    """A mandatory or absent clause: its term, variables and index anchors."""

    __slots__ = ("atom", "term", "vars", "anchors", "root_type", "ground", "literal")

    def __init__(self, atom: Atom, varset: frozenset[Atom], allowed: dict) -> None:
        self.atom = atom
        found: set[Atom] = set()
        # anchors: (is_var, atom, path); a path is linked (link type, position|None,
        # rest), from the anchor's parent up to the clause root (rest None)
        self.anchors: list[tuple[bool, Atom, tuple]] = []
        self.term = _compile(atom, varset, allowed, found, self.anchors, None)
        if self.term.kind == T_CONST and self.term.fn is None:
            self.term.fn = term_closure(self.term)  # a quoted clause is searched, not looked up
        self.vars = frozenset(found)
        # a clause with a ChoiceLink inside is never looked up as it is written, even
        # once its variables are bound: the data holds one of the choices instead
        self.literal = not _holds_choice(atom)
        self.ground = not found and self.literal
        # a quoted clause matches what it quotes: the QuoteLink is not in the data
        self.root_type = atom[1][0][0] if atom[0] == "QuoteLink" and len(atom[1]) == 1 else atom[0]


def _holds_choice(atom: Atom) -> bool:
    """True if the clause cannot be looked up as written: it holds a choice among
    atoms, or quote links that the data does not hold."""
    if atom.__class__ is Node:
        return False
    return atom[0] in ("ChoiceLink", "QuoteLink", "UnquoteLink") or any(
        _holds_choice(a) for a in atom[1]
    )


def _compile(
    atom: Atom,
    varset: frozenset[Atom],
    allowed: dict,
    found: set[Atom],
    anchors: list | None,
    up: tuple | None,
    quoted: bool = False,
) -> PatternTerm:
    """Compile a term in one pass, collecting its variables and (if asked) anchors.

    Inside a QuoteLink every atom stands for itself, variables too, until an UnquoteLink
    makes its content a pattern again; the quote links themselves are no part of the
    data matched."""
    if atom.__class__ is Link and len(atom[1]) == 1:
        if atom[0] == "QuoteLink" and not quoted:
            return _compile(atom[1][0], varset, allowed, found, anchors, up, True)
        if atom[0] == "UnquoteLink" and quoted:
            return _compile(atom[1][0], varset, allowed, found, anchors, up, False)
    if quoted and atom.__class__ is Node:
        if anchors is not None and up is not None:
            anchors.append((False, atom, up))
        return PatternTerm(T_CONST, atom).seal()
    if atom.__class__ is Node:
        if atom in varset and atom[0] == "GlobNode":
            found.add(atom)
            t = PatternTerm(T_GLOB, atom)  # a run of one or more atoms of its parent's outgoing
            t.allowed = allowed.get(atom)
            t.multi = True
            return t
        if atom in varset:
            found.add(atom)
            t = PatternTerm(T_VAR, atom)
            t.allowed = allowed.get(atom)
            if anchors is not None and up is not None:
                anchors.append((True, atom, up))
            return t.seal()
        if anchors is not None and up is not None:
            anchors.append((False, atom, up))
        return PatternTerm(T_CONST, atom).seal()
    if atom[0] == "ChoiceLink" and up is not None and not quoted:
        # inside a clause a ChoiceLink stands for any one of its members (no anchors:
        # the index cannot say which member the data holds)
        t = PatternTerm(T_CHOICE, atom)
        inside = ("ChoiceLink", None, up)
        t.kids = tuple(_compile(a, varset, allowed, found, None, inside) for a in atom[1])
        t.arity = len(t.kids)
        t.multi = True
        return t
    unordered = atom[0] in _t.UNORDERED
    # after a glob the positions of the rest are unknown: anchors say "somewhere"
    globbed = any(a.__class__ is Node and a[0] == "GlobNode" and a in varset for a in atom[1])
    mark = len(anchors) if anchors is not None else 0
    before = len(found)
    kids = []
    for i, a in enumerate(atom[1]):
        step = (atom[0], None if unordered or globbed else i, up)  # linked: cheap to extend
        kids.append(_compile(a, varset, allowed, found, anchors, step, quoted))
    if len(found) == before and all(k.kind == T_CONST for k in kids):
        # a ground subterm: one anchor for the whole of it
        if anchors is not None:
            del anchors[mark:]
            if up is not None:
                anchors.append((False, atom, up))
        return PatternTerm(T_CONST, atom).seal()
    t = PatternTerm(T_ULINK if unordered else T_LINK, atom)
    t.kids = tuple(kids)
    t.arity = len(kids)
    t.multi = any(k.multi for k in kids) or (unordered and any(k.kind != T_CONST for k in kids))
    return t.seal()


_CLAUSES: dict[tuple, Clause] = {}
_CLAUSES_MAX = 8192


def clear_clauses() -> None:
    """Forget every compiled clause (see :func:`robocog.atomspace.matcher.clear_caches`)."""
    _CLAUSES.clear()


def clause_of(atom: Atom, varset: frozenset[Atom], allowed: dict) -> Clause:
    """The compiled clause, shared by every pattern that holds the same clause with the
    same variables and types: a rule's clauses are compiled once however many ways it
    is pinned down (the planner adds EqualLinks to a rule's body for each object)."""
    key = (atom, tuple([(v, allowed.get(v)) for v in all_vars(atom) if v in varset]))
    c = _CLAUSES.get(key)
    if c is None:
        c = Clause(atom, varset, allowed)
        if len(_CLAUSES) >= _CLAUSES_MAX:
            _CLAUSES.clear()
        _CLAUSES[key] = c
    return c


def all_vars(atom: Atom) -> Iterable[Atom]:
    if atom.__class__ is Node:
        if atom[0] in VARIABLE_TYPES:
            yield atom
        return
    for a in atom[1]:
        yield from all_vars(a)


def nodes_of(atom: Atom) -> Iterable[Atom]:
    if atom.__class__ is Node:
        yield atom
        return
    for a in atom[1]:
        yield from nodes_of(a)


_EVALUATABLE = frozenset(
    {
        "EqualLink",
        "IdenticalLink",
        "GreaterThanLink",
        "NotLink",
        "SatisfactionLink",
    }
)


def is_evaluatable(atom: Atom) -> bool:
    """True for terms the matcher evaluates instead of looking up."""
    t = atom[0]
    if t in _EVALUATABLE:
        return True
    if (
        t == "EvaluationLink"
        and atom[1]
        and atom[1][0][0]
        in (
            "GroundedPredicateNode",
            "DefinedPredicateNode",
        )
    ):
        return True
    if t in ("AndLink", "OrLink"):
        return all(is_evaluatable(a) for a in atom[1])
    return False


class Alternative:
    """One alternative: a conjunction of mandatory, absent and evaluatable clauses."""

    __slots__ = ("mandatory", "absent", "evals", "always", "order")

    def __init__(self) -> None:
        self.mandatory: list[Atom] = []
        self.absent: list[Atom] = []
        self.evals: list[Atom] = []
        #: AlwaysLink members: true of every grounding that shares the search's start
        self.always: list[Atom] = []
        #: the evaluations and absences in the order written (a SequentialAndLink
        #: checks them in that order): i for evals[i], -1 - i for absent[i]
        self.order: list[int] = []

    def add_eval(self, atom: Atom) -> None:
        self.order.append(len(self.evals))
        self.evals.append(atom)

    def add_absent(self, atom: Atom) -> None:
        self.order.append(-1 - len(self.absent))
        self.absent.append(atom)

    def merged(self, other: Alternative) -> Alternative:
        new = Alternative()
        new.mandatory = self.mandatory + other.mandatory
        new.absent = self.absent + other.absent
        new.evals = self.evals + other.evals
        new.always = self.always + other.always
        ne, na = len(self.evals), len(self.absent)
        new.order = self.order + [i + ne if i >= 0 else i - na for i in other.order]
        return new


#: link types that mean something to the matcher when they stand as a clause
_SPECIAL = frozenset(
    {
        "AndLink",
        "SequentialAndLink",
        "OrLink",
        "ChoiceLink",
        "PresentLink",
        "AbsentLink",
        "AlwaysLink",
        "NotLink",
    }
)


def _variable_formula(atom: Atom) -> bool:
    """A bare VariableNode, or NotLinks around one."""
    while atom.__class__ is Link and atom[0] == "NotLink" and len(atom[1]) == 1:
        atom = atom[1][0]
    return atom.__class__ is Node and atom[0] == "VariableNode"


def alternatives_of(body: Atom) -> list[Alternative]:
    """The body in disjunctive form: a list of conjunctions."""
    t = body[0]
    # a SequentialAndLink is a conjunction whose evaluatable members are evaluated in
    # their order, the first false one ending the try (evaluations keep their order)
    if t in ("AndLink", "SequentialAndLink"):
        if all(
            c[0] not in _SPECIAL and not is_evaluatable(c) and not _variable_formula(c)
            for c in body[1]
        ):
            plain = Alternative()  # the common case: a conjunction of terms to find
            plain.mandatory.extend(body[1])
            return [plain]
        alts = [Alternative()]
        # a variable standing as a clause (or under NotLinks) beside clauses that ground
        # it is evaluated, as OpenCog evaluates a variable in an evaluatable position
        structured = any(not _variable_formula(c) for c in body[1])
        for c in body[1]:
            if structured and _variable_formula(c):
                evaluated = Alternative()
                evaluated.add_eval(c)
                sub = [evaluated]
            else:
                sub = alternatives_of(c)
            alts = [a.merged(s) for a in alts for s in sub]
        return alts
    if t in ("OrLink", "ChoiceLink"):
        if t == "OrLink" and is_evaluatable(body):
            alt = Alternative()
            alt.add_eval(body)
            return [alt]
        out: list[Alternative] = []
        for c in body[1]:
            out.extend(alternatives_of(c))
        return out
    alt = Alternative()
    if t == "AlwaysLink":
        alt.always.extend(body[1])
    elif t == "PresentLink":
        alt.mandatory.extend(body[1])
    elif t == "AbsentLink":
        for member in body[1]:
            alt.add_absent(member)
    elif t == "NotLink" and len(body[1]) == 1 and not is_evaluatable(body[1][0]):
        inner = body[1][0]
        if inner[0] == "PresentLink":
            for member in inner[1]:
                alt.add_absent(member)
        else:
            alt.add_absent(inner)
    elif is_evaluatable(body):
        alt.add_eval(body)
    else:
        variants = _choices_spelled_out(body)
        if len(variants) > 1:
            # one alternative per choice: each is searched from the index, where a
            # clause holding the choice could not be (it is matched member by member
            # only when there are too many combinations)
            out = []
            for v in variants:
                each = Alternative()
                each.mandatory.append(v)
                out.append(each)
            return out
        alt.mandatory.append(body)
    return [alt]


#: at most this many clauses are made of one clause's ChoiceLinks
_CHOICE_VARIANTS = 64


def _choices_spelled_out(atom: Atom) -> list[Atom]:
    """The clauses a clause with ChoiceLinks inside stands for, one per combination of
    choices ([atom] itself when it has none or too many)."""
    if (
        atom.__class__ is Node
        or atom[0] in ("QuoteLink", "LambdaLink")
        or atom[0] in _t.QUERY_TYPES
    ):
        return [atom]
    if not _holds_choice(atom):
        return [atom]
    combos: list[list[Atom]] = [[]]
    for a in atom[1]:
        options = (
            [x for m in a[1] for x in _choices_spelled_out(m)]
            if a.__class__ is Link and a[0] == "ChoiceLink"
            else _choices_spelled_out(a)
        )
        combos = [c + [o] for c in combos for o in options]
        if len(combos) > _CHOICE_VARIANTS:
            return [atom]
    return [Link(atom[0], *c) for c in combos]
