;;;; scenarios/two-masses-on-a-spring.lisp -- two particles joined by a spring on a frictionless
;;;; floor; the second one is pushed away from the first.
;;;;
;;;; Expected results: the centre of mass moves at m2 v0 / (m1 + m2); the stretch of the spring
;;;; oscillates at w = sqrt(k (m1 + m2) / (m1 m2)): x1 = m2 v0 (tau - sin(w tau)/w) / (m1 + m2)
;;;; and x2 = l0 + (m2 v0 tau + m1 v0 sin(w tau)/w) / (m1 + m2); the state lasts forever. Momentum
;;;; m2 v0 and energy m2 v0^2 / 2 are conserved. The stretch's amplitude v0 / w stays below l0
;;;; (the assumption on v0): faster, the spring would shrink to zero length and open on the
;;;; other side, and without the bound the run branches on it.

(scenario two-masses-on-a-spring
  "Two particles joined by a spring on a frictionless floor; one is pushed."
  (parameters (m1 :positive (:value 1)) (m2 :positive (:value 2)) (k :positive (:value 3))
              (g :positive (:value 981/100)) (v0 :positive (< v0 (* l0 (sqrt (/ (* k (+ m1 m2)) (* m1 m2))))) (:value 1)) (l0 :positive (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body first :mass m1 :position (0 0) :velocity (0 0) :shape point)
  (body second :mass m2 :position (l0 0) :velocity (v0 0) :shape point)
  (spring coupling :from (first (0 0)) :to (second (0 0)) :stiffness k)
  (simulate :states 2))
