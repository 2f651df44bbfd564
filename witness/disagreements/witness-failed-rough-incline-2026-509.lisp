;;;; witness-failed-rough-incline-2026-509 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed
;;;; reason: the witness's server gave no answer within 120 s
;;;; Not examined: the witness's 120 s ran out while the machine carried a load of about 10
;;;; (make crosscheck N=1000 SEED=2026 JOBS=2 beside six other sessions).
;;;; Run: bin/ames check witness/disagreements/witness-failed-rough-incline-2026-509.lisp --numeric

(scenario rough-incline-509 "A particle on a rough incline." (gravity 37/4)
 (body incline :fixed t :shape (polygon (0 0) (4 0) (0 3)))
 (body particle :mass 1 :position (2 3/2) :velocity ((* -4/5 2) (* 3/5 2)) :shape point)
 (friction particle incline :static 13/20) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::ROUGH-INCLINE-509 :STATES
;;    ((:INDEX 0 :START 0 :DURATION 50/259 :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE :FEATURE (:EDGE 1 :OF AMES-SCENARIO::INCLINE)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (1036/125 -777/125)))
;;      :FORCES
;;      ((:FRICTION AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE -481/100 :MODE :SLIDING)
;;       (:GRAVITY AMES-SCENARIO::PARTICLE (0 -37/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE 37/5))
;;      :POSITIONS
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (- (+ 250 (* 518 (EXPT AMES.BASE:TAU 2))) (* 200 AMES.BASE:TAU)) 125)
;;         (- (/ (- (* 777 (EXPT AMES.BASE:TAU 2)) 375 (* 300 AMES.BASE:TAU)) 250)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (- (* 1036 AMES.BASE:TAU) 200) 125) (- (/ (- (* 777 AMES.BASE:TAU) 150) 125)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE ((* -4/5 2) (* 3/5 2)))) :END-EVENT
;;      (:STOPS-SLIDING AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (478/259 837/518))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (EXPT (- (* 259 AMES.BASE:TAU) 50) 2) 1250))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 28749 (EXPT AMES.BASE:TAU 2)) 13875 (* 11100 AMES.BASE:TAU)) 1000))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((/ (- (* 1036 AMES.BASE:TAU) 200) 125) (- (/ (- (* 777 AMES.BASE:TAU) 150) 125))))))
;;     (:INDEX 1 :START 50/259 :DURATION (/ (* 15 (SQRT 310)) (* (SQRT 7) 37)) :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE :FEATURE (:EDGE 1 :OF AMES-SCENARIO::INCLINE)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (74/125 -111/250)))
;;      :FORCES
;;      ((:FRICTION AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE 481/100 :MODE :SLIDING)
;;       (:GRAVITY AMES-SCENARIO::PARTICLE (0 -37/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE 37/5))
;;      :POSITIONS
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (+ 59750 (* 9583 (EXPT AMES.BASE:TAU 2))) 32375)
;;         (- (/ (- (* 28749 (EXPT AMES.BASE:TAU 2)) 209250) 129500)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE ((/ (* 74 AMES.BASE:TAU) 125) (- (/ (* 111 AMES.BASE:TAU) 250)))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :END-EVENT
;;      (:LEAVES AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE :ENDPOINT) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (4 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (* 6 (SQRT 310)) (* (SQRT 7) 25)) (- (/ (* 9 (SQRT 310)) (* (SQRT 7) 50))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (* 1369 (EXPT AMES.BASE:TAU 2)) 5000))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 28749 (EXPT AMES.BASE:TAU 2)) 209250) 14000))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((/ (* 74 AMES.BASE:TAU) 125) (- (/ (* 111 AMES.BASE:TAU) 250))))))
;;     (:INDEX 2 :START (/ (+ (* 50 (SQRT 7)) (* 105 (SQRT 310))) (* (EXPT 7 3/2) 37)) :DURATION
;;      :FOREVER :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 -37/4))) :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -37/4))) :POSITIONS
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (+ (* 100 (SQRT 7)) (* 6 (SQRT 310) AMES.BASE:TAU)) (* (SQRT 7) 25))
;;         (-
;;          (/ (* AMES.BASE:TAU (+ (* 36 (SQRT 310)) (* 925 (SQRT 7) AMES.BASE:TAU)))
;;             (* (SQRT 7) 200))))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (* 6 (SQRT 310)) (* (SQRT 7) 25))
;;         (- (/ (+ (* 18 (SQRT 310)) (* 925 (SQRT 7) AMES.BASE:TAU)) (* (SQRT 7) 100))))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/ (* 6 (SQRT 310)) (* (SQRT 7) 25)) (- (/ (* 9 (SQRT 310)) (* (SQRT 7) 50))))))
;;      :END-EVENT :NONE :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/ (+ 11160 (* 1332 (SQRT 7) (SQRT 310) AMES.BASE:TAU) (* 239575 (EXPT AMES.BASE:TAU 2)))
;;           5600))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (-
;;         (/ (+ (* 1332 (SQRT 310) AMES.BASE:TAU) (* 34225 (SQRT 7) (EXPT AMES.BASE:TAU 2)))
;;            (* (SQRT 7) 800)))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((/ (* 6 (SQRT 310)) (* (SQRT 7) 25))
;;         (- (/ (+ (* 18 (SQRT 310)) (* 925 (SQRT 7) AMES.BASE:TAU)) (* (SQRT 7) 100))))))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1 2) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (66 66) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :ERROR :MESSAGE "the witness's server gave no answer within 120 s")
