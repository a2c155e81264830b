; docs/atomspace.md: what is an object, and what is clear
(cog-execute! (GetLink (InheritanceLink (VariableNode "$x") (ConceptNode "object"))))
(cog-execute! (GetLink (EvaluationLink (PredicateNode "clear") (VariableNode "$x"))))
