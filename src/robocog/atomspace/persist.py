"""SQLite persistence: store and load an AtomSpace, whole or in part.

SQLite is the embedded default: one file, transactions, and a journal that makes each
store all-or-nothing. Every store runs in a single transaction, so a process killed in
the middle of one leaves the file as the previous commit left it, readable as before.

The schema keeps atoms by id with their outgoing sets as id lists, so a link is stored
once however many links hold it, and loads rebuild atoms children-first.
"""

from __future__ import annotations

import json
import sqlite3
from collections.abc import Iterable
from pathlib import Path

from robocog.atomspace import types as _t
from robocog.atomspace.atomese import read_atom, write
from robocog.atomspace.atoms import Atom, Link, Node, _raw_link, _raw_node, bulk
from robocog.atomspace.space import AtomSpace
from robocog.atomspace.values import (
    FloatValue,
    LinkValue,
    QueueValue,
    StringValue,
    TruthValue,
    Value,
)
from robocog.limits import clip

SCHEMA_VERSION = "1"

_SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (k TEXT PRIMARY KEY, v TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS atoms (
    id INTEGER PRIMARY KEY,
    type TEXT NOT NULL,
    name TEXT,
    outgoing TEXT,
    UNIQUE (type, name, outgoing)
);
CREATE INDEX IF NOT EXISTS atoms_type ON atoms (type);
CREATE TABLE IF NOT EXISTS tvs (
    atom INTEGER PRIMARY KEY REFERENCES atoms (id),
    strength REAL NOT NULL,
    confidence REAL NOT NULL
);
CREATE TABLE IF NOT EXISTS vals (
    atom INTEGER NOT NULL REFERENCES atoms (id),
    key TEXT NOT NULL,
    kind TEXT NOT NULL,
    data TEXT NOT NULL,
    PRIMARY KEY (atom, key)
);
"""


class StoreError(RuntimeError):
    """A database that is not an AtomSpace store, or holds something unreadable."""


class SQLiteStore:
    """An AtomSpace store in one SQLite file."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        try:
            self._db = sqlite3.connect(str(self.path), isolation_level=None)
        except sqlite3.Error as exc:  # a missing folder, a file one may not open
            raise StoreError(f"{path}: cannot open the store ({exc})") from None
        try:
            self._db.execute("PRAGMA synchronous = FULL")
            self._db.executescript(_SCHEMA)
            row = self._db.execute("SELECT v FROM meta WHERE k = 'schema'").fetchone()
            if row is None:
                self._db.execute(
                    "INSERT OR IGNORE INTO meta VALUES ('schema', ?)", (SCHEMA_VERSION,)
                )
            elif row[0] != SCHEMA_VERSION:
                raise StoreError(f"{path}: schema version {row[0]}, expected {SCHEMA_VERSION}")
        except (sqlite3.DatabaseError, ValueError) as exc:  # (text that is not UTF-8)
            self._db.close()
            raise StoreError(f"{path}: not an AtomSpace store ({clip(str(exc), 200)})") from None

    def close(self) -> None:
        """Close the database."""
        self._db.close()

    def __enter__(self) -> SQLiteStore:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------ storing
    def store(self, space: AtomSpace, atoms: Iterable[Atom] | None = None) -> int:
        """Store ``space`` (replacing what the file held), or only ``atoms`` of it
        (with their outgoing atoms, added to what the file holds). One transaction.
        Returns the number of atoms written."""
        db = self._db
        db.execute("BEGIN IMMEDIATE")
        try:
            if atoms is None:
                db.execute("DELETE FROM vals")
                db.execute("DELETE FROM tvs")
                db.execute("DELETE FROM atoms")
                ids: dict[Atom, int] = {}
                chosen: Iterable[Atom] = space
            else:
                ids = {}
                chosen = atoms
            n = self._write(space, chosen, ids, fresh=atoms is None)
            db.execute("COMMIT")
        except BaseException:
            db.execute("ROLLBACK")
            raise
        return n

    def _write(
        self, space: AtomSpace, chosen: Iterable[Atom], ids: dict[Atom, int], fresh: bool
    ) -> int:
        db = self._db
        order = _children_first(space, chosen) if fresh and chosen is space else None
        if order is None:
            order = []
            seen: set[Atom] = set()
            for a in chosen:
                _postorder(a, seen, order)
        if fresh:
            rows = []
            append = rows.append
            for i, a in enumerate(order, start=1):
                ids[a] = i
                if a.__class__ is Node:
                    append((i, a[0], a[1], None))
                else:
                    append((i, a[0], None, " ".join([str(ids[x]) for x in a[1]])))
            db.executemany("INSERT INTO atoms VALUES (?, ?, ?, ?)", rows)
        else:
            for a in order:
                ids[a] = self._upsert(a, ids)
        tv_rows = []
        val_rows = []
        if space.parent is None:
            # a flat space: read its value tables directly instead of asking per atom
            tv_items = [(a, tv) for a, tv in space._tv.items() if a in ids]
            val_atoms = [a for a in space._values if a in ids]
        else:
            tv_items = []
            for a in order:
                tv = space.get_tv_or_none(a)
                if tv is not None:
                    tv_items.append((a, tv))
            val_atoms = order
        for a, tv in tv_items:
            tv_rows.append((ids[a], tv.strength, tv.confidence))
        for a in val_atoms:
            for key in space.keys(a):
                v = space.get_value(a, key)
                if v is None:
                    continue
                kind, data = _encode_value(v)
                val_rows.append((ids[a], write(key), kind, data))
        db.executemany("INSERT OR REPLACE INTO tvs VALUES (?, ?, ?)", tv_rows)
        db.executemany("INSERT OR REPLACE INTO vals VALUES (?, ?, ?, ?)", val_rows)
        return len(order)

    def _upsert(self, a: Atom, ids: dict[Atom, int]) -> int:
        if a.__class__ is Node:
            name, outgoing = a[1], None
        else:
            for x in a[1]:
                if x not in ids:
                    ids[x] = self._upsert(x, ids)
            name, outgoing = None, " ".join(str(ids[x]) for x in a[1])
        db = self._db
        row = db.execute(
            "SELECT id FROM atoms WHERE type = ? AND name IS ? AND outgoing IS ?",
            (a[0], name, outgoing),
        ).fetchone()
        if row is not None:
            return int(row[0])
        cur = db.execute(
            "INSERT INTO atoms (type, name, outgoing) VALUES (?, ?, ?)", (a[0], name, outgoing)
        )
        return int(cur.lastrowid)  # type: ignore[arg-type]

    # ------------------------------------------------------------------ loading
    def load(self, space: AtomSpace | None = None, types: Iterable[str] | None = None) -> AtomSpace:
        """Load every atom (or only the atoms of ``types``, with their outgoing atoms)
        into ``space`` (a new one by default) and return it."""
        try:
            with bulk():
                return self._load(space, types)
        except StoreError:
            raise
        except (sqlite3.DatabaseError, ValueError, TypeError, KeyError, RecursionError) as exc:
            # a damaged or foreign file: every row is data from outside, so whatever it
            # holds ends in one error naming the file
            why = clip(f"{type(exc).__name__}: {exc}", 200)
            raise StoreError(f"{self.path}: not a readable AtomSpace store ({why})") from None

    def _load(self, space: AtomSpace | None, types: Iterable[str] | None) -> AtomSpace:
        if space is None:
            space = AtomSpace()
        db = self._db
        wanted: set[str] | None = None
        if types is not None:
            wanted = {(_t.resolve(t) or t) for t in types}
        by_id: dict[int, Atom] = {}
        db.execute("BEGIN")
        try:
            for i, typ, name, outgoing in db.execute(
                "SELECT id, type, name, outgoing FROM atoms ORDER BY id"
            ):
                if _t.resolve(typ) != typ:
                    raise StoreError(f"atom {i} has unknown type {typ!r}")
                if name is not None:
                    atom: Atom = _raw_node(typ, name)
                else:
                    try:
                        out = tuple(by_id[int(x)] for x in outgoing.split()) if outgoing else ()
                    except (KeyError, ValueError):
                        raise StoreError(f"atom {i} refers to a missing atom") from None
                    atom = _raw_link(typ, out)
                by_id[i] = atom
                if wanted is None or typ in wanted:
                    space.add(atom)
            tvs = db.execute("SELECT atom, strength, confidence FROM tvs").fetchall()
            vals = db.execute("SELECT atom, key, kind, data FROM vals").fetchall()
        finally:
            db.execute("COMMIT")
        for i, s, c in tvs:
            a = by_id.get(i)
            if a is not None and a in space:
                space.set_tv(a, TruthValue(s, c))
        for i, k, kind, data in vals:
            a = by_id.get(i)
            if a is not None and a in space:
                space.set_value(a, read_atom(k), _decode_value(kind, data))
        return space

    def count(self) -> int:
        """Number of atoms stored."""
        return int(self._db.execute("SELECT COUNT(*) FROM atoms").fetchone()[0])


def _children_first(space: AtomSpace, atoms: Iterable[Atom]) -> list[Atom] | None:
    """The atoms in their stored order if every link comes after its outgoing atoms
    (true of a flat space, which inserts children first), else None."""
    order = list(atoms)
    seen: set[Atom] = set()
    add = seen.add
    for a in order:
        if a.__class__ is Link:
            for x in a[1]:
                if x not in seen:
                    return None
        add(a)
    return order


def _postorder(a: Atom, seen: set[Atom], order: list[Atom]) -> None:
    if a in seen:
        return
    stack = [(a, False)]
    while stack:
        x, done = stack.pop()
        if done:
            if x not in seen:
                seen.add(x)
                order.append(x)
            continue
        if x in seen:
            continue
        stack.append((x, True))
        if x.__class__ is Link:
            for y in reversed(x[1]):
                if y not in seen:
                    stack.append((y, False))


def _encode_value(v: Value) -> tuple[str, str]:
    if isinstance(v, TruthValue):
        return "stv", json.dumps([v.strength, v.confidence])
    if isinstance(v, FloatValue):
        return "FloatValue", json.dumps(list(v.items))
    if isinstance(v, StringValue):
        return "StringValue", json.dumps(list(v.items))
    if isinstance(v, LinkValue):
        if not all(isinstance(x, Atom) for x in v.items):
            raise StoreError("only LinkValues of atoms can be stored")
        return type(v).__name__, json.dumps([write(x) for x in v.items])
    raise StoreError(f"cannot store a {type(v).__name__}")


def _decode_value(kind: str, data: str) -> Value:
    items = json.loads(data)
    if kind == "stv":
        return TruthValue(*items)
    if kind == "FloatValue":
        return FloatValue(items)
    if kind == "StringValue":
        return StringValue(items)
    if kind in ("LinkValue", "QueueValue"):
        cls = LinkValue if kind == "LinkValue" else QueueValue
        return cls(read_atom(x) for x in items)
    raise StoreError(f"unknown value kind {kind!r}")


def store(space: AtomSpace, path: str | Path, atoms: Iterable[Atom] | None = None) -> int:
    """Store ``space`` (or only ``atoms`` of it) in the SQLite file ``path``."""
    with SQLiteStore(path) as st:
        return st.store(space, atoms)


def load(
    path: str | Path, space: AtomSpace | None = None, types: Iterable[str] | None = None
) -> AtomSpace:
    """Load the SQLite file ``path`` (or only the atoms of ``types``)."""
    with SQLiteStore(path) as st:
        return st.load(space, types)
