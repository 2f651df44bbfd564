;;;; scenarios/particle-at-incline-top.lisp -- a particle released at the top corner of a fixed
;;;; incline whose back face is vertical: it slides down the slope (the corner's two faces are
;;;; alternatives), reaches the foot of the incline and lands on the floor.
;;;;
;;;; Expected results: N = m g cos a, acceleration g sin a down the slope, the foot reached
;;;; after sqrt(2 h / g) / sin a, where the particle meets the floor.

(scenario particle-at-incline-top
  "A particle released at the top corner of a fixed incline slides down its slope to the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h :positive (:value 1)) (a (> a 0) (< a (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body floor   :fixed t :shape (half-plane (1 0) (0 0)))
  (body incline :fixed t :position (0 0)
                :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body particle :mass m :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 3))
