"""Bounded concept memory with an inverted atom index.

Concepts are kept in a dict (term -> concept) bounded by ``concepts_max``; when it is
full the least *useful* concepts (recently and often used ones are useful) are evicted
in a small batch, so the amortised cost of making room stays constant. The atom index
maps every name to the concepts whose term mentions it; it has no cap on the number of
names (ONA stops at 255 atoms), and is cleaned when a concept leaves.
"""

from __future__ import annotations

from bisect import bisect_left, insort
from collections.abc import Callable, Iterator
from heapq import heapify, heappop, heapreplace

from .event import Event
from .stamp import Size
from .table import Table
from .terms import EQUIVALENCE, IMPLICATION, Term
from .truth import Cycle

#: a number of uses (an alias, so that the compiled engine can declare it a C long)
Count = int


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
        "filed",
        "book",
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
        # (use_count, last_used) under which the memory has the concept in its
        # usefulness groups, and the memory's list of concepts to file again, while
        # the concept is filed there unchanged (see ``Memory._refile``)
        self.filed: tuple[int, int] | None = None
        self.book: list[Concept] | None = None

    def __reduce__(self) -> tuple[object, ...]:
        # an empty concept given the state, the same for the compiled and the pure engine
        return (_blank_concept, (), self.__getstate__())

    def __getstate__(self) -> tuple[None, dict[str, object]]:
        state = {k: getattr(self, k) for k in self.__slots__}
        state["filed"] = state["book"] = None  # the loading memory files it anew
        return None, state

    def __setstate__(self, state: tuple[object, dict[str, object]]) -> None:
        for k, v in state[1].items():
            setattr(self, k, v)

    def use(self, now: Cycle, eternal_input: bool, boost: Count) -> None:
        """Record a use (input eternal beliefs count as very many uses)."""
        self.use_count += boost if eternal_input else 1
        self.last_used = now
        book = self.book
        if book is not None:  # changed since its memory filed it: to be filed again
            self.book = None
            book.append(self)

    def priority_at(self, now: Cycle, durability: float) -> float:
        """The priority as of ``now``: decayed by ``durability`` per cycle since it was
        set, which is applied only when it is read."""
        dt: float = now - self.priority_time
        if dt <= 0:
            return self.priority
        # ``pow`` of floats is ``**`` (both C's pow for this positive base); compiled, it
        # is C's pow itself (memory.pxd), where ``**`` would go through Python objects
        return self.priority * pow(durability, dt)

    def tables(self, operations: int, size: int) -> list[Table]:
        """The precondition tables, made on first use."""
        if self.precondition_beliefs is None:
            self.precondition_beliefs = [Table(size) for _ in range(operations + 1)]
        return self.precondition_beliefs

    def usefulness(self, now: int) -> float:
        """u/(u+1) with u = uses per cycle since the last use."""
        span = now - self.last_used + 1
        if span < 1:
            span = 1  # (a clock set back by ``*currenttime``: used just now)
        u = self.use_count / span
        return u / (u + 1.0)


def _blank_concept() -> Concept:
    """A concept without fields, for ``__setstate__`` to fill."""
    return Concept.__new__(Concept)


def _key(e: Event) -> tuple[object, ...]:
    return (e.term, e.type, e.truth, e.stamp, e.occurrence_time)


class EventQueue:
    """Bounded max-priority queue of events (ONA's cycling events).

    Priorities live in a plain list beside the events, so finding the weakest or the
    strongest item is one C-level ``min``/``max`` over at most a few hundred floats.
    """

    __slots__ = ("events", "prio", "capacity", "keys", "_low")

    def __init__(self, capacity: int) -> None:
        self.events: list[Event] = []
        self.prio: list[float] = []
        self.capacity = capacity
        self.keys: dict[tuple[object, ...], int] = {}
        #: ``min(prio)`` while the queue is unchanged, else None: a full queue is asked
        #: for its weakest item by every derived event, and changes only now and then
        self._low: float | None = None

    def lowest(self) -> float:
        """The weakest priority queued (the queue must not be empty)."""
        low = self._low
        if low is None:
            low = self._low = min(self.prio)
        return low

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
            m = self.lowest()
            if priority < m:
                return False
            i = prio.index(m)
            self._forget(self.events[i])
            self.events[i] = e
            prio[i] = priority
        else:
            self.events.append(e)
            prio.append(priority)
        self._low = None
        k = _key(e)
        self.keys[k] = self.keys.get(k, 0) + 1
        return True

    def pop(self) -> tuple[float, Event] | None:
        """Remove and return the highest-priority event."""
        prio = self.prio
        if not prio:
            return None
        i = prio.index(max(prio))
        self._low = None
        p = prio.pop(i)
        e = self.events.pop(i)
        self._forget(e)
        return p, e

    def decay(self, factor: float) -> None:
        """Forget a little: every priority times ``factor``."""
        if self.prio:
            self.prio = [p * factor for p in self.prio]
            self._low = None

    def clear(self) -> None:
        """Drop every item."""
        self.events.clear()
        self.prio.clear()
        self.keys.clear()
        self._low = None


#: what a pickled memory of robocog's older save format held (see ``Memory.__getstate__``)
_STATE_FIELDS = (
    "capacity",
    "operations",
    "table_size",
    "concepts",
    "atom_index",
    "belief_events",
    "next_concept_id",
    "evictions",
)


class Memory:
    """Concepts, the atom index and the event queues of one reasoner.

    Compiled, an extension type (memory.pxd): the reasoning cycle reads its fields as
    C struct members and calls ``conceptualize`` in C, where a Python class would look
    each field up in its instance dict, eight times for every new concept.
    """

    def __init__(self, capacity: int, operations: int, table_size: int, events_max: int) -> None:
        self.capacity = capacity
        self.operations = operations
        self.table_size = table_size
        self.concepts: dict[Term, Concept] = {}
        self.atom_index: dict[Term, dict[Concept, None]] = {}
        self.belief_events = EventQueue(events_max)
        self.next_concept_id = 1
        self.evictions = 0
        # concepts grouped by (use_count, last_used), which fixes their usefulness, so
        # an eviction compares groups instead of concepts. Concepts made or used since
        # the last eviction wait in ``_unfiled``.
        self._groups: dict[tuple[int, int], dict[Concept, None]] = {}
        # the groups' last_used values by use_count, ascending: for one use_count a
        # group is the less useful the older it is, so an eviction ranks only the
        # oldest group of each use_count (a score of them) instead of all ten thousand
        self._lasts: dict[int, list[int]] = {}
        self._unfiled: list[Concept] = []
        #: called with each concept that leaves, so owners of other indexes can clean up
        self.on_remove: Callable[[Concept], None] | None = None
        #: the concept of a term if it exists: the concepts dict's own ``get``, called
        #: millions of times per run
        self.find: Callable[[Term], Concept | None] = self.concepts.get

    def __getstate__(self) -> dict[str, object]:
        # read by tools/convert_pickle_memory.py only: robocog saves memory files
        return {k: getattr(self, k) for k in _STATE_FIELDS}

    def __setstate__(self, state: dict[str, object]) -> None:
        for k in _STATE_FIELDS:
            setattr(self, k, state[k])
        self.on_remove = None  # re-attached by the owner after loading
        self.find = self.concepts.get
        self._groups = {}
        self._lasts = {}
        self._unfiled = list(self.concepts.values())

    def restore(self, concepts: list[Concept], next_concept_id: int, evictions: int) -> None:
        """Hold ``concepts`` (in the order they were made), as a saved memory lists them:
        the atom index is rebuilt in that order, which is the order it had."""
        self.concepts.clear()
        self.atom_index.clear()
        self._groups.clear()
        self._lasts.clear()
        self._unfiled = list(concepts)
        for c in concepts:
            c.filed = None
            c.book = None
            self.concepts[c.term] = c
            for a in c.term.index_names():
                d = self.atom_index.get(a)
                if d is None:
                    self.atom_index[a] = {c: None}
                else:
                    d[c] = None
        self.next_concept_id = next_concept_id
        self.evictions = evictions

    def __len__(self) -> int:
        return len(self.concepts)

    def __iter__(self) -> Iterator[Concept]:
        return iter(self.concepts.values())

    def conceptualize(self, term: Term, now: Cycle) -> Concept:
        """The concept of ``term``, made (evicting the least useful if full) if missing."""
        concepts: dict = self.concepts
        found = concepts.get(term)
        if found is not None:
            return found
        if len(concepts) >= self.capacity:
            self._evict(now)
        c: Concept = Concept(self.next_concept_id, term, now, self.operations, self.table_size)
        self.next_concept_id += 1
        concepts[term] = c
        self._unfiled.append(c)
        index: dict = self.atom_index
        d: dict
        for a in term.index_names():
            d = index.get(a)
            if d is None:
                index[a] = {c: None}
            else:
                d[c] = None
        return c

    def _refile(self) -> None:
        """Put the concepts made or used since the last call into the group of their
        (use_count, last_used)."""
        groups: dict = self._groups
        lasts: dict = self._lasts
        unfiled: list = self._unfiled
        c: Concept
        g: dict
        for c in unfiled:
            old = c.filed
            if old is _GONE:
                continue  # removed meanwhile
            if old is None or old[0] != c.use_count or old[1] != c.last_used:
                key = (c.use_count, c.last_used)
                if old is not None:
                    _ungroup(groups, lasts, old, c)
                g = groups.get(key)
                if g is None:
                    groups[key] = {c: None}
                    ls = lasts.get(c.use_count)
                    if ls is None:
                        lasts[c.use_count] = [c.last_used]
                    elif ls[-1] < c.last_used:
                        ls.append(c.last_used)  # the usual case: used now
                    else:
                        insort(ls, c.last_used)
                else:
                    g[c] = None
                c.filed = key
            c.book = unfiled
        unfiled.clear()

    def _evict(self, now: Cycle) -> None:
        """Remove the ``capacity/16`` least useful concepts, least useful first; ties
        fall to the older concept."""
        self._refile()
        batch = max(1, self.capacity // 16)
        groups: dict = self._groups
        lasts: dict = self._lasts
        # usefulness u/(u+1), u = uses per cycle since the last use. The groups are
        # taken least useful first until the batch is full, with every group as useful
        # as the last one taken, so the oldest of those can be picked. For one use
        # count the older group is the less useful, so the next group to take is the
        # least useful of the oldest untaken group of each use count: ``heads`` holds
        # those, with where each use count's list of ages has got to.
        now1 = now + 1
        heads: list = []
        for n, ls in lasts.items():
            heads.append((_usefulness(n, ls[0], now1), n, 0))
        heapify(heads)
        chosen: list[tuple[float, int, Concept]] = []
        taken: list[tuple[float, int]] = []  # (usefulness, use count) of each group
        c: Concept
        last_key = -1.0
        while heads:
            key, n, i = heads[0]
            if len(chosen) >= batch and key != last_key:
                break
            ls = lasts[n]
            g = groups[(n, ls[i])]
            for c in g:
                chosen.append((key, c.id, c))
            taken.append((key, n))
            last_key = key
            i += 1
            if i < len(ls):
                heapreplace(heads, (_usefulness(n, ls[i], now1), n, i))
            else:
                heappop(heads)
        # ids grow with the order concepts were made in, which is the dict's order
        chosen.sort()
        victims = [c for _, _, c in chosen[:batch]]
        # The groups less useful than the last one taken were fewer than the batch, so
        # all their concepts go: the groups are dropped whole here, the oldest of each
        # use count, instead of one concept at a time by ``_remove_all``.
        whole: dict[int, int] = {}
        for key, n in taken:
            if key != last_key:
                whole[n] = whole.get(n, 0) + 1
        for n, k in whole.items():
            ls = lasts[n]
            for last in ls[:k]:
                for c in groups.pop((n, last)):
                    c.filed = None  # (no group to leave)
            if k == len(ls):
                del lasts[n]
            else:
                del ls[:k]
        self._remove_all(victims)
        self.evictions += len(victims)

    def remove(self, c: Concept) -> None:
        """Forget concept ``c`` and its index entries."""
        self._remove_all((c,))
        if len(self._unfiled) > 2 * self.capacity:
            self._refile()  # drops removed concepts from the list (evictions do it too)

    def _remove_all(self, cs: list[Concept] | tuple[Concept, ...]) -> None:
        """Forget the concepts ``cs`` in order (one loop, so an eviction batch of
        hundreds pays the attribute look-ups once)."""
        concepts: dict = self.concepts
        index: dict = self.atom_index
        groups: dict = self._groups
        lasts: dict = self._lasts
        on_remove = self.on_remove
        c: Concept
        gone: Concept
        d: dict
        for c in cs:
            gone = concepts.pop(c.term, None)
            if gone is not None:
                if gone.filed is not None:
                    _ungroup(groups, lasts, gone.filed, gone)
                gone.filed = _GONE
                gone.book = None
            if on_remove is not None:
                on_remove(c)
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

    def related_above(
        self,
        term: Term,
        now: Cycle,
        durability: float,
        threshold: float,
        most: Size,
        links_least_uses: Count = 0,
    ) -> list[tuple[Concept, float]]:
        """The first ``most`` concepts of :meth:`related` whose priority as of ``now``
        (decayed by ``durability``) is not below ``threshold``, each with that priority:
        the concepts whose beliefs semantic inference takes as second premises. With
        ``links_least_uses``, a ``==>``/``<=>`` concept used fewer times (one that no
        eternal input made, whose uses count the input boost) is passed over, not
        counted.

        :meth:`related` and a test per concept, in one loop: resuming the generator
        cost more than the test, for the seventy-odd concepts of a cycle.
        """
        return _related_above(
            self.concepts,
            self.atom_index,
            term,
            now,
            durability,
            threshold,
            most,
            links_least_uses,
        )


#: the memory's concepts by term, and its atom index (aliases the compiled engine
#: reads as plain dicts)
ConceptsByTerm = dict[Term, Concept]
AtomIndex = dict[Term, dict[Concept, None]]


def _related_above(
    concepts: ConceptsByTerm,
    atom_index: AtomIndex,
    term: Term,
    now: Cycle,
    durability: float,
    threshold: float,
    most: Size,
    links_least_uses: Count = 0,
) -> list[tuple[Concept, float]]:
    """:meth:`Memory.related_above` over the memory's concepts and atom index (a
    function, so that the compiled engine runs its loop with C types)."""
    chosen: list[tuple[Concept, float]] = []
    seen: set[Concept] = set()
    c: Concept
    cp: float
    own = concepts.get(term)
    if own is not None:
        seen.add(own)
        cp = own.priority_at(now, durability)
        if not cp < threshold:
            chosen.append((own, cp))
            if len(chosen) >= most:
                return chosen
    for a in term.index_names():
        d = atom_index.get(a)
        if d:
            for c in d:
                if c in seen:
                    continue
                seen.add(c)
                if (
                    links_least_uses
                    and c.term.n_imp
                    and c.use_count < links_least_uses
                    and (c.term.op is IMPLICATION or c.term.op is EQUIVALENCE)
                ):
                    continue  # a ``==>``/``<=>`` only derivations made
                cp = c.priority_at(now, durability)
                if cp < threshold:
                    continue
                chosen.append((c, cp))
                if len(chosen) >= most:
                    return chosen
    return chosen


#: ``Concept.filed`` of a concept that has left its memory (it may still wait in the
#: memory's list of concepts to file, which then passes it by)
_GONE = (-1, -1)


def _usefulness(n: Count, last: Cycle, now1: Cycle) -> float:
    """u/(u+1) of a group: u = ``n`` uses per cycle since ``last``, ``now1`` one after now."""
    span = now1 - last
    if span < 1:
        span = 1  # (a clock set back by ``*currenttime``: used just now)
    u: float = n / span
    return u / (u + 1.0)


def _ungroup(
    groups: dict[tuple[int, int], dict[Concept, None]],
    lasts: dict[int, list[int]],
    key: tuple[int, int],
    c: Concept,
) -> None:
    g = groups[key]
    del g[c]
    if not g:
        del groups[key]
        n, last = key
        ls = lasts[n]
        if len(ls) == 1:
            del lasts[n]
        else:
            del ls[bisect_left(ls, last)]
