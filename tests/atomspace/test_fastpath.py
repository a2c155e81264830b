"""The fast path answers exactly as the general matcher, and the relation index behind
it follows every add, removal and copy."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.atomspace import AtomSpace, Link, Node, query
from robocog.atomspace.fastpath import fast_query
from robocog.atomspace.matcher import Pattern

from .conftest import C, P, V

NODES = [C(n) for n in "abc"] + [C("absent")]
PREDS = [P("on"), P("near")]
VARS = [V("$x"), V("$y"), V("$z")]
leaf = st.sampled_from(NODES[:3] + VARS)


def rel(pred: Node, *args: Node, inner: str = "ListLink") -> Link:
    return Link("EvaluationLink", pred, Link(inner, *args))


@st.composite
def spaces(draw) -> AtomSpace:  # noqa: ANN001
    s = AtomSpace()
    for pred, args in draw(
        st.lists(
            st.tuples(
                st.sampled_from(PREDS),
                st.lists(st.sampled_from(NODES[:3]), min_size=1, max_size=3),
            ),
            max_size=12,
        )
    ):
        s.add(rel(pred, *args))
    for x, y in draw(st.lists(st.tuples(*[st.sampled_from(NODES[:3])] * 2), max_size=3)):
        s.add(Link("InheritanceLink", x, y))
        s.add(Link("EvaluationLink", P("on"), Link("MemberLink", x, y)))
        s.add(Link("ExecutionLink", P("on"), Link("ListLink", x), y))
    return s


clause = st.one_of(
    # the relation shape (R c (L leaves...)), 1 to 3 leaves, sometimes an absent constant
    st.builds(
        lambda p, xs: rel(p, *xs),
        st.sampled_from(PREDS),
        st.lists(st.sampled_from(NODES + VARS), min_size=1, max_size=3),
    ),
    st.builds(lambda a, b: rel(P("on"), a, b, inner="MemberLink"), leaf, leaf),
    # shapes for the general fast path: a variable predicate, a flat link, three atoms
    st.builds(lambda a, b: rel(V("$p"), a, b), leaf, leaf),
    st.builds(lambda a, b: Link("InheritanceLink", a, b), leaf, leaf),
    st.builds(lambda a, b: Link("ExecutionLink", P("on"), Link("ListLink", a), b), leaf, leaf),
)


def key(found: list[dict]) -> set[frozenset]:
    return {frozenset(b.items()) for b in found}


@settings(max_examples=300, deadline=None)
@given(spaces(), st.lists(clause, min_size=1, max_size=3))
def test_fast_path_agrees_with_the_general_matcher(space: AtomSpace, body: list) -> None:
    pattern = body[0] if len(body) == 1 else Link("AndLink", *body)
    general = Pattern(pattern).groundings(space)
    fast = fast_query(space, pattern)
    if fast is not None:
        assert len(fast) == len(key(fast))  # no grounding twice
        assert key(fast) == key(general)
    assert key(query(space, pattern)) == key(general)


@settings(max_examples=100, deadline=None)
@given(spaces(), st.lists(clause, min_size=1, max_size=2), st.data())
def test_copies_keep_their_own_index(space: AtomSpace, body: list, data) -> None:  # noqa: ANN001
    pattern = body[0] if len(body) == 1 else Link("AndLink", *body)
    before = key(Pattern(pattern).groundings(space))
    copy = space.copy()
    links = sorted(a for a in copy if a.type == "EvaluationLink")
    for a in data.draw(st.lists(st.sampled_from(links), max_size=4)) if links else []:
        copy.remove(a)
    copy.add(rel(P("on"), C("a"), C("c")))
    assert key(query(copy, pattern)) == key(Pattern(pattern).groundings(copy))
    # the original is untouched by the copy's changes, index included
    assert key(query(space, pattern)) == before


def test_the_common_relations_take_the_fast_path() -> None:
    s = AtomSpace()
    for x, y in [("a", "b"), ("b", "c"), ("c", "a"), ("a", "c")]:
        s.add(rel(P("on"), C(x), C(y)))
    x, y, z = VARS
    assert key(fast_query(s, rel(P("on"), C("a"), y))) == key(  # type: ignore[arg-type]
        [{y: C("b")}, {y: C("c")}]
    )
    assert key(fast_query(s, rel(P("on"), x, C("a")))) == key([{x: C("c")}])  # type: ignore[arg-type]
    assert fast_query(s, rel(P("on"), C("a"), C("b"))) == [{}]
    assert fast_query(s, rel(P("on"), C("b"), C("a"))) == []
    assert fast_query(s, rel(P("on"), C("nowhere"), y)) == []
    join = Link("AndLink", rel(P("on"), C("a"), y), rel(P("on"), y, z))
    assert key(fast_query(s, join)) == key(  # type: ignore[arg-type]
        [{y: C("b"), z: C("c")}, {y: C("c"), z: C("a")}]
    )
    # typed variables, evaluatable clauses and frames go to the general matcher
    assert fast_query(s.child(), rel(P("on"), C("a"), y)) is None
    assert (
        fast_query(s, Link("AndLink", rel(P("on"), C("a"), y), Link("EqualLink", y, C("b"))))
        is None
    )
    grounded = Node("GroundedPredicateNode", "py:f")
    assert fast_query(s, Link("EvaluationLink", grounded, Link("ListLink", C("a"), y))) is None


def test_the_relation_index_follows_removals() -> None:
    s = AtomSpace()
    fact = s.add(rel(P("on"), C("a"), C("b")))
    triple = s.add(rel(P("between"), C("a"), C("b"), C("c")))
    # two leaves: the other leaf; otherwise the inner link
    assert s.relation(C("a"), 0, P("on"), "EvaluationLink", "ListLink", 2) == {C("b")}
    assert s.relation(C("b"), 1, P("on"), "EvaluationLink", "ListLink", 2) == {C("a")}
    assert s.relation(C("c"), 2, P("between"), "EvaluationLink", "ListLink", 3) == {triple.out[1]}
    assert s.relation(C("a"), 1, P("on"), "EvaluationLink", "ListLink", 2) == set()
    assert s.remove(fact) and s.remove(triple)
    assert s.relation(C("a"), 0, P("on"), "EvaluationLink", "ListLink", 2) == set()
    assert s.relation(C("c"), 2, P("between"), "EvaluationLink", "ListLink", 3) == set()
    assert s._relations == {}
    assert query(s, rel(P("on"), C("a"), V("$y"))) == []
