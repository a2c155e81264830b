"""The matcher against a brute-force reference, and its use of the indexes."""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.atomspace import AtomSpace, Link, Node, query, substitute
from robocog.atomspace.matcher import compile_pattern
from robocog.atomspace.matcher.search import candidates_of

from .conftest import C, V, ev

BLOCKS = [C(n) for n in "abcd"]
VARS = [V("$x"), V("$y"), V("$z")]
terms = st.sampled_from(BLOCKS + VARS)


@st.composite
def spaces(draw) -> AtomSpace:  # noqa: ANN001
    s = AtomSpace()
    for x, y in draw(
        st.lists(st.tuples(st.sampled_from(BLOCKS), st.sampled_from(BLOCKS)), max_size=8)
    ):
        s.add(ev("on", x, y))
    for x in draw(st.lists(st.sampled_from(BLOCKS), max_size=4)):
        s.add(ev("clear", x))
    for x, y in draw(
        st.lists(st.tuples(st.sampled_from(BLOCKS), st.sampled_from(BLOCKS)), max_size=3)
    ):
        s.add(Link("SetLink", x, y))
    return s


clauses = st.one_of(
    st.builds(lambda a, b: ev("on", a, b), terms, terms),
    st.builds(lambda a: ev("clear", a), terms),
    st.builds(lambda a, b: Link("SetLink", a, b), terms, terms),
)


def brute_force(space: AtomSpace, body: list[Link], absent: list[Link]) -> set[tuple]:
    vs = sorted({v for c in body + absent for v in VARS if v in _nodes(c)})
    found = set()
    universe = list(space)
    for values in itertools.product(universe, repeat=len(vs)):
        b = dict(zip(vs, values, strict=True))
        if all(substitute(c, b) in space for c in body) and not any(
            substitute(c, b) in space for c in absent
        ):
            found.add(tuple(b[v] for v in vs))
    return found


def _nodes(atom) -> set:  # noqa: ANN001
    if isinstance(atom, Node):
        return {atom}
    return set().union(*(_nodes(a) for a in atom.out)) if atom.out else set()


@settings(max_examples=150, deadline=None)
@given(spaces(), st.lists(clauses, min_size=1, max_size=3), st.lists(clauses, max_size=1))
def test_matcher_agrees_with_brute_force(space: AtomSpace, body: list, absent: list) -> None:
    # absent clauses may only use variables the body binds (else they are local)
    bound = set().union(*(_nodes(c) for c in body))
    absent = [a for a in absent if _nodes(a) & set(VARS) <= bound & set(VARS)]
    pattern = Link("AndLink", *body, *(Link("AbsentLink", a) for a in absent))
    vs = sorted(v for v in VARS if v in bound)
    got = {tuple(b[v] for v in vs) for b in query(space, pattern)}
    assert got == brute_force(space, body, absent)


@settings(max_examples=60, deadline=None)
@given(spaces(), st.lists(clauses, min_size=1, max_size=2))
def test_frames_and_copies_answer_like_flat_spaces(space: AtomSpace, body: list) -> None:
    frame = space.child()
    frame.add(ev("clear", C("z")))
    removed = sorted(space)[:3]
    for a in removed:
        frame.remove(a, recursive=True)
    flat = frame.copy()
    pattern = Link("AndLink", *body)
    key = lambda bs: sorted(sorted((k.name, repr(v)) for k, v in b.items()) for b in bs)  # noqa: E731
    assert key(query(frame, pattern)) == key(query(flat, pattern))


def test_a_bound_argument_is_found_through_the_index() -> None:
    s = AtomSpace()
    on = Node("PredicateNode", "on")
    for i in range(3000):
        s.add(Link("EvaluationLink", on, Link("ListLink", C(f"b{i}"), C(f"b{(i * 7) % 3000}"))))
    for i in range(0, 3000, 3):
        s.add(ev("clear", C(f"b{i}")))
    first = compile_pattern(ev("on", C("b10"), V("$y"))).alts[0].mandatory[0]
    second = compile_pattern(ev("on", V("$x"), C("b70"))).alts[0].mandatory[0]
    # candidates come from the bound block's incoming set, not from the 3,000 facts
    assert list(candidates_of(s, first, {})) == [ev("on", C("b10"), C("b70"))]
    assert list(candidates_of(s, second, {})) == [ev("on", C("b10"), C("b70"))]
    join = compile_pattern(Link("AndLink", ev("on", V("$x"), V("$y")), ev("on", V("$y"), C("b70"))))
    c1, c2 = join.alts[0].mandatory
    b10 = s.add(C("b10"))  # bindings hold the space's own atoms
    assert list(candidates_of(s, c1, {V("$y"): b10})) == [ev("on", C("b430"), C("b10"))]
    assert query(s, join.body) == [{V("$x"): C("b430"), V("$y"): C("b10")}]
    # a constant that is not in the space gives no candidates at all
    missing = compile_pattern(ev("on", C("nowhere"), V("$y"))).alts[0].mandatory[0]
    assert list(candidates_of(s, missing, {})) == []


def test_rules_share_compiled_clauses_but_not_across_typings() -> None:
    x = V("$x")
    body = Link("AndLink", ev("clear", x), Link("InheritanceLink", x, C("object")))
    pinned = Link("AndLink", *body.out, Link("EqualLink", x, C("bolt")))
    a = compile_pattern(body).alts[0].mandatory
    b = compile_pattern(pinned).alts[0].mandatory
    assert {id(c) for c in a} == {id(c) for c in b}
    typed = Link("TypedVariableLink", x, Node("TypeNode", "ConceptNode"))
    c = compile_pattern(body, typed).alts[0].mandatory
    assert not {id(k) for k in c} & {id(k) for k in a}
    s = AtomSpace()
    s.add(ev("clear", Node("PredicateNode", "p")))
    s.add(Link("InheritanceLink", Node("PredicateNode", "p"), C("object")))
    assert query(s, body) != [] and query(s, body, typed) == []
