;;;; ames-wrong-drag-fall-5-12 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong
;;;; reason: state 3: start: AMES 2.168413891054518d0, witness 1.7677198449823064d0
;;;; Run: bin/ames check /work/wt/witness/t/../witness/disagreements/ames-wrong-drag-fall-5-12.lisp --numeric

(scenario drag-fall-12 "A ball falls through a medium with drag onto the floor." (gravity 29/4)
 (restitution 1/2) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ball :mass 3/4 :position (0 7/2) :velocity (0 0) :shape point)
 (drag air :on ball :quadratic 37/100) (simulate :states 4))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::DRAG-FALL-12 :STATES
;;    ((:INDEX 0 :START 0 :DURATION 1.2752741422719613d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/ (* 29 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))))
;;             (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2))))))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL
;;        (0
;;         (/ (* 87 (EXPT (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1) 2))
;;            (* (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2) 16))))
;;       (:GRAVITY AMES-SCENARIO::BALL (0 -87/16)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (-
;;            (* 150 (SQRT 1073)
;;               (LOG (/ (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2)))
;;            (* 259 (SQRT 1073)) (* 5365 (SQRT 3) AMES.BASE:TAU))
;;           (* (SQRT 1073) 74))))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/ (* 5 (SQRT 3) (SQRT 1073) (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1))
;;             (* (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 74))))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :IMPULSE 2731623435/643651984 :ENERGY-LOST
;;       829085176737911025/207143938253568128)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -303513715/80456498))) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 2731623435/643651984))
;;       :ENERGY-LOST 829085176737911025/207143938253568128 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -303513715/80456498))) :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 303513715/160912996))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL
;;        (/ (* 6525 (EXPT (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1) 2))
;;           (* (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2) 1184)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL)
;;        (-
;;         (/
;;          (-
;;           (* 13050 (SQRT 1073)
;;              (LOG (/ (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2)))
;;           (* 21 (EXPT 1073 3/2)) (* 155585 (EXPT 3 3/2) AMES.BASE:TAU))
;;          (* (SQRT 1073) 1184)))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* 5 (EXPT 3 3/2) (SQRT 1073) (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1))
;;           (* (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 296)))))))
;;     (:INDEX 1 :START 13832451/10846649 :DURATION
;;      (/ (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))) (SQRT 1073))
;;      :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/ 29
;;             (*
;;              (EXPT
;;               (COS
;;                (/
;;                 (- (* (SQRT 1073) AMES.BASE:TAU)
;;                    (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                 (* (SQRT 3) 10)))
;;               2)
;;              4))))))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* 87
;;              (EXPT
;;               (TAN
;;                (/
;;                 (- (* (SQRT 1073) AMES.BASE:TAU)
;;                    (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                 (* (SQRT 3) 10)))
;;               2))
;;           16))))
;;       (:GRAVITY AMES-SCENARIO::BALL (0 -87/16)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (/
;;          (* 75
;;             (LOG
;;              (/
;;               (* (SQRT 699511033412678161)
;;                  (COS
;;                   (/
;;                    (- (* (SQRT 1073) AMES.BASE:TAU)
;;                       (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                    (* (SQRT 3) 10))))
;;               (* (SQRT 87) 80456498))))
;;          37))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* 5 (SQRT 3) (SQRT 1073)
;;              (TAN
;;               (/
;;                (- (* (SQRT 1073) AMES.BASE:TAU)
;;                   (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                (* (SQRT 3) 10))))
;;           74)))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 303513715/160912996)))
;;      :END-EVENT (:TURNS AMES-SCENARIO::BALL) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0 (/ (* 75 (LOG (/ (SQRT 699511033412678161) (* (SQRT 87) 80456498)))) 37))))
;;      :FINAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL
;;        (/
;;         (* 6525
;;            (EXPT
;;             (TAN
;;              (/
;;               (- (* (SQRT 1073) AMES.BASE:TAU)
;;                  (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;               (* (SQRT 3) 10)))
;;             2))
;;         1184))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL)
;;        (/
;;         (* 6525
;;            (LOG
;;             (/
;;              (* (SQRT 699511033412678161)
;;                 (COS
;;                  (/
;;                   (- (* (SQRT 1073) AMES.BASE:TAU)
;;                      (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                   (* (SQRT 3) 10))))
;;              (* (SQRT 87) 80456498))))
;;         592)))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* 5 (EXPT 3 3/2) (SQRT 1073)
;;              (TAN
;;               (/
;;                (- (* (SQRT 1073) AMES.BASE:TAU)
;;                   (* 10 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;                (* (SQRT 3) 10))))
;;           296))))))
;;     (:INDEX 2 :START
;;      (/
;;       (+ (* 13832451 (SQRT 1073))
;;          (* 108466490 (SQRT 3) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;       (* (SQRT 1073) 10846649))
;;      :DURATION 0.2506698159563544d0 :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/ (* 29 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))))
;;             (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2))))))
;;      :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL
;;        (0
;;         (/ (* 87 (EXPT (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1) 2))
;;            (* (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2) 16))))
;;       (:GRAVITY AMES-SCENARIO::BALL (0 -87/16)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (-
;;            (* 150 (SQRT 1073)
;;               (LOG (/ (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2)))
;;            (* 150 (SQRT 1073) (LOG (/ (SQRT 699511033412678161) (* (SQRT 87) 80456498))))
;;            (* 5365 (SQRT 3) AMES.BASE:TAU))
;;           (* (SQRT 1073) 74))))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0))
;;       (AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/ (* 5 (SQRT 3) (SQRT 1073) (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1))
;;             (* (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 74))))))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :END-EVENT
;;      (:COLLISION AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :IMPULSE 1120465341/588484784 :ENERGY-LOST
;;       139493620042471809/173157170499763328)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -124496149/73560598))) :ACCUMULATION
;;      (:FACTOR 5008262081513101/11163325188300785 :CYCLE
;;       (/
;;        (+ (* 13996739 (SQRT 1073))
;;           (* 186124510 (EXPT 3 3/2) (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;        (* (SQRT 1073) 55837353))
;;       :TIME
;;       (/
;;        (+ 629047314717031698887758444847141
;;           (* 2048802260951545307309088780650 (EXPT 3 3/2) (SQRT 1073)
;;              (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;        363630208944172602314914715590764))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;       :IMPULSES ((:IMPULSE AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 1120465341/588484784))
;;       :ENERGY-LOST 139493620042471809/173157170499763328 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 -124496149/73560598))) :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 124496149/147121196))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL
;;        (/ (* 6525 (EXPT (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1) 2))
;;           (* (EXPT (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2) 1184)))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL)
;;        (-
;;         (/
;;          (-
;;           (* 13050 (SQRT 1073)
;;              (LOG (/ (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 2)))
;;           (* 13050 (SQRT 1073) (LOG (/ (SQRT 699511033412678161) (* (SQRT 87) 80456498))))
;;           (* 155585 (EXPT 3 3/2) AMES.BASE:TAU))
;;          (* (SQRT 1073) 1184)))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL
;;        (0
;;         (-
;;          (/
;;           (* 5 (EXPT 3 3/2) (SQRT 1073) (- (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5))) 1))
;;           (* (+ 1 (EXP (/ (* (SQRT 1073) AMES.BASE:TAU) (* (SQRT 3) 5)))) 296)))))))
;;     (:INDEX 3 :START
;;      (/
;;       (+ 629047314717031698887758444847141
;;          (* 2048802260951545307309088780650 (EXPT 3 3/2) (SQRT 1073)
;;             (ATAN (/ 2246001491 (* (SQRT 3) (SQRT 1073) 80456498)))))
;;       363630208944172602314914715590764)
;;      :DURATION :FOREVER :CONTACTS
;;      ((AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0 :OF AMES-SCENARIO::FLOOR)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::BALL)))
;;      :ACCELERATIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :FORCES
;;      ((:DRAG AMES-SCENARIO::AIR AMES-SCENARIO::BALL (0 0)) (:GRAVITY AMES-SCENARIO::BALL (0 -87/16))
;;       (:NORMAL AMES-SCENARIO::BALL AMES-SCENARIO::FLOOR 87/16))
;;      :POSITIONS ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::BALL (0 0))) :END-EVENT :NONE :FINAL-POSITIONS NIL
;;      :FINAL-VELOCITIES NIL :ENERGY
;;      ((:KINETIC AMES-SCENARIO::BALL 0) (:POTENTIAL (:GRAVITY AMES-SCENARIO::BALL) 0)) :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::BALL (0 0)))))
;;    :OUTCOME :COMPLETE :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :OK :SCHEME :EVENT-DRIVEN :EVENTS
;;    ((:TIME 1.2752741422719536d0 :SPEED 3.7723953011228457d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 0.0d0))) :VELOCITIES (("ball" (0.0d0 -3.7723953011228457d0))) :AFTER
;;      (("ball" (0.0d0 1.886197650561424d0))))
;;     (:TIME 1.5170500286739355d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 0.21972511409846202d0))) :VELOCITIES (("ball" (0.0d0 -5.7314484375962185d-15)))
;;      :AFTER (("ball" (0.0d0 -5.7314484375962185d-15))))
;;     (:TIME 1.7677198449823064d0 :SPEED 1.6924298114052403d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -3.660266534311063d-16))) :VELOCITIES
;;      (("ball" (0.0d0 -1.6924298114052403d0))) :AFTER (("ball" (0.0d0 0.84621490570262d0))))
;;     (:TIME 1.8825969396665196d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 0.04821934344223249d0))) :VELOCITIES (("ball" (0.0d0 -9.173366818764065d-15)))
;;      :AFTER (("ball" (0.0d0 -9.173366818764065d-15))))
;;     (:TIME 1.9983885537344546d0 :SPEED 0.8263225086034791d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -3.0357660829594124d-17))) :VELOCITIES
;;      (("ball" (0.0d0 -0.8263225086034791d0))) :AFTER (("ball" (0.0d0 0.41316125430173956d0))))
;;     (:TIME 2.0551571888685243d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 0.011704719215876633d0))) :VELOCITIES (("ball" (0.0d0 -5.234663614032153d-16)))
;;      :AFTER (("ball" (0.0d0 -5.234663614032153d-16))))
;;     (:TIME 2.1120351965193596d0 :SPEED 0.4107824003919088d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -5.746271514173174d-17))) :VELOCITIES
;;      (("ball" (0.0d0 -0.4107824003919088d0))) :AFTER (("ball" (0.0d0 0.20539120019595442d0))))
;;     (:TIME 2.1403379559787297d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 0.002905180188583985d0))) :VELOCITIES (("ball" (0.0d0 1.5949630396800233d-15)))
;;      :AFTER (("ball" (0.0d0 1.5949630396800233d-15))))
;;     (:TIME 2.168654240845712d0 :SPEED 0.20509703980903066d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -5.2692225582795515d-17))) :VELOCITIES
;;      (("ball" (0.0d0 -0.20509703980903066d0))) :AFTER (("ball" (0.0d0 0.10254851990451536d0))))
;;     (:TIME 2.1827954915711243d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 7.249957316681971d-4))) :VELOCITIES (("ball" (0.0d0 2.1243586317135474d-15)))
;;      :AFTER (("ball" (0.0d0 2.1243586317135474d-15))))
;;     (:TIME 2.1969384288661766d0 :SPEED 0.10251184849029371d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -4.3151246464923076d-17))) :VELOCITIES
;;      (("ball" (0.0d0 -0.10251184849029371d0))) :AFTER (("ball" (0.0d0 0.051255924245146856d0))))
;;     (:TIME 2.2040077901276187d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.8116792925003866d-4))) :VELOCITIES (("ball" (0.0d0 -1.18478733497182d-15)))
;;      :AFTER (("ball" (0.0d0 -1.18478733497182d-15))))
;;     (:TIME 2.21107736231052d0 :SPEED 0.05125134339008598d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.5886949958701657d-17))) :VELOCITIES
;;      (("ball" (0.0d0 -0.05125134339008598d0))) :AFTER (("ball" (0.0d0 0.025625671695042998d0))))
;;     (:TIME 2.214611884687321d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 4.528692347369504d-5))) :VELOCITIES (("ball" (0.0d0 -1.4066040880340151d-15)))
;;      :AFTER (("ball" (0.0d0 -1.4066040880340151d-15))))
;;     (:TIME 2.2181464341550066d0 :SPEED 0.025625099182536873d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -5.032222739637798d-18))) :VELOCITIES
;;      (("ball" (0.0d0 -0.025625099182536873d0))) :AFTER (("ball" (0.0d0 0.012812549591268436d0))))
;;     (:TIME 2.2199136754355235d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.1321414826515591d-5))) :VELOCITIES (("ball" (0.0d0 2.130711378818427d-15)))
;;      :AFTER (("ball" (0.0d0 2.130711378818427d-15))))
;;     (:TIME 2.221680920723096d0 :SPEED 0.01281247802754805d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -5.537901409148616d-18))) :VELOCITIES
;;      (("ball" (0.0d0 -0.01281247802754805d0))) :AFTER (("ball" (0.0d0 0.006406239013774025d0))))
;;     (:TIME 2.2225645389712927d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 2.830333858616277d-6))) :VELOCITIES (("ball" (0.0d0 -2.3581454169025088d-15)))
;;      :AFTER (("ball" (0.0d0 -2.3581454169025088d-15))))
;;     (:TIME 2.2234481578368976d0 :SPEED 0.006406230061325319d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.6469496868175802d-19))) :VELOCITIES
;;      (("ball" (0.0d0 -0.006406230061325319d0))) :AFTER (("ball" (0.0d0 0.0032031150306626593d0))))
;;     (:TIME 2.2238899666905114d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 7.075822278466368d-7))) :VELOCITIES (("ball" (0.0d0 -1.7411707825458306d-15)))
;;      :AFTER (("ball" (0.0d0 -1.7411707825458306d-15))))
;;     (:TIME 2.224331775621547d0 :SPEED 0.0032031139080440207d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -4.421511984667448d-19))) :VELOCITIES
;;      (("ball" (0.0d0 -0.0032031139080440207d0))) :AFTER (("ball" (0.0d0 0.0016015569540220103d0))))
;;     (:TIME 2.22455268001311d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.7689547799850592d-7))) :VELOCITIES (("ball" (0.0d0 -2.6768215111063448d-15)))
;;      :AFTER (("ball" (0.0d0 -2.6768215111063448d-15))))
;;     (:TIME 2.2247735844152663d0 :SPEED 0.001601556800411473d0 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -6.688119211960752d-19))) :VELOCITIES
;;      (("ball" (0.0d0 -0.001601556800411473d0))) :AFTER (("ball" (0.0d0 8.007784002057366d-4))))
;;     (:TIME 2.224884036603733d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 4.4223862766408436d-8))) :VELOCITIES (("ball" (0.0d0 8.261007680495368d-16)))
;;      :AFTER (("ball" (0.0d0 8.261007680495368d-16))))
;;     (:TIME 2.2249944887953093d0 :SPEED 8.007783551003266d-4 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.4077952281162489d-19))) :VELOCITIES
;;      (("ball" (0.0d0 -8.007783551003266d-4))) :AFTER (("ball" (0.0d0 4.003891775501633d-4))))
;;     (:TIME 2.225049714882823d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.1055963482641444d-8))) :VELOCITIES (("ball" (0.0d0 2.896265786106929d-15)))
;;      :AFTER (("ball" (0.0d0 2.896265786106929d-15))))
;;     (:TIME 2.225104940974301d0 :SPEED 4.0038912007316454d-4 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -4.854557578951209d-20))) :VELOCITIES
;;      (("ball" (0.0d0 -4.0038912007316454d-4))) :AFTER (("ball" (0.0d0 2.0019456003658221d-4))))
;;     (:TIME 2.225132554005607d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 2.76398894438107d-9))) :VELOCITIES (("ball" (0.0d0 -1.9535537973978737d-15)))
;;      :AFTER (("ball" (0.0d0 -1.9535537973978737d-15))))
;;     (:TIME 2.225160167044598d0 :SPEED 2.001944496053568d-4 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -9.331714003425099d-18))) :VELOCITIES
;;      (("ball" (0.0d0 -2.001944496053568d-4))) :AFTER (("ball" (0.0d0 1.0009722480267843d-4))))
;;     (:TIME 2.2251739735355d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 6.909953209938931d-10))) :VELOCITIES (("ball" (0.0d0 -2.7090295364317236d-15)))
;;      :AFTER (("ball" (0.0d0 -2.7090295364317236d-15))))
;;     (:TIME 2.225187780041551d0 :SPEED 1.0009700310738756d-4 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.865085486153939d-21))) :VELOCITIES
;;      (("ball" (0.0d0 -1.0009700310738756d-4))) :AFTER (("ball" (0.0d0 5.004850155369378d-5))))
;;     (:TIME 2.225194683237423d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.7274692329541837d-10))) :VELOCITIES (("ball" (0.0d0 1.0054799755378118d-15)))
;;      :AFTER (("ball" (0.0d0 1.0054799755378118d-15))))
;;     (:TIME 2.225201586463777d0 :SPEED 5.004805958427769d-5 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.749435296761369d-20))) :VELOCITIES
;;      (("ball" (0.0d0 -5.004805958427769d-5))) :AFTER (("ball" (0.0d0 2.5024029792138845d-5))))
;;     (:TIME 2.2252050379626493d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 4.3184823931065746d-11))) :VELOCITIES (("ball" (0.0d0 3.161280435355586d-15)))
;;      :AFTER (("ball" (0.0d0 3.161280435355586d-15))))
;;     (:TIME 2.2252084895224846d0 :SPEED 2.502314583793113d-5 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.013999353898129d-20))) :VELOCITIES
;;      (("ball" (0.0d0 -2.502314583793113d-5))) :AFTER (("ball" (0.0d0 1.251157291896556d-5))))
;;     (:TIME 2.225210215073778d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.0794299072135755d-11))) :VELOCITIES (("ball" (0.0d0 -1.8851205407450015d-15)))
;;      :AFTER (("ball" (0.0d0 -1.8851205407450015d-15))))
;;     (:TIME 2.2252119407470055d0 :SPEED 1.2509804856384826d-5 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -3.3719500682841328d-21))) :VELOCITIES
;;      (("ball" (0.0d0 -1.2509804856384826d-5))) :AFTER (("ball" (0.0d0 6.254902428192413d-6))))
;;     (:TIME 2.2252128031262326d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 2.6966677482436152d-12))) :VELOCITIES (("ball" (0.0d0 4.538071613853675d-15)))
;;      :AFTER (("ball" (0.0d0 4.538071613853675d-15))))
;;     (:TIME 2.225213665749417d0 :SPEED 6.2513650571597315d-6 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.0318044165833329d-21))) :VELOCITIES
;;      (("ball" (0.0d0 -6.2513650571597315d-6))) :AFTER (("ball" (0.0d0 3.1256825285798658d-6))))
;;     (:TIME 2.2252140961451348d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 6.722594623471217d-13))) :VELOCITIES (("ball" (0.0d0 2.4042251772132997d-16)))
;;      :AFTER (("ball" (0.0d0 2.4042251772132997d-16))))
;;     (:TIME 2.2252145270294568d0 :SPEED 3.1185977624195797d-6 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -1.262898000215335d-21))) :VELOCITIES
;;      (("ball" (0.0d0 -3.1185977624195797d-6))) :AFTER (("ball" (0.0d0 1.5592988812097898d-6))))
;;     (:TIME 2.225214740630957d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 1.6615553599292483d-13))) :VELOCITIES (("ball" (0.0d0 1.512547363407975d-15)))
;;      :AFTER (("ball" (0.0d0 1.512547363407975d-15))))
;;     (:TIME 2.225214955215251d0 :SPEED 1.5450481299801849d-6 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -2.0431361130059784d-22))) :VELOCITIES
;;      (("ball" (0.0d0 -1.5450481299801849d-6))) :AFTER (("ball" (0.0d0 7.725240649900924d-7))))
;;     (:TIME 2.2252150587515205d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 3.9621661680522936d-14))) :VELOCITIES (("ball" (0.0d0 1.06179893607588d-15)))
;;      :AFTER (("ball" (0.0d0 1.06179893607588d-15))))
;;     (:TIME 2.2252151642999336d0 :SPEED 7.433398794164976d-7 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -3.273567274178607d-22))) :VELOCITIES
;;      (("ball" (0.0d0 -7.433398794164976d-7))) :AFTER (("ball" (0.0d0 3.716699397082488d-7))))
;;     (:TIME 2.225215208831189d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 7.94618241515757d-15))) :VELOCITIES (("ball" (0.0d0 -9.612972233902011d-16)))
;;      :AFTER (("ball" (0.0d0 -9.612972233902011d-16))))
;;     (:TIME 2.2252152578309468d0 :SPEED 3.064299046140847d-7 :PAIRS ((:COLLISION "ball" "floor"))
;;      :POSITIONS (("ball" (0.0d0 -2.8641128709648583d-23))) :VELOCITIES
;;      (("ball" (0.0d0 -3.064299046140847d-7))) :AFTER (("ball" (0.0d0 1.5321495230704235d-7))))
;;     (:TIME 2.225215261569022d0 :SPEED 0.0d0 :PAIRS ((:TURNS "ball" "ball")) :POSITIONS
;;      (("ball" (0.0d0 2.6948051823654123d-16))) :VELOCITIES (("ball" (0.0d0 1.1885706447773649d-14)))
;;      :AFTER (("ball" (0.0d0 1.1885706447773649d-14)))))
;;    :END
;;    (:TIME 2.6692152578309467d0 :POSITIONS (("ball" (0.0d0 5.094498809086786d-13))) :VELOCITIES
;;     (("ball" (0.0d0 1.1506349885085763d-12)))))
