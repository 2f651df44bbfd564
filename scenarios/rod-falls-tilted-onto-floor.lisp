;;;; scenarios/rod-falls-tilted-onto-floor.lisp -- a uniform rod dropped from rest, tilted at
;;;; 30 degrees, falls until its lower end strikes a smooth floor.
;;;;
;;;; Expected results (textbook): the centre falls (1 - l/4) and arrives at
;;;; v = -sqrt(g (4 - l) / 2); the floor's impulse at the end, J = (1 + e) m |v| / (1 + 3
;;;; cos^2 30) = 4 (1 + e) m |v| / 13, gives the centre v' = (9 - 4 e) v / 13 and the
;;;; rod omega' = -6 cos(30) J / (m l) (clockwise: the lower end is on the left); no
;;;; horizontal impulse on a smooth floor, and the kinetic energy lost is
;;;; (1 - e^2) m v^2 (4/13) / 2.

(scenario rod-falls-tilted-onto-floor
  "A uniform rod falls tilted and one end strikes a smooth floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (l :positive (< l 2) (:value 1)) (e :positive (< e 1) (:value 1/2)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position (0 1) :angle (/ pi 6) :velocity (0 0))
  (restitution rod floor e)
  (simulate :states 1))
