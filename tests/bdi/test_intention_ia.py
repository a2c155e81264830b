"""``.intention/2,3,4`` checked against Jason 3.3.

The expected lines were recorded from Jason 3.3 (built by ``build-jason.sh``) running
the same program with ``jason-agent a.mas2j`` (the program of Jason's ``failure``
demo); Jason's fresh variable numbers (``_44``) are compared as placeholders.
"""

from __future__ import annotations

import io
import itertools
import re
from pathlib import Path

import pytest

from robocog.bdi import circumstance
from robocog.bdi.project import run_files

FAILURE = """!test.
+!test : true <- .print("start"); !g1(X); .print("End, X=",X).

+!g1(X) : true <- .print(inig1); !g2(X); .print(endg1).
+!g2(X) : true <- .print(inig2); !g3(X); .print(endg2).
+!g3(X) : true <- .print(inig3); !g4(X); .print(endg3).
+!g4(X) : true <- .print(inig4); !g5(X); .print(endg4).
+!g5(_) : true <- .fail.

-!g3(failure)[error(ErrorId), error_msg(Msg), code(CodeBody), code_src(CodeSrc), \
code_line(CodeLine)] : true
   <- .print("Error ", ErrorId, " '",Msg,"' by ",CodeBody," in ",CodeSrc,":",CodeLine);
      .intention(Id,S,IntendedMeans,current);
      .print("current intention state is: ",S);
      .println;
      .println("*  Intention #",Id, ", IM stack:");
      !print_im(IntendedMeans);
   .

+!print_im([]).
+!print_im([im(PlanLabel,Trigger,Body,Unif)|R])
  <- .println("*        ",Body,"      * unifier: ",Unif,", plan ",PlanLabel);
     !print_im(R).
"""

_SRC = '[code_line({}),code_src("file:a.asl"),source(self),url("file:a.asl")]'
JASON_3_3 = [
    "[a] start",
    "[a] inig1",
    "[a] inig2",
    "[a] inig3",
    "[a] inig4",
    "[a] Error ia_failed '' by .fail in file:a.asl:8",
    "[a] current intention state is: running",
    "[a] ",
    "[a] *  Intention #1, IM stack:",
    '[a] *        { .intention(_44,_45,_46,current); .print("current intention state is: ",'
    '_45); .println; .println("*  Intention #",_44,", IM stack:"); !print_im(_46) }      '
    '* unifier: [map(_47,""),map(_48,ia_failed),map(_49,.fail),map(_50,8),'
    'map(_51,"file:a.asl"),map(_52,failure)], plan p__7' + _SRC.format(10),
    "[a] *        { .fail }      * unifier: [map(_68,_67)], plan p__6" + _SRC.format(8),
    "[a] *        { !g5(_82); .print(endg4) }      * unifier: [map(_83,_81)], plan p__5"
    + _SRC.format(7),
    # g3's plan: its X already bound by the failure plan handling -!g3(failure)
    "[a] *        { !g4(_93); .print(endg3) }      * unifier: [map(_94,failure)], plan p__4"
    + _SRC.format(6),
    "[a] *        { !g3(_103); .print(endg2) }      * unifier: [map(_104,_102)], plan p__3"
    + _SRC.format(5),
    "[a] *        { !g2(_110); .print(endg1) }      * unifier: [map(_111,_109)], plan p__2"
    + _SRC.format(4),
    '[a] *        { !g1(_113); .print("End, X=",_113) }      * unifier: [], plan p__1'
    + _SRC.format(2),
    "[a] endg2",
    "[a] endg1",
    "[a] End, X=failure",
]


def _placeholders(line: str) -> str:
    return re.sub(r"(?<![\w\"])_\d+", "_V", line)


def _run(tmp_path: Path, text: str, monkeypatch: pytest.MonkeyPatch) -> list[str]:
    (tmp_path / "a.asl").write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)  # the file is named as Jason names it: file:a.asl
    # intention numbers count per process, as Jason's do per JVM: start them as a new
    # process would, whatever ran before in this test worker
    monkeypatch.setattr(circumstance, "_intention_ids", itertools.count(1))
    out = io.StringIO()
    run_files([Path("a.asl")], lambda ag, line: out.write(f"[{ag}] {line}\n"), real_time=False)
    return out.getvalue().splitlines()


def test_intention_current_shows_the_stack_as_jason_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    got = _run(tmp_path, FAILURE, monkeypatch)
    assert len(got) == len(JASON_3_3)
    for mine, jason in zip(got, JASON_3_3, strict=True):
        assert _placeholders(mine) == _placeholders(jason)


def test_intention_finds_each_intention_with_its_state(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    program = """!a. !b.
+!a <- .wait(500); .print(a_done).
+!b <- .wait(10);
       .intention(I, St, [im(_, {+!a}, _, _)|_]); .print(St);
       .intention(J, running, [im(_, {+!G}, _, _)|_]); .print(G);
       .intention(K, _, _, current); if (J == K & I \\== K) { .print(distinct) }.
"""
    got = _run(tmp_path, program, monkeypatch)
    assert re.fullmatch(r"\[a\] waiting\[reason\(wait\(\d+\)\[time\(500\)\]\)\]", got[0])
    assert got[1:] == ["[a] b[source(self)]", "[a] distinct", "[a] a_done"]
