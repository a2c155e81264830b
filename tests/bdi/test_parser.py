"""The AgentSpeak parser: Jason's syntax, positions in errors, robustness."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robocog.bdi import ParseError, parse_plan, parse_program, parse_term, term_str
from robocog.bdi.plans import chain_steps
from robocog.bdi.terms import Arith, Literal, Var, make_list

FULL = """
// beliefs, rules, goals and plans
at(home)[source(self)].
~raining.
count(0).
route(X, Y) :- link(X, Z) & (Z == Y | route(Z, Y)).
!start.
@p1[atomic] +!start : at(home) & not raining | count(N) & N >= 0
  <- !!other; ?at(Where); +b(1); -b(1); -+count(N + 1); --old; ++new;
     .print("s", Where, [1, 2 | T], 3.5e2, -4, 7 div 2, 7 mod 2, 2 ** 3);
     if (X > 1) { act(1) } elif (X < 0) { act(2) } else { act(3) };
     while (count(C) & C < 3) { -+count(C + 1) }
     for (.member(M, [a, b])) { .print(M) };
     X = f(Y)[a, b]; Y \\== 3; move(north).
-!start[error(E)] <- .print(E).
+?where(X) <- X = here.
-b(X) : X > 0 <- true.
+!g(X)[source(A)] : .my_name(A) <- true.
"""


def test_a_program_with_every_construct_parses() -> None:
    prog = parse_program(FULL)
    assert [term_str(b) for b in prog.beliefs if isinstance(b, Literal)] == [
        "at(home)[source(self)]",
        "~raining",
        "count(0)",
    ]
    assert len(prog.beliefs) == 4 and term_str(prog.goals[0]) == "start"
    assert len(prog.plans) == 5
    p = prog.plans[0]
    assert term_str(p.label) == "p1[atomic]"
    steps = [repr(s) for s in chain_steps(p.body)]
    assert steps[:7] == [
        "!!other",
        "?at(Where)",
        "+b(1)",
        "-b(1)",
        "-+count((N+1))",
        "--old",
        "++new",
    ]
    assert repr(prog.plans[2].trigger) == "+?where(X)"
    assert repr(prog.plans[3].trigger) == "-b(X)"


def test_variables_are_shared_within_a_clause_only() -> None:
    prog = parse_program("+!a(X) <- .print(X).\n+!b(X) <- .print(X).")
    a, b = prog.plans
    xa = a.trigger.literal.args[0]
    assert xa is chain_steps(a.body)[0].term.args[0]
    assert xa is not b.trigger.literal.args[0]


def test_anonymous_variables_are_all_different() -> None:
    t = parse_term("p(_, _)")
    assert isinstance(t.args[0], Var) and t.args[0] is not t.args[1]


def test_precedence_and_associativity() -> None:
    assert term_str(parse_term("10 - 4 - 3")) == "((10-4)-3)"
    assert term_str(parse_term("1 + 2 * 3")) == "(1+(2*3))"
    assert term_str(parse_term("a & b | c & not d")) == "((a & b) | (c & not (d)))"
    assert isinstance(parse_term("-X"), Arith)
    assert parse_term("-7") == -7


def test_strings_keep_escapes() -> None:
    assert parse_term('"a\\"b\\n"') == 'a"b\n'


def test_plan_without_body_or_context() -> None:
    p = parse_plan("+!g")
    assert p.body is None and p.context is None


@pytest.mark.parametrize(
    ("text", "line", "column"),
    [
        ("+!g <- .print(.", 1, 15),
        ("a.\nb(.\n", 2, 3),
        ("+!g <- x\n  y.", 2, 3),
        ("p(1", 1, 4),
        ('p("abc', 1, 3),
    ],
)
def test_errors_name_line_and_column(text: str, line: int, column: int) -> None:
    with pytest.raises(ParseError) as info:
        parse_program(text, "f.asl")
    assert (info.value.line, info.value.column) == (line, column)
    assert str(info.value).startswith(f"f.asl:{line}:{column}:")


TOKENS = [
    "+",
    "-",
    "!",
    "!!",
    "?",
    "<-",
    ":",
    ":-",
    ".",
    ";",
    ",",
    "(",
    ")",
    "[",
    "]",
    "{",
    "}",
    "|",
    "&",
    "not",
    "if",
    "elif",
    "else",
    "while",
    "for",
    "p",
    "q(X)",
    "X",
    "_",
    "1",
    "2.5",
    '"s"',
    ".print",
    "@l",
    "~",
    "-+",
    "--",
    "==",
    "=",
    "<",
    "div",
    "**",
    " ",
    "\n",
]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(TOKENS), max_size=40))
def test_random_token_soup_only_ever_raises_parse_error(tokens: list[str]) -> None:
    try:
        parse_program(" ".join(tokens))
    except ParseError as exc:
        assert exc.line >= 1 and exc.column >= 1


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_random_text_only_ever_raises_parse_error(text: str) -> None:
    try:
        parse_program(text)
    except ParseError as exc:
        assert exc.line >= 1 and exc.column >= 1


@settings(max_examples=200, deadline=None)
@given(st.integers(min_value=0, max_value=len(FULL)))
def test_truncated_programs_only_ever_raise_parse_error(cut: int) -> None:
    try:
        parse_program(FULL[:cut])
    except ParseError as exc:
        assert 1 <= exc.line <= FULL[:cut].count("\n") + 1


def test_deep_nesting_is_a_parse_error_or_a_term() -> None:
    try:
        t = parse_term("(" * 3000 + "1" + ")" * 3000)
        assert t == 1
    except ParseError as exc:
        assert exc.line == 1


@settings(max_examples=200, deadline=None)
@given(
    st.recursive(
        st.one_of(
            st.integers(-1000, 1000),
            st.floats(allow_nan=False, allow_infinity=False, width=64),
            st.sampled_from(["a", "b", "foo", "x1"]).map(Literal),
            st.text(alphabet='abc "\\', max_size=5),
        ),
        lambda kids: st.one_of(
            st.tuples(st.sampled_from(["f", "g"]), st.lists(kids, min_size=1, max_size=3)).map(
                lambda fa: Literal(fa[0], tuple(fa[1]))
            ),
            st.lists(kids, max_size=3).map(make_list),
        ),
        max_leaves=10,
    )
)
def test_printed_terms_parse_back_to_the_same_term(t: object) -> None:
    assert parse_term(term_str(t)) == t


TRIGGERS = ["+!g", "+!g(X)", "-!g", "-!g(X)", "+b(X)", "-b(X)", "+?b(X)", "+!h"]
CONTEXTS = [
    "",
    " : b(X)",
    " : not b(2)",
    " : X > 0",
    " : b(X) & X < 3 | true",
    " : .member(X, [1])",
]
STEPS = [
    "!g",
    "!g(1)",
    "!!h",
    "!h",
    "?b(X)",
    "+b(1)",
    "-b(1)",
    "-+b(2)",
    ".print(X)",
    ".fail",
    "X = 1",
    "X > 0",
    "act(X)",
    "if (b(X)) { .print(X) } else { !h }",
    "while (b(X) & X < 3) { -+b(X + 1) }",
    "for (b(X)) { !g(X) }",
    ".succeed_goal(g)",
    ".drop_intention(g)",
    ".wait(1)",
    "X = [H|T]",
    "Y = 1 / 0",
    "Y = X div 0",
    ".nth(X, a, Y)",
]


@st.composite
def _programs(draw: st.DrawFn) -> str:
    plans = []
    for _ in range(draw(st.integers(1, 5))):
        body = draw(st.lists(st.sampled_from(STEPS), min_size=1, max_size=5))
        plans.append(
            draw(st.sampled_from(TRIGGERS))
            + draw(st.sampled_from(CONTEXTS))
            + " <- "
            + "; ".join(body)
            + "."
        )
    return "b(1).\n!g.\n!g(2).\n!h.\n" + "\n".join(plans)


@settings(max_examples=200, deadline=None)
@given(_programs())
def test_random_programs_run_without_crashing_the_engine(text: str) -> None:
    from robocog.bdi import Agent

    ag = Agent(parse_program(text), "fuzz", printer=lambda n, t: None, warn=lambda n, t: None)
    ag.run(300)
    assert ag.cycle <= 300
