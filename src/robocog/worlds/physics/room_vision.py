"""The Q.bo's vision as Fujita et al. describe it: image areas classified by an SVM.

``looking_Qbo`` takes three images with the head turned left, ahead and right (about 160
degrees in all), splits each into 3 x 2 areas and asks, for each area and each target
(``door``, ``entry``), whether the target is in it. The paper used libSVM; so does this
module, through scikit-learn's :class:`~sklearn.svm.SVC` (a wrapper of libSVM), one
binary classifier per target with Platt-scaled probabilities as the certainty.

The training set is made by robocog itself: the head camera renders the room from
seeded random poses (robot anywhere in the room, head at any pan, door opened 60-95
degrees) and the renderer's segmentation says what each pixel shows. An area is
labelled ``door`` when a door leaf (the room's or the opposite room's: both look the
same) covers at least a fifth of it, ``entry`` when the corridor seen through the
doorway covers at least a fifth; areas covered by a target between a twentieth and a
fifth are left out of training and testing as ambiguous. Features are the area's
colours on a 5 x 5 grid and the strength of its horizontal and vertical edges per row
of that grid (the slit under the knob is a horizontal edge).

The rendered areas (features and labels, not the fitted classifiers) are cached as a
NumPy archive in the user's cache directory, keyed by the renderer's settings and the
seed; fitting on them takes about a second, so the classifiers are fitted afresh on
every start and no pickled object is ever loaded. Accuracy and confusion matrices on
held-out renders (other poses, other seed) come with every training.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import random
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from robocog.worlds.physics.room_scene import (
    BODY_RADIUS,
    CAMERA_HFOV,
    QBO_BASE,
    RoomPlan,
    scene_xml,
)

#: image size: 3 x 2 square areas of AREA pixels
AREA = 32
COLUMNS, ROWS = 3, 2
WIDTH, HEIGHT = COLUMNS * AREA, ROWS * AREA
#: the head's pans of the three images, degrees (54-degree images: about 160 in all)
PANS = (55.0, 0.0, -55.0)
TARGETS = ("door", "entry")
#: covered share of an area at or above which it shows the target, and below which not
POSITIVE, NEGATIVE = 0.2, 0.05
#: pixel noise of the camera (standard deviation, on a 0-255 scale)
PIXEL_NOISE = 4.0
VERSION = 1
GRID = 5


def area_bearing(pan_degrees: float, column: int) -> float:
    """Bearing (radians, relative to the body) of the centre of an image column."""
    width = CAMERA_HFOV / COLUMNS
    return math.radians(pan_degrees + CAMERA_HFOV / 2 - width * (column + 0.5))


def split_areas(image: np.ndarray) -> list[np.ndarray]:
    """The 3 x 2 areas of an image, row by row from the top, left to right."""
    return [
        image[r * AREA : (r + 1) * AREA, c * AREA : (c + 1) * AREA]
        for r in range(ROWS)
        for c in range(COLUMNS)
    ]


def area_features(area: np.ndarray) -> np.ndarray:
    """Colours on a 5 x 5 grid and horizontal/vertical edge strength per grid row/column."""
    a = area.astype(np.float32) / 255.0
    n = AREA // GRID * GRID
    a = a[:n, :n]
    cell = n // GRID
    colours = a.reshape(GRID, cell, GRID, cell, 3).mean(axis=(1, 3)).ravel()
    grey = a.mean(axis=2)
    dy = np.abs(np.diff(grey, axis=0))[: n - 1 - (n - 1) % GRID]
    dx = np.abs(np.diff(grey, axis=1))[:, : n - 1 - (n - 1) % GRID]
    horizontal = dy.reshape(GRID, -1, n).mean(axis=(1, 2))
    vertical = dx.reshape(n, GRID, -1).mean(axis=(0, 2))
    spread = a.reshape(-1, 3).std(axis=0)
    return np.concatenate([colours, 4 * horizontal, 4 * vertical, spread]).astype(np.float32)


class HeadCamera:
    """Offscreen renderer of the head camera: colour with noise, and segmentation."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self.model = model
        self.renderer: mujoco.Renderer | None = mujoco.Renderer(model, HEIGHT, WIDTH)
        self.camera = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, "eye")
        self.door_geoms = self._geoms("door_", "opposite_")
        self.own_door = self._geoms("door_")
        self.corridor_geoms = self._corridor_geoms()
        self.frames = 0

    def _geoms(self, *prefixes: str) -> set[int]:
        out = set()
        for g in range(self.model.ngeom):
            name = mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_GEOM, g) or ""
            if name.startswith(prefixes):
                out.add(g)
        return out

    def _corridor_geoms(self) -> set[int]:
        """What is seen through the doorway: the corridor's floor, its walls, the opposite
        door, and the corridor side of the room's north wall."""
        out = self._geoms("opposite_", "corridor_floor")
        for g in range(self.model.ngeom):
            name = mujoco.mj_id2name(self.model, mujoco.mjtObj.mjOBJ_GEOM, g) or ""
            rgba = self.model.geom_rgba[g]
            if name.startswith("wall") and rgba[2] > rgba[0] + 0.1:  # corridor-coloured
                out.add(g)
        return out

    def render(self, data: mujoco.MjData, rng: random.Random | None = None) -> np.ndarray:
        """One colour image, with the camera's noise when ``rng`` is given."""
        if self.renderer is None:
            raise RuntimeError("the camera is closed")
        self.renderer.update_scene(data, camera=self.camera)
        image = self.renderer.render()
        self.frames += 1
        if rng is not None and PIXEL_NOISE > 0:
            noise = np.random.default_rng(rng.getrandbits(32)).normal(0, PIXEL_NOISE, image.shape)
            image = np.clip(image.astype(np.float32) + noise, 0, 255).astype(np.uint8)
        return image

    def segment(self, data: mujoco.MjData) -> np.ndarray:
        """The geom id seen at every pixel (-1 for nothing)."""
        if self.renderer is None:
            raise RuntimeError("the camera is closed")
        self.renderer.enable_segmentation_rendering()
        try:
            self.renderer.update_scene(data, camera=self.camera)
            seg = self.renderer.render()
        finally:
            self.renderer.disable_segmentation_rendering()
        ids = seg[..., 0].astype(np.int32)
        ids[seg[..., 1] != int(mujoco.mjtObj.mjOBJ_GEOM)] = -1
        return ids

    def coverage(self, seg: np.ndarray) -> np.ndarray:
        """Per area, the share covered by a door leaf, the corridor, and the room's own
        door (shape (6, 3))."""
        out = []
        for area in split_areas(seg):
            n = area.size
            out.append(
                [
                    np.isin(area, list(self.door_geoms)).sum() / n,
                    np.isin(area, list(self.corridor_geoms)).sum() / n,
                    np.isin(area, list(self.own_door)).sum() / n,
                ]
            )
        return np.array(out, dtype=np.float32)

    def close(self) -> None:
        """Free the GL context (once)."""
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None


def pose_robot(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    x: float,
    y: float,
    yaw: float,
    pan: float = 0.0,
    door: float | None = None,
) -> None:
    """Put the robot (its base's free joint) at a pose, turn the head and set the door's
    angle, at rest, and recompute positions."""

    def qadr(joint: str) -> int:
        return int(model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint)])

    free = qadr(f"{QBO_BASE.name}_free")
    data.qpos[free : free + 7] = [x, y, 0.0, math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]
    data.qpos[qadr("head_pan")] = pan
    if door is not None:
        data.qpos[qadr("door_hinge")] = door
    data.qvel[:] = 0.0
    mujoco.mj_forward(model, data)


@dataclass
class AreaSet:
    """Rendered areas: features, labels (-1 ambiguous, 0 no, 1 yes) per target, coverage."""

    features: np.ndarray
    labels: np.ndarray
    coverage: np.ndarray

    def save(self, path: Path, meta: dict[str, Any]) -> None:
        """Write as an .npz archive (no pickled objects) with its metadata beside it."""
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".tmp.npz")
        np.savez_compressed(tmp, features=self.features, labels=self.labels, coverage=self.coverage)
        os.replace(tmp, path)
        path.with_suffix(".json").write_text(json.dumps(meta, indent=1), encoding="utf-8")

    @classmethod
    def load(cls, path: Path) -> AreaSet:
        """Read an archive written by :meth:`save` (plain arrays only)."""
        with np.load(path, allow_pickle=False) as z:
            return cls(z["features"], z["labels"], z["coverage"])


def label(coverage: np.ndarray) -> np.ndarray:
    """Coverage (n, >=2) -> labels (n, 2): 1 at or above POSITIVE, 0 below NEGATIVE, else -1."""
    c = coverage[:, :2]
    out = np.full(c.shape, -1, dtype=np.int8)
    out[c >= POSITIVE] = 1
    out[c < NEGATIVE] = 0
    return out


def render_areas(images: int, seed: int, plan: RoomPlan | None = None) -> AreaSet:
    """Render ``images`` head images from seeded random poses; their areas, labelled."""
    plan = plan or RoomPlan()
    rng = random.Random(seed)
    model = mujoco.MjModel.from_xml_string(scene_xml(plan))
    data = mujoco.MjData(model)
    camera = HeadCamera(model)
    feats, covs = [], []
    margin = BODY_RADIUS + 0.1
    try:
        for _ in range(images):
            x = rng.uniform(margin, plan.width - margin)
            y = rng.uniform(margin, plan.depth - margin)
            # look more often towards the north-east, where the doors are
            if rng.random() < 0.6:
                tx = rng.uniform(plan.doorway_x - 0.5, plan.width)
                ty = rng.uniform(plan.depth - 1.0, plan.top)
                yaw = math.atan2(ty - y, tx - x) + rng.gauss(0, 0.3)
            else:
                yaw = rng.uniform(-math.pi, math.pi)
            door = math.radians(rng.uniform(60.0, 95.0))
            pose_robot(model, data, x, y, yaw, math.radians(rng.uniform(-60, 60)), door)
            if _leaf_overlaps(data, model, x, y):
                continue
            image = camera.render(data, rng)
            covs.append(camera.coverage(camera.segment(data)))
            feats.extend(area_features(a) for a in split_areas(image))
    finally:
        camera.close()
    coverage = np.concatenate(covs) if covs else np.zeros((0, 3), np.float32)
    return AreaSet(np.array(feats, dtype=np.float32), label(coverage), coverage)


def _leaf_overlaps(data: mujoco.MjData, model: mujoco.MjModel, x: float, y: float) -> bool:
    """True when a robot at (x, y) would stand inside the open door leaf."""
    mujoco.mj_collision(model, data)
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "body")
    for i in range(data.ncon):
        c = data.contact[i]
        if body in (c.geom1, c.geom2) and c.dist < 0:
            return True
    return False


@dataclass
class Scores:
    """Accuracy and confusion matrix of one target's classifier on held-out areas."""

    target: str
    accuracy: float
    confusion: list[list[int]]
    support: int
    accuracy_all: float = 0.0
    areas: int = 0

    def line(self) -> str:
        """One line: accuracy and the matrix (rows: truth no/yes, columns: said no/yes)."""
        (tn, fp), (fn, tp) = self.confusion
        return (
            f"{self.target}: accuracy {self.accuracy:.3f} on {self.support} clear held-out "
            f"areas, confusion [[{tn} {fp}] [{fn} {tp}]] (rows truth no/yes, columns said "
            f"no/yes); {self.accuracy_all:.3f} on all {self.areas} (ambiguous ones counted "
            f"as showing the target from a fifth covered)"
        )


@dataclass
class AreaClassifier:
    """One libSVM classifier per target over area features; certainty in [0, 1]."""

    seed: int = 0
    models: dict[str, Any] = field(default_factory=dict)
    scores: list[Scores] = field(default_factory=list)

    def fit(self, train: AreaSet) -> AreaClassifier:
        """Fit each target's SVC (RBF kernel, Platt probabilities) on its clear areas."""
        from sklearn.calibration import CalibratedClassifierCV
        from sklearn.pipeline import make_pipeline
        from sklearn.preprocessing import StandardScaler
        from sklearn.svm import SVC

        for t, target in enumerate(TARGETS):
            keep = train.labels[:, t] >= 0
            svm = SVC(C=10.0, gamma="scale", random_state=self.seed)
            model = make_pipeline(
                StandardScaler(),
                CalibratedClassifierCV(svm, method="sigmoid", cv=5, ensemble=False),
            )
            model.fit(train.features[keep], train.labels[keep, t])
            self.models[target] = model
        return self

    def certainty(self, features: np.ndarray) -> dict[str, np.ndarray]:
        """Per target, the probability that each area shows it."""
        out = {}
        for target, model in self.models.items():
            classes = list(model.classes_)
            proba = model.predict_proba(features)
            out[target] = proba[:, classes.index(1)] if 1 in classes else np.zeros(len(features))
        return out

    def evaluate(self, test: AreaSet) -> list[Scores]:
        """Accuracy and confusion matrix per target on clear held-out areas."""
        self.scores = []
        cert = self.certainty(test.features)
        for t, target in enumerate(TARGETS):
            keep = test.labels[:, t] >= 0
            truth = test.labels[keep, t].astype(int)
            said = (cert[target][keep] > 0.5).astype(int)
            confusion = [[int(((truth == a) & (said == b)).sum()) for b in (0, 1)] for a in (0, 1)]
            accuracy = float((truth == said).mean()) if len(truth) else 0.0
            every = (test.coverage[:, t] >= POSITIVE).astype(int)
            every_said = (cert[target] > 0.5).astype(int)
            overall = float((every == every_said).mean()) if len(every) else 0.0
            self.scores.append(
                Scores(target, accuracy, confusion, int(keep.sum()), overall, len(every))
            )
        return self.scores


def cache_dir() -> Path:
    """robocog's directory in the user's cache (``$XDG_CACHE_HOME`` or ``~/.cache``)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "robocog" / "qbo-svm"


def _key(images: int, seed: int) -> str:
    settings = {
        "version": VERSION,
        "size": [WIDTH, HEIGHT],
        "pans": PANS,
        "labels": [POSITIVE, NEGATIVE],
        "noise": PIXEL_NOISE,
        "images": images,
        "seed": seed,
        "scene": scene_xml(RoomPlan()),
    }
    return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:16]


def dataset(
    images: int, seed: int, directory: Path | None = None, refresh: bool = False
) -> AreaSet:
    """Rendered areas for (images, seed), from the cache when there, else rendered and cached."""
    directory = directory or cache_dir()
    path = directory / f"areas-{_key(images, seed)}.npz"
    if path.exists() and not refresh:
        try:
            return AreaSet.load(path)
        except (OSError, ValueError, KeyError):
            pass  # a damaged cache entry is rendered again
    areas = render_areas(images, seed)
    try:
        areas.save(path, {"images": images, "seed": seed, "areas": int(len(areas.features))})
    except OSError:
        pass  # a read-only cache only costs the next start a render
    return areas


#: training and held-out images, and their seeds' offset
TRAIN_IMAGES, TEST_IMAGES = 500, 150
TEST_SEED_OFFSET = 10_000


def trained(
    seed: int = 0,
    images: int = TRAIN_IMAGES,
    test_images: int = TEST_IMAGES,
    directory: Path | None = None,
    refresh: bool = False,
) -> AreaClassifier:
    """The classifiers fitted on seeded renders and scored on held-out ones (both cached)."""
    train = dataset(images, seed, directory, refresh)
    test = dataset(test_images, seed + TEST_SEED_OFFSET, directory, refresh)
    classifier = AreaClassifier(seed).fit(train)
    classifier.evaluate(test)
    return classifier


_SHARED: dict[tuple[int, int], AreaClassifier] = {}


def shared_classifier(seed: int = 0, images: int = TRAIN_IMAGES) -> AreaClassifier:
    """One classifier per process and training seed (fitting it costs a second or two)."""
    key = (seed, images)
    if key not in _SHARED:
        _SHARED[key] = trained(seed, images)
    return _SHARED[key]
