"""The room-exit experiment: both of the paper's results occur over seeded runs."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

import robocog
from robocog.experiments import room_exit
from robocog.minds.qbo import reach_exit_program
from robocog.worlds.room import RoomConfig


@pytest.fixture(scope="module")
def thirty_runs() -> list[room_exit.RunResult]:
    return [room_exit.run_once(seed, "reference", keep_route=False) for seed in range(30)]


def test_both_outcomes_of_section_3_1_occur(thirty_runs: list[room_exit.RunResult]) -> None:
    results = thirty_runs
    outcomes = {r.outcome for r in results}
    assert "exit found" in outcomes
    assert "opposite door mistaken" in outcomes
    for r in results:
        if r.outcome == "exit found":
            assert r.left_room and r.door_stop is not None
        if r.outcome == "opposite door mistaken":
            assert r.door_stop is not None


def test_a_mistaken_run_stopped_away_from_the_door_after_heading_for_the_other_one(
    thirty_runs: list[room_exit.RunResult],
) -> None:
    mistaken = [r for r in thirty_runs if r.outcome == "opposite door mistaken"]
    assert mistaken
    assert any(r.opposite_looks > 0 for r in mistaken)


def test_runs_are_reproducible_from_their_seed() -> None:
    a = room_exit.run_once(5, "reference")
    b = room_exit.run_once(5, "reference")
    assert a.route == b.route and a.outcome == b.outcome


def test_the_plans_are_the_papers() -> None:
    source = reach_exit_program()
    for label in ("@re", "@ro", "@s_td1", "@s_td2", "@so1", "@so2", "@da1", "@da2", "@da3", "@da4"):
        assert f"\n{label}\n" in source
    assert "-+expected_target_direction(Dir + 45)" in source
    assert source.rstrip().endswith("!reach_exit.")
    assert "tcp_write(search_Qbo(Dir))" in source


def test_summary_counts_frequencies() -> None:
    results = [room_exit.run_once(seed, "reference", keep_route=False) for seed in range(6)]
    s = room_exit.summarise(results)
    assert s["runs"] == 6
    assert sum(s["outcomes"].values()) == 6
    assert sum(s["frequencies"].values()) == pytest.approx(1.0)
    assert 0.0 <= s["success_rate"] <= 1.0


def test_the_command_writes_json_with_one_entry_per_mind(tmp_path: Path) -> None:
    parser = argparse.ArgumentParser()
    room_exit.configure(parser)
    out = tmp_path / "r.json"
    args = parser.parse_args(
        [
            "--runs",
            "4",
            "--json",
            str(out),
            "--report",
            str(tmp_path / "rep"),
            "--particles",
            "200",
            "--no-plots",
        ]
    )
    assert room_exit.run(args) == 0
    data = json.loads(out.read_text())
    assert data["minds"]["reference"]["runs"] == 4
    assert 0.0 <= data["minds"]["reference"]["success_rate"] <= 1.0
    assert set(data["minds"]) | set(data["unavailable"]) == {"bdi", "reference"}
    assert data["convergence"]["A"]["failing_steps"] == []
    assert data["convergence"]["constant-step"]["failing_steps"]
    assert data["robocog_version"] == robocog.__version__
    assert data["arguments"]["runs"] == 4 and data["arguments"]["particles"] == 200
    assert data["config"]["doorway_width"] == RoomConfig().doorway_width
    page = (tmp_path / "rep" / "room_exit.md").read_text()
    assert "## Configuration" in page and "| particles | 200 |" in page


def test_the_agentspeak_run_of_the_plans_matches_their_python_transcription() -> None:
    pytest.importorskip("robocog.bdi.stdlib")
    for seed in range(8):
        bdi = room_exit.run_once(seed, "bdi")
        reference = room_exit.run_once(seed, "reference")
        assert bdi.route == reference.route, seed
        assert bdi.outcome == reference.outcome


def test_d_measured_on_the_room_shrinks_by_alpha_until_close_to_the_door(
    thirty_runs: list[room_exit.RunResult],
) -> None:
    steps = room_exit.room_d_per_step(thirty_runs, room_exit.front_of_door())
    assert len(steps) >= 5
    far = [st for st in steps if st.mean_distance > 1.0]
    assert far and all(st.holds for st in far)
    assert all(st.mean_distance < 1.0 for st in steps if not st.holds)
    assert steps[0].runs == 30


def test_the_report_has_route_and_convergence_plots(tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    parser = argparse.ArgumentParser()
    room_exit.configure(parser)
    args = parser.parse_args(
        ["--runs", "12", "--mind", "reference", "--out", str(tmp_path), "--particles", "100"]
    )
    assert room_exit.run(args) == 0
    report = (tmp_path / "room_exit.md").read_text()
    assert "![convergence](convergence.png)" in report
    assert (tmp_path / "convergence.png").stat().st_size > 0
    assert (tmp_path / "route_reference_exit.png").exists()
