"""The search: a compiled pattern's alternatives solved against an AtomSpace, binding the
clause with the fewest candidates next and checking evaluatable and absent clauses as
soon as their variables are bound."""

from __future__ import annotations

from typing import TYPE_CHECKING

from robocog.atomspace.atoms import Atom, has_variables
from robocog.atomspace.matcher.clauses import (
    Alternative,
    Clause,
    all_vars,
    alternatives_of,
    clause_of,
    is_evaluatable,
    nodes_of,
)
from robocog.atomspace.matcher.terms import (
    Bindings,
    _self_ground,
    drop_self_groundings,
    has_var_in,
    match,
    substitute,
)
from robocog.atomspace.matcher.variables import PatternError, parse_variables, type_admits

if TYPE_CHECKING:
    from robocog.atomspace.space import AtomSpace


class Pattern:
    """A compiled pattern: variables, their types and the alternatives to search."""

    __slots__ = ("variables", "allowed", "alts", "body")

    def __init__(self, body: Atom, decl: Atom | None = None) -> None:
        self.body = body
        self.variables, self.allowed = parse_variables(decl, body)
        varset = frozenset(self.variables)
        self.alts: list[_CompiledAlt] = [
            _CompiledAlt(a, varset, self.allowed) for a in alternatives_of(body)
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

    def __init__(self, alt: Alternative, varset: frozenset[Atom], allowed: dict) -> None:
        self.allowed = allowed
        self.always = list(alt.always)
        self.order = list(alt.order)
        self.mandatory = [clause_of(c, varset, allowed) for c in alt.mandatory]
        self.bound_vars: set[Atom] = set()
        for c in self.mandatory:
            self.bound_vars |= c.vars
        # absent clauses: variables not bound elsewhere are local to the clause
        self.evals = [(e, frozenset(v for v in all_vars(e) if v in varset)) for e in alt.evals]
        self.eval_vars: set[Atom] = set()
        for _e, vs in self.evals:
            self.eval_vars |= vs
        bindable = self.bound_vars | self.eval_vars
        self.absent = []
        self.absent_vars: set[Atom] = set()
        for a in alt.absent:
            outer = frozenset(v for v in all_vars(a) if v in bindable)
            local = frozenset(v for v in all_vars(a) if v not in bindable)
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

    def _start_clause(self, space: AtomSpace) -> Clause | None:
        """The clause OpenCog's search would start from: the one holding the constant
        with the fewest links into it (the thinnest way in)."""
        best, best_n = None, -1
        for c in self.mandatory:
            for a in nodes_of(c.atom):
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
                    mine = frozenset(b)
                    if any(_self_ground(b[v], mine) for v in vs):
                        return False, rest  # the pattern found itself: never evaluated
                    if _grounded_call(atom) and any(has_variables(b[v]) for v in vs):
                        return False, rest  # user code is never handed another pattern's variables
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
        remaining: list[Clause],
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
            rest: list[Clause] = []
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
            for cand in candidates_of(space, clause, b):
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
        for cand in candidates_of(space, clause, b):
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
            if allowed is not None and not type_admits(allowed, a):
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
            if not has_var_in(g, frozenset([v])) and not any(
                n[0] == "VariableNode" for n in all_vars(g)
            ):
                found = space._find(g)  # the space's own instance: identity holds
                return [found] if found is not None else []
    return None


def _incoming(space: AtomSpace, atom: Atom):  # noqa: ANN202
    if space._parent is None:
        return space._incoming.get(atom, ())
    return space.incoming(atom)


def _estimate(space: AtomSpace, c: Clause, b: Bindings) -> int:
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


def candidates_of(space: AtomSpace, c: Clause, b: Bindings):  # noqa: ANN202
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


def _exists(space: AtomSpace, clause: Clause, b: Bindings) -> bool:
    """True if some grounding of ``clause`` (extending ``b``) is in the space."""
    if clause.literal and all(v in b for v in clause.vars):
        return substitute(clause.atom, b) in space
    for cand in candidates_of(space, clause, b):
        if match(clause.term, cand, b):
            return True
    return False


# ---------------------------------------------------------------------- evaluation
def _grounded_call(atom: Atom) -> bool:
    """Is ``atom`` an EvaluationLink over a GroundedPredicateNode (a call into user code)?"""
    return (
        atom[0] == "EvaluationLink" and bool(atom[1]) and atom[1][0][0] == "GroundedPredicateNode"
    )


def _eval_clause(space: AtomSpace, atom: Atom) -> bool:
    # through the space, which knows its evaluator: the matcher sits below execution.
    # A grounded predicate runs in a scratch space above the queried one, as OpenCog
    # runs it: what it creates while the query runs does not stay
    if atom[0] == "EvaluationLink" and atom[1] and atom[1][0][0] == "GroundedPredicateNode":
        return space.scratch().evaluate(atom).is_true()
    return space.evaluate(atom).is_true()
