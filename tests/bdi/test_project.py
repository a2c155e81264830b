"""Jason projects (.mas2j), includes and the language features Jason 3.3 programs use."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from robocog.bdi.agent import Agent
from robocog.bdi.parser import ParseError, parse_program, read_source
from robocog.bdi.project import build, read_project, run_files


def _printed(tmp_path: Path, files: dict[str, str], run: str) -> list[str]:
    for name, text in files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    lines: list[str] = []
    run_files([tmp_path / run], lambda n, t: lines.append(f"[{n}] {t}"))
    return lines


def test_a_project_runs_its_agents_with_instances_options_and_source_path(
    tmp_path: Path,
) -> None:
    project = """MAS demo {
        infrastructure: Local
        agents: worker [beliefs="size(2), colour(red)", goals="work"] #2;
                boss boss.asl;
        aslSourcePath: "asl";
    }"""
    files = {
        "demo.mas2j": project,
        "asl/worker.asl": "+!work : size(S) & colour(C) <- .my_name(N); .print(N, S, C).",
        "boss.asl": "!hello. +!hello <- .print(ready).",
    }
    lines = _printed(tmp_path, files, "demo.mas2j")
    assert sorted(lines) == ["[boss] ready", "[worker1] worker12red", "[worker2] worker22red"]


def test_a_malformed_project_names_file_line_and_column(tmp_path: Path) -> None:
    path = tmp_path / "bad.mas2j"
    path.write_text("MAS bad {\n  agents: a;\n  agents b c;\n}\n")
    with pytest.raises(ParseError) as err:
        read_project(path)
    assert (err.value.line, err.value.source) == (3, str(path))
    path.write_text("MAS p {\n infrastructure: JaCaMo\n agents: a; }")
    with pytest.raises(ParseError, match="infrastructure JaCaMo is not available") as err:
        build(read_project(path))
    assert (err.value.line, err.value.column) == (2, 18)
    path.write_text("MAS p { agents: ghost; }")
    with pytest.raises(ParseError, match="agent ghost: no file ghost.asl"):
        build(read_project(path))


def test_includes_are_read_where_they_stand_and_a_missing_one_is_an_error(
    tmp_path: Path,
) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "colours.asl").write_text('colour(red).\n{ include("more.asl") }\n')
    (tmp_path / "lib" / "more.asl").write_text("colour(blue).\n")
    main = tmp_path / "main.asl"
    main.write_text(
        '{ include("lib/colours.asl") }\n!s.\n+!s <- .findall(C, colour(C), L); .print(L).\n'
    )
    out: list[str] = []
    Agent(read_source(main), "main", file=str(main), printer=lambda n, t: out.append(t)).run()
    assert out == ["[red,blue]"]
    with pytest.raises(ParseError, match="include: no file 'gone.asl'") as err:
        parse_program('p.\n  { include("gone.asl") }\n', str(tmp_path / "x.asl"))
    assert (err.value.line, err.value.column) == (2, 3)
    with pytest.raises(
        ParseError, match=r"not supported: directive \{ no_such_directive\(\"f\", 1\) \}"
    ):
        parse_program('{ no_such_directive("f", 1) }\n')
    # included into a namespace: its beliefs and plans are that namespace's
    (tmp_path / "lib2.asl").write_text("k(1).\n+!hi <- ?k(X); .print(X).\n")
    prog = parse_program('{ include("lib2.asl", lib) }\n', str(tmp_path / "m.asl"))
    assert [str(b) for b in prog.beliefs] == ["lib::k(1)"]
    assert str(prog.plans[0].trigger) == "+!lib::hi"
    (tmp_path / "loop.asl").write_text('{ include("loop.asl") }\n')
    with pytest.raises(ParseError, match="nested deeper"):
        parse_program((tmp_path / "loop.asl").read_text(), str(tmp_path / "loop.asl"))


def test_a_told_list_arrives_one_belief_per_cycle_and_sources_merge(tmp_path: Path) -> None:
    files = {
        "p.mas2j": "MAS p { agents: a; b; c; }",
        "a.asl": "!s. +!s <- .send(c, tell, [item(1), item(2)]); .send(c, tell, f).",
        "b.asl": "!s. +!s <- .wait(10); .send(c, tell, f); .wait(10); .send(c, untell, f).",
        "c.asl": "+item(_) : .count(item(_), N) <- .print(seen(N)).\n"
        "+f[source(S)] <- .findall(X, f[source(X)], L); .print(L).\n"
        "-f[source(S)] <- .findall(X, f[source(X)], L); .print(L).",
    }
    lines = _printed(tmp_path, files, "p.mas2j")
    assert lines == ["[c] seen(1)", "[c] seen(2)", "[c] [a]", "[c] [a,b]", "[c] [a]"]


def test_suspend_resume_and_drop_all_intentions_keep_jasons_order() -> None:
    program = """
    !start.
    +!start <- !!task; .wait(10); if (.suspended(task, R)) { .print(R) };
       .resume(task); .wait(10); !!other; .drop_all_intentions; .print(still_here).
    +!task <- .print(t1); .suspend; .print(t2).
    +!other <- .print(never).
    """
    out: list[str] = []
    Agent(program, "a", printer=lambda n, t: out.append(t)).run()
    assert out == ["t1", "suspend_ia", "t2", "still_here"]


def test_random_forms_and_remainders_on_doubles() -> None:
    program = """
    !s.
    +!s <- .set_random_seed(3); .findall(X, .random(X, 5), L); .length(L, N); .print(N);
       .random([a], P); .print(P); .print(7.9 mod 2, " ", -7 mod 2, " ", 7.9 div 2).
    """
    out: list[str] = []
    Agent(program, "a", printer=lambda n, t: out.append(t)).run()
    assert out == ["5", "a", "1.9000000000000004 -1 3"]


def test_the_command_runs_several_files_bounds_time_and_refuses_bad_bytes(
    tmp_path: Path,
) -> None:
    (tmp_path / "a.asl").write_text("!s. +!s <- .send(b, achieve, hi).")
    (tmp_path / "b.asl").write_text("+!hi[source(A)] <- .print(hi_from(A)).")
    cmd = [sys.executable, "-m", "robocog.cli", "agent"]
    done = subprocess.run([*cmd, str(tmp_path / "a.asl"), str(tmp_path / "b.asl")],
                          capture_output=True, text=True, timeout=60)  # fmt: skip
    assert done.stdout == "[b] hi_from(a)\n"
    (tmp_path / "loop.asl").write_text("!l. +!l <- !l.")
    done = subprocess.run([*cmd, str(tmp_path / "loop.asl"), "--timeout", "0.5"],
                          capture_output=True, text=True, timeout=60)  # fmt: skip
    assert done.returncode == 3 and "--timeout" in done.stderr
    (tmp_path / "bad.asl").write_bytes(b'!s.\n+!s <- .print("\xff").\n')
    done = subprocess.run([*cmd, str(tmp_path / "bad.asl")], capture_output=True, text=True,
                          timeout=60)  # fmt: skip
    assert done.returncode == 1 and "bad.asl:2:16: not valid UTF-8" in done.stderr


def test_plan_terms_print_as_jason_and_are_added_and_awaited() -> None:
    program = """
    !s.
    +!s <- .print({+!g : c <- .print(x); !h}, " ", {+b}, " ", f('Quoted atom'));
       .add_plan({+!g(X) : X > 1 <- .print(big(X))}); !g(2);
       .add_plan({@p +b <- .print(b_added)}); +b;
       !!later; .wait({+!done}); .print(waited).
    +!later <- !done.
    +!done <- true.
    """
    out: list[str] = []
    Agent(program, "a", printer=lambda n, t: out.append(t)).run()
    assert out == [
        "{ +!g : c <- .print(x); !h } { +b } f('Quoted atom')",
        "big(2)",
        "b_added",
        "waited",
    ]


def test_one_formula_cannot_take_gigabytes_or_hang_the_agent() -> None:
    program = """
    !s.
    +!s <- .printf("%1000000000d", 1).
    -!s[error_msg(M)] <- .print(M); !r.
    +!r <- .replace("aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaab", "(a|a)+$", "x", R).
    -!r[error_msg(M)] <- .print(M).
    """
    out: list[str] = []
    Agent(program, "a", printer=lambda n, t: out.append(t)).run()
    assert "width or precision over 10000" in out[0]
    assert "ran longer than" in out[1]
    huge = '!s.\n+!s <- .print("' + "x" * (2 * 1024 * 1024) + '").\n'
    with pytest.raises(ParseError, match="line longer than") as err:
        parse_program(huge)
    assert err.value.line == 2


def test_jasons_actions_robocog_lacks_fail_saying_so() -> None:
    program = """
    !s.
    +!s <- .save_agent("b.asl").
    -!s[error_msg(M)] <- .print(M); .nonesuch(1).
    """
    out: list[str] = []
    warnings: list[str] = []
    Agent(
        program, "a", printer=lambda n, t: out.append(t), warn=lambda n, t: warnings.append(t)
    ).run()
    assert out == ["not supported: .save_agent/1"]
    assert any("unknown internal action .nonesuch/1" in w for w in warnings)


def test_list_plans_prints_the_library_in_one_message_whose_first_line_is_empty() -> None:
    out: list[str] = []
    Agent(
        "!s.\n@l +!s <- .list_plans.\n+!t <- true.", "a", printer=lambda n, t: out.append(t)
    ).run()
    lines = out[0].split("\n")
    assert lines[0] == "" and lines[1].startswith("// plans from")
    assert lines[2:] == ["@l +!s <- .list_plans.", "@p__2 +!t <- true."]


def test_an_ask_is_answered_by_plans_and_kqml_received_overrides_the_default(
    tmp_path: Path,
) -> None:
    files = {
        "p.mas2j": "MAS p { agents: asker; teller; }",
        "asker.asl": "!s.\n"
        "+!s <- .send(teller, askOne, price(apple, P), A); .print(A);\n"
        "       .send(teller, askOne, price(kiwi, Q), B); .print(B);\n"
        "       .send(teller, tell, hello); .send(teller, achieve, greet).",
        "teller.asl": "+?price(apple, P) <- P = 3.\n"
        "+!kqml_received(S, tell, hello, M) <- .print(heard(S)).\n"
        "+hello <- .print(added).\n"
        "+!greet <- .print(greeting).",
    }
    lines = _printed(tmp_path, files, "p.mas2j")
    # the belief base had no price: the +? plan answered; none for kiwi: false;
    # the program's kqml_received took the tell (no belief added), the achieve went on
    assert lines == [
        "[asker] price(apple,3)[source(teller)]",
        "[asker] false",
        "[teller] heard(asker)",
        "[teller] greeting",
    ]


def test_plans_are_asked_for_told_and_untold(tmp_path: Path) -> None:
    files = {
        "p.mas2j": "MAS p { agents: a; b; }",
        "a.asl": "!s.\n"
        "+!s <- .send(b, askHow, {+!hello(_)}, Plans); .print(Plans);\n"
        '       .send(b, askHow, "+!hello(X)"); .wait(50); !hello(world);\n'
        '       .send(b, untellHow, "@h1"); .wait(50);\n'
        "       .send(b, askHow, {+!hello(_)}, P2); .print(P2).",
        "b.asl": '@h1 +!hello(X) <- .print("hello ", X).',
    }
    lines = _printed(tmp_path, files, "p.mas2j")
    # with an answer variable the plans come back as terms, labelled with where they
    # come from and with fresh variables; without one they are told to the asker, who
    # then has the plan; untellHow removes only plans the sender told, so b keeps its
    # own (Jason 3.3 prints the same lines, with other numbers in the variables)
    fresh = re.compile(r"_\d+")
    term = '[a] [{ @h1[source(b),url("file:b.asl")] +!hello(_N) <- .print("hello ",_N) }]'
    assert [fresh.sub("_N", x) for x in lines] == [term, "[a] hello world", term]


def test_relevant_plans_and_plan_label_give_plan_terms() -> None:
    program = """
    !s.
    @g1 +!g(X) : X > 1 <- .print(big).
    @g2 +!g(_) <- .print(small).
    +!s <- .relevant_plans({+!g(_)}, L, Labels); .length(L, N); .print(N, Labels);
           .plan_label(P, g2); .print(P);
           .relevant_plans("+!other", E); .print(E).
    """
    out: list[str] = []
    Agent(program, "a", printer=lambda n, t: out.append(t)).run()
    # Jason 3.3 (the program in a file rp.asl): 2[g1[source(self),url("file:rp.asl")],
    # g2[...]], { @g2[source(self),url("file:rp.asl")] +!g(_24) <- .print(small) }, []
    # (an agent made from text has no file, so no url)
    assert [re.sub(r"_\d+", "_N", x) for x in out] == [
        "2[g1[source(self)],g2[source(self)]]",
        "{ @g2[source(self)] +!g(_N) <- .print(small) }",
        "[]",
    ]
