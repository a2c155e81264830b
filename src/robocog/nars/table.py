"""Implication tables: bounded, sorted by truth expectation, revising equal terms.

Each concept keeps one table of ``==>`` links and one table of ``=/>`` links per
operation id, so a decision looks only at the implications that can reach its goal.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right

from .event import Implication
from .stamp import merge, overlap
from .terms import Term
from .truth import c2w, expectation, revision


class Table:
    """Add-and-revise table of implications, best expectation first."""

    __slots__ = ("items", "size", "_neg", "_entry")

    def __init__(self, size: int) -> None:
        self.items: list[Implication] = []
        self.size = size
        #: minus each item's expectation, ascending: kept beside the items so that
        #: placing a revised link is a bisection, not a recomputation of every entry
        self._neg: list[float] = []
        #: (term, whether dt is 0) -> the one entry of that term and kind; anticipation
        #: revises hundreds of entries per input, so finding one must not be a scan
        self._entry: dict[tuple[Term, bool], Implication] = {}

    def __len__(self) -> int:
        return len(self.items)

    def __iter__(self):  # noqa: ANN204 - iterator of Implication
        return iter(self.items)

    def _insert(self, imp: Implication) -> bool:
        """Place ``imp`` after every entry of equal or higher expectation; False if the
        full table dropped it at once."""
        neg = self._neg
        e = -expectation(imp.truth)
        i = bisect_right(neg, e)
        self.items.insert(i, imp)
        neg.insert(i, e)
        self._entry[imp.term, imp.dt == 0.0] = imp
        if len(neg) > self.size:
            dropped = self.items.pop()
            neg.pop()
            del self._entry[dropped.term, dropped.dt == 0.0]
            return i < self.size
        return True

    def _remove(self, old: Implication) -> None:
        """Take the stored entry ``old`` out (found by its expectation, then identity)."""
        items = self.items
        i = bisect_left(self._neg, -expectation(old.truth))
        while items[i] is not old:
            i += 1
        del items[i]
        del self._neg[i]
        del self._entry[old.term, old.dt == 0.0]

    def add_and_revise(self, imp: Implication, stamp_size: int = 10) -> Implication | None:
        """Revise with the entry of the same term (or insert); returns the stored entry."""
        # a concurrent (dt 0) and a predictive (dt > 0) link of one term stay apart
        old = self._entry.get((imp.term, imp.dt == 0.0))
        if old is None:
            return imp if self._insert(imp) else None
        if imp.term.op == "==>" and overlap(old.stamp, imp.stamp):
            keep = imp if imp.truth.c > old.truth.c else old
            self._remove(old)
            self._insert(keep)
            return keep
        w1, w2 = c2w(old.truth.c), c2w(imp.truth.c)
        dt = (w1 * old.dt + w2 * imp.dt) / (w1 + w2) if w1 + w2 > 0 else imp.dt
        revised = Implication(
            imp.term,
            revision(old.truth, imp.truth),
            merge(old.stamp, imp.stamp, stamp_size),
            dt,
            imp.creation_time,
            imp.source,
        )
        self._remove(old)
        self._insert(revised)
        return revised
