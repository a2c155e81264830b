"""The field checks of the memory file's reader (``memfile``): each value is checked
for type and range, a failure raising :class:`Bad` with where it is and what is wrong.

Each check has a fast path for a value that passes: a file has hundreds of thousands
of fields, and building the message of a failure that does not happen would be most
of the loading time.
"""

from __future__ import annotations

import math
from typing import Any

from robocog.limits import clip


class Bad(Exception):
    """A field that fails its check: ``where`` names it, ``what`` says why."""

    def __init__(self, where: str, what: str) -> None:
        super().__init__(f"{where}: {what}")
        self.where = where
        self.what = what


def check(ok: bool, where: str, what: str) -> None:
    """Raise Bad(where, what) unless ``ok``."""
    if not ok:
        raise Bad(where, what)


def int_in(v: object, where: str, lo: int, hi: int) -> int:
    """``v`` if it is an integer (not a boolean) in [lo, hi]."""
    if type(v) is int and lo <= v <= hi:
        return v
    if not (isinstance(v, int) and not isinstance(v, bool)):
        raise Bad(where, f"{show(v)} is not an integer")
    if not (lo <= v <= hi):  # type: ignore[operator]
        raise Bad(where, f"{show(v)} is out of range [{lo}, {hi}]")
    return v  # type: ignore[return-value]


def float_in(v: object, where: str, lo: float, hi: float) -> float:
    """``v`` as a float if it is a finite number (not a boolean) in [lo, hi]."""
    if type(v) is float and lo <= v <= hi and v - v == 0.0:
        return v
    ok = isinstance(v, int | float) and not isinstance(v, bool)
    if not ok:
        raise Bad(where, f"{show(v)} is not a number")
    if isinstance(v, float) and not math.isfinite(v):
        raise Bad(where, f"{v!r} is not finite")
    if not (lo <= v <= hi):  # type: ignore[operator]
        raise Bad(where, f"{show(v)} is out of range [{lo:g}, {hi:g}]")
    return float(v)  # type: ignore[arg-type]


def show(v: object) -> str:
    """A value from the file as an error message shows it: at most 40 characters."""
    try:
        text = repr(v)
    except ValueError:  # an integer past Python's digit limit for text
        return "a huge number"
    return clip(text, 40)


def boolean(v: object, where: str) -> bool:
    """``v`` if it is true or false."""
    if v is True or v is False:
        return v
    if not (isinstance(v, bool)):
        raise Bad(where, f"{show(v)} is not true or false")
    return v  # type: ignore[return-value]


def list_of(v: object, where: str, most: int) -> list[Any]:
    """``v`` if it is a list of at most ``most`` items."""
    if type(v) is list and len(v) <= most:
        return v
    if not (isinstance(v, list)):
        raise Bad(where, "is not a list")
    if not (len(v) <= most):  # type: ignore[arg-type]
        raise Bad(where, f"has {len(v)} items, at most {most} are allowed")
    return v  # type: ignore[return-value]


_KEYSETS: dict[tuple[str, ...], frozenset[str]] = {}


def object_of(v: object, where: str, keys: tuple[str, ...]) -> dict[str, Any]:
    """``v`` if it is an object with exactly the fields ``keys``."""
    want = _KEYSETS.get(keys)
    if want is None:
        want = _KEYSETS[keys] = frozenset(keys)
    if type(v) is dict and (tuple(v) == keys or v.keys() == want):
        # (the writer's order first: a tuple compares faster than a set is built)
        return v
    if not (isinstance(v, dict)):
        raise Bad(where, "is not an object")
    missing = sorted(want - v.keys())  # type: ignore[union-attr]
    if not (not missing):
        raise Bad(where, f"lacks {', '.join(missing)}")
    extra = sorted(v.keys() - want)  # type: ignore[union-attr]
    if not (not extra):
        raise Bad(where, f"has unknown fields {', '.join(extra)}")
    return v  # type: ignore[return-value]


def string(v: object, where: str, most: int) -> str:
    """``v`` if it is a string of at most ``most`` characters."""
    if not (isinstance(v, str)):
        raise Bad(where, f"{show(v)} is not a string")
    if not (len(v) <= most):  # type: ignore[arg-type]
        raise Bad(where, f"longer than {most} characters")
    return v  # type: ignore[return-value]
