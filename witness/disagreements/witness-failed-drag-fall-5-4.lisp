;;;; witness-failed-drag-fall-5-4 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed
;;;; reason: Exception: std::exception
;;;; Run: bin/ames check /work/wt/witness/t/../witness/disagreements/witness-failed-drag-fall-5-4.lisp --numeric

(scenario drag-fall-4 "A ball falls through a medium with drag onto the floor." (gravity 39/4)
 (restitution 1/2) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ball :mass 3/2 :position (0 17/4) :velocity (0 0) :shape point)
 (drag air :on ball :linear 17/10) (simulate :states 4))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::DRAG-FALL-4 :STATES
;;    ((:INDEX 0 :START 0 :DURATION 1.1316701055012173d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL (0 (- (/ (* 39 (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))) 4)))))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL
;;        (0
;;         (/
;;          (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15))) (- (* 117 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 117))
;;          8)))
;;       (:GRAVITY AMES-SCENARIO::BALL (0 -117/8)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;              (+ 8775 (* (- (* 9945 AMES.BASE:TAU) 13688) (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;           1156)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15))) (- (* 585 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 585))
;;           68)))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :IMPULSE 4411117359/315338548 :ENERGY-LOST
;;       2161995150541237209/99438399854748304)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -490124151/78834637))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 4411117359/315338548))
;;       :ENERGY-LOST 2161995150541237209/99438399854748304 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -490124151/78834637))) :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 490124151/157669274))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL
;;        (/
;;         (* (EXP (- (/ (* 34 AMES.BASE:TAU) 15)))
;;            (- (+ 1026675 (* 1026675 (EXP (/ (* 34 AMES.BASE:TAU) 15))))
;;               (* 2053350 (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;         18496))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL)
;;        (-
;;         (/
;;          (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;             (+ 1026675 (* (- (* 1163565 AMES.BASE:TAU) 1601496) (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;          9248))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;              (- (* 1755 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 1755))
;;           136))))))
;;     (:INDEX 1 :START 47530347/42000179 :DURATION 0.5755264153378059d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0 (- (/ (* 20927494593 (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))) 1576692740)))))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL
;;        (0
;;         (/
;;          (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;             (- (* 46118262645 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 62782483779))
;;          3153385480)))
;;       (:GRAVITY AMES-SCENARIO::BALL (0 -117/8)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;              (+ 941737256685
;;                 (* (- (* 784010464965 AMES.BASE:TAU) 941737256685)
;;                    (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;           91132840372)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;              (- (* 46118262645 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 62782483779))
;;           5360755316)))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 490124151/157669274)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :IMPULSE 72754991/12919626 :ENERGY-LOST
;;       5293288715410081/1502250623818884)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -145509982/58138317))) :ACCUMULATION
;;      (:FACTOR 11471226610846534/28494993260193867 :CYCLE 613410814814887/1065825648428047 :TIME
;;       38012574895569425852102866957872/18144367127728382214749961848651)
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 72754991/12919626)) :ENERGY-LOST
;;       5293288715410081/1502250623818884 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -145509982/58138317))) :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 72754991/58138317))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL
;;        (/
;;         (* (EXP (- (/ (* 34 AMES.BASE:TAU) 15)))
;;            (-
;;             (+ 11824920808381194362523 (* 6380682448179607188075 (EXP (/ (* 34 AMES.BASE:TAU) 15))))
;;             (* 17372514458552244812730 (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;         114950790232089039424))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL)
;;        (-
;;         (/
;;          (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;             (+ 110183259032145
;;                (* (- (* 91729224400905 AMES.BASE:TAU) 110183259032145)
;;                   (EXP (/ (* 17 AMES.BASE:TAU) 15)))))
;;          729062722976))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* (EXP (- (/ (* 17 AMES.BASE:TAU) 15)))
;;              (- (* 138354787935 (EXP (/ (* 17 AMES.BASE:TAU) 15))) 188347451337))
;;           10721510632))))))
;;     (:INDEX 2 :START 38012574895569425852102866957872/18144367127728382214749961848651 :DURATION
;;      :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;      :ACCELERATIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL (0 0)) (:GRAVITY AMES-SCENARIO::BALL (0 -117/8))
;;       (:NORMAL AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 117/8))
;;      :POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :END-EVENT :NONE :FINAL-POSITIONS NIL
;;      :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL 0) (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL) 0)) :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL (0 0)))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :ERROR :MESSAGE "Exception: std::exception")
