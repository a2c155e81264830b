"""`robocog bridge`: arguments, configuration, and how a mind is found."""

from __future__ import annotations

import argparse
import re
import subprocess
from pathlib import Path

import pytest

from robocog.bridges import cli
from robocog.bridges.config import BridgeConfig
from tests.bridges.procs import bridge_argv, child_env
from tests.bridges.reflex import ReflexMind


def parse(*argv: str) -> argparse.Namespace:
    parser = argparse.ArgumentParser()
    cli.configure(parser)
    return parser.parse_args(list(argv))


def test_places_topics_and_limits_come_from_the_file_and_the_command_line(
    tmp_path: Path,
) -> None:
    config_file = tmp_path / "robot.toml"
    config_file.write_text(
        'pose_source = "odom"\nwatchdog_seconds = 0.5\n'
        '[topics]\nscan = "/front/scan"\n[places]\ndock = [0, 0]\nbin = [1, 2, 3]\n'
    )
    args = parse(
        "ros2",
        "--config",
        str(config_file),
        "--place",
        "door=4,5",
        "--topic",
        "cmd_vel=/robot/cmd_vel",
        "--watchdog",
        "2",
    )
    config = cli.build_config(args)
    assert config.places == {"dock": (0, 0, 0), "bin": (1, 2, 3), "door": (4, 5, 0)}
    assert config.topics.scan == "/front/scan"
    assert config.topics.cmd_vel == "/robot/cmd_vel"
    assert config.pose_source == "odom"
    assert config.watchdog_seconds == 2.0


@pytest.mark.parametrize(
    "argv",
    [
        ("--place", "door"),
        ("--place", "door=1"),
        ("--place", "door=1,nan"),
        ("--place", "door=1,2,inf"),
        ("--topic", "nothing=/x"),
        ("--topic", "scan"),
    ],
)
def test_bad_places_and_topics_are_named(argv: tuple[str, ...]) -> None:
    with pytest.raises(ValueError, match=argv[1]):
        cli.build_config(parse("ros2", *argv))


def test_unknown_configuration_keys_are_an_error(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text("watchdog = 1\n")
    with pytest.raises(ValueError, match="watchdog"):
        BridgeConfig.from_toml(bad)
    with pytest.raises(ValueError, match="place 'x'"):
        BridgeConfig.from_dict({"places": {"x": [1]}})


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("watchdog_seconds = -1.0", "watchdog_seconds must be above 0, not -1.0"),
        ("watchdog_seconds = nan", "watchdog_seconds must be a finite number"),
        ("linear_speed = inf", "linear_speed must be a finite number"),
        ('goto_timeout = "long"', "goto_timeout must be a number"),
        ("max_mind_failures = 0", "max_mind_failures must be above 0"),
        ("pose_timeout = -0.5", "pose_timeout must be 0 (not watched) or more"),
        ("horizontal_fov = 0.0", "horizontal_fov is an angle"),
        ("lockstep = 1", "lockstep must be true or false"),
        ('pose_source = "gps"', "pose_source is amcl or odom"),
        ("start = [0.0, nan]", "start must be finite numbers"),
        ("[places]\nk = [1.0, inf]", "place 'k' must be finite numbers"),
        ("watchdog_seconds = ", "not TOML"),
    ],
)
def test_a_bad_number_in_a_robots_file_is_named_with_the_file(
    tmp_path: Path, text: str, message: str
) -> None:
    bad = tmp_path / "robot.toml"
    bad.write_text(text + "\n")
    with pytest.raises(ValueError, match=re.escape(message)) as refused:
        BridgeConfig.from_toml(bad)
    assert str(refused.value).startswith(str(bad))
    BridgeConfig(pose_timeout=0.0, scan_timeout=None)  # 0 and None: not watched


def test_a_mind_is_found_by_module_and_factory(tmp_path: Path) -> None:
    config = BridgeConfig.preset("garbage")
    assert isinstance(cli.make_mind("tests.bridges.reflex:make", config), ReflexMind)
    source = tmp_path / "target.txt"
    source.write_text("cup")
    mind = cli.make_mind("tests.bridges.reflex:make", config, source)
    assert mind.target == "cup"  # the factory read the source from its MindConfig


@pytest.mark.parametrize(
    ("name", "message"),
    [
        ("marvin", "unknown mind"),
        ("tests.bridges.reflex:nothing", "has no nothing"),
        ("no_such_module_anywhere:make", "not available"),
    ],
)
def test_an_unusable_mind_is_a_clear_error(name: str, message: str) -> None:
    with pytest.raises(cli.MindUnavailable, match=message):
        cli.make_mind(name, BridgeConfig.preset("garbage"))


@pytest.mark.parametrize(("name", "kind"), [("nars", "NarsMind"), ("bdi", "BdiMind")])
def test_the_engines_minds_are_built_or_their_absence_explained(name: str, kind: str) -> None:
    config = BridgeConfig(places={"bin": (1.0, 0.0, 0.0)})
    try:
        mind = cli.make_mind(name, config)
    except cli.MindUnavailable as exc:
        assert "not available" in str(exc) or "could not start" in str(exc)
        pytest.skip(f"{kind} is not ready: {exc}")
    assert type(mind).__name__ == kind
    assert callable(mind.perceive) and callable(mind.decide)


def test_the_command_reports_an_unavailable_mind_and_exits_2() -> None:
    result = subprocess.run(
        bridge_argv("ros2", "--mind", "tests.bridges.reflex:nothing", "--loopback"),
        capture_output=True,
        text=True,
        env=child_env(),
        timeout=60,
    )
    assert result.returncode == 2
    assert "robocog bridge: mind 'tests.bridges.reflex:nothing' is not available" in result.stderr


def test_ros1_without_roscore_fails_with_a_reason(tmp_path: Path) -> None:
    from tests.bridges.conftest import _has_rospy
    from tests.bridges.procs import free_port

    if _has_rospy():
        pytest.skip(_has_rospy())
    env = child_env({"ROS_MASTER_URI": f"http://127.0.0.1:{free_port()}", "ROS_IP": "127.0.0.1"})
    env["ROS_HOME"] = str(tmp_path)
    result = subprocess.run(
        bridge_argv("ros1", "--mind", "tests.bridges.reflex:make"),
        capture_output=True,
        text=True,
        env=env,
        timeout=90,
    )
    assert result.returncode != 0
    assert "rospy node did not start: no ROS master at http://127.0.0.1:" in result.stderr


def test_the_ros1_node_keeps_ros_paths_but_not_robocogs_python(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import os
    import sys

    from robocog.bridges.ros1.link import _node_env

    src = Path(cli.__file__).resolve().parents[2]
    ros = "/opt/ros/noetic/lib/python3/dist-packages"
    site = str(Path(sys.prefix) / "lib" / "site-packages")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(src), ros, site]))
    monkeypatch.setenv("PYTHONHOME", sys.prefix)
    env = _node_env()
    assert env["PYTHONPATH"] == ros
    assert "PYTHONHOME" not in env
    monkeypatch.setenv("PYTHONPATH", str(src))
    assert "PYTHONPATH" not in _node_env()


def test_the_command_run_in_process_puts_the_sigterm_handler_back(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """While it runs, SIGTERM stops the bridge; once it returns, whatever handled
    SIGTERM before does again."""
    import signal

    from robocog.bridges.runner import BridgeRunner
    from tests.bridges.fakes import FakeLink

    stopped: list[bool] = []

    def run(runner: BridgeRunner, duration: float | None = None, **_: object) -> int:
        handler = signal.getsignal(signal.SIGTERM)
        assert callable(handler)
        handler(signal.SIGTERM, None)  # as the signal would call it
        return 0

    monkeypatch.setattr(cli, "_make_link", lambda args, config: FakeLink())
    monkeypatch.setattr(BridgeRunner, "run", run)
    monkeypatch.setattr(BridgeRunner, "stop", lambda runner: stopped.append(True))
    before = signal.getsignal(signal.SIGTERM)
    assert cli.run(parse("ros2", "--mind", "tests.bridges.reflex:make")) == 0
    assert stopped == [True]
    assert signal.getsignal(signal.SIGTERM) is before
