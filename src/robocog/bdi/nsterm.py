"""A literal whose namespace is a variable: Jason's ``Ns::propose(P)``.

robocog keeps a namespace in the functor (``hall::propose``), which costs nothing where
the namespace is written. Where it is a variable, the literal is a :class:`NsLiteral`:
the variable and the literal without a namespace. Once the variable has a value the
literal is an ordinary one (:func:`ns_resolve`); while it has none it unifies with a
literal of any namespace, binding the variable to that namespace (the default
namespace is the atom ``default``), which is how a plan for ``+N::cnp_started`` is
relevant for the event ``+hall::cnp_started`` with ``N = hall``.
"""

from __future__ import annotations

from collections.abc import Callable

from robocog.bdi.terms import NS_SEP, Literal, Term, Var, term_str

#: the namespace of a literal written without one
DEFAULT = "default"


class NsLiteral:
    """``ns::lit`` with ``ns`` a variable (or, after substitution, any term)."""

    __slots__ = ("ns", "lit")

    ground = False

    def __init__(self, ns: Term, lit: Literal) -> None:
        self.ns = ns
        self.lit = lit

    def __eq__(self, other: object) -> bool:
        return isinstance(other, NsLiteral) and self.ns is other.ns and self.lit == other.lit

    def __hash__(self) -> int:
        return hash((id(self.ns), self.lit))

    def __str__(self) -> str:
        return f"{term_str(self.ns)}{NS_SEP}{term_str(self.lit)}"

    __repr__ = __str__


def split_ns(lit: Literal) -> tuple[str, Literal]:
    """A literal's namespace and the literal without it (``default`` when it has none)."""
    f = lit.functor
    if NS_SEP not in f or f.startswith("'"):
        return DEFAULT, lit
    ns, _sep, base = f.rpartition(NS_SEP)
    return ns, Literal(base, lit.args, lit.annots, lit.neg)


def with_ns(ns: str, lit: Literal) -> Literal:
    """``lit`` (written without a namespace) in namespace ``ns``."""
    if ns == DEFAULT:
        return lit
    return Literal(f"{ns}{NS_SEP}{lit.functor}", lit.args, lit.annots, lit.neg)


def ns_resolve(t: NsLiteral, s: dict, fresh: dict | None, resolve: Callable) -> Term:
    """``t`` under ``s``: an ordinary literal when its namespace has a value (an atom),
    else a :class:`NsLiteral` of the resolved parts."""
    ns = resolve(t.ns, s, fresh)
    lit = resolve(t.lit, s, fresh)
    if ns.__class__ is Literal and not ns.args and lit.__class__ is Literal:
        return with_ns(ns.functor, lit)
    return NsLiteral(ns, lit)


def ns_unify(a: NsLiteral, b: Term, s: dict, trail: list, unify: Callable) -> bool:
    """Unify a literal with a variable namespace with ``b`` (either kind of literal)."""
    if b.__class__ is NsLiteral:
        return unify(a.ns, b.ns, s, trail) and unify(a.lit, b.lit, s, trail)
    if b.__class__ is not Literal:
        return False
    ns, base = split_ns(b)
    return unify(a.ns, Literal(ns), s, trail) and unify(a.lit, base, s, trail)


def ns_rename(t: NsLiteral, rename: Callable) -> NsLiteral:
    """``t`` with its variables renamed by ``rename`` (a plan's fresh copy)."""
    return NsLiteral(rename(t.ns), rename(t.lit))


def is_var_ns(t: Term) -> bool:
    """Whether ``t`` is a literal whose namespace is still a variable."""
    return t.__class__ is NsLiteral and t.ns.__class__ is Var
