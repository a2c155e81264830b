"""The process's AprilTag detector (``pupil_apriltags``), and freeing one safely.

Kept apart from the cameras (which need MuJoCo) so that what only reads tags loads
only the detector's library and numpy.
"""

from __future__ import annotations

import atexit
from typing import Any

_DETECTOR: Any = None


def shared_detector() -> Any:
    """One tag36h11 detector for the process (its setup is the costly part; it keeps no
    state between images), released when the interpreter exits (:func:`release_detector`)."""
    global _DETECTOR
    if _DETECTOR is None:
        from pupil_apriltags import Detector

        _DETECTOR = Detector(families="tag36h11", nthreads=1, quad_decimate=1.0)
        # atexit runs before the interpreter takes its modules apart, while the
        # detector's library and everything release_detector needs are whole
        atexit.register(_release_shared)
    return _DETECTOR


def release_detector(detector: Any) -> None:
    """Free a ``pupil_apriltags.Detector``'s C objects in the order the library needs.

    The binding's own ``__del__`` frees each tag family first and the detector after,
    but freeing the detector clears the decoding table it hung on each family, so it
    reads and writes the families just freed: a use after free, which corrupts the heap
    of whatever process drops a detector (at the latest, every process at its exit).
    Here the detector goes first (its families' tables with it), the families after;
    the binding's ``__del__`` then finds nothing left to free. Idempotent.
    """
    pointer = getattr(detector, "tag_detector_ptr", None)
    if pointer is None:
        return
    library = detector.libc
    library.apriltag_detector_destroy.restype = None
    library.apriltag_detector_destroy(pointer)
    detector.tag_detector_ptr = None
    families = dict(detector.tag_families)
    detector.tag_families = {}
    for family, family_pointer in families.items():
        destroy = getattr(library, f"{family}_destroy")
        destroy.restype = None
        destroy(family_pointer)


def _release_shared() -> None:
    global _DETECTOR
    if _DETECTOR is not None:
        release_detector(_DETECTOR)
        _DETECTOR = None
