"""Evidential bases (stamps).

A stamp is the tuple of input ids whose evidence a sentence rests on, newest first, at
most STAMP_SIZE long. Two premises whose stamps share an id would count the same
evidence twice, so inference and revision refuse them.
"""

from __future__ import annotations

STAMP_SIZE = 10

Stamp = tuple[int, ...]


def merge(a: Stamp, b: Stamp, size: int = STAMP_SIZE) -> Stamp:
    """Interleave a0, b0, a1, b1, ... and keep the first ``size`` ids (ONA's zip)."""
    out: list[int] = []
    la, lb = len(a), len(b)
    for i in range(max(la, lb)):
        if i < la:
            out.append(a[i])
        if i < lb:
            out.append(b[i])
        if len(out) >= size:
            break
    return tuple(out[:size])


def overlap(a: Stamp, b: Stamp) -> bool:
    """True if the two bases share evidence."""
    if len(a) < len(b):
        a, b = b, a
    sb = set(b)
    return any(x in sb for x in a)


def has_duplicate(a: Stamp) -> bool:
    """True if one id occurs twice (the sentence double-counts its own evidence)."""
    return len(set(a)) != len(a)


def fmt(a: Stamp) -> str:
    """ONA's printed form ``[i,j,...]``."""
    return "[" + ",".join(str(i) for i in a) + "]"
