"""A learned bottle-and-cup detector, trained on frames the garbage field renders itself.

Hammer et al.'s robot ran YOLOv4 on its camera. Here the detector is learned the same
way (from labelled images), only smaller, on what robocog can label for free: frames of
the physical field (:mod:`robocog.worlds.physics.field_scene`) rendered under the three
lights with random positions, poses and sun angles, the labels coming from the
renderer's segmentation (which geom each pixel shows). Two stages:

1. **Colour likelihood.** A 32-level-per-channel colour table of P(object | colour),
   counted over the training pixels (a histogram classifier, as skin detectors are):
   one lookup per pixel. Pixels over half are candidates; nearby candidates are joined
   (a small dilation) into regions.
2. **Region classifier.** Each region's shape, colour and likelihood statistics go
   through a small neural network (scikit-learn's ``MLPClassifier``, seeded) that says
   background, bottle or cup with a probability; a region whose best object class
   reaches ``min_confidence`` (0.5 by default; YOLOv4's detectors are run with such a
   floor) is a detection.

Nothing about the light is given to the detector: the light changes the pixels, and
the detection rate follows. The model is stored as plain arrays (``.npz``, read with
``allow_pickle=False``) in the user's cache folder, keyed by the training settings,
so it is trained once per machine (``robocog train detector``) and on first use.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

BINS = 32
CLASSES = ("background", "bottle", "cup")
#: region features, in order (see :func:`region_features`)
FEATURES = 14
#: a region needs this many pixels to be considered at all
MIN_PIXELS = 6
VERSION = 4


@dataclass(frozen=True)
class Box:
    """One detection: label, confidence and the pixel box ``(u0, v0, u1, v1)``."""

    label: str
    confidence: float
    u0: int
    v0: int
    u1: int
    v1: int

    @property
    def bottom_centre(self) -> tuple[float, float]:
        return (self.u0 + self.u1) / 2.0, float(self.v1)


@dataclass(frozen=True)
class TrainingSettings:
    """What a trained model depends on (its cache key)."""

    frames: int = 96
    held_out: int = 32
    seed: int = 0
    width: int = 640
    height: int = 480
    hidden: int = 32


@dataclass
class Report:
    """A model's accuracy on held-out renders."""

    frames: int
    objects: int
    found: int
    correct_label: int
    false_positives: int
    region_accuracy: float
    seconds: float
    per_light: dict[str, tuple[int, int]] = field(default_factory=dict)

    @property
    def recall(self) -> float:
        return self.found / self.objects if self.objects else 0.0

    @property
    def label_accuracy(self) -> float:
        return self.correct_label / self.found if self.found else 0.0

    def as_dict(self) -> dict[str, object]:
        out = asdict(self)
        out["recall"] = round(self.recall, 4)
        out["label_accuracy"] = round(self.label_accuracy, 4)
        return out


def cache_dir() -> Path:
    """The user's cache folder for robocog (the platform's: ~/.cache/robocog on Linux);
    ``ROBOCOG_CACHE`` overrides it."""
    override = os.environ.get("ROBOCOG_CACHE")
    if override:
        return Path(override)
    try:
        import platformdirs

        return Path(platformdirs.user_cache_dir("robocog"))
    except ImportError:  # the extra's dependency missing: the XDG default
        return Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "robocog"


def _quantise(image: np.ndarray) -> np.ndarray:
    q = (image[..., :3].astype(np.int32) * BINS) // 256
    return (q[..., 0] * BINS + q[..., 1]) * BINS + q[..., 2]


def _regions(likelihood: np.ndarray) -> tuple[np.ndarray, int]:
    from scipy import ndimage

    mask = likelihood > 0.5
    joined = ndimage.binary_dilation(mask, iterations=2)
    labels, count = ndimage.label(joined)
    labels[~mask] = 0
    return labels, count


def region_features(
    image: np.ndarray, likelihood: np.ndarray, labels: np.ndarray, count: int
) -> tuple[np.ndarray, list[tuple[int, int, int, int]], list[int]]:
    """Per region of at least :data:`MIN_PIXELS`: features, pixel boxes, region ids.

    Features: log area, log width, log height, height/width, fill of the box, mean and
    max likelihood, mean R, G, B over the frame's mean brightness, chroma spread, share
    of reddish and of bluish pixels, the box's bottom row over the image height.
    """
    from scipy import ndimage

    if count == 0:
        return np.zeros((0, FEATURES)), [], []
    slices = ndimage.find_objects(labels)
    brightness = float(image[..., :3].mean()) + 1.0
    feats, boxes, ids = [], [], []
    h = image.shape[0]
    for i, sl in enumerate(slices, start=1):
        if sl is None:
            continue
        region = labels[sl] == i
        area = int(region.sum())
        if area < MIN_PIXELS:
            continue
        pix = image[sl][region][:, :3].astype(np.float64)
        like = likelihood[sl][region]
        height = sl[0].stop - sl[0].start
        width = sl[1].stop - sl[1].start
        mean = pix.mean(axis=0)
        r, g, b = pix[:, 0], pix[:, 1], pix[:, 2]
        feats.append(
            [
                math.log(area),
                math.log(width),
                math.log(height),
                height / width,
                area / (width * height),
                float(like.mean()),
                float(like.max()),
                mean[0] / brightness,
                mean[1] / brightness,
                mean[2] / brightness,
                float(pix.std(axis=0).mean()) / brightness,
                float(((r > g + 40) & (r > b + 40)).mean()),
                float(((b > r + 40) & (b > g + 10)).mean()),
                sl[0].stop / h,
            ]
        )
        boxes.append((sl[1].start, sl[0].start, sl[1].stop - 1, sl[0].stop - 1))
        ids.append(i)
    return np.array(feats, dtype=np.float64), boxes, ids


class TrashDetector:
    """The trained detector: ``detect(image)`` gives :class:`Box` es."""

    def __init__(self, arrays: dict[str, np.ndarray], min_confidence: float = 0.5) -> None:
        self.table = arrays["table"].astype(np.float32)
        self.mean = arrays["mean"]
        self.scale = arrays["scale"]
        self.weights = [arrays[f"w{i}"] for i in range(int(arrays["layers"]))]
        self.biases = [arrays[f"b{i}"] for i in range(int(arrays["layers"]))]
        self.min_confidence = min_confidence
        self.seconds = 0.0
        self.frames = 0

    def likelihood(self, image: np.ndarray) -> np.ndarray:
        """P(object | colour) per pixel."""
        return self.table[_quantise(image)]

    def classify(self, features: np.ndarray) -> np.ndarray:
        """Class probabilities (background, bottle, cup) per feature row."""
        x = (features - self.mean) / self.scale
        for i, (w, b) in enumerate(zip(self.weights, self.biases, strict=True)):
            x = x @ w + b
            if i < len(self.weights) - 1:
                x = np.maximum(x, 0.0)
        x = x - x.max(axis=1, keepdims=True)
        e = np.exp(x)
        return e / e.sum(axis=1, keepdims=True)

    def detect(self, image: np.ndarray) -> list[Box]:
        """The bottles and cups in an RGB frame, most confident first."""
        start = time.perf_counter()
        like = self.likelihood(image)
        labels, count = _regions(like)
        feats, boxes, _ids = region_features(image, like, labels, count)
        out: list[Box] = []
        if len(feats):
            probs = self.classify(feats)
            for p, box in zip(probs, boxes, strict=True):
                k = 1 + int(np.argmax(p[1:]))
                if p[k] >= self.min_confidence:
                    out.append(Box(CLASSES[k], round(float(p[k]), 3), *box))
        out.sort(key=lambda b: -b.confidence)
        self.seconds += time.perf_counter() - start
        self.frames += 1
        return out

    def save(self, path: Path) -> None:
        arrays = {
            "table": self.table,
            "mean": self.mean,
            "scale": self.scale,
            "layers": np.array(len(self.weights)),
        }
        for i, (w, b) in enumerate(zip(self.weights, self.biases, strict=True)):
            arrays[f"w{i}"] = w
            arrays[f"b{i}"] = b
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".tmp.npz")
        np.savez_compressed(tmp, **arrays)
        os.replace(tmp, path)

    @classmethod
    def load(cls, path: Path, min_confidence: float = 0.5) -> TrashDetector:
        with np.load(path, allow_pickle=False) as data:
            return cls({k: data[k] for k in data.files}, min_confidence)


# ---- training data: frames of random fields, labelled by segmentation ------------------


@dataclass
class Frame:
    """One rendered frame with its labels: per object, label and pixel mask size/box."""

    image: np.ndarray
    object_of_pixel: np.ndarray  # -1 background, else index into labels
    labels: list[str]
    light: str
    #: each object's distance from the robot (metres)
    distances: list[float] = field(default_factory=list)


def _random_scene(
    rng: random.Random,
) -> tuple[list, tuple[float, float], dict[str, tuple[float, float]]]:
    """Objects scattered around a spot of the field, and two checkpoint markers."""
    from robocog.worlds.physics.field_scene import Placed

    cx, cy = rng.uniform(2.5, 19.5), rng.uniform(2.5, 19.5)
    objects = []
    for i in range(rng.randint(6, 12)):
        d = rng.uniform(0.0, 2.5)
        a = rng.uniform(-math.pi, math.pi)
        pose = rng.choices(("upright", "leaning", "lying"), (0.6, 0.2, 0.2))[0]
        objects.append(
            Placed(
                f"trash{i}",
                rng.choice(("bottle", "cup")),
                min(21.7, max(0.3, cx + d * math.cos(a))),
                min(21.7, max(0.3, cy + d * math.sin(a))),
                rng.uniform(-math.pi, math.pi),
                pose,
            )
        )
    markers = {f"m{i}": (cx + rng.uniform(-4, 4), cy + rng.uniform(-4, 4)) for i in range(2)}
    return objects, (cx, cy), markers


def render_frames(
    count: int,
    seed: int,
    width: int = 640,
    height: int = 480,
    lights: Sequence[str] = ("sunny", "cloudy", "evening"),
    jitter: bool = True,
    progress: Callable[[int], None] | None = None,
    per_scene: int = 6,
    camera: object | None = None,
) -> list[Frame]:
    """``count`` labelled frames of random fields, the lights taken in turn.

    Each scene (objects scattered round a spot, upright, leaning or lying) is seen from
    ``per_scene`` robot poses 0.8 to 6 m from the spot, looking roughly at it; each
    frame is rendered twice, in colour and as segmentation (which object each pixel
    shows). With ``jitter`` the sun's height, bearing and strength vary per frame.
    The colour frame goes through the camera's sensor model (``camera``, the field's
    :class:`~robocog.worlds.physics.field_scene.CameraModel` by default).
    """
    import mujoco

    from robocog.worlds.physics.field_scene import (
        CameraModel,
        field_xml,
        prepare_renderer,
        set_light,
    )

    sensor = camera if camera is not None else CameraModel()
    noise = np.random.default_rng(seed)
    rng = random.Random(seed)
    frames: list[Frame] = []
    while len(frames) < count:
        objects, (cx, cy), markers = _random_scene(rng)
        xml = field_xml(22.0, markers, objects, (cx - 3.0, cy, 0.0))
        model = mujoco.MjModel.from_xml_string(xml)
        data = mujoco.MjData(model)
        for _ in range(100):  # let leaning and lying objects settle
            mujoco.mj_step(model, data)
        names = [p.name for p in objects]
        geom_obj = np.full(model.ngeom + 1, -1, dtype=np.int32)
        for g in range(model.ngeom):
            body = model.body(int(model.geom_bodyid[g])).name
            if body in names:
                geom_obj[g] = names.index(body)
        body_ids = [model.body(n).id for n in names]
        free = model.joint("robot_free").qposadr[0]
        renderer = prepare_renderer(mujoco.Renderer(model, height, width))
        try:
            for _view in range(per_scene):
                if len(frames) >= count:
                    break
                light = lights[len(frames) % len(lights)]
                set_light(model, light, jitter=rng if jitter else None)
                d = rng.uniform(0.8, 6.0)
                a = rng.uniform(-math.pi, math.pi)
                x = min(21.6, max(0.4, cx + d * math.cos(a)))
                y = min(21.6, max(0.4, cy + d * math.sin(a)))
                theta = math.atan2(cy - y, cx - x) + rng.uniform(-0.45, 0.45)
                data.qpos[free : free + 7] = [
                    x,
                    y,
                    0.0,
                    math.cos(theta / 2),
                    0.0,
                    0.0,
                    math.sin(theta / 2),
                ]
                mujoco.mj_forward(model, data)
                renderer.disable_segmentation_rendering()
                renderer.update_scene(data, camera="camera")
                image = sensor.expose(renderer.render(), noise)  # type: ignore[attr-defined]
                renderer.enable_segmentation_rendering()
                renderer.update_scene(data, camera="camera")
                seg = renderer.render()
                ids = seg[..., 0].astype(np.int64)
                is_geom = seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM)
                ids = np.where(is_geom & (ids >= 0), ids, model.ngeom)
                distances = [math.hypot(data.xpos[b][0] - x, data.xpos[b][1] - y) for b in body_ids]
                frames.append(
                    Frame(image, geom_obj[ids], [p.label for p in objects], light, distances)
                )
                if progress:
                    progress(len(frames))
        finally:
            renderer.close()
    return frames


def match_boxes(
    boxes: list[tuple[int, int, int, int]], frame: Frame, min_pixels: int
) -> tuple[list[int], dict[int, int]]:
    """Per box: the object it shows (by most pixels inside, -1 none); objects in view."""
    visible: dict[int, int] = {}
    obj = frame.object_of_pixel
    for k in range(len(frame.labels)):
        n = int((obj == k).sum())
        if n >= min_pixels:
            visible[k] = n
    out = []
    for u0, v0, u1, v1 in boxes:
        patch = obj[v0 : v1 + 1, u0 : u1 + 1]
        inside = patch[patch >= 0]
        if inside.size == 0:
            out.append(-1)
            continue
        k = int(np.bincount(inside).argmax())
        # the box must hold a fair share of the object's pixels, and be mostly it
        share = (inside == k).sum()
        out.append(k if share >= 0.3 * visible.get(k, share) and k in visible else -1)
    return out, visible


@dataclass(frozen=True)
class FrameScore:
    """How one frame's detections met its objects: those counted (``wanted``), those a
    box found (``found``, in ``wanted``'s order), how many of those carry the right
    label, and the boxes that show no object."""

    wanted: set[int]
    found: list[int]
    labelled_right: int
    false_positives: int


def score_frame(
    boxes: Sequence[Box],
    frame: Frame,
    min_pixels: int,
    counts: Callable[[int, int], bool],
) -> FrameScore:
    """Match ``boxes`` to ``frame``'s objects and score them; ``counts(k, pixels)`` says
    which visible objects the measure asks for. The held-out evaluation here and the
    experiment's Table I score alike through this one rule."""
    coords = [(b.u0, b.v0, b.u1, b.v1) for b in boxes]
    matched, visible = match_boxes(coords, frame, min_pixels)
    wanted = {k for k, n in visible.items() if counts(k, n)}
    hit: dict[int, str] = {}
    false_pos = 0
    for box, k in zip(boxes, matched, strict=True):
        if k < 0:
            false_pos += 1
        elif k not in hit:
            hit[k] = box.label
    found = [k for k in wanted if k in hit]
    right = sum(hit[k] == frame.labels[k] for k in found)
    return FrameScore(wanted, found, right, false_pos)


def train(
    settings: TrainingSettings | None = None,
    progress: Callable[[str, int, int], None] | None = None,
) -> tuple[TrashDetector, Report]:
    """Render, label, fit the colour table and the region network; report on held-out
    frames (rendered with another seed, never seen in training)."""
    from sklearn.neural_network import MLPClassifier

    s = settings or TrainingSettings()
    started = time.perf_counter()
    frames = render_frames(
        s.frames,
        s.seed,
        s.width,
        s.height,
        progress=(lambda n: progress("rendering", n, s.frames)) if progress else None,
    )
    # stage 1: the colour table
    obj_counts = np.ones(BINS**3)
    bg_counts = np.ones(BINS**3)
    for f in frames:
        q = _quantise(f.image)
        is_obj = f.object_of_pixel >= 0
        obj_counts += np.bincount(q[is_obj], minlength=BINS**3)
        bg_counts += np.bincount(q[~is_obj], minlength=BINS**3)
    # objects are rare pixels: weigh the classes equally so the table asks "which is
    # this colour more like", not "which is more common"
    p_obj = obj_counts / obj_counts.sum()
    p_bg = bg_counts / bg_counts.sum()
    table = (p_obj / (p_obj + p_bg)).astype(np.float32)
    # stage 2: regions
    xs, ys = [], []
    for f in frames:
        like = table[_quantise(f.image)]
        labels, count = _regions(like)
        feats, boxes, _ = region_features(f.image, like, labels, count)
        matched, _visible = match_boxes(boxes, f, MIN_PIXELS)
        for row, k in zip(feats, matched, strict=True):
            xs.append(row)
            ys.append(0 if k < 0 else CLASSES.index(f.labels[k]))
    x = np.array(xs)
    y = np.array(ys)
    mean = x.mean(axis=0)
    scale = x.std(axis=0) + 1e-6
    net = MLPClassifier(
        hidden_layer_sizes=(s.hidden,), max_iter=800, random_state=s.seed, alpha=1e-3
    )
    net.fit((x - mean) / scale, y)
    if list(net.classes_) != [0, 1, 2]:
        raise RuntimeError("the training renders lacked a class; render more frames")
    arrays: dict[str, np.ndarray] = {
        "table": table,
        "mean": mean,
        "scale": scale,
        "layers": np.array(len(net.coefs_)),
    }
    for i, (w, b) in enumerate(zip(net.coefs_, net.intercepts_, strict=True)):
        arrays[f"w{i}"] = w
        arrays[f"b{i}"] = b
    detector = TrashDetector(arrays)
    held = render_frames(
        s.held_out,
        s.seed + 7919,
        s.width,
        s.height,
        progress=(lambda n: progress("held-out", n, s.held_out)) if progress else None,
    )
    report = evaluate(detector, held)
    report.seconds = round(time.perf_counter() - started, 1)
    return detector, report


def evaluate(detector: TrashDetector, frames: Sequence[Frame], min_pixels: int = 30) -> Report:
    """Recall (objects of at least ``min_pixels`` pixels found), label accuracy, false
    positives and the region classifier's accuracy over labelled frames."""
    objects = found = correct = false_pos = 0
    regions_right = regions = 0
    per_light: dict[str, list[int]] = {}
    for f in frames:
        boxes = detector.detect(f.image)
        score = score_frame(boxes, f, MIN_PIXELS, lambda _k, n: n >= min_pixels)
        false_pos += score.false_positives
        objects += len(score.wanted)
        found += len(score.found)
        correct += score.labelled_right
        light = per_light.setdefault(f.light, [0, 0])
        light[0] += len(score.found)
        light[1] += len(score.wanted)
        # the region classifier alone, on every region
        like = detector.likelihood(f.image)
        labels, count = _regions(like)
        feats, rboxes, _ = region_features(f.image, like, labels, count)
        if len(feats):
            truth, _ = match_boxes(rboxes, f, MIN_PIXELS)
            guess = np.argmax(detector.classify(feats), axis=1)
            want = [0 if k < 0 else CLASSES.index(f.labels[k]) for k in truth]
            regions += len(want)
            regions_right += int((guess == np.array(want)).sum())
    return Report(
        frames=len(frames),
        objects=objects,
        found=found,
        correct_label=correct,
        false_positives=false_pos,
        region_accuracy=round(regions_right / regions, 4) if regions else 0.0,
        seconds=0.0,
        per_light={k: (v[0], v[1]) for k, v in per_light.items()},
    )


def _key(settings: TrainingSettings) -> str:
    """The settings, the lights and the camera the frames are rendered with: a change
    to any of them makes another model."""
    from robocog.worlds.physics.field_scene import LIGHTING, CameraModel

    scene = {"lights": {k: asdict(v) for k, v in LIGHTING.items()}, "camera": asdict(CameraModel())}
    text = json.dumps({"v": VERSION, **asdict(settings), **scene}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def model_path(settings: TrainingSettings | None = None) -> Path:
    """Where the model of these settings is cached."""
    s = settings or TrainingSettings()
    return cache_dir() / f"trash-detector-{_key(s)}.npz"


def load_or_train(
    settings: TrainingSettings | None = None,
    min_confidence: float = 0.5,
    progress: Callable[[str, int, int], None] | None = None,
    retrain: bool = False,
) -> tuple[TrashDetector, Report | None]:
    """The cached model for these settings, trained first if there is none (the report
    is None when the model came from the cache; its training report sits beside it)."""
    s = settings or TrainingSettings()
    path = model_path(s)
    if path.exists() and not retrain:
        return TrashDetector.load(path, min_confidence), None
    detector, report = train(s, progress)
    detector.save(path)
    path.with_suffix(".json").write_text(json.dumps(report.as_dict(), indent=2))
    detector.min_confidence = min_confidence
    return detector, report
