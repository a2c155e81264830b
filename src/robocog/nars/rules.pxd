# For the compiled engine: the extension types and C functions that rules.py names,
# so that its annotated variables are read as structs and its calls made in C.
# rules.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term, compound, substitute
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf

cpdef tuple variable_forms(Term t)
cpdef Term make(str op, tuple args)
