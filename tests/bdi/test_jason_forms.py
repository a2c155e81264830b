"""Forms of Jason's own examples, each checked against Jason 3.3.

The expected output of every program here was recorded from Jason 3.3 (built by
``build-jason.sh``) with ``jason-agent FILE.asl`` (or ``FILE.mas2j``), and the same
program is run through ``robocog agent``.
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from robocog.bdi.agent import Agent
from robocog.bdi.parser import ParseError, parse_program
from robocog.bdi.project import run_files


def _run(tmp_path: Path, name: str, text: str, real_time: bool = True) -> list[str]:
    path = tmp_path / f"{name}.asl"
    path.write_text(text, encoding="utf-8")
    out = io.StringIO()
    run_files([path], lambda ag, line: out.write(f"[{ag}] {line}\n"), real_time=real_time)
    return out.getvalue().splitlines()


def test_missing_semicolon_is_a_syntax_error_where_jason_reports_it() -> None:
    # Jason 3.3: as2j: error parsing "file:t.asl": Encountered " <ATOM> ".print "" at
    # line 3, column 3.
    with pytest.raises(ParseError) as err:
        parse_program("!g.\n+!g <- .print(a)\n  .print(b).\n", "t.asl")
    assert (err.value.line, err.value.column) == (3, 3)
    assert str(err.value).startswith("t.asl:3:3:")


def test_a_dot_before_a_name_is_never_the_end_of_a_clause() -> None:
    with pytest.raises(ParseError):
        parse_program("b(1).c.\n")
    prog = parse_program("b(1). c.\n")
    assert len(prog.beliefs) == 2


def test_bracketed_fork_join(tmp_path: Path) -> None:
    # Jason 3.3 prints c, a, done: the first branch of ||| to finish ends the other
    src = (
        "!start.\n"
        "+!start <- !g(c) |&| (!g(a) ||| !h(b)); .print(done).\n"
        "+!g(X) <- .print(X).\n"
        "+!h(X) <- .wait(200); .print(X).\n"
    )
    assert _run(tmp_path, "fork", src) == ["[fork] c", "[fork] a", "[fork] done"]


def test_hard_deadline_fails_the_goal(tmp_path: Path) -> None:
    src = (
        "!start.\n"
        "+!start <- !g(3)[hard_deadline(100)]; .print(after); "
        "!g(1)[hard_deadline(500)]; .print(end).\n"
        "+!g(V) <- .wait(V*50); .print(g,V).\n"
        '-!g(V)[error(E)] <- .print("failed ",E," ",V).\n'
    )
    assert _run(tmp_path, "deadline", src) == [
        "[deadline] failed deadline_reached 3",
        "[deadline] after",
        "[deadline] g1",
        "[deadline] end",
    ]


def test_a_wait_that_was_abandoned_does_not_end_a_later_wait(tmp_path: Path) -> None:
    # the .wait(600) of g(3) is cut by the deadline; the later .wait(300) of the same
    # intention must last its own time, on both clocks
    src = (
        "!start.\n"
        "+!start <- !g(3)[hard_deadline(100)]; !g(2); .print(end).\n"
        "+!g(V) <- .wait(V*200); .print(g,V).\n"
        "-!g(V) <- .print(failed,V).\n"
    )
    for real in (True, False):
        ag = Agent(src, "a")
        lines: list[tuple[str, float]] = []
        ag.printer = lambda _n, line, ag=ag, lines=lines: lines.append((line, ag.clock))
        ag.run(real_time=real)
        assert [x for x, _ in lines] == ["failed3", "g2", "end"]
        assert lines[1][1] - lines[0][1] >= 399


def _two_agents(tmp_path: Path) -> Path:
    (tmp_path / "busy.asl").write_text(
        "!busy.\n+!busy <- for (.range(I,1,20000)) { X = I * 2 }; .print(busy_done).\n",
        encoding="utf-8",
    )
    (tmp_path / "ticker.asl").write_text(
        "!tick.\n+!tick <- .wait(5); .print(tick); .send(busy, tell, ticked).\n",
        encoding="utf-8",
    )
    mas = tmp_path / "two.mas2j"
    mas.write_text("MAS two {\n agents: busy; ticker;\n}\n", encoding="utf-8")
    return mas


def test_a_busy_agent_does_not_stop_another_agents_clock(tmp_path: Path) -> None:
    # Jason 3.3 prints [ticker] tick before [busy] busy_done: its clock is the wall clock
    out: list[str] = []
    run_files([_two_agents(tmp_path)], lambda ag, line: out.append(f"[{ag}] {line}"))
    assert out == ["[ticker] tick", "[busy] busy_done"]


def test_the_virtual_clock_stands_still_while_agents_work(tmp_path: Path) -> None:
    out: list[str] = []
    run_files(
        [_two_agents(tmp_path)], lambda ag, line: out.append(f"[{ag}] {line}"), real_time=False
    )
    assert out == ["[busy] busy_done", "[ticker] tick"]


def test_plan_term_with_a_label_variable_and_abstract_namespace() -> None:
    prog = parse_program(
        "+!g <- P = {@L +!T : C <- B}; .print(P).\n"
        "r :- .count(::p(_)[source(_)], N) & N > 0.\n"
        "+!ns::go <- true.\n"
    )
    assert len(prog.plans) == 2 and len(prog.beliefs) == 1


def test_directory_facilitator_clone_and_agents_made_at_run_time(tmp_path: Path) -> None:
    # Jason 3.3 (jason-agent df.mas2j): [p] c offers initiator from df, [bob] 10 : 41,
    # [carl] hi, [c] [p], [c] []
    files = {
        "c.asl": "!start.\n+!start <- .df_register(initiator); .wait(300); "
        '.df_search("participant", L); .print(L); .df_search(nothing, N); .print(N).\n',
        "p.asl": '!start.\n+!start <- .df_register("participant"); .df_subscribe("initiator").\n'
        '+provider(A, S)[source(Src)] <- .print(A, " offers ", S, " from ", Src).\n',
        "m.asl": 'test(1).\n!start.\n+!start <- +a(40); .clone("bob"); .send(bob, tell, p(10)); '
        '.create_agent(carl, "carl.asl"); .wait(300); .kill_agent(carl).\n'
        '+p(X) : a(V) & test(T) <- .print(X, " : ", V + T).\n',
        "carl.asl": "!hi.\n+!hi <- .print(hi).\n",
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    mas = tmp_path / "df.mas2j"
    mas.write_text("MAS df {\n agents: c; p; m;\n}\n", encoding="utf-8")
    out: list[str] = []
    system = run_files([mas], lambda ag, line: out.append(f"[{ag}] {line}"))
    assert sorted(out) == sorted(
        ["[p] c offers initiator from df", "[bob] 10 : 41", "[carl] hi", "[c] [p]", "[c] []"]
    )
    assert [x for x in out if x.startswith("[c]")] == ["[c] [p]", "[c] []"]
    assert "carl" not in system.agents and "bob" in system.agents


def test_signal_idle_events_and_stop_with_a_deadline(tmp_path: Path) -> None:
    # Jason 3.3 (jason-agent idle.mas2j) prints for w: sleeping, awake, got1s, sleeping,
    # awake, got2s (what follows .stopMAS(T) races with the shutdown there)
    (tmp_path / "w.asl").write_text(
        "+jag_sleeping <- .print(sleeping).\n+jag_awaking <- .print(awake).\n"
        "+ping(N)[source(A)] <- .print(got, N, A).\n",
        encoding="utf-8",
    )
    (tmp_path / "s.asl").write_text(
        "!go.\n+!go <- .wait(100); .send(w, signal, ping(1)); .wait(100); "
        ".send(w, signal, ping(2)); .wait(100); .stopMAS(60000).\n"
        "+jag_shutting_down(T) <- .print(bye, T).\n",
        encoding="utf-8",
    )
    mas = tmp_path / "idle.mas2j"
    mas.write_text("MAS idle {\n agents: w; s;\n}\n", encoding="utf-8")
    out: list[str] = []
    system = run_files([mas], lambda ag, line: out.append(f"[{ag}] {line}"))
    w = [x[4:] for x in out if x.startswith("[w]")]
    assert w[:6] == ["sleeping", "awake", "got1s", "sleeping", "awake", "got2s"]
    assert "[s] bye60000" in out
    assert system.clock < 30000  # handled: the system did not wait out the deadline
    assert not system.agents["w"].believes("ping(1)")  # a signal adds no belief


def test_rule_terms_told_added_and_listed(tmp_path: Path) -> None:
    # Jason 3.3 (jason-agent rules.mas2j): [r] [{ ok :- (p & q) }], [s] [{ big(V) :-
    # (V > 10) }], [r] yes
    (tmp_path / "s.asl").write_text(
        "big(V) :- V > 10.\n!go.\n"
        "+!go <- .send(r, tellRule, [{ok :- p & q}]); .wait(100); .send(r, achieve, check);\n"
        "        .relevant_rules(big(_), L); .print(L).\n",
        encoding="utf-8",
    )
    (tmp_path / "r.asl").write_text(
        "p. q.\n+!kqml_received(A, tellRule, Rules, _) <- "
        "for (.member(R, Rules)) { +R[source(A)] }; .relevant_rules(_, LR); .print(LR).\n"
        "+!check : ok <- .print(yes).\n+!check <- .print(no).\n",
        encoding="utf-8",
    )
    mas = tmp_path / "rules.mas2j"
    mas.write_text("MAS rules {\n agents: s; r;\n}\n", encoding="utf-8")
    out: list[str] = []
    run_files([mas], lambda ag, line: out.append(f"[{ag}] {line}"))
    assert [x for x in out if x.startswith("[r]")] == ["[r] [{ ok :- (p & q) }]", "[r] yes"]
    assert [x for x in out if x.startswith("[s]")] == ["[s] [{ big(V) :- (V > 10) }]"]


def test_univ_on_a_plan_term_and_running_its_body(tmp_path: Path) -> None:
    # Jason 3.3: job[source(self),url("file:m.asl")], n(3), step ?n(_22), step .print(3),
    # 3, step !done(3), finished3, empty
    src = (
        "n(3).\n!start.\n"
        "@job +!work : n(3) <- ?n(X); .print(X); !done(X).\n"
        "+!done(X) <- .print(finished, X).\n"
        "+!start <- .relevant_plans({+!work}, [P|_]); P =.. [L, T, C, B]; .print(L); "
        ".print(C);\n   if (C) { !run(B) }.\n"
        "+!run({}) <- .print(empty).\n"
        '+!run({H; R}) <- .print(step, " ", H); H; !run(R).\n'
    )
    out = [re.sub(r"_\d+", "_N", x) for x in _run(tmp_path, "m", src)]
    assert out[0].startswith("[m] job[source(self),url(") and out[0].endswith('m.asl")]')
    assert out[1:] == [
        "[m] n(3)",
        "[m] step ?n(_N)",
        "[m] step .print(3)",
        "[m] 3",
        "[m] step !done(3)",
        "[m] finished3",
        "[m] empty",
    ]


def test_options_selected_by_a_select_option_rule(tmp_path: Path) -> None:
    # Jason 3.3 prints second2: the rule takes apart each option's plan term and picks
    # the one whose label is annotated pick (without the rule: first1)
    rule = (
        "select__option(E, I, P, U) :- "
        "P = {@L +!T : C <- B} & L =.. [F, Ts, As] & .member(pick, As).\n"
    )
    plans = (
        "v(1). v(2).\n!g.\n+!g : v(X) <- .print(first, X).\n"
        "@mine[pick] +!g : v(X) & X > 1 <- .print(second, X).\n"
    )
    assert _run(tmp_path, "sel", rule + plans) == ["[sel] second2"]
    assert _run(tmp_path, "plain", plans) == ["[plain] first1"]


def test_univ_on_a_rule_term_takes_its_head(tmp_path: Path) -> None:
    # Jason 3.3 prints [default,a,[X],[]]
    src = "!g.\n+!g <- R = {a(X) :- b(X) & c}; R =.. L; .print(L).\n"
    assert _run(tmp_path, "ru", src) == ["[ru] [default,a,[X],[]]"]
