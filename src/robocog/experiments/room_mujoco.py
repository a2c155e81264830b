"""The physical room's own parts of ``robocog experiment room-exit --world mujoco``.

``--train-svm`` renders the SVMs' areas afresh and reports their scores; ``--over ros2``
runs each seed with the room served over ROS 2 and the Q.bo mind in a bridge process
(:mod:`robocog.experiments.room_over_ros2`).
"""

from __future__ import annotations

import argparse
from collections import Counter
from dataclasses import asdict
from pathlib import Path
from typing import Any

from robocog.atomic import write_json


def train_svm(args: argparse.Namespace, console: Any) -> int:
    """``--train-svm``: the physical room's classifiers trained again, and their scores."""
    import time

    try:
        from robocog.worlds.physics import room_vision
    except ImportError as exc:
        console.print(f"[red]the physical room needs the physics extra: {exc}[/red]")
        return 1
    started = time.perf_counter()
    classifier = room_vision.trained(refresh=True)
    console.print(
        f"SVM trained on {room_vision.TRAIN_IMAGES} renders (seed 0), scored on "
        f"{room_vision.TEST_IMAGES} held-out ones, in {time.perf_counter() - started:.0f} s; "
        f"cached in {room_vision.cache_dir()}"
    )
    for score in classifier.scores:
        console.print(score.line())
    if args.json:
        write_json(
            Path(args.json),
            {
                "experiment": "room-exit",
                "svm": [asdict(score) for score in classifier.scores],
                "cache": str(room_vision.cache_dir()),
            },
        )
    return 0


def over_ros2(args: argparse.Namespace, console: Any) -> int:
    """``--over ros2``: each seed's room served here, the Q.bo mind in a bridge process."""
    if getattr(args, "world", "2d") != "mujoco":
        console.print("[red]--over ros2 serves the physical room: add --world mujoco[/red]")
        return 2
    try:
        import sklearn  # noqa: F401

        from robocog.experiments.room_over_ros2 import run_over_ros2
        from robocog.worlds.physics.room_vision import shared_classifier
    except ImportError as exc:
        console.print(f"[red]--over ros2 needs the physics and ros2 extras: {exc}[/red]")
        return 2
    shared_classifier()  # trained (or read from the cache) before the bridge needs it
    runs = []
    for i in range(args.runs):
        seed = args.seed + i
        record = args.record / f"room_seed{seed}.mcap" if args.record else None
        run = run_over_ros2(seed, record=record)
        runs.append(run)
        console.print(
            f"seed {seed}: {run.outcome} at ({run.x:.2f}, {run.y:.2f}), "
            f"{run.sim_seconds:.0f} s simulated in {run.wall_seconds:.0f} s"
            + (f"; {run.error}" if run.error else "")
        )
    counts = Counter(r.outcome for r in runs)
    console.print(f"over ROS 2: {counts.get('left the room', 0)} of {len(runs)} runs left the room")
    if args.json:
        write_json(
            Path(args.json),
            {
                "experiment": "room-exit",
                "world": "mujoco",
                "over": "ros2",
                "seed": args.seed,
                "runs": args.runs,
                "outcomes": {
                    o: counts.get(o, 0) for o in ("left the room", "in the doorway", "in the room")
                },
                "results": [asdict(r) for r in runs],
            },
        )
    return 0 if all(r.error is None for r in runs) else 1
