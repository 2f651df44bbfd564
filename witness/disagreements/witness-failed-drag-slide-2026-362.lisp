;;;; witness-failed-drag-slide-2026-362 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed
;;;; reason: the witness's server gave no answer within 120 s
;;;; Examined: AMES's block reaches the wall only after 556 s (quadratic drag: x = ln(1 + k v0 t)/k);
;;;; the witness (Lsodar with Python drag callbacks) cannot integrate that horizon within its 120 s.
;;;; A witness limitation (a long horizon), not AMES's; AMES's numbers unwitnessed.
;;;; Run: bin/ames check witness/disagreements/witness-failed-drag-slide-2026-362.lisp --numeric

(scenario drag-slide-362 "A block slides through a medium with drag on a frictionless floor."
 (gravity 17/2) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (16 0) (17 0) (17 2) (16 2)))
 (body block :mass 1 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 11/25) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::DRAG-SLIDE-362 :STATES
;;    ((:INDEX 0 :START 0 :DURATION 556.1327191227074d0 :CONTACTS
;;      ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((- (/ 2475 (EXPT (+ 25 (* 33 AMES.BASE:TAU)) 2))) 0)))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::OIL AMES-SCENARIO::BLOCK
;;        ((- (/ 2475 (EXPT (+ 25 (* 33 AMES.BASE:TAU)) 2))) 0))
;;       (:GRAVITY AMES-SCENARIO::BLOCK (0 -17/2))
;;       (:NORMAL AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 17/2))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((/ (* 25 (LOG (/ (+ 25 (* 33 AMES.BASE:TAU)) 25))) 11) 0)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK ((/ 75 (+ 25 (* 33 AMES.BASE:TAU))) 0)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (3 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :IMPULSE 5262601/1289504226 :ENERGY-LOST
;;       27694969285201/3325642297743718152)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (15 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;       (AMES-SCENARIO::BLOCK (5262601/1289504226 0)))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK))
;;        (AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :FEATURE (:EDGE 3 :OF AMES-SCENARIO::WALL)
;;         :OBSERVER-FEATURE (:EDGE 1 :OF AMES-SCENARIO::BLOCK)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 0)
;;        (:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL 5262601/1289504226))
;;       :ENERGY-LOST 27694969285201/3325642297743718152 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0))
;;        (AMES-SCENARIO::BLOCK (5262601/1289504226 0)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK (/ 5625 (* (EXPT (+ 25 (* 33 AMES.BASE:TAU)) 2) 2)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK) 0))
;;      :MOMENTUM ((:MOMENTUM AMES-SCENARIO::BLOCK ((/ 75 (+ 25 (* 33 AMES.BASE:TAU))) 0))))
;;     (:INDEX 1 :START 519965740/934967 :DURATION :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:EDGE 0 :OF AMES-SCENARIO::BLOCK))
;;       (AMES-SCENARIO::BLOCK AMES-SCENARIO::WALL :FEATURE (:EDGE 3 :OF AMES-SCENARIO::WALL)
;;        :OBSERVER-FEATURE (:EDGE 1 :OF AMES-SCENARIO::BLOCK)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::WALL (0 0)) (AMES-SCENARIO::BLOCK (0 0))) :FORCES
;;      ((:DRAG AMES-SCENARIO::OIL AMES-SCENARIO::BLOCK (0 0)) (:GRAVITY AMES-SCENARIO::BLOCK (0 -17/2))
;;       (:NORMAL AMES-SCENARIO::BLOCK AMES-SCENARIO::FLOOR 17/2)
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
