"""Seeing the tabletop from pixels: render, detect AprilTags, turn tag poses into facts.

Two fixed cameras look at the table: one overhead, which sees the top face of every
cube that nothing covers, and one in front, above the arm's shoulder, which sees the
front faces of the cubes under others. Each frame is rendered offscreen, converted to
grey and given to the AprilTag detector (``pupil_apriltags``, the AprilTag 3 library),
which returns each tag's id and its pose in the camera. With the cameras' calibration
(where they hang and how wide they see) a pose becomes a point in the world: the tag's
centre and the direction its face looks.

From the sightings, with the map of the fixed objects (:class:`~.scene.Layout`), come
the facts the planner needs: which cube rests on which cube (one centred on another's
top, one cube height higher) and which rests on a fixed object (over its surface, at
its height). A cube seen in the air, or tilted, rests on nothing known. Nothing here
reads where the simulator keeps its bodies: only images and the calibration.
"""

from __future__ import annotations

import contextlib
import math
import os
from collections.abc import Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from robocog.worlds.physics.detector import shared_detector
from robocog.worlds.physics.scene import CUBE, TAG_SIZE, Layout

CAMERAS = ("overhead", "front")
TOP_FACE = 0.8
SIDE_FACE = 0.35


@dataclass(frozen=True)
class Sighting:
    """One tag seen by one camera: its centre and face normal in the world frame."""

    id: int
    camera: str
    position: tuple[float, float, float]
    normal: tuple[float, float, float]
    yaw: float
    margin: float


@dataclass(frozen=True)
class CubeView:
    """Where perception puts a cube: its centre, its yaw, and whether it sits upright."""

    name: str
    id: int
    centre: tuple[float, float, float]
    yaw: float
    upright: bool
    seen_from: str


@contextlib.contextmanager
def _quiet_stderr() -> Iterator[None]:
    """Send file descriptor 2 to /dev/null for a while (C code writes there directly)."""
    try:
        saved = os.dup(2)
    except OSError:
        yield
        return
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
            yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


class Eyes:
    """Renders the cameras and detects tags; one per model."""

    def __init__(self, model: mujoco.MjModel, width: int = 1280, height: int = 960) -> None:
        self.model = model
        self.width, self.height = width, height
        self.renderer: mujoco.Renderer | None = mujoco.Renderer(model, height, width)
        self.detector = shared_detector()
        self.frames = 0
        self.render_seconds = 0.0
        self.detect_seconds = 0.0
        self.last_images: dict[str, np.ndarray] = {}

    def intrinsics(self, camera: str) -> tuple[float, float, float, float]:
        """fx, fy, cx, cy of a camera from its vertical field of view (square pixels)."""
        cam = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_CAMERA, camera)
        fovy = math.radians(float(self.model.cam_fovy[cam]))
        f = (self.height / 2) / math.tan(fovy / 2)
        return f, f, self.width / 2, self.height / 2

    def render(self, data: mujoco.MjData, camera: str) -> np.ndarray:
        """One RGB frame of ``camera``."""
        import time

        t = time.perf_counter()
        if self.renderer is None:
            raise RuntimeError("these eyes are closed")
        self.renderer.update_scene(data, camera=camera)
        image = self.renderer.render()
        self.render_seconds += time.perf_counter() - t
        self.frames += 1
        self.last_images[camera] = image
        return image

    def detect(self, image: np.ndarray, data: mujoco.MjData, camera: str) -> list[Sighting]:
        """The tags in one image, placed in the world by the camera's calibration."""
        import time

        grey = (image[..., 0] * 0.299 + image[..., 1] * 0.587 + image[..., 2] * 0.114).astype(
            np.uint8
        )
        t = time.perf_counter()
        with _quiet_stderr():  # the library prints pose-solver notes on the C stream
            found = self.detector.detect(
                grey,
                estimate_tag_pose=True,
                camera_params=self.intrinsics(camera),
                tag_size=TAG_SIZE,
            )
        self.detect_seconds += time.perf_counter() - t
        cam = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_CAMERA, camera)
        origin = data.cam_xpos[cam].copy()
        to_world = data.cam_xmat[cam].reshape(3, 3) @ np.diag([1.0, -1.0, -1.0])
        out = []
        for det in found:
            if det.pose_t is None or det.decision_margin < 20:
                continue
            pos = origin + to_world @ det.pose_t.ravel()
            rot = to_world @ det.pose_R
            normal = -rot[:, 2]  # the tag's z axis points into its face
            sight = origin - pos
            if float(normal @ sight) < 0.45 * float(np.linalg.norm(sight)):
                continue  # seen at a glancing angle, where the pose is ambiguous
            x_axis = rot[:, 0]
            out.append(
                Sighting(
                    int(det.tag_id),
                    camera,
                    (float(pos[0]), float(pos[1]), float(pos[2])),
                    (float(normal[0]), float(normal[1]), float(normal[2])),
                    math.atan2(float(x_axis[1]), float(x_axis[0])),
                    float(det.decision_margin),
                )
            )
        return out

    def look(self, data: mujoco.MjData) -> list[Sighting]:
        """Render every camera and detect its tags."""
        out: list[Sighting] = []
        for camera in CAMERAS:
            out += self.detect(self.render(data, camera), data, camera)
        return out

    def close(self) -> None:
        """Free the renderer's GL context (once)."""
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None


def cube_views(sightings: list[Sighting], names: dict[int, str]) -> dict[str, CubeView]:
    """One view per cube seen, fused from every face any camera saw of it.

    A face's centre lies half a cube from the cube's centre, against the face's normal.
    A small tag is well placed across the image but less surely in depth, and its tilt
    is uncertain (the two mirror solutions of a planar pose lie close; the wrong one
    also moves the tag along the line of sight). So a face that looks up by more than
    35 degrees counts as a top face and one within 20 degrees of the horizon as a side,
    each gives a centre, and the cube's centre is the median of them: one bad pose
    among three is outvoted. The yaw comes from the squarest top face.
    """
    by_id: dict[int, list[Sighting]] = {}
    for s in sightings:
        if s.id in names:
            by_id.setdefault(s.id, []).append(s)
    out = {}
    for tag_id, seen in by_id.items():
        centres = []
        tops = []
        for s in seen:
            nx, ny, nz = s.normal
            px, py, pz = s.position
            if nz > TOP_FACE:
                centres.append((px, py, pz - CUBE / 2))
                tops.append(s)
            elif abs(nz) < SIDE_FACE:
                h = math.hypot(nx, ny)
                centres.append((px - nx / h * CUBE / 2, py - ny / h * CUBE / 2, pz))
        name = names[tag_id]
        if not centres:  # every face seen is tilted: the cube lies on an edge
            s = max(seen, key=lambda t: t.margin)
            nx, ny, nz = s.normal
            px, py, pz = s.position
            centre = (px - nx * CUBE / 2, py - ny * CUBE / 2, pz - nz * CUBE / 2)
            out[name] = CubeView(name, tag_id, centre, 0.0, False, s.camera)
            continue
        arr = np.array(centres)
        centre = tuple(float(v) for v in np.median(arr, axis=0))
        if tops:
            best = max(tops, key=lambda t: t.normal[2])
            yaw = best.yaw
        else:
            best = seen[0]
            yaw = math.atan2(best.normal[1], best.normal[0])
        out[name] = CubeView(name, tag_id, centre, yaw, True, best.camera)  # type: ignore[arg-type]
    return out


def resting(views: dict[str, CubeView], layout: Layout) -> dict[str, str]:
    """What each seen cube rests on: another seen cube, a fixed object, or nothing known."""
    out: dict[str, str] = {}
    for name, v in views.items():
        if not v.upright:
            continue
        x, y, z = v.centre
        below = None
        for other, w in views.items():
            if other == name or not w.upright:
                continue
            dz = z - w.centre[2]
            if (
                abs(dz - CUBE) < 0.35 * CUBE
                and math.hypot(x - w.centre[0], y - w.centre[1]) < 0.5 * CUBE
            ):
                below = other
        if below is None:
            for region in layout.regions:
                if region.contains(x, y) and abs(z - CUBE / 2 - region.top) < 0.015:
                    below = region.name
                    break
        if below is not None:
            out[name] = below
    return out
