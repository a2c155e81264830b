"""Sweeps: the grid, the table that resumes, executors that agree, and the report."""

from __future__ import annotations

import dataclasses
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robocog import cli
from robocog.experiments.sweep import (
    SweepError,
    SweepSpec,
    Task,
    in_process,
    parse_axis,
    process_pool,
    ray_cluster,
    read_table,
    run_sweep,
)
from robocog.experiments.sweep_report import Estimate, summarise, write_report


def _spec(minds: tuple[str, ...] = ("bdi",), runs: int = 2, **kw: object) -> SweepSpec:
    axes = (parse_axis("detection=0.5,0.9"), parse_axis("grasp=0.6:0.9:0.3"))
    return SweepSpec("garbage", axes, minds, runs, 1, fixed=(("light", "sunny"),), **kw)  # type: ignore[arg-type]


def test_axes_are_parsed_with_both_ends_and_no_float_drift() -> None:
    axis = parse_axis("detection=0.5:0.95:0.05")
    assert axis.values[0] == 0.5 and axis.values[-1] == 0.95 and len(axis.values) == 10
    assert 0.55 in axis.values
    assert parse_axis("objects=4,8").values == (4.0, 8.0)
    for bad in ("detection", "x=1:0:0.1", "x=0:1:0", "x=nan", "x=1,1", "x=0:1e9:1e-6", "x=a"):
        with pytest.raises(SweepError):
            parse_axis(bad)


def test_a_sweep_is_every_combination_and_refuses_what_the_study_lacks() -> None:
    spec = _spec(("nars", "bdi"), runs=3)
    assert spec.missions == 2 * 2 * 2 * 3 == len(spec.tasks())
    assert len({t.key for t in spec.tasks()}) == spec.missions
    from robocog.experiments.sweep import check

    with pytest.raises(SweepError, match="no setting 'colour'"):
        check(SweepSpec("garbage", (parse_axis("colour=1,2"),), ("bdi",), 1, 1))
    with pytest.raises(SweepError, match="no mind"):
        check(SweepSpec("garbage", (), ("cortex",), 1, 1))


@pytest.mark.parametrize(
    ("argv", "says"),
    [
        (["garbage", "--vary", "detection=2"], "--vary detection=2: detection must be"),
        (["room-exit", "--vary", "obstacles=1.5"], "--vary obstacles=1.5: obstacles is a whole"),
        (["assembly", "--vary", "failure_rate=0:2:0.5"], "failure_rate=1.5: failure_rate"),
        (["garbage", "--light", "foo", "--vary", "detection=0.5"], "light must be one of"),
    ],
)
def test_a_value_the_world_refuses_is_one_line_before_any_mission(
    argv: list[str], says: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "sweep"
    assert cli.main(["sweep", *argv, "--runs", "1", "--jobs", "2", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err and "Traceback" not in err
    assert not out.exists()  # no table begun


@pytest.mark.slow
def test_local_pool_and_this_process_give_the_same_table(tmp_path: Path) -> None:
    spec = _spec(("bdi", "nars"), runs=1)
    # missions of a third of a battery charge: what is compared is the table, not the length
    spec = dataclasses.replace(spec, axes=(*spec.axes, parse_axis("mission_time=150")))
    here = run_sweep(spec, tmp_path / "a.jsonl", in_process)
    pool = run_sweep(spec, tmp_path / "b.jsonl", process_pool(2))
    assert len(here) == spec.missions and here == pool
    # the rows come from the world: detection and grasp change what is collected
    assert {r["mind"] for r in here} == {"bdi", "nars"}
    assert all(0 <= r["collected"] <= r["objects"] for r in here)


@pytest.mark.slow
def test_a_local_ray_cluster_gives_the_same_table(tmp_path: Path) -> None:
    pytest.importorskip("ray")
    spec = _spec(("bdi",), runs=2)
    here = run_sweep(spec, tmp_path / "a.jsonl", in_process)
    before = signal.getsignal(signal.SIGTERM)
    on_ray = run_sweep(spec, tmp_path / "b.jsonl", ray_cluster(None, cpus=2))
    assert here == on_ray
    # Ray's own SIGTERM handler, set by its start, does not outlive the sweep
    assert signal.getsignal(signal.SIGTERM) == before


def test_a_killed_sweep_resumes_to_the_table_of_an_uninterrupted_one(tmp_path: Path) -> None:
    whole = tmp_path / "whole"
    cut = tmp_path / "cut"
    argv = ["sweep", "garbage", "--vary", "detection=0.5:0.9:0.1", "--minds", "bdi"]
    argv += ["--runs", "4", "--jobs", "1"]
    assert cli.main([*argv, "--out", str(whole)]) == 0
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(Path(cli.__file__).parents[1]), env.get("PYTHONPATH", "")]
    )
    proc = subprocess.Popen(
        [sys.executable, "-m", "robocog.cli", *argv, "--out", str(cut)],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    table = cut / "results.jsonl"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if table.exists() and table.read_text().count("\n") >= 4:  # header and 3 rows
            break
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    lines = table.read_text().count("\n") - 1
    assert 3 <= lines < 20, "the sweep was to be killed half-way"
    with table.open("a") as f:  # as if the kill cut a row in half
        f.write('{"key": "bdi|detection=0.9|0|')
    assert cli.main([*argv, "--out", str(cut)]) == 0
    spec, rows_cut = read_table(table)
    _, rows_whole = read_table(whole / "results.jsonl")
    key = [t.key for t in spec.tasks()]
    assert sorted(r["key"] for r in rows_cut) == sorted(key)
    by_key = {r["key"]: r for r in rows_whole}
    assert all(by_key[r["key"]] == r for r in rows_cut)
    assert (cut / "report.md").read_text() == (whole / "report.md").read_text()


def test_a_table_of_another_sweep_or_a_bad_line_is_refused(tmp_path: Path) -> None:
    table = tmp_path / "t.jsonl"
    run_sweep(_spec(runs=1), table)
    with pytest.raises(SweepError, match="another sweep"):
        run_sweep(_spec(runs=2), table)
    lines = table.read_text().splitlines()
    table.write_text("\n".join([lines[0], lines[1], "{oops", *lines[2:]]) + "\n")
    with pytest.raises(SweepError, match=r"t\.jsonl:3:2"):
        read_table(table)
    table.write_text(lines[0] + "\n" + json.dumps({"key": "nars|x|0|0"}) + "\n")
    with pytest.raises(SweepError, match="not a mission of this sweep"):
        read_table(table)
    assert cli.main(["sweep", "garbage", "--vary", "detection=2:1:1", "--out", str(tmp_path)]) == 2


def test_the_report_has_intervals_a_paired_difference_and_its_sign_changes(
    tmp_path: Path,
) -> None:
    spec = SweepSpec("garbage", (parse_axis("detection=0.5,0.7,0.9"),), ("nars", "bdi"), 2, 1)
    rows = []
    # made-up rows: NARS leads at low detection, BDI at high, the lead changing sign once
    for det, (ra, rb) in zip(
        spec.axes[0].values, ((0.6, 0.4), (0.55, 0.5), (0.3, 0.6)), strict=True
    ):
        for run in range(2):
            for mind, rate in (("nars", ra + 0.1 * run), ("bdi", rb + 0.1 * run)):
                task = Task(mind, (("detection", det),), 0, run)
                rows.append({"key": task.key, "mind": mind, "detection": det, "seed": 0,
                             "run": run, "rate": rate, "missed_grasp": 1})  # fmt: skip
    summary = summarise(spec, rows)
    d = summary.difference
    assert d[(("detection", 0.5),)].mean == pytest.approx(0.2)
    assert d[(("detection", 0.9),)].mean == pytest.approx(-0.3)
    (crossing,) = summary.crossings()
    assert crossing["between"] == (0.7, 0.9)
    assert crossing["at"] == pytest.approx(0.7 + 0.2 * 0.05 / 0.35)
    page = write_report(summary, tmp_path).read_text()
    assert "nars - bdi" in page and "crossing zero near 0.729" in page
    assert (
        "| mission_time | 420.0 |" in page
        and "| detection |" not in page.split("## Configuration")[1]
    )
    assert summary.curves[("nars", (("detection", 0.5),))].text() == "65.0% [1.5, 100.0]"
    assert "Student-t" in page


def test_an_estimate_is_a_mean_with_a_t_interval() -> None:
    est = Estimate.of([0.2, 0.4, 0.6])
    assert est.mean == pytest.approx(0.4)
    assert est.high - est.mean == pytest.approx(4.303 * 0.2 / 3**0.5)
    all_or_nothing = Estimate.of([1.0, 1.0, 0.0, 1.0])  # Wilson: 3 of 4
    assert all_or_nothing.mean == 0.75
    assert all_or_nothing.low == pytest.approx(0.3006, abs=1e-3)
    assert all_or_nothing.high == pytest.approx(0.9544, abs=1e-3)
    assert Estimate.of([1.0] * 30).high == 1.0 and Estimate.of([1.0] * 30).low < 1.0
    assert not Estimate.of([-0.1, 0.1]).excludes_zero


def test_a_sweep_says_what_it_runs_and_that_it_resumed(tmp_path: Path, capsys) -> None:  # noqa: ANN001
    argv = ["sweep", "garbage", "--vary", "detection=0.5,0.9", "--minds", "bdi", "--runs", "1"]
    argv += ["--jobs", "1", "--out", str(tmp_path)]
    assert cli.main(argv) == 0
    first = capsys.readouterr().err
    assert first.startswith("robocog sweep garbage: 2 missions on this process")
    assert "missions: 2/2" in first and "resum" not in first
    assert cli.main(argv) == 0
    assert "resumed: all 2 missions are already in" in capsys.readouterr().err
    lines = (tmp_path / "results.jsonl").read_text().splitlines()
    (tmp_path / "results.jsonl").write_text("\n".join(lines[:2]) + "\n")  # header, one row
    assert cli.main(argv) == 0
    assert "resuming: 1 of 2 missions are already in" in capsys.readouterr().err
