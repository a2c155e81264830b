# For the compiled engine: the C signatures of the filters in filters.py.
# filters.py stays the only source of behaviour; see setup.py.

cimport cython

from robocog.nars.terms cimport Term, names_repeat

@cython.locals(comp=Term, c=Term, s=Term, p=Term)
cpdef bint hol_component_invalid(Term t)
# every conclusion is filtered
cpdef bint rejected(Term t)
@cython.locals(s=Term, p=Term)
cpdef bint _rejected(Term t)
@cython.locals(s=Term, first=Term)
cpdef bint conjunction_starts_with_operation(Term t)
