"""The standard internal actions, each checked on what the agent prints."""

from __future__ import annotations

import pytest

from robocog.bdi import Agent


def out(body: str, beliefs: str = "") -> list[str]:
    printed: list[str] = []
    Agent(
        f"{beliefs}\n!s.\n+!s <- {body}.\n-!s[error(E)] <- .print(failed, E).",
        "t",
        printer=lambda n, t: printed.append(t),
    ).run(10_000)
    return printed


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ('.concat("ab", 1, f(x), S); .print(S)', "ab1f(x)"),
        (".concat([1], [], [2, 3], L); .print(L)", "[1,2,3]"),
        ('.length("hello", N); .print(N)', "5"),
        (".length([], N); .print(N)", "0"),
        ('.term2string(T, "p(1, [a])"); .print(T)', "p(1,[a])"),
        ('.term2string(g("x"), S); .print(S)', 'g("x")'),
        ('.sort([b, 3, "s", f(1), a, [x], 1.5], L); .print(L)', '[1.5,3,"s",[x],a,b,f(1)]'),
        (".max([2, 9, 4], M); .min([2, 9, 4], N); .print(M, N)", "92"),
        (".nth(1, [a, b, c], X); .print(X)", "b"),
        (".delete(b, [a, b, c, b], L); .print(L)", "[a,c]"),
        (".reverse([1, [2, 3]], L); .print(L)", "[[2,3],1]"),
        (".findall(X-Y, .member(X, [1, 2]) & .member(Y, [a]), L); .print(L)", "[(1-a),(2-a)]"),
        (".setof(X, .member(X, [c, a, c, b]), L); .print(L)", "[a,b,c]"),
        (".union([c, a], [b, a], U); .intersection([a, b], [b, c], I); .print(U, I)", "[a,b,c][b]"),
        (".difference([a, b, c], [b], D); .print(D)", "[a,c]"),
        (".findall(I, .range(I, 5, 1, -2), L); .print(L)", "[5,3,1]"),
        ('.substring("lo", "hello"); .upper_case("ab", U); .print(U)', "AB"),
        (".my_name(N); .print(N)", "t"),
        ("X = math.max(3, 8) + math.abs(-2); .print(X)", "10"),
        ("L = [1, 2, 3]; X = math.sum(L) / math.average(L); .print(X)", "3"),
        (".nth(5, [a], X)", "failedinternal_action"),  # Jason: out of bounds raises
        (".max([], X)", "failedia_failed"),
        (".length(a, N)", "failedia_failed"),
        (".nosuch(1)", "failedaction_failed"),  # to the environment, as in Jason
        (".fail(error(custom))", "failedcustom"),
        ('X = 5; .puts("x=#{X}, f=#{f(X)}")', "x=5, f=f(5)"),
        ('.printf("%d-%s-%.2f", 3, abc, 2.5)', "3-abc-2.50"),
        (".findall(P, .prefix(P, [a, b]), L); .print(L)", "[[a,b],[a],[]]"),
        (".findall(P, .suffix(P, [a, b]), L); .print(L)", "[[a,b],[b],[]]"),
        ('.replace("a-b-c", "-", "+", R); .print(R)', "a+b+c"),
        (".copy_term(f(X, Y, X), T); T = f(1, 2, Z); .print(Z)", "1"),
        (".eval(E, 1 > 2 | true); .print(E)", "true"),
        ('X = .length([a, b]) + .length("abc"); .print(X)', "5"),
        ("X = math.median([3, 1, 2]) + math.max([4, 9]); .print(X)", "11"),
        # the forms and errors Jason 3.3 gives for the same calls
        ('.substring(S, "abcdef", 1, 3); .substring(T, "abc", 1); .print(S, T)', "bcbc"),
        ('.findall(p(B, E), .substring("bc", "abcbc", B, E), L); .print(L)', "[p(1,2),p(3,4)]"),
        (".delete(0, 2, [a, b, c, d], L); .delete(1, [a, b, c], M); .print(L, M)", "[c,d][a,c]"),
        (".concat(a, 1, f(x), S); .print(S)", "a1f(x)"),
        ('.nth(0, "abc", C); .print(C)', "a"),
        (".fail(foo)", "failedinternal_action"),
        (".length(1, 2, 3)", "failedwrong_arguments"),
    ],
)
def test_internal_actions(body: str, expected: str) -> None:
    assert out(body) == [expected]


def test_count_as_a_function_and_assert_order() -> None:
    printed = out(
        ".asserta(q(1)); .assertz(q(2)); .asserta(q(0)); .findall(Q, q(Q), L);"
        " N = .count(q(_)); .print(L, N)"
    )
    assert printed == ["[0,1,2]3"]


def test_count_abolish_and_type_tests() -> None:
    printed = out(
        ".count(p(_), N); .abolish(p(1)); .count(p(_), M); .print(N, M);"
        ' if (.atom(a) & .number(1.5) & .string("x") & .list([]) & .ground(f(a))) { .print(types) }',
        "p(1). p(2).",
    )
    assert printed == ["21", "types"]


def test_intend_and_desire_see_the_goals() -> None:
    assert out(".intend(s); .print(yes)") == ["yes"]
    assert out("if (.intend(other)) { .print(yes) } else { .print(no) }") == ["no"]


def test_add_and_remove_plans_at_run_time() -> None:
    printed = out(
        '.add_plan("@extra +!extra <- .print(added)."); !extra; .remove_plan(extra); !extra'
    )
    assert printed == ["added", "failedno_relevant"]
