# For the compiled engine: the C signatures of the stamp functions in stamp.py.
# stamp.py stays the only source of behaviour; see setup.py.

cpdef tuple merge(tuple a, tuple b, long size=*)
cpdef bint overlap(tuple a, tuple b)
