# For the compiled engine: the extension types and C functions that memorize.py names,
# so that its annotated variables are read as structs and its calls made in C, and the
# C signature of add_derived, which every conclusion goes through.
# memorize.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf
from robocog.nars.event cimport Event, revised_or_chosen
from robocog.nars.memory cimport Concept
from robocog.nars.unify cimport unify
from robocog.nars.state cimport Reasoner, emit, shows

cpdef void add_derived(Reasoner s, Term term, Truth t, tuple stamp, long occurrence, double priority)
cpdef bint _needs_existing_concept(Term t, long occurrence)
