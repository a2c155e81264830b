"""What the interpreter computes once and reuses must not change what agents do.

Plan contexts are compiled, candidate plans are remembered per trigger, goals and
actions with one variable reuse what they built for the same value, and ``run()``
inlines the cycle: each test below gives a case where a stale or wrong shortcut would
show in the output.
"""

from __future__ import annotations

from robocog.bdi import Agent
from robocog.bdi.beliefs import BeliefBase
from robocog.bdi.logic import compile_cond, holds, right_assoc
from robocog.bdi.parser import parse_term
from robocog.bdi.terms import Literal, java_double_str
from robocog.bdi.unifier import resolve, variables


def run(src: str, cycles: int | None = 100_000) -> list[str]:
    out: list[str] = []
    ag = Agent(src, "t", printer=lambda n, t: out.append(t))
    ag.run(cycles)
    return out


def test_actions_get_the_current_value_when_a_variable_changes() -> None:
    calls: list[object] = []
    src = """!go([a, b, b, 1, 1.0, c]).
+!go([]).
+!go([X|T]) <- act(X); !go(T)."""
    ag = Agent(src, "t", printer=lambda n, t: None)
    ag.register_action("act", lambda x: calls.append(x) or True)
    ag.run()
    assert calls == ["a", "b", "b", 1, 1.0, "c"]
    assert [type(c) for c in calls[3:5]] == [int, float]


def test_goals_get_the_current_value_when_a_variable_changes() -> None:
    src = """!go([p, q, q, r]).
+!go([]).
+!go([X|T]) <- !show(X); !go(T).
+!show(Y) <- .print(Y)."""
    assert run(src) == ["p", "q", "q", "r"]


def test_a_goal_with_an_unbound_variable_gets_fresh_variables_each_time() -> None:
    src = """!s.
+!s <- !get(A); !get(B); .print(A, B).
+!get(X) : not got(_) <- +got(1); X = 1.
+!get(X) <- X = 2."""
    assert run(src) == ["12"]


def test_a_plan_added_at_run_time_is_used_by_a_goal_already_seen() -> None:
    src = """!s.
+!s <- !g; .add_plan("+!g <- .print(new)."); !g.
+!g <- .print(old)."""
    assert run(src) == ["old", "old"]
    src2 = """!s.
+!s <- !g; .add_plan("+!g <- .print(new).", self, begin); !g.
+!g <- .print(old)."""
    assert run(src2) == ["old", "new"]


def test_a_removed_plan_is_no_longer_a_candidate() -> None:
    src = """!s.
+!s <- !g; .remove_plan(first); !g.
@first +!g <- .print(first).
+!g <- .print(second)."""
    assert run(src) == ["first", "second"]


def test_conjunctions_keep_their_order_of_solutions_when_regrouped() -> None:
    src = """p(1). p(2). q(1, a). q(2, b). q(2, c). r(c).
!s.
+!s : (p(X) & q(X, Y)) & r(Y) <- .print(X, Y)."""
    assert run(src) == ["2c"]
    f = parse_term("(a & b) & (c & d)")
    assert str(right_assoc(f)) == "(a & (b & (c & d)))"


def test_a_compiled_context_agrees_with_holds() -> None:
    ag = Agent("p(1). p(2). q(2). t(a) :- p(2). u. r(X) :- p(X) & X > 1.", "t")
    for text in [
        "p(X) & q(X)",
        "p(X) & X > 1",
        "X = 3 & X > 2",
        "not p(3) & p(Y)",
        "u & p(Z)",
        "t(W) & p(2)",
        "r(V)",
        "p(9) & p(1)",
        "not u",
        "true & p(1)",
        "false | p(1)",
    ]:
        f = right_assoc(parse_term(text))
        s1: dict = {}
        s2: dict = {}
        assert compile_cond(f)(ag, s1, []) == holds(ag, f, s2, []), text
        names = variables(f)
        assert [resolve(v, s1) for v in names] == [resolve(v, s2) for v in names], text


def test_a_deterministic_fact_query_is_decided_without_backtracking() -> None:
    bb = BeliefBase()
    bb.add(Literal("on", (Literal("a"), Literal("b")), (Literal("source", (Literal("self"),)),)))
    pattern = parse_term("on(a, X)")
    s: dict = {}
    assert bb.first_det(pattern, s, []) is True
    assert [str(v) for v in s.values()] == ["b"]
    assert bb.first_det(parse_term("on(c, X)"), {}, []) is False
    bb.add(Literal("on", (Literal("a"), Literal("c")), (Literal("source", (Literal("self"),)),)))
    assert bb.first_det(pattern, {}, []) is None  # two answers now


def test_an_atom_with_a_rule_is_still_evaluated_by_its_rule() -> None:
    src = """ready :- battery(B) & B > 10.
battery(50).
!s.
+!s : ready & battery(B) <- .print(B)."""
    assert run(src) == ["50"]


def test_an_unhandled_external_belief_change_from_a_plan_is_still_dropped() -> None:
    src = """c(0).
!s.
+!s <- -+c(1); -+c(2); .print(done).
-c(X) <- .print(gone(X))."""
    assert run(src) == ["gone(0)", "gone(1)", "done"]


def test_run_and_step_take_the_same_number_of_cycles() -> None:
    src = "c(0).\n!count(50).\n+!count(0).\n+!count(N) : c(C) <- -+c(C + 1); !count(N - 1)."
    a = Agent(src, "t")
    n = a.run()
    b = Agent(src, "t")
    m = 0
    while not b.is_idle():
        b.step()
        m += 1
    assert n == m == a.cycle == b.cycle
    assert a.query("c(X)") == b.query("c(X)") == [{"X": 50}]


def test_large_doubles_print_with_all_their_digits() -> None:
    assert java_double_str(113958956955015.75) == "1.1395895695501575E14"
    assert java_double_str(1e7) == "1.0E7"
    assert java_double_str(-2.5e-10) == "-2.5E-10"
    assert java_double_str(0.0005) == "5.0E-4"


def test_free_variable_queries_bind_as_unification_would() -> None:
    # all free and distinct: the fast path; a repeated variable, a bound one, an
    # annotation or a rule in the predicate: unification; the answers must agree
    src = """v(1, 1). v(2, 3). v(f(x), [a]). w(1). w(X) :- X = 9.
!s.
+!s <- .findall(p(A, B), v(A, B), L1); .findall(A2, v(A2, A2), L2); .findall(C, v(2, C), L3);
  .findall(D, w(D), L4); .findall(E, v(E, _)[source(self)], L5); .print(L1, L2, L3, L4, L5);
  .findall(Z, v(Z, _), L6); .print(Z, L6)."""
    assert run(src) == [
        "[p(1,1),p(2,3),p(f(x),[a])][1][3][1,9][1,2,f(x)]",
        "Z<no-value>[1,2,f(x)]",
    ]
