# For the compiled engine: the extension types that spikegroups.py names, so that its
# annotated variables are read as structs.
# spikegroups.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.memory cimport Concept
