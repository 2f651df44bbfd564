;;;; refused-drag-projectile-reversing-push.lisp -- FIXED (now agrees; see *WITNESSED-FIXES* in
;;;; t/witness.lisp: the landing of a numeric state was no impact). Was: a refusal make crosscheck found (drag-projectile,
;;;; seed 5, #17): a ball launched slightly toward -x, pushed toward +x, under quadratic drag.
;;;; AMES: "No event within 200000 steps of the numeric integration" (20 s). The witness
;;;; (Lsodar) lands it on the floor. The horizontal velocity passes through zero during the
;;;; flight (the push turns it); the integrator seems to stall there. For the lead: AMES's
;;;; numeric integration of two-dimensional quadratic drag.
;;;; Run: bin/ames check witness/disagreements/refused-drag-projectile-reversing-push.lisp --numeric

(scenario drag-projectile-17 "A ball launched through a medium with drag lands on the floor."
 (gravity 37/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ball :mass 7/4 :position (0 0) :velocity ((* -1 1/4) 15/4) :shape point)
 (force push :on ball :value (1 0)) (drag air :on ball :quadratic 4/25) (simulate :states 2))
