; docs/atomspace.md: a small knowledge base of parts
(InheritanceLink (stv 1 1) (ConceptNode "screw") (ConceptNode "object"))
(InheritanceLink (stv 1 1) (ConceptNode "washer") (ConceptNode "object"))
(EvaluationLink (PredicateNode "clear") (ConceptNode "washer"))
