# For the compiled engine: the extension types and C functions that sensorimotor.py names,
# so that its annotated variables are read as structs and its calls made in C, and the
# layout of its own _Pattern.
# sensorimotor.py stays the only source of behaviour; see setup.py.

cimport cython

from robocog.nars.terms cimport Term, compound
from robocog.nars.truth cimport Truth, expectation
from robocog.nars cimport truth as tf
from robocog.nars.stamp cimport merge, overlap
from robocog.nars.event cimport Event, Implication, event_of, outdone, revised_or_chosen
from robocog.nars.memory cimport Concept
from robocog.nars.table cimport Table
from robocog.nars.unify cimport apply, unify
from robocog.nars.state cimport Reasoner, emit, remember, shows
from robocog.nars.rules cimport variable_forms
from robocog.nars.spikegroups cimport group_add, group_remove

# the C signatures of the functions that the processing of every selected event calls
# many times over (induction and what it stores)
cpdef tuple split_precondition(Term subject)
cpdef long _sequence_length(Term t)
cpdef bint _has_op(Term t)
cpdef bint executable(Term op)
cpdef long op_id(Reasoner s, Term op)
cpdef void note_event(Reasoner s, Concept c)
@cython.locals(i=Py_ssize_t, x=object)
cpdef bint _drop(object idx, Concept c)
cpdef _keys_of(Reasoner s, Term term)
cpdef void _activate_sequence(Reasoner s, Event se)
cpdef void _induce(Reasoner s, Event pre, Event op, Event post, double priority)

cdef class _Pattern:
    cdef public Term source
    cdef public list keys
    cdef public object key
    cdef public long uses
    cdef public dict matches
    cdef public dict group
    cdef public dict groups

    cpdef dict match(self, Term term)

cdef class _Source:
    cdef public Event spike
    cdef public double f
    cdef public double c
    cdef public bint weak
    cdef public dict bind
    cdef public long serial

@cython.locals(t=Truth, c=double)
cpdef _Source _source(Event spike, dict bind, bint as_is, Truth op, double weak, long now)
cpdef _Pattern _pattern(Reasoner s, Term source)
cpdef Event _newest_instance(_Pattern pattern, dict groups, Event best)
cpdef Event _prediction(
    Term outcome, double f, double c, Event spike, Implication imp, long occ, long now,
    long stamp_size
)
@cython.locals(n=long, r=double)
cpdef long _offset(double dt)
@cython.locals(past_c=double)
cpdef double _failure_confidence(Truth pre, long rdt, double confidence)
@cython.locals(t=Term)
cpdef anticipate(Reasoner s, Event e)
@cython.locals(rdt=long, occ=long, k=Py_ssize_t, serial=long, v=Term)
cpdef _anticipate(Reasoner s, Event e, list touched)
cpdef Event source_spike(Reasoner s, Term source, dict groups=*)
# the times of the index scans as C integers: every input event's processing compares
# them against hundreds of index entries
@cython.locals(now=long, occ=long, window=long, tdiff=long, e_is_op=bint, concurrent=bint, least=double, longest=long, size=long)
cpdef void process_belief_event(Reasoner s, Event e, double priority)
