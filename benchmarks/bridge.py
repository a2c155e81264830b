"""Percept-to-command latency of the ROS 2 bridge over Cyclone DDS on 127.0.0.1.

A stand-in robot publishes clear laser scans, then one with an obstacle on the left,
and times how long it takes until the turn comes back on ``/cmd_vel``: DDS delivery to
the bridge, the scan becoming an Obstacle percept, a reflex mind deciding to turn, the
Turn becoming a Twist, and DDS delivery back. The bridge runs in its own process, as it
would beside a robot.

In the same run the peer is the floor under any bridge: a bare Cyclone DDS node in its
own process that answers each scan with a Twist as soon as it arrives (no percepts, no
mind, no body). The ratio says what robocog's bridge adds on top of DDS itself.

    python benchmarks/bridge.py                  # 200 trials each
    python benchmarks/bridge.py --trials 1000 --json bridge.json
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing
import os
import threading
import time
from collections.abc import Sequence

from robocog.bridges.ros2.loopback import use_loopback
from robocog.robot.commands import Command, Outcome, Turn
from robocog.robot.loop import percentile
from robocog.robot.percepts import Obstacle, Percept


class TurnAway:
    """The reflex under test: turn right from an obstacle on the left, else stay."""

    def __init__(self) -> None:
        self.obstacle: str = "none"

    def perceive(self, percepts: Sequence[Percept]) -> None:
        """Keep only the obstacle sector: the cheapest mind, so the bridge is measured."""
        self.obstacle = next((p.sector for p in percepts if isinstance(p, Obstacle)), "none")

    def decide(self) -> list[Command]:
        """Turn away from an obstacle on the left: the command whose latency is timed."""
        return [Turn(-0.3)] if self.obstacle == "left" else []

    def on_outcome(self, command: Command, outcome: Outcome) -> None:
        """Outcomes change nothing for this mind."""


def run_bridge(domain: int, seconds: float) -> None:
    """The bridge process: RobotBody over Ros2Link, driven by TurnAway."""
    use_loopback()
    from robocog.bridges.body import RobotBody
    from robocog.bridges.config import BridgeConfig
    from robocog.bridges.ros2.link import Ros2Link
    from robocog.bridges.runner import BridgeRunner

    # a fast turn (5 ms) so that one trial's motion is over before the next begins
    config = BridgeConfig(angular_speed=60.0, command_rate=200.0, watchdog_seconds=5.0)
    body = RobotBody(Ros2Link(config, domain), config).start()
    try:
        BridgeRunner(body, TurnAway()).run(duration=seconds)
    finally:
        body.close()


def run_echo(domain: int, seconds: float) -> None:
    """The peer process: bare DDS, a Twist straight back for every scan with a return."""
    use_loopback()
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.pub import DataWriter
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic
    from cyclonedds.util import duration

    from robocog.bridges.ros2 import messages as m
    from robocog.bridges.ros2.link import RELIABLE, SENSOR

    dp = DomainParticipant(domain)
    scans = DataReader(dp, Topic(dp, "rt/scan", m.LaserScan, qos=RELIABLE), qos=SENSOR)
    cmd = DataWriter(dp, Topic(dp, "rt/cmd_vel", m.Twist, qos=RELIABLE), qos=RELIABLE)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        for scan in scans.take_iter(timeout=duration(milliseconds=100)):
            if any(math.isfinite(r) for r in scan.ranges):
                cmd.write(m.Twist(m.Vector3(), m.Vector3(z=-1.0)))
            break


def measure(kind: str, domain: int, trials: int) -> list[float]:
    """Start the process under test, then time ``trials`` scan-to-twist round trips."""
    from robocog.testing.ros2_standin import StandInRobot, scan_of

    target = run_bridge if kind == "robocog" else run_echo
    ctx = multiprocessing.get_context("spawn")
    budget = 20.0 + trials * 0.2
    proc = ctx.Process(target=target, args=(domain, budget), daemon=True)
    proc.start()
    turned = threading.Event()

    def on_event(event: dict[str, object]) -> None:
        if event["event"] == "cmd_vel" and float(event["angular"]) < 0:  # type: ignore[arg-type]
            turned.set()

    robot = StandInRobot(domain, on_event=on_event)
    robot.start(rate=None)  # only listens; the scans below are written by hand
    clear, blocked = scan_of(None), scan_of((0.9, 1.0))
    samples: list[float] = []
    try:
        # wait for the two processes to find each other
        deadline = time.monotonic() + 30
        while not turned.is_set():
            if time.monotonic() > deadline:
                raise RuntimeError(f"{kind}: no answer to a scan within 30 s")
            robot.scan_writer.write(blocked)
            time.sleep(0.05)
        for _ in range(trials):
            for _ in range(3):  # clear scans: the reflex goes quiet
                robot.scan_writer.write(clear)
                time.sleep(0.01)
            time.sleep(0.02)
            turned.clear()
            start = time.perf_counter()
            robot.scan_writer.write(blocked)
            if turned.wait(2.0):
                samples.append(time.perf_counter() - start)
            time.sleep(0.01)
    finally:
        robot.close()
        proc.terminate()
        proc.join(5)
    return samples


def main(argv: list[str] | None = None) -> int:
    """Run the trials and print (and optionally write) the latency figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=200)
    parser.add_argument("--json", help="write the figures to this file")
    args = parser.parse_args(argv)
    use_loopback()
    base = 1 + (os.getpid() * 7) % 180
    results: dict[str, dict[str, float]] = {}
    for offset, kind in enumerate(("robocog", "dds-echo")):
        samples = measure(kind, base + offset, args.trials)
        results[kind] = {
            "trials": float(args.trials),
            "answered": float(len(samples)),
            "p50_ms": percentile(samples, 50) * 1e3,
            "p99_ms": percentile(samples, 99) * 1e3,
        }
    ours, peer = results["robocog"], results["dds-echo"]
    ratio = ours["p50_ms"] / peer["p50_ms"] if peer["p50_ms"] else math.inf
    print("percept-to-command latency over Cyclone DDS on 127.0.0.1 (scan -> cmd_vel)")
    print(f"{'':10} {'answered':>9} {'p50 ms':>8} {'p99 ms':>8}")
    for kind, r in results.items():
        print(
            f"{kind:10} {int(r['answered']):>5}/{int(r['trials']):<3} "
            f"{r['p50_ms']:8.3f} {r['p99_ms']:8.3f}"
        )
    print(f"robocog / bare DDS at p50: {ratio:.2f}x")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as handle:
            json.dump({"results": results, "p50_ratio": ratio}, handle, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
