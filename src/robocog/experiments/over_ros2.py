"""The garbage missions with world and mind in separate processes, over ROS 2 (DDS).

This process serves the field as a ROS 2 robot (``robocog.sim.ros2``, lock-step: the
field steps when the controller has decided on a frame) and starts ``robocog bridge
ros2`` with the mind in a child process, on a domain of its own and on 127.0.0.1 only.
What a mission reports is read off the field, as in the in-process experiment, so the
two can be set side by side on the same seeds: every percept and every command then
crossed DDS as ROS 2 messages (LaserScan, Detection2DArray, PoseWithCovarianceStamped,
NavigateToPose and Grasp goals and results).
"""

from __future__ import annotations

import random
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from robocog.worlds.garbage import GarbageConfig, GarbageField

#: how long one mission may take on the wall clock before it is abandoned (s)
MISSION_TIMEOUT = 600.0


@dataclass
class RemoteRun:
    """One mission over ROS 2: what the field reports, and how long it took."""

    seed: int
    objects: int
    collected: int
    frames: int
    goals: int
    sim_seconds: float
    wall_seconds: float
    bridge_exit: int | None
    error: str | None = None
    #: the bridge's watchdog events (a run they touched is no longer the same run)
    watchdog_trips: int = 0

    @property
    def rate(self) -> float:
        """Share of the placed objects that ended in the trailer."""
        return self.collected / self.objects if self.objects else 0.0


def random_domain() -> int:
    """A DDS domain (1..230) picked at random: other runs may share this machine."""
    return random.SystemRandom().randrange(1, 231)


def bridge_argv(domain: int, mind: str, seed: int, *options: str) -> list[str]:
    """The command line of a ``robocog bridge ros2`` process on the loopback, with the
    options a run adds; one place, so that every remote run starts its bridge alike."""
    return [
        sys.executable,
        "-m",
        "robocog.cli",
        "bridge",
        "ros2",
        "--loopback",
        "--domain",
        str(domain),
        "--mind",
        mind,
        "--seed",
        str(seed),
        *options,
    ]


def stop_bridge(bridge: subprocess.Popen[str]) -> None:
    """End a bridge process still running: asked first, killed after 10 s."""
    if bridge.poll() is None:
        bridge.terminate()
        try:
            bridge.wait(timeout=10)
        except subprocess.TimeoutExpired:
            bridge.kill()
            bridge.wait(timeout=10)


def run_mission(
    mind: str,
    config: GarbageConfig,
    seed: int,
    *,
    domain: int | None = None,
    record: Path | None = None,
    timeout: float = MISSION_TIMEOUT,
    make_world: Callable[[GarbageConfig, int], GarbageField] | None = None,
    serve: Callable[..., Any] | None = None,
) -> RemoteRun:
    """One mission of ``mind`` (``nars`` or ``bdi``) on the field of ``seed``, the mind
    in a ``robocog bridge ros2`` process and the field served from this one.

    ``make_world`` makes the field (the 2D one by default) and ``serve`` is the robot
    that serves it (``GarbageRobot``'s signature; the physical field's
    ``MujocoGarbageRobot``); the field runs on this thread."""
    from robocog.bridges.ros2.loopback import loopback_unless_configured
    from robocog.experiments.garbage import frame_budget
    from robocog.sim.ros2 import GarbageRobot

    loopback_unless_configured()
    domain = random_domain() if domain is None else domain
    world = (make_world or _field)(config, seed)
    serve = serve or GarbageRobot
    recorder = None
    if record is not None:
        from robocog.bridges.ros2.record import Recorder

        recorder = Recorder(record)
    robot = serve(
        world,
        domain,
        lockstep=True,
        max_frames=frame_budget(config),
        on_message=recorder.write if recorder is not None else None,
    )
    argv = bridge_argv(
        domain,
        mind,
        seed,
        "--robot",
        "garbage",
        "--lockstep",
        # lock-step: the field waits for the mind, so a long silence means a machine
        # too busy to schedule the bridge, not a lost robot; a trip would change the run
        "--watchdog",
        "30",
    )
    started = time.monotonic()
    bridge = subprocess.Popen(
        argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, start_new_session=True
    )
    error = None
    try:
        robot.run(until=lambda: bridge.poll() is not None or time.monotonic() - started > timeout)
        if bridge.poll() is not None:
            error = f"the bridge ended early ({bridge.returncode})"
        elif not world.done and robot.frames < (robot.max_frames or 0):
            error = f"abandoned after {timeout:g} s"
    finally:
        robot.close()
        if recorder is not None:
            recorder.close()
        stop_bridge(bridge)
        stderr = bridge.stderr.read() if bridge.stderr is not None else ""
        release = getattr(world, "close", None)
        if release is not None:
            release()  # a physical field's GL context
    if error and stderr:
        error += ": " + stderr.strip().splitlines()[-1][:300]
    # before the first frame the bridge's watchdog always holds the robot: not counted
    trips = [
        ln
        for ln in stderr.splitlines()
        if "watchdog: robot stopped" in ln and "no percepts from the robot yet" not in ln
    ]
    return RemoteRun(
        seed=seed,
        objects=len(world.objects()),
        collected=world.collected(),
        frames=robot.frames,
        goals=robot.goals,
        sim_seconds=world.time(),
        wall_seconds=time.monotonic() - started,
        bridge_exit=bridge.returncode,
        error=error,
        watchdog_trips=len(trips),
    )


def _field(config: GarbageConfig, seed: int) -> GarbageField:
    return GarbageField(config, seed=seed)


def pooled(runs: list[RemoteRun]) -> float | None:
    """Objects collected over objects placed, pooled over the runs."""
    placed = sum(r.objects for r in runs)
    return sum(r.collected for r in runs) / placed if placed else None
