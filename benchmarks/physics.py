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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--perturb-runs", type=int, default=0)
    args = parser.parse_args()
    print(f"MUJOCO_GL={os.environ.get('MUJOCO_GL')}, load average {os.getloadavg()[0]:.1f}")
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
