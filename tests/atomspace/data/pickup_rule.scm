; Thiella 2021, Section 3.2: the Pickup rule, first QueryLink (no argument).
; The Scheme procedure pickup-action is registered from Python.
(QueryLink
  ( VariableList
    ( TypedVariableLink
      ( VariableNode "?ob")
      ( TypeNode "ConceptNode"))
    ) ; parameters
  ( AndLink
    ( PresentLink
      ( InheritanceLink
        ( VariableNode "?ob")
        ( ConceptNode "object"))
      ( EvaluationLink
        ( PredicateNode "clear")
        ( VariableNode "?ob"))
    )
    ( AbsentLink
      ( EvaluationLink
        ( PredicateNode "stacked")
        ( VariableNode "?ob"))
    )
  )
  ( ExecutionOutputLink
    ( GroundedSchemaNode "scm: pickup-action")
    ( ListLink
      ; effect
      ( EvaluationLink
        ( PredicateNode "in_hand")
        ( VariableNode "?ob"))
      ; precondition
      ( EvaluationLink
        ( PredicateNode "clear")
        ( VariableNode "?ob"))
    )
  )
)
