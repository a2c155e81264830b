"""Variable declarations: VariableList, TypedVariableLink and the type constraints
of OpenCog (TypeChoice, signatures, deep types), read into the types each variable admits."""

from __future__ import annotations

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import VARIABLE_TYPES, Atom, Link, Node, variables_of


class PatternError(ValueError):
    """A pattern the matcher cannot run (bad variable declaration, unused variable)."""


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


def type_admits(allowed: frozenset[str], atom: Atom) -> bool:
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
