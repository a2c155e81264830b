; A factorial written in Atomese alone: a DefinedSchema that calls itself through a CondLink.
(use-modules (opencog) (opencog exec))
(DefineLink
  (DefinedSchema "factorial")
  (Lambda
    (TypedVariable (Variable "$n") (Type "NumberNode"))
    (Cond
      (GreaterThan (Variable "$n") (Number 0))
      (Times (Variable "$n")
             (ExecutionOutput (DefinedSchema "factorial") (Minus (Variable "$n") (Number 1))))
      (Number 1))))
