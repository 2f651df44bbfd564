;;;; refused-disc-incline-corner-4242-2.lisp -- FIXED (now agrees; t/witness-refusals.lisp).
;;;; Was: a refusal make crosscheck found (disc-incline, seed 4242, #2; 4 of 24 alike): a disc
;;;; rolls (no slip) down a rough incline and lands on the smooth floor in the corner.
;;;; AMES: "No set of contacts and modes is consistent at the start of the state" at the
;;;; impact: with the incline's impulse active, its friction impulse would slip in either
;;;; mode and the impulse would pull; pivoting stopped there, since a mode's exit is no
;;;; contact to flip, and never tried the incline's impulse inactive (the disc leaves the
;;;; slope: the floor's vertical impulse alone stops its fall). Fixed
;;;; (src/simulator/choice.lisp): before refusing, every subset of the lone contacts is tried
;;;; with every combination of modes.
;;;; Run: bin/ames check witness/disagreements/refused-disc-incline-corner-4242-2.lisp --numeric

(scenario disc-incline-2 "A disc or a hoop on an incline." (gravity 37/4)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body incline :fixed t :shape (polygon (0 0) (15 0) (0 25/4)))
 (body disc :mass 9/4 :inertia :uniform :shape (circle 3/20) :position (393/52 1697/520) :velocity
  (0 0) :angular-velocity 0)
 (friction disc incline :static 7/10) (simulate :states 3))
