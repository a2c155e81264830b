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

Two more measures run after it. The NavigateToPose round trip: ``GoTo("next")`` through
a ``RobotBody`` over DDS to the garbage field served by ``robocog.sim.ros2`` in lock-step
(the goal answers as soon as the field has moved), beside the same GoTos called on a
field in this process. And the real-time factor of whole garbage missions with world
and mind in two processes over DDS (``robocog experiment garbage --over ros2``: simulated
seconds over wall seconds, the bridge's start-up included), beside the same missions in
one process.
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


def navigate_round_trips(domain: int, trials: int) -> tuple[list[float], list[float], int]:
    """Seconds per ``GoTo("next")`` over DDS to a lock-step sim and in this process, and
    how many of the goals over DDS succeeded."""
    from robocog.bridges.body import RobotBody
    from robocog.bridges.config import BridgeConfig
    from robocog.bridges.ros2.link import Ros2Link
    from robocog.robot.commands import GoTo
    from robocog.sim.ros2 import GarbageRobot
    from robocog.worlds.garbage import GarbageConfig, GarbageField

    field = GarbageConfig()
    robot = GarbageRobot(GarbageField(field, seed=0), domain, lockstep=True)
    server = threading.Thread(target=robot.run, name="sim", daemon=True)
    server.start()
    config = BridgeConfig.preset("garbage")
    body = RobotBody(Ros2Link(config, domain), config).start()
    over: list[float] = []
    succeeded = 0
    try:
        body.execute(GoTo("next"))  # the first goal waits for discovery: not timed
        for _ in range(trials):
            start = time.perf_counter()
            outcome = body.execute(GoTo("next"))
            over.append(time.perf_counter() - start)
            succeeded += outcome.ok
    finally:
        body.close()
        robot.close()
    world = GarbageField(field, seed=0)
    world.execute(GoTo("next"))
    local: list[float] = []
    for _ in range(trials):
        start = time.perf_counter()
        world.execute(GoTo("next"))
        local.append(time.perf_counter() - start)
    return over, local, succeeded


def real_time_factors(minds: list[str], seeds: int) -> list[tuple[str, int, float, float]]:
    """(mind, seed, real-time factor over DDS, in one process) per mission."""
    from robocog.experiments.garbage import default_minds, run_once
    from robocog.experiments.over_ros2 import random_domain, run_mission
    from robocog.worlds.garbage import GarbageConfig

    rows = []
    config = GarbageConfig()
    for spec, mind in zip(default_minds(minds), minds, strict=True):
        for seed in range(seeds):
            remote = run_mission(mind, config, seed, domain=random_domain())
            if remote.error:
                raise RuntimeError(f"{mind} seed {seed} over ROS 2: {remote.error}")
            start = time.perf_counter()
            local = run_once(spec, config, seed)
            wall = time.perf_counter() - start
            rows.append(
                (mind, seed, remote.sim_seconds / remote.wall_seconds, local.sim_seconds / wall)
            )
    return rows


def main(argv: list[str] | None = None) -> int:
    """Run the trials and print (and optionally write) the latency figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=200)
    parser.add_argument(
        "--goals", type=int, default=20, help="NavigateToPose round trips (the field ends after 21)"
    )
    parser.add_argument("--missions", type=int, default=2, help="missions per mind (RTF)")
    parser.add_argument("--minds", default="nars,bdi", help="minds of the RTF missions")
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
    report: dict[str, object] = {"results": results, "p50_ratio": ratio}

    if args.goals:
        over, local, ok = navigate_round_trips(base + 2, args.goals)
        report["navigate"] = {
            "goals": args.goals,
            "succeeded": ok,
            "dds_p50_ms": percentile(over, 50) * 1e3,
            "dds_p99_ms": percentile(over, 99) * 1e3,
            "in_process_p50_ms": percentile(local, 50) * 1e3,
        }
        print()
        print('NavigateToPose round trip (GoTo("next") to a lock-step sim, result included)')
        print(
            f"over DDS: p50 {percentile(over, 50) * 1e3:.2f} ms, "
            f"p99 {percentile(over, 99) * 1e3:.2f} ms ({ok}/{args.goals} succeeded); "
            f"in process: p50 {percentile(local, 50) * 1e3:.3f} ms"
        )

    if args.missions:
        minds = [m.strip() for m in args.minds.split(",") if m.strip()]
        rows = real_time_factors(minds, args.missions)
        report["real_time_factor"] = [
            {"mind": mind, "seed": seed, "over_ros2": r, "in_process": q}
            for mind, seed, r, q in rows
        ]
        print()
        print("real-time factor of whole garbage missions (simulated s / wall s)")
        print(f"{'mind':6} {'seed':>4} {'over ROS 2':>11} {'in process':>11}")
        for mind, seed, r, q in rows:
            print(f"{mind:6} {seed:>4} {r:10.0f}x {q:10.0f}x")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as handle:
            json.dump(report, handle, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
