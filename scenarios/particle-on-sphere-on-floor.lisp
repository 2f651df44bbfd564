;;;; scenarios/particle-on-sphere-on-floor.lisp -- the thesis's third example (section 2.6.3)
;;;; run to the end: the particle starts at rest at angle theta0 from the top of a fixed sphere
;;;; that stands on the floor, slides, lifts off where cos theta = (2/3) cos theta0, flies
;;;; clear of the sphere and lands on the floor.
;;;;
;;;; Expected results: lift-off at cos theta = (2/3) cos theta0 with v^2 = (2/3) g r
;;;; cos theta0 (as particle-on-sphere); free flight that never meets the sphere again;
;;;; landing on the floor.

(scenario particle-on-sphere-on-floor
  "A particle slides off a fixed sphere standing on the floor, flies, and lands on the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1))
              (theta0 (> theta0 0) (< theta0 (/ pi 2)) (:value 1/10)))
  (gravity g)
  (body floor    :fixed t :shape (half-plane (1 0) (0 0)))
  (body sphere   :fixed t :position (0 r) :shape (circle r))
  (body particle :mass m :velocity (0 0) :shape point
                 :position ((* r (sin theta0)) (+ r (* r (cos theta0)))))
  (simulate :states 4))
