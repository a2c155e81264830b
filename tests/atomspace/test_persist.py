"""SQLite persistence: round trips, partial stores, atomicity under a killed process."""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

from robocog.atomspace import AtomSpace, FloatValue, StringValue, stv
from robocog.atomspace.persist import SQLiteStore, StoreError, load, store

from .conftest import DATA, C, P, ev


def test_whole_space_round_trips(tmp_path: Path) -> None:
    s = AtomSpace()
    s.load_atomese((DATA / "kb_7_1a.scm").read_text())
    s.set_tv(ev("clear", C("bolt")), stv(0.75, 0.5))
    s.set_value(C("bolt"), P("size"), FloatValue([0.02, 0.01]))
    s.set_value(C("bolt"), P("label"), StringValue(["M6 bolt"]))
    db = tmp_path / "kb.db"
    assert store(s, db) == len(s)
    t = load(db)
    assert t.signature() == s.signature()
    assert t.get_tv(ev("clear", C("bolt"))) == stv(0.75, 0.5)
    assert t.get_value(C("bolt"), P("size")) == FloatValue([0.02, 0.01])
    assert t.get_value(C("bolt"), P("label")) == StringValue(["M6 bolt"])
    # storing again replaces
    s.remove(ev("clear", C("bolt")))
    store(s, db)
    assert load(db).signature() == s.signature()


def test_part_of_a_space(tmp_path: Path) -> None:
    s = AtomSpace()
    s.load_atomese((DATA / "kb_7_1a.scm").read_text())
    db = tmp_path / "part.db"
    with SQLiteStore(db) as st:
        st.store(s, atoms=[ev("clear", C("bolt"))])
        assert st.count() == 3  # the link, its predicate and its concept, nothing else
        st.store(s, atoms=[ev("clear", C("screw")), ev("clear", C("bolt"))])
        assert st.count() == 5
    loaded = load(db)
    assert loaded.signature() == frozenset(
        {ev("clear", C("bolt")), ev("clear", C("screw")), P("clear"), C("bolt"), C("screw")}
    )
    only = load(tmp_path / "part.db", types=["ConceptNode"])
    assert only.signature() == frozenset({C("bolt"), C("screw")})


def test_not_a_store_is_an_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.db"
    bad.write_bytes(b"this is not sqlite" * 100)
    with pytest.raises(StoreError):
        load(bad)


_WRITER = r"""
import sys
from robocog.atomspace import AtomSpace, Link, Node
from robocog.atomspace.persist import SQLiteStore

def state(n, tag):
    s = AtomSpace()
    on = Node("PredicateNode", "on")
    for i in range(n):
        s.add(Link("EvaluationLink", on, Link("ListLink", Node("ConceptNode", f"{tag}{i}"), Node("ConceptNode", "table"))))
    return s

db = SQLiteStore(sys.argv[1])
db.store(state(50, "a"))
print("first-committed", flush=True)
big = state(int(sys.argv[2]), "b")
print("second-started", flush=True)
db.store(big)
print("second-committed", flush=True)
"""


def test_killed_store_leaves_the_previous_state_readable(tmp_path: Path) -> None:
    db = tmp_path / "kill.db"
    proc = subprocess.Popen(
        [sys.executable, "-c", _WRITER, str(db), "40000"],
        stdout=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None
    assert proc.stdout.readline().strip() == "first-committed"
    assert proc.stdout.readline().strip() == "second-started"
    # the rollback journal is there from the second store's first write to its commit,
    # which takes a second or so: killed when it appears, the writer is mid-store
    journal = db.with_name(db.name + "-journal")
    deadline = time.monotonic() + 60
    while not journal.exists() and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.005)
    proc.kill()
    proc.wait()
    rest = proc.stdout.read()
    loaded = load(db)
    names = {a.name for a in loaded.get_by_type("ConceptNode")}
    if "second-committed" in rest:  # the machine was faster than expected
        assert len(names) == 40001
    else:
        assert names == {f"a{i}" for i in range(50)} | {"table"}
        assert len(loaded) == 50 * 3 + 2
