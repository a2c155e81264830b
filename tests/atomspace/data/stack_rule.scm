; Thiella 2021, Appendix 7.3: the Stack rule, first QueryLink (no arguments).
(QueryLink
  ( VariableList
    ( TypedVariableLink
      ( VariableNode "?ob" )
      ( TypeNode "ConceptNode" ))
    ( TypedVariableLink
      ( VariableNode "?underob" )
      ( TypeNode "ConceptNode" ))
  ) ; parameters
  ( AndLink
    ( PresentLink
      ( NotLink
        ( EqualLink
          ( VariableNode "?ob" )
          ( VariableNode "?underob" )))
      ( InheritanceLink
        ( VariableNode "?ob" )
        ( ConceptNode "object" ))
      ( EvaluationLink
        ( PredicateNode "in_hand" )
        ( VariableNode "?ob" ))
    )
    ( OrLink
      ( AndLink
        ( InheritanceLink
          ( VariableNode "?underob" )
          ( ConceptNode "object" ))
        ( EvaluationLink
          ( PredicateNode "clear" )
          ( VariableNode "?underob" ))
      )
      ( AndLink
        ( InheritanceLink
          ( VariableNode "?underob" )
          ( ConceptNode "fixed-object" ))
      )
    )
  )
  ( ExecutionOutputLink
    ( GroundedSchemaNode "scm: stack-action" )
    ( ListLink
      ; effect
      ( EvaluationLink
        ( PredicateNode "on" )
        ( ListLink
          ( VariableNode "?ob" )
          ( VariableNode "?underob" )
        )
      )
      ; precondition
      ( EvaluationLink
        ( PredicateNode "in_hand" )
        ( VariableNode "?ob" ))
    )
  )
)
