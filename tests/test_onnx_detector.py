"""A user's YOLO-layout ONNX model in place of the learned detector: a tiny model built
here whose output is a fixed set of candidate boxes."""

from __future__ import annotations

import numpy as np
import pytest

onnx = pytest.importorskip("onnx")
pytest.importorskip("onnxruntime")

from onnx import TensorProto, helper  # noqa: E402

from robocog.worlds.physics.onnx_detector import OnnxDetector  # noqa: E402


def _model(path, rows: np.ndarray, size: int = 32) -> None:
    """input 1x3xSxS -> rows (+ 0 x the input's mean, so the output depends on it)."""
    const = helper.make_tensor("rows", TensorProto.FLOAT, rows.shape, rows.flatten().tolist())
    shape = helper.make_tensor("shape", TensorProto.INT64, [3], [1, 1, 1])
    zero = helper.make_tensor("zero", TensorProto.FLOAT, [], [0.0])
    nodes = [
        helper.make_node("ReduceMean", ["images"], ["mean"], axes=[1, 2, 3], keepdims=1),
        helper.make_node("Reshape", ["mean", "shape"], ["mean3"]),
        helper.make_node("Mul", ["mean3", "zero"], ["nothing"]),
        helper.make_node("Add", ["rows", "nothing"], ["output"]),
    ]
    graph = helper.make_graph(
        nodes,
        "tiny-yolo",
        [helper.make_tensor_value_info("images", TensorProto.FLOAT, [1, 3, size, size])],
        [helper.make_tensor_value_info("output", TensorProto.FLOAT, list(rows.shape))],
        initializer=[const, shape, zero],
    )
    model = helper.make_model(graph, opset_imports=[helper.make_opsetid("", 13)])
    model.ir_version = 8
    onnx.checker.check_model(model)
    onnx.save(model, str(path))


def _row(cx, cy, w, h, obj, cls, score, classes=80):
    r = np.zeros(5 + classes, dtype=np.float32)
    r[:5] = (cx, cy, w, h, obj)
    r[5 + cls] = score
    return r


def test_an_onnx_yolo_model_detects_through_onnxruntime(tmp_path):
    rows = np.stack(
        [
            _row(16, 16, 8, 16, 0.9, 39, 0.9),  # a bottle, confidence 0.81
            _row(17, 16, 8, 16, 0.9, 39, 0.8),  # the same bottle again: suppressed
            _row(8, 24, 6, 6, 0.9, 41, 0.7),  # a cup, 0.63
            _row(24, 8, 6, 6, 0.3, 41, 0.5),  # too unsure: 0.15
            _row(24, 24, 6, 6, 0.9, 0, 0.9),  # a person: not trash
        ]
    )[None]
    path = tmp_path / "tiny.onnx"
    _model(path, rows)
    detector = OnnxDetector(path, min_confidence=0.5)
    image = np.zeros((64, 64, 3), dtype=np.uint8)
    boxes = detector.detect(image)
    assert [(b.label, b.confidence) for b in boxes] == [("bottle", 0.81), ("cup", 0.63)]
    bottle = boxes[0]
    assert (bottle.u0, bottle.v0, bottle.u1, bottle.v1) == (24, 16, 40, 48)  # scaled x2
    with pytest.raises(FileNotFoundError):
        OnnxDetector(tmp_path / "missing.onnx")
