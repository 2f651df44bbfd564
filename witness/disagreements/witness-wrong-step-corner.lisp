;;;; witness-wrong-step-corner.lisp -- FIXED in the witness (CORNER-HELD in witness/siconos_driver.py;
;;;; listed in t/witness.lisp *WITNESSED-FIXES*). Was: make crosscheck SEED=303 #903, counted "AMES wrong", a defect of
;;;; the witness: the particle lands exactly in the concave corner of the floor and the step (x = 11/4
;;;; at t = 1). AMES: it hits the floor and the step's face at once, a plastic impact on both, and
;;;; rests in the corner. The witness sees the floor's impact only (the step's left face holds a body
;;;; only within its extent, and the particle is at its very end) and slides the particle on through
;;;; the step (x = 4.125 at its end). Not fixed: a contact at a face's end point that is also a
;;;; corner of two faces needs the driver to keep both faces there.
;;;; Run: bin/ames check witness/disagreements/witness-wrong-step-corner.lisp --numeric

(scenario step-903 "A particle thrown toward a step on the floor." (gravity 9) (restitution 0)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body step :fixed t :shape (polygon (11/4 0) ((+ 11/4 3/2) 0) ((+ 11/4 3/2) 3/4) (11/4 3/4)))
 (body particle :mass 1 :position (0 (+ 3/4 15/4)) :velocity (11/4 0) :shape point)
 (simulate :states 3))
