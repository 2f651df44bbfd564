;;;; scenarios/blocks-colliding.lisp -- two blocks on a frictionless floor, A sliding into B
;;;; at rest: a head-on impact with Newton's coefficient of restitution e.
;;;;
;;;; Expected results: A reaches B after d / v; just after the impact A moves at
;;;; (ma - e mb) v / (ma + mb) and B at (1 + e) ma v / (ma + mb) (momentum conserved, the
;;;; separation speed e times the approach speed), with the impulse (1 + e) ma mb v / (ma + mb)
;;;; and the kinetic energy lost (1 - e^2) ma mb v^2 / (2 (ma + mb)). With e = 0 they move on
;;;; together in contact.

(scenario blocks-colliding
  "Block A slides into block B at rest on a frictionless floor."
  (parameters (ma :positive (:value 1)) (mb :positive (:value 2)) (g :positive (:value 981/100))
              (v :positive (:value 3)) (d :positive (:value 1)) (e (>= e 0) (<= e 1) (:value 1/2)))
  (gravity g)
  (restitution e)
  (body floor   :fixed t :shape (half-plane (1 0) (0 0)))
  (body block-a :mass ma :position (0 0) :velocity (v 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (body block-b :mass mb :position ((+ 1 d) 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (simulate :states 2))
