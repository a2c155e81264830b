"""Atomese reader and writer: the thesis's texts, round trips, errors with places."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.atomspace import AtomeseError, AtomSpace, Link, Node, parse, read_atom, stv, write
from robocog.atomspace.atomese import dump, write_pretty

from .conftest import DATA, C, P, ev


def test_thesis_knowledge_base_loads_as_written() -> None:
    s = AtomSpace()
    top = s.load_atomese((DATA / "kb_7_1a.scm").read_text())
    assert len(top) == 4 + 6 + 4
    assert Link("InheritanceLink", C("table"), C("fixed-object")) in s
    # the EqualLink is unordered: either spelling is the same atom
    assert Link("NotLink", Link("EqualLink", C("table"), C("toolbox"))) in s
    assert ev("clear", C("bolt")) in s
    assert len(s.get_by_type("ConceptNode")) == 6


def test_truth_values_short_names_and_comments() -> None:
    text = """
    ; the thesis's first example
    ConceptNode "man" (stv 0.5 0.001)
    """
    # a bare (unparenthesised) node is not Atomese
    with pytest.raises(AtomeseError):
        parse(text)
    s = AtomSpace()
    s.load_atomese('(ConceptNode "man" (stv 0.5 0.001)) ; comment\n(Concept "cat" (stv 0.5 0.001))')
    assert s.get_tv(C("man")) == stv(0.5, 0.001) and s.get_tv(C("cat")) == stv(0.5, 0.001)
    s.load_atomese(
        '(EvaluationLink (stv 1 1) (Predicate "LessThan") (List (Number 3) (NumberNode "42")))'
    )
    link = ev("LessThan", Node("NumberNode", "3"), Node("NumberNode", "42"))
    assert s.get_tv(link) == stv(1, 1)
    assert read_atom("(TypeNode 'ConceptNode)") == Node("TypeNode", "ConceptNode")


def test_define_and_environment_symbols() -> None:
    p = parse('(define x (Concept "a"))\n(Inheritance x (Concept "b"))')
    assert p.atoms == [Link("InheritanceLink", C("a"), C("b"))]
    p = parse('(EqualLink (Variable "?ob") args)', env={"args": C("bolt")})
    assert p.atoms[0] == Link("EqualLink", Node("VariableNode", "?ob"), C("bolt"))
    with pytest.raises(AtomeseError) as e:
        parse('(EqualLink (Variable "?ob")\n   args)')
    assert (e.value.line, e.value.column) == (2, 4)


def test_scheme_procedures_are_refused_with_a_place() -> None:
    with pytest.raises(AtomeseError) as e:
        parse("(define (pickup-action . args)\n  (car args))")
    assert e.value.line >= 1
    with pytest.raises(AtomeseError):
        parse("(let ((x 1)) x)")


def test_cog_execute_forms() -> None:
    p = parse('(Concept "a")\n(cog-execute! (Get (Inheritance (Variable "$x") (Concept "b"))))')
    assert [f.execute for f in p.forms] == [False, True]
    assert p.forms[1].line == 2


@pytest.mark.parametrize(
    ("text", "line", "column"),
    [
        ('(Concept "a"', 1, 1),
        ('(Concept "a"))', 1, 14),
        ('\n  (Concept "a" "b")', 2, 3),
        ('(Concept "unterminated)', 1, 10),
        ('(NoSuchLink (Concept "a"))', 1, 2),
        ("()", 1, 1),
        ('(List\n (Concept "a")\n (stv 2 1))', 3, 2),
        ("hello", 1, 1),
        ('(List (Concept "a") 42)', 1, 21),
        ("(Concept #)", 1, 10),
    ],
)
def test_malformed_text_gives_line_and_column(text: str, line: int, column: int) -> None:
    with pytest.raises(AtomeseError) as e:
        parse(text)
    assert (e.value.line, e.value.column) == (line, column), str(e.value)
    assert f":{line}:{column}:" in str(e.value)


def test_failed_load_leaves_the_space_unchanged() -> None:
    s = AtomSpace()
    s.load_atomese('(Concept "kept")')
    with pytest.raises(AtomeseError):
        s.load_atomese('(Concept "a")\n(Concept "b"')
    assert set(s) == {C("kept")}


names = st.text(alphabet=st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=8)
node_types = st.sampled_from(["ConceptNode", "PredicateNode", "VariableNode", "NumberNode"])
link_types = st.sampled_from(
    ["ListLink", "SetLink", "EvaluationLink", "AndLink", "InheritanceLink"]
)
atoms = st.recursive(
    st.builds(Node, node_types, names),
    lambda kids: st.builds(lambda t, out: Link(t, *out), link_types, st.lists(kids, max_size=4)),
    max_leaves=12,
)


@given(atoms)
def test_write_then_read_round_trips(atom: Node | Link) -> None:
    assert read_atom(write(atom)) == atom
    assert read_atom(write_pretty(atom)) == atom


@given(
    st.lists(atoms, max_size=5), st.lists(st.tuples(st.floats(0, 1), st.floats(0, 1)), max_size=5)
)
def test_dump_then_load_round_trips(roots: list, tvs: list) -> None:
    s = AtomSpace()
    for r in roots:
        s.add(r)
    for atom, (a, b) in zip(roots, tvs, strict=False):
        s.set_tv(atom, stv(a, b))
    t = AtomSpace()
    t.load_atomese(dump(s))
    assert t.signature() == s.signature()
    for a in s:
        assert t.get_tv(a) == s.get_tv(a)


@settings(max_examples=300)
@given(st.text(alphabet="()\" \n;abcAZ\\Concept.1stv'", max_size=60))
def test_random_text_never_crashes(text: str) -> None:
    try:
        parse(text)
    except AtomeseError as e:
        assert e.line >= 1 and e.column >= 1
        assert e.line <= text.count("\n") + 1


@settings(max_examples=200)
@given(st.integers(min_value=0, max_value=10_000))
def test_truncated_thesis_text_errors_with_a_place(cut: int) -> None:
    text = (DATA / "pickup_rule.scm").read_text()
    cut = cut % len(text)
    piece = text[:cut]
    try:
        parse(piece, env={"args": C("x")})
    except AtomeseError as e:
        lines = piece.split("\n")
        assert 1 <= e.line <= len(lines)
        assert 1 <= e.column <= len(lines[e.line - 1]) + 1


def test_deep_nesting_is_an_error_or_an_atom_never_a_crash() -> None:
    from robocog.atomspace import AtomSpace, load
    from robocog.atomspace.atomese import MAX_NESTING
    from robocog.atomspace.atoms import deep as deep_limit

    n = MAX_NESTING - 1
    deep = "(List " * n + '(Concept "x")' + ")" * n
    atom = read_atom(deep)
    assert atom.type == "ListLink"
    space = AtomSpace()
    with deep_limit():  # comparing two deep atoms recurses in C
        assert load(deep, space)[0] == atom and atom in space  # added (by recursion) too
    with pytest.raises(AtomeseError, match="nesting deeper than"):
        parse("(List " * 30000 + '(Concept "x")' + ")" * 30000)
    with pytest.raises(AtomeseError):
        parse("(List " * 5000)


def test_arity_text_and_messages_are_bounded() -> None:
    from robocog.atomspace.atomese import MAX_ARITY, MAX_MESSAGE

    wide = "(List " + " ".join(f'(Concept "{i}")' for i in range(MAX_ARITY + 1)) + ")"
    with pytest.raises(AtomeseError, match="more than"):
        parse(wide)
    with pytest.raises(AtomeseError) as info:
        parse("(" + "x" * 10**6 + " 1)")
    assert len(info.value.message) <= MAX_MESSAGE


def test_a_second_definition_is_refused_and_nothing_is_added() -> None:
    from robocog.atomspace import AtomSpace, load

    space = AtomSpace()
    text = '(Concept "a")\n(Define (DefinedSchema "f") (Concept "x"))\n(Define (DefinedSchema "f") (Concept "y"))'
    with pytest.raises(AtomeseError) as info:
        load(text, space)
    assert info.value.line == 3 and "already defined" in info.value.message
    assert len(space) == 0
    load('(Define (DefinedSchema "f") (Concept "x"))', space)
    with pytest.raises(AtomeseError, match="already defined"):
        load('(Define (DefinedSchema "f") (Concept "z"))', space)


def test_names_with_quotes_and_backslashes() -> None:
    n = C('say "hi" \\ bye')
    assert read_atom(write(n)) == n
    assert P("x") != read_atom(write(n))


R2L = """
(EvaluationLink (stv 1 1)
  (PredicateNode
    "is.v@5fdee4a0-7ad4-4aa7-9172-55a137c3dbdf"
    (stv 9.75697e-13 0.00124844))
  (ListLink
    (ConceptNode
      "cat.n@e425545c-ceea-4eee-931b-a6c312d66d58")
    (ConceptNode
      "animal.n@1813a95c-0c44-46f6-bad3-7232f6ff8616")))
(InheritanceLink (stv 1 1)
  (InterpretationNode
    "sentence@c9bf0479-2636-4a8b-901c-38d1305ed29e_parse_0_interpretation_$X"
    (stv 9.75697e-13 0.00124844))
  (DefinedLinguisticConceptNode
    "DeclarativeSpeechAct" (stv 9.75697e-13 0.00124844)))
(ImplicationLink (stv 1 1)
  (PredicateNode "is.v@5fdee4a0-7ad4-4aa7-9172-55a137c3dbdf" (stv 9.75697e-13 0.00124844))
  (PredicateNode "be" (stv 9.75697e-13 0.00124844)))
"""


def test_relex2logic_output_of_section_2_2_3_3_loads() -> None:
    s = AtomSpace()
    top = s.load_atomese(R2L)
    assert [a.type for a in top] == ["EvaluationLink", "InheritanceLink", "ImplicationLink"]
    assert all(s.get_tv(a) == stv(1, 1) for a in top)
    is_v = P("is.v@5fdee4a0-7ad4-4aa7-9172-55a137c3dbdf")
    assert s.get_tv(is_v) == stv(9.75697e-13, 0.00124844)
    assert len(s.incoming(is_v)) == 2  # one atom, shared by both links
    assert (
        s.get_tv(Node("DefinedLinguisticConceptNode", "DeclarativeSpeechAct")).confidence
        == 0.00124844
    )
