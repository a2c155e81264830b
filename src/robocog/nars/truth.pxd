# For the compiled engine: the C layout of a truth value defined in truth.py, and the
# truth functions' C signatures.
# truth.py stays the only source of behaviour; see setup.py.

cdef class Truth:
    cdef readonly double f
    cdef readonly double c

cdef double _K, _MAX_C, _DECAY
cdef list _DECAY_POWERS

cpdef Truth truth_of(double f, double c)
cpdef double w2c(double w)
cpdef double c2w(double c)
cpdef double _or(double a, double b)
cpdef double expectation(Truth t)
cpdef Truth revision(Truth a, Truth b)
cpdef Truth pooled(Truth a, Truth b, double w1, double w2)
cpdef Truth deduction(Truth a, Truth b)
cpdef Truth abduction(Truth a, Truth b)
cpdef Truth induction(Truth a, Truth b)
cpdef Truth exemplification(Truth a, Truth b)
cpdef Truth comparison(Truth a, Truth b)
cpdef Truth analogy(Truth a, Truth b)
cpdef Truth resemblance(Truth a, Truth b)
cpdef Truth intersection(Truth a, Truth b)
cpdef Truth union(Truth a, Truth b)
cpdef Truth difference(Truth a, Truth b)
cpdef Truth negation(Truth a, Truth _b=*)
cpdef Truth conversion(Truth a, Truth _b=*)
cpdef Truth contraposition(Truth a, Truth _b=*)
cpdef Truth structural_deduction(Truth a, Truth _b=*)
cpdef Truth structural_deduction_negated(Truth a, Truth _b=*)
cpdef Truth structural_intersection(Truth a, Truth _b=*)
cpdef Truth structural_abduction(Truth a, Truth _b=*)
cpdef Truth decompose_pnn(Truth a, Truth b)
cpdef Truth decompose_npp(Truth a, Truth b)
cpdef Truth decompose_pnp(Truth a, Truth b)
cpdef Truth decompose_ppp(Truth a, Truth b)
cpdef Truth decompose_nnn(Truth a, Truth b)
cpdef Truth eternalize(Truth a)
cpdef double decay(long d)
cpdef Truth projection(Truth a, long source_time, long target_time)
cpdef Truth anonymous_analogy(Truth a, Truth b)
cpdef Truth goal_deduction(Truth goal, Truth belief)
cpdef Truth frequency_greater(Truth a, Truth b)
cpdef Truth frequency_equal(Truth a, Truth b)
