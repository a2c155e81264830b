; The four manipulator actions of the planner, as Atomese queries.
;
; Each rule is a QueryLink: the variable declaration, the pattern that must hold in the
; AtomSpace (PresentLink / AbsentLink / NotLink of EqualLink), and the rewrite. In the
; rewrite a plain atom is added to the AtomSpace and a (DeleteLink atom) removes it, so
; every effect of Section 3.2 is written here rather than hidden in a Scheme callback.
; Fixed objects stay clear: Stack has one query for an object underneath (which stops
; being clear) and one for a fixed object underneath (which does not).
; An action that adds "in-hand" fills the hand, one that deletes it empties the hand.

(DefineLink (DefinedSchemaNode "pickup")
  (QueryLink
    (VariableList
      (TypedVariableLink (VariableNode "?ob") (TypeNode "ConceptNode")))
    (AndLink
      (PresentLink
        (InheritanceLink (VariableNode "?ob") (ConceptNode "object"))
        (EvaluationLink (PredicateNode "clear") (VariableNode "?ob")))
      (AbsentLink
        (EvaluationLink (PredicateNode "stacked") (VariableNode "?ob"))))
    (ListLink
      (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))
      (DeleteLink (EvaluationLink (PredicateNode "clear") (VariableNode "?ob"))))))

(DefineLink (DefinedSchemaNode "putdown")
  (QueryLink
    (VariableList
      (TypedVariableLink (VariableNode "?ob") (TypeNode "ConceptNode")))
    (AndLink
      (PresentLink
        (InheritanceLink (VariableNode "?ob") (ConceptNode "object"))
        (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))))
    (ListLink
      (EvaluationLink (PredicateNode "clear") (VariableNode "?ob"))
      (DeleteLink (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))))))

(DefineLink (DefinedSchemaNode "stack")
  (QueryLink
    (VariableList
      (TypedVariableLink (VariableNode "?ob") (TypeNode "ConceptNode"))
      (TypedVariableLink (VariableNode "?under") (TypeNode "ConceptNode")))
    (AndLink
      (NotLink (EqualLink (VariableNode "?ob") (VariableNode "?under")))
      (PresentLink
        (InheritanceLink (VariableNode "?ob") (ConceptNode "object"))
        (InheritanceLink (VariableNode "?under") (ConceptNode "object"))
        (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))
        (EvaluationLink (PredicateNode "clear") (VariableNode "?under"))))
    (ListLink
      (EvaluationLink (PredicateNode "on") (ListLink (VariableNode "?ob") (VariableNode "?under")))
      (EvaluationLink (PredicateNode "stacked") (VariableNode "?ob"))
      (EvaluationLink (PredicateNode "clear") (VariableNode "?ob"))
      (DeleteLink (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob")))
      (DeleteLink (EvaluationLink (PredicateNode "clear") (VariableNode "?under"))))))

(DefineLink (DefinedSchemaNode "stack")
  (QueryLink
    (VariableList
      (TypedVariableLink (VariableNode "?ob") (TypeNode "ConceptNode"))
      (TypedVariableLink (VariableNode "?under") (TypeNode "ConceptNode")))
    (AndLink
      (NotLink (EqualLink (VariableNode "?ob") (VariableNode "?under")))
      (PresentLink
        (InheritanceLink (VariableNode "?ob") (ConceptNode "object"))
        (InheritanceLink (VariableNode "?under") (ConceptNode "fixed-object"))
        (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))
        (EvaluationLink (PredicateNode "clear") (VariableNode "?under"))))
    (ListLink
      (EvaluationLink (PredicateNode "on") (ListLink (VariableNode "?ob") (VariableNode "?under")))
      (EvaluationLink (PredicateNode "stacked") (VariableNode "?ob"))
      (EvaluationLink (PredicateNode "clear") (VariableNode "?ob"))
      (DeleteLink (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))))))

(DefineLink (DefinedSchemaNode "unstack")
  (QueryLink
    (VariableList
      (TypedVariableLink (VariableNode "?ob") (TypeNode "ConceptNode"))
      (TypedVariableLink (VariableNode "?under") (TypeNode "ConceptNode")))
    (AndLink
      (NotLink (EqualLink (VariableNode "?ob") (VariableNode "?under")))
      (PresentLink
        (InheritanceLink (VariableNode "?ob") (ConceptNode "object"))
        (EvaluationLink (PredicateNode "clear") (VariableNode "?ob"))
        (EvaluationLink (PredicateNode "on") (ListLink (VariableNode "?ob") (VariableNode "?under")))))
    (ListLink
      (EvaluationLink (PredicateNode "in-hand") (VariableNode "?ob"))
      (EvaluationLink (PredicateNode "clear") (VariableNode "?under"))
      (DeleteLink (EvaluationLink (PredicateNode "clear") (VariableNode "?ob")))
      (DeleteLink (EvaluationLink (PredicateNode "on") (ListLink (VariableNode "?ob") (VariableNode "?under"))))
      (DeleteLink (EvaluationLink (PredicateNode "stacked") (VariableNode "?ob"))))))
