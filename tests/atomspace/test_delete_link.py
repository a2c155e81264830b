"""DeleteLink as OpenCog has it: closed, it removes what it holds and is never added;
with variables, it is an ordinary atom, and a rewrite that grounds it removes atoms."""

from __future__ import annotations

import pytest

from robocog.atomspace import AtomSpace, Link, is_a, read_atom
from robocog.atomspace.types import declare_type

from .conftest import C, V, ev


def test_delete_link_is_a_builtin_free_link() -> None:
    assert is_a("DeleteLink", "FreeLink") and is_a("DeleteLink", "OrderedLink")
    assert read_atom('(DeleteLink (ConceptNode "a"))').type == "DeleteLink"
    assert declare_type("DeleteLink", "FreeLink") == "DeleteLink"  # re-declaring: no-op


def test_adding_a_closed_delete_link_removes_what_it_holds(blocks: AtomSpace) -> None:
    fact = ev("on", C("a"), C("b"))
    assert blocks.add(Link("DeleteLink", fact)) is None
    assert fact not in blocks
    assert Link("DeleteLink", fact) not in blocks
    assert C("a") in blocks  # the outgoing atoms of a removed link stay
    # recursive, as cog-extract-recursive!: links holding the atom go with it
    assert blocks.add(Link("DeleteLink", C("c"))) is None
    assert C("c") not in blocks and ev("on", C("b"), C("c")) not in blocks
    assert len(blocks) == len(set(blocks))


def test_an_open_delete_link_is_an_ordinary_atom() -> None:
    s = AtomSpace()
    open_delete = Link("DeleteLink", ev("clear", V("$x")))
    assert s.add(open_delete) == open_delete and open_delete in s


def test_frames_hide_and_atomese_deletes() -> None:
    s = AtomSpace()
    s.add(ev("clear", C("a")))
    frame = s.child()
    assert frame.add(Link("DeleteLink", ev("clear", C("a")))) is None
    assert ev("clear", C("a")) not in frame and ev("clear", C("a")) in s
    added = s.load_atomese(
        '(DeleteLink (EvaluationLink (PredicateNode "clear") (ConceptNode "a")))\n(ConceptNode "b")'
    )
    assert added == [C("b")] and ev("clear", C("a")) not in s


def test_a_link_cannot_hold_a_closed_delete_link() -> None:
    s = AtomSpace()
    before = len(s)
    with pytest.raises(ValueError):
        s.add(Link("ListLink", C("x"), Link("DeleteLink", C("y"))))
    assert len(s) == before
    with pytest.raises(ValueError):
        s.child().add(Link("ListLink", Link("DeleteLink", C("y"))))


def test_a_rewrite_deletes_what_it_grounds(blocks: AtomSpace) -> None:
    # pick up every clear block: it is in the hand and no longer clear
    rule = read_atom(
        """(BindLink (VariableNode "$x")
             (EvaluationLink (PredicateNode "clear") (VariableNode "$x"))
             (ListLink
               (EvaluationLink (PredicateNode "in-hand") (VariableNode "$x"))
               (DeleteLink (EvaluationLink (PredicateNode "clear") (VariableNode "$x")))))"""
    )
    result = blocks.execute(rule)
    assert ev("clear", C("a")) not in blocks
    assert ev("in-hand", C("a")) in blocks
    assert result.out == (Link("ListLink", ev("in-hand", C("a"))),)
    # a rewrite that is only a DeleteLink returns nothing and removes the groundings
    drop = read_atom(
        """(BindLink (VariableNode "$x")
             (EvaluationLink (PredicateNode "in-hand") (VariableNode "$x"))
             (DeleteLink (EvaluationLink (PredicateNode "in-hand") (VariableNode "$x"))))"""
    )
    assert blocks.execute(drop).out == ()
    assert ev("in-hand", C("a")) not in blocks
