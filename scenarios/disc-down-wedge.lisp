;;;; scenarios/disc-down-wedge.lisp -- a disc slides down a movable wedge of symbolic angle a.
;;;;
;;;; The particle-on-wedge of thesis section 2.6.1 with a disc of radius r in place of the
;;;; particle (bodies translate and do not rotate; all contacts are frictionless). The
;;;; wedge is the right triangle (0 0) (h/tan a, 0) (0 h) on a fixed ground (y <= 0); the
;;;; disc touches the middle of its slope, its centre r away along the slope's outward
;;;; normal (sin a, cos a). r < h/4 keeps the disc clear of the ground at the start.
;;;; (Once, the geometry could not show cos(pi/2 - a) > 0 here: issue 9.)
;;;;
;;;; Expected results (textbook): the disc's centre moves parallel to the slope, so the
;;;; accelerations are those of the particle on the wedge:
;;;;   A_wedge = (-m g sin a cos a / (mw + m sin^2 a), 0),
;;;;   A_disc  = (mw g sin a cos a / (mw + m sin^2 a), -(mw + m) g sin^2 a / (mw + m sin^2 a)),
;;;;   N (disc-wedge) = m mw g cos a / (mw + m sin^2 a).
;;;; The disc's centre starts at height h/2 + r cos a and falls with that constant
;;;; vertical acceleration; the disc meets the ground when its centre is at height r:
;;;;   t1 = sqrt((h + 2 r cos a - 2 r) (mw + m sin^2 a) / ((m + mw) g sin^2 a)),
;;;; before its contact point reaches the foot of the slope (at
;;;; sqrt(h (mw + m sin^2 a) / ((m + mw) g sin^2 a)), later since cos a < 1): the state
;;;; ends with (:collision disc ground), which ends the run.

(scenario disc-down-wedge
  "A disc slides down a movable wedge of symbolic angle resting on frictionless ground."
  (parameters (m :positive (:value 1)) (mw :positive (:value 3)) (g :positive (:value 981/100))
              (h :positive (:value 2)) (r (> r 0) (< r (/ h 4)) (:value 1/4))
              (a (> a 0) (< a (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body ground :fixed t :shape (half-plane (1 0) (0 0)))
  (body wedge :mass mw :position (0 0) :velocity (0 0)
              :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  ;; touching the middle of the slope
  (body disc :mass m :position ((+ (/ h (* 2 (tan a))) (* r (sin a))) (+ (/ h 2) (* r (cos a))))
             :velocity (0 0) :shape (circle r))
  (simulate :states 3))
