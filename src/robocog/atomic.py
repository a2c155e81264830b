"""Atomic file writes: a reader sees the old file or the new one, never half of either.

Saved memories, experiment results and reports are written to a temporary file in the
same folder (so the rename stays on one file system), flushed to disk, then renamed over
the target. A process killed in between leaves the previous file as it was. The new
file gets the permissions a plain ``open(path, "w")`` would give it: an existing file's
own, else those the user's umask allows (not the owner-only mode of a private temporary
file, which would make a report unreadable to the group that can read its plots). Every
package may use this module: it knows nothing of engines or robots.
"""

from __future__ import annotations

import json
import os
import secrets
import stat
from pathlib import Path
from typing import Any


def write_bytes(path: str | os.PathLike[str], data: bytes, mode: int | None = None) -> None:
    """Replace the file at ``path`` with ``data`` in one step, creating its folder.

    ``mode`` gives the file those permissions whatever the umask (0o600 for a file that
    only its owner may read, as a saved memory); by default it gets what ``open`` gives.
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    # the writer's process id is in the name: a later writer removes at once the
    # temporary file of one killed outright (see ``writer_alive``)
    fd, tmp = _create_beside(target)
    try:
        with os.fdopen(fd, "wb") as f:
            if mode is not None:
                os.fchmod(f.fileno(), mode)
            else:
                try:
                    os.fchmod(f.fileno(), stat.S_IMODE(os.stat(target).st_mode))  # its own
                except FileNotFoundError:
                    pass  # a new file: the mode the umask gave it at creation
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _create_beside(target: Path) -> tuple[int, Path]:
    """A new, empty file in ``target``'s folder, open for writing, and its path.

    Created with mode 0o666, so that the kernel applies the process's umask, as it does
    for any file a program opens for writing (``tempfile.mkstemp`` would force 0o600).
    """
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    for _ in range(100):
        tmp = target.parent / f".{target.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp"
        try:
            return os.open(tmp, flags, 0o666), tmp
        except FileExistsError:
            continue
    raise FileExistsError(f"{target.parent}: no free name for a temporary file")


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
