"""Choose MuJoCo's offscreen OpenGL before mujoco is imported, so rendering works headless.

MuJoCo reads ``MUJOCO_GL`` once. Without a display, EGL (Debian's ``libegl1`` with
``libgl1-mesa-dri``: Mesa renders on the processor) works with no X server; OSMesa
(``libosmesa6``) is the fallback. A value the user set is kept.
"""

from __future__ import annotations

import ctypes.util
import os


def choose_gl() -> str | None:
    """Set ``MUJOCO_GL`` to ``egl`` or ``osmesa`` if unset and a library for it exists."""
    if os.environ.get("MUJOCO_GL"):
        return os.environ["MUJOCO_GL"]
    for backend, library in (("egl", "EGL"), ("osmesa", "OSMesa")):
        if ctypes.util.find_library(library):
            os.environ["MUJOCO_GL"] = backend
            os.environ.setdefault("PYOPENGL_PLATFORM", backend)
            return backend
    return None
