;;;; refused-disc-incline-inactive-mode-4242-3.lisp -- FIXED (now agrees; t/witness-refusals.lisp).
;;;; Was: a refusal make crosscheck found (disc-incline, seed 4242, #3; 5 of 24 alike): a disc
;;;; launched up a rough incline comes back down and lands on the smooth floor in the corner,
;;;; touching the incline. AMES: "The instance is not active" at (:MODE (FRICTION-IMPULSE ..)
;;;; :FROM :SLIDING-BACKWARD :TO :STICKING): pivoting forced the incline's friction impulse
;;;; out of sticking, then found the incline's impulse pulling and deactivated it, and
;;;; undoing the forced exit met an inactive instance. Fixed (src/simulator/choice.lisp): a
;;;; forced exit of an instance since deactivated is neither undone nor applied again.
;;;; Run: bin/ames check witness/disagreements/refused-disc-incline-inactive-mode-4242-3.lisp --numeric

(scenario disc-incline-3 "A disc or a hoop on an incline." (gravity 59/4)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body incline :fixed t :shape (polygon (0 0) (8 0) (0 6)))
 (body disc :mass 5/2 :inertia :uniform :shape (circle 1/4) :position (83/20 16/5) :velocity
  (-1/5 3/20) :angular-velocity 1)
 (friction disc incline :static 11/20) (simulate :states 3))
