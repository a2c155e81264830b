"""Pattern terms: a pattern atom compiled into terms that match atoms (one closure per
shape), matching with bindings, substitution of bindings into an atom."""

from __future__ import annotations

from collections.abc import Callable, Iterable

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import Atom, Link, Node, variables_of
from robocog.atomspace.matcher.variables import type_admits

Bindings = dict[Atom, Atom]


T_CONST, T_VAR, T_LINK, T_ULINK, T_CHOICE, T_GLOB = 0, 1, 2, 3, 4, 5


class PatternTerm:
    """A compiled pattern term."""

    __slots__ = ("kind", "atom", "type", "kids", "arity", "allowed", "multi", "fn")

    def __init__(self, kind: int, atom: Atom) -> None:
        self.kind = kind
        self.atom = atom
        self.type = atom[0]
        self.kids: tuple[PatternTerm, ...] = ()
        self.arity = 0
        self.allowed: frozenset[str] | None = None
        self.multi = False  # may yield more than one binding (unordered with variables)
        self.fn: Callable[[Atom, Bindings], Bindings | None] | None = None

    def seal(self) -> PatternTerm:
        """Build the matching closure of a variable or link term that yields at most
        one binding (constants are compared inline by their parents)."""
        if not self.multi and self.kind != T_CONST:
            self.fn = term_closure(self)
        return self


def term_closure(t: PatternTerm) -> Callable[[Atom, Bindings], Bindings | None]:
    """A function matching one atom against term ``t`` (specialised by its shape, so
    the matcher's inner loop does no dispatch)."""
    if t.kind == T_CONST:
        c = t.atom

        def const(a: Atom, b: Bindings) -> Bindings | None:
            return b if (a is c or a == c) else None

        return const
    if t.kind == T_VAR:
        var, allowed = t.atom, t.allowed

        def variable(a: Atom, b: Bindings) -> Bindings | None:
            v = b.get(var)
            if v is not None:
                return b if (v is a or v == a) else None
            if allowed is not None and not type_admits(allowed, a):
                return None
            nb = b.copy()
            nb[var] = a
            return nb

        return variable
    typ, n = t.type, t.arity
    consts = tuple((i, k.atom) for i, k in enumerate(t.kids) if k.kind == T_CONST)
    active = tuple((i, k.fn) for i, k in enumerate(t.kids) if k.kind != T_CONST)
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


def has_var_in(atom: Atom, varset: frozenset[Atom]) -> bool:
    if atom.__class__ is Node:
        return atom in varset
    return any(has_var_in(a, varset) for a in atom[1])


def _bind(t: PatternTerm, a: Atom, b: Bindings) -> Bindings | None:
    v = b.get(t.atom)
    if v is not None:
        return b if (v is a or v == a) else None
    if t.allowed is not None and not type_admits(t.allowed, a):
        return None
    nb = b.copy()
    nb[t.atom] = a
    return nb


def _match1(t: PatternTerm, a: Atom, b: Bindings) -> Bindings | None:
    """Match a term that yields at most one binding."""
    if t.kind == T_CONST:
        return b if (t.atom is a or t.atom == a) else None
    return t.fn(a, b)  # type: ignore[misc]


def match(t: PatternTerm, a: Atom, b: Bindings) -> list[Bindings]:
    """Every extension of ``b`` under which term ``t`` equals atom ``a``."""
    if not t.multi:
        r = _match1(t, a, b)
        return [] if r is None else [r]
    if t.kind == T_CHOICE:
        found: list[Bindings] = []
        for k in t.kids:
            for b2 in match(k, a, b):
                if b2 not in found:
                    found.append(b2)
        return found
    if t.kind == T_LINK and any(k.kind == T_GLOB for k in t.kids):
        if a.__class__ is not Link or a[0] != t.type:
            return []
        results: list[Bindings] = []
        _match_run(t.kids, 0, a[1], 0, b, results)
        return results
    if a.__class__ is not Link or a[0] != t.type or len(a[1]) != t.arity:
        return []
    if t.kind == T_LINK:
        bs = [b]
        for kt, x in zip(t.kids, a[1], strict=True):
            bs = [b2 for b1 in bs for b2 in match(kt, x, b1)]
            if not bs:
                return []
        return bs
    # unordered: give each pattern term a distinct outgoing atom, in every way
    results: list[Bindings] = []
    kids = sorted(t.kids, key=lambda k: k.kind != T_CONST)
    _match_unordered(kids, 0, list(a[1]), [False] * len(a[1]), b, results)
    return results


def _match_run(
    kids: tuple[PatternTerm, ...], i: int, out: tuple[Atom, ...], j: int, b: Bindings, results: list
) -> None:
    """Match pattern terms ``kids[i:]`` against atoms ``out[j:]``, a glob taking a run
    of one or more atoms (every length that lets the rest match)."""
    if i == len(kids):
        if j == len(out):
            results.append(b)
        return
    kt = kids[i]
    if kt.kind != T_GLOB:
        if j < len(out):
            for b2 in match(kt, out[j], b):
                _match_run(kids, i + 1, out, j + 1, b2, results)
        return
    need = sum(1 for k in kids[i + 1 :])  # each later term takes at least one atom
    bound = b.get(kt.atom)
    for end in range(j + 1, len(out) - need + 1):
        run = out[j:end]
        if kt.allowed is not None and not all(type_admits(kt.allowed, x) for x in run):
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
    kids: list[PatternTerm],
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
        # a nested query binds what it declares; the outer groundings reach the rest
        # (without a declaration every variable in it is its own)
        decl = atom[1][0] if atom[1] else None
        if decl is None or not (
            decl[0] in _t.VARIABLE_DECLS or (decl.__class__ is Node and decl[0] == "VariableNode")
        ):
            return atom
        own = set(variables_of(decl)) if decl.__class__ is not Node else {decl}
        if decl[0] == "TypedVariableLink":
            own = {decl[1][0]}
        elif decl[0] in ("VariableList", "VariableSet"):
            own = {d[1][0] if d[0] == "TypedVariableLink" else d for d in decl[1]}
        inner = {k: v for k, v in b.items() if k not in own}
        if not inner:
            return atom
        new = (decl, *[substitute(x, inner) for x in atom[1][1:]])
        if all(x is y for x, y in zip(new, atom[1], strict=True)):
            return atom
        return tuple.__new__(Link, (atom[0], tuple(new)))
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
