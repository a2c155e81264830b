"""The physical room's runs with the robot and the mind in separate processes, over ROS 2.

This process serves the Q.bo's room (:mod:`robocog.sim.room`: head camera images, a
Range per ultrasonic sensor, odometry, tf, joint states; cmd_vel and the head's pan in)
and starts ``robocog bridge ros2 --mind qbo`` in a child process, on a DDS domain of
its own and on 127.0.0.1 only. The bridge's Q.bo body looks by turning the head and
classifying the images it receives, and drives by velocity until its odometry or its
ultrasonic readings say to stop, so every percept and command crosses DDS as a ROS 2
message. Where the robot ended is read off the simulator.
"""

from __future__ import annotations

import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from robocog.experiments.over_ros2 import bridge_argv, random_domain, stop_bridge

#: simulated seconds one run may take (the in-process runs take 65-90)
SIM_LIMIT = 200.0
#: the simulator's speed against the wall clock
RATE = 4.0


@dataclass
class RemoteRoomRun:
    """One run over ROS 2: where the robot ended, and how long it took."""

    seed: int
    outcome: str  # "left the room", "in the doorway", "in the room"
    x: float
    y: float
    sim_seconds: float
    wall_seconds: float
    images: int
    bridge_exit: int | None
    error: str | None = None
    record: str | None = None


def run_over_ros2(
    seed: int,
    *,
    record: Path | None = None,
    rate: float = RATE,
    sim_limit: float = SIM_LIMIT,
    domain: int | None = None,
) -> RemoteRoomRun:
    """One run of the Q.bo mind on the room of ``seed``, the mind in a bridge process."""
    from robocog.bridges.ros2.loopback import loopback_unless_configured
    from robocog.sim.room import QboRoomRobot
    from robocog.worlds.mujoco_room import MujocoRoom

    loopback_unless_configured()
    domain = random_domain() if domain is None else domain
    world = MujocoRoom(seed)
    recorder = None
    if record is not None:
        from robocog.bridges.ros2.record import Recorder

        record.parent.mkdir(parents=True, exist_ok=True)
        recorder = Recorder(record)
    robot = QboRoomRobot(
        world, domain, rate=rate, on_message=recorder.write if recorder is not None else None
    )
    argv = bridge_argv(domain, "qbo", seed, "--watchdog", "30")
    started = time.monotonic()
    error = None
    with tempfile.TemporaryFile("w+") as log:
        bridge = subprocess.Popen(
            argv, stdout=subprocess.DEVNULL, stderr=log, text=True, start_new_session=True
        )
        try:
            robot.run(
                until=lambda: (
                    world.exited() or world.time() >= sim_limit or bridge.poll() is not None
                )
            )
            if bridge.poll() is not None:
                error = f"the bridge ended early ({bridge.returncode})"
        finally:
            robot.close()
            if recorder is not None:
                recorder.close()
            stop_bridge(bridge)
            log.seek(0)
            lines = log.read().strip().splitlines()
    if error and lines:
        error += ": " + lines[-1][:300]
    if world.exited():
        outcome = "left the room"
    elif world.at_entrance():
        outcome = "in the doorway"
    else:
        outcome = "in the room"
    run = RemoteRoomRun(
        seed=seed,
        outcome=outcome,
        x=world.x,
        y=world.y,
        sim_seconds=world.time(),
        wall_seconds=time.monotonic() - started,
        images=robot.images,
        bridge_exit=bridge.returncode,
        error=error,
        record=str(record) if record is not None else None,
    )
    world.close()
    return run
