# For the compiled engine: the C signatures of the unification functions in unify.py.
# unify.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term, substitute

cpdef dict unify(Term general, Term specific, bint query_only=*)
cpdef bint _unify(Term g, Term s, dict b, bint query_only)
cpdef bint may_unify(Term general, Term specific)
cpdef Term apply(Term term, dict bindings)
