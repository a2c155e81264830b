# For the compiled engine: the extension types and C functions that nar.py names.
# nar.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars cimport truth as tf
from robocog.nars.event cimport Event
from robocog.nars.memory cimport Concept
from robocog.nars.state cimport Reasoner, emit
