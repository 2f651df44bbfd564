;;;; witness-wrong-rough-incline-at-rest.lisp -- a disagreement found by the witness (make crosscheck N=100
;;;; SEED=23, scenario 89), the witness wrong: a particle at rest on a rough incline (tan a = 8/15 <
;;;; mu = 13/20) stays at rest, as AMES says; the witness's LCP gave it one step of tangential
;;;; speed above 1e-6 and called that a slide start (then a stop 2e-4 s later). Fixed in the
;;;; witness: a slide start counts once it has lasted 5 steps (siconos_friction.py).
;;;; The original header follows.
;;;; verdict: ames-wrong
;;;; reason: state 0: AMES has no more events; the witness has ((:STARTS-SLIDING "particle"
;;;;   "incline")) at 0.1252d0
;;;; Run: bin/ames check witness/disagreements/witness-wrong-rough-incline-at-rest.lisp --numeric

(scenario rough-incline-89 "A particle on a rough incline." (gravity 29/2)
 (body incline :fixed t :shape (polygon (0 0) (15 0) (0 8)))
 (body particle :mass 1 :position (15/2 4) :velocity (0 0) :shape point)
 (friction particle incline :static 13/20) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::ROUGH-INCLINE-89 :STATES
;;    ((:INDEX 0 :START 0 :DURATION :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE :FEATURE (:EDGE 1 :OF AMES-SCENARIO::INCLINE)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :FORCES
;;      ((:FRICTION AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE 116/17 :MODE :STATIC)
;;       (:GRAVITY AMES-SCENARIO::PARTICLE (0 -29/2))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::INCLINE 435/34))
;;      :POSITIONS ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (15/2 4))) :VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::INCLINE (0 0)) (AMES-SCENARIO::PARTICLE (0 0))) :END-EVENT :NONE
;;      :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE 0) (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE) 58))
;;      :MOMENTUM ((:MOMENTUM AMES-SCENARIO::PARTICLE (0 0)))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :EVENTS
;;    ((:TIME 0.1252d0 :SPEED 0.0d0 :PAIRS ((:STARTS-SLIDING "particle" "incline")) :POSITIONS
;;      (("particle" (7.5d0 4.0d0))) :VELOCITIES (("particle" (0.0d0 2.168404344971009d-19))) :AFTER
;;      (("particle" (0.0d0 2.168404344971009d-19))))
;;     (:TIME 0.1254d0 :SPEED 0.0d0 :PAIRS ((:STOPS-SLIDING "particle" "incline")) :POSITIONS
;;      (("particle" (7.5d0 3.9999997825d0))) :VELOCITIES
;;      (("particle" (-2.168404344971009d-19 -4.336808689942018d-19))) :AFTER
;;      (("particle" (-2.168404344971009d-19 -4.336808689942018d-19)))))
;;    :END
;;    (:TIME 0.5d0 :POSITIONS (("particle" (7.5d0 3.9999998550000004d0))) :VELOCITIES
;;     (("particle" (0.0d0 0.0d0)))))
