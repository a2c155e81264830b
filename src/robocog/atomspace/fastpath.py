"""The matcher's fast path: conjunctions of plain relation clauses, read off the indexes.

Most queries a robot asks have one shape: a relation with some arguments known and some
asked, ``(EvaluationLink (PredicateNode "on") (ListLink B ?y))``, ``(InheritanceLink ?x
C)``, and conjunctions of these joined by shared variables. For them, compiling a
pattern (terms, closures, anchors) costs more than answering it, so this path reads the
pattern as it stands and answers from the space's indexes, compiling and caching
nothing. A relation ``(R c (L leaves...))`` is answered from the relation index
(``space.relation(...)``), whose entry for a known leaf holds exactly the relations with
that leaf at that place; any other plain clause from the incoming set of a known atom
(checked in full). A clause's variables, once bound, anchor the clauses joined to it,
and the clause with the fewest candidates is taken next, as in the general matcher.

The commonest shapes have their own code, as a query of them takes about a microsecond
and each call or step saved shows: one two-leaf relation with one leaf known is answered
by ``matcher.query`` itself, two joined by a variable by :func:`_two`, longer
conjunctions of relations by :func:`_pair_join`, other plain clauses by the rest of
:func:`fast_query`. None of them keeps anything between queries but ``_PLAIN``, the
table of which link types are plain relations, which depends on the type declarations
only, never on the store's contents.

Only what this path answers exactly as the general matcher would is taken: no variable
declaration (every variable free and untyped), no limit, a flat space, and clauses that
are ordered links of ordinary relation types holding nodes and ordered links of nodes.
Anything else (typed variables, Present/Absent/Not/Or, evaluatable clauses, unordered
links, deeper nesting, frames) returns None and goes to the general matcher. The
groundings are the same; like the general matcher's, their order follows the index
sets' and is not part of the contract.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import Atom, Link, Node

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace

Bindings = dict[Atom, Atom]

#: ordered link types that mean more to the matcher than a relation to look up
_NOT_PLAIN = frozenset(
    {
        "NotLink",
        "AbsentLink",
        "GreaterThanLink",
        "ExecutionOutputLink",
        "LambdaLink",
        "PutLink",
        "QuoteLink",
        "UnquoteLink",
        "TypedVariableLink",
        "VariableList",
        "SignatureLink",
        "TypeChoice",
        "SequentialAndLink",
        "DeleteLink",
    }
)
_EVAL_PREDICATES = frozenset({"GroundedPredicateNode", "DefinedPredicateNode"})
_VAR = "VariableNode"
#: a run of atoms: the general matcher's work, never a plain clause's
_GLOB = "GlobNode"


#: the ordered link types the matcher treats as plain relations, as they are met (a set,
#: as membership is the cheapest test on the hot path; an atom of a type exists only
#: once the type is declared, and a declaration never changes, so a member stays one)
_PLAIN: set[str] = set()


def _plain(t: str) -> bool:
    """True for an ordered link type the matcher treats as a plain relation (and then
    remembered in ``_PLAIN``; other types are answered afresh, as they leave this path)."""
    if t in _PLAIN:
        return True
    ok = (
        t in _t.LINK_TYPES
        and t not in _t.UNORDERED
        and t not in _NOT_PLAIN
        and t not in _t.QUERY_TYPES
        and not _t.is_a(t, "PatternLink")
    )
    if ok:
        _PLAIN.add(t)
    return ok


class _NoMatch(Exception):
    """A constant of the pattern is not in the space: no grounding at all."""


def _read(clause: Atom, atoms: dict) -> tuple | None:
    """``(type, arity, direct, nested, vars)`` of a plain clause, or None.

    direct: ``(i, atom, is_var)`` for each node at position i; nested: ``(i, type,
    arity, leaves)`` for each link of nodes at position i, leaves ``(j, atom, is_var)``.
    Constants are replaced by the space's own instances (identity is then equality).
    """
    if clause.__class__ is not Link:
        return None
    typ = clause[0]
    if not _plain(typ):
        return None
    out = clause[1]
    if typ == "EvaluationLink" and out and out[0][0] in _EVAL_PREDICATES:
        return None
    direct = []
    nested = []
    vs = []
    for i, x in enumerate(out):
        if x.__class__ is Node:
            if x[0] == _GLOB:
                return None
            if x[0] == _VAR:
                direct.append((i, x, True))
                vs.append(x)
            else:
                c = atoms.get(x)
                if c is None:
                    raise _NoMatch
                direct.append((i, c, False))
            continue
        if x.__class__ is not Link or not _plain(x[0]):
            return None
        leaves = []
        for j, y in enumerate(x[1]):
            if y.__class__ is not Node or y[0] == _GLOB:
                return None
            if y[0] == _VAR:
                leaves.append((j, y, True))
                vs.append(y)
            else:
                c = atoms.get(y)
                if c is None:
                    raise _NoMatch
                leaves.append((j, c, False))
        if any(is_var for _j, _a, is_var in leaves):
            nested.append((i, x[0], len(x[1]), tuple(leaves)))
        else:  # a ground link: one constant
            c = atoms.get(x)
            if c is None:
                raise _NoMatch
            direct.append((i, c, False))
    return typ, len(out), tuple(direct), tuple(nested), vs


def _check(link: Atom, clause: tuple, b: Bindings) -> Bindings | None:
    """``b`` extended so that ``link`` grounds the clause, or None."""
    _typ, n, direct, nested, _vs = clause
    out = link[1]
    if len(out) != n:
        return None
    nb = b
    for i, a, is_var in direct:
        x = out[i]
        if is_var:
            v = nb.get(a)
            if v is None:
                if nb is b:
                    nb = b.copy()
                nb[a] = x
            elif v is not x:
                return None
        elif x is not a:
            return None
    for i, itype, m, leaves in nested:
        inner = out[i]
        if inner.__class__ is not Link or inner[0] != itype:
            return None
        io = inner[1]
        if len(io) != m:
            return None
        for j, a, is_var in leaves:
            x = io[j]
            if is_var:
                v = nb.get(a)
                if v is None:
                    if nb is b:
                        nb = b.copy()
                    nb[a] = x
                elif v is not x:
                    return None
            elif x is not a:
                return None
    return nb


def _candidates(space: AtomSpace, clause: tuple, b: Bindings) -> tuple[int, object]:
    """(size, links) for the clause's rarest anchor under ``b``: a known node of the
    clause gives its incoming set, a known leaf one link down the links above its
    incoming links of the right type and place (supersets, checked in full later);
    with nothing known, the type's atoms."""
    typ = clause[0]
    best_n = -1
    best: object = ()
    inc_get = space._incoming.get
    for _i, a, is_var in clause[2]:
        if is_var:
            a = b.get(a)
            if a is None:
                continue
        s = inc_get(a)
        if s is None:
            return 0, ()
        n = len(s)
        if best_n < 0 or n < best_n:
            best_n, best = n, s
    for _i, itype, _m, leaves in clause[3]:
        for j, a, is_var in leaves:
            if is_var:
                a = b.get(a)
                if a is None:
                    continue
            s = inc_get(a)
            if s is None:
                return 0, ()
            if best_n >= 0 and len(s) >= best_n:
                continue
            up: set = set()
            for lk in s:
                if lk[0] == itype and len(lk[1]) > j and lk[1][j] is a:
                    up.update(inc_get(lk, ()))
            best_n, best = len(up), up
            if not up:
                return 0, ()
    if best_n < 0:
        s = space._by_type.get(typ, ())
        return len(s), s
    return best_n, best


def fast_query(space: AtomSpace, body: Atom) -> list[Bindings] | None:
    """Every grounding of ``body`` (no declaration, every variable free), or None if
    the body is not a conjunction of plain clauses (then the general matcher runs)."""
    if body.__class__ is not Link or space._parent is not None:
        return None
    typ, out = body
    if typ == "AndLink":
        if len(out) == 2:
            found = _two(space._relations.get, out[0], out[1])
            if found is not None:
                return found
        pairs = []
        for c in out:
            pc = _pair_clause(c)
            if pc is None:
                break
            pairs.append(pc)
        else:
            if pairs:
                found = []
                if _pair_join(space._relations.get, pairs, _NO_BINDINGS, found):
                    return found
    else:
        pc = _pair_clause(body)
        if pc is not None:
            one = _pair_one(space._relations.get, pc)
            if one is not None:
                return one
    atoms = space._atoms
    try:
        if body[0] == "AndLink":
            clauses = []
            for c in body[1]:
                r = _read(c, atoms)
                if r is None:
                    return None
                clauses.append(r)
            if not clauses:
                return None
        else:
            r = _read(body, atoms)
            if r is None:
                return None
            clauses = [r]
    except _NoMatch:
        return []
    if len(clauses) == 1:
        clause = clauses[0]
        if not clause[4]:
            ground = body[1][0] if body[0] == "AndLink" else body
            return [{}] if ground in atoms else []
        typ = clause[0]
        _n, cands = _candidates(space, clause, {})
        out = []
        empty: Bindings = {}
        for link in cands:
            if link[0] == typ:
                nb = _check(link, clause, empty)
                if nb is not None:
                    out.append(nb)
        return out
    out = []
    _join(space, clauses, {}, out)
    return out


def _join(space: AtomSpace, clauses: list, b: Bindings, out: list[Bindings]) -> None:
    """Ground the clauses one at a time, the one with the fewest candidates first."""
    best_i, best_n, best = -1, -1, None
    for k, c in enumerate(clauses):
        n, s = _candidates(space, c, b)
        if n == 0:
            return
        if best_n < 0 or n < best_n:
            best_i, best_n, best = k, n, s
    clause = clauses[best_i]
    rest = clauses[:best_i] + clauses[best_i + 1 :]
    typ = clause[0]
    if not rest:
        for link in best:  # type: ignore[attr-defined]
            if link[0] == typ:
                nb = _check(link, clause, b)
                if nb is not None:
                    out.append(nb if nb is not b else b.copy())
        return
    for link in best:  # type: ignore[attr-defined]
        if link[0] == typ:
            nb = _check(link, clause, b)
            if nb is not None:
                _join(space, rest, nb, out)


# ---------------------------------------------------------------------- relations
# The commonest clause of all, ``(R c (L leaves...))`` with a constant node ``c`` and
# nodes as leaves (``(EvaluationLink (PredicateNode "on") (ListLink B ?y))``), answered
# from the space's relation index: the entry of a known leaf holds exactly the inner
# links ``(L ...)`` of the relations with ``c``, ``R``, ``L``, that leaf at that place and
# that many leaves, so only the other leaves are left to check or bind (for the usual
# two leaves: one).
_NO_BINDINGS: Bindings = {}


def _pair_clause(clause: Atom) -> tuple | None:
    """``(R, c, L, leaves, arity)`` of a clause ``(R c (L leaves...))``; None for any
    other shape."""
    if clause.__class__ is not Link:
        return None
    typ, out = clause
    if len(out) != 2 or not (typ in _PLAIN or _plain(typ)):
        return None
    c, inner = out
    if c.__class__ is not Node or inner.__class__ is not Link or c[0] in (_VAR, _GLOB):
        return None
    if typ == "EvaluationLink" and c[0] in _EVAL_PREDICATES:
        return None
    itype, leaves = inner
    if not (itype in _PLAIN or _plain(itype)):
        return None
    for a in leaves:
        if a.__class__ is not Node or a[0] == _GLOB:
            return None
    return typ, c, itype, leaves, len(leaves)


def _two(rel_get, p: Atom, q: Atom, atoms: bool = False) -> list | None:  # noqa: ANN001, C901
    """Every grounding of ``(AndLink p q)`` when p and q are clauses ``(R c (L a0 a1))``
    with node leaves joined by a variable, such as ``on(B, ?y), on(?y, ?z)``; None for
    any other shape (then :func:`_pair_join` or the general matcher answers).
    With ``atoms``, each grounding is given as a GetLink gives it (see :func:`get_set`).

    The rarest known leaf anchors one clause; each atom that gives the variable at that
    clause's other end is looked up in the other clause. The two clauses are read here
    rather than by a helper, as reading them is a third of the query's time.
    """
    if p.__class__ is not Link or q.__class__ is not Link:
        return None
    # atoms are indexed rather than unpacked: Python unpacks tuple subclasses slowly
    pt = p[0]
    po = p[1]
    qt = q[0]
    qo = q[1]
    if len(po) != 2 or len(qo) != 2:
        return None
    if not (pt in _PLAIN or _plain(pt)) or not (qt in _PLAIN or _plain(qt)):
        return None
    pc, pi = po
    qc, qi = qo
    if (
        pc.__class__ is not Node
        or qc.__class__ is not Node
        or pc[0] == "VariableNode"
        or qc[0] == "VariableNode"
        or pt == "EvaluationLink"
        and pc[0] in _EVAL_PREDICATES
        or qt == "EvaluationLink"
        and qc[0] in _EVAL_PREDICATES
    ):
        return None
    # a plain type is a link type: pi and qi are links once their types are plain
    pit = pi[0]
    qit = qi[0]
    if not (pit in _PLAIN or _plain(pit)) or not (qit in _PLAIN or _plain(qit)):
        return None
    pl = pi[1]
    ql = qi[1]
    if len(pl) != 2 or len(ql) != 2:
        return None
    p0, p1 = pl
    q0, q1 = ql
    if (
        p0.__class__ is not Node
        or p1.__class__ is not Node
        or q0.__class__ is not Node
        or q1.__class__ is not Node
    ):
        return None
    # the anchor: the known leaf with the fewest relations; v the leaf at its other end
    best = v = None
    anchored_p = True
    for leaf, i, c, typ, itype, other, in_p in (
        (p0, 0, pc, pt, pit, p1, True),
        (p1, 1, pc, pt, pit, p0, True),
        (q0, 0, qc, qt, qit, q1, False),
        (q1, 1, qc, qt, qit, q0, False),
    ):
        if leaf[0] != "VariableNode":
            s = rel_get((leaf, i, c, typ, itype, 2))
            if s is None:
                return []
            if best is None or len(s) < len(best):
                best, v, anchored_p = s, other, in_p
    if best is None or v[0] != "VariableNode":
        return None
    if anchored_p:
        typ, c, itype, b0, b1 = qt, qc, qit, q0, q1
    else:
        typ, c, itype, b0, b1 = pt, pc, pit, p0, p1
    # the other clause, looked up by v at position j; w is its other leaf
    if b0 == v:
        j, w = 0, b1
    elif b1 == v:
        j, w = 1, b0
    else:
        return None  # no shared variable: a product, left to _pair_join
    found: list = []
    if w[0] != "VariableNode" or w == v:
        # w is known: a constant, or v again
        for x in best:
            s = rel_get((x, j, c, typ, itype, 2))
            if s is not None and (x if w == v else w) in s:
                found.append(x if atoms else {v: x})
        if atoms:
            found.sort()  # the SetLink's order
        return found
    if not atoms:
        for x in best:
            s = rel_get((x, j, c, typ, itype, 2))
            if s is not None:
                for z in s:
                    found.append({v: x, w: z})
        return found
    # a ListLink in the order the variables first appear in the body, in the SetLink's
    # order: the pairs are sorted before they become links, as comparing plain pairs
    # costs two thirds of comparing the links
    for x in best:
        s = rel_get((x, j, c, typ, itype, 2))
        if s is not None:
            for z in s:
                found.append((x, z))
    if next(a for a in (p0, p1, q0, q1) if a == v or a == w) != v:
        found = [(z, x) for x, z in found]
    found.sort()
    new = tuple.__new__
    return [new(Link, ("ListLink", pair)) for pair in found]


def get_set(space: AtomSpace, body: Atom) -> list[Atom] | None:
    """The members of the SetLink a GetLink of ``body`` (no declaration) returns, in the
    SetLink's order, read straight off the relation index for the two shapes asked most: one relation
    with one leaf known and one variable, and two such relations joined by a variable
    (a ListLink of the two variables in order of appearance). None for anything else,
    which then goes through the groundings as dicts."""
    if body.__class__ is not Link or space._parent is not None:
        return None
    if body[0] == "AndLink":
        out = body[1]
        if len(out) != 2:
            return None
        return _two(space._relations.get, out[0], out[1], True)
    pc = _pair_clause(body)
    return None if pc is None else _pair_one(space._relations.get, pc, True)


def _pair_one(rel_get, clause: tuple, atoms: bool = False) -> list | None:  # noqa: ANN001
    """Every grounding of one ``(R c (L leaves...))`` clause (None if no leaf is a
    constant); the single-clause case of :func:`_pair_join`, unrolled for two leaves
    because it is the query asked most. With ``atoms``, the groundings of its one
    variable as a GetLink gives them (sorted), or None for any other shape."""
    typ, c, itype, leaves, m = clause
    if m == 2:
        a0, a1 = leaves
        if a0[0] == _VAR:
            if a1[0] == _VAR:
                return None
            best = rel_get((a1, 1, c, typ, itype, 2))
            v = a0
        else:
            best = rel_get((a0, 0, c, typ, itype, 2))
            if a1[0] != _VAR:  # ground
                if atoms:
                    return None  # a GetLink without variables: the general answer
                return [{}] if best is not None and a1 in best else []
            v = a1
        if best is None:
            return []
        return sorted(best) if atoms else [{v: x} for x in best]
    if atoms:
        return None
    found: list[Bindings] = []
    if _pair_join(rel_get, [clause], _NO_BINDINGS, found):
        return found
    return None


def _pair_join(rel_get, clauses: list, b: Bindings, out: list[Bindings]) -> bool:  # noqa: ANN001
    """Append to ``out`` every grounding of the clauses extending ``b``, grounding
    first the clause whose rarest known leaf has the fewest links; False if at some
    point no clause has a known leaf (the caller then drops ``out`` and takes the
    general path)."""
    best = None
    best_k = best_j = -1
    k = 0
    for typ, c, itype, leaves, m in clauses:
        j = 0
        for a in leaves:
            if a[0] == _VAR:
                a = b.get(a)
                if a is None:
                    j += 1
                    continue
            s = rel_get((a, j, c, typ, itype, m))
            if s is None:
                return True  # this clause has no grounding: nor has the conjunction
            if best is None or len(s) < len(best):
                best, best_k, best_j = s, k, j
            j += 1
        k += 1
    if best is None:
        return False
    leaves, m = clauses[best_k][3:]
    rest = clauses[:best_k] + clauses[best_k + 1 :]
    last2 = rest[0] if len(rest) == 1 and rest[0][4] == 2 else None
    if m == 2:
        # the index has checked the known leaf; one leaf is left
        oj = 1 - best_j
        other = leaves[oj]
        bind = want = None
        if other[0] == _VAR:
            want = b.get(other)
            if want is None:
                bind = other
        else:
            want = other
        if bind is not None and rest:
            # one dict for every candidate: what is called next copies before keeping
            nb = b.copy()
            for x in best:
                nb[bind] = x
                if last2 is not None:
                    if not _last2(rel_get, last2, nb, out):
                        return False
                elif not _pair_join(rel_get, rest, nb, out):
                    return False
            return True
        for x in best:
            if bind is not None:
                nb = b.copy()
                nb[bind] = x
            elif x is want or x == want:
                nb = b if rest else b.copy()
            else:
                continue
            if not rest:
                out.append(nb)
            elif last2 is not None:
                if not _last2(rel_get, last2, nb, out):
                    return False
            elif not _pair_join(rel_get, rest, nb, out):
                return False
        return True
    for inner in best:
        io = inner[1]
        nb = b.copy()
        j = 0
        for a in leaves:
            x = io[j]
            j += 1
            if a[0] == _VAR:
                if nb.setdefault(a, x) is x:
                    continue
            elif x is a or x == a:
                continue
            break
        else:
            if not rest:
                out.append(nb)
            elif not _pair_join(rel_get, rest, nb, out):
                return False
    return True


def _last2(rel_get, clause: tuple, b: Bindings, out: list[Bindings]) -> bool:  # noqa: ANN001
    """The last clause of a join when it has two leaves: :func:`_pair_join` for one
    clause, unrolled (it runs once per grounding of the clauses before it)."""
    typ, c, itype, (a0, a1), _m = clause
    x0 = b.get(a0) if a0[0] == _VAR else a0
    x1 = b.get(a1) if a1[0] == _VAR else a1
    if x0 is not None:
        s = rel_get((x0, 0, c, typ, itype, 2))
        if s is None:
            return True
        if x1 is not None:  # both leaves known
            if x1 in s:
                out.append(b.copy())
            return True
        bind = a1
    elif x1 is not None:
        s = rel_get((x1, 1, c, typ, itype, 2))
        if s is None:
            return True
        bind = a0
    else:
        return False
    for x in s:
        nb = b.copy()
        nb[bind] = x
        out.append(nb)
    return True
