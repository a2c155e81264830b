# For the compiled engine: the C layout of an interned term defined in terms.py.
# terms.py stays the only source of behaviour; see setup.py.

cimport cython

cdef class Term:
    cdef public object op
    cdef public object name
    cdef public tuple args
    cdef public long complexity
    cdef public object _str
    cdef public bint has_var
    cdef public bint has_query_var
    cdef public bint has_indep_var
    cdef public bint has_dep_var
    cdef public bint is_var
    cdef public bint is_op
    cdef public object cache
    cdef public long flags
    cdef public long n_imp
    cdef public long n_temp
    cdef public object _names
    cdef public object hol
    cdef public tuple forms
    cdef public object anticipated
    cdef public list keys

    @cython.locals(out=list, level=list, nxt=list, x=Term, y=Term, a=Term, b=Term, simple=bint)
    cpdef tuple index_names(self)
    @cython.locals(out=list, level=list, nxt=list, t=Term, a=Term)
    cpdef list level_order_atoms(self)

cpdef Term compound(str op, tuple args)
cdef inline tuple _key_of(Term t)
# a sweep of the interning table visits hundreds of thousands of terms
@cython.locals(table=dict, terms=list, later=list, t=Term, n=Py_ssize_t, alone=Py_ssize_t,
               forms=tuple)
cpdef void _sweep()
@cython.locals(r=Term, a=Term, b=Term, na=Term, nb=Term)
cpdef Term substitute(Term t, dict mapping)

# a new term's properties, computed once when it is interned (a burst of new terms
# follows every new object the robot sees)
@cython.locals(t=Term, a=Term, b=Term, complexity=long, flags=long, n_imp=long,
               n_temp=long, hv=bint, hq=bint, hi=bint, hd=bint, table=dict, kind=long)
cpdef Term _make_compound(tuple key, str op, tuple args)
@cython.locals(a=Term, b=Term, na=tuple, nb=tuple, seen=set, stack=list, x=Term)
cpdef bint names_repeat(Term t)
