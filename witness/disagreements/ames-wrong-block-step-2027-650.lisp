;;;; ames-wrong-block-step-2027-650 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong
;;;; reason: at the witness's step 6.25e-5 s: state 1: end time: AMES 1.0522262569844087d0, witness 0.8788125d0; at its step 0.001 s: state 1: end time: AMES 1.0522262569844087d0, witness 0.88d0
;;;; Examined (witness helper, session 6): AMES WRONG. The flat block lands on the ledge's edge
;;;; (0, 0) with e = 1 (agreed: one impulse at the edge, the bottom-left corner separating, the
;;;; unique solution of Newton's law at both points) and flies off spinning at
;;;; omega = -8 sqrt(1870)/31 = -11.16 rad/s, its centre at x = 3/20 rising at 19 sqrt(1870)/310.
;;;; Its left face (the far side at the start) comes round onto the ledge's edge at
;;;; t = 0.878743 s (the edge at (-0.375, -0.123) in the block's frame, within the face; by hand,
;;;; and the witness's 0.8788). AMES flew on to 1.0522 s, through the ledge, to the ledge's
;;;; lower corner: src/simulator/corners.lisp described a fixed corner only on the faces it
;;;; was in front of at the scenario's start, a rule a turning body breaks. Fixed on branch
;;;; s6-witness2 (a fixed corner on every face of a rotating body): state 1 then ends at
;;;; 0.878739 s and the verdict is agree.
;;;; Run: bin/ames check witness/disagreements/ames-wrong-block-step-2027-650.lisp --numeric

(scenario block-step-650 "A rod or a block falls across the edge of a ledge." (gravity 11)
 (body floor :fixed t :shape (half-plane (1 -1) (0 -1)))
 (body ledge :fixed t :shape (polygon (-7/2 -1) (0 -1) (0 0) (-7/2 0)))
 (body block :mass 11/4 :inertia :uniform :shape
  (polygon (-3/8 -3/8) (3/8 -3/8) (3/8 3/8) (-3/8 3/8)) :position (3/20 49/40) :angle 0 :velocity
  (0 0))
 (restitution 1) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::BLOCK-STEP-650 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ (SQRT 17) (SQRT 110)) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (0 -11)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::BLOCK (0 -121/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (3/20 (- (/ (- (* 220 (EXPT AMES.BASE:TAU 2)) 49) 40)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (0 (- (* 11 AMES.BASE:TAU)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (0 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE
;;       (/ (* 55 (SQRT 17) (SQRT 110)) 124) :ENERGY-LOST 0)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (3/20 3/8)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (0 (- (/ (* 11 (SQRT 17)) (SQRT 110))))))
;;      :ANGLES ((AMES-SCENARIO::BLOCK 0)) :ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK 0))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::BLOCK 0)) :FINAL-ANGLES ((AMES-SCENARIO::BLOCK 0))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK 0)) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :FEATURE (:VERTEX 2) :OBSERVER-FEATURE (:EDGE 0)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE (/ (* 55 (SQRT 17) (SQRT 110)) 124)))
;;       :ENERGY-LOST 0 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (0 (- (/ (* 11 (SQRT 17)) (SQRT 110))))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (0 (/ (* 19 (SQRT 17) (SQRT 110)) 310))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::BLOCK 0)) :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::BLOCK (- (/ (* 8 (SQRT 17) (SQRT 110)) 31)))))
;;      :EVENTS
;;      ((:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE
;;        (/ (* 55 (SQRT 17) (SQRT 110)) 124) :ENERGY-LOST 0)
;;       (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE
;;        (/ (* 55 (SQRT 17) (SQRT 110)) 124) :ENERGY-LOST 0))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK (/ (* 1331 (EXPT AMES.BASE:TAU 2)) 8))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::BLOCK) 0)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK)
;;        (- (/ (- (* 26620 (EXPT AMES.BASE:TAU 2)) 5929) 160))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::BLOCK (- (/ (* 363 AMES.BASE:TAU) 80)))
;;       (:MOMENTUM AMES-SCENARIO::BLOCK (0 (- (/ (* 121 AMES.BASE:TAU) 4))))))
;;     (:INDEX 1 :START (/ (SQRT 17) (SQRT 110)) :DURATION 0.6591035604309605d0 :CONTACTS NIL
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (0 -11)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::BLOCK (0 -121/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK
;;        (3/20
;;         (-
;;          (/ (- (* 6820 (EXPT AMES.BASE:TAU 2)) 465 (* 76 (SQRT 17) (SQRT 110) AMES.BASE:TAU))
;;             1240)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (0 (- (/ (- (* 3410 AMES.BASE:TAU) (* 19 (SQRT 17) (SQRT 110))) 310)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (0 (/ (* 19 (SQRT 17) (SQRT 110)) 310))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE
;;       (/
;;        (+ (* 33 (SQRT 17) (SQRT 110) (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))
;;           (* 33 (SQRT 17) (SQRT 110) (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;        (+ 155
;;           (* 186 (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;              (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))))
;;       :ENERGY-LOST 0)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK
;;        ((/
;;          (* 3
;;             (- (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;                (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;          8)
;;         -38758776/144945173)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (0 -212326104/46160545)))
;;      :ANGLES ((AMES-SCENARIO::BLOCK (- (/ (* 8 (SQRT 17) (SQRT 110) AMES.BASE:TAU) 31))))
;;      :ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK (- (/ (* 8 (SQRT 17) (SQRT 110)) 31))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::BLOCK 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::BLOCK (- (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK (- (/ (* 8 (SQRT 17) (SQRT 110)) 31)))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :FEATURE (:EDGE 1) :OBSERVER-FEATURE (:VERTEX 1)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE
;;         (/
;;          (+ (* 33 (SQRT 17) (SQRT 110) (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))
;;             (* 33 (SQRT 17) (SQRT 110) (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;          (+ 155
;;             (* 186 (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;                (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))))))
;;       :ENERGY-LOST 0 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (0 -212326104/46160545)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK
;;         ((/
;;           (+ (* 12 (SQRT 17) (SQRT 110) (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))
;;              (* 12 (SQRT 17) (SQRT 110) (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;           (+ 155
;;              (* 186 (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;                 (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684)))))
;;          -212326104/46160545)))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::BLOCK (- (/ (* 8 (SQRT 17) (SQRT 110)) 31))))
;;       :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::BLOCK
;;         (/
;;          (+ (* 8 (SQRT 17) (SQRT 110))
;;             (* 48 (SQRT 17) (SQRT 110) (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;                (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))
;;          (+ 155
;;             (* 186 (COS (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))
;;                (SIN (/ (* 8479675 (SQRT 17) (SQRT 110)) 49853684))))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK
;;        (/
;;         (- (+ 742577 (* 12790910 (EXPT AMES.BASE:TAU 2)))
;;            (* 142538 (SQRT 17) (SQRT 110) AMES.BASE:TAU))
;;         76880))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::BLOCK) 30855/1922)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK)
;;        (-
;;         (/ (- (* 825220 (EXPT AMES.BASE:TAU 2)) 56265 (* 9196 (SQRT 17) (SQRT 110) AMES.BASE:TAU))
;;            4960))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::BLOCK
;;        (- (/ (+ (* 33 (SQRT 17) (SQRT 110)) (* 3630 AMES.BASE:TAU)) 800)))
;;       (:MOMENTUM AMES-SCENARIO::BLOCK
;;        (0 (- (/ (- (* 37510 AMES.BASE:TAU) (* 209 (SQRT 17) (SQRT 110))) 1240)))))))
;;    :OUTCOME :STOPPED :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (30 30) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 6.25d-5 :COLLISION-SPEED 0.05d0 :EVENTS
;;    ((:TIME 0.3931875d0 :PAIRS ((:COLLISION "block" "ledge")) :POSITIONS
;;      (("block" (0.15d0 0.3749900390625228d0))) :VELOCITIES (("block" (0.0d0 -4.324375000000007d0)))
;;      :ANGLES (("block" 0.0d0)) :ANGULAR-VELOCITIES (("block" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.3931875d0 :PAIRS ((:LIFT-OFF "block" "ledge")) :POSITIONS
;;      (("block" (0.1500000028090261d0 0.3749457780627649d0))) :VELOCITIES
;;      (("block" (0.0d0 2.6502903225806502d0))) :ANGLES (("block" -3.616430411491715d-4))
;;      :ANGULAR-VELOCITIES (("block" -11.160564516129051d0)) :HINGES NIL)
;;     (:TIME 0.8788125d0 :PAIRS ((:COLLISION "block" "ledge")) :POSITIONS
;;      (("block" (0.1500000028090261d0 0.3650871950864481d0))) :VELOCITIES
;;      (("block" (0.0d0 -2.6908971774193846d0))) :ANGLES (("block" -5.419513250904049d0))
;;      :ANGULAR-VELOCITIES (("block" -11.160564516129051d0)) :HINGES NIL)
;;     (:TIME 0.8788125d0 :PAIRS ((:LIFT-OFF "block" "ledge")) :POSITIONS
;;      (("block" (0.15012012041189413d0 0.36505955584055244d0))) :VELOCITIES
;;      (("block" (3.825278519092802d0 1.7848300253265013d0))) :ANGLES (("block" -5.41996791893917d0))
;;      :ANGULAR-VELOCITIES (("block" -3.426185988408684d0)) :HINGES NIL))
;;    :END
;;    (:TIME 1.0721875d0 :POSITIONS (("block" (0.8898333540414319d0 0.5045346635505632d0))) :VELOCITIES
;;     (("block" (3.825278519092802d0 -0.34229497467350767d0))) :ANGLES (("block" -6.082506634447735d0))
;;     :ANGULAR-VELOCITIES (("block" -3.426185988408684d0)) :HINGES NIL))
