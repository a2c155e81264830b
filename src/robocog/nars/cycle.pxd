# For the compiled engine: the extension types and C functions that cycle.py names,
# so that its annotated variables are read as structs and its calls made in C.
# cycle.py stays the only source of behaviour; see setup.py.

from robocog.nars.event cimport Event
from robocog.nars.memory cimport Concept
from robocog.nars.stamp cimport has_duplicate, merge, overlap
from robocog.nars.state cimport Reasoner, emit, shows
from robocog.nars.inference cimport Derivation, apply_double, apply_single, special
