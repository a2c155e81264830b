"""The physical tabletop's speed, and how often PlannerMind recovers from a moved cube.

``python benchmarks/physics.py`` runs the ``tables`` assembly sequence (Tables
5.2-5.10) once on the MuJoCo tabletop and reports:

* the real-time factor of the physics alone (simulated seconds per wall second spent
  stepping, without rendering), and of the whole run with PlannerMind, where the two
  cameras render and the detector runs only when the mind looks (once per command);
* the wall time per rendered camera frame (1280 x 960, offscreen) and per detection.

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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--perturb-runs", type=int, default=0)
    parser.add_argument("--room-runs", type=int, default=3)
    parser.add_argument("--only", choices=("room", "tabletop"))
    args = parser.parse_args()
    print(f"MUJOCO_GL={os.environ.get('MUJOCO_GL')}, load average {os.getloadavg()[0]:.1f}")
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
