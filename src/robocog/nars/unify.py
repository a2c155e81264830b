"""Unification of a general term (with variables) against a specific one.

Only the general side's variables bind; the specific side's variables are ordinary
names, as in ONA. A query variable may not stand for a variable.
"""

from __future__ import annotations

from .terms import Bindings, Term, substitute


def unify(general: Term, specific: Term, query_only: bool = False) -> Bindings | None:
    """Bindings making ``general`` equal to ``specific``, or None."""
    if not general.has_var:
        return {} if general is specific else None
    b: Bindings = {}
    return b if _unify(general, specific, b, query_only) else None


def may_unify(general: Term, specific: Term) -> bool:
    """False when ``unify(general, specific)`` is sure to fail at its first look:
    another connector or number of components, or another term where ``general`` has
    a component without variables (ground terms are interned); else True, and unify
    decides. A test of a few fields, for loops that meet many terms few of which match."""
    if general.op is None:
        return True
    ga = general.args
    sa = specific.args
    if general.op != specific.op or len(ga) != len(sa):
        return False
    x: Term
    for i in range(len(ga)):
        x = ga[i]
        if not x.has_var and x is not sa[i]:
            return False
    return True


def _unify(g: Term, s: Term, b: Bindings, query_only: bool) -> bool:
    if g is s and not g.has_var:
        return True
    if g.op is None:
        if g.is_var and (not query_only or g.has_query_var):
            if g.has_query_var and s.is_var:
                return False
            got = b.get(g)
            if got is None:
                b[g] = s
                return True
            return got is s
        return g is s
    ga = g.args
    sa = s.args
    if g.op != s.op or len(ga) != len(sa):
        return False
    # a plain loop: a generator inside ``all`` costs a frame per argument on this hot path
    for x, y in zip(ga, sa):  # noqa: B905 - lengths checked above
        if x.has_var:
            if not _unify(x, y, b, query_only):
                return False
        elif x is not y:  # ground terms are interned: unifiable only if identical
            return False
    return True


def apply(term: Term, bindings: Bindings) -> Term:
    """``term`` with its bound variables replaced."""
    if not bindings or not term.has_var:
        return term
    return substitute(term, bindings)
