"""The ROS 2 launch file shipped for machines with ROS: its command line is one the
bridge accepts. ``launch`` itself is ROS's, absent here, so a minimal stand-in of its
four names records what the file builds."""

from __future__ import annotations

import argparse
import importlib.util
import sys
import types
from pathlib import Path

import pytest

import robocog.bridges.ros2 as ros2_package
from robocog.bridges.cli import configure

LAUNCH_FILE = Path(ros2_package.__path__[0]) / "bridge.launch.py"


class _Config:
    values: dict[str, str] = {}

    def __init__(self, name: str) -> None:
        self.name = name

    def perform(self, _context: object) -> str:
        return self.values[self.name]


def _stand_in_launch(monkeypatch: pytest.MonkeyPatch) -> None:
    launch = types.ModuleType("launch")
    actions = types.ModuleType("launch.actions")
    substitutions = types.ModuleType("launch.substitutions")
    launch.LaunchDescription = lambda items: list(items)
    actions.DeclareLaunchArgument = lambda name, default_value, description: (
        "arg",
        name,
        default_value,
    )
    actions.ExecuteProcess = lambda cmd, output, name: ("process", cmd)
    actions.OpaqueFunction = lambda function: ("function", function)
    substitutions.LaunchConfiguration = _Config
    for module in (launch, actions, substitutions):
        monkeypatch.setitem(sys.modules, module.__name__, module)


def _commands(monkeypatch: pytest.MonkeyPatch, **given: str) -> list[str]:
    _stand_in_launch(monkeypatch)
    spec = importlib.util.spec_from_file_location("bridge_launch", LAUNCH_FILE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    items = module.generate_launch_description()
    defaults = {item[1]: item[2] for item in items if item[0] == "arg"}
    _Config.values = {**defaults, **given}
    [(_, function)] = [item for item in items if item[0] == "function"]
    [(_, cmd)] = function(None)
    return cmd


@pytest.mark.parametrize(
    "given",
    [
        {},
        {"mind": "bdi", "knowledge": "robot.asl", "namespace": "robot1"},
        {"config": "my_robot.toml", "record": "run.mcap", "watchdog": "0.5"},
    ],
)
def test_the_launch_file_starts_a_bridge_the_cli_accepts(
    monkeypatch: pytest.MonkeyPatch, given: dict[str, str], tmp_path: Path
) -> None:
    # the files it names exist (the command line checks them while it is read)
    monkeypatch.chdir(tmp_path)
    for key in ("knowledge", "config"):
        if key in given:
            (tmp_path / given[key]).write_text("")
    cmd = _commands(monkeypatch, **given)
    assert cmd[:3] == ["robocog", "bridge", "ros2"]
    parser = argparse.ArgumentParser()
    configure(parser)
    args = parser.parse_args(cmd[2:])
    assert args.mind == given.get("mind", "nars")
    assert args.watchdog == float(given.get("watchdog", "1.0"))
    if "knowledge" in given:
        assert str(args.program) == given["knowledge"]
    if "config" in given:
        assert str(args.config) == given["config"] and str(args.record) == given["record"]
    else:
        assert args.robot == "garbage"
