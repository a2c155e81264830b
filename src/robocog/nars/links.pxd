# For the compiled engine: the extension types and C functions that links.py names,
# so that its annotated variables are read as structs and its calls made in C.
# links.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars cimport truth as tf
from robocog.nars.stamp cimport merge, overlap
from robocog.nars.event cimport Event
from robocog.nars.memory cimport Concept
from robocog.nars.unify cimport apply, may_unify, unify
from robocog.nars.state cimport Reasoner, remember
from robocog.nars.sensorimotor cimport note_event
