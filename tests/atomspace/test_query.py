"""The behaviours of OpenCog's query tests, in robocog's own cases.

Each case loads a small knowledge base, runs a query link and compares the result with
the set OpenCog's semantics give: presence, absence, choice, unordered links,
evaluation of grounded predicates, execution output, constant clauses, and the result
forms of GetLink, BindLink, QueryLink, MeetLink and SatisfactionLink.
"""

from __future__ import annotations

import pytest

from robocog.atomspace import (
    FALSE_TV,
    TRUE_TV,
    AtomSpace,
    GroundedError,
    Link,
    Node,
    PatternError,
    QueueValue,
    TruthValue,
    query,
    read_atom,
    stv,
)

from .conftest import C, V, ev


def S(*atoms: Node | Link) -> Link:
    return Link("SetLink", *atoms)


def L(*atoms: Node | Link) -> Link:
    return Link("ListLink", *atoms)


def run(space: AtomSpace, text: str):  # noqa: ANN201
    return space.execute(read_atom(text))


@pytest.fixture
def animals() -> AtomSpace:
    s = AtomSpace()
    s.load_atomese(
        """
        (Inheritance (Concept "cat") (Concept "animal"))
        (Inheritance (Concept "dog") (Concept "animal"))
        (Inheritance (Concept "rock") (Concept "mineral"))
        (Evaluation (Predicate "has-fur") (Concept "cat"))
        (Evaluation (Predicate "has-fur") (Concept "dog"))
        (Evaluation (Predicate "barks") (Concept "dog"))
        (Inheritance (Predicate "has-fur") (Concept "animal"))
        (Set (Concept "red") (Concept "green") (Concept "blue"))
        (Member (Concept "cat") (Set (Concept "pet") (Concept "mammal")))
        """
    )
    return s


def test_get_single_variable_returns_the_atoms(animals: AtomSpace) -> None:
    r = run(animals, '(Get (Inheritance (Variable "$x") (Concept "animal")))')
    assert r == S(C("cat"), C("dog"), Node("PredicateNode", "has-fur"))


def test_execute_puts_the_result_in_the_space_and_query_does_not(animals: AtomSpace) -> None:
    # cog-execute! of 2021 adds what a GetLink returns; the next query sees its ListLinks
    body = read_atom('(Inheritance (Variable "$x") (Variable "$c"))')
    before = len(animals)
    assert len(query(animals, body)) == 4
    assert len(animals) == before
    r = run(
        animals,
        """(Get (VariableList (Variable "$c") (Variable "$x"))
                (Inheritance (Variable "$x") (Variable "$c")))""",
    )
    assert animals.contains(r) and animals.contains(L(C("animal"), C("cat")))
    lists = query(animals, read_atom('(List (Concept "animal") (Variable "$y"))'))
    assert len(lists) == 3


def test_typed_variable_restricts_groundings(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (Type "ConceptNode"))
                (Inheritance (Variable "$x") (Concept "animal")))""",
    )
    assert r == S(C("cat"), C("dog"))
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (TypeChoice (Type "PredicateNode") (Type "NumberNode")))
                (Inheritance (Variable "$x") (Concept "animal")))""",
    )
    assert r == S(Node("PredicateNode", "has-fur"))
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (TypeInh "Node"))
                (Inheritance (Variable "$x") (Concept "mineral")))""",
    )
    assert r == S(C("rock"))


def test_several_variables_give_list_links_in_declaration_order(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (VariableList (Variable "$c") (Variable "$x"))
                (Inheritance (Variable "$x") (Variable "$c")))""",
    )
    assert r == S(
        L(C("animal"), C("cat")),
        L(C("animal"), C("dog")),
        L(C("mineral"), C("rock")),
        L(C("animal"), Node("PredicateNode", "has-fur")),
    )


def test_implicit_and_joins_clauses(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Evaluation (Predicate "barks") (Variable "$x"))))""",
    )
    assert r == S(C("dog"))
    # the same without the AndLink wrapper, with PresentLink
    r = run(
        animals,
        """(Get (Present (Inheritance (Variable "$x") (Concept "animal"))
                         (Evaluation (Predicate "has-fur") (Variable "$x"))))""",
    )
    assert r == S(C("cat"), C("dog"))


def test_absent_link_rejects_groundings_whose_term_is_present(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Absent (Evaluation (Predicate "barks") (Variable "$x")))))""",
    )
    assert r == S(C("cat"), Node("PredicateNode", "has-fur"))


def test_absent_link_alone_with_constants(animals: AtomSpace) -> None:
    assert (
        run(animals, '(Satisfaction (Absent (Evaluation (Predicate "barks") (Concept "cat"))))')
        == TRUE_TV
    )
    assert (
        run(animals, '(Satisfaction (Absent (Evaluation (Predicate "barks") (Concept "dog"))))')
        == FALSE_TV
    )


def test_not_over_a_present_term_is_absence(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (Type "ConceptNode"))
             (And (Inheritance (Variable "$x") (Concept "animal"))
                  (Not (Evaluation (Predicate "barks") (Variable "$x")))))""",
    )
    assert r == S(C("cat"))


def test_choice_link_unites_alternatives(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (Type "ConceptNode"))
             (Choice (Inheritance (Variable "$x") (Concept "mineral"))
                     (Evaluation (Predicate "barks") (Variable "$x"))))""",
    )
    assert r == S(C("rock"), C("dog"))


def test_or_link_of_conjunctions_as_in_the_stack_rule(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$x") (Type "ConceptNode"))
             (Or (And (Inheritance (Variable "$x") (Concept "animal"))
                      (Evaluation (Predicate "barks") (Variable "$x")))
                 (And (Inheritance (Variable "$x") (Concept "mineral")))))""",
    )
    assert r == S(C("dog"), C("rock"))


def test_unordered_links_match_in_every_order(animals: AtomSpace) -> None:
    r = run(animals, '(Get (Set (Concept "blue") (Variable "$a") (Variable "$b")))')
    assert r == S(L(C("green"), C("red")), L(C("red"), C("green")))
    # the variables come out in declaration order
    r = run(
        animals,
        """(Get (VariableList (Variable "$b") (Variable "$a"))
                (Set (Concept "blue") (Variable "$a") (Variable "$b")))""",
    )
    assert r == S(L(C("green"), C("red")), L(C("red"), C("green")))
    r = run(animals, '(Get (Member (Concept "cat") (Set (Variable "$k") (Concept "pet"))))')
    assert r == S(C("mammal"))
    r = run(animals, '(Get (Set (Concept "red") (Variable "$a")))')
    assert r == S()  # arity differs


def test_equal_and_not_equal_are_evaluated(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Inheritance (Variable "$y") (Concept "animal"))
                     (Not (Equal (Variable "$x") (Variable "$y")))
                     (Evaluation (Predicate "has-fur") (Variable "$x"))
                     (Evaluation (Predicate "has-fur") (Variable "$y"))))""",
    )
    assert r == S(L(C("cat"), C("dog")), L(C("dog"), C("cat")))
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Equal (Variable "$x") (Concept "dog"))))""",
    )
    assert r == S(C("dog"))


def test_constant_clauses(animals: AtomSpace) -> None:
    # a satisfied pattern without variables grounds once, with no values
    assert run(animals, '(Get (Inheritance (Concept "cat") (Concept "animal")))') == S(L())
    assert run(animals, '(Get (Inheritance (Concept "cat") (Concept "mineral")))') == S()
    # a constant clause beside a variable one gates the whole pattern
    r = run(
        animals,
        """(Get (And (Inheritance (Concept "cat") (Concept "animal"))
                     (Evaluation (Predicate "barks") (Variable "$x"))))""",
    )
    assert r == S(C("dog"))
    r = run(
        animals,
        """(Get (And (Inheritance (Concept "cat") (Concept "mineral"))
                     (Evaluation (Predicate "barks") (Variable "$x"))))""",
    )
    assert r == S()
    r = run(animals, '(Bind (Inheritance (Concept "cat") (Concept "animal")) (Concept "yes"))')
    assert r == S(C("yes")) and C("yes") in animals


def test_bind_and_query_instantiate_rewrites(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Bind (TypedVariable (Variable "$x") (Type "ConceptNode"))
                 (Evaluation (Predicate "has-fur") (Variable "$x"))
                 (Inheritance (Variable "$x") (Concept "furry")))""",
    )
    assert r == S(
        Link("InheritanceLink", C("cat"), C("furry")),
        Link("InheritanceLink", C("dog"), C("furry")),
    )
    assert Link("InheritanceLink", C("dog"), C("furry")) in animals
    r2 = run(
        animals,
        """(Query (Variable "$x")
                  (Inheritance (Variable "$x") (Concept "furry"))
                  (Evaluation (Predicate "soft") (Variable "$x")))""",
    )
    assert r2 == S(ev("soft", C("cat")), ev("soft", C("dog")))


def test_meet_returns_a_queue_value_and_satisfaction_a_tv(animals: AtomSpace) -> None:
    r = run(animals, '(Meet (Evaluation (Predicate "barks") (Variable "$x")))')
    assert isinstance(r, QueueValue) and list(r) == [C("dog")]
    assert (
        run(animals, '(Satisfaction (Evaluation (Predicate "barks") (Variable "$x")))') == TRUE_TV
    )
    assert (
        run(animals, '(Satisfaction (Evaluation (Predicate "flies") (Variable "$x")))') == FALSE_TV
    )


def test_grounded_predicates_are_evaluated(animals: AtomSpace) -> None:
    calls: list[tuple] = []

    def short_name(space: AtomSpace, x: Node) -> TruthValue:
        calls.append((x,))
        return stv(1, 1) if len(x.name) <= 3 else stv(0, 1)

    animals.register("short", short_name)
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Evaluation (GroundedPredicate "py:short") (List (Variable "$x")))))""",
    )
    assert r == S(C("cat"), C("dog"))
    assert len(calls) == 3  # called once per candidate grounding
    animals.register("never", lambda space, x: False)
    r = run(
        animals,
        """(Get (And (Inheritance (Variable "$x") (Concept "animal"))
                     (Evaluation (GroundedPredicate "py:never") (List (Variable "$x")))))""",
    )
    assert r == S()


def test_execution_output_calls_registered_functions(animals: AtomSpace) -> None:
    def make_pet(space: AtomSpace, x: Node) -> Link:
        return Link("InheritanceLink", x, C("pet"))

    animals.register("make-pet", make_pet)
    r = run(
        animals,
        """(Bind (Evaluation (Predicate "has-fur") (Variable "$x"))
                 (ExecutionOutput (GroundedSchema "py:make-pet") (List (Variable "$x"))))""",
    )
    assert r == S(
        Link("InheritanceLink", C("cat"), C("pet")), Link("InheritanceLink", C("dog"), C("pet"))
    )
    assert Link("InheritanceLink", C("cat"), C("pet")) in animals
    out = run(animals, '(ExecutionOutput (GroundedSchema "py: make-pet") (List (Concept "rock")))')
    assert out == Link("InheritanceLink", C("rock"), C("pet")) and out in animals


def test_unregistered_or_foreign_names_are_errors_never_imports(animals: AtomSpace) -> None:
    with pytest.raises(GroundedError, match="no Python function"):
        run(animals, '(ExecutionOutput (GroundedSchema "py:os.system") (List (Concept "x")))')
    with pytest.raises(GroundedError):
        run(animals, '(ExecutionOutput (GroundedSchema "lib:libc.so\\\\system") (List))')
    with pytest.raises(GroundedError):
        run(
            animals,
            '(Get (And (Inheritance (Variable "$x") (Concept "animal")) '
            '(Evaluation (GroundedPredicate "py:__import__") (List (Variable "$x")))))',
        )


def test_low_level_query_api(blocks: AtomSpace) -> None:
    x, y = V("$x"), V("$y")
    got = query(blocks, ev("on", x, y))
    assert sorted((b[x].name, b[y].name) for b in got) == [("a", "b"), ("b", "c")]
    got = query(blocks, Link("AndLink", ev("on", x, y), ev("on", y, V("$z"))))
    assert [(b[x].name, b[y].name, b[V("$z")].name) for b in got] == [("a", "b", "c")]
    assert query(blocks, ev("on", x, C("c")), variables=[x]) == [{x: C("b")}]


def test_undeclared_variables_are_constants(blocks: AtomSpace) -> None:
    r = run(
        blocks,
        """(Get (Variable "$x") (Evaluation (Predicate "on") (List (Variable "$x") (Variable "$y"))))""",
    )
    assert r == S()


def test_bad_patterns_are_errors(blocks: AtomSpace) -> None:
    with pytest.raises(PatternError):
        run(
            blocks,
            '(Get (VariableList (Variable "$x") (Variable "$unused")) (Evaluation (Predicate "clear") (Variable "$x")))',
        )
    with pytest.raises(PatternError):
        run(
            blocks,
            '(Get (TypedVariable (Variable "$x") (Type "NoSuchType")) (Evaluation (Predicate "clear") (Variable "$x")))',
        )


def test_queries_see_frames(blocks: AtomSpace) -> None:
    frame = blocks.child()
    frame.remove(ev("on", C("a"), C("b")))
    frame.add(ev("on", C("a"), C("c")))
    text = '(Get (Evaluation (Predicate "on") (List (Variable "$x") (Concept "c"))))'
    assert run(frame, text) == S(C("a"), C("b"))
    assert run(blocks, text) == S(C("b"))
    text = '(Get (Evaluation (Predicate "on") (List (Concept "a") (Variable "$y"))))'
    assert run(frame, text) == S(C("c"))
    assert run(blocks, text) == S(C("b"))


def test_a_typed_variable_alone_is_a_clause(animals: AtomSpace) -> None:
    r = run(
        animals,
        """(Get (TypedVariable (Variable "$l") (Type "MemberLink")) (Variable "$l"))""",
    )
    assert r == S(Link("MemberLink", C("cat"), S(C("pet"), C("mammal"))))
    r = run(
        animals,
        """(Get (VariableList (TypedVariable (Variable "$e") (Type "EvaluationLink"))
                              (Variable "$x"))
                (And (Variable "$e")
                     (Equal (Variable "$e") (Evaluation (Predicate "barks") (Variable "$x")))))""",
    )
    assert r == S(L(ev("barks", C("dog")), C("dog")))
