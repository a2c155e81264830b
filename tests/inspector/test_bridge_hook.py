"""The inspector on a bridge's runner: a robot behind ROS, here a fake link."""

from __future__ import annotations

import threading
from dataclasses import replace

from robocog.bridges.body import RobotBody
from robocog.bridges.config import BridgeConfig
from robocog.bridges.perception import PoseReading, ScanReading
from robocog.bridges.runner import BridgeRunner
from robocog.inspector.hub import Inspector
from robocog.minds.bdi_mind import BdiMind
from tests.bridges.fakes import FakeLink


def test_a_bridge_runner_is_watched_and_instructed_like_a_loop() -> None:
    config = replace(
        BridgeConfig.preset("garbage"),
        watchdog_seconds=0.5,
        cycle_period=0.02,
        command_rate=50.0,
        lockstep=False,
    )
    body = RobotBody(FakeLink(), config).start()
    stop = threading.Event()

    def driver() -> None:  # a robot's driver: a scan and a pose every 20 ms
        x = 1.0
        while not stop.wait(0.02):
            body.on_scan(ScanReading(0.8, 0.0, 0.1, 10.0, [5.0]))
            body.on_pose(PoseReading(x, 2.0, 0.5))
            x += 0.01

    feeding = threading.Thread(target=driver, daemon=True)
    feeding.start()
    mind = BdiMind("ready.\n")  # an agent that only listens: the robot stays put
    runner = BridgeRunner(body, mind)
    ins = Inspector(world_budget=None)
    runner.on_cycle = ins.watch(body, mind, runner, "ros2 bridge, mind bdi")
    ins.submit("belief", "visited(p9)")
    try:
        assert runner.run(duration=1.0) == 0
    finally:
        stop.set()
        feeding.join()
        body.close()
    first, last = ins.history.bounds()
    assert last - first >= runner.cycles
    snap = ins.history.latest()
    world = snap.world
    assert world["kind"] == "generic" and world["name"] == "RobotBody"
    assert world["robot"]["y"] == 2.0 and world["robot"]["x"] > 1.0
    assert len(world["trajectory"]) > 2
    assert {p["name"] for p in world["places"]} >= {"p0", "p1"}
    assert snap.run == "ros2 bridge, mind bdi"
    assert ins.console_entries()[0]["status"] == "ok"
    assert mind.beliefs("visited") == ["visited(p9)[source(self)]"]
    assert snap.mind["kind"] == "bdi"
