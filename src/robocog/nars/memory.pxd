# For the compiled engine: the C layout of a concept defined in memory.py.
# memory.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.event cimport Event
from robocog.nars.table cimport Table

cimport cython

# ``pow`` in memory.py is C's (the same function Python's float power calls)
from libc.math cimport pow

cdef class Concept:
    cdef public long id
    cdef public Term term
    cdef public long use_count
    cdef public long last_used
    cdef public Event belief
    cdef public Event belief_spike
    cdef public Event predicted_belief
    cdef public Event goal_spike
    cdef public list precondition_beliefs
    cdef public object implication_links
    cdef public double priority
    cdef public long priority_time
    cdef public long selected_time
    cdef public long process_id
    cdef public bint timed
    cdef public object filed
    cdef public list book

    cpdef use(self, long now, bint eternal_input, long boost)
    cpdef double priority_at(self, long now, double durability)

cdef class EventQueue:
    cdef public list events
    cdef public list prio
    cdef public long capacity
    cdef public dict keys
    cdef object _low

    cpdef double lowest(self)
    cpdef bint contains(self, Event e)
    cpdef void _forget(self, Event e)
    cpdef bint push(self, Event e, double priority)

cdef class Memory:
    cdef public long capacity
    cdef public long operations
    cdef public long table_size
    cdef public dict concepts
    cdef public dict atom_index
    cdef public EventQueue belief_events
    cdef public long next_concept_id
    cdef public long evictions
    cdef public dict _groups
    cdef public dict _lasts
    cdef public list _unfiled
    cdef public object on_remove
    cdef public object find

    @cython.locals(a=Term)
    cpdef Concept conceptualize(self, Term term, long now)
    cpdef void _refile(self)
    cpdef void _evict(self, long now)
    cpdef void _remove_all(self, object cs)

# the second premises of every selected event: seventy-odd concepts a cycle
@cython.locals(chosen=list, seen=set, c=Concept, cp=double, own=Concept, d=dict, a=Term)
cpdef list _related_above(
    dict concepts, dict atom_index, Term term, long now, double durability,
    double threshold, Py_ssize_t most, long links_least_uses=*
)
