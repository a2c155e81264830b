"""Implication tables: bounded, sorted by truth expectation, revising equal terms.

Each concept keeps one table of ``==>`` links and one table of ``=/>`` links per
operation id, so a decision looks only at the implications that can reach its goal.
"""

from __future__ import annotations

from .event import Implication, implication_of
from .stamp import Size, Stamp, merge, overlap
from .terms import Term
from .truth import Truth, c2w, expectation, pooled

#: a position in a table (the compiled engine declares it a C Py_ssize_t)
Index = int


def _bisect_left(neg: list, e: float, lo: Index, hi: Index) -> Index:
    """``bisect.bisect_left(neg, e, lo, hi)`` written out: compiled, a loop over the
    floats as C doubles instead of a call comparing float objects (anticipation revises
    hundreds of entries per input)."""
    while lo < hi:
        mid = (lo + hi) >> 1
        v = neg[mid]
        if v < e:
            lo = mid + 1
        else:
            hi = mid
    return lo


def _bisect_right(neg: list, e: float, lo: Index, hi: Index) -> Index:
    """``bisect.bisect_right(neg, e, lo, hi)`` written out, as :func:`_bisect_left`."""
    while lo < hi:
        mid = (lo + hi) >> 1
        v = neg[mid]
        if e < v:
            hi = mid
        else:
            lo = mid + 1
    return lo


class Table:
    """Add-and-revise table of implications, best expectation first."""

    __slots__ = ("items", "size", "_neg", "_predictive", "_concurrent")

    def __init__(self, size: int) -> None:
        self.items: list[Implication] = []
        self.size = size
        #: minus each item's expectation, ascending: kept beside the items so that
        #: placing a revised link is a bisection, not a recomputation of every entry
        self._neg: list[float] = []
        #: term -> the one entry of that term with a nonzero offset, and with offset 0
        #: (a predictive and a concurrent link of one term stay apart); anticipation
        #: revises hundreds of entries per input, so finding one must not be a scan,
        #: and the interned term alone is a cheaper key than a (term, kind) pair
        self._predictive: dict[Term, Implication] = {}
        self._concurrent: dict[Term, Implication] = {}

    def __reduce__(self) -> tuple[object, ...]:
        # by its fields, so that the compiled and the pure engine read each other's saves
        return (_restored, (self.size, self.items, self._neg))

    def __len__(self) -> int:
        return len(self.items)

    def __iter__(self):  # noqa: ANN204 - iterator of Implication
        return iter(self.items)

    def _entries(self, dt: float) -> dict[Term, Implication]:
        """The index of the entries whose offset is of the kind of ``dt``."""
        return self._concurrent if dt == 0.0 else self._predictive

    def _insert(self, imp: Implication) -> bool:
        """Place ``imp`` after every entry of equal or higher expectation; False if the
        full table dropped it at once."""
        neg = self._neg
        e = -expectation(imp.truth)
        i = _bisect_right(neg, e, 0, len(neg))
        self.items.insert(i, imp)
        neg.insert(i, e)
        self._entries(imp.dt)[imp.term] = imp
        if len(neg) > self.size:
            dropped: Implication = self.items.pop()
            neg.pop()
            del self._entries(dropped.dt)[dropped.term]
            return i < self.size
        return True

    def _replace(self, old: Implication, new: Implication, at: Index = -1) -> None:
        """Put ``new`` in the stored entry ``old``'s stead, after every other entry of
        equal or higher expectation (where taking ``old`` out and inserting ``new`` would
        put it). ``old`` is at ``at`` if that is not -1, else it is found by its
        expectation, then identity; a revision moves an entry by a few places at most,
        so when it stays put no list is shifted, and otherwise only the side it moved
        to is searched."""
        items = self.items
        neg = self._neg
        n = len(neg)
        # minus the expectations, written out (this runs for every revision)
        t = old.truth
        e_old = -(t.c * (t.f - 0.5) + 0.5)
        i = at
        if i < 0:
            i = _bisect_left(neg, e_old, 0, n)
            while items[i] is not old:
                i += 1
        t = new.truth
        e = -(t.c * (t.f - 0.5) + 0.5)
        # (the neighbours read into C doubles when compiled, then compared)
        stays = True
        if i > 0:
            v = neg[i - 1]
            stays = v <= e
        if stays and i < n - 1:
            v = neg[i + 1]
            stays = v > e
        if stays:
            items[i] = new
            neg[i] = e
        else:
            del items[i]
            del neg[i]
            # the entries before i were <= e_old, those after it >= e_old
            j = _bisect_right(neg, e, i, n - 1) if e >= e_old else _bisect_right(neg, e, 0, i)
            items.insert(j, new)
            neg.insert(j, e)
        zero = new.dt == 0.0
        if zero != (old.dt == 0.0) or new.term is not old.term:
            del self._entries(old.dt)[old.term]
        self._entries(new.dt)[new.term] = new

    def add_and_revise(self, imp: Implication, stamp_size: Size = 10) -> Implication | None:
        """Revise with the entry of the same term (or insert); returns the stored entry."""
        # a concurrent (dt 0) and a predictive (dt > 0) link of one term stay apart
        old = self._entries(imp.dt).get(imp.term)
        if old is None:
            return imp if self._insert(imp) else None
        if imp.term.op == "==>" and overlap(old.stamp, imp.stamp):
            keep = imp if imp.truth.c > old.truth.c else old
            self._replace(old, keep)
            return keep
        return self._revise(old, imp, imp.truth, c2w(imp.truth.c), imp.stamp, stamp_size)

    def add_failure(
        self, imp: Implication, truth: Truth, weight: float, stamp_size: Size, at: Index = -1
    ) -> None:
        """``add_and_revise(Implication(imp.term, truth, (), imp.dt, imp.creation_time,
        imp.source))`` without making that implication: anticipation counts one failure
        (evidence without a stamp) against hundreds of links per input. ``weight`` is
        ``c2w(truth.c)``. ``at`` is where the caller saw ``imp`` among the items, if it
        knows (anticipation walks a table in order): if ``imp`` is still there, or one
        place before (where an entry moving back past it puts it), it is the stored
        entry of its term, and neither the index nor the expectations are searched."""
        items = self.items
        if 0 <= at < len(items):
            if items[at] is imp:
                self._revise(imp, imp, truth, weight, (), stamp_size, at)
                return
            if at > 0 and items[at - 1] is imp:
                self._revise(imp, imp, truth, weight, (), stamp_size, at - 1)
                return
        old = self._entries(imp.dt).get(imp.term)
        if old is None:
            self._insert(implication_of(imp.term, truth, (), imp.dt, imp.creation_time, imp.source))
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
        at: Index = -1,
    ) -> Implication:
        """Replace ``old`` (at ``at`` among the items, if not -1) by its revision with
        ``imp`` carrying ``truth`` (of evidence weight ``weight``) and ``stamp``; the
        offset is the weights' mean of both."""
        w1 = c2w(old.truth.c)
        dt = (w1 * old.dt + weight * imp.dt) / (w1 + weight) if w1 + weight > 0 else imp.dt
        # merged with no ids, a stamp is itself cut to size
        kept = old.stamp
        if stamp or len(kept) > stamp_size:
            kept = merge(kept, stamp, stamp_size)
        revised = implication_of(
            imp.term, pooled(old.truth, truth, w1, weight), kept, dt, imp.creation_time, imp.source
        )
        self._replace(old, revised, at)
        return revised


def _restored(size: int, items: list[Implication], neg: list[float], *_: object) -> Table:
    """A table as :meth:`Table.__reduce__` saved it (earlier saves add the entry
    index, which is rebuilt from the items)."""
    table = Table(size)
    table.items = items
    table._neg = neg
    for m in items:
        table._entries(m.dt)[m.term] = m
    return table


def restored_table(size: int, items: list[Implication]) -> Table:
    """A table holding ``items`` in their order (best expectation first), as a saved
    memory lists them; the expectations and the entry index are computed as
    :meth:`Table._insert` does."""
    return _restored(size, list(items), [-expectation(m.truth) for m in items])
