# For the compiled engine: the extension types and C functions that inference.py names,
# so that its annotated variables are read as structs and its calls made in C, and the
# layout of its own Derivation and the C signatures of the functions the cycle calls.
# inference.py stays the only source of behaviour; see setup.py.

from robocog.nars.terms cimport Term, compound
from robocog.nars.truth cimport Truth
from robocog.nars cimport truth as tf
from robocog.nars.unify cimport apply, unify
from robocog.nars.state cimport Reasoner
from robocog.nars.memorize cimport add_derived
from robocog.nars.rules cimport RuleTable, variable_forms

cdef class Derivation:
    cdef public Reasoner state
    cdef public long occurrence
    cdef public tuple stamp
    cdef public double parent_priority
    cdef public double concept_priority

    cpdef void emit(self, Term term, Truth t, bint var_intro=*)

cpdef void apply_single(RuleTable table, Term term, Truth t, Derivation d)
cpdef void apply_double(RuleTable table, Term t1, Term t2, Truth v1, Truth v2, Derivation d)
cpdef void special(Term term1, Term term2, Truth v1, Truth v2, Derivation d)
