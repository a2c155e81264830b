; docs/atomspace.md: one more fact, on top of a stored space
(InheritanceLink (stv 1 1) (ConceptNode "bolt") (ConceptNode "object"))
