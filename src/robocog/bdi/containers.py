"""Jason's mutable collections as terms: the set of ``.set.*`` and the queue of ``.queue.*``.

A program keeps such a collection in a variable and changes it in place (``.set.add(S,
x)``, ``.queue.remove(Q, X)``), also inside rules, where backtracking does not undo the
change: that is what makes them useful for a search written as rules (Jason's A* demo
keeps its open queue and closed set this way). They are terms like any other, so they
unify (a set with a set of the same members, a queue only with itself, as in Jason),
print (a set as ``{a,b}`` in term order, a queue as Java prints its collection) and are
ground.

The priority queue orders its members by Jason's term order with the binary heap of
Java's ``PriorityQueue``, step for step: members that compare equal leave it in the
order Java's heap gives them, so a search that breaks ties by it finds the same path
as on Jason.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Iterator

from robocog.bdi.terms import Term, compare, sorted_terms, term_str


class SetTerm:
    """A set of terms (Java's ``TreeSet`` in Jason): members equal in term order once."""

    __slots__ = ("_items",)

    #: a set holds ground terms only in practice, and is never renamed or resolved
    ground = True

    def __init__(self, items: Iterable[Term] = ()) -> None:
        self._items: dict[Term, None] = dict.fromkeys(items)

    def add(self, t: Term) -> None:
        """Put ``t`` in (nothing changes when it is there already)."""
        self._items[t] = None

    def remove(self, t: Term) -> None:
        """Take ``t`` out (nothing changes when it is not there)."""
        self._items.pop(t, None)

    def clear(self) -> None:
        """Take every member out."""
        self._items.clear()

    def retain(self, keep: Iterable[Term]) -> None:
        """Keep only the members that are also in ``keep`` (the intersection)."""
        other = set(keep)
        self._items = {t: None for t in self._items if t in other}

    def __contains__(self, t: object) -> bool:
        return t in self._items

    def __len__(self) -> int:
        return len(self._items)

    def members(self) -> list[Term]:
        """The members in Jason's term order (the order a ``TreeSet`` iterates in)."""
        return sorted_terms(list(self._items))

    def __iter__(self) -> Iterator[Term]:
        return iter(self.members())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, SetTerm) and self._items.keys() == other._items.keys()

    def __hash__(self) -> int:
        return hash(frozenset(self._items))

    def __str__(self) -> str:
        return "{" + ",".join(term_str(t) for t in self.members()) + "}"

    __repr__ = __str__


class QueueTerm:
    """A queue of terms: first in, first out, or, made with ``priority``, least first in
    Jason's term order (Java's ``PriorityBlockingQueue``, whose heap is reproduced)."""

    __slots__ = ("priority", "_fifo", "_heap")

    ground = True

    def __init__(self, priority: bool = False) -> None:
        self.priority = priority
        self._fifo: deque[Term] = deque()
        self._heap: list[Term] = []

    def offer(self, t: Term) -> None:
        """Add ``t`` (at the end, or where the heap's sift-up puts it)."""
        if not self.priority:
            self._fifo.append(t)
            return
        heap = self._heap
        heap.append(t)
        k = len(heap) - 1
        while k > 0:
            parent = (k - 1) >> 1
            e = heap[parent]
            if compare(t, e) >= 0:
                break
            heap[k] = e
            k = parent
        heap[k] = t

    def peek(self) -> Term | None:
        """The first member, or None when the queue is empty."""
        if not self.priority:
            return self._fifo[0] if self._fifo else None
        return self._heap[0] if self._heap else None

    def poll(self) -> Term | None:
        """Take the first member out and return it (None when the queue is empty)."""
        if not self.priority:
            return self._fifo.popleft() if self._fifo else None
        heap = self._heap
        if not heap:
            return None
        first = heap[0]
        x = heap.pop()
        n = len(heap)
        if n:
            # Java's siftDown: the last member goes down from the root
            k = 0
            half = n >> 1
            while k < half:
                child = 2 * k + 1
                c = heap[child]
                right = child + 1
                if right < n and compare(c, heap[right]) > 0:
                    child = right
                    c = heap[child]
                if compare(x, c) <= 0:
                    break
                heap[k] = c
                k = child
            heap[k] = x
        return first

    def clear(self) -> None:
        """Take every member out."""
        self._fifo.clear()
        self._heap.clear()

    def members(self) -> list[Term]:
        """The members in the order Java iterates them (a heap in its array's order)."""
        return list(self._heap) if self.priority else list(self._fifo)

    def copy(self) -> QueueTerm:
        """A new queue of the same kind with the same members."""
        q = QueueTerm(self.priority)
        q._fifo = deque(self._fifo)
        q._heap = list(self._heap)
        return q

    def __len__(self) -> int:
        return len(self._heap) if self.priority else len(self._fifo)

    def __iter__(self) -> Iterator[Term]:
        return iter(self.members())

    def __str__(self) -> str:
        # Java's AbstractCollection.toString
        return "[" + ", ".join(term_str(t) for t in self.members()) + "]"

    __repr__ = __str__
