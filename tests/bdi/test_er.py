"""JasonER: sub-plans, goal conditions, branches for update events and ``.done``.

Each program was run on Jason 3.3 and on robocog; the expected lines are Jason's.
"""

from __future__ import annotations

import pytest

from robocog.bdi import Agent, ParseError
from robocog.bdi.parser import parse_program


def out(program: str) -> list[str]:
    printed: list[str] = []
    Agent(program, "t", printer=lambda n, t: printed.append(t)).run(10_000)
    return printed


SCOPE = """\
!start.
+!start <- !g(5); !h.
+!g(X) <- !a; !b(Y); .print(X, " ", Y). {
   +!a <- .print(a, X).
   +!b(Y) <- Y = X + 1.
}
+!h <- !a.
-!h <- .print(no_a).
"""


def test_sub_plans_share_their_plans_variables_and_scope() -> None:
    # !a is relevant only while +!g(X) is intended: !h finds no plan for it
    assert out(SCOPE) == ["a5", "5 6", "no_a"]


CONDITION = """\
!start.
!other.
+!start <- !w(1); .print(after_w); !v; .print(after_v).
+!w(N) <: false <- .print(waiting, N); .send(self, tell, go(N)). {
   +go(M) : M == N <- .print(got_go, M); .done.
}
+!v <: flag <- .print(v_body).
+!other <- .wait(300); +flag; .print(flag_added).
"""


def test_a_goal_condition_holds_the_goal_until_done_or_until_it_holds() -> None:
    # +go(1) from outside runs the sub-plan in a branch of !w's intention; its .done
    # achieves !w(1); !v waits for flag after its body, and goes on a cycle after the
    # belief is added (the intention that added it first), as in Jason
    assert out(CONDITION) == [
        "waiting1",
        "got_go1",
        "after_w",
        "v_body",
        "flag_added",
        "after_v",
    ]


def test_a_goal_condition_that_comes_to_hold_ends_the_plan_while_it_runs() -> None:
    prog = (
        "!start.\n!other.\n+!start <- !w; .print(after_w).\n"
        "+!w <: flag <- .print(w1); .wait(1000); .print(w2_never).\n"
        "+!other <- .wait(200); +flag; .print(flag_added).\n"
    )
    assert out(prog) == ["w1", "flag_added", "after_w"]


def test_an_update_event_no_sub_plan_takes_goes_to_the_plan_library() -> None:
    prog = (
        "!w.\n+!w <: false <- .send(self, tell, other). {\n"
        "  +go <- .done.\n}\n+other <- .print(root_plan).\n"
    )
    assert out(prog) == ["root_plan"]


def test_sub_plans_nest_and_share_down_the_levels() -> None:
    prog = parse_program("+!a(X) <- !b. {\n +!b <- !c(X). {\n  +!c(Z) <- .print(X, Z).\n }\n}\n")
    (a,) = prog.plans
    (b,) = list(a.subplans)
    (c,) = list(b.subplans)
    x = a.trigger.literal.args[0]
    assert b.body[0].term.args[0] is x and c.body[0].term.args[0] is x
    assert b.scope is a and c.scope is b
    assert out("!a(1).\n+!a(X) <- !b. {\n +!b <- !c(X). {\n  +!c(Z) <- .print(X, Z).\n }\n}\n") == [
        "11"
    ]


@pytest.mark.parametrize("text", ["{ +!b <- true. }\n", "a.\n{ +!b <- true. }\n"])
def test_sub_plans_must_follow_a_plan(text: str) -> None:
    with pytest.raises(ParseError, match="must follow a plan") as err:
        parse_program(text)
    assert (err.value.line, err.value.column) == (text.count("\n"), 1)
