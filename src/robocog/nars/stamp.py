"""Evidential bases (stamps).

A stamp is the tuple of input ids whose evidence a sentence rests on, newest first, at
most STAMP_SIZE long. Two premises whose stamps share an id would count the same
evidence twice, so inference and revision refuse them.
"""

from __future__ import annotations

STAMP_SIZE = 10

Stamp = tuple[int, ...]
#: a stamp's length (the compiled engine declares it a C long)
Size = int


def merge(a: Stamp, b: Stamp, size: Size = STAMP_SIZE) -> Stamp:
    """Interleave a0, b0, a1, b1, ... and keep the first ``size`` ids (ONA's zip)."""
    if not b:  # negative evidence has an empty stamp
        return a if len(a) <= size else a[:size]
    if not a:
        return b if len(b) <= size else b[:size]
    la = len(a)
    lb = len(b)
    n = la if la < lb else lb
    # one pass, stopping once ``size`` ids are taken (compiled: C indexes, see stamp.pxd)
    out: list = []
    i = 0
    while i < n and len(out) < size:
        out.append(a[i])
        out.append(b[i])
        i += 1
    if len(out) < size:
        out += a[n:] if la > n else b[n:]  # the longer stamp's tail follows
    return tuple(out[:size])


def overlap(a: Stamp, b: Stamp) -> bool:
    """True if the two bases share evidence."""
    if len(a) == 1:  # an input's stamp: a tuple scan
        return a[0] in b
    # a stamp holds at most ``STAMP_SIZE`` ids: comparing them pairwise costs less than
    # building a set, compiled (the ids as C longs, see stamp.pxd) by far
    for x in a:
        for y in b:
            if x == y:
                return True
    return False


def has_duplicate(a: Stamp) -> bool:
    """True if one id occurs twice (the sentence double-counts its own evidence)."""
    # at most ``STAMP_SIZE`` ids: pairwise comparisons, compiled with C longs, cost less
    # than building a set
    n = len(a)
    for i in range(1, n):
        x = a[i]
        for j in range(i):
            if a[j] == x:
                return True
    return False


def fmt(a: Stamp) -> str:
    """ONA's printed form ``[i,j,...]``."""
    return "[" + ",".join(str(i) for i in a) + "]"
