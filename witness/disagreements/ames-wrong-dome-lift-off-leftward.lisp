;;;; witness/disagreements/ames-wrong-dome-lift-off-leftward.lisp -- a disagreement found by
;;;; the witness (make crosscheck FAMILIES=dome, seed 3, index 7); run:
;;;; bin/ames check THIS-FILE --numeric
;;;;
;;;; A particle released at rest on a dome (the upper half of a fixed circle of radius r on
;;;; the floor) at the angle a from the top on the LEFT slides down and leaves the dome
;;;; where cos = (2/3) cos a (thesis 2.6.3), here at t = 0.41283 s, (-1.7960, 0.8800): AMES
;;;; and Siconos agree on state 0 and its (:lift-off particle dome) (to 5e-8). But AMES's
;;;; state 1 keeps the contact "particle on the arc of dome", with the normal force
;;;; N = 24 sin(s/2) - 16 cos(17/20) that is zero at its start and attractive after it, and
;;;; slides the particle down the arc to its end (-2, 0), (:leaves particle dome) at
;;;; 0.66549 s. The particle flies free after the lift-off (Siconos: no contact; it lands
;;;; on the floor). The same scenario on the right (particle at (+r sin a, r cos a),
;;;; scenario dome-7-right below) agrees with the witness in every state: the lift-off's
;;;; successor state keeps the contact only when the particle moves toward -x (s
;;;; increasing along the arc from 0 to pi). (With the values as parameters, g = 8, r = 2,
;;;; a = 17/20, AMES's run ends undecided: the values are written in.)

(scenario dome-lift-off-leftward
  "A particle released on the left of a dome's top slides and leaves the dome."
  (gravity 8)
  (restitution 1)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body dome :fixed t :shape (arc :center (0 0) :radius 2 :from 0 :to pi :solid :inside))
  (body particle :mass 1 :position ((- (* 2 (sin 17/20))) (* 2 (cos 17/20))) :velocity (0 0) :shape point)
  (simulate :states 3))

(scenario dome-lift-off-rightward
  "The same on the right of the top: AMES and the witness agree."
  (gravity 8)
  (restitution 1)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body dome :fixed t :shape (arc :center (0 0) :radius 2 :from 0 :to pi :solid :inside))
  (body particle :mass 1 :position ((* 2 (sin 17/20)) (* 2 (cos 17/20))) :velocity (0 0) :shape point)
  (simulate :states 3))
