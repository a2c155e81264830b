"""Atomic file writes: a reader sees the old file or the new one, never half of either.

Saved memories, experiment results and reports are written to a temporary file in the
same folder (so the rename stays on one file system), flushed to disk, then renamed over
the target. A process killed in between leaves the previous file as it was. Every
package may use this module: it knows nothing of engines or robots.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any


def write_bytes(path: str | os.PathLike[str], data: bytes) -> None:
    """Replace the file at ``path`` with ``data`` in one step, creating its folder."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    # the writer's process id is in the name: a later writer removes at once the
    # temporary file of one killed outright (see ``writer_alive``)
    prefix = f".{target.name}.{os.getpid()}."
    fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=prefix, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def writer_alive(temporary: str | os.PathLike[str], target_name: str) -> bool:
    """Whether the process that made ``temporary`` (a file :func:`write_bytes` made for
    ``target_name``) may still be writing it: False once that process is gone."""
    rest = Path(temporary).name[len(target_name) + 2 :]
    pid_text = rest.split(".", 1)[0]
    if not pid_text.isdigit():
        return True  # (a name from before process ids were in it: age decides)
    pid = int(pid_text)
    if pid == os.getpid():
        return False  # this process writes one file at a time, in write_bytes
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, OSError):
        return True
    return True


def write_text(path: str | os.PathLike[str], text: str) -> None:
    """Replace the file at ``path`` with ``text`` (UTF-8) in one step."""
    write_bytes(path, text.encode("utf-8"))


def write_json(path: str | os.PathLike[str], payload: Any) -> None:
    """Replace the file at ``path`` with ``payload`` as indented JSON in one step."""
    write_text(path, json.dumps(payload, indent=2) + "\n")
