"""The AprilTag detector is freed in the order its C library needs, at exit as anywhere.

The binding frees a detector's tag family before the detector, whose own teardown then
reads and writes that family's freed memory; the process's shared detector used to be
freed that way when the interpreter exited. These run a process that reads a tag once
and exits, and look at what it leaves: its output, and under valgrind (when installed)
every access the library makes to freed memory.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

apriltags = pytest.importorskip(
    "pupil_apriltags", reason="the physics extra (pupil-apriltags) is not installed"
)

from robocog.worlds.physics.detector import release_detector, shared_detector  # noqa: E402
from robocog.worlds.physics.tags import tag_cells  # noqa: E402

SRC = Path(__file__).resolve().parents[2] / "src"

#: a process that reads one tag (its pose too, as the cameras do) with the shared
#: detector and exits; an exit hook registered before the detector was made runs after
#: the detector's own and says what it left for the binding's __del__
ONCE = """
import atexit
import numpy as np
from robocog.worlds.physics.detector import shared_detector
from robocog.worlds.physics.tags import tag_cells

made = []
atexit.register(lambda: print("left for the binding:", made[0].tag_detector_ptr, flush=True))
made.append(shared_detector())
image = np.kron(tag_cells(7) * 255, np.ones((6, 6), dtype=np.uint8)).astype(np.uint8)
found = made[0].detect(
    np.pad(image, 12, constant_values=255),
    estimate_tag_pose=True, camera_params=(200.0, 200.0, 40.0, 40.0), tag_size=0.03,
)
print("found", [d.tag_id for d in found], flush=True)
"""

#: what a process tearing down badly prints (Python's or the C library's)
TEARDOWN_FAULTS = (
    "Exception ignored",
    "Traceback",
    "free():",
    "double free",
    "corrupted",
    "Segmentation",
    "Fatal Python error",
)


def _run(*prefix: str, timeout: float) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(SRC) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    if prefix:
        env["PYTHONMALLOC"] = "malloc"  # every allocation through malloc, as valgrind sees it
    return subprocess.run(
        [*prefix, sys.executable, "-c", ONCE],
        capture_output=True,
        text=True,
        env=env,
        timeout=timeout,
    )


def _image(tag_id: int) -> np.ndarray:
    cells = np.kron(tag_cells(tag_id) * 255, np.ones((6, 6), dtype=np.uint8)).astype(np.uint8)
    return np.pad(cells, 12, constant_values=255)


def test_a_process_that_reads_a_tag_exits_cleanly() -> None:
    for _ in range(3):
        done = _run(timeout=120)
        assert done.returncode == 0, done.stderr
        assert "found [7]" in done.stdout
        # the detector was freed by robocog's exit hook; the binding's __del__ had nothing
        assert "left for the binding: None" in done.stdout
        for fault in TEARDOWN_FAULTS:
            assert fault not in done.stderr, done.stderr


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("valgrind") is None, reason="valgrind is not installed")
def test_nothing_of_the_detector_is_touched_after_it_is_freed() -> None:
    done = _run("valgrind", "--error-exitcode=0", timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    assert "found [7]" in done.stdout
    # valgrind's reports are blocks of lines separated by an empty one ("==pid== ");
    # the interpreter's own (ld.so, CPython with the system malloc) are not ours to judge
    blocks = [b for b in done.stderr.split("== \n") if "Invalid" in b or "free'd" in b]
    ours = [b for b in blocks if "apriltag" in b or "tag36h11" in b or "quick_decode" in b]
    assert not ours, "\n".join(ours)[:4000]


def test_a_detector_released_here_still_read_tags_and_is_released_once() -> None:
    shared = shared_detector()
    assert shared is shared_detector()
    assert [d.tag_id for d in shared.detect(_image(3))] == [3]
    # a detector of its own, freed in the right order and then dropped
    from pupil_apriltags import Detector

    own = Detector(families="tag36h11", nthreads=1)
    assert [d.tag_id for d in own.detect(_image(5))] == [5]
    release_detector(own)
    assert own.tag_detector_ptr is None and own.tag_families == {}
    release_detector(own)  # a second time: nothing left to free
    del own
    assert [d.tag_id for d in shared.detect(_image(9))] == [9]
