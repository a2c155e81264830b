"""The garbage experiment on the physical field: Table II in MuJoCo, and Table I measured.

``robocog experiment garbage --world mujoco`` runs the same minds on
:class:`~robocog.worlds.mujoco_garbage.MujocoGarbageField` and measures Table I (the
detection rate under each light) from rendered frames: random fields seen from random
poses under the light, every object within the camera's range that shows at least
:data:`MIN_VISIBLE` pixels counts, and it is detected when a box of the detector
covers it. The paper's rates are printed beside the measured ones; nothing here or in
the field sets a rate.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

#: Hammer et al., Table I: detection rates of bottles and cups by light (for comparison)
PAPER_DETECTION: dict[str, float] = {"sunny": 0.83, "cloudy": 0.70, "evening": 0.61}
#: an object counts as in view when this many of its pixels show
MIN_VISIBLE = 20


@dataclass
class DetectionRate:
    """Objects in view and detected over the frames of one light."""

    light: str
    frames: int
    in_view: int
    detected: int
    labelled_right: int
    false_positives: int

    @property
    def rate(self) -> float:
        return self.detected / self.in_view if self.in_view else 0.0

    def as_dict(self) -> dict[str, Any]:
        return {
            "rate": round(self.rate, 4),
            "frames": self.frames,
            "in_view": self.in_view,
            "detected": self.detected,
            "label_accuracy": round(self.labelled_right / self.detected, 4)
            if self.detected
            else None,
            "false_positives": self.false_positives,
            "paper": PAPER_DETECTION.get(self.light),
        }


def measure_detection(
    detector: Any,
    frames: int = 300,
    seed: int = 1,
    lights: Sequence[str] = ("sunny", "cloudy", "evening"),
    camera_range: float = 5.0,
    progress: Callable[[str, int, int], None] | None = None,
) -> dict[str, DetectionRate]:
    """Table I measured: ``frames`` renders per light of random fields (the held-out
    kind: another seed than the detector's training), the same scenes and poses under
    every light."""
    from robocog.worlds.physics.trash_detector import render_frames, score_frame

    out: dict[str, DetectionRate] = {}
    for light in lights:
        shot = render_frames(
            frames,
            seed,
            lights=(light,),
            jitter=False,
            progress=(lambda n, li=light: progress(li, n, frames)) if progress else None,
        )
        in_view = detected = right = false_pos = 0
        for f in shot:
            boxes = detector.detect(f.image)
            score = score_frame(
                boxes,
                f,
                MIN_VISIBLE,
                lambda k, _n, f=f: not f.distances or f.distances[k] <= camera_range,
            )
            false_pos += score.false_positives
            in_view += len(score.wanted)
            detected += len(score.found)
            right += score.labelled_right
        out[light] = DetectionRate(light, len(shot), in_view, detected, right, false_pos)
    return out


def world_factory(
    detector: Any, physical: Any = None, film: list[Any] | None = None
) -> Callable[..., Any]:
    """Makes a physical field per mission, all sharing one detector; with ``film`` the
    first mission's camera frames are kept there (a quarter size, for a GIF)."""
    from robocog.worlds.mujoco_garbage import MujocoGarbageField

    made = [0]

    def make(config: Any, seed: int) -> Any:
        world = MujocoGarbageField(config, seed, physical=physical, detector=detector)
        if film is not None and made[0] == 0:
            world.on_frame = lambda image: film.append(image[::4, ::4].copy())
        made[0] += 1
        return world

    return make


def write_gif(frames: Sequence[Any], path: Any, seconds_per_frame: float = 0.25) -> None:
    """The frames of a mission as an animated GIF (at most 600 frames)."""
    import imageio.v2 as imageio

    path.parent.mkdir(parents=True, exist_ok=True)
    imageio.mimsave(path, list(frames)[:600], duration=seconds_per_frame, loop=0)
