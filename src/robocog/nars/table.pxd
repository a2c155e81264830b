# For the compiled engine: the C layout of an implication table defined in table.py,
# and its methods' C signatures.
# table.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term
from robocog.nars.truth cimport Truth, c2w, expectation, pooled
from robocog.nars.stamp cimport merge, overlap
from robocog.nars.event cimport Implication

cdef class Table:
    cdef public list items
    cdef public long size
    cdef public list _neg
    cdef public dict _entry

    cpdef bint _insert(self, Implication imp)
    cpdef _replace(self, Implication old, Implication new)
    cpdef Implication add_and_revise(self, Implication imp, long stamp_size=*)
    cpdef add_failure(self, Implication imp, Truth truth, double weight, long stamp_size)
    cpdef Implication _revise(
        self, Implication old, Implication imp, Truth truth, double weight, tuple stamp,
        long stamp_size
    )
