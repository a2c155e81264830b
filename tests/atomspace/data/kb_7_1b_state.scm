; Thiella 2021, Appendix 7.1, second state: the screw is on the toolbox and the bolt is in
; the hand (the InheritanceLinks and NotLinks of the first example stay as they are).
( EvaluationLink
  ( PredicateNode "clear")
  ( ConceptNode "screw" ))
( EvaluationLink
  ( PredicateNode "in-hand")
  ( ConceptNode "bolt" ))
( EvaluationLink
  ( PredicateNode "on")
  ( ListLink
    ( ConceptNode "screw" )
    ( ConceptNode "toolbox" )))
( EvaluationLink
  ( PredicateNode "clear")
  ( ConceptNode "table" ))
