"""A user's own YOLO model, exported to ONNX, as the physical garbage field's detector.

Hammer et al. ran YOLOv4; a user with such a model (exported to ONNX, as Darknet and
the Ultralytics tools do) can put it in place of robocog's learned detector with
``--detector model.onnx``. It runs through onnxruntime on the processor. The model's
input is one ``1 x 3 x H x W`` image scaled to 0..1 (its size read from the model, 416
where it is left open); its first output holds one row per candidate box,
``cx, cy, w, h, objectness, class scores...`` in input pixels (the YOLOv4/v5 export
layout). A row's confidence is objectness times its best class score; the rows whose
class is one of ``labels`` (COCO's bottle and cup by default) and whose confidence
reaches ``min_confidence`` are kept, overlapping boxes of a class thinned by
non-maximum suppression.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from robocog.worlds.physics.trash_detector import Box

#: COCO class indices of the objects the field holds
COCO_LABELS: dict[int, str] = {39: "bottle", 41: "cup"}


def _iou(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    x0 = np.maximum(a[0], b[:, 0])
    y0 = np.maximum(a[1], b[:, 1])
    x1 = np.minimum(a[2], b[:, 2])
    y1 = np.minimum(a[3], b[:, 3])
    inter = np.clip(x1 - x0, 0, None) * np.clip(y1 - y0, 0, None)
    area = (a[2] - a[0]) * (a[3] - a[1])
    areas = (b[:, 2] - b[:, 0]) * (b[:, 3] - b[:, 1])
    return inter / np.maximum(area + areas - inter, 1e-9)


class OnnxDetector:
    """``detect(image)`` with a YOLO-layout ONNX model."""

    def __init__(
        self,
        path: Path | str,
        min_confidence: float = 0.5,
        labels: dict[int, str] | None = None,
        iou: float = 0.45,
    ) -> None:
        import onnxruntime

        path = Path(path)
        if not path.is_file():
            raise FileNotFoundError(f"no ONNX model at {path}")
        self.session = onnxruntime.InferenceSession(str(path), providers=["CPUExecutionProvider"])
        spec = self.session.get_inputs()[0]
        self.input = spec.name
        shape = list(spec.shape)
        if len(shape) != 4:
            raise ValueError(f"{path}: the model's input must be 1 x 3 x H x W, not {shape}")
        self.height = shape[2] if isinstance(shape[2], int) else 416
        self.width = shape[3] if isinstance(shape[3], int) else 416
        self.labels = labels or COCO_LABELS
        self.min_confidence = min_confidence
        self.iou = iou
        self.seconds = 0.0
        self.frames = 0

    def detect(self, image: np.ndarray) -> list[Box]:
        """The bottles and cups in an RGB frame, most confident first."""
        start = time.perf_counter()
        h, w = image.shape[:2]
        rows = (np.arange(self.height) * h // self.height).clip(0, h - 1)
        cols = (np.arange(self.width) * w // self.width).clip(0, w - 1)
        x = image[rows][:, cols, :3].astype(np.float32) / 255.0
        x = np.ascontiguousarray(x.transpose(2, 0, 1)[None])
        out = np.asarray(self.session.run(None, {self.input: x})[0], dtype=np.float64)
        out = out.reshape(-1, out.shape[-1])
        boxes: list[Box] = []
        if out.shape[1] > 5 and len(out):
            scores = out[:, 5:]
            cls = np.argmax(scores, axis=1)
            conf = out[:, 4] * scores[np.arange(len(out)), cls]
            sx, sy = w / self.width, h / self.height
            corners = np.column_stack(
                (
                    (out[:, 0] - out[:, 2] / 2) * sx,
                    (out[:, 1] - out[:, 3] / 2) * sy,
                    (out[:, 0] + out[:, 2] / 2) * sx,
                    (out[:, 1] + out[:, 3] / 2) * sy,
                )
            )
            for k, label in self.labels.items():
                keep = np.where((cls == k) & (conf >= self.min_confidence))[0]
                keep = keep[np.argsort(-conf[keep])]
                while len(keep):
                    best, keep = keep[0], keep[1:]
                    c = corners[best]
                    boxes.append(
                        Box(
                            label,
                            round(float(conf[best]), 3),
                            int(max(0, c[0])),
                            int(max(0, c[1])),
                            int(min(w - 1, c[2])),
                            int(min(h - 1, c[3])),
                        )
                    )
                    if len(keep):
                        keep = keep[_iou(c, corners[keep]) < self.iou]
        boxes.sort(key=lambda b: -b.confidence)
        self.seconds += time.perf_counter() - start
        self.frames += 1
        return boxes


def camera_detector(
    onnx_model: Path | None = None, say: Callable[[str], None] | None = None
) -> tuple[Any, Any]:
    """The detector a physical field's camera runs, and its training report (None when
    there is none): the user's ONNX model when one is given, else robocog's learned
    detector, trained on rendered frames the first time (``say`` is told so before).

    One-line errors: ``ImportError`` when onnxruntime is missing, ``ValueError`` when
    onnxruntime cannot load the model."""
    if onnx_model is not None:
        try:
            return OnnxDetector(onnx_model), None
        except ImportError:
            raise
        except Exception as exc:  # noqa: BLE001 - onnxruntime refuses a model in many ways
            raise ValueError(f"{onnx_model}: {exc}") from None
    from robocog.worlds.physics.trash_detector import load_or_train, model_path

    if say is not None and not model_path().exists():
        say("training the detector on rendered frames (once per machine)...")
    return load_or_train()
