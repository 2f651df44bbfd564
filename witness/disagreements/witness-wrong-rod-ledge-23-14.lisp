;;;; witness-wrong-rod-ledge-23-14 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong
;;;; reason: state 2: final angular velocity rod: AMES -5.086321032638d0, witness -4.913095241582052d0
;;;; make crosscheck N=30 SEED=23 FAMILIES=rod-ledge #14, examined: the witness's step, not AMES.
;;;; The rod (spinning at 23 rad/s after its first landing on the ledge's edge) strikes the edge
;;;; again; the first-order witness (Moreau-Jean, step 1e-3) puts that impact on its step grid,
;;;; 0.75 ms late, when the rod has turned 0.008 rad further: the impulse, which depends on where
;;;; the rod is struck, leaves it at omega -4.913 (3.4 % off AMES's -5.0863). Refining the
;;;; witness's step, omega after that impact: -4.9131 (1e-3), -5.0761 (2.5e-4), -5.0827
;;;; (6.25e-5), converging on AMES's -5.0863 (first-order extrapolation of the last two:
;;;; -5.0849); every other value converges likewise. AMES is right. Fixed in the comparator: a
;;;; first-order witness's disagreement is compared again at a quarter of its step
;;;; (src/witness/refine.lisp); at 2.5e-4 every value agrees to 20 steps (0.5 %).
;;;; The witness's answers at both steps are kept below (t/witness-comparator.lisp reads them).
;;;; Run: bin/ames check witness/disagreements/witness-wrong-rod-ledge-23-14.lisp --numeric

(scenario rod-ledge-14 "A rod or a block falls across the edge of a ledge." (gravity 29/2)
 (body floor :fixed t :shape (half-plane (1 -5/4) (0 -5/4)))
 (body ledge :fixed t :shape (polygon (-3/2 -5/4) (0 -5/4) (0 0) (-3/2 0)))
 (body rod :mass 3/2 :inertia :uniform :shape (segment (-1/4 0) (1/4 0)) :position (1/5 3/4) :angle
  0 :velocity (0 0))
 (restitution 1/2) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::ROD-LEDGE-14 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ (SQRT 3) (SQRT 29)) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 -29/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::ROD (0 -87/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (1/5 (- (/ (- (* 29 (EXPT AMES.BASE:TAU 2)) 3) 4)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (0 (- (/ (* 29 AMES.BASE:TAU) 2)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :IMPULSE
;;       (/ (* 25 (EXPT 3 5/2) (SQRT 29)) 584) :ENERGY-LOST 19575/4672)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (1/5 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (0 (- (/ (* (SQRT 3) (SQRT 29)) 2)))))
;;      :ANGLES ((AMES-SCENARIO::ROD 0)) :ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD 0))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::ROD 0)) :FINAL-ANGLES ((AMES-SCENARIO::ROD 0))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD 0)) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :FEATURE (:VERTEX 2) :OBSERVER-FEATURE (:EDGE 0)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE (/ (* 25 (EXPT 3 5/2) (SQRT 29)) 584)))
;;       :ENERGY-LOST 19575/4672 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (0 (- (/ (* (SQRT 3) (SQRT 29)) 2)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (0 (- (/ (* 71 (SQRT 3) (SQRT 29)) 292)))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::ROD 0)) :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::ROD (- (/ (* 20 (EXPT 3 5/2) (SQRT 29)) 73)))))
;;      :EVENTS
;;      ((:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :IMPULSE
;;        (/ (* 25 (EXPT 3 5/2) (SQRT 29)) 584) :ENERGY-LOST 19575/4672)
;;       (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :IMPULSE
;;        (/ (* 25 (EXPT 3 5/2) (SQRT 29)) 584) :ENERGY-LOST 19575/4672))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::ROD (/ (* 2523 (EXPT AMES.BASE:TAU 2)) 16))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::ROD) 0)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::ROD) (- (/ (- (* 2523 (EXPT AMES.BASE:TAU 2)) 261) 16))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::ROD (- (/ (* 87 AMES.BASE:TAU) 20)))
;;       (:MOMENTUM AMES-SCENARIO::ROD (0 (- (/ (* 87 AMES.BASE:TAU) 4))))))
;;     (:INDEX 1 :START (/ (SQRT 3) (SQRT 29)) :DURATION
;;      (- (/ (* 73 (- (ACOS 4/5) PI)) (* (EXPT 3 5/2) (SQRT 29) 20))) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 -29/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::ROD (0 -87/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        (1/5 (- (/ (* AMES.BASE:TAU (+ (* 71 (SQRT 3) (SQRT 29)) (* 2117 AMES.BASE:TAU))) 292)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (0 (- (/ (+ (* 71 (SQRT 3) (SQRT 29)) (* 4234 AMES.BASE:TAU)) 292)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (0 (- (/ (* 71 (SQRT 3) (SQRT 29)) 292)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :IMPULSE
;;       (/ (* 25 (EXPT 3 11/2) (SQRT 29)) 15184) :ENERGY-LOST 14270175/4433728)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        (1/5 (- (/ (* (- (ACOS 4/5) PI) (- (* 5329 (ACOS 4/5)) 38340 (* 5329 PI))) 388800)))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        (0 (/ (* (SQRT 29) (- (* 5329 (ACOS 4/5)) 19170 (* 5329 PI))) (* (EXPT 3 5/2) 2920)))))
;;      :ANGLES ((AMES-SCENARIO::ROD (- (/ (* 20 (EXPT 3 5/2) (SQRT 29) AMES.BASE:TAU) 73))))
;;      :ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD (- (/ (* 20 (EXPT 3 5/2) (SQRT 29)) 73))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::ROD 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::ROD (- (ACOS 4/5) PI))) :FINAL-ANGULAR-VELOCITIES
;;      ((AMES-SCENARIO::ROD (- (/ (* 20 (EXPT 3 5/2) (SQRT 29)) 73)))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :FEATURE (:EDGE 1) :OBSERVER-FEATURE (:VERTEX 1)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE (/ (* 25 (EXPT 3 11/2) (SQRT 29)) 15184)))
;;       :ENERGY-LOST 14270175/4433728 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD
;;         (0 (/ (* (SQRT 29) (- (* 5329 (ACOS 4/5)) 19170 (* 5329 PI))) (* (EXPT 3 5/2) 2920)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD
;;         ((/ (* 25 (EXPT 3 9/2) (SQRT 29)) 7592)
;;          (/ (* (SQRT 29) (- (* 5329 (ACOS 4/5)) 19170 (* 5329 PI))) (* (EXPT 3 5/2) 2920)))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::ROD (- (/ (* 20 (EXPT 3 5/2) (SQRT 29)) 73))))
;;       :ANGULAR-VELOCITIES-AFTER ((AMES-SCENARIO::ROD (- (/ (* 115 (EXPT 3 5/2) (SQRT 29)) 1898)))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::ROD
;;        (/
;;         (+ 1315701 (* 20732 (EXPT 3 3/2) (EXPT 29 3/2) AMES.BASE:TAU)
;;            (* 53780268 (EXPT AMES.BASE:TAU 2)))
;;         341056))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::ROD) 176175/21316)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::ROD)
;;        (- (/ (* 87 AMES.BASE:TAU (+ (* 71 (SQRT 3) (SQRT 29)) (* 2117 AMES.BASE:TAU))) 1168))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::ROD
;;        (- (/ (+ (* (EXPT 3 3/2) (SQRT 29)) (* 87 AMES.BASE:TAU)) 20)))
;;       (:MOMENTUM AMES-SCENARIO::ROD
;;        (0 (- (/ (+ (* 71 (EXPT 3 3/2) (SQRT 29)) (* 12702 AMES.BASE:TAU)) 584))))))
;;     (:INDEX 2 :START
;;      (-
;;       (/ (- (* 73 (SQRT 29) (ACOS 4/5)) (* 540 (SQRT 29)) (* 73 (SQRT 29) PI)) (* (EXPT 3 5/2) 580)))
;;      :DURATION 0.17006141480792164d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 -29/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::ROD (0 -87/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        ((/ (+ 7592 (* 125 (EXPT 3 9/2) (SQRT 29) AMES.BASE:TAU)) 37960)
;;         (-
;;          (/
;;           (-
;;            (+ (* 103660 (EXPT 3 7/2) PI) (* 389017 (SQRT 3) (EXPT PI 2))
;;               (* 389017 (SQRT 3) (EXPT (ACOS 4/5) 2)) (* 20703600 (SQRT 29) AMES.BASE:TAU)
;;               (* 5755320 (SQRT 29) PI AMES.BASE:TAU) (* 846800 (EXPT 3 11/2) (EXPT AMES.BASE:TAU 2)))
;;            (* 103660 (EXPT 3 7/2) (ACOS 4/5)) (* 778034 (SQRT 3) PI (ACOS 4/5))
;;            (* 5755320 (SQRT 29) (ACOS 4/5) AMES.BASE:TAU))
;;           (* (EXPT 3 11/2) 116800))))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        ((/ (* 25 (EXPT 3 9/2) (SQRT 29)) 7592)
;;         (-
;;          (/
;;           (- (+ (* 19170 (SQRT 29)) (* 5329 (SQRT 29) PI) (* 42340 (EXPT 3 5/2) AMES.BASE:TAU))
;;              (* 5329 (SQRT 29) (ACOS 4/5)))
;;           (* (EXPT 3 5/2) 2920))))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        ((/ (* 25 (EXPT 3 9/2) (SQRT 29)) 7592)
;;         (/ (* (SQRT 29) (- (* 5329 (ACOS 4/5)) 19170 (* 5329 PI))) (* (EXPT 3 5/2) 2920)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR :IMPULSE
;;       (-
;;        (/
;;         (-
;;          (* 1941181715 (EXPT 3 9/2) (SQRT 29)
;;             (COS
;;              (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                 5388404918)))
;;          7276354286760)
;;         (+ 512607011488
;;            (* 1537821034464
;;               (EXPT
;;                (COS
;;                 (/
;;                  (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                  5388404918))
;;                2)))))
;;       :ENERGY-LOST
;;       (/
;;        (-
;;         (+ 5882814634050069812366400
;;            (* 238989689259596591513175
;;               (EXPT
;;                (COS
;;                 (/
;;                  (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                  5388404918))
;;                2)))
;;         (* 3138827976293417465200 (EXPT 3 9/2) (SQRT 29)
;;            (COS
;;             (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                5388404918))))
;;        (+ 262765948226658563974144
;;           (* 788297844679975691922432
;;              (EXPT
;;               (COS
;;                (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918))
;;               2)))))
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (12301447/19742603 -163469216/136785149)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (362152913/145567200 -106491545/16879841)))
;;      :ANGLES
;;      ((AMES-SCENARIO::ROD
;;        (-
;;         (/ (- (+ (* 1898 PI) (* 115 (EXPT 3 5/2) (SQRT 29) AMES.BASE:TAU)) (* 1898 (ACOS 4/5)))
;;            1898))))
;;      :ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD (- (/ (* 115 (EXPT 3 5/2) (SQRT 29)) 1898))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::ROD 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::ROD
;;        (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;           5388404918)))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD (- (/ (* 115 (EXPT 3 5/2) (SQRT 29)) 1898))))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0) :OBSERVER-FEATURE (:VERTEX 0)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR
;;         (-
;;          (/
;;           (-
;;            (* 1941181715 (EXPT 3 9/2) (SQRT 29)
;;               (COS
;;                (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918)))
;;            7276354286760)
;;           (+ 512607011488
;;              (* 1537821034464
;;                 (EXPT
;;                  (COS
;;                   (/
;;                    (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29))
;;                       (* 5388404918 PI))
;;                    5388404918))
;;                  2)))))))
;;       :ENERGY-LOST
;;       (/
;;        (-
;;         (+ 5882814634050069812366400
;;            (* 238989689259596591513175
;;               (EXPT
;;                (COS
;;                 (/
;;                  (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                  5388404918))
;;                2)))
;;         (* 3138827976293417465200 (EXPT 3 9/2) (SQRT 29)
;;            (COS
;;             (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                5388404918))))
;;        (+ 262765948226658563974144
;;           (* 788297844679975691922432
;;              (EXPT
;;               (COS
;;                (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918))
;;               2))))
;;       :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (362152913/145567200 -106491545/16879841)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD
;;         (362152913/145567200
;;          (/
;;           (-
;;            (* 4850902857840
;;               (EXPT
;;                (SIN
;;                 (/
;;                  (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                  5388404918))
;;                2))
;;            4042419048200
;;            (* 1941181715 (EXPT 3 7/2) (SQRT 29)
;;               (COS
;;                (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918))))
;;           (+ 256303505744
;;              (* 768910517232
;;                 (EXPT
;;                  (COS
;;                   (/
;;                    (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29))
;;                       (* 5388404918 PI))
;;                    5388404918))
;;                  2)))))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::ROD (- (/ (* 115 (EXPT 3 5/2) (SQRT 29)) 1898))))
;;       :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::ROD
;;         (/
;;          (-
;;           (* 1941181715 (EXPT 3 7/2) (SQRT 29)
;;              (EXPT
;;               (COS
;;                (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918))
;;               2))
;;           (* 3882363430 (EXPT 3 5/2) (SQRT 29))
;;           (* 7276354286760
;;              (COS
;;               (/ (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                  5388404918))))
;;          (+ 64075876436
;;             (* 192227629308
;;                (EXPT
;;                 (COS
;;                  (/
;;                   (- (* 5388404918 (ACOS 4/5)) (* 55522325 (EXPT 3 5/2) (SQRT 29)) (* 5388404918 PI))
;;                   5388404918))
;;                 2)))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::ROD
;;        (/
;;         (* 29
;;            (-
;;             (+ 136839514725 (* 34529042340 PI) (* 4799302729 (EXPT PI 2))
;;                (* 4799302729 (EXPT (ACOS 4/5) 2)) (* 350370800 (EXPT 3 11/2) (SQRT 29) AMES.BASE:TAU)
;;                (* 2629754920 (EXPT 3 5/2) (SQRT 29) PI AMES.BASE:TAU)
;;                (* 2538614098800 (EXPT AMES.BASE:TAU 2)))
;;             (* 34529042340 (ACOS 4/5)) (* 9598605458 PI (ACOS 4/5))
;;             (* 2629754920 (EXPT 3 5/2) (SQRT 29) (ACOS 4/5) AMES.BASE:TAU)))
;;         466871558400))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::ROD) 93196575/230553856)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::ROD)
;;        (-
;;         (/
;;          (* 29
;;             (-
;;              (+ (* 103660 (EXPT 3 7/2) PI) (* 389017 (SQRT 3) (EXPT PI 2))
;;                 (* 389017 (SQRT 3) (EXPT (ACOS 4/5) 2)) (* 20703600 (SQRT 29) AMES.BASE:TAU)
;;                 (* 5755320 (SQRT 29) PI AMES.BASE:TAU)
;;                 (* 846800 (EXPT 3 11/2) (EXPT AMES.BASE:TAU 2)))
;;              (* 103660 (EXPT 3 7/2) (ACOS 4/5)) (* 778034 (SQRT 3) PI (ACOS 4/5))
;;              (* 5755320 (SQRT 29) (ACOS 4/5) AMES.BASE:TAU)))
;;          (* (EXPT 3 9/2) 467200)))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::ROD
;;        (-
;;         (/
;;          (-
;;           (+ (* 19675440 (SQRT 29)) (* (+ (* 4192772 (SQRT 29)) (* 2398050 (SQRT 29) PI)) (ACOS 4/5))
;;              (* 35226880 (EXPT 3 5/2) AMES.BASE:TAU)
;;              (* 21870000 (EXPT 29 3/2) (EXPT AMES.BASE:TAU 2)))
;;           (* 4192772 (SQRT 29) PI) (* 1199025 (SQRT 29) (EXPT PI 2))
;;           (* 1199025 (SQRT 29) (EXPT (ACOS 4/5) 2)))
;;          (* (EXPT 3 3/2) 24294400))))
;;       (:MOMENTUM AMES-SCENARIO::ROD
;;        ((/ (* 25 (EXPT 3 11/2) (SQRT 29)) 15184)
;;         (-
;;          (/
;;           (- (+ (* 19170 (SQRT 29)) (* 5329 (SQRT 29) PI) (* 42340 (EXPT 3 5/2) AMES.BASE:TAU))
;;              (* 5329 (SQRT 29) (ACOS 4/5)))
;;           (* (EXPT 3 3/2) 5840))))))))
;;    :OUTCOME :STATE-LIMIT :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1 2) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (45 45) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 0.001d0 :EVENTS
;;    ((:TIME 0.323d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.2d0 -0.0017089999999978546d0))) :VELOCITIES (("rod" (0.0d0 -4.6689999999999845d0)))
;;      :ANGLES (("rod" 0.0d0)) :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.323d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20001135829920422d0 -0.004199006973053939d0))) :VELOCITIES
;;      (("rod" (0.0d0 -2.280075342465746d0))) :ANGLES (("rod" -0.020990759123528446d0))
;;      :ANGULAR-VELOCITIES (("rod" -23.072876712328693d0)) :HINGES NIL)
;;     (:TIME 0.431d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20001135829920422d0 -0.3311723186168884d0))) :VELOCITIES
;;      (("rod" (0.0d0 -3.8315753424657397d0))) :ANGLES (("rod" -2.489788567342694d0))
;;      :ANGULAR-VELOCITIES (("rod" -23.072876712328693d0)) :HINGES NIL)
;;     (:TIME 0.431d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20106067405924502d0 -0.33501114395935416d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 -3.8460753424657397d0))) :ANGLES (("rod" -2.50519641763622d0))
;;      :ANGULAR-VELOCITIES (("rod" -4.913095241582052d0)) :HINGES NIL)
;;     (:TIME 0.6011436781692444d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.6255114206600468d0 -1.199081767702664d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 -5.895505621907054d0))) :ANGLES (("rod" -3.3388351214741747d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.602d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6251529923783603d0 -1.198368952178529d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 -6.31107534246573d0))) :ANGLES (("rod" -3.3404226087051425d0))
;;      :ANGULAR-VELOCITIES (("rod" -4.913095241582052d0)) :HINGES NIL)
;;     (:TIME 0.6115984130106746d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.6515924367560103d0 -1.2346409740506177d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 -1.1106977011516204d0))) :ANGLES (("rod" -3.0743100237574055d0))
;;      :ANGULAR-VELOCITIES (("rod" -3.552713678800501d-15)) :HINGES NIL)
;;     (:TIME 0.612d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6500995993383083d0 -1.2346857902337312d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 -3.5492102549646236d0))) :ANGLES (("rod" -3.0658352872911183d0))
;;      :ANGULAR-VELOCITIES (("rod" 29.282045658519475d0)) :HINGES NIL)
;;     (:TIME 0.612d0 :PAIRS ((:LIFT-OFF "rod" "floor")) :POSITIONS
;;      (("rod" (0.6525942600343031d0 -1.2346108985079263d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 0.5257555467710495d0))) :ANGLES (("rod" -3.079997306356734d0))
;;      :ANGULAR-VELOCITIES (("rod" -19.650790252761094d0)) :HINGES NIL)
;;     (:TIME 0.6199724824320039d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.6724828986069321d0 -1.229723015041845d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 2.0524561268615145d0))) :ANGLES (("rod" -3.222818270333637d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.62d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6700568849062667d0 -1.231285859680529d0))) :VELOCITIES
;;      (("rod" (2.494660695994795d0 0.4242555467710495d0))) :ANGLES (("rod" -3.2175528381260605d0))
;;      :ANGULAR-VELOCITIES (("rod" -19.650790252761094d0)) :HINGES NIL))
;;    :END
;;    (:TIME 0.62d0 :POSITIONS (("rod" (0.6725515456022615d0 -1.229678792460339d0))) :VELOCITIES
;;     (("rod" (2.494660695994795d0 2.0985280338693157d0))) :ANGLES (("rod" -3.222967262113882d0))
;;     :ANGULAR-VELOCITIES (("rod" 0.5560429054169198d0)) :HINGES NIL))

;; witness's answer at a quarter of its step:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 2.5d-4 :EVENTS
;;    ((:TIME 0.322d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.2d0 -5.422031249972758d-4))) :VELOCITIES (("rod" (0.0d0 -4.665374999999982d0)))
;;      :ANGLES (("rod" 0.0d0)) :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.322d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20000082160036578d0 -0.0011237354645932934d0))) :VELOCITIES
;;      (("rod" (0.0d0 -2.271161815068485d0))) :ANGLES (("rod" -0.005618595117029937d0))
;;      :ANGULAR-VELOCITIES (("rod" -23.01924657534238d0)) :HINGES NIL)
;;     (:TIME 0.4305d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20000082160036578d0 -0.3319329550707565d0))) :VELOCITIES
;;      (("rod" (0.0d0 -3.840786815068479d0))) :ANGLES (("rod" -2.497452036897841d0))
;;      :ANGULAR-VELOCITIES (("rod" -23.01924657534238d0)) :HINGES NIL)
;;     (:TIME 0.4305d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.2003690021861621d0 -0.3328936048995235d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -3.8444118150684785d0))) :ANGLES (("rod" -2.5005556096059376d0))
;;      :ANGULAR-VELOCITIES (("rod" -5.076105973647877d0)) :HINGES NIL)
;;     (:TIME 0.6002869219537396d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.6231350796857774d0 -1.1945866923668598d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -5.8728046022906435d0))) :ANGLES (("rod" -3.361968252663555d0))
;;      :ANGULAR-VELOCITIES (("rod" 8.881784197001252d-16)) :HINGES NIL)
;;     (:TIME 0.6005d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6230431447512343d0 -1.1943917136323972d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -6.30578681506847d0))) :ANGLES (("rod" -3.362224598632599d0))
;;      :ANGULAR-VELOCITIES (("rod" -5.076105973647877d0)) :HINGES NIL)
;;     (:TIME 0.6005d0 :PAIRS ((:LIFT-OFF "rod" "floor")) :POSITIONS
;;      (("rod" (0.6236656398065584d0 -1.1957119223071482d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -3.374047233839438d0))) :ANGLES (("rod" -3.3604888700004403d0))
;;      :ANGULAR-VELOCITIES (("rod" 29.29440709196121d0)) :HINGES NIL)
;;     (:TIME 0.6106501377114766d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.6489392819515712d0 -1.2304982050192927d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -1.073315660450056d0))) :ANGLES (("rod" -3.065633519704742d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.61075d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6485654420195238d0 -1.2301773946455425d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 -3.5190472338394376d0))) :ANGLES (("rod" -3.067544799080824d0))
;;      :ANGULAR-VELOCITIES (("rod" 29.29440709196121d0)) :HINGES NIL)
;;     (:TIME 0.61075d0 :PAIRS ((:LIFT-OFF "rod" "floor")) :POSITIONS
;;      (("rod" (0.6491879370748479d0 -1.2307115881712647d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 0.553433206510134d0))) :ANGLES (("rod" -3.064362255272735d0))
;;      :ANGULAR-VELOCITIES (("rod" -19.48482166384145d0)) :HINGES NIL)
;;     (:TIME 0.6197440507822548d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.671582945631999d0 -1.2261209897603316d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 2.053841721414219d0))) :ANGLES (("rod" -3.237226403996221d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.61975d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.6709752640111927d0 -1.226424125739301d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 0.4265582065101337d0))) :ANGLES (("rod" -3.2348544448313503d0))
;;      :ANGULAR-VELOCITIES (("rod" -19.48482166384145d0)) :HINGES NIL)
;;     (:TIME 0.61975d0 :PAIRS ((:LIFT-OFF "rod" "floor")) :POSITIONS
;;      (("rod" (0.6715977590665168d0 -1.226113600224725d0))) :VELOCITIES
;;      (("rod" (2.489980221296475d0 2.093509957155465d0))) :ANGLES (("rod" -3.2372842251653404d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.4749808451067423d0)) :HINGES NIL))
;;    :END
;;    (:TIME 0.62025d0 :POSITIONS (("rod" (0.6728427491771649d0 -1.2250686577461474d0))) :VELOCITIES
;;     (("rod" (2.489980221296475d0 2.086259957155466d0))) :ANGLES (("rod" -3.237046734742787d0))
;;     :ANGULAR-VELOCITIES (("rod" 0.4749808451067423d0)) :HINGES NIL))
