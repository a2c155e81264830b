"""The assembly experiment: Tables 5.2-5.10 planned and executed on the tabletop."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from robocog.experiments import assembly
from robocog.experiments.assembly_thesis import EXPERIMENTS


def test_every_table_is_reached_with_the_thesis_plan() -> None:
    run = assembly.run_sequence("tables", seed=0)
    assert [r.table for r in run.requests] == [e.table for e in EXPERIMENTS]
    for req, exp in zip(run.requests, EXPERIMENTS, strict=True):
        assert req.reached, req.table
        plan = req.record.first_plan
        assert plan is not None and plan.length == exp.length, req.table
        assert req.record.replans == 0


def test_blockb_and_blockc_are_each_one_request() -> None:
    run = assembly.run_sequence("whole", seed=0)
    by_table = {r.table: r for r in run.requests}
    assert by_table["BlockB"].reached and by_table["BlockC"].reached
    plan_b = by_table["BlockB"].record.first_plan
    plan_c = by_table["BlockC"].record.first_plan
    assert plan_b is not None and plan_b.length == 10
    assert plan_c is not None and plan_c.length == 8
    assert run.reached


def test_injected_grasp_failures_are_recovered_by_replanning() -> None:
    slips = replans = 0
    for seed in range(1, 4):
        run = assembly.run_sequence("tables", seed=seed, failure_rate=0.3)
        assert run.reached
        slips += sum(r.failed_grasps for r in run.requests)
        replans += sum(r.record.replans for r in run.requests)
    assert slips > 0 and replans == slips


def test_thesis_figures_of_a_whole_assembly_add_up_its_splits() -> None:
    plan, iterations, seconds = assembly.thesis_figures("BlockB")
    assert len(plan) == 10 and iterations == 493 + 343 + 3 and seconds == 39.0 + 2.1


def test_the_command_writes_json_and_a_report(tmp_path: Path) -> None:
    parser = argparse.ArgumentParser()
    assembly.configure(parser)
    out = tmp_path / "a.json"
    args = parser.parse_args(
        ["--runs", "2", "--json", str(out), "--report", str(tmp_path / "r"), "--no-plots"]
    )
    assert assembly.run(args) == 0
    data = json.loads(out.read_text())
    for key in ("planner", "planner_grasp_failures"):
        assert data["minds"][key]["success_rate"] == 1.0
        assert data["minds"][key]["runs"] >= 2
    assert data["minds"]["planner_grasp_failures"]["runs"] == 4
    assert data["arguments"]["failure_rate"] == 0.25 and "robocog_version" in data
    report = (tmp_path / "r" / "assembly.md").read_text()
    assert "| failure_rate | 0.25 |" in report
    assert "5.8" in report and "5853" in report and "BlockC" in report


def test_the_report_plots_search_times(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    parser = argparse.ArgumentParser()
    assembly.configure(parser)
    args = parser.parse_args(["--runs", "0", "--out", str(tmp_path)])
    assert assembly.run(args) == 0
    assert (tmp_path / "assembly_times.png").stat().st_size > 0
    assert "assembly_times.png" in (tmp_path / "assembly.md").read_text()
