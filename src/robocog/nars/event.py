"""Events (sentences in time) and implications, the items the reasoner moves around."""

from __future__ import annotations

from dataclasses import dataclass

from .stamp import Stamp, fmt, merge
from .terms import Term
from .truth import Truth, projection, revision

ETERNAL = -1
BELIEF = "."
GOAL = "!"


@dataclass(slots=True)
class Event:
    """A belief or goal with its truth, evidence and time.

    ``occurrence_time`` is -1 for eternal sentences; ``dt`` is the time offset of a
    temporal implication; ``creation_time`` is when the reasoner made it.
    """

    term: Term
    type: str
    truth: Truth
    stamp: Stamp
    occurrence_time: int = ETERNAL
    creation_time: int = 0
    dt: float = 0.0
    processed: bool = False
    is_input: bool = False

    def same(self, other: Event) -> bool:
        """ONA's Event_Equal: term, type, truth, stamp and time agree."""
        return (
            self.term is other.term
            and self.type == other.type
            and self.truth == other.truth
            and self.stamp == other.stamp
            and self.occurrence_time == other.occurrence_time
        )

    def confidence_at(self, target_time: int) -> float:
        """``self.projected(target_time).truth.c``, without making the projected event."""
        if self.occurrence_time == ETERNAL or self.occurrence_time == target_time:
            return self.truth.c
        return projection(self.truth, self.occurrence_time, target_time).c

    def projected(self, target_time: int) -> Event:
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


@dataclass(slots=True)
class Implication:
    """A temporal or declarative implication stored in its predicate's table."""

    term: Term
    truth: Truth
    stamp: Stamp
    dt: float = 0.0
    creation_time: int = 0
    source: Term | None = None
