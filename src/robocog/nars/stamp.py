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
    longer = a if la > lb else b
    m = la + lb
    if m > size:
        m = size
    # the first m ids of a0, b0, ..., a(n-1), b(n-1), then the longer stamp's tail,
    # each put in its place (compiled: C indexes into one list of the final length,
    # see stamp.pxd; predictions merge stamps hundreds of times per input)
    out: list = [None] * m
    k = 0
    while k < m:
        if k < 2 * n:
            out[k] = b[k >> 1] if k & 1 else a[k >> 1]
        else:
            out[k] = longer[k - n]
        k += 1
    return tuple(out)


def overlap(a: Stamp, b: Stamp) -> bool:
    """True if the two bases share evidence."""
    # a stamp holds at most ``STAMP_SIZE`` ids: comparing them pairwise costs less than
    # building a set, compiled (the ids as C longs, see stamp.pxd) by far; an input's
    # stamp of one id too (``a[0] in b`` compares Python integers)
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
            y = a[j]  # (compiled, a C long like ``x``: no integer object made to compare)
            if y == x:
                return True
    return False


def fmt(a: Stamp) -> str:
    """ONA's printed form ``[i,j,...]``."""
    return "[" + ",".join(str(i) for i in a) + "]"
