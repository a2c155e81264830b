"""``robocog train detector``: train the physical garbage field's bottle-and-cup detector.

The detector (:mod:`robocog.worlds.physics.trash_detector`) learns from frames the
field renders itself, labelled by the renderer's segmentation; the model is cached in
the user's cache folder, so this runs once per machine (``--retrain`` does it again).
It reports the model's accuracy on held-out renders.
"""

from __future__ import annotations

import argparse
import json
import sys

from robocog.argtypes import NEW_FILE, SEED, int_range


def configure(parser: argparse.ArgumentParser) -> None:
    """``robocog train detector [options]``."""
    sub = parser.add_subparsers(dest="what", metavar="WHAT")
    p = sub.add_parser("detector", help="the garbage field's bottle-and-cup detector")
    renders = int_range(3, 10_000)
    p.add_argument("--frames", type=renders, default=96, help="training renders (default 96)")
    p.add_argument("--held-out", type=renders, default=32, help="held-out renders (default 32)")
    p.add_argument("--seed", type=SEED, default=0, help="seed of the renders and the network")
    p.add_argument("--retrain", action="store_true", help="train even if a model is cached")
    p.add_argument("--json", type=NEW_FILE, metavar="FILE", help="write the report as JSON")


def run(args: argparse.Namespace) -> int:
    """Train (or find the cached model) and print its held-out accuracy."""
    if getattr(args, "what", None) != "detector":
        print("robocog train: name what to train: detector", file=sys.stderr)
        return 2
    try:
        from robocog.worlds.physics import trash_detector as td
    except ImportError as exc:
        print(f"robocog train: needs the physics extra ({exc})", file=sys.stderr)
        return 2
    settings = td.TrainingSettings(frames=args.frames, held_out=args.held_out, seed=args.seed)
    path = td.model_path(settings)

    def progress(stage: str, n: int, total: int) -> None:
        print(f"\r{stage}: {n}/{total} frames", end="", file=sys.stderr, flush=True)

    _detector, report = td.load_or_train(settings, progress=progress, retrain=args.retrain)
    print(file=sys.stderr)
    if report is None:
        saved = path.with_suffix(".json")
        doc = json.loads(saved.read_text()) if saved.exists() else {}
        print(f"cached model: {path}")
    else:
        doc = report.as_dict()
        print(f"trained: {path}")
    if doc:
        print(
            f"held-out renders: {doc['frames']}; objects found {doc['found']}/{doc['objects']}"
            f" (recall {doc['recall']:.1%}), labels right {doc['label_accuracy']:.1%}, "
            f"false positives {doc['false_positives']}, region classifier "
            f"{doc['region_accuracy']:.1%}"
        )
        for light, (found, total) in sorted(doc.get("per_light", {}).items()):
            print(f"  {light:8} {found}/{total}")
    if args.json is not None:
        args.json.write_text(json.dumps({"model": str(path), **doc}, indent=2))
    return 0
