"""Atoms are values; unordered links are canonical; the type hierarchy."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.atomspace import Link, Node, constructor, declare_type, is_a, subtypes
from robocog.atomspace import types as T

from .conftest import C

THESIS_TYPES = (
    "ConceptNode PredicateNode VariableNode TypeNode NumberNode GroundedSchemaNode "
    "GroundedPredicateNode InheritanceLink EvaluationLink ListLink SetLink AndLink OrLink "
    "NotLink EqualLink PresentLink AbsentLink ChoiceLink QueryLink BindLink GetLink "
    "MeetLink SatisfactionLink ExecutionOutputLink VariableList TypedVariableLink "
    "ImplicationLink MemberLink StateLink DefineLink"
).split()


def test_every_type_of_the_thesis_is_declared() -> None:
    for t in THESIS_TYPES:
        assert T.is_type(t), t
        assert is_a(t, "Node") or is_a(t, "Link")
        assert is_a(t, "Atom")


def test_nodes_and_links_are_values() -> None:
    assert Node("ConceptNode", "a") == Node("Concept", "a")
    assert hash(Node("ConceptNode", "a")) == hash(Node("ConceptNode", "a"))
    assert Node("ConceptNode", "a") != Node("PredicateNode", "a")
    l1 = Link("ListLink", C("a"), C("b"))
    assert l1 == Link("List", C("a"), C("b"))
    assert l1 != Link("ListLink", C("b"), C("a"))
    assert l1.type == "ListLink" and l1.out == (C("a"), C("b")) and l1.arity == 2


@given(st.lists(st.text(max_size=3), min_size=0, max_size=6))
def test_unordered_links_are_canonical(names: list[str]) -> None:
    atoms = [C(n) for n in names]
    a = Link("SetLink", *atoms)
    b = Link("SetLink", *reversed(atoms))
    assert a == b and hash(a) == hash(b)
    assert a.out == tuple(sorted(a.out))
    # ordered links keep their order
    if len(set(names)) > 1:
        assert Link("ListLink", *atoms) != Link("ListLink", *sorted(atoms, reverse=True)) or (
            atoms == sorted(atoms, reverse=True)
        )


def test_equal_and_and_links_are_unordered() -> None:
    assert Link("EqualLink", C("x"), C("y")) == Link("EqualLink", C("y"), C("x"))
    assert Link("AndLink", C("x"), C("y")) == Link("AndLink", C("y"), C("x"))


def test_bad_types_and_outgoing_are_refused() -> None:
    with pytest.raises(ValueError):
        Node("ListLink", "x")
    with pytest.raises(ValueError):
        Link("ConceptNode", C("a"))
    with pytest.raises(ValueError):
        Link("ListLink", "not an atom")  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        Node("NoSuchNode", "x")


def test_declare_a_new_type() -> None:
    name = declare_type("BlockNode", "ConceptNode")
    assert is_a(name, "ConceptNode") and name in subtypes("ConceptNode")
    assert Node("Block", "b1").type == "BlockNode"
    assert declare_type("BlockNode", "ConceptNode") == "BlockNode"  # idempotent
    with pytest.raises(ValueError):
        declare_type("BlockNode", "PredicateNode")
    link = declare_type("NearLink", "UnorderedLink")
    assert Link(link, C("b"), C("a")) == Link(link, C("a"), C("b"))


def test_constructor_factories() -> None:
    Concept = constructor("Concept")
    Inh = constructor("InheritanceLink")
    assert Inh(Concept("cat"), Concept("animal")) == Link("InheritanceLink", C("cat"), C("animal"))
