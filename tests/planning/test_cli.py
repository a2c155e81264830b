from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from robocog.experiments import plan_cli as cli

BLOCKS = Path(__file__).resolve().parents[3] / "shared" / "pddl" / "blocks"


def _run(argv: list[str], capsys) -> tuple[int, str, str]:
    parser = argparse.ArgumentParser()
    cli.configure(parser)
    code = cli.run(parser.parse_args(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_sentences_in_plan_out(capsys) -> None:
    code, out, _ = _run(
        [
            "--objects",
            "screw",
            "bolt",
            "washer",
            "workbench",
            "--facts",
            "The workbench is a fixed object.",
            "--goal",
            "The washer is on the screw. The bolt is on the washer.",
        ],
        capsys,
    )
    assert code == 0
    assert out.splitlines()[:4] == [
        '(pickup (ConceptNode "washer"))',
        '(stack (ConceptNode "washer") (ConceptNode "screw"))',
        '(pickup (ConceptNode "bolt"))',
        '(stack (ConceptNode "bolt") (ConceptNode "washer"))',
    ]


def test_json_output(capsys) -> None:
    code, out, _ = _run(["--thesis", "5.4", "--mode", "first", "--json"], capsys)
    data = json.loads(out)
    assert code == 0
    assert set(data) >= {"steps", "length", "iterations", "seconds", "optimal"}
    assert data["length"] == 4 and data["optimal"] is True
    assert data["steps"][0] == '(unstack (ConceptNode "SnapRing1") (ConceptNode "SnapRing2"))'


@pytest.mark.skipif(not (BLOCKS / "domain.pddl").exists(), reason="IPC blocks tasks absent")
def test_pddl_task(capsys) -> None:
    code, out, _ = _run(
        ["--pddl", str(BLOCKS / "domain.pddl"), str(BLOCKS / "task01.pddl"), "--json"], capsys
    )
    data = json.loads(out)
    assert code == 0 and data["length"] == 6 and data["optimal"]
    assert data["steps"][0].startswith("(pick-up ")


def test_bad_sentence_is_reported_not_raised(capsys) -> None:
    code, _, err = _run(["--objects", "a", "--goal", "The a is under the b."], capsys)
    assert code == 2
    assert "sentence 1" in err and "column" in err


def test_missing_pddl_file_is_reported(capsys, tmp_path: Path) -> None:
    with pytest.raises(SystemExit) as stop:  # refused while the command line is read
        _run(["--pddl", str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")], capsys)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and "d.pddl" in err


def test_no_plan_exits_with_one(capsys) -> None:
    code, out, _ = _run(
        [
            "--objects",
            "a",
            "t",
            "--facts",
            "The t is a fixed object.",
            "--goal",
            "The t is on the a.",
        ],
        capsys,
    )
    assert code == 1 and "no plan" in out


@pytest.mark.skipif(not (BLOCKS / "domain.pddl").exists(), reason="IPC blocks tasks absent")
def test_scene_written_as_pddl_and_planned_again(capsys, tmp_path: Path) -> None:
    out_file = tmp_path / "scene.pddl"
    code, out, _ = _run(["--thesis", "5.4", "--write-pddl", str(out_file), "--json"], capsys)
    first = json.loads(out)
    assert code == 0 and out_file.exists()
    domain = tmp_path / "domain.pddl"
    domain.write_text((BLOCKS / "domain.pddl").read_text())
    code, out, _ = _run(["--pddl", str(domain), str(out_file), "--json"], capsys)
    again = json.loads(out)
    # the bins and the workbench are all "the table" in the blocks world: still 4 actions
    assert code == 0 and again["length"] == first["length"] == 4
