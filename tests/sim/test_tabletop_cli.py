"""``robocog sim tabletop``: the operator's commands are read strictly."""

from __future__ import annotations

import pytest

from robocog.robot import PickUp, PutDown, Stack, Unstack
from robocog.sim.tabletop import DEFAULT_SCRIPT, parse_script


def test_a_script_becomes_commands() -> None:
    assert parse_script("pickup A; Stack A B;; unstack C D ; PutDown A") == [
        PickUp("A"),
        Stack("A", "B"),
        Unstack("C", "D"),
        PutDown("A"),
    ]
    assert len(parse_script(DEFAULT_SCRIPT)) == 4


@pytest.mark.parametrize("bad", ["Jump A", "Stack A", "PickUp", "PickUp A B"])
def test_a_bad_command_is_named(bad: str) -> None:
    with pytest.raises(ValueError, match="command 2"):
        parse_script(f"PickUp X; {bad}")


def test_the_core_and_the_commands_load_without_mujoco() -> None:
    import subprocess
    import sys

    code = (
        "import sys, robocog, robocog.worlds, robocog.worlds.tabletop, robocog.sim.cli, "
        "robocog.experiments.assembly, robocog.minds.planner_mind; "
        "sys.exit('mujoco' in sys.modules or 'pupil_apriltags' in sys.modules)"
    )
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0
