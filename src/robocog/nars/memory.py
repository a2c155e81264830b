"""Bounded concept memory with an inverted atom index.

Concepts are kept in a dict (term -> concept) bounded by ``concepts_max``; when it is
full the least *useful* concepts (recently and often used ones are useful) are evicted
in a small batch, so the amortised cost of making room stays constant. The atom index
maps every name to the concepts whose term mentions it; it has no cap on the number of
names (ONA stops at 255 atoms), and is cleaned when a concept leaves.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from .event import ETERNAL, Event
from .table import Table
from .terms import Term


class Concept:
    """Everything the reasoner knows about one term."""

    __slots__ = (
        "id",
        "term",
        "use_count",
        "last_used",
        "belief",
        "belief_spike",
        "predicted_belief",
        "goal_spike",
        "precondition_beliefs",
        "implication_links",
        "priority",
        "priority_time",
        "selected_time",
        "process_id",
        "timed",
    )

    def __init__(self, cid: int, term: Term, now: int, operations: int, table_size: int) -> None:
        self.id = cid
        self.term = term
        self.use_count = 1
        self.last_used = now
        self.belief: Event | None = None
        self.belief_spike: Event | None = None
        self.predicted_belief: Event | None = None
        self.goal_spike: Event | None = None
        # index 0: implications without operation; i: those whose subject ends in op i
        # (made on first use: most concepts never hold an implication)
        self.precondition_beliefs: list[Table] | None = None
        self.implication_links: Table | None = None
        self.priority = 0.0
        self.priority_time = 0  # when ``priority`` was set (decay is applied lazily)
        self.selected_time = 0  # when an event of this concept was last selected (ONA: 0)
        self.process_id = 0
        self.timed = False  # ever entered the occurrence-time index (most never do)

    def use(self, now: int, eternal_input: bool, boost: int) -> None:
        """Record a use (input eternal beliefs count as very many uses)."""
        self.use_count += boost if eternal_input else 1
        self.last_used = now

    def tables(self, operations: int, size: int) -> list[Table]:
        """The precondition tables, made on first use."""
        if self.precondition_beliefs is None:
            self.precondition_beliefs = [Table(size) for _ in range(operations + 1)]
        return self.precondition_beliefs

    def usefulness(self, now: int) -> float:
        """u/(u+1) with u = uses per cycle since the last use."""
        u = self.use_count / (now - self.last_used + 1)
        return u / (u + 1.0)


def _key(e: Event) -> tuple[object, ...]:
    return (e.term, e.type, e.truth, e.stamp, e.occurrence_time)


class EventQueue:
    """Bounded max-priority queue of events (ONA's cycling events).

    Priorities live in a plain list beside the events, so finding the weakest or the
    strongest item is one C-level ``min``/``max`` over at most a few hundred floats.
    """

    __slots__ = ("events", "prio", "capacity", "keys")

    def __init__(self, capacity: int) -> None:
        self.events: list[Event] = []
        self.prio: list[float] = []
        self.capacity = capacity
        self.keys: dict[tuple[object, ...], int] = {}

    def __len__(self) -> int:
        return len(self.events)

    @property
    def items(self) -> list[tuple[float, Event]]:
        """(priority, event) pairs, for inspection."""
        return list(zip(self.prio, self.events, strict=True))

    def contains(self, e: Event) -> bool:
        """True if an equal event is queued."""
        return _key(e) in self.keys

    def _forget(self, e: Event) -> None:
        k = _key(e)
        n = self.keys.get(k, 0) - 1
        if n <= 0:
            self.keys.pop(k, None)
        else:
            self.keys[k] = n

    def push(self, e: Event, priority: float) -> bool:
        """Add ``e``; a full queue evicts its weakest item or rejects a weaker newcomer."""
        prio = self.prio
        if len(prio) >= self.capacity:
            m = min(prio)
            if priority < m:
                return False
            i = prio.index(m)
            self._forget(self.events[i])
            self.events[i] = e
            prio[i] = priority
        else:
            self.events.append(e)
            prio.append(priority)
        k = _key(e)
        self.keys[k] = self.keys.get(k, 0) + 1
        return True

    def pop(self) -> tuple[float, Event] | None:
        """Remove and return the highest-priority event."""
        prio = self.prio
        if not prio:
            return None
        i = prio.index(max(prio))
        p = prio.pop(i)
        e = self.events.pop(i)
        self._forget(e)
        return p, e

    def decay(self, factor: float) -> None:
        """Forget a little: every priority times ``factor``."""
        if self.prio:
            self.prio = [p * factor for p in self.prio]

    def clear(self) -> None:
        """Drop every item."""
        self.events.clear()
        self.prio.clear()
        self.keys.clear()


class Memory:
    """Concepts, the atom index and the event queues of one reasoner."""

    def __init__(self, capacity: int, operations: int, table_size: int, events_max: int) -> None:
        self.capacity = capacity
        self.operations = operations
        self.table_size = table_size
        self.concepts: dict[Term, Concept] = {}
        self.atom_index: dict[Term, dict[Concept, None]] = {}
        self.belief_events = EventQueue(events_max)
        self.next_concept_id = 1
        self.evictions = 0
        #: called with each concept that leaves, so owners of other indexes can clean up
        self.on_remove: Callable[[Concept], None] | None = None
        # ``find`` is the dict's own ``get`` (called millions of times per run)
        self.find = self.concepts.get  # type: ignore[method-assign]

    def __getstate__(self) -> dict[str, object]:
        state = dict(self.__dict__)
        state["on_remove"] = None  # re-attached by the owner after loading
        state.pop("find", None)
        return state

    def __setstate__(self, state: dict[str, object]) -> None:
        self.__dict__.update(state)
        self.find = self.concepts.get  # type: ignore[method-assign]

    def __len__(self) -> int:
        return len(self.concepts)

    def __iter__(self) -> Iterator[Concept]:
        return iter(self.concepts.values())

    def find(self, term: Term) -> Concept | None:
        """The concept of ``term`` if it exists."""
        return self.concepts.get(term)

    def conceptualize(self, term: Term, now: int) -> Concept:
        """The concept of ``term``, made (evicting the least useful if full) if missing."""
        c = self.concepts.get(term)
        if c is not None:
            return c
        if len(self.concepts) >= self.capacity:
            self._evict(now)
        c = Concept(self.next_concept_id, term, now, self.operations, self.table_size)
        self.next_concept_id += 1
        self.concepts[term] = c
        index = self.atom_index
        for a in term.index_names():
            d = index.get(a)
            if d is None:
                index[a] = {c: None}
            else:
                d[c] = None
        return c

    def _evict(self, now: int) -> None:
        batch = max(1, self.capacity // 16)
        # usefulness u/(u+1) of every concept, computed in one comprehension; the
        # selection then keys on list positions (a C-level getter), and ties fall to the
        # older concept exactly as a per-concept key function would
        now1 = now + 1
        cs = list(self.concepts.values())
        keys = [(u := c.use_count / (now1 - c.last_used)) / (u + 1.0) for c in cs]
        # a stable C-level sort: the same choice and order as ``heapq.nsmallest``
        for i in sorted(range(len(cs)), key=keys.__getitem__)[:batch]:
            self.remove(cs[i])
            self.evictions += 1

    def remove(self, c: Concept) -> None:
        """Forget concept ``c`` and its index entries."""
        self.concepts.pop(c.term, None)
        if self.on_remove is not None:
            self.on_remove(c)
        index = self.atom_index
        for a in c.term.index_names():
            d = index.get(a)
            if d is not None:
                d.pop(c, None)
                if not d:
                    del index[a]

    def related(self, term: Term) -> Iterator[Concept]:
        """The concept of ``term``, then every concept sharing a name with it (ONA's order).

        Lazy, so a caller needing the first 80 does not pay for 10,000; the caller must
        not add concepts while iterating.
        """
        seen: set[int] = set()
        own = self.concepts.get(term)
        if own is not None:
            seen.add(own.id)
            yield own
        for a in term.index_names():
            d = self.atom_index.get(a)
            if d:
                for c in d:
                    if c.id not in seen:
                        seen.add(c.id)
                        yield c


def is_eternal(e: Event | None) -> bool:
    """True for an eternal event."""
    return e is not None and e.occurrence_time == ETERNAL
