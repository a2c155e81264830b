from __future__ import annotations

import random
from collections import deque

import pytest

from robocog.planning.atomspace_rules import AtomSpaceSearch, facts_of
from robocog.planning.rules import RuleError, Var, default_rules, read_rules
from robocog.planning.task import PLACE, TAKE
from robocog.planning.world import Scene, build_task, scene_facts

from .conftest import random_goal, random_scene


def _rule(name: str, fixed_under: bool = False):
    for rule in default_rules():
        if rule.name == name and (
            name != "stack" or (("fixed-object", Var("?under")) in rule.present) == fixed_under
        ):
            return rule
    raise AssertionError(name)


def test_the_four_actions_are_read_with_their_kinds() -> None:
    kinds = {(r.name, r.kind) for r in default_rules()}
    assert kinds == {("pickup", TAKE), ("unstack", TAKE), ("putdown", PLACE), ("stack", PLACE)}


def test_pickup_needs_a_clear_unstacked_object() -> None:
    scene = Scene(["a", "b", "c"], ["table"], on={"a": "b", "c": "table"})
    found = {b[Var("?ob")] for b in _rule("pickup").groundings(scene_facts(scene))}
    assert found == set()  # a and c are stacked, b is covered by a
    scene2 = Scene(["a", "b"], ["table"])
    assert {b[Var("?ob")] for b in _rule("pickup").groundings(scene_facts(scene2))} == {"a", "b"}


def test_unstack_finds_every_stacked_clear_object_and_the_given_form_pins_one() -> None:
    scene = Scene(["a", "b", "c", "d"], ["table"], on={"a": "b", "c": "table"})
    rule = _rule("unstack")
    every = {rule.label(b) for b in rule.groundings(scene_facts(scene))}
    assert every == {("unstack", ("a", "b")), ("unstack", ("c", "table"))}
    one = rule.given("c").groundings(scene_facts(scene))
    assert [rule.label(b) for b in one] == [("unstack", ("c", "table"))]


def test_stack_on_a_fixed_object_keeps_it_clear() -> None:
    scene = Scene(["a"], ["table"], held="a")
    facts = frozenset(scene_facts(scene))
    rule = _rule("stack", fixed_under=True)
    (binding,) = rule.given("a", "table").groundings(facts)
    after = rule.apply(facts, binding)
    assert {("on", "a", "table"), ("stacked", "a"), ("clear", "table"), ("clear", "a")} <= after
    assert ("in-hand", "a") not in after
    on_object = _rule("stack")
    scene2 = Scene(["a", "b"], [], held="a")
    facts2 = frozenset(scene_facts(scene2))
    (b2,) = on_object.given("a", "b").groundings(facts2)
    assert ("clear", "b") not in on_object.apply(facts2, b2)


def test_rule_file_errors_name_line_and_column() -> None:
    text = '(DefineLink (DefinedSchemaNode "x")\n  (QueryLink (VariableNode "?a") (AndLink (FooLink)) (ListLink)))'
    with pytest.raises(RuleError) as info:
        read_rules(text, "bad.scm")
    assert "bad.scm:2:" in str(info.value)
    assert "unsupported clause foolink" in str(info.value)


def _reachable(task, limit: int = 400):
    seen = {task.init}
    queue = deque([task.init])
    while queue and len(seen) < limit:
        s = queue.popleft()
        for _op, t in task.successors(s):
            if t not in seen:
                seen.add(t)
                queue.append(t)
    return seen


@pytest.mark.parametrize("seed", range(12))
def test_compiled_operators_agree_with_the_rule_matcher(seed: int) -> None:
    rng = random.Random(seed)
    scene = random_scene(rng, rng.randint(1, 4), rng.randint(0, 2))
    task = build_task(scene, [])
    rules = default_rules()
    for state in list(_reachable(task, 60)):
        facts = frozenset(task.state_facts(state)) | {
            f for f in scene_facts(scene) if f[0] in ("object", "fixed-object")
        }
        busy = any(f[0] == "in-hand" for f in facts)
        want = PLACE if busy else TAKE
        expected = set()
        for rule in rules:
            if rule.kind != want:
                continue
            for b in rule.groundings(facts):
                nxt = rule.apply(facts, b)
                expected.add(
                    (
                        rule.label(b),
                        frozenset(f for f in nxt if f[0] not in ("object", "fixed-object")),
                    )
                )
        got = {
            ((op.name, op.args), frozenset(task.state_facts(s))) for op, s in task.successors(state)
        }
        assert got == expected


@pytest.mark.parametrize("seed", range(6))
def test_atomspace_matcher_expands_states_as_the_compiled_operators_do(seed: int) -> None:
    rng = random.Random(100 + seed)
    scene = random_scene(rng, rng.randint(1, 3), rng.randint(0, 2))
    goal = random_goal(rng, scene)
    task = build_task(scene, goal)
    space = AtomSpaceSearch(scene, goal)
    frontier = [(task.init, space.init)]
    for _depth in range(3):
        nxt = []
        for s_task, s_space in frontier:
            a = {(lab, frozenset(facts_of(k))) for lab, k in space.successors(s_space)}
            b = {
                ((op.name, op.args), frozenset(task.state_facts(s)))
                for op, s in task.successors(s_task)
            }
            assert a == b
            pairs = {frozenset(facts_of(k)): k for _lab, k in space.successors(s_space)}
            for _op, s in task.successors(s_task):
                nxt.append((s, pairs[frozenset(task.state_facts(s))]))
        frontier = nxt[:8]
