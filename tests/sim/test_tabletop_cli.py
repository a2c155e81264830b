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
