;;;; witness-failed-bowl-4242-885 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed; fixed in the witness: a model rebuilt at t = 4.888 started with
;;;; the particle 2.5e-12 behind the bowl (round-off), which Siconos's event-driven scheme
;;;; refuses (its _TOL_ED is 2.2e-12); a body that round-off put slightly behind an active
;;;; contact is now moved onto it (siconos_driver.py's ONTO-CONTACTS). Now agrees.
;;;; reason: Exception: std::exception
;;;; Run: bin/ames check /work/main/t/../witness/disagreements/witness-failed-bowl-4242-885.lisp --numeric

(scenario bowl-885 "A particle swings in a bowl." (gravity 39/4)
 (body bowl :fixed t :shape (arc :center (0 2) :radius 2 :from pi :to (* 2 pi) :solid :outside))
 (body particle :mass 1 :position (0 0) :velocity ((* -1 23/4) 0) :shape point)
 (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::BOWL-885 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ (* 4 (AMES-SCENARIO::ELLIPTIC-K 529/1248)) (SQRT 78)) :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL :FEATURE (:ARC 0 :OF AMES-SCENARIO::BOWL)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* (COS (/ AMES-SCENARIO::S 2)) (- (* 936 (SIN (/ AMES-SCENARIO::S 2))) 95)) 32))
;;         (/ (- (* 936 (EXPT (SIN (/ AMES-SCENARIO::S 2)) 2)) 312 (* 95 (SIN (/ AMES-SCENARIO::S 2))))
;;            32))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -39/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL
;;        (/ (- (* 936 (SIN (/ AMES-SCENARIO::S 2))) 95) 32)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH ((* 2 (COS (/ AMES-SCENARIO::S 2))) (- 2 (* 2 (SIN (/ AMES-SCENARIO::S 2)))))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((-
;;           (/ (* (SIN (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4))
;;          (-
;;           (/ (* (COS (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4)))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::BOWL (0 0)) (AMES-SCENARIO::PARTICLE ((* -1 23/4) 0)))
;;      :END-EVENT (:TURNS AMES-SCENARIO::PARTICLE) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::BOWL (0 0)) (AMES-SCENARIO::PARTICLE ((- (/ (* 23 (SQRT 719)) 312)) 529/312)))
;;      :FINAL-VELOCITIES ((AMES-SCENARIO::BOWL (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :END-ARC-LENGTH
;;      (- (* 2 PI) (* 2 (ASIN 95/624))) :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL) :ARC-LENGTH-FROM PI :DIRECTION 1
;;       :TANGENTIAL-ACCELERATION (/ (* 39 (COS (/ AMES-SCENARIO::S 2))) 4) :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2) (/ (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95) 16)) :ODE
;;       :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95) 32))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 39 (SIN (/ AMES-SCENARIO::S 2))) 39) 2))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((- (/ (* (SIN (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4))
;;         (-
;;          (/ (* (COS (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95)))
;;             4))))))
;;     (:INDEX 1 :START (/ (* 4 (AMES-SCENARIO::ELLIPTIC-K 529/1248)) (SQRT 78)) :DURATION :FOREVER
;;      :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL :FEATURE (:ARC 0 :OF AMES-SCENARIO::BOWL)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* (COS (/ AMES-SCENARIO::S 2)) (- (* 936 (SIN (/ AMES-SCENARIO::S 2))) 95)) 32))
;;         (/ (- (* 936 (EXPT (SIN (/ AMES-SCENARIO::S 2)) 2)) 312 (* 95 (SIN (/ AMES-SCENARIO::S 2))))
;;            32))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -39/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL
;;        (/ (- (* 936 (SIN (/ AMES-SCENARIO::S 2))) 95) 32)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH ((* 2 (COS (/ AMES-SCENARIO::S 2))) (- 2 (* 2 (SIN (/ AMES-SCENARIO::S 2)))))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::BOWL (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/ (* (SIN (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4)
;;          (/ (* (COS (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::BOWL (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :END-EVENT
;;      :NONE :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :PERIODIC
;;      (:PERIOD (/ (* 16 (AMES-SCENARIO::ELLIPTIC-K 529/1248)) (SQRT 78)) :BETWEEN
;;       ((- (* 2 PI) (* 2 (ATAN (/ 95 (* (SQRT 719) 23))))) (* 2 (ASIN 95/624))))
;;      :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::BOWL) :ARC-LENGTH-FROM
;;       (- (* 2 PI) (* 2 (ATAN (/ 95 (* (SQRT 719) 23))))) :DIRECTION -1 :TANGENTIAL-ACCELERATION
;;       (/ (* 39 (COS (/ AMES-SCENARIO::S 2))) 4) :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2) (/ (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95) 16)) :ODE
;;       :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95) 32))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 39 (SIN (/ AMES-SCENARIO::S 2))) 39) 2))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((/ (* (SIN (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95))) 4)
;;         (/ (* (COS (/ AMES-SCENARIO::S 2)) (SQRT (- (* 624 (SIN (/ AMES-SCENARIO::S 2))) 95)))
;;            4))))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (42 42) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :ERROR :MESSAGE "Exception: std::exception")
