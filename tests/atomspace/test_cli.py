"""``robocog atomese FILE...``."""

from __future__ import annotations

from pathlib import Path

from robocog.cli import main

from .conftest import DATA


def test_prints_query_results(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    q = tmp_path / "q.scm"
    q.write_text(
        '(Get (TypedVariable (Variable "$x") (Type "ConceptNode"))\n'
        '     (Inheritance (Variable "$x") (Concept "object")))\n'
        '(cog-execute! (Satisfaction (Evaluation (Predicate "clear") (Concept "table"))))\n'
    )
    assert main(["atomese", str(DATA / "kb_7_1a.scm"), str(q)]) == 0
    out = capsys.readouterr().out
    assert '(ConceptNode "bolt")' in out and '(ConceptNode "screw")' in out
    assert '(ConceptNode "table")' not in out.split("SatisfactionLink")[0]
    assert "(stv 1 1)" in out


def test_reports_malformed_files_with_place(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    bad = tmp_path / "bad.scm"
    bad.write_text('(Concept "a")\n  (List (Concept "b")\n')
    assert main(["atomese", str(bad)]) == 1
    err = capsys.readouterr().err
    assert f"{bad}:2:3:" in err


def test_dump_and_save(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    db = tmp_path / "s.db"
    assert main(["atomese", str(DATA / "kb_7_1a.scm"), "--save", str(db)]) == 0
    capsys.readouterr()
    assert main(["atomese", "--db", str(db), "--dump", str(DATA / "kb_7_1b_state.scm")]) == 0
    out = capsys.readouterr().out
    assert '(PredicateNode "in-hand")' in out and '(ConceptNode "fixed-object")' in out
