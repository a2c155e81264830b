"""Atomese constructs of OpenCog's 2021 AtomSpace: globs, choices inside clauses,
quotes, deep (signature) types, for-all clauses, beta reduction with PutLink."""

from __future__ import annotations

from robocog.atomspace import AtomSpace, execute
from robocog.atomspace.atomese import read_atom


def space_of(*atoms: str) -> AtomSpace:
    space = AtomSpace()
    for text in atoms:
        space.add(read_atom(text))
    return space


def run(space: AtomSpace, text: str) -> str:
    return str(execute(space, read_atom(text)))


def test_a_glob_takes_every_run_that_lets_the_rest_match_and_is_spliced_back() -> None:
    space = space_of(
        '(ListLink (ConceptNode "I") (ConceptNode "love") (ConceptNode "you"))',
        '(ListLink (ConceptNode "I") (ConceptNode "do") (ConceptNode "not") (ConceptNode "you"))',
        '(ListLink (ConceptNode "I") (ConceptNode "you"))',
    )
    out = run(
        space,
        '(BindLink (ListLink (ConceptNode "I") (GlobNode "$g") (ConceptNode "you"))'
        ' (ListLink (GlobNode "$g")))',
    )
    assert '(ListLink (ConceptNode "love"))' in out
    assert '(ListLink (ConceptNode "do") (ConceptNode "not"))' in out
    assert out.count("ListLink") == 2  # not (I you): a glob takes one atom or more


def test_a_choice_inside_a_clause_matches_any_of_its_members_even_nested() -> None:
    space = space_of(
        '(ListLink (ConceptNode "A") (ConceptNode "x"))',
        '(ListLink (ConceptNode "C") (ConceptNode "y"))',
        '(ListLink (ConceptNode "D") (ConceptNode "z"))',
    )
    out = run(
        space,
        '(GetLink (ListLink (ChoiceLink (ConceptNode "A")'
        ' (ChoiceLink (ConceptNode "C") (ConceptNode "E"))) (VariableNode "$v")))',
    )
    assert out == '(SetLink (ConceptNode "x") (ConceptNode "y"))'


def test_a_quoted_variable_is_matched_as_itself_and_unquote_makes_a_variable_again() -> None:
    space = space_of(
        '(ListLink (VariableNode "$v") (ConceptNode "kept"))',
        '(ListLink (ConceptNode "other") (ConceptNode "not kept"))',
    )
    out = run(
        space,
        '(GetLink (TypedVariableLink (VariableNode "$w") (TypeNode "ConceptNode"))'
        ' (ListLink (QuoteLink (VariableNode "$v")) (VariableNode "$w")))',
    )
    assert out == '(SetLink (ConceptNode "kept"))'
    out = run(
        space,
        '(GetLink (QuoteLink (ListLink (UnquoteLink (VariableNode "$a")) (ConceptNode "kept"))))',
    )
    assert out == '(SetLink (VariableNode "$v"))'


def test_a_signature_types_a_variable_by_its_whole_shape() -> None:
    space = space_of(
        '(InheritanceLink (ConceptNode "foo") (ConceptNode "bar"))',
        '(InheritanceLink (ConceptNode "baz") (ConceptNode "bar"))',
        '(InheritanceLink (ConceptNode "foo") (PredicateNode "p"))',
    )
    out = run(
        space,
        '(GetLink (TypedVariableLink (VariableNode "$x") (SignatureLink'
        ' (InheritanceLink (ConceptNode "foo") (TypeNode "ConceptNode")))) (VariableNode "$x"))',
    )
    assert out == '(SetLink (InheritanceLink (ConceptNode "foo") (ConceptNode "bar")))'


def test_an_always_clause_must_hold_for_every_grounding_of_its_group() -> None:
    space = space_of(
        '(InheritanceLink (ConceptNode "b1") (ConceptNode "basket"))',
        '(InheritanceLink (ConceptNode "b2") (ConceptNode "basket"))',
        '(MemberLink (ConceptNode "r1") (ConceptNode "b1"))',
        '(MemberLink (ConceptNode "r2") (ConceptNode "b1"))',
        '(MemberLink (ConceptNode "r3") (ConceptNode "b2"))',
        '(MemberLink (ConceptNode "g1") (ConceptNode "b2"))',
        '(EvaluationLink (PredicateNode "red") (ConceptNode "r1"))',
        '(EvaluationLink (PredicateNode "red") (ConceptNode "r2"))',
        '(EvaluationLink (PredicateNode "red") (ConceptNode "r3"))',
    )
    out = run(
        space,
        '(BindLink (VariableList (VariableNode "$b") (VariableNode "$x"))'
        ' (AndLink (InheritanceLink (VariableNode "$b") (ConceptNode "basket"))'
        ' (MemberLink (VariableNode "$x") (VariableNode "$b"))'
        ' (AlwaysLink (EvaluationLink (PredicateNode "red") (VariableNode "$x"))))'
        ' (VariableNode "$b"))',
    )
    assert out == '(SetLink (ConceptNode "b1"))'


def test_put_reduces_the_body_with_each_argument_and_a_closed_delete_removes() -> None:
    space = space_of('(ConceptNode "gone")', '(ConceptNode "a")', '(ConceptNode "b")')
    out = run(
        space,
        '(PutLink (LambdaLink (VariableNode "$x") (ListLink (VariableNode "$x") (ConceptNode "z")))'
        ' (SetLink (ConceptNode "a") (ConceptNode "b")))',
    )
    assert out == (
        '(SetLink (ListLink (ConceptNode "a") (ConceptNode "z"))'
        ' (ListLink (ConceptNode "b") (ConceptNode "z")))'
    )
    assert run(space, '(PutLink (DeleteLink (VariableNode "X")) (ConceptNode "gone"))') == "None"
    assert read_atom('(ConceptNode "gone")') not in space


def test_opencogs_other_2021_link_types_are_read() -> None:
    space = space_of('(AssociativeLink (ConceptNode "a") (ConceptNode "b"))')
    out = run(space, '(GetLink (AssociativeLink (ConceptNode "a") (VariableNode "$x")))')
    assert out == '(SetLink (ConceptNode "b"))'


def test_a_sequential_and_checks_its_members_in_order_and_stops_at_the_first_false() -> None:
    space = space_of('(EvaluationLink (PredicateNode "visible") (ListLink (ConceptNode "it")))')
    calls: list[str] = []

    def mark(_space: AtomSpace, *args: object) -> bool:
        calls.append("called")
        return True

    space.functions["mark"] = mark
    body = (
        '(SatisfactionLink (TypedVariableLink (VariableNode "$x") (TypeNode "ConceptNode"))'
        " (SequentialAndLink"
        ' (AbsentLink (EvaluationLink (PredicateNode "visible") (ListLink (VariableNode "$x"))))'
        ' (EvaluationLink (GroundedPredicateNode "py:mark") (ListLink))))'
    )
    assert run(space, body) == "(stv 0 1)"
    assert calls == []  # the absence failed first: the predicate never ran


def test_a_grounded_predicate_makes_its_atoms_in_a_scratch_space_but_sets_values_for_good() -> None:
    space = space_of('(ListLink (ConceptNode "foo") (ConceptNode "bar"))')

    def litter(s: AtomSpace, x: object) -> bool:
        s.add(read_atom('(ConceptNode "litter")'))
        s.set_tv(read_atom('(ConceptNode "marked")'), read_atom_tv())
        return True

    def read_atom_tv():  # noqa: ANN202
        from robocog.atomspace import stv

        return stv(0.5, 0.5)

    space.functions["litter"] = litter
    out = run(
        space,
        '(GetLink (AndLink (PresentLink (ListLink (ConceptNode "foo") (VariableNode "x")))'
        ' (EvaluationLink (GroundedPredicateNode "py:litter") (ListLink (VariableNode "x")))))',
    )
    assert out == '(SetLink (ConceptNode "bar"))'
    assert read_atom('(ConceptNode "litter")') not in space
    assert str(space.get_tv(read_atom('(ConceptNode "marked")'))) == "(stv 0.5 0.5)"


def test_a_variable_as_a_clause_is_evaluated_and_defined_predicates_are_expanded() -> None:
    space = space_of(
        '(ContextLink (ConceptNode "c1") (EqualLink (ConceptNode "a") (ConceptNode "a"))'
        ' (ConceptNode "yes"))',
        '(ContextLink (ConceptNode "c2") (EqualLink (ConceptNode "a") (ConceptNode "b"))'
        ' (ConceptNode "no"))',
        '(DefineLink (DefinedPredicateNode "in context")'
        ' (ContextLink (VariableNode "$c") (VariableNode "$t") (VariableNode "$r")))',
    )
    out = run(
        space,
        '(BindLink (VariableList (VariableNode "$c") (VariableNode "$t") (VariableNode "$r"))'
        ' (AndLink (ContextLink (VariableNode "$c") (VariableNode "$t") (VariableNode "$r"))'
        ' (VariableNode "$t")) (VariableNode "$r"))',
    )
    assert out == '(SetLink (ConceptNode "yes"))'
    # the definition's own ContextLink (with variables) is in the space: never a grounding
    out = run(space, '(GetLink (DefinedPredicateNode "in context"))')
    assert out.count("ListLink") == 2 and "VariableNode" not in out
