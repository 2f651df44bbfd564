;;;; scenarios/particle-under-plane.lisp -- thesis figure 2-5: a particle at rest under a fixed plane.
;;;;
;;;; A particle at rest touches the underside of a fixed horizontal plane (a ceiling:
;;;; the half-plane y >= 0, whose edge runs from (0 0) to (1 0) with the solid to its
;;;; left, above). Gravity points down. The particle starts at the origin, on the
;;;; ceiling's edge (a straight edge with no vertex).
;;;;
;;;; Expected results (thesis 2.5.8):
;;;;   State 0: contact particle-ceiling. Keeping it would need N = -m g < 0 (an
;;;;     attractive normal force), so the state ends at once:
;;;;       duration 0, end event (:lift-off particle ceiling).
;;;;     Positions and velocities carry over unchanged: (0 0) and (0 0).
;;;;   State 1: no contact, free fall: acceleration (0, -g),
;;;;     position (0, -g tau^2 / 2), velocity (0, -g tau); nothing below, so it lasts
;;;;     forever (duration :forever, end event :none).

(scenario particle-under-plane
  "A particle at rest touching the underside of a fixed horizontal plane falls away."
  (parameters (m :positive) (g :positive (:value 981/100)))
  (gravity g)
  (body ceiling :fixed t :shape (half-plane (0 0) (1 0)))
  (body particle :mass m :position (0 0) :velocity (0 0) :shape point)
  (simulate :states 3))
