;;;; witness/disagreements/ames-wrong-loop-missed-turning-point.lisp -- a disagreement found
;;;; by the witness (make crosscheck FAMILIES=loop,bowl,dome,bumper,gravitation N=40 SEED=1,
;;;; index 30); run: bin/ames check THIS-FILE --numeric
;;;;
;;;; A particle launched toward -x at v0 = 25/8 from the bottom of a vertical loop (r = 3/4,
;;;; g = 43/4): v0^2 = 9.77 < 2 g r = 16.1, so it climbs to where s'^2 = 0 (AMES's own energy
;;;; integral, s'^2 = (1032 sin(4 s/3) - 407)/64, vanishes at sin(4 s/3) = 407/1032, below
;;;; the centre's height), turns and swings back: Siconos turns it at t = 0.45313 s. AMES
;;;; says "ends: nothing more changes, duration: forever" for state 0 (no :turns, no period),
;;;; so its velocity formula takes the square root of a negative past the turn. The same
;;;; launch toward +x (scenario loop-30-right below) agrees with the witness (the turn, then
;;;; a periodic state), as do other leftward launches (r = 1): the turning point along s
;;;; increasing from 3 pi/8 (4 s/3 from pi/2 to pi - asin(407/1032)) is missed, maybe taken
;;;; on the other branch of the arcsine (behind the start).

(scenario loop-30 "A particle launched inside a vertical loop." (gravity 43/4) (restitution 1)
 (body loop :fixed t :shape (arc :center (0 3/4) :radius 3/4 :from 0 :to (* 2 pi) :solid :outside))
 (body particle :mass 1 :position (0 0) :velocity ((- 25/8) 0) :shape point) (simulate :states 3))

(scenario loop-30-right "The same launched toward +x: AMES and the witness agree." (gravity 43/4)
 (restitution 1)
 (body loop :fixed t :shape (arc :center (0 3/4) :radius 3/4 :from 0 :to (* 2 pi) :solid :outside))
 (body particle :mass 1 :position (0 0) :velocity (25/8 0) :shape point) (simulate :states 3))



;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::LOOP-30 :STATES
;;    ((:INDEX 0 :START 0 :DURATION :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP :FEATURE (:ARC 0 :OF AMES-SCENARIO::LOOP)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (COS (/ (* 4 AMES-SCENARIO::S) 3)) (- (* 1548 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407))
;;           48))
;;         (/
;;          (- (* 1548 (EXPT (SIN (/ (* 4 AMES-SCENARIO::S) 3)) 2)) 516
;;             (* 407 (SIN (/ (* 4 AMES-SCENARIO::S) 3))))
;;          48))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -43/4))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP
;;        (/ (- (* 1548 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407) 48)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/ (* 3 (COS (/ (* 4 AMES-SCENARIO::S) 3))) 4)
;;          (- (/ (- (* 3 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 3) 4)))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((-
;;           (/
;;            (* (SIN (/ (* 4 AMES-SCENARIO::S) 3))
;;               (SQRT (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407)))
;;            8))
;;          (-
;;           (/
;;            (* (COS (/ (* 4 AMES-SCENARIO::S) 3))
;;               (SQRT (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407)))
;;            8)))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::LOOP (0 0)) (AMES-SCENARIO::PARTICLE ((- 25/8) 0)))
;;      :END-EVENT :NONE :FINAL-POSITIONS NIL :FINAL-VELOCITIES NIL :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP) :ARC-LENGTH-FROM (/ (* 3 PI) 8)
;;       :DIRECTION 1 :TANGENTIAL-ACCELERATION (/ (* 43 (COS (/ (* 4 AMES-SCENARIO::S) 3))) 4)
;;       :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2) (/ (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407) 64))
;;       :ODE :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407) 128))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 129 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 129) 16))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SIN (/ (* 4 AMES-SCENARIO::S) 3))
;;              (SQRT (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407)))
;;           8))
;;         (-
;;          (/
;;           (* (COS (/ (* 4 AMES-SCENARIO::S) 3))
;;              (SQRT (- (* 1032 (SIN (/ (* 4 AMES-SCENARIO::S) 3))) 407)))
;;           8)))))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :OK :SCHEME :CURVED :EVENTS
;;    ((:TIME 0.4531337297564063d0 :SPEED 0.0d0 :PAIRS ((:TURNS "particle" "particle")) :POSITIONS
;;      (("particle" (-0.6892106373096993d0 0.45421511627081324d0))) :VELOCITIES
;;      (("particle" (7.848433513884706d-9 3.3783169336542926d-9))) :AFTER
;;      (("particle" (7.848433513884706d-9 3.3783169336542926d-9)))))
;;    :SAMPLES
;;    ((:TIME 0.05d0 :POSITIONS (("particle" (-0.1542126639333776d0 0.01602557654740296d0))) :VELOCITIES
;;      (("particle" (-3.0037922750583106d0 0.6311157362408469d0))))
;;     (:TIME 0.125d0 :POSITIONS (("particle" (-0.36079031456566374d0 0.09248167411032522d0)))
;;      :VELOCITIES (("particle" (-2.444894698266475d0 1.341550938663263d0))))
;;     (:TIME 0.2d0 :POSITIONS (("particle" (-0.515769595824504d0 0.2054986464451798d0))) :VELOCITIES
;;      (("particle" (-1.6788395923848252d0 1.5902520946282999d0))))
;;     (:TIME 0.3d0 :POSITIONS (("particle" (-0.6362323345243882d0 0.35287481003385535d0))) :VELOCITIES
;;      (("particle" (-0.7815855262639896d0 1.2521743686110882d0))))
;;     (:TIME 0.4d0 :POSITIONS (("particle" (-0.6836000029437184d0 0.4414695542165287d0))) :VELOCITIES
;;      (("particle" (-0.21534534547152828d0 0.477133070042532d0))))
;;     (:TIME 0.475d0 :POSITIONS (("particle" (-0.688276039782787d0 0.4520468273618103d0))) :VELOCITIES
;;      (("particle" (0.08577575608348291d0 -0.19814320882303246d0)))))
;;    :END
;;    (:TIME 0.5d0 :POSITIONS (("particle" (-0.6848646555037105d0 0.4442870567971004d0))) :VELOCITIES
;;     (("particle" (0.18832326628494722d0 -0.4218857976253742d0)))))
