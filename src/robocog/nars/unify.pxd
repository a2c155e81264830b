# For the compiled engine: the extension types and C functions that unify.py names,
# so that its annotated variables are read as structs and its calls made in C.
# unify.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
