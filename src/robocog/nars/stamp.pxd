# For the compiled engine: the C signatures of the stamp functions in stamp.py.
# stamp.py stays the only source of behaviour; see setup.py.

cimport cython

cpdef tuple merge(tuple a, tuple b, long size=*)
@cython.locals(x=long, y=long)
cpdef bint overlap(tuple a, tuple b)
