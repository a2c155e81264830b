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

from collections.abc import Iterable
from typing import TYPE_CHECKING

from robocog.atomspace.atoms import Atom, Link, Node
from robocog.atomspace.fastpath import _EVAL_PREDICATES, _PLAIN, fast_query
from robocog.atomspace.matcher.clauses import clause_of, clear_clauses, is_evaluatable
from robocog.atomspace.matcher.search import Pattern
from robocog.atomspace.matcher.terms import Bindings, drop_self_groundings, match, substitute
from robocog.atomspace.matcher.variables import (
    PatternError,
    TypeSet,
    is_variable_decl,
    parse_variables,
)

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace

__all__ = [
    "Bindings",
    "Pattern",
    "PatternError",
    "TypeSet",
    "clause_of",
    "clear_caches",
    "compile_pattern",
    "drop_self_groundings",
    "is_evaluatable",
    "is_variable_decl",
    "match",
    "parse_variables",
    "query",
    "substitute",
]

_CACHE: dict[tuple[Atom, Atom | None], Pattern] = {}
_CACHE_MAX = 4096


def clear_caches() -> None:
    """Forget every compiled pattern and clause, and the fast path's table of relation
    types, so that the next query of a pattern starts from its atom (as in a fresh
    process): what a benchmark's "cold" round measures."""
    _CACHE.clear()
    clear_clauses()
    _PLAIN.clear()


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
