;;;; scenarios/particle-in-a-bowl.lisp -- a particle released at rest inside a fixed circular
;;;; bowl swings to the same height on the other side and back, forever.
;;;;
;;;; Expected results: on the bowl (radius r, s the arc length) the energy integral is
;;;; s'^2 = 2 g r (sin(s/r) - cos theta0) (s = pi r / 2 at the bottom); the particle turns at
;;;; s = r (pi/2 - theta0) and s = r (pi/2 + theta0), the angle theta0 either side of the
;;;; bottom; the motion is periodic with the pendulum's period
;;;; 4 sqrt(r/g) K(sin^2(theta0/2)) (2.018 s with the defaults); the bowl pushes with
;;;; N = m g (3 sin(s/r) - 2 cos theta0) > 0, so the particle never leaves it.

(scenario particle-in-a-bowl
  "A particle released at rest inside a fixed circular bowl, at angle theta0 from the bottom."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
              (theta0 :positive (< theta0 (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body bowl :fixed t :shape (arc :center (0 r) :radius r :from pi :to (* 2 pi) :solid :outside))
  (body particle :mass m :position ((* r (sin theta0)) (- r (* r (cos theta0))))
                 :velocity (0 0) :shape point)
  (simulate :states 3))
