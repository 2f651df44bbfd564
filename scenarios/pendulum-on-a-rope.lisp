;;;; scenarios/pendulum-on-a-rope.lisp -- a particle on a taut rope from a fixed point,
;;;; released at rest at theta0 from the vertical, swings back and forth.
;;;;
;;;; Expected results (textbook): the simple pendulum. Each swing ends (:turns bob) at the
;;;; mirror point, at the same height (energy), with the bob at rest, after half a period,
;;;; 2 sqrt(l/g) K(sin^2(theta0/2)); the rope stays taut (its tension m g cos theta0 > 0 at
;;;; the turning points). The swing has no closed form in time: each state is integrated
;;;; numerically, and its end put exactly back on the rope's circle at rest
;;;; (src/simulator/circle-snapping.lisp), so that the next swing starts with the rope
;;;; exactly taut.

(scenario pendulum-on-a-rope
  "A particle on a taut rope released at an angle swings back and forth."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (l :positive (:value 1))
              (theta0 :positive (< theta0 (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body ceiling :fixed t :position (0 0) :shape point)
  (body bob :mass m :position ((* l (sin theta0)) (- (* l (cos theta0)))) :velocity (0 0) :shape point)
  (rope cord :length l :through ((ceiling (0 0)) (bob (0 0))))
  (simulate :states 4))
