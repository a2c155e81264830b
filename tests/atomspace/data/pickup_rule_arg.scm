; Thiella 2021, Section 3.2: the Pickup rule, second QueryLink (one argument, `args`).
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
    ( EqualLink
      ( VariableNode "?ob")
      args
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
