"""The AtomSpace: a set of unique atoms with incoming sets, type index and Values.

Three layouts serve the planner, which keeps one state per search node:

- a flat space owns its atoms and indexes;
- ``space.child()`` makes a frame: it sees its parent (live), adds atoms of its own and
  can hide parent atoms by removing them, without touching the parent;
- ``space.copy()`` makes an independent flat space that shares the index sets with the
  original until one side writes to them (copy-on-write per entry), so a copy costs one
  dict copy per index and nothing per atom.

Every atom in a space has its outgoing atoms in the same space, and the incoming set of
an atom is the set of links in the space that hold it. Removing an atom that is still
held by a link is refused unless the removal is recursive, as OpenCog's ``cog-extract!``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import Any

from robocog.atomspace import types as _t
from robocog.atomspace.atoms import Atom, Link, Node
from robocog.atomspace.execute import evaluate as _evaluate
from robocog.atomspace.execute import execute as _execute
from robocog.atomspace.values import DEFAULT_TV, TruthValue, Value

_EMPTY: frozenset = frozenset()
#: link types of which only one may exist per first atom (OpenCog's UniqueLink)
_UNIQUE_KEYED = frozenset({"StateLink", "DefineLink"})
#: link types that do something when added
_ON_ADD = _UNIQUE_KEYED | {"DeleteLink"}


def _refuse_held_deletes(out: tuple[Atom, ...]) -> None:
    """Refuse (before anything is added) a link that holds a closed DeleteLink: the
    DeleteLink can never be in a space, so neither can a link holding it."""
    for x in out:
        if x[0] == "DeleteLink" and x.__class__ is Link and is_closed(x):
            raise ValueError(f"a link cannot hold a DeleteLink without variables: {x}")


def is_closed(atom: Atom) -> bool:
    """True if no VariableNode or GlobNode occurs in ``atom`` (OpenCog's is_closed)."""
    if atom.__class__ is Node:
        return atom[0] not in ("VariableNode", "GlobNode")
    return all(is_closed(a) for a in atom[1])


#: a grounded function: called with the space and the argument atoms
GroundedFunction = Callable[..., Any]

#: functions every space can call by name when its own table lacks them
GLOBAL_FUNCTIONS: dict[str, GroundedFunction] = {}


def register_function(name: str, fn: GroundedFunction) -> None:
    """Register ``fn`` under ``name`` for every AtomSpace (``py:name`` in Atomese)."""
    if not callable(fn):
        raise TypeError(f"{name}: {fn!r} is not callable")
    GLOBAL_FUNCTIONS[name] = fn


def _relation_keys(link: Atom) -> list[tuple[tuple, Atom]]:
    """The (key, member) entries of ``link`` in the relation index, if it is a relation
    ``(R c (L leaves...))`` (a node, then a link): one per leaf, keyed ``(leaf, its
    position, c, R, L, number of leaves)``. For two leaves the member is the other leaf
    (the relation is then determined by the key and the member, and a query reads its
    answer straight from the set); otherwise it is the inner link ``(L ...)``."""
    out = link[1]
    if len(out) != 2:
        return []
    c, inner = out
    if c.__class__ is not Node or inner.__class__ is not Link:
        return []
    typ = link[0]
    itype, leaves = inner
    m = len(leaves)
    if m == 2:
        y0, y1 = leaves
        return [((y0, 0, c, typ, itype, 2), y1), ((y1, 1, c, typ, itype, 2), y0)]
    return [((y, j, c, typ, itype, m), inner) for j, y in enumerate(leaves)]


class AtomSpace:
    """A typed hypergraph of unique atoms with truth values and key-value Values."""

    __slots__ = (
        "_atoms",
        "_incoming",
        "_by_type",
        "_tv",
        "_values",
        "_parent",
        "_hidden",
        "_owned_inc",
        "_owned_typ",
        "_relations",
        "_owned_rel",
        "functions",
        "name",
        "_scratch",
    )

    def __init__(self, parent: AtomSpace | None = None, name: str = "") -> None:
        self._atoms: dict[Atom, Atom] = {}
        self._incoming: dict[Atom, set[Link]] = {}
        self._by_type: dict[str, set[Atom]] = {}
        self._tv: dict[Atom, TruthValue] = {}
        self._values: dict[Atom, dict[Atom, Value]] = {}
        self._parent = parent
        self._hidden: set[Atom] = set()
        # copy-on-write bookkeeping: None = every set is ours; else the keys we own
        self._owned_inc: set[Atom] | None = None
        self._owned_typ: set[str] | None = None
        # the relation index: (leaf, position, c, R, L, arity) -> the inner links of
        # the relations (R c (L ... leaf ...)) in the space (see _relation_keys)
        self._relations: dict[tuple, set[Link]] = {}
        self._owned_rel: set[tuple] | None = None
        self.functions: dict[str, GroundedFunction] = parent.functions if parent is not None else {}
        self.name = name
        # a scratch space keeps the atoms made in it; a value set on any other atom
        # goes to the parent (with the atom), as a value set during a query stays
        self._scratch = False

    def scratch(self) -> AtomSpace:
        """A temporary space above this one, for what a grounded predicate makes
        while a query runs: atoms it adds stay in it, values it sets do not."""
        child = AtomSpace(parent=self, name=f"{self.name}:scratch")
        child._scratch = True
        return child

    # ------------------------------------------------------------------ frames/copies
    @property
    def parent(self) -> AtomSpace | None:
        """The space this frame sees through, or None for a flat space."""
        return self._parent

    def child(self, name: str = "") -> AtomSpace:
        """A frame over this space: sees it live, changes only itself."""
        return AtomSpace(parent=self, name=name)

    def copy(self, name: str = "") -> AtomSpace:
        """An independent flat space with the same atoms, Values and functions.

        The index sets are shared copy-on-write, so the cost is a few dict copies.
        """
        if self._parent is not None:
            new = AtomSpace(name=name)
            new.functions = self.functions
            for a in self:
                new._insert_canonical(a)
            for a in self:
                tv = self.get_tv_or_none(a)
                if tv is not None:
                    new._tv[a] = tv
                vals = self._find_values(a)
                if vals:
                    new._values[a] = dict(vals)
            return new
        new = AtomSpace(name=name)
        new.functions = self.functions
        new._atoms = self._atoms.copy()
        new._incoming = self._incoming.copy()
        new._by_type = self._by_type.copy()
        new._tv = self._tv.copy()
        new._values = self._values.copy()  # inner dicts are replaced, never mutated
        new._relations = self._relations.copy()
        self._owned_inc = set()
        self._owned_typ = set()
        self._owned_rel = set()
        new._owned_inc = set()
        new._owned_typ = set()
        new._owned_rel = set()
        return new

    # ------------------------------------------------------------------ lookup
    def _find(self, atom: Atom) -> Atom | None:
        """The canonical instance of ``atom`` visible here, or None."""
        s: AtomSpace | None = self
        while s is not None:
            found = s._atoms.get(atom)
            if found is not None:
                return found
            if s._hidden and atom in s._hidden:
                return None
            s = s._parent
        return None

    def __contains__(self, atom: object) -> bool:
        if self._parent is None:
            return atom in self._atoms
        return isinstance(atom, Atom) and self._find(atom) is not None

    def contains(self, atom: Atom) -> bool:
        """True if ``atom`` is in this space (or visible through its parents)."""
        return atom in self

    def __len__(self) -> int:
        if self._parent is None:
            return len(self._atoms)
        return len(self._atoms) + len(self._parent) - len(self._hidden)

    def __iter__(self) -> Iterator[Atom]:
        yield from self._atoms
        if self._parent is not None:
            hidden = self._hidden
            for a in self._parent:
                if a not in hidden:
                    yield a

    def atoms(self) -> list[Atom]:
        """Every atom visible in this space."""
        return list(self)

    def signature(self) -> frozenset[Atom]:
        """The set of visible atoms, hashable: two states with equal signatures hold
        the same atoms (the planner's test for a state already seen)."""
        if self._parent is None:
            return frozenset(self._atoms)
        return frozenset(self)

    def incoming(self, atom: Atom, type: str | None = None) -> set[Link] | frozenset[Link]:
        """The links in this space that hold ``atom``, optionally only of one type.

        The returned set must not be modified.
        """
        if self._parent is None:
            inc = self._incoming.get(atom, _EMPTY)
        else:
            own = self._incoming.get(atom, _EMPTY)
            if self._hidden and atom in self._hidden:
                return _EMPTY
            up = self._parent.incoming(atom)
            if self._hidden:
                up = {x for x in up if x not in self._hidden}
            inc = (own | up) if own else up
        if type is not None:
            full = _t.resolve(type) or type
            return {x for x in inc if x[0] == full}
        return inc

    def get_by_type(self, type: str, subtypes: bool = False) -> set[Atom]:
        """Every atom of ``type`` (and of its subtypes if asked)."""
        full = _t.resolve(type)
        if full is None:
            raise ValueError(f"unknown type {type!r}")
        names = _t.subtypes(full) if subtypes else (full,)
        out: set[Atom] = set()
        for n in names:
            out |= self._type_set(n)
        return out

    def _type_set(self, full: str) -> set[Atom] | frozenset[Atom]:
        own = self._by_type.get(full, _EMPTY)
        if self._parent is None:
            return own
        up = self._parent._type_set(full)
        if self._hidden:
            up = {x for x in up if x not in self._hidden}
        return (own | up) if own else up

    def count_type(self, full: str) -> int:
        """Number of atoms of exactly type ``full`` (cheap for flat spaces)."""
        if self._parent is None:
            return len(self._by_type.get(full, _EMPTY))
        return len(self._type_set(full))

    # ------------------------------------------------------------------ adding
    def add(self, atom: Atom, tv: TruthValue | None = None) -> Atom | None:
        """Add ``atom`` (and its outgoing atoms); return the canonical instance.

        As in OpenCog, a StateLink is unique per key (its first atom): adding one
        replaces the key's previous state; a DefineLink may define its first atom once;
        and a DeleteLink without free variables is never added: the atoms it holds are
        removed instead (recursively, as ``cog-extract-recursive!``) and None is
        returned. A DeleteLink with variables (in a rule's rewrite) is an ordinary atom.
        """
        if atom[0] in _ON_ADD and atom.__class__ is Link and atom[1]:
            if atom[0] == "DeleteLink":
                if is_closed(atom):
                    for a in atom[1]:
                        self.remove(a, recursive=True)
                    return None
            else:
                self._unique_keyed(atom)
        if (
            self._parent is None
            and self._owned_inc is None
            and self._owned_typ is None
            and self._owned_rel is None
        ):
            found = self._atoms.get(atom)
            if found is None:
                found = self._add_flat(atom)
            if tv is not None:
                self.set_tv(found, tv)
            return found
        found = self._find(atom)
        if found is None:
            if not isinstance(atom, Atom):
                raise TypeError(f"not an atom: {atom!r}")
            if atom.__class__ is Link or isinstance(atom, Link):
                out = atom[1]
                _refuse_held_deletes(out)
                new_out = tuple([self.add(x) for x in out])  # type: ignore[misc]
                if any(a is not b for a, b in zip(new_out, out, strict=True)):
                    atom = tuple.__new__(Link, (atom[0], new_out))
            found = self._insert_canonical(atom)
        if tv is not None:
            self.set_tv(found, tv)
        return found

    def _unique_keyed(self, atom: Link) -> None:
        if atom in self:
            return
        key = atom[1][0]
        if key not in self:
            return
        state = atom[0] == "StateLink"
        if state and not is_closed(atom):
            return  # a StateLink with variables (in a pattern) is no state, as in OpenCog
        for old in list(self.incoming(key, atom[0])):
            if state and not is_closed(old):
                continue
            if old[1] and old[1][0] == key:
                if atom[0] == "DefineLink":
                    raise ValueError(f"{key} is already defined")
                self.remove(old, recursive=True)

    def _add_flat(self, atom: Atom) -> Atom:
        """Insert into a flat space that shares no index sets (the loading fast path)."""
        atoms = self._atoms
        cls = atom.__class__
        if cls is Link:
            out = atom[1]
            _refuse_held_deletes(out)
            new = []
            changed = False
            for x in out:
                c = atoms.get(x)
                if c is None:
                    c = self._add_flat(x)
                if c is not x:
                    changed = True
                new.append(c)
            if changed:
                atom = tuple.__new__(Link, (atom[0], tuple(new)))
            atoms[atom] = atom
            inc = self._incoming
            holds_link = False
            for c in new:
                s = inc.get(c)
                if s is None:
                    inc[c] = {atom}
                else:
                    s.add(atom)
                if c.__class__ is Link:
                    holds_link = True
            if holds_link:
                rel = self._relations
                for key, member in _relation_keys(atom):
                    s = rel.get(key)
                    if s is None:
                        rel[key] = {member}
                    else:
                        s.add(member)
        elif cls is Node:
            atoms[atom] = atom
        else:
            if not isinstance(atom, Atom):
                raise TypeError(f"not an atom: {atom!r}")
            atom = (
                tuple.__new__(Link, tuple(atom))
                if isinstance(atom, Link)
                else tuple.__new__(Node, tuple(atom))
            )
            return self._add_flat(atom)
        bt = self._by_type.get(atom[0])
        if bt is None:
            self._by_type[atom[0]] = {atom}
        else:
            bt.add(atom)
        return atom

    def add_node(self, type: str, name: str, tv: TruthValue | None = None) -> Node:
        """Add the node (type, name)."""
        return self.add(Node(type, name), tv)  # type: ignore[return-value]

    def add_link(self, type: str, outgoing: Iterable[Atom], tv: TruthValue | None = None) -> Link:
        """Add the link (type, outgoing)."""
        return self.add(Link(type, *outgoing), tv)  # type: ignore[return-value]

    def _insert_canonical(self, atom: Atom) -> Atom:
        """Insert an atom whose outgoing atoms are already canonical members."""
        if self._hidden and atom in self._hidden:
            self._hidden.discard(atom)
            if self._parent is not None:
                up = self._parent._find(atom)
                if up is not None:
                    return up
        self._atoms[atom] = atom
        self._typ_set_w(atom[0]).add(atom)
        if atom.__class__ is Link:
            for x in atom[1]:
                self._inc_set_w(x).add(atom)
            for key, member in _relation_keys(atom):
                self._rel_set_w(key).add(member)
        return atom

    def _inc_set_w(self, atom: Atom) -> set[Link]:
        """The incoming set of ``atom``, ready to be written (copied if shared)."""
        return _writable_set(self._incoming, self._owned_inc, atom)

    def _rel_set_w(self, key: tuple) -> set[Link]:
        """The relation-index entry ``key``, ready to be written (copied if shared)."""
        return _writable_set(self._relations, self._owned_rel, key)

    def relation(
        self, leaf: Atom, j: int, c: Atom, outer: str, inner: str, arity: int
    ) -> set[Link]:
        """The relations ``(outer c (inner ...))`` in this space whose inner link has
        ``arity`` atoms and ``leaf`` at position ``j``: for two leaves, the set of the
        other leaves; otherwise the set of the inner links ``(inner ...)``.

        The index behind the matcher's fast path for the commonest clause,
        ``(EvaluationLink (PredicateNode "on") (ListLink B ?y))``: everything but the
        other leaves is in the key. Flat spaces only (a frame's index holds its own
        atoms); the returned set must not be modified.
        """
        return self._relations.get((leaf, j, c, outer, inner, arity), _EMPTY)

    def _typ_set_w(self, type: str) -> set[Atom]:
        s = self._by_type.get(type)
        owned = self._owned_typ
        if s is None:
            s = set()
            self._by_type[type] = s
            if owned is not None:
                owned.add(type)
        elif owned is not None and type not in owned:
            s = set(s)
            self._by_type[type] = s
            owned.add(type)
        return s

    # ------------------------------------------------------------------ removing
    def remove(self, atom: Atom, recursive: bool = False) -> bool:
        """Remove ``atom``; refuse (return False) if links still hold it, unless
        ``recursive``, which first removes every link that holds it, transitively.

        The outgoing atoms of a removed link stay, as with OpenCog's ``cog-extract!``.
        Returns True if the atom was present and is now gone.
        """
        found = self._find(atom)
        if found is None:
            return False
        inc = self.incoming(found)
        if inc:
            if not recursive:
                return False
            for link in list(inc):
                self.remove(link, recursive=True)
        self._delete(found)
        return True

    extract = remove

    def _delete(self, atom: Atom) -> None:
        own = self._atoms.pop(atom, None)
        if own is not None:
            self._typ_set_w(atom[0]).discard(atom)
            if not self._by_type[atom[0]]:
                del self._by_type[atom[0]]
            if atom.__class__ is Link:
                for x in atom[1]:
                    s = self._incoming.get(x)
                    if s is not None and atom in s:
                        s = self._inc_set_w(x)
                        s.discard(atom)
                        if not s:
                            del self._incoming[x]
                for key, member in _relation_keys(atom):
                    s = self._relations.get(key)
                    if s is not None and member in s:
                        s = self._rel_set_w(key)
                        s.discard(member)
                        if not s:
                            del self._relations[key]
            self._incoming.pop(atom, None)
        self._tv.pop(atom, None)
        self._values.pop(atom, None)
        if self._parent is not None and self._parent._find(atom) is not None:
            self._hidden.add(atom)

    def clear(self) -> None:
        """Remove every atom (a frame hides all of its parent's)."""
        for a in list(self):
            if a in self:
                self.remove(a, recursive=True)

    # ------------------------------------------------------------------ values
    def get_tv_or_none(self, atom: Atom) -> TruthValue | None:
        """The truth value set on ``atom`` here or in a parent, or None."""
        s: AtomSpace | None = self
        while s is not None:
            tv = s._tv.get(atom)
            if tv is not None:
                return tv
            if s._hidden and atom in s._hidden:
                return None
            s = s._parent
        return None

    def get_tv(self, atom: Atom) -> TruthValue:
        """The truth value of ``atom`` (``(stv 1 0)`` if none was set)."""
        tv = self.get_tv_or_none(atom)
        return DEFAULT_TV if tv is None else tv

    def set_tv(self, atom: Atom, tv: TruthValue) -> Atom:
        """Set the truth value (adding the atom if needed); a frame shadows its parent."""
        if not isinstance(tv, TruthValue):
            raise TypeError(f"not a truth value: {tv!r}")
        if self._scratch and self._parent is not None and atom not in self._atoms:
            return self._parent.set_tv(atom, tv)
        found = self._find(atom)
        if found is None:
            found = self.add(atom)
        self._tv[found] = tv
        return found

    def _find_values(self, atom: Atom) -> dict[Atom, Value] | None:
        s: AtomSpace | None = self
        merged: dict[Atom, Value] | None = None
        chain = []
        while s is not None:
            chain.append(s._values.get(atom))
            if s._hidden and atom in s._hidden:
                break
            s = s._parent
        for d in reversed(chain):
            if d:
                merged = {**(merged or {}), **d}
        return merged

    def set_value(self, atom: Atom, key: Atom, value: Value) -> Atom:
        """Attach ``value`` to ``atom`` under the key atom ``key``."""
        if not isinstance(value, Value):
            raise TypeError(f"not a Value: {value!r}")
        if isinstance(value, TruthValue) and key == TV_KEY:
            return self.set_tv(atom, value)
        if self._scratch and self._parent is not None and atom not in self._atoms:
            return self._parent.set_value(atom, key, value)
        found = self._find(atom)
        if found is None:
            found = self.add(atom)
        self._values[found] = {**self._values.get(found, {}), key: value}
        return found

    def get_value(self, atom: Atom, key: Atom) -> Value | None:
        """The Value under ``key`` on ``atom``, or None."""
        if key == TV_KEY:
            return self.get_tv(atom)
        vals = self._find_values(atom)
        return None if not vals else vals.get(key)

    def keys(self, atom: Atom) -> list[Atom]:
        """The keys under which ``atom`` carries Values."""
        vals = self._find_values(atom)
        return list(vals) if vals else []

    # ------------------------------------------------------------------ functions
    def register(self, name: str, fn: GroundedFunction) -> None:
        """Register ``fn`` for this space, its frames and copies (``py:name``)."""
        if not callable(fn):
            raise TypeError(f"{name}: {fn!r} is not callable")
        self.functions[name] = fn

    def lookup_function(self, name: str) -> GroundedFunction:
        """The function registered under ``name``; KeyError if there is none."""
        fn = self.functions.get(name)
        if fn is None:
            fn = GLOBAL_FUNCTIONS.get(name)
        if fn is None:
            raise KeyError(name)
        return fn

    # ------------------------------------------------------------------ execution
    def execute(self, atom: Atom) -> Any:
        """Execute an executable atom (a query link, an ExecutionOutputLink) here."""
        return _execute(self, atom)

    def evaluate(self, atom: Atom) -> TruthValue:
        """Evaluate an evaluatable atom (SatisfactionLink, EqualLink, ...) to a TV."""
        return _evaluate(self, atom)

    def load_atomese(self, text: str, source: str = "<string>") -> list[Atom]:
        """Parse Atomese text and add its atoms; returns the top-level atoms."""
        from robocog.atomspace.atomese import load

        return load(text, self, source=source)

    def __repr__(self) -> str:
        kind = "frame" if self._parent is not None else "space"
        label = f" {self.name!r}" if self.name else ""
        return f"<AtomSpace {kind}{label} with {len(self)} atoms>"


#: the key under which OpenCog stores an atom's truth value
TV_KEY = Node("PredicateNode", "*-TruthValueKey-*")


def _writable_set(table: dict, owned: set | None, key: object) -> set:
    """Copy-on-write for an index shared with a copy: the set under ``key`` in ``table``,
    made if missing and copied once if this space does not own it yet (``owned`` is None
    when nothing is shared)."""
    s = table.get(key)
    if s is None:
        s = table[key] = set()
        if owned is not None:
            owned.add(key)
    elif owned is not None and key not in owned:
        s = table[key] = set(s)
        owned.add(key)
    return s
