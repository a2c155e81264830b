(InheritanceLink (stv 0.9 0.8) (ConceptNode "cat") (ConceptNode "animal"))
(EvaluationLink (PredicateNode "on") (ListLink (ConceptNode "a") (ConceptNode "b")))
(DefineLink (DefinedSchemaNode "x") (ConceptNode "y"))
