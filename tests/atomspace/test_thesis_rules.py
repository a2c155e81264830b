"""The thesis's rules (Thiella 2021, Section 3.2 and Appendix 7.3) on its knowledge bases
(Appendix 7.1), as written, with the Scheme procedures registered from Python."""

from __future__ import annotations

import pytest

from robocog.atomspace import AtomSpace, Link, Node, parse, read_atom

from .conftest import DATA, C, P, ev


def pickup_action(space: AtomSpace, effect: Link, precondition: Link) -> Link:
    """The thesis's pickup-action: extract the precondition, return the effect."""
    space.remove(precondition, recursive=True)
    return effect


def stack_action(space: AtomSpace, effect: Link, precondition: Link) -> Link:
    """The thesis's stack-action, as its Scheme body does it."""
    over, under = effect.out[1].out
    space.remove(precondition, recursive=True)
    space.remove(P("in_hand"))
    space.remove(ev("clear", under))
    space.remove(P("clear"))
    space.add(ev("clear", over))
    space.add(ev("stacked", over))
    return effect


@pytest.fixture
def kb() -> AtomSpace:
    s = AtomSpace()
    s.load_atomese((DATA / "kb_7_1a.scm").read_text())
    s.register("pickup-action", pickup_action)
    s.register("stack-action", stack_action)
    return s


def pickup_rule() -> Link:
    return read_atom((DATA / "pickup_rule.scm").read_text())  # type: ignore[return-value]


def pickable(space: AtomSpace) -> set[str]:
    """Run the rule in a throw-away frame, as the thesis does in a copy, and read the
    objects from the rewrites."""
    frame = space.child()
    result = frame.execute(pickup_rule())
    return {r.out[1].name for r in result.out}


def test_pickup_grounds_exactly_the_pickable_objects(kb: AtomSpace) -> None:
    # screw, bolt and toolbox are objects and clear; the table is a fixed object
    assert pickable(kb) == {"screw", "bolt", "toolbox"}


def test_pickup_applies_its_effects_only_in_the_frame(kb: AtomSpace) -> None:
    before = kb.signature()
    frame = kb.child()
    result = frame.execute(pickup_rule())
    assert result == Link("SetLink", *(ev("in_hand", C(n)) for n in ("screw", "bolt", "toolbox")))
    for n in ("screw", "bolt", "toolbox"):
        assert ev("in_hand", C(n)) in frame
        assert ev("clear", C(n)) not in frame
    assert ev("clear", C("table")) in frame
    assert kb.signature() == before


def test_a_stacked_object_is_not_picked_up(kb: AtomSpace) -> None:
    kb.add(ev("stacked", C("screw")))
    assert pickable(kb) == {"bolt", "toolbox"}


def test_second_state_of_appendix_7_1(kb: AtomSpace) -> None:
    # screw on the toolbox, bolt in hand: only the screw is clear among the objects
    for n in ("screw", "bolt", "toolbox", "table"):
        kb.remove(ev("clear", C(n)))
    kb.load_atomese((DATA / "kb_7_1b_state.scm").read_text())
    assert pickable(kb) == {"screw"}


def test_pickup_with_an_argument_picks_only_that_object(kb: AtomSpace) -> None:
    text = (DATA / "pickup_rule_arg.scm").read_text()
    for name, expected in (("bolt", {"bolt"}), ("table", set()), ("nothing", set())):
        rule = parse(text, env={"args": C(name)}).atoms[0]
        state = kb.copy()
        result = state.execute(rule)
        assert {r.out[1].name for r in result.out} == expected
        if expected:
            assert ev("in_hand", C(name)) in state and ev("clear", C(name)) not in state
            assert ev("clear", C(name)) in kb


def test_py_prefix_works_like_the_thesis_scm_prefix(kb: AtomSpace) -> None:
    text = (DATA / "pickup_rule.scm").read_text().replace("scm: pickup-action", "py:pickup-action")
    frame = kb.child()
    assert len(frame.execute(read_atom(text)).out) == 3


def test_stack_rule_with_or_and_present_not_equal(kb: AtomSpace) -> None:
    # the bolt is in hand; the screw and toolbox are clear objects, the table is fixed
    kb.remove(ev("clear", C("bolt")))
    kb.add(ev("in_hand", C("bolt")))
    rule = read_atom((DATA / "stack_rule.scm").read_text())
    frame = kb.child()
    result = frame.execute(rule)
    targets = {r.out[1].out[1].name for r in result.out}
    assert targets == {"screw", "toolbox", "table"}
    assert all(r.out[1].out[0] == C("bolt") for r in result.out)
    # after stacking on the screw alone, the screw is no longer clear
    only = frame.child()
    one = kb.copy()
    res = one.execute(
        Link(
            "BindLink",
            *rule.out[:1],
            Link(
                "AndLink",
                rule.out[1],
                Link("EqualLink", Node("VariableNode", "?underob"), C("screw")),
            ),
            rule.out[2],
        )
    )
    assert {r.out[1].out[1].name for r in res.out} == {"screw"}
    assert ev("clear", C("screw")) not in one and ev("stacked", C("bolt")) in one
    assert ev("clear", C("bolt")) in one
    assert len(only) == len(frame)
