# For the compiled engine: the extension types and C functions that memorize.py names,
# so that its annotated variables are read as structs and its calls made in C, and the
# C signatures of add_derived, which every conclusion goes through, and of the functions
# it calls.
# memorize.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf
from robocog.nars.event cimport Event, event_of, revised_or_chosen
from robocog.nars.filters cimport rejected
from robocog.nars.memory cimport Concept, EventQueue
from robocog.nars.unify cimport unify
from robocog.nars.state cimport Reasoner, emit, shows

cpdef void add_derived(Reasoner s, Term term, Truth t, tuple stamp, long occurrence, double priority)
cpdef bint _needs_existing_concept(Term t, long occurrence)
cpdef double concept_priority(Reasoner s, Concept c)
cpdef void raise_priority(Reasoner s, Concept c, double p)
cpdef void add_event(Reasoner s, Event e, double priority, bint is_input=*, bint revised=*)
cpdef void _store(Reasoner s, Event e, double priority, bint is_input, bint revised, bint index)
cpdef bint _queue(Reasoner s, Event e, double priority)
cpdef void _process_new_belief(Reasoner s, Event e, double priority, bint is_input, bint index=*)
