# For the compiled engine: the extension types and C functions that rules.py names,
# so that its annotated variables are read as structs and its calls made in C.
# rules.py stays the only source of behaviour; see setup.py.

cimport cython

from robocog.nars.terms cimport Term, compound, substitute
from robocog.nars.truth cimport Truth
from robocog.nars.filters cimport hol_component_invalid
from robocog.nars cimport truth as tf

cpdef tuple variable_forms(Term t)

cdef class RuleTable:
    cdef public dict single
    cdef public dict double
    cdef dict _cache
    cdef dict _single_cache
    cdef dict _shape_cache
    cdef dict _pairs
    cdef long _pairs_limit
    cdef long _pair_hits
    cdef dict _singles

    cpdef tuple conclusions(self, Term t1, Term t2)
    cpdef tuple single_conclusions(self, Term t)
    cpdef list single_rules(self, str op)
    cpdef list candidates(self, Term t1, Term t2)
    cpdef list double_rules(self, str op1, str op2)

# variable introduction: run once for each new conclusion term, the most of them in the
# cycles after a new object is seen
@cython.locals(op=str, sim=bint, s=Term, p=Term, a=Term, s_image=bint, p_image=bint)
cpdef void _count_statement_atoms(
    Term t, dict counts, bint extensional, bint ignore_structure, bint spatial
)
@cython.locals(op=str, ext=bint)
cpdef void _count_hol(Term t, dict counts, bint extensional)
@cython.locals(got=list, i=Py_ssize_t, counts=dict)
cpdef dict _hol_counts(Term t, bint extensional)
@cython.locals(a=Term, v=long)
cpdef bint _shared_or_twice(dict cl, dict cr)
@cython.locals(v=long)
cpdef bint _twice(dict counts)
@cython.locals(cl=dict, cr=dict, dep=long, ind=long, mapping=dict, a=Term, vl=object, vr=object)
cpdef object introduce_implication_variables(Term t, bint extensional)
@cython.locals(counts=dict, dep=long, mapping=dict, a=Term, v=long)
cpdef object introduce_conjunction_variables(Term t, bint extensional)
@cython.locals(op=str, found=list, ext=bint)
cpdef tuple _variable_forms(Term t)
@cython.locals(a=Term, b=Term)
cpdef Term make(str op, tuple args)

# the rules that can match a shape of premise pair, worked out at its first meeting
cpdef bint is_pattern_variable(Term t)
@cython.locals(comps=list, p=Term, k=Py_ssize_t, i=Py_ssize_t, j=Py_ssize_t, a=Term, b=Term,
               eq=long, bit=Py_ssize_t)
cpdef bint _fits(object r, tuple key)
