"""Atoms: Nodes (type, name) and Links (type, outgoing).

An atom is an immutable value: two atoms with the same type and name (or type and
outgoing set) are equal and hash alike, wherever they were built. That is what makes an
atom unique inside an AtomSpace, and lets search states share atoms freely. Atoms are
tuples underneath so that hashing and comparison run in C: the matcher does little else.
Unordered links sort their outgoing set when built, so every spelling of the same set
is one atom; tuples of atoms compare deterministically, so the order is the same in
every process.
"""

from __future__ import annotations

import gc
from collections.abc import Iterable, Iterator
from contextlib import contextmanager

from robocog.atomspace import types as _t


class Atom(tuple):
    """Base of Node and Link: a tuple ``(type, payload)``."""

    __slots__ = ()

    @property
    def type(self) -> str:
        """The atom's type name, e.g. ``"ConceptNode"``."""
        return self[0]

    def is_node(self) -> bool:
        """True for nodes."""
        return False

    def is_link(self) -> bool:
        """True for links."""
        return False

    def __repr__(self) -> str:
        return atom_text(self)

    __str__ = __repr__


class Node(Atom):
    """A node: a type and a name (its only identity)."""

    __slots__ = ()

    def __new__(cls, type: str, name: str) -> Node:
        full = _t.resolve(type)
        if full is None or full not in _t.NODE_TYPES:
            raise ValueError(f"{type!r} is not a node type")
        if not isinstance(name, str):
            raise ValueError(f"node name must be a string, not {name!r}")
        return tuple.__new__(cls, (full, name))

    @property
    def name(self) -> str:
        """The node's name."""
        return self[1]

    @property
    def out(self) -> tuple[Atom, ...]:
        """Nodes have an empty outgoing set."""
        return ()

    def is_node(self) -> bool:
        """True for nodes."""
        return True

    def __reduce__(self):  # noqa: ANN204 - pickling support
        return (Node, (self[0], self[1]))


class Link(Atom):
    """A link: a type and an outgoing tuple of atoms (sorted if the type is unordered)."""

    __slots__ = ()

    def __new__(cls, type: str, *out: Atom) -> Link:
        full = _t.resolve(type)
        if full is None or full not in _t.LINK_TYPES:
            raise ValueError(f"{type!r} is not a link type")
        for a in out:
            if not isinstance(a, Atom):
                raise ValueError(f"outgoing set of {full} holds a non-atom {a!r}")
        if full in _t.UNORDERED:
            return tuple.__new__(cls, (full, tuple(sorted(out))))
        return tuple.__new__(cls, (full, out))

    @classmethod
    def of(cls, type: str, out: Iterable[Atom]) -> Link:
        """Build a link from an iterable outgoing set."""
        return cls(type, *out)

    @property
    def out(self) -> tuple[Atom, ...]:
        """The outgoing set."""
        return self[1]

    @property
    def arity(self) -> int:
        """Number of atoms in the outgoing set."""
        return len(self[1])

    def is_link(self) -> bool:
        """True for links."""
        return True

    def __reduce__(self):  # noqa: ANN204 - pickling support
        return (Link, (self[0], *self[1]))


def _raw_link(type: str, out: tuple[Atom, ...]) -> Link:
    """Build a link from a resolved type and an outgoing tuple without checks.

    For hot paths that already hold canonical parts (substitution in the matcher).
    """
    if type in _t.UNORDERED:
        out = tuple(sorted(out))
    return tuple.__new__(Link, (type, out))


def _raw_node(type: str, name: str) -> Node:
    """Build a node from a resolved type without checks."""
    return tuple.__new__(Node, (type, name))


def has_variables(atom: Atom) -> bool:
    """True if a VariableNode occurs anywhere in ``atom``."""
    if atom.__class__ is Node:
        return atom[0] == "VariableNode"
    return any(has_variables(a) for a in atom[1])


#: the node types that stand for something to be found: a GlobNode stands for a run
VARIABLE_TYPES = frozenset({"VariableNode", "GlobNode"})


def variables_of(atom: Atom, found: list[Atom] | None = None) -> list[Atom]:
    """The VariableNodes and GlobNodes in ``atom`` in order of first appearance (not
    inside scopes)."""
    if found is None:
        found = []
    if atom.__class__ is Node:
        if atom[0] in VARIABLE_TYPES and atom not in found:
            found.append(atom)
        return found
    if atom[0] in _t.QUERY_TYPES or atom[0] == "LambdaLink":
        return found  # a nested scope binds its own variables
    if atom[0] == "QuoteLink":
        return _unquoted_variables(atom, found)  # quoted variables are literal atoms
    for a in atom[1]:
        if a.__class__ is Node:  # the node case above, without a call per leaf
            if a[0] in VARIABLE_TYPES and a not in found:
                found.append(a)
        else:
            variables_of(a, found)
    return found


def _unquoted_variables(atom: Atom, found: list[Atom]) -> list[Atom]:
    """The variables under the UnquoteLinks of a quoted atom."""
    if atom.__class__ is Node:
        return found
    for a in atom[1]:
        if a.__class__ is Link and a[0] == "UnquoteLink":
            variables_of(a, found)
        else:
            _unquoted_variables(a, found)
    return found


def constructor(type: str):  # noqa: ANN201 - returns a factory
    """A factory for one type: ``Concept = constructor("ConceptNode"); Concept("a")``."""
    full = _t.resolve(type)
    if full is None:
        raise ValueError(f"unknown type {type!r}")
    if full in _t.NODE_TYPES:

        def make_node(name: str) -> Node:
            return Node(full, name)

        make_node.__name__ = full
        return make_node

    def make_link(*out: Atom) -> Link:
        return Link(full, *out)

    make_link.__name__ = full
    return make_link


# ---------------------------------------------------------------------- text
def quote(name: str) -> str:
    """A node name as an Atomese string literal."""
    return '"' + name.replace("\\", "\\\\").replace('"', '\\"') + '"'


def atom_text(atom: Atom) -> str:
    """One-line Atomese for an atom: how an atom prints itself (the reader and the
    pretty printer are in :mod:`robocog.atomspace.atomese`)."""
    parts: list[str] = []
    _write_flat(atom, parts)
    return "".join(parts)


def _write_flat(atom: Atom, parts: list[str]) -> None:
    if atom.__class__ is Node or (isinstance(atom, Atom) and isinstance(atom[1], str)):
        parts.append(f"({atom[0]} {quote(atom[1])})")
        return
    parts.append("(" + atom[0])
    for a in atom[1]:
        parts.append(" ")
        _write_flat(a, parts)
    parts.append(")")


@contextmanager
def bulk() -> Iterator[None]:
    """Pause Python's cyclic garbage collector while adding many atoms.

    Atoms are tuples, which the collector tracks; during a load of 10^5-10^6 atoms its
    repeated passes over them take about half of the time. Atoms form no cycles, so
    nothing is lost by pausing it.
    """
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


#: the Python recursion limit while adding, printing or matching deep atoms: an atom
#: nested :data:`robocog.atomspace.atomese.MAX_NESTING` deep needs a few frames a level
DEEP_LIMIT = 12000


@contextmanager
def deep() -> Iterator[None]:
    """Raise Python's recursion limit for work on deeply nested atoms (adding, hashing,
    printing recurse once per level); restored afterwards."""
    import sys

    old = sys.getrecursionlimit()
    if old < DEEP_LIMIT:
        sys.setrecursionlimit(DEEP_LIMIT)
    try:
        yield
    finally:
        if old < DEEP_LIMIT:
            sys.setrecursionlimit(old)
