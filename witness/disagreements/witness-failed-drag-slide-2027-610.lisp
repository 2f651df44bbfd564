;;;; witness-failed-drag-slide-2027-610 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed
;;;; reason: the witness's server gave no answer within 120 s
;;;; Examined: the block (m = 7/4, quadratic drag c = 1/2, k = c/m = 2/7, v0 = 3/2) reaches the
;;;; wall (its front at x = 16, the block's x = 15) at t = (exp(15 k) - 1)/(k v0) = 167.19 s
;;;; (x = ln(1 + k v0 t)/k), AMES's duration 167.19365648338618; the witness (Lsodar with Python
;;;; drag callbacks) cannot integrate that horizon within its 120 s under the run's load.
;;;; A witness limitation (a long horizon), as drag-slide-2026-362; AMES's time checked by hand.
;;;; Run: bin/ames check witness/disagreements/witness-failed-drag-slide-2027-610.lisp --numeric

(scenario drag-slide-610 "A block slides through a medium with drag on a frictionless floor."
 (gravity 43/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (16 0) (17 0) (17 2) (16 2)))
 (body block :mass 7/4 :position (0 0) :velocity (3/2 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 1/2) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::DRAG-SLIDE-610 :STATES
;;    ((:INDEX 0 :START 0 :DURATION 167.19365648338618d0 :CONTACTS
;;      ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((- (/ 63 (* (EXPT (+ 7 (* 3 AMES.BASE:TAU)) 2) 2))) 0)))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::OIL AMES-SCENARIO::BLOCK
;;        ((- (/ 441 (* (EXPT (+ 7 (* 3 AMES.BASE:TAU)) 2) 8))) 0))
;;       (:GRAVITY AMES-SCENARIO::BLOCK (0 -301/16))
;;       (:NORMAL AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 301/16))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((/ (* 7 (LOG (/ (+ 7 (* 3 AMES.BASE:TAU)) 7))) 2) 0)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((/ 21 (+ 14 (* 6 AMES.BASE:TAU))) 0)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (3/2 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :IMPULSE 3340672/92462705 :ENERGY-LOST
;;       22320178823168/59845462711419175)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (15 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK (13362688/647238935 0)))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK))
;;        (AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :FEATURE (:EDGE 3 :OF AMES-SCENARIO::WALL)
;;         :OBSERVER-FEATURE (:EDGE 1 :OF AMES-SCENARIO::BLOCK)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 0)
;;        (:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL 3340672/92462705))
;;       :ENERGY-LOST 22320178823168/59845462711419175 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;        (AMES-SCENARIO::BLOCK (13362688/647238935 0)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK (/ 3087 (* (EXPT (+ 7 (* 3 AMES.BASE:TAU)) 2) 32)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK) 0))
;;      :MOMENTUM ((:MOMENTUM AMES-SCENARIO::BLOCK ((/ 147 (+ 56 (* 24 AMES.BASE:TAU))) 0))))
;;     (:INDEX 1 :START 96644454/578039 :DURATION :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK))
;;       (AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :FEATURE (:EDGE 3 :OF AMES-SCENARIO::WALL)
;;        :OBSERVER-FEATURE (:EDGE 1 :OF AMES-SCENARIO::BLOCK)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0))) :FORCES
;;      ((:DRAG AMES-SCENARIO::OIL AMES-SCENARIO::BLOCK (0 0))
;;       (:GRAVITY AMES-SCENARIO::BLOCK (0 -301/16))
;;       (:NORMAL AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 301/16)
;;       (:NORMAL AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL 0))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (15 0)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0)))
;;      :END-EVENT :NONE :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK 0) (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK) 0)) :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BLOCK (0 0)))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (61 61) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :ERROR :MESSAGE "the witness's server gave no answer within 120 s")
