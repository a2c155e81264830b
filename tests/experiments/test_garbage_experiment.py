"""The garbage experiment: rates come from the world, the JSON and report have their shape."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

import pytest

from robocog import __version__, cli
from robocog.experiments.garbage import (
    TIMING_KEYS,
    MindSpec,
    default_minds,
    learn_accumulation,
    run_experiment,
)
from robocog.experiments.report import TIMINGS_HEADING, explain, write_json, write_report
from robocog.robot import Command, Detection, Drop, GoTo, Gripper, Outcome, Percept, Pick
from robocog.worlds.garbage import GarbageConfig, GarbageField


class Sweeper:
    """Picks the first thing it sees (once per instance), drops what it holds, moves on."""

    def __init__(self, retry: bool) -> None:
        self.retry = retry
        self.seen: list[Detection] = []
        self.holding = False
        self.failed: set[str] = set()

    def perceive(self, percepts: Sequence[Percept]) -> None:
        self.seen = [p for p in percepts if isinstance(p, Detection)]
        self.holding = any(isinstance(p, Gripper) and p.holding for p in percepts)

    def decide(self) -> list[Command]:
        if self.holding:
            return [Drop()]
        for d in self.seen:
            if self.retry:
                return [Pick(d.label)]
            if d.instance not in self.failed:
                return [Pick(d.instance or d.label)]
        return [GoTo("next")]

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        if isinstance(command, Pick) and not outcome.ok:
            self.failed.add(command.target)


def _specs() -> list[MindSpec]:
    return [
        MindSpec("careful", lambda w, s: Sweeper(retry=False)),
        MindSpec("stubborn", lambda w, s: Sweeper(retry=True)),
        MindSpec("absent", lambda w, s: Sweeper(False), probe=lambda: "engine not built"),
    ]


def test_rates_are_read_off_the_world_and_the_same_seeds_meet_every_mind() -> None:
    result = run_experiment(_specs(), runs=6, seed=2)
    careful, stubborn, absent = (result.minds[n] for n in ("careful", "stubborn", "absent"))
    assert [r.seed for r in careful.runs] == [r.seed for r in stubborn.runs]
    assert len(careful.runs) == 6 and absent.runs == []
    assert absent.unavailable == "engine not built" and not absent.ok
    for m in (careful, stubborn):
        assert m.success_rate == sum(r.collected for r in m.runs) / sum(r.objects for r in m.runs)
        for r in m.runs:
            missed = sum(r.causes.values())
            assert missed + r.collected == r.objects
    again = run_experiment(_specs()[:1], runs=6, seed=2)
    assert again.minds["careful"].success_rate == careful.success_rate
    # Only the stubborn mind keeps grasping at objects lying over.
    assert sum(r.futile_picks for r in stubborn.runs) > sum(r.futile_picks for r in careful.runs)
    assert any("lying over" in line for line in explain(result))


def test_json_shape_and_report_files(tmp_path: Path) -> None:
    result = run_experiment(_specs(), runs=2, seed=0, config=GarbageConfig(light="cloudy"))
    write_json(tmp_path / "r.json", result)
    doc = json.loads((tmp_path / "r.json").read_text())
    assert doc["experiment"] == "garbage" and doc["light"] == "cloudy"
    assert set(doc["minds"]) == {"careful", "stubborn", "absent"}
    for name in ("careful", "stubborn"):
        entry = doc["minds"][name]
        assert 0.0 <= entry["success_rate"] <= 1.0
        assert entry["runs"] == 2
        assert set(entry["failures"]) == {"detection", "grasp", "decision", "time"}
    assert doc["minds"]["absent"]["runs"] == 0
    assert doc["minds"]["absent"]["success_rate"] is None
    assert doc["minds"]["absent"]["status"] == "unavailable"
    page = write_report(result, tmp_path / "report")
    text = page.read_text()
    assert "Table II" in text and "absent did not run" in text
    assert (tmp_path / "report" / "success.png").exists()
    assert (tmp_path / "report" / "trajectory_careful.png").exists()


def test_the_command_writes_json_with_an_entry_per_mind(tmp_path: Path) -> None:
    out = tmp_path / "json.json"
    args = ["experiment", "garbage", "--minds", "bdi", "--runs", "2", "--rounds", "0"]
    code = cli.main([*args, "--json", str(out), "--out", str(tmp_path / "report")])
    doc = json.loads(out.read_text())
    assert set(doc["minds"]) == {"BDI"}
    entry = doc["minds"]["BDI"]
    assert entry["runs"] in (0, 2)
    assert entry["success_rate"] is None or 0.0 <= entry["success_rate"] <= 1.0
    assert code == (0 if entry["status"] == "ok" else 1)
    assert (tmp_path / "report" / "report.md").exists()


def test_bad_arguments_are_refused(capsys) -> None:  # noqa: ANN001 - pytest fixture
    with pytest.raises(SystemExit) as refused:  # while the command line is read
        cli.main(["experiment", "garbage", "--runs", "0"])
    assert refused.value.code == 2
    assert cli.main(["experiment", "garbage", "--minds", "cortex", "--runs", "1"]) == 2
    assert "unknown mind" in capsys.readouterr().err


def test_a_field_layout_for_the_plot() -> None:
    layout = GarbageField(seed=0).describe()
    assert layout["size"] == 22.0 and len(layout["checkpoints"]) == 8  # type: ignore[arg-type]


def _without_timings(doc: object) -> object:
    """The JSON document with every machine-dependent figure taken out."""
    if isinstance(doc, dict):
        return {k: _without_timings(v) for k, v in doc.items() if k not in TIMING_KEYS}
    if isinstance(doc, list):
        return [_without_timings(v) for v in doc]
    return doc


@pytest.mark.slow
def test_two_demos_give_the_same_report_apart_from_timings(tmp_path: Path) -> None:
    """Nothing in a result depends on the wall clock: same arguments, same report."""
    pages, docs = [], []
    for name in ("first", "second"):
        out = tmp_path / name
        argv = ["demo", "--runs", "1", "--rounds", "2", "--seed", "4", "--out", str(out)]
        # a file to write goes in a folder that exists (the report folder is made later)
        result = tmp_path / f"{name}.json"
        assert cli.main([*argv, "--json", str(result)]) == 0
        page = (out / "report.md").read_text()
        assert TIMINGS_HEADING in page
        pages.append(page.split(TIMINGS_HEADING)[0])
        docs.append(json.loads(result.read_text()))
    assert pages[0] == pages[1]
    assert _without_timings(docs[0]) == _without_timings(docs[1])
    doc = docs[0]
    assert doc["robocog_version"] == __version__
    assert doc["config"]["light"] == "sunny" and doc["config"]["mission_time"] == 420.0
    assert doc["question"]["rounds"] == 2  # the rounds asked for, all of them run
    assert "wall_seconds" in doc  # the timings are there, only set apart


def test_detection_and_grasp_can_be_set_apart_from_the_light() -> None:
    config = GarbageConfig(light="evening", detection=0.95, grasp=0.6)
    assert config.detection_rate == 0.95 and config.pick_success == 0.6
    assert GarbageConfig(light="evening").detection_rate == 0.61
    with pytest.raises(ValueError, match="detection"):
        GarbageConfig(detection=1.5)


@pytest.mark.slow
def test_nars_ranks_the_hotspots_first_after_a_few_rounds() -> None:
    """A small field (six checkpoints, two hotspots, six objects a round) for six rounds:
    the order comes from NARS's evidence for ``<<({SELF} * {p}) --> at> =/> <trash -->
    [see]>>``, one piece per arrival, and must put the hotspots on top."""
    spec = default_minds(["nars"])[0]
    why = spec.probe()
    if why:
        pytest.skip(f"the reasoner cannot drive the robot yet: {why}")
    config = GarbageConfig(checkpoints=6, objects=6, hotspots={1: 5.0, 4: 5.0})
    acc = learn_accumulation(spec, config, seed=0, rounds=6)
    assert acc.rounds == 6 and acc.hotspots == ["p1", "p4"]
    assert all(acc.arrivals[p] >= 5 for p in acc.arrivals)
    assert acc.hotspots_first, acc.ranking
    expectations = [e for _p, _f, _c, e in acc.ranking]
    assert expectations == sorted(expectations, reverse=True)
    assert acc.answer is not None and acc.answer[0].startswith("<<({SELF} * {p")


class _Noting(Sweeper):
    """A mind that, like the NARS mind, records a rewritten rule of its knowledge."""

    def __init__(self) -> None:
        super().__init__(retry=False)
        self.notes = ["One rule was rewritten; nothing is wrong with the run."]


def test_a_minds_notes_sit_in_their_own_section_not_under_table_ii(tmp_path: Path) -> None:
    result = run_experiment([MindSpec("noting", lambda w, s: _Noting())], runs=1, seed=0)
    text = write_report(result, tmp_path).read_text()
    table_ii = text.index("## Success rate (Table II)")
    next_section = text.index("\n## ", table_ii + 1)
    assert "rewritten" not in text[table_ii:next_section]
    notes = text.index("## How the paper's knowledge was read")
    assert notes < text.index("## Configuration")
    assert "**noting.** One rule was rewritten" in text[notes:]


def test_the_nars_minds_note_explains_the_rewritten_rule_in_words() -> None:
    from robocog.minds.nars_mind import BRACKETED_GOTO_RULE, PRINTED_GOTO_RULE, rewrite_note

    note = rewrite_note(PRINTED_GOTO_RULE, "line 1, column 91: unexpected '.'")
    assert PRINTED_GOTO_RULE in note and BRACKETED_GOTO_RULE in note
    assert "without changing its meaning" in note and "column 91" in note
    assert "gripper open" in note and "Nothing is wrong with the run" in note
