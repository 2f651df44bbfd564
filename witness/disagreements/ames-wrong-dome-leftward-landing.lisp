;;;; witness/disagreements/ames-wrong-dome-leftward-landing.lisp -- a disagreement found by
;;;; the witness (make crosscheck N=50 SEED=4 FAMILIES=loop,bowl,dome,bumper,gravitation,
;;;; index 12); run: bin/ames check THIS-FILE --numeric
;;;;
;;;; A particle pushed toward -x (13/8) from the top of a dome (r = 3/4, g = 21/4) slides,
;;;; leaves the dome (state 0: AMES and Siconos agree, 1.5e-8) and lands on the floor
;;;; (state 1 agrees too) with restitution 0. AMES's impact leaves the velocity unchanged
;;;; (just before and just after: (-1.667, -2.780)), and its state 2 has no contact: the
;;;; particle falls through the floor forever (y = -2.05 at the witness's end, where Siconos
;;;; has it sliding on the floor at y = 0). The same push toward +x (scenario dome-12-right
;;;; below) agrees in every state. With ames-wrong-dome-lift-off-leftward.lisp and the
;;;; refusals of leftward dome and loop lift-offs ("No set of contacts and modes is
;;;; consistent at the start of the state"), motion toward -x on arcs looks mishandled.

(scenario dome-12 "A particle slides off a dome onto the floor." (gravity 21/4) (restitution 0)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body dome :fixed t :shape (arc :center (0 0) :radius 3/4 :from 0 :to pi :solid :inside))
 (body particle :mass 1 :position (0 3/4) :velocity ((* -1 13/8) 0) :shape point)
 (simulate :states 3))

(scenario dome-12-right "The same pushed toward +x: AMES and the witness agree." (gravity 21/4)
 (restitution 0)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body dome :fixed t :shape (arc :center (0 0) :radius 3/4 :from 0 :to pi :solid :inside))
 (body particle :mass 1 :position (0 3/4) :velocity ((* 1 13/8) 0) :shape point)
 (simulate :states 3))



;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::DOME-12 :STATES
;;    ((:INDEX 0 :START 0 :DURATION
;;      (/
;;       (* 12
;;          (- (AMES-SCENARIO::ELLIPTIC-F (/ (+ PI (ACOS 673/756)) 2) 1008/1177)
;;             (AMES-SCENARIO::ELLIPTIC-K 1008/1177)))
;;       (SQRT 1177))
;;      :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::DOME :FEATURE (:ARC 0 :OF AMES-SCENARIO::DOME)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (* (COS (/ (* 4 AMES-SCENARIO::S) 3)) (- (* 756 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 673))
;;            48)
;;         (/
;;          (- (* 756 (EXPT (SIN (/ (* 4 AMES-SCENARIO::S) 3)) 2)) 252
;;             (* 673 (SIN (/ (* 4 AMES-SCENARIO::S) 3))))
;;          48))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::DOME
;;        (/ (- (* 756 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 673) 48)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/ (* 3 (COS (/ (* 4 AMES-SCENARIO::S) 3))) 4)
;;          (/ (* 3 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 4))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((-
;;           (/
;;            (* (SQRT (- 673 (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3)))))
;;               (SIN (/ (* 4 AMES-SCENARIO::S) 3)))
;;            8))
;;          (/
;;           (* (COS (/ (* 4 AMES-SCENARIO::S) 3))
;;              (SQRT (- 673 (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3))))))
;;           8))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE ((* -1 13/8) 0)))
;;      :END-EVENT (:LIFT-OFF AMES-SCENARIO::PARTICLE AMES-SCENARIO::DOME) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (* 3 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))) 4)
;;         (/ (* 3 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))) 4))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;              (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;           8))
;;         (/
;;          (* (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;             (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;          8))))
;;      :END-ARC-LENGTH (/ (+ (* 3 PI) (* 6 (ACOS 673/756))) 8) :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::DOME) :ARC-LENGTH-FROM (/ (* 3 PI) 8)
;;       :DIRECTION 1 :TANGENTIAL-ACCELERATION (- (/ (* 21 (COS (/ (* 4 AMES-SCENARIO::S) 3))) 4))
;;       :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2) (- (/ (- (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 673) 64)))
;;       :ODE :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (- (/ (- (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 673) 128)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (/ (* 63 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 16)))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3)))))
;;              (SIN (/ (* 4 AMES-SCENARIO::S) 3)))
;;           8))
;;         (/
;;          (* (COS (/ (* 4 AMES-SCENARIO::S) 3))
;;             (SQRT (- 673 (* 504 (SIN (/ (* 4 AMES-SCENARIO::S) 3))))))
;;          8)))))
;;     (:INDEX 1 :START
;;      (/
;;       (- (* 12 (AMES-SCENARIO::ELLIPTIC-F (/ (+ PI (ACOS 673/756)) 2) 1008/1177))
;;          (* 12 (AMES-SCENARIO::ELLIPTIC-K 1008/1177)))
;;       (SQRT 1177))
;;      :DURATION (/ (- (SQRT 849109967) (* (SQRT 673) (SQRT 118607))) (* (EXPT 3 9/2) 392)) :CONTACTS
;;      NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0)) (AMES-SCENARIO::PARTICLE (0 -21/4)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (-
;;            (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;               (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)) AMES.BASE:TAU)
;;            (* 6 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;           8))
;;         (/
;;          (-
;;           (+ (* 6 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;              (* (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                 (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))) AMES.BASE:TAU))
;;           (* 21 (EXPT AMES.BASE:TAU 2)))
;;          8))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;              (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;           8))
;;         (/
;;          (-
;;           (* (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;              (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;           (* 42 AMES.BASE:TAU))
;;          8))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;              (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;           8))
;;         (/
;;          (* (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;             (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;          8))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR :IMPULSE NIL :ENERGY-LOST
;;       (-
;;        (/
;;         (-
;;          (+ (* (SQRT 673) (SQRT 118607) (SQRT 849109967))
;;             (* (- (* 28 (EXPT 3 7/2) (SQRT 849109967)) (* 28 (EXPT 3 7/2) (SQRT 673) (SQRT 118607)))
;;                (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;             (* 432081216 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;          464466239)
;;         109734912)))
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (-
;;            (* (- (SQRT 849109967) (* (SQRT 673) (SQRT 118607)))
;;               (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;               (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;            (* 784 (EXPT 3 11/2) (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;           (* (EXPT 3 9/2) 3136)))
;;         (/
;;          (-
;;           (+ (* (SQRT 3) (SQRT 673) (SQRT 118607) (SQRT 849109967))
;;              (* (- (* 2268 (SQRT 849109967)) (* 2268 (SQRT 673) (SQRT 118607)))
;;                 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                 (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;              (* 21952 (EXPT 3 19/2) (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;           (* 464466239 (SQRT 3)))
;;          (* (EXPT 3 17/2) 87808)))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;              (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;           8))
;;         (/
;;          (-
;;           (+ (* (SQRT 673) (SQRT 118607))
;;              (* 28 (EXPT 3 7/2) (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                 (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))))
;;           (SQRT 849109967))
;;          (* (EXPT 3 7/2) 224)))))
;;      :IMPACT
;;      (:CONTACTS NIL :IMPULSES NIL :ENERGY-LOST
;;       (-
;;        (/
;;         (-
;;          (+ (* (SQRT 673) (SQRT 118607) (SQRT 849109967))
;;             (* (- (* 28 (EXPT 3 7/2) (SQRT 849109967)) (* 28 (EXPT 3 7/2) (SQRT 673) (SQRT 118607)))
;;                (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;             (* 432081216 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;          464466239)
;;         109734912))
;;       :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((-
;;           (/
;;            (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;               (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;            8))
;;          (/
;;           (-
;;            (+ (* (SQRT 673) (SQRT 118607))
;;               (* 28 (EXPT 3 7/2) (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                  (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))))
;;            (SQRT 849109967))
;;           (* (EXPT 3 7/2) 224)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((- (/ (EXPT 673 3/2) (* (EXPT 3 7/2) 224)))
;;          (- (/ (SQRT 849109967) (* (EXPT 3 7/2) 224)))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (-
;;         (/
;;          (-
;;           (+ (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;              (* 84 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                 (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))) AMES.BASE:TAU))
;;           673 (* 1764 (EXPT AMES.BASE:TAU 2)))
;;          128)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (/
;;         (-
;;          (+ (* 126 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;             (* 21 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))) AMES.BASE:TAU))
;;          (* 441 (EXPT AMES.BASE:TAU 2)))
;;         32)))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;              (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;           8))
;;         (/
;;          (-
;;           (* (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;              (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;           (* 42 AMES.BASE:TAU))
;;          8)))))
;;     (:INDEX 2 :START
;;      (/
;;       (-
;;        (+ (* (SQRT 1177) (SQRT 849109967))
;;           (* 1568 (EXPT 3 11/2) (AMES-SCENARIO::ELLIPTIC-F (/ (+ PI (ACOS 673/756)) 2) 1008/1177)))
;;        (* (SQRT 673) (SQRT 1177) (SQRT 118607))
;;        (* 1568 (EXPT 3 11/2) (AMES-SCENARIO::ELLIPTIC-K 1008/1177)))
;;       (* (EXPT 3 9/2) (SQRT 1177) 392))
;;      :DURATION :FOREVER :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0)) (AMES-SCENARIO::PARTICLE (0 -21/4)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (-
;;            (+
;;             (* (- (* (SQRT 3) (SQRT 849109967)) (* (SQRT 3) (SQRT 673) (SQRT 118607)))
;;                (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))))
;;                (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2)))
;;             (* 14 (EXPT 3 3/2) (EXPT 673 3/2) AMES.BASE:TAU))
;;            (* 571536 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;           762048))
;;         (/
;;          (-
;;           (+ (* (SQRT 673) (SQRT 118607) (SQRT 849109967))
;;              (* (- (* 28 (EXPT 3 7/2) (SQRT 849109967)) (* 28 (EXPT 3 7/2) (SQRT 673) (SQRT 118607)))
;;                 (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                 (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;              (* 432081216 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;           464466239 (* 392 (EXPT 3 9/2) (SQRT 849109967) AMES.BASE:TAU)
;;           (* 1512284256 (EXPT AMES.BASE:TAU 2)))
;;          576108288))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 673 3/2) (* (EXPT 3 7/2) 224)))
;;         (- (/ (+ (SQRT 849109967) (* 392 (EXPT 3 9/2) AMES.BASE:TAU)) (* (EXPT 3 7/2) 224))))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::DOME (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 673 3/2) (* (EXPT 3 7/2) 224))) (- (/ (SQRT 849109967) (* (EXPT 3 7/2) 224))))))
;;      :END-EVENT :NONE :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/ (+ 18171 (* (SQRT 3) (SQRT 849109967) AMES.BASE:TAU) (* 47628 (EXPT AMES.BASE:TAU 2)))
;;           3456))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (/
;;         (-
;;          (+ (* (SQRT 673) (SQRT 118607) (SQRT 849109967))
;;             (* (- (* 28 (EXPT 3 7/2) (SQRT 849109967)) (* 28 (EXPT 3 7/2) (SQRT 673) (SQRT 118607)))
;;                (COS (/ (+ PI (* 2 (ACOS 673/756))) 2))
;;                (SQRT (- 673 (* 504 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))))
;;             (* 432081216 (SIN (/ (+ PI (* 2 (ACOS 673/756))) 2))))
;;          464466239 (* 392 (EXPT 3 9/2) (SQRT 849109967) AMES.BASE:TAU)
;;          (* 1512284256 (EXPT AMES.BASE:TAU 2)))
;;         109734912)))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 673 3/2) (* (EXPT 3 7/2) 224)))
;;         (- (/ (+ (SQRT 849109967) (* 392 (EXPT 3 9/2) AMES.BASE:TAU)) (* (EXPT 3 7/2) 224))))))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :OK :SCHEME :CURVED :EVENTS
;;    ((:TIME 0.20778956075484747d0 :SPEED 0.0d0 :PAIRS ((:LIFT-OFF "particle" "dome")) :POSITIONS
;;      (("particle" (-0.3416604124597292d0 0.6676587171286344d0))) :VELOCITIES
;;      (("particle" (-1.6666721808552525d0 -0.8528847001280627d0))) :AFTER
;;      (("particle" (-1.6666721808552525d0 -0.8528847001280627d0))))
;;     (:TIME 0.575182059375895d0 :SPEED 2.7816953178885617d0 :PAIRS ((:COLLISION "particle" "floor"))
;;      :POSITIONS (("particle" (-0.9539832693663306d0 -2.220446049250313d-16))) :VELOCITIES
;;      (("particle" (-1.6666721808552525d0 -2.7816953178885617d0))) :AFTER
;;      (("particle" (-1.6666721808552525d0 0.0d0)))))
;;    :END
;;    (:TIME 1.076d0 :POSITIONS (("particle" (-1.7886825986777428d0 -2.220446049250313d-16)))
;;     :VELOCITIES (("particle" (-1.6666721808552525d0 0.0d0)))))
