;;;; scenarios/ladder-from-45-degrees.lisp -- a uniform ladder on a frictionless floor and wall
;;;; released from rest at 45 degrees (a symbolic angle a, the value 45 degrees).
;;;;
;;;; Source type: the textbook ladder sliding down a smooth wall (classical mechanics,
;;;; Lagrangian or energy plus the wall's normal force). Expected results (textbook): with
;;;; phi its angle to the floor, phi'^2 = 3 g (sin a - sin phi) / l; the wall's push
;;;; (3/4) m g cos phi (3 sin phi - 2 sin a) vanishes, and the top leaves the wall, when sin
;;;; phi = (2/3) sin a: the centre at (1/3) l sin a (the top at 2/3 of its starting
;;;; height), turning at sqrt(g sin a / l), and the floor then pushes with m g / 4.
;;;; With l = 4, a = 45 degrees: the centre at 0.9428 m, omega 1.316 rad/s.

(scenario ladder-from-45-degrees
  "A ladder slides down a frictionless wall and floor from 45 degrees."
  (parameters (m :positive (:value 3)) (g :positive (:value 981/100)) (l :positive (:value 4))
              (a (> a 0) (< a (/ pi 2)) (:value (deg 45))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 0) (0 1)))
  (body ladder :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position ((* (/ l 2) (cos a)) (* (/ l 2) (sin a))) :angle (- pi a)
               :velocity (0 0))
  (query leaves-wall-at (value (y ladder) :at (:lift-off ladder wall)))
  (query omega-then (value (angular-velocity ladder) :at (:lift-off ladder wall)))
  (query floor-push-then (value (normal-force ladder floor) :at (:lift-off ladder wall)))
  (simulate :states 1))
