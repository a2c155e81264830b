# For the compiled engine: the extension types and C functions that declarative.py names,
# so that its annotated variables are read as structs and its calls made in C.
# declarative.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth, expectation
from robocog.nars cimport truth as tf
from robocog.nars.stamp cimport merge, overlap
from robocog.nars.event cimport Event, Implication, revised_or_chosen
from robocog.nars.unify cimport apply, unify
from robocog.nars.state cimport Reasoner, emit, shows
from robocog.nars.memory cimport Concept
