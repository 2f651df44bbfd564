;;;; witness-unseen-impact-block-step-2026-433 -- a disagreement found by the witness (make crosscheck
;;;; N=1000 SEED=2026 #433), examined by hand: the witness's, not AMES's.
;;;; verdict: ames-wrong
;;;; reason: state 1: AMES ends the state with (:COLLISION BLOCK LEDGE) at 0.4276374438004553d0; the witness has no more events
;;;; A square block (side 7/4) tilted by atan(20/99) lands plastically on its lowest corner on
;;;; the ledge's top at t = 2/sqrt(23) (approach speed sqrt(23), ω = 0 before; after it
;;;; ω = -3.3534, the witness -3.3613 at its step 1e-3: agreed). After the impact the corner's
;;;; height is h(τ) = y(τ) - (7/8)(sin θ + cos θ): h(0) = 0, h'(0) = 0 (plastic), h''(0) =
;;;; -g + (7/8)(sin θ + cos θ) ω^2 = +0.093 > 0, h''' = -25.8: the corner lifts by under a
;;;; micrometre and strikes the ledge again at τ = 0.0106 s, AMES's second collision (a Taylor
;;;; estimate gives 0.0108). Its approach speed, from AMES's own impulse J = 4.31e-4 and energy
;;;; lost E = 1.07e-7 (plastic: v = 2 E / J, exact whatever the effective mass; the first impact
;;;; gives sqrt(23) this way), is 4.97e-4 m/s. The rotation witness counts a closing as a
;;;; collision only above max(0.05, 20 g h) = 0.23 m/s, and its first-order motion cannot
;;;; resolve a 1-micrometre gap: it has the lift-off and then nothing. AMES is right. Fixed in
;;;; the comparator: a collision of AMES's slower than half the witness's stated collision speed,
;;;; which the witness does not have, is unsupported, said so (src/witness/compare-slow-impacts.lisp).
;;;; Run: bin/ames check witness/disagreements/witness-unseen-impact-block-step-2026-433.lisp --numeric

(scenario block-step-433 "A rod or a block falls across the edge of a ledge." (gravity 23/2)
 (body floor :fixed t :shape (half-plane (1 -1/2) (0 -1/2)))
 (body ledge :fixed t :shape (polygon (-17/4 -1/2) (0 -1/2) (0 0) (-17/4 0)))
 (body block :mass 7/4 :inertia :uniform :shape
  (polygon (-7/8 -7/8) (7/8 -7/8) (7/8 7/8) (-7/8 7/8)) :position (399/1616 1641/808) :angle
  (atan 20/99) :velocity (1/4 0))
 (restitution 0) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::BLOCK-STEP-433 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ 2 (SQRT 23)) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (0 -23/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::BLOCK (0 -161/8))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK
;;        ((/ (+ 399 (* 404 AMES.BASE:TAU)) 1616)
;;         (- (/ (- (* 4646 (EXPT AMES.BASE:TAU 2)) 1641) 808)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (1/4 (- (/ (* 23 AMES.BASE:TAU) 2)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (1/4 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE (/ (* 71407 (SQRT 23)) 78250)
;;       :ENERGY-LOST 1642361/156500)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK ((/ (+ 808 (* 399 (SQRT 23))) (* (SQRT 23) 1616)) 833/808)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (1/4 (- (SQRT 23)))))
;;      :ANGLES ((AMES-SCENARIO::BLOCK (ATAN 20/99))) :ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK 0))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::BLOCK 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::BLOCK (ATAN 20/99))) :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK 0))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :FEATURE (:EDGE 2) :OBSERVER-FEATURE (:VERTEX 0)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE (/ (* 71407 (SQRT 23)) 78250)))
;;       :ENERGY-LOST 1642361/156500 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (1/4 (- (SQRT 23)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (1/4 (- (/ (* 18723 (SQRT 23)) 39125)))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::BLOCK 0)) :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::BLOCK (- (/ (* 191496 (SQRT 23)) 273875)))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK (/ (+ 7 (* 14812 (EXPT AMES.BASE:TAU 2))) 128))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::BLOCK) 0)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK)
;;        (- (/ (- (* 748006 (EXPT AMES.BASE:TAU 2)) 264201) 6464))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::BLOCK
;;        (- (/ (+ 11487 (* 64239 AMES.BASE:TAU) (* 32522 (EXPT AMES.BASE:TAU 2))) 12928)))
;;       (:MOMENTUM AMES-SCENARIO::BLOCK (7/16 (- (/ (* 161 AMES.BASE:TAU) 8))))))
;;     (:INDEX 1 :START (/ 2 (SQRT 23)) :DURATION 0.010608615686305774d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::BLOCK (0 -23/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::BLOCK (0 -161/8))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK
;;        ((/ (+ 808 (* 399 (SQRT 23)) (* 404 (SQRT 23) AMES.BASE:TAU)) (* (SQRT 23) 1616))
;;         (-
;;          (/
;;           (- (+ (* 15128184 (SQRT 23) AMES.BASE:TAU) (* 181774750 (EXPT AMES.BASE:TAU 2))) 32591125)
;;           31613000)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (1/4 (- (/ (+ (* 37446 (SQRT 23)) (* 899875 AMES.BASE:TAU)) 78250)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (1/4 (- (/ (* 18723 (SQRT 23)) 39125)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :IMPULSE
;;       (-
;;        (/
;;         (-
;;          (+ 4572168502300
;;             (* 1157334537093 (SQRT 23)
;;                (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;          (* 1157334537093 (SQRT 23)
;;             (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;         (-
;;          (* 3242849176500
;;             (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;             (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;          2702374313750)))
;;       :ENERGY-LOST
;;       (/
;;        (-
;;         (+
;;          (* 1511865290605875887375400 (SQRT 23)
;;             (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;          (*
;;           (-
;;            (* 8801924087774336467567122
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;            (* 1511865290605875887375400 (SQRT 23)))
;;           (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;         7387351302947771820253561)
;;        (-
;;         (* 1752678463587788025375000
;;            (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;            (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;         1460565386323156687812500)))
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (65654681/185562017 110322093/109669933)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::BLOCK (1/4 -83471812/34535135)))
;;      :ANGLES
;;      ((AMES-SCENARIO::BLOCK
;;        (- (/ (- (* 191496 (SQRT 23) AMES.BASE:TAU) (* 273875 (ATAN 20/99))) 273875))))
;;      :ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK (- (/ (* 191496 (SQRT 23)) 273875))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::BLOCK 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::BLOCK
;;        (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::BLOCK (- (/ (* 191496 (SQRT 23)) 273875)))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE :FEATURE (:EDGE 2) :OBSERVER-FEATURE (:VERTEX 0)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::BLOCK AMES-SCENARIO::LEDGE
;;         (-
;;          (/
;;           (-
;;            (+ 4572168502300
;;               (* 1157334537093 (SQRT 23)
;;                  (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;            (* 1157334537093 (SQRT 23)
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;           (-
;;            (* 3242849176500
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;               (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;            2702374313750)))))
;;       :ENERGY-LOST
;;       (/
;;        (-
;;         (+
;;          (* 1511865290605875887375400 (SQRT 23)
;;             (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;          (*
;;           (-
;;            (* 8801924087774336467567122
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;            (* 1511865290605875887375400 (SQRT 23)))
;;           (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;         7387351302947771820253561)
;;        (-
;;         (* 1752678463587788025375000
;;            (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;            (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;         1460565386323156687812500))
;;       :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK (1/4 -83471812/34535135)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::BLOCK
;;         (1/4
;;          (-
;;           (/
;;            (-
;;             (*
;;              (+ (* 330667010598 (SQRT 23))
;;                 (* 3919001573400
;;                    (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;              (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;             1959500786700
;;             (* 330667010598 (SQRT 23)
;;                (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;            (-
;;             (* 1621424588250
;;                (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;                (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;             1351187156875))))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::BLOCK (- (/ (* 191496 (SQRT 23)) 273875))))
;;       :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::BLOCK
;;         (-
;;          (/
;;           (-
;;            (* 15676006293600
;;               (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;            (* 2645336084784 (SQRT 23))
;;            (* 15676006293600
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))))
;;           (-
;;            (* 11349972117750
;;               (COS (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425))
;;               (SIN (/ (- (* 74538203425 (ATAN 20/99)) (* 552897917 (SQRT 23))) 74538203425)))
;;            9458310098125))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BLOCK
;;        (/
;;         (+ 913734037279 (* 82044186000 (EXPT 23 3/2) AMES.BASE:TAU)
;;            (* 22673700437500 (EXPT AMES.BASE:TAU 2)))
;;         195938000000))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::BLOCK) 30749925003/6123062500)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BLOCK)
;;        (-
;;         (/
;;          (- (+ (* 105897288 (EXPT 23 3/2) AMES.BASE:TAU) (* 29265734750 (EXPT AMES.BASE:TAU 2)))
;;             5247171125)
;;          252904000))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::BLOCK
;;        (-
;;         (/
;;          (+ 9671298658 (* 439932451 (SQRT 23))
;;             (* (+ 5089693000 (* 109276125 (EXPT 23 3/2))) AMES.BASE:TAU)
;;             (* 55322750 (EXPT 23 3/2) (EXPT AMES.BASE:TAU 2)))
;;          (* (SQRT 23) 505808000))))
;;       (:MOMENTUM AMES-SCENARIO::BLOCK
;;        (7/16 (- (/ (+ (* 262122 (SQRT 23)) (* 6299125 AMES.BASE:TAU)) 313000)))))))
;;    :OUTCOME :STOPPED :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (30 30) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 0.001d0 :EVENTS
;;    ((:TIME 0.418d0 :PAIRS ((:COLLISION "block" "ledge")) :POSITIONS
;;      (("block" (0.3511559405940483d0 1.0310788440594083d0))) :VELOCITIES
;;      (("block" (0.25d0 -4.795499999999967d0))) :ANGLES (("block" 0.19933730498232405d0))
;;      :ANGULAR-VELOCITIES (("block" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.41900004568927535d0 :PAIRS ((:LIFT-OFF "block" "ledge")) :POSITIONS
;;      (("block" (0.35165595201636707d0 1.0263928069879185d0))) :VELOCITIES
;;      (("block" (0.25d0 -2.3117428346200293d0))) :ANGLES (("block" 0.19272531553908423d0))
;;      :ANGULAR-VELOCITIES (("block" -3.3612543468437286d0)) :HINGES NIL))
;;    :END
;;    (:TIME 0.447d0 :POSITIONS (("block" (0.3586559405940475d0 0.9571561282150485d0))) :VELOCITIES
;;     (("block" (0.25d0 -2.6337423091933583d0))) :ANGLES (("block" 0.09861034740073518d0))
;;     :ANGULAR-VELOCITIES (("block" -3.3612543468437286d0)) :HINGES NIL))
