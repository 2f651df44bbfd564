;;;; scenarios/disc-rolled-up-an-incline.lisp -- a uniform disc rolling at v0 up a long rough
;;;; incline rises, stops and rolls back down.
;;;;
;;;; Source type: the textbook's "how high does a rolling body climb" (first-year rotational
;;;; dynamics: the kinetic energy (3/4) m v0^2 of a rolling disc all turned to m g h).
;;;; Expected results (textbook): static friction m g sin a / 3 now down the slope (it
;;;; spins the disc down as it slows), the acceleration (2/3) g sin a down the slope
;;;; throughout, the same up and down: one state; it stops (angular velocity 0) after
;;;; 3 v0 / (2 g sin a), its centre risen h = 3 v0^2 / (4 g) (its greatest height), and
;;;; its slowest speed is 0 there; its speed has no largest value (it rolls back for ever).
;;;; The angular momentum about a point of the slope, -(3/2) m r v0 at the start, changes at
;;;; the gravity torque m g r sin a.

(scenario disc-rolled-up-an-incline
  "A disc rolling up a long rough incline rises, stops and rolls back."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (v0 :positive (:value 3)) (a (> a 0) (< a (/ pi 2)) (:value (deg 20)))
              (mu :positive (> mu (/ (tan a) 3)) (:value 1/2)))
  (gravity g)
  (body slope :fixed t :shape (half-plane ((cos a) (sin a)) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r)
        :position ((- (* r (sin a))) (* r (cos a))) :velocity ((* v0 (cos a)) (* v0 (sin a)))
        :angular-velocity (- (/ v0 r)))
  (friction disc slope :static mu)
  (query stops-at (time (reaches (angular-velocity disc) 0)))
  (query highest (maximum (y disc) :during (start 0)))
  (query slowest (minimum (speed disc) :during (start 0)))
  (query fastest (maximum (speed disc) :during (start 0)))
  (query angular-momentum-then (value (angular-momentum disc) :at (reaches (angular-velocity disc) 0)))
  (simulate :states 1))
