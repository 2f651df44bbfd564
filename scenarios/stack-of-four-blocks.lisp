;;;; scenarios/stack-of-four-blocks.lisp -- four unit blocks stacked on a frictionless
;;;; floor, at rest (the stack family of the scale benchmark, bench/scale-families.lisp,
;;;; at N = 4).
;;;;
;;;; Expected results: nothing moves, forever. The normal force under block k carries the
;;;; weight of k and of every block above it: g (m1 + m2 + m3 + m4) from the floor under
;;;; b1, g (m2 + m3 + m4) from b1 under b2, g (m3 + m4) under b3, g m4 under b4.

(scenario stack-of-four-blocks
  "A stack of four blocks at rest on a floor."
  (parameters (m1 :positive) (m2 :positive) (m3 :positive) (m4 :positive)
              (g :positive (:value 981/100)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body b1 :mass m1 :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b2 :mass m2 :position (0 1) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b3 :mass m3 :position (0 2) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b4 :mass m4 :position (0 3) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (simulate :states 2))
