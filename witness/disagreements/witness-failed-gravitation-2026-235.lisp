;;;; witness-failed-gravitation-2026-235 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: witness-failed
;;;; reason: the witness's server gave no answer within 120 s
;;;; Not examined: the witness's 120 s ran out while the machine carried a load of about 10
;;;; (make crosscheck N=1000 SEED=2026 JOBS=2 beside six other sessions).
;;;; Run: bin/ames check witness/disagreements/witness-failed-gravitation-2026-235.lisp --numeric

(scenario gravitation-235 "A probe launched straight up from a planet." (gravitation 1)
 (body planet :mass 671 :fixed t :position (0 0) :shape (circle 49/4))
 (body probe :mass 1 :position ((* -1 49/4) (* 0 49/4)) :velocity ((* -1 97/10) (* 0 97/10)) :shape
  point)
 (simulate :states 2))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::GRAVITATION-235 :STATES
;;    ((:INDEX 0 :START 0 :DURATION
;;      (-
;;       (/
;;        (- (* 920612000 (SQRT 75759) (ASIN (/ (SQRT 75759) (* (SQRT 1342) 20)))) 88220219115
;;           (* 460306000 (SQRT 75759) PI))
;;        11478852162))
;;      :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE ((/ 671 (EXPT AMES-SCENARIO::S 2)) 0)))
;;      :FORCES
;;      ((:GRAVITATION AMES-SCENARIO::PLANET AMES-SCENARIO::PROBE
;;        ((- (/ 671 (EXPT AMES-SCENARIO::S 2))) 0))
;;       (:GRAVITATION AMES-SCENARIO::PROBE AMES-SCENARIO::PLANET
;;        ((/ 671 (EXPT AMES-SCENARIO::S 2)) 0)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::PLANET (0 0))
;;       (AMES-SCENARIO::PROBE (:ON-PATH ((- AMES-SCENARIO::S) 0) :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::PLANET (0 0))
;;       (AMES-SCENARIO::PROBE
;;        (:ON-PATH
;;         ((- (/ (SQRT (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) AMES-SCENARIO::S))) 70)) 0)
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE ((* -1 97/10) (* 0 97/10)))) :END-EVENT
;;      (:TURNS AMES-SCENARIO::PROBE) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (-6575800/75759 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (0 0))) :END-ARC-LENGTH 6575800/75759
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PROBE
;;        (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) (* AMES-SCENARIO::S 9800))))
;;       (:POTENTIAL (:GRAVITATION AMES-SCENARIO::PLANET AMES-SCENARIO::PROBE)
;;        (- (/ 671 AMES-SCENARIO::S))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PROBE
;;        ((- (/ (SQRT (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) AMES-SCENARIO::S))) 70)) 0))))
;;     (:INDEX 1 :START
;;      (-
;;       (/
;;        (- (* 920612000 (SQRT 75759) (ASIN (/ (SQRT 75759) (* (SQRT 1342) 20)))) 88220219115
;;           (* 460306000 (SQRT 75759) PI))
;;        11478852162))
;;      :DURATION
;;      (-
;;       (/
;;        (- (* 920612000 (SQRT 75759) (ASIN (/ (SQRT 75759) (* (SQRT 1342) 20)))) 88220219115
;;           (* 460306000 (SQRT 75759) PI))
;;        11478852162))
;;      :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE ((/ 671 (EXPT AMES-SCENARIO::S 2)) 0)))
;;      :FORCES
;;      ((:GRAVITATION AMES-SCENARIO::PLANET AMES-SCENARIO::PROBE
;;        ((- (/ 671 (EXPT AMES-SCENARIO::S 2))) 0))
;;       (:GRAVITATION AMES-SCENARIO::PROBE AMES-SCENARIO::PLANET
;;        ((/ 671 (EXPT AMES-SCENARIO::S 2)) 0)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::PLANET (0 0))
;;       (AMES-SCENARIO::PROBE (:ON-PATH ((- AMES-SCENARIO::S) 0) :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::PLANET (0 0))
;;       (AMES-SCENARIO::PROBE
;;        (:ON-PATH ((/ (SQRT (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) AMES-SCENARIO::S))) 70) 0)
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (0 0))) :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PROBE AMES-SCENARIO::PLANET :IMPULSE 97/10 :ENERGY-LOST 9409/200)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (-49/4 0)))
;;      :FINAL-VELOCITIES ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (97/10 0))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::PROBE AMES-SCENARIO::PLANET :FEATURE (:CIRCLE :OF AMES-SCENARIO::PLANET)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PROBE)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::PROBE AMES-SCENARIO::PLANET 97/10)) :ENERGY-LOST 9409/200
;;       :VELOCITIES-BEFORE ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (97/10 0)))
;;       :VELOCITIES-AFTER ((AMES-SCENARIO::PLANET (0 0)) (AMES-SCENARIO::PROBE (0 0))))
;;      :END-ARC-LENGTH 49/4 :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PROBE
;;        (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) (* AMES-SCENARIO::S 9800))))
;;       (:POTENTIAL (:GRAVITATION AMES-SCENARIO::PLANET AMES-SCENARIO::PROBE)
;;        (- (/ 671 AMES-SCENARIO::S))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PROBE
;;        ((/ (SQRT (- (/ (- (* 75759 AMES-SCENARIO::S) 6575800) AMES-SCENARIO::S))) 70) 0)))))
;;    :OUTCOME :STATE-LIMIT :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (36 36) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :ERROR :MESSAGE "the witness's server gave no answer within 120 s")
