"""ONA's conclusion filters: the derived terms it throws away before they reach memory.

Each filter is a pure function of the term, so ``rejected`` runs them once per term and
keeps the verdict on it. ``hol_component_invalid`` also judges the forms that variable
introduction makes (``rules.variable_forms``).
"""

from __future__ import annotations

from .terms import (
    CONJUNCTION,
    EQUIVALENCE,
    EXT_INTERSECTION,
    EXT_SET,
    F_JUNCTION_RIGHT_NESTED,
    IMPLICATION,
    INHERITANCE,
    INT_INTERSECTION,
    INT_SET,
    NEGATION,
    PRODUCT,
    SIMILARITY,
    Term,
    names_repeat,
)


def atom_appears_twice(t: Term) -> bool:
    """Filter: an -->/<-> statement naming an atom twice, or ==>/<=> with equal sides."""
    if t.op in (INHERITANCE, SIMILARITY):
        s = t.args[0]
        if not (s.op == "*" and len(s.args) == 2 and s.args[0].op == "*" and s.args[1].op == "*"):
            if names_repeat(t):
                return True
    if t.op in (IMPLICATION, EQUIVALENCE) and t.args[0] is t.args[1]:
        return True
    return False


def nested_hol_statement(t: Term) -> bool:
    """Filter: two ==>/<=> or more than two =/> in one term."""
    return t.n_imp >= 2 or t.n_temp > 2


def inh_or_sim_has_dep_var(t: Term) -> bool:
    """Filter: an -->/<-> statement with a dependent variable."""
    return t.op in (INHERITANCE, SIMILARITY) and t.has_dep_var


def junction_not_right_nested(t: Term) -> bool:
    """Filter: && or || whose right component is again && or ||."""
    return bool(t.flags & F_JUNCTION_RIGHT_NESTED)


def invalid_set_op(t: Term) -> bool:
    """Filter: intersections of sets that reductions should have merged."""
    if t.op == INHERITANCE:
        s, p = t.args
        if s.op == "&" and s.args[0].op == EXT_SET and s.args[1].op == EXT_SET:
            return True
        if p.op == "|" and p.args[0].op == INT_SET and p.args[1].op == INT_SET:
            return True
    return False


def dep_var_appears_once(t: Term) -> bool:
    """Filter: a dependent variable mentioned only once."""
    if not t.has_dep_var:
        return False
    counts: dict[Term, int] = {}
    for a in t.atoms():
        if a.has_dep_var:
            counts[a] = counts.get(a, 0) + 1
    return any(v == 1 for v in counts.values())


def conjunction_starts_with_operation(t: Term) -> bool:
    """Filter: a declarative implication whose condition conjunction starts with an op."""
    op = t.op
    if (op is IMPLICATION or op is EQUIVALENCE) and t.args[0].op is CONJUNCTION:
        s = t.args[0]
        while s.op is CONJUNCTION:
            first = s.args[0]
            if first.is_op:
                return True
            s = first
    return False


def hol_component_invalid(t: Term) -> bool:
    """Filter for variable introduction: components like ``<$1 --> $1>`` or var-only ones."""
    op = t.op
    if op is not IMPLICATION and op is not EQUIVALENCE and op is not CONJUNCTION:
        return False
    for comp in t.args:
        c = comp.args[0] if comp.op is NEGATION else comp
        cop = c.op
        if cop is INHERITANCE or cop is SIMILARITY:
            s, p = c.args
            if s is p or (s.is_var and p.is_var):
                return True
            if (s.op is None and not s.is_var) or (p.op is None and not p.is_var):
                continue  # a plain name on either side: not variables only
            if not c.index_names():  # its distinct names, cached on the term
                return True
    return False


def rejected(t: Term) -> bool:
    """True if a conclusion is one ONA's filters throw away (cached on the term)."""
    got = t.cache
    if got is None:
        got = t.cache = _rejected(t)
    return got


def _rejected(t: Term) -> bool:
    """The filters above in one pass (all pure, so the O(1) checks go first)."""
    if t.n_imp >= 2 or t.n_temp > 2 or t.flags & F_JUNCTION_RIGHT_NESTED:
        return True  # nested_hol_statement, junction_not_right_nested
    op = t.op
    # (connectors by identity: see ``terms.CONNECTORS``)
    if op is INHERITANCE or op is SIMILARITY:
        if t.has_dep_var:
            return True  # inh_or_sim_has_dep_var
        s, p = t.args
        if op is INHERITANCE and (
            (s.op is EXT_INTERSECTION and s.args[0].op is EXT_SET and s.args[1].op is EXT_SET)
            or (p.op is INT_INTERSECTION and p.args[0].op is INT_SET and p.args[1].op is INT_SET)
        ):
            return True  # invalid_set_op
        if s.op is None and p.op is None:
            if s is p and not s.is_var:
                return True  # atom_appears_twice on ``<a --> a>``
        elif not (
            s.op is PRODUCT
            and len(s.args) == 2
            and s.args[0].op is PRODUCT
            and s.args[1].op is PRODUCT
        ) and names_repeat(t):
            return True  # atom_appears_twice
        return False  # no dependent variable: dep_var_appears_once cannot hold
    if op is IMPLICATION or op is EQUIVALENCE:
        if t.args[0] is t.args[1]:
            return True  # atom_appears_twice
        if conjunction_starts_with_operation(t):
            return True
    return dep_var_appears_once(t)
