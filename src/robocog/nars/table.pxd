# For the compiled engine: the C layout of an implication table defined in table.py,
# and its methods' C signatures.
# table.py stays the only source of behaviour; see setup.py.

cimport cython

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth, c2w, expectation, pooled
from robocog.nars.stamp cimport merge, overlap
from robocog.nars.event cimport Implication, implication_of

@cython.locals(mid=Py_ssize_t, v=double)
cdef Py_ssize_t _bisect_left(list neg, double e, Py_ssize_t lo, Py_ssize_t hi)
@cython.locals(mid=Py_ssize_t, v=double)
cdef Py_ssize_t _bisect_right(list neg, double e, Py_ssize_t lo, Py_ssize_t hi)

cdef class Table:
    cdef public list items
    cdef public long size
    cdef public list _neg
    cdef public dict _predictive
    cdef public dict _concurrent

    cdef dict _entries(self, double dt)
    @cython.locals(e=double, i=Py_ssize_t)
    cpdef bint _insert(self, Implication imp)
    @cython.locals(
        n=Py_ssize_t, i=Py_ssize_t, j=Py_ssize_t, e=double, e_old=double, v=double,
        stays=bint, zero=bint, t=Truth
    )
    cpdef _replace(self, Implication old, Implication new, Py_ssize_t at=*)
    cpdef Implication add_and_revise(self, Implication imp, long stamp_size=*)
    cpdef add_failure(
        self, Implication imp, Truth truth, double weight, long stamp_size, Py_ssize_t at=*
    )
    @cython.locals(w1=double, dt=double)
    cpdef Implication _revise(
        self, Implication old, Implication imp, Truth truth, double weight, tuple stamp,
        long stamp_size, Py_ssize_t at=*
    )
