; Thiella 2021, Appendix 7.1: a table with a screw, a bolt and a toolbox on it.
( InheritanceLink
    ( ConceptNode "screw" )
    ( ConceptNode "object" ))
( InheritanceLink
    ( ConceptNode "bolt" )
    ( ConceptNode "object" ))
( InheritanceLink
    ( ConceptNode "toolbox" )
    ( ConceptNode "object" ))
( InheritanceLink
    ( ConceptNode "table" )
    ( ConceptNode "fixed-object" ))

(NotLink (EqualLink
    (ConceptNode "screw") (ConceptNode "bolt")))
(NotLink (EqualLink
    (ConceptNode "screw") (ConceptNode "toolbox")))
(NotLink (EqualLink
    (ConceptNode "screw") (ConceptNode "table")))
(NotLink (EqualLink
    (ConceptNode "bolt") (ConceptNode "toolbox")))
(NotLink (EqualLink
    (ConceptNode "bolt") (ConceptNode "table")))
(NotLink (EqualLink
    (ConceptNode "toolbox") (ConceptNode "table")))

(EvaluationLink
    (PredicateNode "clear")
    (ConceptNode "screw"))
(EvaluationLink
    (PredicateNode "clear")
    (ConceptNode "bolt"))
(EvaluationLink
    (PredicateNode "clear")
    (ConceptNode "toolbox"))
(EvaluationLink
    (PredicateNode "clear")
    (ConceptNode "table"))
