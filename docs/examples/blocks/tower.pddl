; Eight blocks in two towers, to be rebuilt as one tower in reverse order
; (docs/planning.md's PDDL example).
(define (problem tower-8)
  (:domain blocks)
  (:objects a b c d e f g h - block)
  (:init (handempty)
         (ontable a) (on b a) (on c b) (on d c) (clear d)
         (ontable e) (on f e) (on g f) (on h g) (clear h))
  (:goal (and (on a b) (on b c) (on c d) (on d e) (on e f) (on f g) (on g h))))
