;;;; crash-rod-ledge-2031-10 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: crash
;;;; reason: the Lisp process died in this scenario
;;;; Run: bin/ames check /work/wt/atspeed/t/../witness/disagreements/crash-rod-ledge-2031-10.lisp --numeric

(scenario rod-ledge-10 "A rod or a block falls across the edge of a ledge." (gravity 45/4)
 (body floor :fixed t :shape (half-plane (1 -1) (0 -1)))
 (body ledge :fixed t :shape (polygon (-4 -1) (0 -1) (0 0) (-4 0)))
 (body rod :mass 3 :inertia :uniform :shape (segment (-5/8 0) (5/8 0)) :position (-7/16 3/5) :angle
  0 :velocity (-1/4 0))
 (restitution 0) (simulate :states 3))


;; AMES's answer:
;;   NIL

;; witness's answer:
;;   NIL
