# For the compiled engine: the extension types and C functions that questions.py names,
# so that its annotated variables are read as structs and its calls made in C.
# questions.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport expectation
from robocog.nars.stamp cimport has_duplicate, merge, overlap
from robocog.nars.event cimport Event, Implication
from robocog.nars.memory cimport Concept
from robocog.nars.unify cimport may_unify, unify
from robocog.nars.state cimport Reasoner, emit
