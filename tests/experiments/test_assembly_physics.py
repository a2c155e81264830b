"""``robocog experiment assembly --world mujoco`` on a short sequence: report, film, frames."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

import robocog.worlds.physics  # noqa: F401  (chooses the GL backend before mujoco loads)

pytest.importorskip("mujoco", reason="the physics extra (mujoco) is not installed")
pytest.importorskip(
    "pupil_apriltags", reason="the physics extra (pupil-apriltags) is not installed"
)
pytest.importorskip("imageio", reason="the physics extra (imageio) is not installed")

from robocog.experiments import assembly  # noqa: E402


@pytest.mark.slow
def test_table_5_2_runs_physically_with_a_report_a_film_and_a_key_frame(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(assembly, "SEQUENCES", {"tables": [("request", "5.2")]})
    args = argparse.Namespace(
        world="mujoco",
        seed=0,
        runs=0,
        failure_rate=0.25,
        mode="astar",
        report=str(tmp_path),
        json=str(tmp_path / "a.json"),
        perturb=False,
        no_video=False,
        no_plots=True,
    )
    assert assembly.run(args) == 0
    report = (tmp_path / "assembly.md").read_text()
    assert "| 5.2 | pickup BettClamp" in report and "| same |" in report
    assert (tmp_path / "tables.gif").stat().st_size > 10_000
    assert (tmp_path / "tables_5.2.png").read_bytes().startswith(b"\x89PNG")
    row = json.loads((tmp_path / "a.json").read_text())["requests"]["tables"][0]
    assert row["reached"] and row["replans"] == 0 and row["sim_seconds"] > 10
