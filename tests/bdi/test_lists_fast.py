"""Lists made from Python items keep them and build their cells on demand, sorting and
maxima of plain numbers or strings skip the key per item, and ``.findall`` over facts
runs without a generator per solution: each must give what the general way gives."""

from __future__ import annotations

import random

from robocog.bdi import Agent
from robocog.bdi.beliefs import BeliefBase
from robocog.bdi.parser import parse_term
from robocog.bdi.terms import (
    NIL,
    Cons,
    Literal,
    Var,
    iter_list,
    list_items,
    list_tail,
    make_list,
    max_term,
    min_term,
    sort_key,
    sorted_terms,
    term_str,
)
from robocog.bdi.unifier import resolve, unify


def cells(items: list, tail: object = NIL) -> object:
    """A list built cell by cell, the way the parser and the unifier build them."""
    out = tail
    for x in reversed(items):
        out = Cons(x, out)
    return out


def test_a_list_made_from_items_behaves_as_one_built_cell_by_cell() -> None:
    items = [3, "s", Literal("a"), 1.5, Literal("f", (Var("X"),))]
    lazy, eager = make_list(items), cells(items)
    assert lazy == eager and eager == lazy
    assert hash(make_list(items[:4])) == hash(cells(items[:4]))
    assert term_str(lazy) == term_str(eager) == '[3,"s",a,1.5,f(X)]'
    assert list(iter_list(lazy)) == items and list_tail(lazy) is NIL
    assert not lazy.ground and not lazy.tail.tail.tail.ground
    assert lazy.tail.tail.tail.tail.tail is NIL
    ground = make_list([1, 2, 3])
    assert ground.ground and ground.tail.ground and ground.tail.tail.tail is NIL
    assert list_items(ground) == (1, 2, 3) and list_items(cells([1, 2])) == [1, 2]
    assert list_items(cells([1], Var("T"))) is None and list_items(NIL) == ()


def test_a_made_list_unifies_with_a_head_and_tail_pattern() -> None:
    s: dict = {}
    pattern = parse_term("[A, B | T]")
    assert unify(pattern, make_list([1, 2, 3, 4]), s, [])
    got = resolve(pattern, s)
    assert term_str(got) == "[1,2,3,4]"
    assert make_list([1, 2], Var("T")).tail.tail.__class__ is Var


def test_sorting_and_extremes_follow_the_term_order() -> None:
    rng = random.Random(4)
    for trial in range(200):
        pool = [rng.randint(-5, 5), rng.random(), float(rng.randint(0, 3))]
        if trial % 3 == 1:
            pool = [rng.choice("abcAB") * rng.randint(0, 2) for _ in range(3)]
        elif trial % 3 == 2:
            pool += ["x", Literal("b"), make_list([1]), Literal("a", (2,))]
        items = [rng.choice(pool) for _ in range(rng.randint(1, 8))]
        assert sorted_terms(items) == sorted(items, key=sort_key)
        assert [x.__class__ for x in sorted_terms(items)] == [
            x.__class__ for x in sorted(items, key=sort_key)
        ]
        assert max_term(items) is max(items, key=sort_key)
        assert min_term(items) is min(items, key=sort_key)


def _general(bb: BeliefBase, pattern: Literal, template: object) -> list:
    s: dict = {}
    trail: list = []
    return [resolve(template, s, {}) for _ in bb.query(pattern, s, trail, None)]


def test_findall_over_facts_gives_the_general_query_s_answers_in_its_order() -> None:
    bb = BeliefBase()
    for text in ["p(1, a)", "p(2, b)", "p(1, c)", "p(3, f(1))", "p(1, a)[source(x)]", "q(1)"]:
        bb.add(parse_term(text))
    x, y = Var("X"), Var("Y")
    cases = [
        (Literal("p", (x, y)), y),
        (Literal("p", (x, y)), x),
        (Literal("p", (x, y)), Literal("pair", (y, x))),
        (Literal("p", (1, y)), y),
        (Literal("p", (x, x)), x),
        (Literal("p", (x, Literal("f", (y,)))), y),
        (Literal("p", (x, y)), Literal("k")),
        (Literal("p", (7, y)), y),
        (Literal("r", (x,)), x),
    ]
    for pattern, template in cases:
        got = bb.collect(pattern, template, {})
        assert got == _general(bb, pattern, template), term_str(pattern)
    assert bb.collect(parse_term("p(X, Y)[source(S)]"), x, {}) is None
    bb.add(parse_term("p(Z, z)"))
    assert bb.collect(Literal("p", (x, y)), y, {}) is None


def test_findall_in_a_program_with_bound_variables_and_rules() -> None:
    out: list[str] = []
    src = """v(1, 10). v(2, 20). v(1, 30). w(X, Y) :- v(X, Y) & Y > 15.
!s.
+!s <- K = 1; .findall(V, v(K, V), A); .findall(V, w(_, V), B);
       .findall(p(I, V), v(I, V), C); .sort(C, D); .max(A, M); .length(C, N);
       .print(A, B, C, D, M, N)."""
    ag = Agent(src, "t", printer=lambda n, t: out.append(t))
    ag.run(10_000)
    assert out == ["[10,30][20,30][p(1,10),p(2,20),p(1,30)][p(1,10),p(1,30),p(2,20)]303"]
