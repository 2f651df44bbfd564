;;;; scenarios/blocks-dropped-side-by-side.lisp -- three unit blocks side by side, two
;;;; apart, released from rest at heights 2, 4 and 6 above a floor (the independent drops
;;;; of the scale benchmark, bench/scale-families.lisp, at N = 3). They never meet: each
;;;; falls on its own, and a plastic impact (e = 0) stops it on the floor.
;;;;
;;;; Expected results: block k lands at t = sqrt(4 k / g) with speed sqrt(4 k g) (the
;;;; states end at t = 2/sqrt(g), 2 sqrt(2/g) and 2 sqrt(3/g)); the energy lost is
;;;; 2 k mk g; then all three rest on the floor forever, each carried by N = mk g.

(scenario blocks-dropped-side-by-side
  "Three blocks released side by side at different heights land in turn."
  (parameters (m1 :positive) (m2 :positive) (m3 :positive) (g :positive (:value 981/100)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body b1 :mass m1 :position (0 2) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b2 :mass m2 :position (2 4) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body b3 :mass m3 :position (4 6) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (simulate :states 5))
