# For the compiled engine: the C signatures of the stamp functions in stamp.py.
# stamp.py stays the only source of behaviour; see setup.py.

cimport cython

@cython.locals(la=Py_ssize_t, lb=Py_ssize_t, n=Py_ssize_t, m=Py_ssize_t, k=Py_ssize_t)
cpdef tuple merge(tuple a, tuple b, long size=*)
@cython.locals(x=long, y=long)
cpdef bint overlap(tuple a, tuple b)
@cython.locals(n=Py_ssize_t, i=Py_ssize_t, j=Py_ssize_t, x=long, y=long)
cpdef bint has_duplicate(tuple a)
