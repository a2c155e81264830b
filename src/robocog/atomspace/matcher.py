"""The pattern matcher: find every grounding of a pattern's variables in an AtomSpace.

A pattern is compiled once (and cached by the pattern atom) into alternatives, each a
conjunction of three kinds of clauses, as OpenCog's query engine sorts them:

- mandatory clauses, terms that must be present (PresentLink members, and any
  non-evaluatable term under the AndLink: the implicit AND of OpenCog);
- absent clauses (AbsentLink, or NotLink over a non-evaluatable term), which must have
  no grounding;
- evaluatable clauses (EqualLink, IdenticalLink, NotLink, GreaterThanLink, an
  EvaluationLink with a GroundedPredicateNode, nested And/Or of these) that must
  evaluate to true once their variables are bound.

OrLink and ChoiceLink of clauses split the pattern into alternatives whose groundings
are united. The search binds mandatory clauses one at a time, always taking next the
clause with the fewest candidates: a clause whose variables are all bound is a single
membership test; otherwise the candidates are found by walking up the incoming sets from
its rarest constant or bound atom (type and position checked at every step), so any
bound argument is found through the index, never by a scan. Evaluatable and absent
clauses are checked as soon as their variables are bound, which prunes early.
Unordered links (SetLink, AndLink, EqualLink, ...) are matched in every order.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import VARIABLE_TYPES, Atom, Link, Node, variables_of
from robocog.atomspace.fastpath import _EVAL_PREDICATES, _PLAIN, fast_query

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace

Bindings = dict[Atom, Atom]


class PatternError(ValueError):
    """A pattern the matcher cannot run (bad variable declaration, unused variable)."""


# ---------------------------------------------------------------------- terms
_CONST, _VAR, _LINK, _ULINK, _CHOICE, _GLOB = 0, 1, 2, 3, 4, 5


class _Term:
    """A compiled pattern term."""

    __slots__ = ("kind", "atom", "type", "kids", "arity", "allowed", "multi", "fn")

    def __init__(self, kind: int, atom: Atom) -> None:
        self.kind = kind
        self.atom = atom
        self.type = atom[0]
        self.kids: tuple[_Term, ...] = ()
        self.arity = 0
        self.allowed: frozenset[str] | None = None
        self.multi = False  # may yield more than one binding (unordered with variables)
        self.fn: Callable[[Atom, Bindings], Bindings | None] | None = None

    def seal(self) -> _Term:
        """Build the matching closure of a variable or link term that yields at most
        one binding (constants are compared inline by their parents)."""
        if not self.multi and self.kind != _CONST:
            self.fn = _closure(self)
        return self


def _closure(t: _Term) -> Callable[[Atom, Bindings], Bindings | None]:
    """A function matching one atom against term ``t`` (specialised by its shape, so
    the matcher's inner loop does no dispatch)."""
    if t.kind == _CONST:
        c = t.atom

        def const(a: Atom, b: Bindings) -> Bindings | None:
            return b if (a is c or a == c) else None

        return const
    if t.kind == _VAR:
        var, allowed = t.atom, t.allowed

        def variable(a: Atom, b: Bindings) -> Bindings | None:
            v = b.get(var)
            if v is not None:
                return b if (v is a or v == a) else None
            if allowed is not None and not _admits(allowed, a):
                return None
            nb = b.copy()
            nb[var] = a
            return nb

        return variable
    typ, n = t.type, t.arity
    consts = tuple((i, k.atom) for i, k in enumerate(t.kids) if k.kind == _CONST)
    active = tuple((i, k.fn) for i, k in enumerate(t.kids) if k.kind != _CONST)
    if len(active) == 1:
        (i0, f0) = active[0]

        def link_one(a: Atom, b: Bindings) -> Bindings | None:
            if a[0] != typ or a.__class__ is not Link:
                return None
            out = a[1]
            if len(out) != n:
                return None
            for i, c in consts:
                x = out[i]
                if x is not c and x != c:
                    return None
            return f0(out[i0], b)  # type: ignore[misc]

        return link_one

    def link(a: Atom, b: Bindings) -> Bindings | None:
        if a[0] != typ or a.__class__ is not Link:
            return None
        out = a[1]
        if len(out) != n:
            return None
        for i, c in consts:
            x = out[i]
            if x is not c and x != c:
                return None
        for i, f in active:
            b = f(out[i], b)  # type: ignore[misc, assignment]
            if b is None:
                return None
        return b

    return link


def drop_self_groundings(found: list[Bindings], variables: Iterable[Atom]) -> list[Bindings]:
    """The groundings that do not hold the pattern's own variables: with atoms that
    have variables in the space, a pattern may find its own clauses there, which
    OpenCog never counts."""
    mine = frozenset(variables)
    return [b for b in found if not any(_self_ground(x, mine) for x in b.values())]


def _self_ground(atom: Atom, mine: frozenset[Atom]) -> bool:
    """True if a grounding holds one of the pattern's own variables (outside quotes):
    the pattern found itself, or a copy of its clauses, in the space."""
    if atom.__class__ is Node:
        return atom in mine
    if atom[0] in ("QuoteLink", "UnquoteLink"):
        return False
    return any(_self_ground(a, mine) for a in atom[1])


def _has_var_in(atom: Atom, varset: frozenset[Atom]) -> bool:
    if atom.__class__ is Node:
        return atom in varset
    return any(_has_var_in(a, varset) for a in atom[1])


def _bind(t: _Term, a: Atom, b: Bindings) -> Bindings | None:
    v = b.get(t.atom)
    if v is not None:
        return b if (v is a or v == a) else None
    if t.allowed is not None and not _admits(t.allowed, a):
        return None
    nb = b.copy()
    nb[t.atom] = a
    return nb


def _match1(t: _Term, a: Atom, b: Bindings) -> Bindings | None:
    """Match a term that yields at most one binding."""
    if t.kind == _CONST:
        return b if (t.atom is a or t.atom == a) else None
    return t.fn(a, b)  # type: ignore[misc]


def match(t: _Term, a: Atom, b: Bindings) -> list[Bindings]:
    """Every extension of ``b`` under which term ``t`` equals atom ``a``."""
    if not t.multi:
        r = _match1(t, a, b)
        return [] if r is None else [r]
    if t.kind == _CHOICE:
        found: list[Bindings] = []
        for k in t.kids:
            for b2 in match(k, a, b):
                if b2 not in found:
                    found.append(b2)
        return found
    if t.kind == _LINK and any(k.kind == _GLOB for k in t.kids):
        if a.__class__ is not Link or a[0] != t.type:
            return []
        results: list[Bindings] = []
        _match_run(t.kids, 0, a[1], 0, b, results)
        return results
    if a.__class__ is not Link or a[0] != t.type or len(a[1]) != t.arity:
        return []
    if t.kind == _LINK:
        bs = [b]
        for kt, x in zip(t.kids, a[1], strict=True):
            bs = [b2 for b1 in bs for b2 in match(kt, x, b1)]
            if not bs:
                return []
        return bs
    # unordered: give each pattern term a distinct outgoing atom, in every way
    results: list[Bindings] = []
    kids = sorted(t.kids, key=lambda k: k.kind != _CONST)
    _match_unordered(kids, 0, list(a[1]), [False] * len(a[1]), b, results)
    return results


def _match_run(
    kids: tuple[_Term, ...], i: int, out: tuple[Atom, ...], j: int, b: Bindings, results: list
) -> None:
    """Match pattern terms ``kids[i:]`` against atoms ``out[j:]``, a glob taking a run
    of one or more atoms (every length that lets the rest match)."""
    if i == len(kids):
        if j == len(out):
            results.append(b)
        return
    kt = kids[i]
    if kt.kind != _GLOB:
        if j < len(out):
            for b2 in match(kt, out[j], b):
                _match_run(kids, i + 1, out, j + 1, b2, results)
        return
    need = sum(1 for k in kids[i + 1 :])  # each later term takes at least one atom
    bound = b.get(kt.atom)
    for end in range(j + 1, len(out) - need + 1):
        run = out[j:end]
        if kt.allowed is not None and not all(_admits(kt.allowed, x) for x in run):
            break
        value = tuple.__new__(Link, ("ListLink", run))
        if bound is not None:
            if bound != value:
                continue
            _match_run(kids, i + 1, out, end, b, results)
            continue
        b2 = b.copy()
        b2[kt.atom] = value
        _match_run(kids, i + 1, out, end, b2, results)


def _match_unordered(
    kids: list[_Term],
    i: int,
    out: list[Atom],
    used: list[bool],
    b: Bindings,
    results: list[Bindings],
) -> None:
    if i == len(kids):
        results.append(b)
        return
    kt = kids[i]
    tried: set[Atom] = set()
    for j, x in enumerate(out):
        if used[j] or x in tried:
            continue
        tried.add(x)  # equal atoms in a set give the same groundings
        for b2 in match(kt, x, b):
            used[j] = True
            _match_unordered(kids, i + 1, out, used, b2, results)
            used[j] = False


def substitute(atom: Atom, b: Bindings) -> Atom:
    """``atom`` with every bound variable replaced by its grounding."""
    if atom.__class__ is Node:
        return b.get(atom, atom)
    if atom[0] in _t.QUERY_TYPES:
        return atom
    if atom[0] == "PutLink" and len(atom[1]) == 2:
        # the PutLink binds its body's variables itself: only the arguments take ours
        body, args = atom[1]
        own = set(variables_of(body)) if body[0] != "LambdaLink" else set()
        inner = {k: v for k, v in b.items() if k not in own} if own else b
        return tuple.__new__(Link, ("PutLink", (substitute(body, inner), substitute(args, b))))
    out = atom[1]
    new = tuple([substitute(x, b) for x in out])
    if any(x.__class__ is Node and x[0] == "GlobNode" and x in b for x in out):
        # a glob's grounding is a run: its atoms take the glob's place
        spliced: list[Atom] = []
        for x, y in zip(out, new, strict=True):
            if x.__class__ is Node and x[0] == "GlobNode" and x in b:
                spliced.extend(y[1])
            else:
                spliced.append(y)
        new = tuple(spliced)
    elif all(x is y for x, y in zip(new, out, strict=True)):
        return atom
    if atom[0] in _t.UNORDERED:
        new = tuple(sorted(new))
    return tuple.__new__(Link, (atom[0], new))


# ---------------------------------------------------------------------- clauses
class _Clause:
    """A mandatory or absent clause: its term, variables and index anchors."""

    __slots__ = ("atom", "term", "vars", "anchors", "root_type", "ground", "literal")

    def __init__(self, atom: Atom, varset: frozenset[Atom], allowed: dict) -> None:
        self.atom = atom
        found: set[Atom] = set()
        # anchors: (is_var, atom, path); a path is linked (link type, position|None,
        # rest), from the anchor's parent up to the clause root (rest None)
        self.anchors: list[tuple[bool, Atom, tuple]] = []
        self.term = _compile(atom, varset, allowed, found, self.anchors, None)
        if self.term.kind == _CONST and self.term.fn is None:
            self.term.fn = _closure(self.term)  # a quoted clause is searched, not looked up
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
) -> _Term:
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
        return _Term(_CONST, atom).seal()
    if atom.__class__ is Node:
        if atom in varset and atom[0] == "GlobNode":
            found.add(atom)
            t = _Term(_GLOB, atom)  # a run of one or more atoms of its parent's outgoing
            t.allowed = allowed.get(atom)
            t.multi = True
            return t
        if atom in varset:
            found.add(atom)
            t = _Term(_VAR, atom)
            t.allowed = allowed.get(atom)
            if anchors is not None and up is not None:
                anchors.append((True, atom, up))
            return t.seal()
        if anchors is not None and up is not None:
            anchors.append((False, atom, up))
        return _Term(_CONST, atom).seal()
    if atom[0] == "ChoiceLink" and up is not None and not quoted:
        # inside a clause a ChoiceLink stands for any one of its members (no anchors:
        # the index cannot say which member the data holds)
        t = _Term(_CHOICE, atom)
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
    if len(found) == before and all(k.kind == _CONST for k in kids):
        # a ground subterm: one anchor for the whole of it
        if anchors is not None:
            del anchors[mark:]
            if up is not None:
                anchors.append((False, atom, up))
        return _Term(_CONST, atom).seal()
    t = _Term(_ULINK if unordered else _LINK, atom)
    t.kids = tuple(kids)
    t.arity = len(kids)
    t.multi = any(k.multi for k in kids) or (unordered and any(k.kind != _CONST for k in kids))
    return t.seal()


_CLAUSES: dict[tuple, _Clause] = {}
_CLAUSES_MAX = 8192


def clause_of(atom: Atom, varset: frozenset[Atom], allowed: dict) -> _Clause:
    """The compiled clause, shared by every pattern that holds the same clause with the
    same variables and types: a rule's clauses are compiled once however many ways it
    is pinned down (the planner adds EqualLinks to a rule's body for each object)."""
    key = (atom, tuple([(v, allowed.get(v)) for v in _all_vars(atom) if v in varset]))
    c = _CLAUSES.get(key)
    if c is None:
        c = _Clause(atom, varset, allowed)
        if len(_CLAUSES) >= _CLAUSES_MAX:
            _CLAUSES.clear()
        _CLAUSES[key] = c
    return c


def _all_vars(atom: Atom) -> Iterable[Atom]:
    if atom.__class__ is Node:
        if atom[0] in VARIABLE_TYPES:
            yield atom
        return
    for a in atom[1]:
        yield from _all_vars(a)


def _nodes(atom: Atom) -> Iterable[Atom]:
    if atom.__class__ is Node:
        yield atom
        return
    for a in atom[1]:
        yield from _nodes(a)


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


class _Alt:
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

    def merged(self, other: _Alt) -> _Alt:
        new = _Alt()
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


def _alternatives(body: Atom) -> list[_Alt]:
    """The body in disjunctive form: a list of conjunctions."""
    t = body[0]
    # a SequentialAndLink is a conjunction whose evaluatable members are evaluated in
    # their order, the first false one ending the try (evaluations keep their order)
    if t in ("AndLink", "SequentialAndLink"):
        if all(
            c[0] not in _SPECIAL and not is_evaluatable(c) and not _variable_formula(c)
            for c in body[1]
        ):
            plain = _Alt()  # the common case: a conjunction of terms to find
            plain.mandatory.extend(body[1])
            return [plain]
        alts = [_Alt()]
        # a variable standing as a clause (or under NotLinks) beside clauses that ground
        # it is evaluated, as OpenCog evaluates a variable in an evaluatable position
        structured = any(not _variable_formula(c) for c in body[1])
        for c in body[1]:
            if structured and _variable_formula(c):
                evaluated = _Alt()
                evaluated.add_eval(c)
                sub = [evaluated]
            else:
                sub = _alternatives(c)
            alts = [a.merged(s) for a in alts for s in sub]
        return alts
    if t in ("OrLink", "ChoiceLink"):
        if t == "OrLink" and is_evaluatable(body):
            alt = _Alt()
            alt.add_eval(body)
            return [alt]
        out: list[_Alt] = []
        for c in body[1]:
            out.extend(_alternatives(c))
        return out
    alt = _Alt()
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
                each = _Alt()
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


# ---------------------------------------------------------------------- variables
def parse_variables(
    decl: Atom | None, body: Atom
) -> tuple[list[Atom], dict[Atom, frozenset[str] | None]]:
    """Variables in declaration order and the types each may take (None = any)."""
    allowed: dict[Atom, frozenset[str] | None] = {}
    if decl is None:
        vs = variables_of(body)
        return vs, {v: None for v in vs}
    items: tuple[Atom, ...]
    if decl[0] in ("VariableList", "VariableSet"):
        items = decl[1]
    else:
        items = (decl,)
    order: list[Atom] = []
    for it in items:
        if it.__class__ is Node and it[0] in VARIABLE_TYPES:
            order.append(it)
            allowed[it] = None
        elif it[0] == "TypedVariableLink" and len(it[1]) == 2:
            var, typ = it[1]
            if var[0] not in VARIABLE_TYPES:
                raise PatternError(f"TypedVariableLink must name a VariableNode: {it}")
            order.append(var)
            allowed[var] = _type_constraint(typ)
        else:
            raise PatternError(f"not a variable declaration: {it}")
    return order, allowed


class TypeSet(frozenset):
    """The atom types a variable may take: a set of type names (what the index is
    searched by), plus OpenCog's "deep" types, SignatureLinks that an atom must match
    in its whole shape (a TypeNode inside matches any atom of that type)."""

    simple: frozenset[str]
    deep: tuple[Atom, ...]

    def __new__(cls, simple: frozenset[str], deep: tuple[Atom, ...] = ()) -> TypeSet:
        roots = {_root_type(sig) for sig in deep}
        obj = super().__new__(cls, simple | roots)
        obj.simple = simple
        obj.deep = deep
        return obj

    def __eq__(self, other: object) -> bool:
        return (
            isinstance(other, TypeSet)
            and frozenset.__eq__(self, other)
            and self.simple == other.simple
            and self.deep == other.deep
        )

    def __hash__(self) -> int:
        return hash((frozenset(self), self.deep))

    def __or__(self, other: frozenset) -> TypeSet:  # type: ignore[override]
        if isinstance(other, TypeSet):
            return TypeSet(self.simple | other.simple, self.deep + other.deep)
        return TypeSet(self.simple | other, self.deep)

    def admits(self, atom: Atom) -> bool:
        """True if ``atom`` is of one of the simple types or matches a signature."""
        return atom[0] in self.simple or any(_signature_matches(s, atom) for s in self.deep)


def _root_type(sig: Atom) -> str:
    """The type of the atoms a signature can match at its root."""
    if sig[0] == "SignatureLink":
        return _root_type(sig[1][0])
    if sig[0] == "TypeNode":
        full = _t.resolve(sig[1])
        if full is None:
            raise PatternError(f"unknown type {sig[1]!r}")
        return full
    return sig[0]


def _signature_matches(sig: Atom, atom: Atom) -> bool:
    t = sig[0]
    if t == "SignatureLink":
        return len(sig[1]) == 1 and _signature_matches(sig[1][0], atom)
    if t in ("TypeNode", "TypeInhNode", "TypeChoice"):
        return atom[0] in _type_constraint(sig) or (
            t == "TypeChoice" and any(_signature_matches(x, atom) for x in sig[1])
        )
    if sig.__class__ is Node:
        return atom == sig
    if atom.__class__ is not Link or atom[0] != t or len(atom[1]) != len(sig[1]):
        return False
    return all(_signature_matches(x, y) for x, y in zip(sig[1], atom[1], strict=True))


def _admits(allowed: frozenset[str], atom: Atom) -> bool:
    """The type check of a variable: by type name, and by shape for deep types."""
    if atom[0] not in allowed:
        return False
    return not isinstance(allowed, TypeSet) or not allowed.deep or allowed.admits(atom)


def _type_constraint(typ: Atom) -> frozenset[str]:
    if typ[0] == "TypeNode":
        full = _t.resolve(typ[1])
        if full is None:
            raise PatternError(f"unknown type {typ[1]!r}")
        return frozenset({full})
    if typ[0] == "TypeInhNode":
        full = _t.resolve(typ[1])
        if full is None:
            raise PatternError(f"unknown type {typ[1]!r}")
        return _t.subtypes(full)
    if typ[0] == "SignatureLink":
        if len(typ[1]) != 1:
            raise PatternError(f"a SignatureLink holds one signature: {typ}")
        return TypeSet(frozenset(), (typ,))
    if typ[0] == "TypeChoice":
        simple: frozenset[str] = frozenset()
        deep: tuple[Atom, ...] = ()
        for x in typ[1]:
            c = _type_constraint(x)
            if isinstance(c, TypeSet):
                simple |= c.simple
                deep += c.deep
            else:
                simple |= c
        return TypeSet(simple, deep) if deep else simple
    raise PatternError(f"unsupported type restriction {typ}")


def is_variable_decl(atom: Atom) -> bool:
    """True if ``atom`` reads as a variable declaration."""
    return (atom.__class__ is Node and atom[0] == "VariableNode") or atom[0] in _t.VARIABLE_DECLS


# ---------------------------------------------------------------------- compiled query
class Pattern:
    """A compiled pattern: variables, their types and the alternatives to search."""

    __slots__ = ("variables", "allowed", "alts", "body")

    def __init__(self, body: Atom, decl: Atom | None = None) -> None:
        self.body = body
        self.variables, self.allowed = parse_variables(decl, body)
        varset = frozenset(self.variables)
        self.alts: list[_CompiledAlt] = [
            _CompiledAlt(a, varset, self.allowed) for a in _alternatives(body)
        ]
        used: set[Atom] = set()
        for ca in self.alts:
            used |= ca.bound_vars | ca.eval_vars | ca.absent_vars
        for v in self.variables:
            if v not in used:
                raise PatternError(f"the variable {v} does not appear in any clause")

    def groundings(self, space: AtomSpace, limit: int | None = None) -> list[Bindings]:
        """Every grounding (deduplicated, in the order found)."""
        if self.variables and space.count_type("VariableNode"):
            # atoms with variables in the space: the pattern may find its own clauses
            # there, which OpenCog never counts (a variable grounded by itself)
            kept = drop_self_groundings(self._groundings(space, None), self.variables)
            return kept if limit is None else kept[:limit]
        return self._groundings(space, limit)

    def _groundings(self, space: AtomSpace, limit: int | None = None) -> list[Bindings]:
        alts = self.alts
        if len(alts) == 1:
            # within one alternative every grounding is distinct already
            out: list[Bindings] = []
            alts[0].solve(space, out, limit)
            return out
        seen: set[tuple[Atom, ...]] = set()
        result: list[Bindings] = []
        vs = self.variables
        for ca in alts:
            found: list[Bindings] = []
            ca.solve(space, found, None if limit is None else limit - len(result))
            for b in found:
                key = tuple(b.get(v) for v in vs)  # type: ignore[misc]
                if key in seen:
                    continue
                seen.add(key)
                result.append(b)
                if limit is not None and len(result) >= limit:
                    return result
        return result


class _CompiledAlt:
    __slots__ = (
        "mandatory",
        "absent",
        "evals",
        "bound_vars",
        "eval_vars",
        "absent_vars",
        "enum_vars",
        "allowed",
        "always",
        "order",
    )

    def __init__(self, alt: _Alt, varset: frozenset[Atom], allowed: dict) -> None:
        self.allowed = allowed
        self.always = list(alt.always)
        self.order = list(alt.order)
        self.mandatory = [clause_of(c, varset, allowed) for c in alt.mandatory]
        self.bound_vars: set[Atom] = set()
        for c in self.mandatory:
            self.bound_vars |= c.vars
        # absent clauses: variables not bound elsewhere are local to the clause
        self.evals = [(e, frozenset(v for v in _all_vars(e) if v in varset)) for e in alt.evals]
        self.eval_vars: set[Atom] = set()
        for _e, vs in self.evals:
            self.eval_vars |= vs
        bindable = self.bound_vars | self.eval_vars
        self.absent = []
        self.absent_vars: set[Atom] = set()
        for a in alt.absent:
            outer = frozenset(v for v in _all_vars(a) if v in bindable)
            local = frozenset(v for v in _all_vars(a) if v not in bindable)
            self.absent.append((clause_of(a, outer | local, allowed), outer))
            self.absent_vars |= {v for v in local if v in varset}
        self.enum_vars = [v for v in varset if v in self.eval_vars and v not in self.bound_vars]

    # -- the search -------------------------------------------------------------
    def solve(self, space: AtomSpace, out: list[Bindings], limit: int | None = None) -> None:
        """Append every grounding of this alternative to ``out``."""
        if self.always:
            self._solve_always(space, out, limit)
            return
        self._solve(space, out, limit)

    def _solve_always(self, space: AtomSpace, out: list[Bindings], limit: int | None) -> None:
        """OpenCog's for-all: the groundings that share a grounding of the clause the
        search starts from count only if every one of them satisfies the AlwaysLink
        clauses; one that does not sinks its whole group."""
        found: list[Bindings] = []
        self._solve(space, found, None)
        start = self._start_clause(space)
        key_vars = sorted(start.vars, key=repr) if start is not None else []
        groups: dict[tuple[Atom | None, ...], list[Bindings]] = {}
        for b in found:
            groups.setdefault(tuple(b.get(v) for v in key_vars), []).append(b)
        for group in groups.values():
            if all(self._always_holds(space, b) for b in group):
                for b in group:
                    out.append(b)
                    if limit is not None and len(out) >= limit:
                        return

    def _always_holds(self, space: AtomSpace, b: Bindings) -> bool:
        for clause in self.always:
            atom = substitute(clause, b)
            if is_evaluatable(atom):
                if not _eval_clause(space, atom):
                    return False
            elif atom not in space:
                return False
        return True

    def _start_clause(self, space: AtomSpace) -> _Clause | None:
        """The clause OpenCog's search would start from: the one holding the constant
        with the fewest links into it (the thinnest way in)."""
        best, best_n = None, -1
        for c in self.mandatory:
            for a in _nodes(c.atom):
                if a[0] not in ("VariableNode", "GlobNode"):
                    n = len(_incoming(space, a))
                    if best_n < 0 or n < best_n:
                        best, best_n = c, n
        return best if best is not None else (self.mandatory[0] if self.mandatory else None)

    def _solve(self, space: AtomSpace, out: list[Bindings], limit: int | None = None) -> None:
        pending = list(self.order)
        b: Bindings = {}
        if pending:
            ok, pending = self._check_ready(space, pending, b)
            if not ok:
                return
        try:
            self._search(space, self.mandatory, b, pending, out, limit)
        except _Enough:
            pass

    def _check_ready(
        self, space: AtomSpace, pending: list[int], b: Bindings
    ) -> tuple[bool, list[int]]:
        rest: list[int] = []
        for i in pending:
            if i >= 0:
                atom, vs = self.evals[i]
                if all(v in b for v in vs):
                    if not _eval_clause(space, substitute(atom, b)):
                        return False, rest
                    continue
            else:
                clause, outer = self.absent[-1 - i]
                if all(v in b for v in outer):
                    if _exists(space, clause, b):
                        return False, rest
                    continue
            rest.append(i)
        return True, rest

    def _search(
        self,
        space: AtomSpace,
        remaining: list[_Clause],
        b: Bindings,
        pending: list[int],
        out: list[Bindings],
        limit: int | None,
    ) -> None:
        if not remaining:
            if pending or self.enum_vars:
                self._enumerate(space, b, pending, out, limit)
            else:
                out.append(b)
                if limit is not None and len(out) >= limit:
                    raise _Enough
            return
        # pick the clause with the fewest candidates (estimated from the index sizes)
        if len(remaining) == 1:
            clause = remaining[0]
            rest: list[_Clause] = []
            ground = clause.ground or (clause.literal and all(v in b for v in clause.vars))
        else:
            best_i, best_n = -1, -1
            for i, c in enumerate(remaining):
                if c.ground or (c.literal and all(v in b for v in c.vars)):
                    best_i, best_n = i, -2
                    break
                n = _estimate(space, c, b)
                if best_n < 0 or n < best_n:
                    best_i, best_n = i, n
                    if n == 0:
                        return
            clause = remaining[best_i]
            rest = remaining[:best_i] + remaining[best_i + 1 :]
            ground = best_n == -2
        if ground:
            if substitute(clause.atom, b) in space:
                self._search(space, rest, b, pending, out, limit)
            return
        term = clause.term
        last = not rest and not pending and not self.enum_vars
        if not term.multi:
            fn = term.fn
            for cand in _candidates(space, clause, b):
                b2 = fn(cand, b)  # type: ignore[misc]
                if b2 is None:
                    continue
                if last:
                    out.append(b2)
                    if limit is not None and len(out) >= limit:
                        raise _Enough
                    continue
                if pending:
                    ok, pend2 = self._check_ready(space, pending, b2)
                    if not ok:
                        continue
                else:
                    pend2 = pending
                self._search(space, rest, b2, pend2, out, limit)
            return
        for cand in _candidates(space, clause, b):
            for b2 in match(term, cand, b):
                if pending:
                    ok, pend2 = self._check_ready(space, pending, b2)
                    if not ok:
                        continue
                else:
                    pend2 = pending
                self._search(space, rest, b2, pend2, out, limit)

    def _enumerate(
        self,
        space: AtomSpace,
        b: Bindings,
        pending: list[int],
        out: list[Bindings],
        limit: int | None,
    ) -> None:
        """Ground variables that only evaluatable clauses mention."""
        todo = [v for v in self.enum_vars if v not in b]
        if not todo:
            ok, rest = self._check_ready(space, pending, b)
            if ok and not rest:
                out.append(b)
                if limit is not None and len(out) >= limit:
                    raise _Enough
            return
        v = todo[0]
        allowed = self.allowed.get(v)
        choices = _equal_shortcut(space, self.evals, v, b)
        if choices is None:
            if allowed is not None:
                choices = [a for t in allowed for a in space.get_by_type(t)]
            else:
                choices = list(space)
        for a in choices:
            if allowed is not None and not _admits(allowed, a):
                continue
            b2 = b.copy()
            b2[v] = a
            ok, rest = self._check_ready(space, pending, b2)
            if ok:
                self._enumerate(space, b2, rest, out, limit)


class _Enough(Exception):
    """Raised to stop a search once the asked number of groundings is found."""


def _equal_shortcut(space: AtomSpace, evals, v: Atom, b: Bindings) -> list[Atom] | None:  # noqa: ANN001
    """If an EqualLink ties ``v`` to a grounded atom, that atom is the only choice."""
    for atom, _vs in evals:
        if atom[0] in ("EqualLink", "IdenticalLink") and len(atom[1]) == 2:
            x, y = atom[1]
            other = y if x == v else x if y == v else None
            if other is None:
                continue
            g = substitute(other, b)
            if not _has_var_in(g, frozenset([v])) and not any(
                n[0] == "VariableNode" for n in _all_vars(g)
            ):
                found = space._find(g)  # the space's own instance: identity holds
                return [found] if found is not None else []
    return None


def _incoming(space: AtomSpace, atom: Atom):  # noqa: ANN202
    if space._parent is None:
        return space._incoming.get(atom, ())
    return space.incoming(atom)


def _estimate(space: AtomSpace, c: _Clause, b: Bindings) -> int:
    """An upper bound on the candidates of clause ``c``: its rarest anchor's incoming
    set, or the number of atoms of its type."""
    best = -1
    for is_var, x, _path in c.anchors:
        if is_var:
            a = b.get(x)
            if a is None:
                continue
        else:
            a = x
        n = len(_incoming(space, a))
        if best < 0 or n < best:
            best = n
            if n == 0:
                return 0
    if c.root_type == "VariableNode":
        return len(space)
    tcount = space.count_type(c.root_type)
    return tcount if best < 0 or tcount < best else best


def _candidates(space: AtomSpace, c: _Clause, b: Bindings):  # noqa: ANN202
    """Atoms that may ground clause ``c``, found from its rarest anchor upward."""
    flat = space._parent is None
    inc_get = space._incoming.get
    best = None
    best_n = -1
    for is_var, x, path in c.anchors:
        if is_var:
            a = b.get(x)
            if a is None:
                continue
        else:
            a = space._atoms.get(x) if flat else space._find(x)
            if a is None:  # a constant part that is not in the space: nothing matches
                return ()
        inc = inc_get(a, ()) if flat else space.incoming(a)
        n = len(inc)
        if best_n < 0 or n < best_n:
            best, best_n = (a, inc, path), n
            if n == 0:
                return ()
    typ = c.root_type
    if typ == "VariableNode":  # a bare variable clause: any atom of its declared types
        allowed = c.term.allowed
        if allowed is None:
            return list(space)
        return [a for t in allowed for a in space._type_set(t)]
    tcount = space.count_type(typ)
    if best is None or tcount <= best_n:
        # a copy: a grounded predicate called during the search may add atoms
        return list(space._by_type.get(typ, ())) if flat else list(space._type_set(typ))
    a, inc, path = best
    ltype, pos, path = path
    if pos is None:
        current = [lk for lk in inc if lk[0] == ltype]
    else:
        # members of a space are canonical: identity is equality here
        current = [lk for lk in inc if lk[0] == ltype and len(lk[1]) > pos and lk[1][pos] is a]
    while path is not None:
        ltype, pos, path = path
        if not current:
            return ()
        if pos is None:
            seen: set[Atom] = set()
            for x in current:
                for lk in inc_get(x, ()) if flat else space.incoming(x):
                    if lk[0] == ltype:
                        seen.add(lk)
            current = list(seen)
        else:
            nxt = []
            for x in current:
                for lk in inc_get(x, ()) if flat else space.incoming(x):
                    if lk[0] == ltype:
                        o = lk[1]
                        if len(o) > pos and o[pos] is x:
                            nxt.append(lk)
            current = nxt
    return current


def _exists(space: AtomSpace, clause: _Clause, b: Bindings) -> bool:
    """True if some grounding of ``clause`` (extending ``b``) is in the space."""
    if clause.literal and all(v in b for v in clause.vars):
        return substitute(clause.atom, b) in space
    for cand in _candidates(space, clause, b):
        if match(clause.term, cand, b):
            return True
    return False


# ---------------------------------------------------------------------- evaluation
def _eval_clause(space: AtomSpace, atom: Atom) -> bool:
    # through the space, which knows its evaluator: the matcher sits below execution.
    # A grounded predicate runs in a scratch space above the queried one, as OpenCog
    # runs it: what it creates while the query runs does not stay
    if atom[0] == "EvaluationLink" and atom[1] and atom[1][0][0] == "GroundedPredicateNode":
        return space.scratch().evaluate(atom).is_true()
    return space.evaluate(atom).is_true()


_CACHE: dict[tuple[Atom, Atom | None], Pattern] = {}
_CACHE_MAX = 4096


def compile_pattern(body: Atom, decl: Atom | None = None) -> Pattern:
    """The compiled pattern for ``body`` under ``decl`` (cached)."""
    key = (body, decl)
    p = _CACHE.get(key)
    if p is None:
        p = Pattern(body, decl)
        if len(_CACHE) >= _CACHE_MAX:
            _CACHE.clear()
        _CACHE[key] = p
    return p


def query(
    space: AtomSpace,
    body: Atom,
    variables: Atom | Iterable[Atom] | None = None,
    limit: int | None = None,
) -> list[Bindings]:
    """Every grounding of ``body`` in ``space``: a list of {variable: atom} dicts.

    ``variables`` is a declaration atom (VariableList, TypedVariableLink, a
    VariableNode) or an iterable of VariableNodes; by default every variable in the
    body is free.
    """
    if variables is None and limit is None:
        # The query asked most, one relation (R c (L a0 a1)) with one leaf known and the
        # other a variable, is answered right here from the relation index (see
        # fastpath): a call more would cost a tenth of its time. Its types are plain
        # relations once fast_query has met them (the first query of a type goes there);
        # everything else, joins included, goes to fast_query.
        if body.__class__ is Link and space._parent is None:
            # atoms are tuple subclasses, which Python unpacks more slowly than it
            # indexes them: hence body[0], body[1] rather than typ, out = body
            typ = body[0]
            out = body[1]
            if typ in _PLAIN and len(out) == 2:
                c, inner = out
                k = c[0]
                if (
                    c.__class__ is Node
                    and k != "VariableNode"
                    and (typ != "EvaluationLink" or k not in _EVAL_PREDICATES)
                ):
                    itype = inner[0]
                    leaves = inner[1]
                    # a plain type is a link type, so inner is a link
                    if itype in _PLAIN and len(leaves) == 2:
                        a0, a1 = leaves
                        # the variable leaf and the known one (a VariableNode is a
                        # node; the known leaf must be one too: a link may hold
                        # variables)
                        if a1[0] == "VariableNode":
                            known, pos, var = a0, 0, a1
                        else:
                            known, pos, var = a1, 1, a0
                        if (
                            var[0] == "VariableNode"
                            and known.__class__ is Node
                            and known[0] != "VariableNode"
                            and known[0] != "GlobNode"
                        ):
                            best = space._relations.get((known, pos, c, typ, itype, 2))
                            found = []
                            if best is not None:
                                for x in best:
                                    found.append({var: x})
                            return found
        found = fast_query(space, body)
        if found is not None:
            return found
    decl: Atom | None
    if variables is None or isinstance(variables, Atom):
        decl = variables  # type: ignore[assignment]
    else:
        decl = Link("VariableList", *variables)
    return compile_pattern(body, decl).groundings(space, limit)
