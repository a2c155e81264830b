"""Memory files on disk: written atomically, read within bounds, known by their header.

The bytes of a saved memory, below :mod:`robocog.nars.memfile` (which turns them into a
reasoner's state and back): a gzip stream (plain JSON is read too) that must start with
the format's header, bounded in size on disk and once decompressed; a pickle of an
earlier robocog is recognised and refused; a save replaces the file atomically and
removes what killed saves left behind; ``*save``/``*load`` names stay inside their
directory.
"""

from __future__ import annotations

import os
import re
import stat
import time as _time
import zlib
from pathlib import Path

from robocog import atomic

FORMAT = "robocog-nar-memory"
#: how a robocog memory file starts, once decompressed: its first field is the format
HEADER = re.compile(rb'\s*\{\s*"format"\s*:\s*"' + FORMAT.encode() + rb'"')
#: enough decompressed bytes to see the header
HEADER_BYTES = 256
#: bounds on what a file may make the reader hold: its size on disk, its size once
#: decompressed (a small file can inflate a thousandfold)
MAX_FILE_BYTES = 1 << 30
MAX_JSON_BYTES = 2 << 30
#: a compressed file may expand to at most this many times its size (robocog's memories
#: expand about tenfold; a gzip bomb a thousandfold), and always to this many bytes
MAX_EXPANSION = 40
MIN_EXPANDED_BYTES = 32 << 20
#: a temporary file of a save is removed by the next save of the same memory (or the
#: start of a session saving it) once its writer is gone, or in any case once it is older
#: than this (a save killed outright, e.g. by SIGKILL, cannot clean up itself)
STALE_TMP_SECONDS = 600.0
PICKLE_HINT = (
    "it is a pickle (robocog's memory format before version 1, or any pickle), refused "
    "because loading a pickle can run code; if you trust the file and its author, convert "
    "it once with `python tools/convert_pickle_memory.py --trust OLD NEW`"
)


class MemoryFileError(ValueError):
    """A memory file that cannot be read or written; the message is one line that says
    which file and what is wrong with it."""


def zlib_gzip(data: bytes) -> bytes:
    """``data`` gzip-compressed, without a time stamp (equal states, equal files)."""
    c = zlib.compressobj(6, zlib.DEFLATED, 31)
    return c.compress(data) + c.flush()


def write_file(path: str | os.PathLike[str], data: bytes) -> None:
    """Write a memory file atomically (readers see the old file or the new one), mode
    0600, removing what interrupted saves of the same file left behind."""
    target = Path(path)
    if target.is_dir():
        raise MemoryFileError(f"{target}: is a directory")
    if target.exists() and not is_memory_file(target):
        raise MemoryFileError(f"{target}: exists and is not a robocog memory; not overwritten")
    _sweep_stale(target)
    try:
        atomic.write_bytes(target, data, mode=0o600)  # a memory is its owner's alone
    except OSError as exc:
        raise MemoryFileError(f"{target}: cannot be written: {exc.strerror or exc}") from None


def _sweep_stale(target: Path) -> None:
    """Remove temporary files of earlier saves of ``target`` that were killed midway."""
    folder = target.parent
    if not folder.is_dir():
        return
    cutoff = _time.time() - STALE_TMP_SECONDS
    for p in folder.glob(f".{_glob_escape(target.name)}.*.tmp"):
        try:
            if not p.is_file() or p.is_symlink():
                continue
            if not atomic.writer_alive(p, target.name) or p.stat().st_mtime < cutoff:
                p.unlink()
        except OSError:
            pass


def sweep_stale(path: str | os.PathLike[str]) -> None:
    """Remove what killed saves of ``path`` left behind (a session's start does this
    for its ``--save`` file, a save for its own)."""
    _sweep_stale(Path(path))


def _glob_escape(name: str) -> str:
    return "".join(f"[{ch}]" if ch in "*?[" else ch for ch in name)


def _open_regular(path: str | os.PathLike[str]) -> int:
    """A descriptor of the regular file at ``path``; anything else (a FIFO, a device such
    as /dev/zero, a socket, a folder) is refused at once, before any read could block
    or run without end. (Opened without blocking, then checked on the descriptor, so
    the file checked is the file read.)"""
    name = str(path)
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except IsADirectoryError:
        raise MemoryFileError(f"{name}: is a directory") from None
    except OSError as exc:
        raise MemoryFileError(f"{name}: cannot be read: {exc.strerror or exc}") from None
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        what = "a directory" if stat.S_ISDIR(mode) else "not a regular file"
        raise MemoryFileError(f"{name}: {what}; a memory is read from a regular file only")
    os.set_blocking(fd, True)
    return fd


def is_memory_file(path: str | os.PathLike[str]) -> bool:
    """True if the file at ``path`` starts as a robocog memory file does."""
    try:
        fd = _open_regular(path)
    except MemoryFileError:
        return False
    with os.fdopen(fd, "rb") as f:
        try:
            head = f.read(4096)
        except OSError:
            return False
    if head[:2] == b"\x1f\x8b":
        try:
            head = zlib.decompressobj(31).decompress(head, HEADER_BYTES)
        except zlib.error:
            return False
    return HEADER.match(head) is not None


def expansion_bound(compressed: int) -> int:
    """The most bytes a compressed file of ``compressed`` bytes may expand to."""
    return min(MAX_JSON_BYTES, max(MIN_EXPANDED_BYTES, MAX_EXPANSION * compressed))


def _expanded_size(raw: bytes, bound: int, name: str) -> int:
    """How many bytes ``raw`` decompresses to, counted up to ``bound + 1``."""
    d = zlib.decompressobj(31)
    total = 0
    data = raw
    try:
        while total <= bound and not d.eof:
            got = len(d.decompress(data, 1 << 20))
            total += got
            data = d.unconsumed_tail
            if not data and not got:
                break  # all input taken, no output pending: a truncated stream
    except zlib.error as exc:
        raise MemoryFileError(f"{name}: damaged compressed data ({exc})") from None
    return total


def read_file(path: str | os.PathLike[str]) -> bytes:
    """The JSON text of the memory file at ``path``, decompressed within the bounds."""
    name = str(path)
    fd = _open_regular(path)
    with os.fdopen(fd, "rb") as f:
        size = os.fstat(fd).st_size
        if size > MAX_FILE_BYTES:
            raise MemoryFileError(f"{name}: larger than {MAX_FILE_BYTES} bytes (MAX_FILE_BYTES)")
        try:
            # (the size on disk, not the bound: a read of n bytes reserves n at once)
            raw = f.read(size + 1)
        except OSError as exc:
            raise MemoryFileError(f"{name}: cannot be read: {exc.strerror or exc}") from None
    if len(raw) > MAX_FILE_BYTES:
        raise MemoryFileError(f"{name}: larger than {MAX_FILE_BYTES} bytes (MAX_FILE_BYTES)")
    if not raw:
        raise MemoryFileError(f"{name}: empty file, not a robocog memory")
    if raw[:1] == b"\x80":
        raise MemoryFileError(f"{name}: {PICKLE_HINT}")
    if raw[:2] == b"\x1f\x8b":
        bound = expansion_bound(len(raw))
        # a first pass measures the expansion a megabyte at a time, holding none of
        # it, so that a gzip bomb is refused without ever being held
        size = _expanded_size(raw, bound, name)
        d = zlib.decompressobj(31)
        try:
            data = d.decompress(raw, min(size, bound) + 1) if size <= bound else b""
        except zlib.error as exc:
            raise MemoryFileError(f"{name}: damaged compressed data ({exc})") from None
        if size > bound or len(data) > bound:
            raise MemoryFileError(
                f"{name}: decompresses to more than {bound} bytes ({MAX_EXPANSION} times its "
                f"size, at least {MIN_EXPANDED_BYTES}, at most {MAX_JSON_BYTES}): not a "
                "memory robocog saved"
            )
        if not d.eof:
            raise MemoryFileError(f"{name}: truncated (the compressed data ends early)")
        if d.unused_data:
            raise MemoryFileError(
                f"{name}: {len(d.unused_data)} bytes after the compressed memory "
                "(a second member or trailing data); refused"
            )
        raw = data
    if HEADER.match(raw[:HEADER_BYTES]) is None:
        start = raw[:16]
        raise MemoryFileError(f"{name}: not a robocog memory (it starts with {start!r})")
    return raw


def path_in(directory: str | os.PathLike[str] | None, name: str) -> Path:
    """The file ``name`` inside ``directory``, for ``*save``/``*load`` lines of an input
    stream: refused (MemoryFileError) without a directory, for absolute names, names
    with ``..`` and names that lead out of the directory through a symbolic link."""
    if directory is None:
        raise MemoryFileError(
            "*save and *load need a memory directory (robocog nar --memory-dir DIR)"
        )
    if not name or "\x00" in name or len(name) > 4096:
        raise MemoryFileError("a memory file name is needed")
    rel = Path(name)
    if rel.is_absolute() or name.startswith(("/", "\\", "~")):
        raise MemoryFileError(f"{name}: absolute names are refused; name a file in {directory}")
    if any(part == ".." for part in rel.parts) or "\\" in name:
        raise MemoryFileError(f"{name}: names with '..' or '\\' are refused")
    root = Path(os.path.realpath(directory))
    target = root / rel
    if target.is_symlink():
        raise MemoryFileError(f"{name}: is a symbolic link; refused")
    real = Path(os.path.realpath(target))
    if real != root and root not in real.parents:
        raise MemoryFileError(f"{name}: leads out of the memory directory; refused")
    return real
