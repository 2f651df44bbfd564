;;;; witness-wrong-hinged-swing-777-982 -- a disagreement found by the witness (make crosscheck,
;;;; seed 777 #982), examined by hand: the comparator's, not AMES's.
;;;; verdict: ames-wrong (the comparator's); reason: state 0: velocity x swing at 0.9719 s: AMES
;;;;   0.23398165325773918d0, witness 0.2551821085659675d0
;;;; By hand: a uniform disc (r = 1/4, m = 1) hinged at its rim, released 39 degrees from the
;;;; vertical, g = 15: phi'' = -40 sin phi (I = 3/32 about the pin). Integrated (RK4, 2e5
;;;; steps) to the sample's time t = 0.9718640: phi = 0.647971, phi' = 1.270088, the centre's
;;;; vx = 0.253163. AMES's energy integral, omega = sqrt(-(80 sin(17 pi/60) + 80 sin s)), at
;;;; that angle (s = phi - pi/2) gives exactly 1.270088 and vx = 0.253163: AMES is right. The
;;;; witness (Moreau-Jean, step 1e-3, first order) says vx = 0.25518 (0.8 % off) and lags by
;;;; 0.0047 rad; the comparator evaluates AMES's velocity at the witness's position, 0.0055 s
;;;; from the turning point, where the speed goes as the square root of the energy left:
;;;; there AMES's formula gives 0.23398. A first-order witness's phase lag near a turning point
;;;; is taken for a wrong speed. To fix in the comparator (compare at AMES's own position at
;;;; the sample's time, integrating its energy integral) or the witness (a smaller step).
;;;; Fixed in the comparator (src/witness/compare-swing.lisp): a swing's velocity is now AMES's
;;;; at its own position at the sample's time (0.253163 here); it agrees (t/witness-comparator.lisp).
;;;; Run: bin/ames check witness/disagreements/witness-wrong-hinged-swing-777-982.lisp --numeric

(scenario hinged-swing-982 "A body hinged at a point swings under gravity." (gravity 15)
 (body swing :mass 1 :inertia :uniform :shape (circle 1/4) :position
  ((* 1/4 (cos (deg -51))) (* 1/4 (sin (deg -51)))) :angle (deg -51) :velocity (0 0)
  :angular-velocity 0)
 (hinge pin :body swing :at ((- 1/4) 0)) (simulate :states 1))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::HINGED-SWING-982 :STATES
;;    ((:INDEX 0 :START 0 :DURATION :FOREVER :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::SWING
;;        ((+ (* 20 (SIN (/ (* 17 PI) 60)) (COS AMES-SCENARIO::S))
;;            (* 30 (COS AMES-SCENARIO::S) (SIN AMES-SCENARIO::S)))
;;         (-
;;          (+ (* 20 (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))
;;             (* 30 (EXPT (SIN AMES-SCENARIO::S) 2)))
;;          10))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::SWING (0 -15))
;;       (:HINGE AMES-SCENARIO::PIN AMES-SCENARIO::SWING
;;        ((+ (* 20 (SIN (/ (* 17 PI) 60)) (COS AMES-SCENARIO::S))
;;            (* 30 (COS AMES-SCENARIO::S) (SIN AMES-SCENARIO::S)))
;;         (+ 5 (* 20 (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))
;;            (* 30 (EXPT (SIN AMES-SCENARIO::S) 2))))))
;;      :POSITIONS
;;      ((AMES-SCENARIO::SWING
;;        (:ON-PATH ((/ (COS AMES-SCENARIO::S) 4) (/ (SIN AMES-SCENARIO::S) 4)) :ARC-LENGTH
;;         AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::SWING
;;        (:ON-PATH
;;         ((* (SQRT 5) (SQRT (- (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))))
;;             (SIN AMES-SCENARIO::S))
;;          (-
;;           (* (SQRT 5) (COS AMES-SCENARIO::S)
;;              (SQRT (- (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S)))))))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::SWING (0 0))) :END-EVENT :NONE :FINAL-POSITIONS NIL
;;      :FINAL-VELOCITIES NIL :ANGLES ((AMES-SCENARIO::SWING AMES-SCENARIO::S)) :ANGULAR-VELOCITIES
;;      ((AMES-SCENARIO::SWING
;;        (- (SQRT (- (+ (* 80 (SIN (/ (* 17 PI) 60))) (* 80 (SIN AMES-SCENARIO::S))))))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::SWING (- (* 40 (COS AMES-SCENARIO::S))))) :FINAL-ANGLES
;;      NIL :FINAL-ANGULAR-VELOCITIES NIL :PERIODIC
;;      (:PERIOD (/ (* 2 (AMES-SCENARIO::ELLIPTIC-K (- (/ (- (SIN (/ (* 17 PI) 60)) 1) 2)))) (SQRT 10))
;;       :BETWEEN ((- (/ (* 17 PI) 60)) (- (/ (* 43 PI) 60))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::SWING
;;        (- (/ (+ (* 5 (SIN (/ (* 17 PI) 60))) (* 5 (SIN AMES-SCENARIO::S))) 2)))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::SWING)
;;        (- (/ (* 5 (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))) 4)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::SWING) (/ (* 15 (SIN AMES-SCENARIO::S)) 4)))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::SWING
;;        (-
;;         (/
;;          (* (SQRT 5) (SQRT (- (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))))
;;             (+ 1 (* 2 (EXPT (COS AMES-SCENARIO::S) 2)) (* 2 (EXPT (SIN AMES-SCENARIO::S) 2))))
;;          8)))
;;       (:MOMENTUM AMES-SCENARIO::SWING
;;        ((* (SQRT 5) (SQRT (- (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S))))
;;            (SIN AMES-SCENARIO::S))
;;         (-
;;          (* (SQRT 5) (COS AMES-SCENARIO::S)
;;             (SQRT (- (+ (SIN (/ (* 17 PI) 60)) (SIN AMES-SCENARIO::S)))))))))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (14 14) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 0.001d0 :EVENTS
;;    ((:TIME 0.5115681717377912d0 :PAIRS ((:TURNS "swing" "swing")) :POSITIONS
;;      (("swing" (-0.15782977933889056d0 -0.1938807900587154d0))) :VELOCITIES
;;      (("swing" (-2.6376859665194763d-8 -3.240274113218075d-8))) :ANGLES
;;      (("swing" -2.2540493018931382d0)) :ANGULAR-VELOCITIES (("swing" 0.0d0)) :HINGES NIL)
;;     (:TIME 1.0232519202277122d0 :PAIRS ((:TURNS "swing" "swing")) :POSITIONS
;;      (("swing" (0.15832983661980404d0 -0.19347264105159923d0))) :VELOCITIES
;;      (("swing" (1.4397985121424733d-8 -1.7594039120787455d-8))) :ANGLES
;;      (("swing" -0.8849614357331534d0)) :ANGULAR-VELOCITIES (("swing" 0.0d0)) :HINGES NIL)
;;     (:TIME 1.5350518853162343d0 :PAIRS ((:TURNS "swing" "swing")) :POSITIONS
;;      (("swing" (-0.15882971205263333d0 -0.1930624835872544d0))) :VELOCITIES
;;      (("swing" (-2.7847096324825835d-9 -3.3849459715761844d-9))) :ANGLES
;;      (("swing" -2.25921765889247d0)) :ANGULAR-VELOCITIES (("swing" 0.0d0)) :HINGES NIL))
;;    :SAMPLES
;;    ((:TIME 0.10230147543938867d0 :POSITIONS
;;      (("swing" (0.13120203175380826d0 -0.21280495416526693d0))) :VELOCITIES
;;      (("swing" (-0.5175392259018392d0 -0.32081344989334903d0))) :ANGLES
;;      (("swing" -1.0183062523881383d0)) :ANGULAR-VELOCITIES (("swing" -2.4356307711128014d0)))
;;     (:TIME 0.25575368859847164d0 :POSITIONS
;;      (("swing" (-2.028692073695708d-4 -0.24999950248240776d0))) :VELOCITIES
;;      (("swing" (-1.0575056456126533d0 -0.0036150470874001537d0))) :ANGLES
;;      (("swing" -1.571607803873003d0)) :ANGULAR-VELOCITIES (("swing" -4.230054323006842d0)))
;;     (:TIME 0.40920590175755467d0 :POSITIONS
;;      (("swing" (-0.13165911706805938d0 -0.21252250776399215d0))) :VELOCITIES
;;      (("swing" (-0.5195766284138716d0 0.32011873769172766d0))) :ANGLES
;;      (("swing" -2.1254356466558146d0)) :ANGULAR-VELOCITIES (("swing" -2.441102191845165d0)))
;;     (:TIME 0.6138088526363319d0 :POSITIONS (("swing" (-0.13169380097901465d0 -0.2125010245875119d0)))
;;      :VELOCITIES (("swing" (0.5182186822313877d0 -0.32290147734248054d0))) :ANGLES
;;      (("swing" -2.1255988398936525d0)) :ANGULAR-VELOCITIES (("swing" 2.442347398575577d0)))
;;     (:TIME 0.8184118035151093d0 :POSITIONS (("swing" (0.05303478936113123d0 -0.24430936442554158d0)))
;;      :VELOCITIES (("swing" (0.9850201348086938d0 0.20967086827050635d0))) :ANGLES
;;      (("swing" -1.3570324784027121d0)) :ANGULAR-VELOCITIES (("swing" 4.028360538224206d0)))
;;     (:TIME 0.9718640166741922d0 :POSITIONS (("swing" (0.1518184613892235d0 -0.19862311677573716d0)))
;;      :VELOCITIES (("swing" (0.2551821085659675d0 0.19452514279418007d0))) :ANGLES
;;      (("swing" -0.9181714943740413d0)) :ANGULAR-VELOCITIES (("swing" 1.28348251856289d0))))
;;    :END
;;    (:TIME 1.625d0 :POSITIONS (("swing" (-0.13861859170428842d0 -0.20805020075433667d0))) :VELOCITIES
;;     (("swing" (0.4551827904934278d0 -0.30471161827320237d0))) :ANGLES
;;     (("swing" -2.1585275417196197d0)) :ANGULAR-VELOCITIES (("swing" 2.191038267386702d0)) :HINGES
;;     (("pin" (5.273817447010136d0 12.877351448974895d0)))))
