# For the compiled engine: the C layout of an interned term defined in terms.py.
# terms.py stays the only source of behaviour; see setup.py.

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

    cpdef tuple index_names(self)

cpdef Term compound(str op, tuple args)
cpdef Term substitute(Term t, dict mapping)
