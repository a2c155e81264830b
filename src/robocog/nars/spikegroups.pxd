# For the compiled engine: the extension types that spikegroups.py names, so that its
# annotated variables are read as structs.
# spikegroups.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.memory cimport Concept

cimport cython

# run for every event a concept of the time index receives
@cython.locals(d=dict)
cpdef void group_add(dict groups, Concept c, object keys)
@cython.locals(d=dict)
cpdef void group_remove(dict groups, Concept c, object keys)
