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
