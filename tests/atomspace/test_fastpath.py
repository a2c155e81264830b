"""The fast path answers exactly as the general matcher, and the relation index behind
it follows every add, removal and copy."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.atomspace import AtomSpace, Link, Node, query
from robocog.atomspace.fastpath import fast_query, get_set
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


# two-leaf relations: the shape that query() answers itself, alone or two joined
binary = st.builds(
    lambda p, inner, a, b: rel(p, a, b, inner=inner),
    st.sampled_from(PREDS),
    st.sampled_from(["ListLink", "MemberLink"]),
    st.sampled_from(NODES + VARS),
    st.sampled_from(NODES + VARS),
)
facts = st.builds(
    lambda p, inner, a, b: rel(p, a, b, inner=inner),
    st.sampled_from(PREDS),
    st.sampled_from(["ListLink", "MemberLink"]),
    st.sampled_from(NODES),
    st.sampled_from(NODES),
)


@settings(max_examples=200, deadline=None)
@given(
    st.lists(binary, min_size=1, max_size=2),
    st.lists(st.tuples(st.booleans(), facts, st.booleans()), min_size=1, max_size=25),
)
def test_answers_follow_every_add_and_remove(body: list, steps: list) -> None:
    """query() reads the store as it is at each call: between queries relations come
    and go (and the fast path's table of relation types is sometimes emptied, as a
    fresh process would have it), and every answer is the general matcher's."""
    from robocog.atomspace import fastpath

    pattern = body[0] if len(body) == 1 else Link("AndLink", *body)
    s = AtomSpace()
    for adding, fact, forget in steps:
        if adding:
            s.add(fact)
        else:
            s.remove(fact)
        if forget:
            fastpath._PLAIN.clear()
        found = query(s, pattern)
        assert len(found) == len(key(found))
        assert key(found) == key(Pattern(pattern).groundings(s))


@settings(max_examples=100, deadline=None)
@given(spaces(), st.lists(binary, min_size=1, max_size=2))
def test_getlink_lists_the_variables_in_order_of_appearance(space: AtomSpace, body: list) -> None:
    """Without a declaration a GetLink's groundings are its variables' atoms, in a
    ListLink in order of first appearance when there are several."""
    from robocog.atomspace import variables_of

    pattern = body[0] if len(body) == 1 else Link("AndLink", *body)
    vs = variables_of(pattern)
    if not vs:
        return
    expected = [
        b[vs[0]] if len(vs) == 1 else Link("ListLink", *[b[v] for v in vs])
        for b in Pattern(pattern).groundings(space)
    ]
    assert space.execute(Link("GetLink", pattern)) == Link("SetLink", *expected)
    members = get_set(space, pattern)  # the members without dicts, already in order
    if members is not None:
        assert tuple(members) == Link("SetLink", *expected)[1]


def test_getlink_members_come_straight_from_the_index() -> None:
    s = AtomSpace()
    for x, y in [("a", "b"), ("b", "c"), ("a", "c"), ("c", "a"), ("b", "b")]:
        s.add(rel(P("on"), C(x), C(y)))
    x, y, _z = VARS
    assert get_set(s, rel(P("on"), C("a"), y)) == [C("b"), C("c")]
    # joined: an AndLink's clauses are sorted, so here $a appears first although the
    # clause with the constant (on($b, c)) anchors the join and binds $b first
    a, b = V("$a"), V("$b")
    both = Link("AndLink", rel(P("on"), b, C("c")), rel(P("on"), a, b))
    expected = [Link("ListLink", C(u), C(w)) for u, w in [("a", "b"), ("b", "b"), ("c", "a")]]
    assert get_set(s, both) == expected
    assert s.execute(Link("GetLink", both)) == Link("SetLink", *expected)
    assert get_set(s, Link("InheritanceLink", x, C("a"))) is None  # not a relation: dicts


def test_two_joined_relations_by_hand() -> None:
    s = AtomSpace()
    for x, y in [("a", "b"), ("b", "c"), ("a", "c"), ("c", "a"), ("b", "b")]:
        s.add(rel(P("on"), C(x), C(y)))
    x, y, z = VARS
    a, b, c = (C(n) for n in "abc")

    def on(u: Node, w: Node) -> Link:
        return rel(P("on"), u, w)

    cases = [
        # known at both ends: the far end is checked, not bound
        ((on(a, y), on(y, c)), [{y: b}]),
        ((on(y, b), on(a, y)), [{y: b}]),
        # the variable twice in the second clause
        ((on(a, y), on(y, y)), [{y: b}]),
        # bound at the first end, at the last end
        ((on(a, y), on(y, z)), [{y: b, z: c}, {y: b, z: b}, {y: c, z: a}]),
        ((on(x, y), on(y, a)), [{x: b, y: c}, {x: a, y: c}]),
        # nothing known: the general path
        ((on(x, y), on(y, x)), [{x: a, y: c}, {x: c, y: a}, {x: b, y: b}]),
        # a relation that is not there, a constant that is not there
        ((on(a, y), rel(P("near"), y, z)), []),
        ((on(a, y), on(y, C("absent"))), []),
    ]
    for clauses, expected in cases:
        found = query(s, Link("AndLink", *clauses))
        assert len(found) == len(expected), clauses
        assert key(found) == key(expected), clauses
