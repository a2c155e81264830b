# For the compiled engine: the C layout of events and implications defined in event.py.
# event.py stays the only source of behaviour; see setup.py.

cimport cython

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth, decay, projection, revision
from robocog.nars.stamp cimport merge, overlap

cdef class Event:
    cdef public Term term
    cdef public object type
    cdef public Truth truth
    cdef public tuple stamp
    cdef public long occurrence_time
    cdef public long creation_time
    cdef public double dt
    cdef public bint processed
    cdef public bint is_input

    cpdef Event copy(self)
    cpdef double confidence_at(self, long target_time)
    cpdef Event projected(self, long target_time)

cdef class Implication:
    cdef public Term term
    cdef public Truth truth
    cdef public tuple stamp
    cdef public double dt
    cdef public long creation_time
    cdef public Term source

cpdef Event event_of(
    Term term, str type, Truth truth, tuple stamp, long occurrence_time, long creation_time
)
cpdef tuple revised_or_chosen(Event old, Event new, long stamp_size, bint fresh=*)
cpdef double projected_confidence(double c, long occurrence_time, long target_time)
cpdef bint revises(Event old, Term term, long occurrence_time)
@cython.locals(later=long)
cpdef bint outdone(Event old, Term term, long occurrence_time, double c)
cpdef Implication implication_of(
    Term term, Truth truth, tuple stamp, double dt, long creation_time, Term source
)
