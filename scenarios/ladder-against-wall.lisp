;;;; scenarios/awaiting-rotation/ladder-against-wall.lisp -- a uniform ladder on a frictionless
;;;; floor leans against a frictionless wall; released from rest, it slides and leaves the
;;;; wall.
;;;;
;;;; The ladder is a thin uniform rod (a segment with :inertia :uniform, m l^2 / 12) of
;;;; length l at angle a with the floor, its foot on the floor and its top against the wall
;;;; (the wall is the half-plane x < 0, the floor y < 0).
;;;; Expected results (textbook): with phi its angle to the floor, energy gives
;;;; phi'^2 = 3 g (sin a - sin phi) / l while both ends touch; the wall's push is zero, and
;;;; the top leaves the wall ((:lift-off ladder wall)), when sin phi = (2/3) sin a: the top
;;;; has dropped to 2/3 of its starting height, (2/3) l sin a, turning at sqrt(g sin a / l).
;;;; AMES: one state along the ladder's angle theta = pi - phi (the :TURNING integrator),
;;;; ended by (:lift-off ladder wall) at theta = pi - asin(2 sin(a) / 3) after an elliptic
;;;; time; the fall that follows, on the floor alone, has no closed form (--numeric
;;;; integrates it), so the run stops after the first state.

(scenario ladder-against-wall
  "A ladder slides down a frictionless wall and floor and leaves the wall at 2/3 of its height."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (a (> a 0) (< a (/ pi 2)) (:value (deg 60))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 0) (0 1)))
  (body ladder :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position ((* (/ l 2) (cos a)) (* (/ l 2) (sin a))) :angle (- pi a)
               :velocity (0 0))
  (query leaves-wall-at (value (y ladder) :at (:lift-off ladder wall)))
  (simulate :states 1))
