"""The reasoning cycle: Jason's semantics, seen through what agents print and believe."""

from __future__ import annotations

from collections import deque

import pytest

from robocog.bdi import ActionHandle, Agent
from robocog.bdi.circumstance import Intention


def run(src: str, cycles: int | None = 100_000, **kw: object) -> list[str]:
    out: list[str] = []
    ag = Agent(src, "t", printer=lambda n, t: out.append(t), **kw)
    ag.run(cycles)
    return out


def test_tail_recursion_keeps_the_stack_flat() -> None:
    src = "!s.\n+!s <- !sum(3000, 0).\n+!sum(0, A) <- .print(A).\n+!sum(N, A) <- !sum(N-1, A+N)."
    ag = Agent(src, "t", printer=lambda n, t: None)
    deepest = 0
    while not ag.is_idle():
        ag.step()
        for i in ag.intentions():
            deepest = max(deepest, len(i))
    assert deepest <= 3


def test_tail_recursion_still_returns_bindings_to_the_caller() -> None:
    src = """!s.
+!s <- !len([a, b, c, d], 0, N); .print(N).
+!len([], A, A).
+!len([_|T], A, N) <- !len(T, A + 1, N)."""
    assert run(src) == ["4"]


def test_non_tail_recursion_unwinds_in_order() -> None:
    src = "!s.\n+!s <- !c(3).\n+!c(0).\n+!c(N) <- !c(N-1); .print(N)."
    assert run(src) == ["1", "2", "3"]


def test_failure_in_a_failure_plan_goes_to_the_goal_below() -> None:
    src = """!s.
+!s <- !a; .print(s_after).
+!a <- !b.
+!b <- .fail.
-!b <- .print(b_handler); .fail.
-!a <- .print(a_handler)."""
    assert run(src) == ["b_handler", "a_handler", "s_after"]


def test_an_unhandled_failure_drops_the_intention_and_warns() -> None:
    warnings: list[str] = []
    out = run(
        "!s.\n!t.\n+!s <- .fail; .print(no).\n+!t <- .print(t).",
        warn=lambda n, t: warnings.append(t),
    )
    assert out == ["t"]
    assert warnings and "s" in warnings[0]


def test_belief_events_with_no_plan_do_not_stop_the_body() -> None:
    assert run("!s.\n+!s <- +a; +b; -a; .print(done).") == ["done"]


def test_external_belief_plan_runs_as_its_own_intention() -> None:
    src = "seen(1).\n+seen(X) <- .print(seen, X).\n!s.\n+!s <- .print(s)."
    assert run(src) == ["seen1", "s"]


def test_test_goal_plan_binding_flows_back() -> None:
    src = "!s.\n+!s <- ?v(X); .print(X).\n+?v(Y) <- Y = 5."
    assert run(src) == ["5"]


def test_failing_test_goal_has_its_error() -> None:
    src = "!s.\n+!s <- ?nothere.\n-!s[error(E)] <- .print(E)."
    assert run(src) == ["test_goal_failed"]


def test_succeed_goal_continues_the_caller() -> None:
    src = """!s.
+!s <- !loop; .print(after).
+!loop <- .print(in); .succeed_goal(loop); .print(never)."""
    assert run(src) == ["in", "after"]


def test_drop_intention_stops_everything_of_that_goal() -> None:
    src = """!a.
!b.
+!a <- .print(a1); .print(a2); .print(a3).
+!b <- .drop_intention(a); .print(b)."""
    assert run(src) == ["a1", "a2", "b"]


def test_strong_negation_and_rules_with_not() -> None:
    src = """~wet(street).
p(1). p(2). p(3).
odd(X) :- p(X) & X mod 2 == 1.
!s.
+!s : ~wet(street) <- .findall(X, odd(X), L); .print(L); .count(p(_) & not odd(_), N); .print(N)."""
    assert run(src) == ["[1,3]", "0"]


def test_findall_sees_newest_beliefs_first_and_initial_ones_in_order() -> None:
    src = "b(1). b(2).\n!s.\n+!s <- +c(1); +c(2); .findall(X, b(X), L); .findall(Y, c(Y), M); .print(L, M)."
    assert run(src) == ["[1,2][2,1]"]


def test_printing_follows_jason() -> None:
    src = '!s.\n+!s <- .print(1.0, " ", 2.5, " ", 1/3, " ", "x", " ", f("x", [a|T]), " ", 1e-4, " ", 123456789.5).'
    assert run(src) == ['1 2.5 0.3333333333333333 x f("x",[a|T]) 1.0E-4 1.234567895E8']


def test_while_and_for_leave_the_plans_variables_as_they_were() -> None:
    src = """!s.
+!s <- X = 1; for (.member(Y, [a, b])) { Z = Y }; .print(X); if (var_unbound(Z)) { true }."""
    out = run(src + "\n-!s <- .print(failed).")
    assert out[0] == "1"


def test_wait_suspends_only_its_intention() -> None:
    src = "!a.\n!b.\n+!a <- .wait(50); .print(a).\n+!b <- .print(b1); .print(b2)."
    assert run(src) == ["b1", "b2", "a"]


def test_wait_for_an_event() -> None:
    src = "!a.\n!b.\n+!a <- .wait({+go}); .print(went).\n+!b <- .print(b); +go."
    assert run(src) == ["b", "went"]


def test_percepts_become_beliefs_with_source_percept_and_events() -> None:
    out: list[str] = []
    ag = Agent(
        "+obstacle(D)[source(percept)] <- .print(seen, D).\n-obstacle(D) <- .print(gone, D).",
        "t",
        printer=lambda n, t: out.append(t),
    )
    ag.add_percept("obstacle(front)")
    ag.run()
    assert ag.query("obstacle(D)[source(S)]") == [
        {"D": ag.query("X = front")[0]["X"], "S": ag.query("X = percept")[0]["X"]}
    ]
    ag.set_percepts(["obstacle(left)"])
    ag.run()
    assert out == ["seenfront", "gonefront", "seenleft"]
    ag.clear_percepts()
    ag.run()
    assert ag.beliefs() == []


def test_deferred_actions_let_other_intentions_run_and_then_resume() -> None:
    out: list[str] = []
    handles: list[ActionHandle] = []

    def move(distance: float) -> ActionHandle:
        h = ActionHandle()
        handles.append(h)
        return h

    ag = Agent(
        "!go.\n!talk.\n+!go <- move(2); .print(arrived).\n+!talk <- .print(t1); .print(t2).\n"
        "-!go[error(E)] <- .print(E).",
        "t",
        printer=lambda n, t: out.append(t),
    )
    ag.register_action("move", move)
    ag.run()
    assert out == ["t1", "t2"] and ag.has_pending() and len(handles) == 1
    handles[0].succeed()
    ag.run()
    assert out == ["t1", "t2", "arrived"] and not ag.has_pending()
    ag.add_goal("go")
    ag.run()
    handles[1].fail("blocked")
    ag.run()
    assert out[-1] == "action_failed"


def test_an_action_raising_an_exception_fails_the_goal() -> None:
    out: list[str] = []
    ag = Agent(
        '!go.\n+!go <- boom.\n-!go[error(E), error_msg(M)] <- .print(E, " ", M).',
        "t",
        printer=lambda n, t: out.append(t),
    )
    ag.register_action("boom", lambda: 1 / 0)
    ag.run()
    assert out == ["action_failed division by zero"]


def test_unknown_action_fails() -> None:
    assert run("!go.\n+!go <- jump.\n-!go[error(E)] <- .print(E).") == ["action_failed"]


class LastIntentionFirst(Agent):
    def select_intention(self, running: deque[Intention]) -> Intention | None:
        return running.pop()


class LastPlanFirst(Agent):
    def select_option(self, options: list) -> tuple | None:
        return options[-1] if options else None


def test_selection_functions_can_be_overridden() -> None:
    src = "!a.\n!b.\n+!a <- .print(a1); .print(a2).\n+!b <- .print(b1); .print(b2)."
    out: list[str] = []
    LastIntentionFirst(src, "t", printer=lambda n, t: out.append(t)).run()
    assert out == ["a1", "b1", "b2", "a2"]
    out2: list[str] = []
    LastPlanFirst(
        "!g.\n+!g <- .print(first).\n+!g <- .print(second).",
        "t",
        printer=lambda n, t: out2.append(t),
    ).run()
    assert out2 == ["second"]


def test_same_program_same_inputs_same_trace() -> None:
    src = """!a. !b. !c.
+!a <- for (.range(I, 1, 5)) { +x(I); .print(a, I) }.
+!b <- while (x(N) & N < 4) { -x(N); .print(b, N) }.
+!c <- .findall(X, x(X), L); .print(L).
+x(N) : N > 3 <- .print(big, N)."""
    assert run(src) == run(src)
    assert len(run(src)) > 5


def test_python_api_reads_and_changes_beliefs() -> None:
    ag = Agent("p(1). p(2).\nq(X) :- p(X) & X > 1.", "t")
    ag.add_belief("p(3)")
    assert [b["X"] for b in ag.query("q(X)")] == [3, 2]
    ag.remove_belief("p(3)")
    assert ag.believes("q(2)") and not ag.believes("q(3)")
    assert sorted(str(b) for b in ag.beliefs("p")) == ["p(1)[source(self)]", "p(2)[source(self)]"]


@pytest.mark.parametrize(
    ("expr", "value"),
    [
        ("-7 div 2", "-3"),
        ("-7 mod 3", "-1"),
        ("2 ** 0.5 * 2 ** 0.5", "2.0000000000000004"),
        ("10 / 4", "2.5"),
        ("3 - -2", "5"),
    ],
)
def test_arithmetic_like_java(expr: str, value: str) -> None:
    assert run(f"!s.\n+!s <- X = {expr}; .print(X).") == [value]


def test_division_by_zero_fails_the_goal() -> None:
    assert run("!s.\n+!s <- X = 1 div 0.\n-!s[error(E)] <- .print(E).") == ["ia_failed"]
    assert run("!s.\n+!s <- X = 1 / 0; .print(X).") == ["Infinity"]


def test_an_atomic_plan_runs_without_interleaving() -> None:
    src = """!a.
!b.
@pa[atomic] +!a <- .print(a1); !sub; .print(a2).
+!sub <- .print(sub).
+!b <- .print(b1); .print(b2)."""
    assert run(src) == ["a1", "sub", "a2", "b1", "b2"]
    assert run(src.replace("@pa[atomic] ", "")) == ["a1", "b1", "sub", "b2", "a2"]


def test_true_and_false_inside_formulas() -> None:
    src = """!s.
+!s : 1 < 2 & true <- if (true & not false) { .print(yes) }; .eval(E, true | false); .print(E)."""
    assert run(src) == ["yes", "true"]


def test_wait_for_a_condition_and_timeouts() -> None:
    src = """!a.
!b.
+!a <- .wait(n(X) & X > 2); ?n(Y); .print(a, Y);
       .wait({+never}, 100, T); .print(waited, T);
       .wait({+never}, 50).
-!a[error(E)] <- .print(timeout, E).
+!b <- for (.range(I, 1, 4)) { -+n(I) }."""
    assert run(src) == ["a3", "waited100", "timeoutwait_timeout"]


# ---- fork-join (the orders below are those Jason 3.3 prints for the same programs)
def test_fork_and_interleaves_the_branches_and_waits_for_both() -> None:
    src = """!start.
+!start <- .print(begin); !a |&| !b; .print(both_done); !c ||| !d; .print(one_done).
+!a <- .print(a1); .print(a2); .print(a3).
+!b <- .print(b1).
+!c <- .print(c1); .print(c2); .print(c3).
+!d <- .print(d1)."""
    assert run(src) == [
        "begin", "a1", "b1", "a2", "a3", "both_done", "c1", "d1", "c2", "one_done",
    ]  # fmt: skip


def test_fork_branches_keep_their_own_bindings_and_the_last_goes_on() -> None:
    src = """!g.
+!g <- !v(A) |&| !w(B); .print(after, A, B).
+!v(5) <- .print(v).
+!w(7) <- .print(w1); .print(w2)."""
    # the branch of !w arrives last at the join: its bindings go on, A stays unbound
    out = run(src)
    assert out[:3] == ["v", "w1", "w2"]
    assert out[3].startswith("after") and out[3].endswith("7") and "5" not in out[3]


def test_a_failing_branch_of_fork_and_drops_the_other_and_fails_the_goal() -> None:
    src = """!g3.
+!g3 <- !ok |&| !bad; .print(never).
-!g3 <- .print(g3_failed).
+!ok <- .print(ok1); .print(ok2); .print(ok3).
+!bad <- .print(bad1); .fail."""
    assert run(src) == ["ok1", "bad1", "ok2", "g3_failed"]


def test_a_failing_branch_of_fork_or_leaves_the_other_to_finish() -> None:
    warned: list[str] = []
    src = """!g4.
+!g4 <- !bad ||| !slow; .print(after).
+!bad <- .fail.
+!slow <- .print(s1); .print(s2)."""
    out = run(src, warn=lambda n, t: warned.append(t))
    assert out == ["s1", "s2", "after"]
    assert any("|||" in w for w in warned)


def test_fork_operators_nest_as_in_jason() -> None:
    # |&| binds tighter than |||: a ||| (b |&| c); Jason runs "after" twice here too
    src = "!g.\n+!g <- .print(a) ||| .print(b) |&| .print(c); .print(after)."
    assert run(src) == ["a", "b", "c", "after", "after"]


def test_printing_univ_and_true_as_jason_3_3() -> None:
    src = """!s.
+!s <- true; T = p(X + 1, Y < 2, Y \\== a, Z =.. W); .print(T);
  p(1)[x] =.. L; .print(L); Q =.. [default, q, [1], [b]]; .print(Q); R =.. [r, [2], []]; .print(R);
  true.
-!s[error(E), error_msg(M), noenv] <- .print(E, " ", M)."""
    # relational expressions with spaces, arithmetic without; =.. with the namespace
    # first; a `true` that is not first in the body is an (environment) action
    assert run(src) == [
        "p((X+1),(Y < 2),(Y \\\\== a),(Z =.. W))".replace("\\\\", "\\"),
        "[default,p,[1],[x]]",
        "q(1)[b]",
        "r(2)",
        "action_failed no environment configured!",
    ]


def test_annotation_lists_with_a_tail() -> None:
    # the outputs Jason 3.3 prints for the same program
    src = """b(1)[x,y].
!s.
+!s <- +b(2)[z]; ?b(1)[A|T]; .print(A, " ", T); ?b(1)[x|T2]; .print(T2);
  ?b(2)[source(S)|R]; .print(S, " ", R);
  .findall(Ts, b(_)[_|Ts], L); .print(L);
  X = q(1)[a|Tl]; Tl = [c,b]; .print(X);
  !g(5)[u, v]; !h[w].
+!g(N)[source(S)|Rest] <- .print(g, N, " ", S, " ", Rest).
+!h[A|B] <- .print(h, " ", A, " ", B)."""
    assert run(src) == [
        "source(self) [x,y]",
        "[source(self),y]",
        "self [z]",
        "[[z],[x,y]]",
        "q(1)[a,b,c]",
        "g5 self [u,v]",
        "h source(self) [w]",
    ]


def test_a_failure_plan_after_fail_goal_of_the_last_formula_runs_once() -> None:
    src = """!v.
+!v <- .fail_goal(v).
-!v <- .print(v_failed); !w.
+!w <- !w2.
+!w2 <- .fail.
-!w <- .print(w_failed)."""
    assert run(src, 2_000) == ["v_failed", "w_failed"]


def test_namespaces_as_jason_3_3_prints_them() -> None:
    src = """b(0).
ns1::b(1).
!start.
+!start <- ?b(X); .print(X); ?ns1::b(Y); .print(Y);
  +ns1::c(5); !ns1::g(7); !g(8);
  ns1::b(Z) =.. U; .print(U); .print(ns1::b(1), " ", default::b(1)); !t; !pub::t2.
+!ns1::g(X) <- .print(ns1g, X).
+!g(X) <- .print(g, X).
+ns1::c(X) <- .print(added_c, X).
{ begin namespace(priv, local) }
+!t <- .print(never).
{ end }
{ begin namespace(pub, global) }
q(1).
+!t2 <- ?q(A); .print(t2, A); if (q(B)) { .print(ifq, B) }; ?default::b(D); .print(D).
{ end }
+!t <- .print(default_t)."""
    assert run(src) == [
        "0", "1", "added_c5", "ns1g7", "g8", "[ns1,b,[Z],[]]", "ns1::b(1) b(1)",
        "default_t", "t21", "ifq1", "0",
    ]  # fmt: skip


def test_a_wait_that_times_out_fails_with_jasons_error() -> None:
    src = """!s.
+!s <- .wait({+never}, 30).
-!s[error(E), error_msg(M)] <- .print(E, "|", M)."""
    assert run(src) == ["wait_timeout|timeout in .wait"]
