;;;; witness-wrong-rough-incline-stop-at-rest.lisp -- make crosscheck SEED=101 #588: a particle at rest
;;;; on a rough incline (tan a = 5/12 < mu = 4/5) stays at rest, as AMES says; the witness's LCP gave it a
;;;; few steps of tangential speed and then a (:stops-sliding) at 4e-4 s. Fixed in the witness: a slide
;;;; ends only once it has lasted five steps.
;;;; Run: bin/ames check witness/disagreements/witness-wrong-rough-incline-stop-at-rest.lisp --numeric

(scenario rough-incline-588 "A particle on a rough incline." (gravity 25/2)
 (body incline :fixed t :shape (polygon (0 0) (9 0) (0 15/4)))
 (body particle :mass 1 :position (27/4 15/16) :velocity (0 0) :shape point)
 (friction particle incline :static 4/5) (simulate :states 3))
