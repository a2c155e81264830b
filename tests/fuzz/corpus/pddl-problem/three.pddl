(define (problem three) (:domain blocks)
  (:objects a b c - block)
  (:init (clear c) (on c b) (on b a) (ontable a) (handempty))
  (:goal (and (on a b) (on b c))))
