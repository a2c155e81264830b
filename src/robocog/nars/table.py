"""Implication tables: bounded, sorted by truth expectation, revising equal terms.

Each concept keeps one table of ``==>`` links and one table of ``=/>`` links per
operation id, so a decision looks only at the implications that can reach its goal.
"""

from __future__ import annotations

from bisect import bisect_left, bisect_right

from .event import Implication
from .stamp import Size, Stamp, merge, overlap
from .terms import Term
from .truth import Truth, c2w, expectation, pooled


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

    def __reduce__(self) -> tuple[object, ...]:
        # by its fields, so that the compiled and the pure engine read each other's saves
        return (_restored, (self.size, self.items, self._neg, self._entry))

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

    def _replace(self, old: Implication, new: Implication) -> None:
        """Put ``new`` in the stored entry ``old``'s stead, after every other entry of
        equal or higher expectation (where taking ``old`` out and inserting ``new`` would
        put it). ``old`` is found by its expectation, then identity; a revision moves an
        entry by a few places at most, so when it stays put no list is shifted, and
        otherwise only the side it moved to is searched."""
        items = self.items
        neg = self._neg
        # minus the expectations, written out (this runs for every revision)
        t = old.truth
        e_old = -(t.c * (t.f - 0.5) + 0.5)
        i = bisect_left(neg, e_old)
        while items[i] is not old:
            i += 1
        t = new.truth
        e = -(t.c * (t.f - 0.5) + 0.5)
        last = len(neg) - 1
        if (i == 0 or neg[i - 1] <= e) and (i == last or neg[i + 1] > e):
            items[i] = new
            neg[i] = e
        else:
            del items[i]
            del neg[i]
            # the entries before i were <= e_old, those after it >= e_old
            j = bisect_right(neg, e, i) if e >= e_old else bisect_right(neg, e, 0, i)
            items.insert(j, new)
            neg.insert(j, e)
        entry = self._entry
        zero = new.dt == 0.0
        if zero is not (old.dt == 0.0) or new.term is not old.term:
            del entry[old.term, old.dt == 0.0]
        entry[new.term, zero] = new

    def add_and_revise(self, imp: Implication, stamp_size: Size = 10) -> Implication | None:
        """Revise with the entry of the same term (or insert); returns the stored entry."""
        # a concurrent (dt 0) and a predictive (dt > 0) link of one term stay apart
        old = self._entry.get((imp.term, imp.dt == 0.0))
        if old is None:
            return imp if self._insert(imp) else None
        if imp.term.op == "==>" and overlap(old.stamp, imp.stamp):
            keep = imp if imp.truth.c > old.truth.c else old
            self._replace(old, keep)
            return keep
        return self._revise(old, imp, imp.truth, c2w(imp.truth.c), imp.stamp, stamp_size)

    def add_failure(self, imp: Implication, truth: Truth, weight: float, stamp_size: Size) -> None:
        """``add_and_revise(Implication(imp.term, truth, (), imp.dt, imp.creation_time,
        imp.source))`` without making that implication: anticipation counts one failure
        (evidence without a stamp) against hundreds of links per input. ``weight`` is
        ``c2w(truth.c)``, the same for all of them."""
        old = self._entry.get((imp.term, imp.dt == 0.0))
        if old is None:
            self._insert(Implication(imp.term, truth, (), imp.dt, imp.creation_time, imp.source))
            return
        # an empty stamp overlaps nothing: never the ``==>`` case of add_and_revise
        self._revise(old, imp, truth, weight, (), stamp_size)

    def _revise(
        self,
        old: Implication,
        imp: Implication,
        truth: Truth,
        weight: float,
        stamp: Stamp,
        stamp_size: Size,
    ) -> Implication:
        """Replace ``old`` by its revision with ``imp`` carrying ``truth`` (of evidence
        weight ``weight``) and ``stamp``; the offset is the weights' mean of both."""
        w1 = c2w(old.truth.c)
        dt = (w1 * old.dt + weight * imp.dt) / (w1 + weight) if w1 + weight > 0 else imp.dt
        # merged with no ids, a stamp is itself cut to size
        kept = old.stamp
        if stamp or len(kept) > stamp_size:
            kept = merge(kept, stamp, stamp_size)
        revised = Implication(
            imp.term, pooled(old.truth, truth, w1, weight), kept, dt, imp.creation_time, imp.source
        )
        self._replace(old, revised)
        return revised


def _restored(
    size: int,
    items: list[Implication],
    neg: list[float],
    entry: dict[tuple[Term, bool], Implication],
) -> Table:
    """A table as :meth:`Table.__reduce__` saved it."""
    table = Table(size)
    table.items = items
    table._neg = neg
    table._entry = entry
    return table


def restored_table(size: int, items: list[Implication]) -> Table:
    """A table holding ``items`` in their order (best expectation first), as a saved
    memory lists them; the expectations and the entry index are computed as
    :meth:`Table._insert` does."""
    table = Table(size)
    table.items = list(items)
    table._neg = [-expectation(m.truth) for m in items]
    table._entry = {(m.term, m.dt == 0.0): m for m in items}
    return table
