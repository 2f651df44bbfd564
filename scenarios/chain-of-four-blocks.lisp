;;;; scenarios/chain-of-four-blocks.lisp -- four touching unit blocks in a row on a
;;;; frictionless floor, the first pushed by f toward a wall that the last one touches
;;;; (the chain family of the scale benchmark, bench/scale-families.lisp, at N = 4).
;;;;
;;;; Expected results: nothing moves, forever. Each block pushes the next with f (the
;;;; push is passed down the chain unchanged, since no block accelerates), the wall pushes
;;;; back on the last with f, and the floor carries each block's weight: N = mk g.

(scenario chain-of-four-blocks
  "A chain of four touching blocks on a floor pushed into a wall."
  (parameters (m1 :positive) (m2 :positive) (m3 :positive) (m4 :positive)
              (g :positive (:value 981/100)) (f :positive (:value 5)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall  :fixed t :shape (half-plane (4 1) (4 0)))
  (body b1 :mass m1 :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b2 :mass m2 :position (1 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b3 :mass m3 :position (2 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b4 :mass m4 :position (3 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (force push :on b1 :value (f 0))
  (simulate :states 2))
