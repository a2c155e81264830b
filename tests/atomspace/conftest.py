"""Shared helpers for the AtomSpace tests."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocog.atomspace import AtomSpace, Link, Node

DATA = Path(__file__).parent / "data"


def C(name: str) -> Node:
    """A ConceptNode."""
    return Node("ConceptNode", name)


def P(name: str) -> Node:
    """A PredicateNode."""
    return Node("PredicateNode", name)


def V(name: str) -> Node:
    """A VariableNode."""
    return Node("VariableNode", name)


def ev(pred: str, *args: Node) -> Link:
    """(EvaluationLink (PredicateNode pred) arg) or with a ListLink for several args."""
    arg = args[0] if len(args) == 1 else Link("ListLink", *args)
    return Link("EvaluationLink", P(pred), arg)


@pytest.fixture
def blocks() -> AtomSpace:
    """a on b on c, a clear."""
    s = AtomSpace()
    s.add(ev("on", C("a"), C("b")))
    s.add(ev("on", C("b"), C("c")))
    s.add(ev("clear", C("a")))
    return s
