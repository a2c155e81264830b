# For the compiled engine: the extension types and C functions that decision.py names,
# so that its annotated variables are read as structs and its calls made in C.
# decision.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term, compound
from robocog.nars.truth cimport Truth, expectation
from robocog.nars cimport truth as tf
from robocog.nars.stamp cimport merge
from robocog.nars.event cimport Event, Implication, revised_or_chosen
from robocog.nars.memory cimport Concept
from robocog.nars.table cimport Table
from robocog.nars.unify cimport apply, may_unify, unify
from robocog.nars.state cimport Reasoner, emit, remember, shows
from robocog.nars.sensorimotor cimport executable, split_precondition

# the C signatures of the helpers that the choice of a decision calls for every link
cpdef bint _ground(Term t)
cpdef bint _self_operation(Term op)
cpdef list _preconditions(Reasoner s, Term pre)
cpdef bint _has_measurement(Reasoner s, Term t)
cpdef dict _unified(Reasoner s, Term general, Term specific)
