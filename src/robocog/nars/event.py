"""Events (sentences in time) and implications, the items the reasoner moves around."""

from __future__ import annotations

try:
    import cython
except ImportError:  # the pure engine runs without Cython
    from . import cy as cython


from .stamp import Size, Stamp, fmt, merge, overlap
from .terms import Term
from .truth import Cycle, Truth, decay, projection, revision

ETERNAL = -1
BELIEF = "."
GOAL = "!"


def _fields(r: Event | Implication) -> tuple[object, ...]:
    return tuple([getattr(r, name) for name in type(r).__slots__])


# Equality, pickling and printing by the fields named in ``__slots__``, for Event and
# Implication (written out rather than dataclasses so that, compiled, they are
# extension types with their own free lists: see ``event.pxd``; an extension type's
# free list serves no subtype, so the two share these functions, not a base class)
def _equal(r: Event | Implication, other: object) -> bool:
    if other.__class__ is not r.__class__:
        return NotImplemented  # type: ignore[return-value]
    return _fields(r) == _fields(other)  # type: ignore[arg-type]


def _reduce(r: Event | Implication) -> tuple[type, tuple[object, ...]]:
    # by the fields, so that the compiled and the pure engine read each other's saves
    return (type(r), _fields(r))


def _repr(r: Event | Implication) -> str:
    pairs = zip(type(r).__slots__, _fields(r), strict=True)
    return f"{type(r).__name__}(" + ", ".join(f"{n}={v!r}" for n, v in pairs) + ")"


# Compiled, events stay out of Python's cycle collector: an event refers to its term, its
# truth and a stamp of numbers, none of which can lead back to it, and a full memory holds
# tens of thousands of them.
@cython.freelist(64)
@cython.no_gc
@cython.cclass
class Event:
    """A belief or goal with its truth, evidence and time.

    ``occurrence_time`` is -1 for eternal sentences; ``dt`` is the time offset of a
    temporal implication; ``creation_time`` is when the reasoner made it.
    """

    __slots__ = (
        "term",
        "type",
        "truth",
        "stamp",
        "occurrence_time",
        "creation_time",
        "dt",
        "processed",
        "is_input",
    )

    def __eq__(self, other: object) -> bool:
        return _equal(self, other)

    __hash__ = None  # type: ignore[assignment]  # mutable, like the dataclasses they were

    def __reduce__(self) -> tuple[type, tuple[object, ...]]:
        return _reduce(self)

    def __repr__(self) -> str:
        return _repr(self)

    def __init__(
        self,
        term: Term,
        type: str,  # noqa: A002 - ONA's name for the punctuation
        truth: Truth,
        stamp: Stamp,
        occurrence_time: int = ETERNAL,
        creation_time: int = 0,
        dt: float = 0.0,
        processed: bool = False,
        is_input: bool = False,
    ) -> None:
        self.term = term
        self.type = type
        self.truth = truth
        self.stamp = stamp
        self.occurrence_time = occurrence_time
        self.creation_time = creation_time
        self.dt = dt
        self.processed = processed
        self.is_input = is_input

    def copy(self) -> Event:
        """A copy of this event, to keep where the original may change."""
        return Event(
            self.term,
            self.type,
            self.truth,
            self.stamp,
            self.occurrence_time,
            self.creation_time,
            self.dt,
            self.processed,
            self.is_input,
        )

    def same(self, other: Event) -> bool:
        """ONA's Event_Equal: term, type, truth, stamp and time agree."""
        return (
            self.term is other.term
            and self.type == other.type
            and self.truth == other.truth
            and self.stamp == other.stamp
            and self.occurrence_time == other.occurrence_time
        )

    def confidence_at(self, target_time: Cycle) -> float:
        """``self.projected(target_time).truth.c``, without making the projected event."""
        return projected_confidence(self.truth.c, self.occurrence_time, target_time)

    def projected(self, target_time: Cycle) -> Event:
        """This event seen from ``target_time`` (confidence decays with distance); the
        event itself when nothing changes (callers only read what they get)."""
        if self.occurrence_time == ETERNAL or self.occurrence_time == target_time:
            return self
        return Event(
            self.term,
            self.type,
            projection(self.truth, self.occurrence_time, target_time),
            self.stamp,
            target_time,
            self.creation_time,
            self.dt,
            self.processed,
            self.is_input,
        )

    def sentence(self) -> str:
        """``TERM. :|: occurrenceTime=T`` as ONA prints the head of a line."""
        head = f"{self.term}{self.type}"
        if self.occurrence_time != ETERNAL:
            head += f" :|: occurrenceTime={self.occurrence_time}"
        return head

    def line(self, priority: float) -> str:
        """ONA's ``Input:``/``Derived:`` payload for this event."""
        dt = f"dt={self.dt:f} " if self.term.op == "=/>" else ""
        return f"{dt}{self.sentence()} Priority={priority:f} Stamp={fmt(self.stamp)} {self.truth}"


def projected_confidence(c: float, occurrence_time: Cycle, target_time: Cycle) -> float:
    """The confidence ``c`` of an event at ``occurrence_time`` projected to
    ``target_time``: projection's product, without making the projected truth (or,
    for :func:`outdone`, the event)."""
    if occurrence_time == ETERNAL or occurrence_time == target_time:
        return c
    return c * decay(abs(target_time - occurrence_time))


def revises(old: Event, term: Term, occurrence_time: Cycle) -> bool:
    """True if an event of ``term`` at ``occurrence_time`` is revised with ``old``
    rather than chosen between, unless their stamps overlap: the same term, at the
    same time or ``old`` eternal, and not a conjunction or sequence with dependent
    variables. (Pure reads, cheapest first; the stamps are compared by the caller.)"""
    return (
        old.term is term
        and (old.occurrence_time == ETERNAL or old.occurrence_time == occurrence_time)
        and not (term.op in ("&&", "&/") and term.has_dep_var)
    )


def event_of(
    term: Term,
    type: str,  # noqa: A002 - ONA's name for the punctuation
    truth: Truth,
    stamp: Stamp,
    occurrence_time: Cycle,
    creation_time: Cycle,
) -> Event:
    """``Event(term, type, truth, stamp, occurrence_time, creation_time)`` made without
    the keyword-capable constructor call: anticipation predicts hundreds of events per
    input (compiled, this allocates the struct and sets its fields)."""
    e: Event = Event.__new__(Event)
    e.term = term
    e.type = type
    e.truth = truth
    e.stamp = stamp
    e.occurrence_time = occurrence_time
    e.creation_time = creation_time
    e.dt = 0.0
    e.processed = False
    e.is_input = False
    return e


def revise_events(a: Event, b: Event, stamp_size: int) -> Event:
    """Revision of two events of one term at the later occurrence."""
    t = max(a.occurrence_time, b.occurrence_time)
    pa = a.projected(t)
    pb = b.projected(t)
    return Event(
        a.term,
        a.type,
        revision(pa.truth, pb.truth),
        merge(a.stamp, b.stamp, stamp_size),
        t,
        max(a.creation_time, b.creation_time),
        a.dt,
    )


def revised_or_chosen(
    old: Event | None, new: Event, stamp_size: Size, fresh: bool = False
) -> tuple[Event, bool]:
    """ONA's revision-and-choice for the event slot of a concept holding ``old``: the
    revised event and True, or the stronger of the two and False. ``new`` is copied
    before it is kept unless the caller made it for this call (``fresh``)."""
    if old is None:
        return (new if fresh else new.copy()), False
    later = max(old.occurrence_time, new.occurrence_time)
    # (the comparison of the stamps' ids last: the other tests are cheaper)
    if not revises(old, new.term, new.occurrence_time) or overlap(new.stamp, old.stamp):
        # a choice needs only the projected confidences (anticipation makes thousands
        # of these per input), not the projected events
        if new.confidence_at(later) > old.confidence_at(later):
            return (new if fresh else new.copy()), False
        return old, False
    return revise_events(old.projected(later), new.projected(later), stamp_size), True


def outdone(old: Event, term: Term, occurrence_time: Cycle, c: float) -> bool:
    """True if ``revised_or_chosen(old, new)`` keeps ``old`` as it is for every
    ``new`` of this term, occurrence time and confidence, whatever its stamp; False
    if that takes ``new`` or its stamp. Anticipation asks this before it makes a
    prediction: most of the thousands it makes per input lose to the event already
    predicted, and so need no event, truth or merged stamp of their own."""
    if revises(old, term, occurrence_time):
        return False  # revised unless the stamps overlap
    later = max(old.occurrence_time, occurrence_time)
    # (``new.confidence_at(later)`` for the event not made)
    return not projected_confidence(c, occurrence_time, later) > old.confidence_at(later)


@cython.freelist(64)
@cython.no_gc  # as an event: a term, a truth and a stamp of numbers
@cython.cclass
class Implication:
    """A temporal or declarative implication stored in its predicate's table."""

    __slots__ = ("term", "truth", "stamp", "dt", "creation_time", "source")

    def __eq__(self, other: object) -> bool:
        return _equal(self, other)

    __hash__ = None  # type: ignore[assignment]  # mutable, like the dataclasses they were

    def __reduce__(self) -> tuple[type, tuple[object, ...]]:
        return _reduce(self)

    def __repr__(self) -> str:
        return _repr(self)

    def __init__(
        self,
        term: Term,
        truth: Truth,
        stamp: Stamp,
        dt: float = 0.0,
        creation_time: int = 0,
        source: Term | None = None,
    ) -> None:
        self.term = term
        self.truth = truth
        self.stamp = stamp
        self.dt = dt
        self.creation_time = creation_time
        self.source = source


def implication_of(
    term: Term,
    truth: Truth,
    stamp: Stamp,
    dt: float,
    creation_time: Cycle,
    source: Term | None,
) -> Implication:
    """``Implication(term, truth, stamp, dt, creation_time, source)`` made without the
    keyword-capable constructor call: anticipation revises hundreds of links per input."""
    imp: Implication = Implication.__new__(Implication)
    imp.term = term
    imp.truth = truth
    imp.stamp = stamp
    imp.dt = dt
    imp.creation_time = creation_time
    imp.source = source
    return imp
