;;;; witness-handover-terrain-2029-225 -- a disagreement make crosscheck N=1000 SEED=2029
;;;; found (#225, family terrain), examined: AMES is right; the comparator now agrees.
;;;; verdict: agree (was ames-wrong: "state 1: AMES's end event (:LEAVES PARTICLE PIECE1),
;;;; the witness's ((:COLLISION "particle" "floor"))")
;;;; The particle lands plastically on piece1's slope, slides down it and reaches its foot,
;;;; (7/2, 0), where the slope meets the floor, at t = 1.12242 s. AMES ends the slide with
;;;; (:leaves particle piece1 :endpoint) and starts a state of zero duration that ends with
;;;; the floor's collision at the same instant; the witness reports the collision alone.
;;;; Both agree on the instant, the positions and velocities (to 3e-14) and everything after.
;;;; src/witness/compare-handover.lisp accepts such a leaving provisionally and keeps the
;;;; witness's event for AMES's next state (t/witness-comparator.lisp).
;;;; Run: bin/ames check witness/disagreements/witness-handover-terrain-2029-225.lisp --numeric

(scenario terrain-225 "A particle thrown over polygonal terrain." (gravity 21/2)
 (body floor :fixed t :shape (half-plane (1 0) (0 0))) (restitution 0)
 (body piece0 :fixed t :shape (polygon (5/4 0) (9/4 0) (5/4 7/4)))
 (body piece1 :fixed t :shape (polygon (7/2 0) (11/2 0) (11/2 5/4)))
 (body particle :mass 1 :position (0 19/4) :velocity (4 1/4) :shape point) (simulate :states 4))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::TERRAIN-225 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ (- (* 2 (SQRT 67)) 3) 14) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (0 -21/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((* 4 AMES.BASE:TAU) (- (/ (- (* 21 (EXPT AMES.BASE:TAU 2)) 19 AMES.BASE:TAU) 4)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (4 (- (/ (- (* 42 AMES.BASE:TAU) 1) 4)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (4 1/4)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 :IMPULSE
;;       (/ (* 12 (SQRT 67)) (SQRT 89)) :ENERGY-LOST 4824/89)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE ((/ (- (* 4 (SQRT 67)) 6) 7) (/ (- (* 40 (SQRT 67)) 305) 112))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (4 (- (/ (- (* 3 (SQRT 67)) 5) 2)))))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 :FEATURE (:EDGE 2 :OF AMES-SCENARIO::PIECE1)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 (/ (* 12 (SQRT 67)) (SQRT 89))))
;;       :ENERGY-LOST 4824/89 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE (4 (- (/ (- (* 3 (SQRT 67)) 5) 2)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((- (/ (- (* 60 (SQRT 67)) 356) 89)) (- (/ (- (* 75 (SQRT 67)) 445) 178))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/ (- (+ 257 (* 1764 (EXPT AMES.BASE:TAU 2))) (* 84 AMES.BASE:TAU)) 32))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 441 (EXPT AMES.BASE:TAU 2)) 399 (* 21 AMES.BASE:TAU)) 8))))
;;      :MOMENTUM ((:MOMENTUM AMES-SCENARIO::PARTICLE (4 (- (/ (- (* 42 AMES.BASE:TAU) 1) 4))))))
;;     (:INDEX 1 :START (/ (- (* 2 (SQRT 67)) 3) 14) :DURATION
;;      (/ (- (+ (* 178 (SQRT 7)) (* 7 (SQRT 1507))) (* 30 (SQRT 7) (SQRT 67))) (* (EXPT 7 3/2) 30))
;;      :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 :FEATURE (:EDGE 2 :OF AMES-SCENARIO::PIECE1)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (-420/89 -525/178)))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 (/ 84 (SQRT 89))))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (- (+ 534 (* (- (* 420 (SQRT 67)) 2492) AMES.BASE:TAU) (* 1470 (EXPT AMES.BASE:TAU 2)))
;;              (* 356 (SQRT 67)))
;;           623))
;;         (-
;;          (/
;;           (-
;;            (+ 27145 (* (- (* 4200 (SQRT 67)) 24920) AMES.BASE:TAU) (* 14700 (EXPT AMES.BASE:TAU 2)))
;;            (* 3560 (SQRT 67)))
;;           9968)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (- (+ (* 60 (SQRT 67)) (* 420 AMES.BASE:TAU)) 356) 89))
;;         (- (/ (- (+ (* 75 (SQRT 67)) (* 525 AMES.BASE:TAU)) 445) 178)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (- (* 60 (SQRT 67)) 356) 89)) (- (/ (- (* 75 (SQRT 67)) 445) 178)))))
;;      :END-EVENT (:LEAVES AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE1 :ENDPOINT) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (7/2 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) (- (/ (* 5 (SQRT 7) (SQRT 1507)) 356)))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/
;;         (- (+ 22996 (* (- (* 3150 (SQRT 67)) 18690) AMES.BASE:TAU) (* 11025 (EXPT AMES.BASE:TAU 2)))
;;            (* 2670 (SQRT 67)))
;;         712))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (-
;;         (/
;;          (-
;;           (+ 81435 (* (- (* 12600 (SQRT 67)) 74760) AMES.BASE:TAU) (* 44100 (EXPT AMES.BASE:TAU 2)))
;;           (* 10680 (SQRT 67)))
;;          2848))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((- (/ (- (+ (* 60 (SQRT 67)) (* 420 AMES.BASE:TAU)) 356) 89))
;;         (- (/ (- (+ (* 75 (SQRT 67)) (* 525 AMES.BASE:TAU)) 445) 178))))))
;;     (:INDEX 2 :START (/ (+ (* 19 (SQRT 7)) (SQRT 1507)) (* (SQRT 7) 30)) :DURATION 0 :CONTACTS NIL
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (0 -21/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (- (* 4 (SQRT 7) (SQRT 1507) AMES.BASE:TAU) 623) 178))
;;         (- (/ (* AMES.BASE:TAU (+ (* 5 (SQRT 7) (SQRT 1507)) (* 1869 AMES.BASE:TAU))) 356)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89))
;;         (- (/ (+ (* 5 (SQRT 7) (SQRT 1507)) (* 3738 AMES.BASE:TAU)) 356)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) (- (/ (* 5 (SQRT 7) (SQRT 1507)) 356)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR :IMPULSE
;;       (/ (* 5 (SQRT 7) (SQRT 1507)) 356) :ENERGY-LOST 263725/253472)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (7/2 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) (- (/ (* 5 (SQRT 7) (SQRT 1507)) 356)))))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR (/ (* 5 (SQRT 7) (SQRT 1507)) 356)))
;;       :ENERGY-LOST 263725/253472 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) (- (/ (* 5 (SQRT 7) (SQRT 1507)) 356)))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/ (+ 10549 (* 60 (EXPT 7 3/2) (SQRT 1507) AMES.BASE:TAU) (* 156996 (EXPT AMES.BASE:TAU 2)))
;;           2848))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (* 21 AMES.BASE:TAU (+ (* 5 (SQRT 7) (SQRT 1507)) (* 1869 AMES.BASE:TAU))) 712))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89))
;;         (- (/ (+ (* 5 (SQRT 7) (SQRT 1507)) (* 3738 AMES.BASE:TAU)) 356))))))
;;     (:INDEX 3 :START (/ (+ (* 19 (SQRT 7)) (SQRT 1507)) (* (SQRT 7) 30)) :DURATION
;;      (/ 445 (* (SQRT 7) (SQRT 1507) 8)) :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (0 0)))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::FLOOR 21/2))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE ((- (/ (- (* 4 (SQRT 7) (SQRT 1507) AMES.BASE:TAU) 623) 178)) 0)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE0 :IMPULSE
;;       (+ (/ (* 8 (SQRT 1507)) (* (SQRT 7) 89)) (/ (* 2 (SQRT 65) (SQRT 1507)) (* (SQRT 7) 89)))
;;       :ENERGY-LOST 21098/7921)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE (9/4 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;       (AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0)))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE0 :FEATURE (:EDGE 0 :OF AMES-SCENARIO::PIECE0)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE))
;;        (AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE0 :FEATURE (:EDGE 1 :OF AMES-SCENARIO::PIECE0)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE0 (/ (* 8 (SQRT 1507)) (* (SQRT 7) 89)))
;;        (:IMPULSE AMES-SCENARIO::PARTICLE AMES-SCENARIO::PIECE0
;;         (/ (* 2 (SQRT 65) (SQRT 1507)) (* (SQRT 7) 89))))
;;       :ENERGY-LOST 21098/7921 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::PIECE0 (0 0)) (AMES-SCENARIO::PIECE1 (0 0))
;;        (AMES-SCENARIO::PARTICLE (0 0))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE 21098/7921)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE) 0))
;;      :MOMENTUM ((:MOMENTUM AMES-SCENARIO::PARTICLE ((- (/ (* 2 (SQRT 7) (SQRT 1507)) 89)) 0)))))
;;    :OUTCOME :STATE-LIMIT :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1 3) :UNCHECKED ((:STATE 2 :REASON "it lasts no time")) :NUMBERS (0 0) :EQUATIONS
;;     (64 64) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :EVENT-DRIVEN :EVENTS
;;    ((:TIME 0.9550503959817886d0 :SPEED 10.411747902346507d0 :PAIRS ((:COLLISION "particle" "piece1"))
;;      :POSITIONS (("particle" (3.820201583927151d0 0.2001259899544683d0))) :VELOCITIES
;;      (("particle" (3.999999999999953d0 -9.778029157808387d0))) :AFTER
;;      (("particle" (-1.5182153518240282d0 -0.9488845948900178d0))))
;;     (:TIME 1.1224205946746797d0 :SPEED 1.4425326528325328d0 :PAIRS ((:COLLISION "particle" "floor"))
;;      :POSITIONS (("particle" (3.5000000000000004d0 -1.1796119636642288d-16))) :VELOCITIES
;;      (("particle" (-2.3080522445320533d0 -1.4425326528325328d0))) :AFTER
;;      (("particle" (-2.3080522445320533d0 0.0d0))))
;;     (:TIME 1.6640027893417826d0 :SPEED 2.0039505329799683d0 :PAIRS ((:COLLISION "particle" "piece0"))
;;      :POSITIONS (("particle" (2.25d0 4.4065989822147055d-16))) :VELOCITIES
;;      (("particle" (-2.308052244532108d0 0.0d0))) :AFTER (("particle" (0.0d0 0.0d0)))))
;;    :END
;;    (:TIME 1.6840027893417826d0 :POSITIONS (("particle" (2.25d0 4.4065989822147055d-16))) :VELOCITIES
;;     (("particle" (0.0d0 0.0d0)))))
