# For the compiled engine: the C layout of the reasoner's state defined in state.py, so
# that the engine's functions read its fields as a struct, and the C signatures of its
# small functions. state.py stays the only source of behaviour; see setup.py.

from robocog.nars.memory cimport Memory

cdef class Reasoner:
    cdef public object config
    cdef public object seed
    cdef public object rand_state
    cdef public list answer_cbs
    cdef public list derivation_cbs
    cdef public list execution_cbs
    cdef public object output
    cdef public dict operations
    cdef public object memory_dir
    cdef public Memory memory
    cdef public long time
    cdef public long stamp_base
    cdef public double concept_threshold
    cdef public long matched_total
    cdef public list op_names
    cdef public long process_id
    cdef public dict stats
    cdef public dict pending_questions
    cdef public object time_index
    cdef public dict table_index
    cdef public dict links_by_subject
    cdef public dict general_links
    cdef public dict consequences
    cdef public dict fresh_beliefs
    cdef public dict fresh_shapes
    cdef public long fresh_order
    cdef public long fresh_swept
    cdef public object strongest
    cdef public list goal_layers
    cdef public dict recent_goal_concepts
    cdef public dict unified
    cdef public dict measured
    cdef public object groups
    cdef public dict outcomes
    cdef public dict patterns

cpdef emit(Reasoner s, str line)
cpdef bint shows(Reasoner s, double priority)
cpdef remember(dict cache, key, value, long size=*)
