"""AtomSpace: uniqueness, incoming sets, removal, values, frames and copies."""

from __future__ import annotations

import pytest

from robocog.atomspace import TV_KEY, AtomSpace, FloatValue, Link, Node, StringValue, stv

from .conftest import C, P, ev


def test_atoms_are_unique_and_share_their_parts(blocks: AtomSpace) -> None:
    n = len(blocks)
    again = blocks.add(ev("on", C("a"), C("b")))
    assert len(blocks) == n
    assert again is blocks.add(Link("EvaluationLink", P("on"), Link("ListLink", C("a"), C("b"))))
    # on, clear, a, b, c, two ListLinks, three EvaluationLinks
    assert n == 10
    inner = blocks.add(Link("ListLink", C("a"), C("b")))
    assert again.out[1] is inner


def test_incoming_and_by_type(blocks: AtomSpace) -> None:
    inc = blocks.incoming(C("b"))
    assert inc == {Link("ListLink", C("a"), C("b")), Link("ListLink", C("b"), C("c"))}
    assert blocks.incoming(C("a"), "EvaluationLink") == {ev("clear", C("a"))}
    assert blocks.get_by_type("ConceptNode") == {C("a"), C("b"), C("c")}
    assert blocks.get_by_type("PredicateNode") == {P("on"), P("clear")}
    assert len(blocks.get_by_type("Node", subtypes=True)) == 5


def test_remove_refuses_to_orphan_unless_recursive(blocks: AtomSpace) -> None:
    assert blocks.remove(C("b")) is False
    assert C("b") in blocks
    assert blocks.remove(C("b"), recursive=True) is True
    assert C("b") not in blocks
    for a in blocks:
        assert C("b") not in getattr(a, "out", ())
    # links that held b transitively are gone; their other parts stay
    assert ev("on", C("a"), C("b")) not in blocks
    assert C("a") in blocks and C("c") in blocks
    assert blocks.incoming(C("a")) == {ev("clear", C("a"))}
    assert blocks.remove(C("zzz")) is False


def test_truth_values_and_values(blocks: AtomSpace) -> None:
    fact = ev("clear", C("a"))
    assert blocks.get_tv(fact) == stv(1, 0)  # OpenCog's default
    blocks.set_tv(fact, stv(0.5, 0.25))
    assert blocks.get_tv(fact) == stv(0.5, 0.25)
    assert blocks.get_value(fact, TV_KEY) == stv(0.5, 0.25)
    key = P("weight")
    blocks.set_value(fact, key, FloatValue([1, 2.5]))
    blocks.set_value(fact, P("label"), StringValue(["x"]))
    assert blocks.get_value(fact, key) == FloatValue([1.0, 2.5])
    assert set(blocks.keys(fact)) == {key, P("label")}
    with pytest.raises(ValueError):
        stv(1.5, 0)
    t = blocks.add(C("new"), tv=stv(0.1, 0.2))
    assert blocks.get_tv(t) == stv(0.1, 0.2)


def test_frame_sees_parent_and_shadows_it(blocks: AtomSpace) -> None:
    frame = blocks.child()
    assert ev("clear", C("a")) in frame and len(frame) == len(blocks)
    assert frame.remove(ev("clear", C("a")))
    frame.add(ev("holding", C("a")))
    frame.set_tv(ev("on", C("a"), C("b")), stv(0.2, 0.9))
    # the frame changed, the parent did not
    assert ev("clear", C("a")) not in frame and ev("clear", C("a")) in blocks
    assert ev("holding", C("a")) in frame and ev("holding", C("a")) not in blocks
    assert blocks.get_tv(ev("on", C("a"), C("b"))) == stv(1, 0)
    assert frame.get_tv(ev("on", C("a"), C("b"))) == stv(0.2, 0.9)
    assert frame.incoming(C("a"), "EvaluationLink") == {ev("holding", C("a"))}
    assert len(frame) == len(blocks) + 1  # -clear(a) +holding +holding(a)
    assert set(frame) == (set(blocks) - {ev("clear", C("a"))}) | {
        ev("holding", C("a")),
        P("holding"),
    }
    # a frame sees later additions to its parent
    blocks.add(C("late"))
    assert C("late") in frame
    # re-adding a hidden atom makes it visible again
    frame.add(ev("clear", C("a")))
    assert ev("clear", C("a")) in frame
    # frames of frames
    deeper = frame.child()
    deeper.remove(ev("on", C("b"), C("c")))
    assert ev("on", C("b"), C("c")) in frame and ev("on", C("b"), C("c")) not in deeper


def test_copy_is_independent(blocks: AtomSpace) -> None:
    copy = blocks.copy()
    assert copy.signature() == blocks.signature()
    copy.remove(ev("clear", C("a")))
    copy.add(ev("clear", C("b")))
    assert ev("clear", C("a")) in blocks and ev("clear", C("b")) not in blocks
    assert blocks.incoming(P("clear")) == {ev("clear", C("a"))}
    assert copy.incoming(P("clear")) == {ev("clear", C("b"))}
    blocks.add(ev("clear", C("c")))
    assert ev("clear", C("c")) not in copy
    assert copy.get_by_type("EvaluationLink") != blocks.get_by_type("EvaluationLink")
    # copying a frame flattens it
    frame = blocks.child()
    frame.remove(ev("clear", C("a")))
    flat = frame.copy()
    assert flat.parent is None and flat.signature() == frame.signature()


def test_equal_states_have_equal_signatures() -> None:
    s1, s2 = AtomSpace(), AtomSpace()
    s1.add(ev("on", C("a"), C("b")))
    s1.add(ev("clear", C("a")))
    s2.add(ev("clear", C("a")))
    s2.add(ev("on", C("a"), C("b")))
    assert s1.signature() == s2.signature()
    s2.remove(ev("clear", C("a")))
    assert s1.signature() != s2.signature()


def test_functions_are_shared_by_frames_and_copies() -> None:
    s = AtomSpace()
    s.register("f", lambda space: None)
    assert s.child().lookup_function("f") is s.copy().lookup_function("f")
    with pytest.raises(KeyError):
        s.lookup_function("g")
    with pytest.raises(TypeError):
        s.register("g", 3)  # type: ignore[arg-type]


def test_add_node_and_link_helpers() -> None:
    s = AtomSpace()
    a = s.add_node("Concept", "a")
    link = s.add_link("InheritanceLink", [a, Node("ConceptNode", "b")], tv=stv(1, 1))
    assert link in s and s.get_tv(link) == stv(1, 1)
    assert repr(s).startswith("<AtomSpace space")


def test_state_link_keeps_one_state_per_key() -> None:
    s = AtomSpace()
    hand = Node("AnchorNode", "hand")
    s.add(Link("StateLink", hand, C("empty")))
    s.add(Link("StateLink", hand, C("bolt")))
    states = s.incoming(hand, "StateLink")
    assert states == {Link("StateLink", hand, C("bolt"))}
    frame = s.child()
    frame.add(Link("StateLink", hand, C("screw")))
    assert frame.incoming(hand, "StateLink") == {Link("StateLink", hand, C("screw"))}
    assert s.incoming(hand, "StateLink") == {Link("StateLink", hand, C("bolt"))}


def test_define_link_defines_once() -> None:
    s = AtomSpace()
    name = Node("DefinedPredicateNode", "is-clear")
    s.add(Link("DefineLink", name, ev("clear", C("a"))))
    s.add(Link("DefineLink", name, ev("clear", C("a"))))  # the same definition again
    with pytest.raises(ValueError):
        s.add(Link("DefineLink", name, ev("clear", C("b"))))
