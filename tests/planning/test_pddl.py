from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from robocog.planning.pddl import (
    PDDLError,
    ground,
    read_domain,
    read_problem,
    scene_problem,
    task_state_problem,
    write_problem,
)
from robocog.planning.planner import solve_task
from robocog.planning.world import Scene

BLOCKS = Path(__file__).resolve().parents[3] / "shared" / "pddl" / "blocks"
needs_tasks = pytest.mark.skipif(
    not (BLOCKS / "domain.pddl").exists(), reason="IPC blocks tasks absent"
)


@needs_tasks
def test_reads_the_four_operator_domain() -> None:
    domain = read_domain((BLOCKS / "domain.pddl").read_text())
    assert [a.name for a in domain.actions] == ["pick-up", "put-down", "stack", "unstack"]
    assert domain.predicates == {"on": 2, "ontable": 1, "clear": 1, "handempty": 0, "holding": 1}
    stack = domain.actions[2]
    assert (False, ("clear", "?y")) in stack.effect


@needs_tasks
@pytest.mark.parametrize("number", range(1, 36))
def test_ipc_task_is_solved_with_a_valid_plan_at_its_lower_bound_or_proved(number: int) -> None:
    domain = read_domain((BLOCKS / "domain.pddl").read_text())
    problem = read_problem((BLOCKS / f"task{number:02d}.pddl").read_text())
    task = ground(domain, problem)
    result = solve_task(task, "astar", style="pddl")
    assert result.found and result.optimal
    ops = {(op.name, op.args): op for op in task.operators}
    assert task.validate([ops[(s.name, s.args)] for s in result.steps])
    assert result.length >= result.lower_bound
    assert result.length % 2 == 0  # every move is a take and a place


@needs_tasks
def test_small_tasks_match_breadth_first_lengths() -> None:
    domain = read_domain((BLOCKS / "domain.pddl").read_text())
    for number in range(1, 7):
        task = ground(domain, read_problem((BLOCKS / f"task{number:02d}.pddl").read_text()))
        assert solve_task(task, "astar").length == solve_task(task, "first").length


@needs_tasks
def test_a_problem_written_from_a_state_reads_back_to_that_state() -> None:
    domain = read_domain((BLOCKS / "domain.pddl").read_text())
    task = ground(domain, read_problem((BLOCKS / "task05.pddl").read_text()))
    result = solve_task(task, "astar")
    ops = {(op.name, op.args): op for op in task.operators}
    state = task.init
    for step in result.steps[:3]:
        state = ops[(step.name, step.args)].apply(state)
    text = task_state_problem(task, state, "midway", "blocks")
    again = ground(domain, read_problem(text))
    assert set(again.state_facts(again.init)) == set(task.state_facts(state))
    assert solve_task(again, "astar").length == result.length - 3


def test_scene_written_as_blocks_problem() -> None:
    scene = Scene(["A", "B", "C"], ["table"], on={"A": "B", "C": "table"})
    text = scene_problem(scene, [("on", "B", "A"), ("on", "C", "table")], "s")
    problem = read_problem(text)
    assert set(problem.init) == {
        ("on", "a", "b"),
        ("ontable", "b"),
        ("ontable", "c"),
        ("clear", "a"),
        ("clear", "c"),
        ("handempty",),
    }
    assert problem.goal == [(True, ("on", "b", "a")), (True, ("ontable", "c"))]


@pytest.mark.parametrize(
    ("text", "marker"),
    [
        (
            "(define (domain d) (:action a :parameters (?x) :precondition (or (p ?x) (q ?x))))",
            "(or",
        ),
        (
            "(define (domain d)\n  (:predicates (p ?x))\n  (:action a :parameters (?x) :effect (q ?y)))",
            "(:action",
        ),
        ("(define (domain d) (:bogus))", "(:bogus"),
        ("(define (domain d)", "(define"),
    ],
)
def test_domain_errors_name_line_and_column(text: str, marker: str) -> None:
    with pytest.raises(PDDLError) as info:
        read_domain(text, "d.pddl")
    before = text[: text.index(marker)]
    line = before.count("\n") + 1
    column = len(before) - (before.rfind("\n") + 1) + 1
    assert f"d.pddl:{line}:{column}:" in str(info.value)


def test_unknown_predicate_in_a_problem_is_reported() -> None:
    domain = read_domain(
        "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x))))"
    )
    problem = read_problem(
        "(define (problem q) (:domain d) (:objects o) (:init (r o)) (:goal (and)))"
    )
    with pytest.raises(PDDLError, match="unknown predicate"):
        ground(domain, problem)


GRIPPER = """(define (domain gripper) (:requirements :strips)
 (:predicates (room ?r) (ball ?b) (at-robby ?r) (at ?b ?r) (free) (carry ?b))
 (:action move :parameters (?from ?to) :precondition (and (room ?from) (room ?to) (at-robby ?from))
  :effect (and (at-robby ?to) (not (at-robby ?from))))
 (:action pick :parameters (?b ?r) :precondition (and (ball ?b) (room ?r) (at ?b ?r) (at-robby ?r) (free))
  :effect (and (carry ?b) (not (at ?b ?r)) (not (free))))
 (:action drop :parameters (?b ?r) :precondition (and (ball ?b) (room ?r) (carry ?b) (at-robby ?r))
  :effect (and (at ?b ?r) (free) (not (carry ?b)))))"""

GRIPPER_TASK = """(define (problem g) (:domain gripper) (:objects ra rb b1 b2)
 (:init (room ra) (room rb) (ball b1) (ball b2) (at-robby ra) (at b1 ra) (at b2 ra) (free))
 (:goal (and (at b1 rb) (at b2 rb))))"""


def test_another_strips_domain_is_planned_optimally_without_the_blocks_bound() -> None:
    from robocog.planning.heuristics import BlocksView

    task = ground(read_domain(GRIPPER), read_problem(GRIPPER_TASK))
    assert not BlocksView.fits(task)
    best = solve_task(task, "astar")
    assert best.optimal and best.length == solve_task(task, "first").length == 7
    assert best.lower_bound == 0


names = st.from_regex(r"[a-z][a-z0-9\-]{0,5}", fullmatch=True)


@given(
    st.lists(names, min_size=1, max_size=5, unique=True),
    st.lists(
        st.tuples(
            st.sampled_from(["on", "clear", "ontable"]), st.integers(0, 4), st.integers(0, 4)
        ),
        max_size=6,
    ),
)
def test_written_problems_read_back_unchanged(objects: list[str], raw: list) -> None:
    def fact(p: str, i: int, j: int) -> tuple[str, ...]:
        a, b = objects[i % len(objects)], objects[j % len(objects)]
        return (p, a, b) if p == "on" else (p, a)

    init = list(dict.fromkeys(fact(*r) for r in raw)) + [("handempty",)]
    goal = list(dict.fromkeys(fact(*r) for r in raw[::-1]))
    problem = read_problem(write_problem("p", "blocks", objects, init, goal))
    assert [o for o, _ in problem.objects] == objects
    assert problem.init == init
    assert problem.goal == [(True, g) for g in goal]
