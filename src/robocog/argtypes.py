"""Argument types shared by every ``robocog`` command: numbers within a range, files that
exist, folders that can be made.

A command line is user input like any other: a negative count, a NaN time limit or a
report folder under a file must be refused before any work starts, with one line that
names the option and what it accepts, rather than run silently with a nonsense value or
end in a traceback minutes later. argparse calls these types while it reads the line and
turns their :class:`argparse.ArgumentTypeError` into ``robocog CMD: error: argument
--opt: ...`` and exit status 2.

Each type is an object that knows its own range (``lo``/``hi`` of a number, ``kind`` of a
path), so that a test can walk every command's options and try values outside it. This
module imports nothing of robocog, so every package may use it.
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

#: the largest seed: numpy's generators take seeds below 2**32
SEED_MAX = 2**32 - 1
#: longest number text read: a 20-digit number is a typo, not a count
_MAX_DIGITS = 18


def _number_text(text: str) -> str:
    s = text.strip()
    if not s:
        raise argparse.ArgumentTypeError("expected a number, got an empty value")
    if len(s) > 40:
        raise argparse.ArgumentTypeError(f"expected a number, got {s[:20]}... ({len(s)} chars)")
    return s


class IntRange:
    """A whole number from ``lo`` to ``hi`` (inclusive); ``what`` says what it counts."""

    kind = "int"

    def __init__(self, lo: int, hi: int, what: str = "") -> None:
        self.lo, self.hi, self.what = lo, hi, what
        self.__name__ = "integer"  # argparse names the type in some messages

    def allowed(self) -> str:
        """The range in words, for messages and help."""
        unit = f" {self.what}" if self.what else ""
        return f"a whole number from {self.lo:,} to {self.hi:,}{unit}"

    def __call__(self, text: str) -> int:
        s = _number_text(text)
        digits = s.lstrip("+-")
        if not digits.isdigit():
            raise argparse.ArgumentTypeError(f"expected {self.allowed()}, got {s!r}")
        if len(digits) > _MAX_DIGITS:
            raise argparse.ArgumentTypeError(
                f"{s[:12]}... ({len(digits)} digits) is too large: expected {self.allowed()}"
            )
        value = int(s)
        if not self.lo <= value <= self.hi:
            raise argparse.ArgumentTypeError(f"expected {self.allowed()}, got {value}")
        return value

    def __repr__(self) -> str:
        return f"IntRange({self.lo}, {self.hi})"


class FloatRange:
    """A finite number from ``lo`` to ``hi``; ``lo_open`` excludes ``lo`` itself (a time
    limit of 0 s means nothing)."""

    kind = "float"

    def __init__(self, lo: float, hi: float, unit: str = "", *, lo_open: bool = False) -> None:
        self.lo, self.hi, self.unit, self.lo_open = lo, hi, unit, lo_open
        self.__name__ = "number"

    def allowed(self) -> str:
        """The range in words, for messages and help."""
        unit = f" {self.unit}" if self.unit else ""
        above = "above" if self.lo_open else "from"
        return f"a number {above} {self.lo:g} up to {self.hi:g}{unit}"

    def __call__(self, text: str) -> float:
        s = _number_text(text)
        try:
            value = float(s)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {self.allowed()}, got {s!r}") from None
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"expected {self.allowed()}, got {s!r}")
        too_low = value <= self.lo if self.lo_open else value < self.lo
        if too_low or value > self.hi:
            raise argparse.ArgumentTypeError(f"expected {self.allowed()}, got {value:g}")
        return value

    def __repr__(self) -> str:
        return f"FloatRange({self.lo}, {self.hi})"


def int_range(lo: int, hi: int, what: str = "") -> IntRange:
    """A whole number from ``lo`` to ``hi``."""
    return IntRange(lo, hi, what)


def positive_int(hi: int = 10**9, what: str = "") -> IntRange:
    """A count of at least 1 (runs, cycles, iterations)."""
    return IntRange(1, hi, what)


def count(hi: int = 10**9, what: str = "") -> IntRange:
    """A count that may be 0 (0: skip that part)."""
    return IntRange(0, hi, what)


def seconds(hi: float = 7 * 24 * 3600.0) -> FloatRange:
    """A duration in seconds above 0 (at most a week by default)."""
    return FloatRange(0.0, hi, "s", lo_open=True)


def fraction() -> FloatRange:
    """A probability or share, from 0 to 1."""
    return FloatRange(0.0, 1.0)


#: a random seed
SEED = IntRange(0, SEED_MAX)
#: a TCP port; 0 lets the system choose a free one
PORT = IntRange(0, 65535)
#: a DDS domain of ROS 2 (the specification allows 0 to 232)
DDS_DOMAIN = IntRange(0, 232)


def _where(path: Path) -> str:
    return str(path) if len(str(path)) <= 120 else f"{str(path)[:117]}..."


class PathType:
    """A path checked for what the command does with it.

    ``kind`` is one of ``file`` (read: must be a regular file), ``dir`` (read: must be a
    folder), ``new-file`` (written: its folder must exist, and it must not be a folder)
    and ``new-dir`` (written: created with its parents, so the nearest existing one must
    be a folder one may write in).
    """

    def __init__(self, kind: str, as_path: bool = True) -> None:
        if kind not in ("file", "dir", "new-file", "new-dir"):
            raise ValueError(f"unknown path kind {kind!r}")
        self.kind, self.as_path = kind, as_path
        self.__name__ = "path"

    def __call__(self, text: str) -> Path | str:
        if not text or "\0" in text:
            raise argparse.ArgumentTypeError(f"expected a path, got {text!r}")
        path = Path(text).expanduser()
        where = _where(path)
        if self.kind == "file":
            if not path.exists():
                missing = _missing_folder(path)
                if missing is not None:
                    raise argparse.ArgumentTypeError(f"no folder {_where(missing)}")
                raise argparse.ArgumentTypeError(f"no such file: {where}")
            if not path.is_file():
                raise argparse.ArgumentTypeError(f"{where} is not a regular file")
            if not os.access(path, os.R_OK):
                raise argparse.ArgumentTypeError(f"cannot read {where}: permission denied")
        elif self.kind == "dir":
            if not path.is_dir():
                what = "" if path.exists() else " (it does not exist)"
                raise argparse.ArgumentTypeError(f"{where} is not a directory{what}")
        elif self.kind == "new-file":
            if path.is_dir():
                raise argparse.ArgumentTypeError(f"{where} is a directory; give a file name")
            folder = path.parent
            if not folder.is_dir():
                what = "is not a folder" if folder.exists() else "does not exist"
                raise argparse.ArgumentTypeError(f"cannot write {where}: {_where(folder)} {what}")
            if not os.access(folder, os.W_OK):
                raise argparse.ArgumentTypeError(f"cannot write in {_where(folder)}")
        else:
            if path.exists() and not path.is_dir():
                raise argparse.ArgumentTypeError(f"{where} exists and is not a folder")
            nearest = path
            while not nearest.exists() and nearest != nearest.parent:
                nearest = nearest.parent
            if not nearest.is_dir():
                raise argparse.ArgumentTypeError(
                    f"cannot make the folder {where}: {_where(nearest)} is not a folder"
                )
            if not os.access(nearest, os.W_OK):
                raise argparse.ArgumentTypeError(
                    f"cannot make {where}: {_where(nearest)} is read-only"
                )
        return path if self.as_path else str(path)

    def __repr__(self) -> str:
        return f"PathType({self.kind!r})"


def _missing_folder(path: Path) -> Path | None:
    """The first folder of ``path`` that does not exist (None when its folder exists)."""
    folder = path.parent
    if folder.is_dir():
        return None
    while not folder.parent.is_dir() and folder != folder.parent:
        folder = folder.parent
    return folder


#: the path checks; a test tells an option's kind from its type
EXISTING_FILE = PathType("file")
EXISTING_DIR = PathType("dir")
NEW_FILE = PathType("new-file")
NEW_DIR = PathType("new-dir")
#: the same, giving ``str`` (for options whose code takes a string)
EXISTING_FILE_STR = PathType("file", as_path=False)
EXISTING_DIR_STR = PathType("dir", as_path=False)
NEW_FILE_STR = PathType("new-file", as_path=False)
NEW_DIR_STR = PathType("new-dir", as_path=False)
