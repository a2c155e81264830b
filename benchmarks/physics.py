"""The physical tabletop's speed, and how often PlannerMind recovers from a moved cube.

``python benchmarks/physics.py`` runs the ``tables`` assembly sequence (Tables
5.2-5.10) once on the MuJoCo tabletop and reports:

* the real-time factor of the physics alone (simulated seconds per wall second spent
  stepping, without rendering), and of the whole run with PlannerMind, where the two
  cameras render and the detector runs only when the mind looks (once per command);
* the wall time per rendered camera frame (1280 x 960, offscreen) and per detection.

``--field garbage`` measures the physical garbage field instead
(:mod:`robocog.worlds.mujoco_garbage`): the robot drives its route for ``--seconds``
of simulated time with the camera rendering 640 x 480 frames at 4 a second (through
the sensor model), the learned detector running at 10 Hz on the latest frame and the
lidar casting its 360 rays at 10 Hz (with the localiser matching every scan), and
reports the real-time factor of the whole beside the cost of a frame, a detection and
a scan, and the physics alone.

``--perturb-runs N`` then runs the sequence with ``--perturb`` for seeds 1..N (one of
a request's cubes moved by hand in one request) and counts the runs in which every
table's goal held in the simulator afterwards.

``--room-runs N`` (default 3) runs the Q.bo of Fujita et al. in the physical room
(``room-exit --world mujoco``, the plans of Figs. 6-8 in the AgentSpeak interpreter)
for seeds 1..N and reports the real-time factor of the whole runs (physics, the head
camera's renders, the SVMs and the mind) and of the physics alone. ``--only room`` or
``--only tabletop`` runs one of the two.
"""

from __future__ import annotations

import argparse
import os
import time

import robocog.worlds.physics  # noqa: F401  (chooses the GL backend before mujoco loads)
from robocog.experiments.assembly import make_world, run_sequence


def speed(seed: int) -> dict[str, float]:
    """One clean run of the tables sequence, timed by part."""
    world = make_world("mujoco", seed, 0.0)
    steps_before = world.physics_steps
    start, cpu = time.perf_counter(), time.process_time()
    run = run_sequence("tables", seed, 0.0, world_kind="mujoco", world=world)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    steps = world.physics_steps - steps_before
    # the physics alone: the same number of steps again, nothing rendered
    import mujoco

    t = time.perf_counter()
    mujoco.mj_step(world.model, world.data, nstep=steps)
    physics_wall = time.perf_counter() - t
    sim = steps * world.model.opt.timestep
    frames, looks = world.eyes.frames, world.looks
    out = {
        "reached": float(run.reached),
        "sim_seconds": sim,
        "wall_seconds": wall,
        "cpu_seconds": cpu,
        "rtf_run": sim / wall,
        "rtf_physics": sim / physics_wall,
        "looks": looks,
        "frames": frames,
        "ms_per_frame": 1e3 * world.eyes.render_seconds / frames,
        "ms_per_detection": 1e3 * world.eyes.detect_seconds / frames,
    }
    world.close()
    return out


def room_speed(runs: int) -> dict[str, float]:
    """Runs of the physical room, timed; then their physics steps again, unrendered."""
    import mujoco

    from robocog.experiments.room_exit import run_once
    from robocog.worlds.mujoco_room import MujocoRoom
    from robocog.worlds.physics.room_vision import shared_classifier

    shared_classifier()  # fitted once per process, before the clock starts
    sim = wall = 0.0
    left = through = 0
    for seed in range(1, runs + 1):
        result = run_once(seed, "bdi", world_kind="mujoco", keep_route=False)
        sim += result.sim_seconds
        wall += result.wall_seconds
        left += result.physical_outcome == "left the room"
        through += result.exited
    world = MujocoRoom(0)
    steps = round(sim / world.model.opt.timestep)
    t = time.perf_counter()
    mujoco.mj_step(world.model, world.data, nstep=steps)
    physics_wall = time.perf_counter() - t
    world.close()
    return {
        "runs": runs,
        "left": left,
        "through": through,
        "sim_seconds": sim,
        "wall_seconds": wall,
        "rtf_run": sim / wall,
        "rtf_physics": sim / physics_wall,
    }


def garbage_field(seed: int, seconds: float) -> dict[str, float]:
    """The physical garbage field driving its route with every sensor at its rate."""
    from robocog.worlds.garbage import GarbageConfig
    from robocog.worlds.mujoco_garbage import MujocoGarbageField
    from robocog.worlds.physics.mobile_base import steer
    from robocog.worlds.physics.trash_detector import load_or_train

    detector, _ = load_or_train()
    world = MujocoGarbageField(GarbageConfig(), seed=seed, detector=detector)
    dt = world.model.opt.timestep
    steps = int(seconds / dt)
    frame_every = int(round(0.25 / dt))
    detect_every = int(round(0.1 / dt))
    route = [world.checkpoints[p] for p in world.route]
    leg = 0
    image = None
    t0 = time.perf_counter()
    for i in range(steps):
        v, w, arrived = steer(world.base.estimate, route[leg % len(route)], world.spec)
        if arrived:
            leg += 1
        world.drive(v, w)
        world.step()
        if i % frame_every == 0:
            image = world.render()
        if i % detect_every == 0 and image is not None:
            world.detect(image)
    wall = time.perf_counter() - t0
    c = world.costs
    import mujoco

    t = time.perf_counter()
    mujoco.mj_step(world.model, world.data, nstep=steps)
    physics = time.perf_counter() - t
    world.close()
    return {
        "sim_seconds": steps * dt,
        "wall_seconds": wall,
        "rtf": steps * dt / wall,
        "rtf_physics": steps * dt / physics,
        "frames": c.frames,
        "ms_per_frame": 1e3 * c.render_seconds / max(1, c.frames),
        "detections": c.detections,
        "ms_per_detection": 1e3 * c.detect_seconds / max(1, c.detections),
        "scans": c.scans,
        "ms_per_scan": 1e3 * c.scan_seconds / max(1, c.scans),
        "legs": leg,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--perturb-runs", type=int, default=0)
    parser.add_argument("--room-runs", type=int, default=3)
    parser.add_argument("--only", choices=("room", "tabletop"))
    parser.add_argument("--field", choices=("tabletop", "garbage"), default="tabletop")
    parser.add_argument("--seconds", type=float, default=60.0, help="garbage: simulated s")
    args = parser.parse_args()
    print(f"MUJOCO_GL={os.environ.get('MUJOCO_GL')}, load average {os.getloadavg()[0]:.1f}")
    if args.field == "garbage":
        g = garbage_field(args.seed, args.seconds)
        print(
            f"garbage field: {g['sim_seconds']:.0f} s simulated in {g['wall_seconds']:.1f} s "
            f"wall: real-time factor {g['rtf']:.2f} with the camera at 4 fps "
            f"({g['frames']:.0f} frames, {g['ms_per_frame']:.0f} ms each), the detector at "
            f"10 Hz ({g['detections']:.0f}, {g['ms_per_detection']:.1f} ms each), the lidar "
            f"at 10 Hz ({g['scans']:.0f} scans of 360 rays, {g['ms_per_scan']:.2f} ms each); "
            f"physics alone {g['rtf_physics']:.0f}x real time; {g['legs']:.0f} legs driven"
        )
        return
    if args.only != "tabletop" and args.room_runs > 0:
        r = room_speed(args.room_runs)
        print(
            f"Q.bo room: {r['runs']:.0f} runs ({r['left']:.0f} left the room, "
            f"{r['through']:.0f} through the doorway), "
            f"{r['sim_seconds']:.0f} s simulated in {r['wall_seconds']:.1f} s wall: "
            f"real-time factor {r['rtf_run']:.1f}; physics alone {r['rtf_physics']:.0f}x "
            "real time"
        )
    if args.only == "room":
        return
    s = speed(args.seed)
    print(
        f"tables sequence: reached {bool(s['reached'])}; {s['sim_seconds']:.0f} s simulated in "
        f"{s['wall_seconds']:.1f} s wall ({s['cpu_seconds']:.1f} s CPU): real-time factor "
        f"{s['rtf_run']:.1f} with {s['looks']:.0f} looks ({s['frames']:.0f} frames); physics "
        f"alone {s['rtf_physics']:.0f}x real time; {s['ms_per_frame']:.0f} ms per rendered "
        f"frame, {s['ms_per_detection']:.0f} ms per detection"
    )
    if args.perturb_runs:
        ok = 0
        for seed in range(1, args.perturb_runs + 1):
            t = time.perf_counter()
            run = run_sequence("tables", seed, 0.0, world_kind="mujoco", perturb=True)
            moved = [r for r in run.requests if r.perturbed]
            replans = sum(r.record.replans for r in run.requests)
            ok += run.reached
            failed = [r.table for r in run.requests if not r.reached]
            if run.stopped:
                failed.append(f"stopped at {run.stopped}")
            print(
                f"seed {seed}: {'every table reached' if run.reached else f'NOT reached: {failed}'}"
                f"; {moved[0].table + ': ' + str(moved[0].perturbed) if moved else 'nothing moved'}"
                f"; {replans} replans; {time.perf_counter() - t:.0f} s",
                flush=True,
            )
        print(f"--perturb: {ok}/{args.perturb_runs} runs reached every table")


if __name__ == "__main__":
    main()
