"""Non-Axiomatic Reasoning System compatible with OpenNARS for Applications (ONA).

Narsese terms, NAL truth functions, stamps, a bounded concept memory, declarative and
sensorimotor inference, decisions, and ONA's shell protocol. Imports nothing from the
robot side of robocog, so it can be used as a library by itself.

``robocog build`` compiles the engine's modules (see ``build.py``); they are used only
while the sources they were built from are unchanged. ``ENGINE`` says which engine
runs and, for the pure-Python one, why.
"""

from __future__ import annotations

import hashlib
import json
import os
import sys
from pathlib import Path


def _choose_engine(here: Path) -> tuple[str, Path | None]:
    """("compiled", its folder), or ("python (reason)", None)."""
    if os.environ.get("ROBOCOG_PURE_PYTHON"):
        return "python (ROBOCOG_PURE_PYTHON is set)", None
    folder = here / "_compiled"
    try:
        manifest = json.loads((folder / "manifest.json").read_text())
        sources = manifest["sources"]
        tag = manifest["cache_tag"]
    except (OSError, ValueError, KeyError, TypeError):
        return "python (not compiled: `robocog build` compiles it)", None
    if tag != sys.implementation.cache_tag:
        return f"python (compiled for {tag}, this is {sys.implementation.cache_tag})", None
    for name, digest in sources.items():
        try:
            now = hashlib.sha256((here / name).read_bytes()).hexdigest()
        except OSError:
            now = None
        if now != digest:
            return f"python ({name} changed since the engine was compiled; `robocog build`)", None
    return "compiled", folder


ENGINE, _folder = _choose_engine(Path(__file__).parent)
if _folder is not None:
    __path__.insert(0, str(_folder))  # the compiled modules are found first

from .nar import NAR  # noqa: E402 - after choosing where the engine's modules come from
from .narsese import NarseseError, parse_sentence, parse_term  # noqa: E402
from .terms import Term  # noqa: E402

__all__ = ["ENGINE", "NAR", "NarseseError", "Term", "parse_sentence", "parse_term"]
