;;;; scenarios/sphere-rolls-or-slips-on-an-incline.lisp -- a solid sphere released on a rough
;;;; incline, mu left open: it rolls or slips according to mu.
;;;;
;;;; Source type: the textbook's rolling-or-slipping condition (first-year mechanics,
;;;; "when does a ball slip on an incline"). Expected results (textbook), I = (2/5) m r^2:
;;;; it rolls when mu_s >= tan(a) / (1 + m r^2 / I) = (2/7) tan a, with a = (5/7) g sin a
;;;; and friction (2/7) m g sin a; below it slips: kinetic friction mu m g cos a, a = g (sin
;;;; a - mu cos a), angular acceleration -(5/2) mu g cos a / r; in both its angular
;;;; momentum about a point of the slope changes at the gravity torque, -m g r sin a.
;;;; AMES branches on 7 mu cos a - 2 sin a (slips below 0, rolls at and above); the values
;;;; (mu = 1/10, a = 45 degrees) select the slip.

(scenario sphere-rolls-or-slips-on-an-incline
  "A solid sphere on a rough incline: it rolls or slips according to mu."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (a (> a 0) (< a (/ pi 2)) (:value (deg 45)))
              (mu :positive (:value 1/10)))
  (gravity g)
  (body slope :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
  (body ball :mass m :inertia (* 2/5 m r r) :shape (circle r)
        :position ((* r (sin a)) (* r (cos a))) :velocity (0 0))
  (friction ball slope :static mu)
  (simulate :states 1 :until 1))
