;;;; scenarios/particle-down-quarter-circle.lisp -- a particle runs down a fixed quarter-circle
;;;; track (concave, like the inside of a bowl) from rest at its top and out onto the floor: at
;;;; the bottom its speed is sqrt(2 g R) and the track pushes with N = 3 m g; then it slides on
;;;; along the floor.
;;;;
;;;; Expected results: on the track N(s) = 3 m g cos(s / r) (s from the bottom), the
;;;; bottom reached with velocity (sqrt(2 g r), 0) and N = 3 m g, the floor met there
;;;; tangentially; then sliding on the floor with N = m g, forever.

(scenario particle-down-quarter-circle
  "A particle runs from rest down a quarter-circle track onto the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1)))
  (gravity g)
  (body floor    :fixed t :shape (half-plane (1 0) (0 0)))
  ;; the track: the arc of radius r centred at (0 r) from straight left (angle pi) to straight
  ;; down (3 pi / 2); its solid side is outside the circle, so the particle runs inside it
  (body track    :fixed t :position (0 0)
                 :shape (arc :center (0 r) :radius r :from pi :to (* 3/2 pi) :solid :outside))
  (body particle :mass m :position ((- r) r) :velocity (0 0) :shape point)
  (simulate :states 3))
