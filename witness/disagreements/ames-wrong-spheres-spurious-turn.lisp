;;;; ames-wrong-gravitation-101-718 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong
;;;; reason: state 1: AMES ends the state with (:TURNS PAIR-0) at 4.978625637340064d0; the witness has no more events
;;;; Diagnosis: after their plastic collision the two spheres rest against each other on the
;;;; line of their centres (gravitation pressing them together: an equilibrium). AMES's
;;;; state 1 takes the contact as a path integrated numerically and ends it with (:turns
;;;; PAIR-0) after 8.7e-22 s: a turning point found in the round-off of a motion that starts
;;;; at rest and stays there: its path position is a rational near 5 pi / 4 (the angle
;;;; 406138636/129277943 for pi), off the equilibrium by round-off. The witness has no event. (With
;;;; (simulate :states 3) the next state is refused: a geometric fact on those round-off
;;;; positions cannot be decided.) For the lead: a turning point at tau ~ 0 of a path state
;;;; starting at rest with zero path acceleration is no event.
;;;; Run: bin/ames check witness/disagreements/ames-wrong-spheres-spurious-turn.lisp --numeric

(scenario gravitation-718 "Two spheres released at rest fall together." (gravitation 3/4)
 (restitution 0) (body first :mass 3 :position (0 0) :velocity (0 0) :shape (circle 1/4))
 (body second :mass 9/4 :position (9/2 0) :velocity (0 0) :shape (circle 1)) (simulate :states 2))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::GRAVITATION-718 :STATES
;;    ((:INDEX 0 :START 0 :DURATION
;;      (- (/ (- (* 18 (SQRT 7) (ASIN (/ (SQRT 5) (* (SQRT 2) 3)))) (SQRT 455) (* 9 (SQRT 7) PI)) 14))
;;      :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FIRST ((/ 27 (* (EXPT AMES-SCENARIO::S 2) 16)) 0))
;;       (AMES-SCENARIO::SECOND ((- (/ 9 (* (EXPT AMES-SCENARIO::S 2) 4))) 0)))
;;      :FORCES
;;      ((:GRAVITATION AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND
;;        ((/ 81 (* (EXPT AMES-SCENARIO::S 2) 16)) 0))
;;       (:GRAVITATION AMES-SCENARIO::SECOND AMES-SCENARIO::FIRST
;;        ((- (/ 81 (* (EXPT AMES-SCENARIO::S 2) 16))) 0)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::FIRST
;;        (:ON-PATH ((- (/ (- (* 6 AMES-SCENARIO::S) 27) 14)) 0) :ARC-LENGTH AMES-SCENARIO::S))
;;       (AMES-SCENARIO::SECOND
;;        (:ON-PATH ((/ (+ 27 (* 8 AMES-SCENARIO::S)) 14) 0) :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FIRST
;;        (:ON-PATH
;;         ((/ (* 3 (SQRT (- (/ (- (* 14 AMES-SCENARIO::S) 63) AMES-SCENARIO::S)))) (* (EXPT 2 3/2) 7))
;;          0)
;;         :ARC-LENGTH AMES-SCENARIO::S))
;;       (AMES-SCENARIO::SECOND
;;        (:ON-PATH
;;         ((- (/ (* (SQRT 2) (SQRT (- (/ (- (* 14 AMES-SCENARIO::S) 63) AMES-SCENARIO::S)))) 7)) 0)
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FIRST (0 0)) (AMES-SCENARIO::SECOND (0 0))) :END-EVENT
;;      (:COLLISION AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND :IMPULSE
;;       (/ (* 9 (SQRT 13)) (* (SQRT 5) (SQRT 7) 2)) :ENERGY-LOST 117/40)
;;      :FINAL-POSITIONS ((AMES-SCENARIO::FIRST (39/28 0)) (AMES-SCENARIO::SECOND (37/14 0)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FIRST ((/ (* 3 (SQRT 13)) (* (SQRT 5) (SQRT 7) 2)) 0))
;;       (AMES-SCENARIO::SECOND ((- (/ (* (SQRT 2) (SQRT 182)) (* (SQRT 5) 7))) 0)))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND :FEATURE (:CIRCLE :OF AMES-SCENARIO::SECOND)
;;         :OBSERVER-FEATURE (:CIRCLE :OF AMES-SCENARIO::FIRST)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND
;;         (/ (* 9 (SQRT 13)) (* (SQRT 5) (SQRT 7) 2))))
;;       :ENERGY-LOST 117/40 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FIRST ((/ (* 3 (SQRT 13)) (* (SQRT 5) (SQRT 7) 2)) 0))
;;        (AMES-SCENARIO::SECOND ((- (/ (* (SQRT 2) (SQRT 182)) (* (SQRT 5) 7))) 0)))
;;       :VELOCITIES-AFTER ((AMES-SCENARIO::FIRST (0 0)) (AMES-SCENARIO::SECOND (0 0))))
;;      :END-ARC-LENGTH 5/4 :ENERGY
;;      ((:KINETIC AMES-SCENARIO::FIRST
;;        (- (/ (- (* 54 AMES-SCENARIO::S) 243) (* AMES-SCENARIO::S 112))))
;;       (:KINETIC AMES-SCENARIO::SECOND (- (/ (- (* 18 AMES-SCENARIO::S) 81) (* AMES-SCENARIO::S 28))))
;;       (:POTENTIAL (:GRAVITATION AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND)
;;        (- (/ 81 (* AMES-SCENARIO::S 16)))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::FIRST
;;        ((/ (* 9 (SQRT (- (/ (- (* 14 AMES-SCENARIO::S) 63) AMES-SCENARIO::S)))) (* (EXPT 2 3/2) 7))
;;         0))
;;       (:MOMENTUM AMES-SCENARIO::SECOND
;;        ((-
;;          (/ (* 9 (SQRT (- (/ (- (* 14 AMES-SCENARIO::S) 63) AMES-SCENARIO::S)))) (* (EXPT 2 3/2) 7)))
;;         0))))
;;     (:INDEX 1 :START
;;      (- (/ (- (* 18 (SQRT 7) (ASIN (/ (SQRT 5) (* (SQRT 2) 3)))) (SQRT 455) (* 9 (SQRT 7) PI)) 14))
;;      :DURATION 8.673617379884036d-22 :CONTACTS
;;      ((AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND :FEATURE (:CIRCLE :OF AMES-SCENARIO::SECOND)
;;        :OBSERVER-FEATURE (:CIRCLE :OF AMES-SCENARIO::FIRST)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FIRST
;;        ((-
;;          (/
;;           (-
;;            (*
;;             (-
;;              (+ (* 192 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2))
;;                 (* 192 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)))
;;              (* 384 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;                 (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)))
;;             (COS (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5))
;;             (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))
;;            (* 945
;;               (EXPT (SIN (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5)) 2)))
;;           (-
;;            (+ (* 560 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2))
;;               (* 560 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)))
;;            (* 1120 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;               (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)))))
;;         (-
;;          (/
;;           (* 3 (SIN (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5))
;;              (-
;;               (+ (* 315 (COS (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5)))
;;                  (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2)
;;                     (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))
;;                  (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)
;;                     (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2)))
;;               (* 128 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;                  (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                  (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))))
;;           (*
;;            (EXPT
;;             (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;             2)
;;            560)))))
;;       (AMES-SCENARIO::SECOND
;;        ((/
;;          (-
;;           (*
;;            (-
;;             (+ (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2))
;;                (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)))
;;             (* 128 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;                (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)))
;;            (COS (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5))
;;            (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))
;;           (* 315 (EXPT (SIN (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5)) 2)))
;;          (-
;;           (+ (* 140 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2))
;;              (* 140 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)))
;;           (* 280 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;              (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X))))
;;         (/
;;          (* (SIN (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5))
;;             (-
;;              (+ (* 315 (COS (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5)))
;;                 (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2)
;;                    (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))
;;                 (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)
;;                    (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2)))
;;              (* 128 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;                 (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                 (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))))
;;          (*
;;           (EXPT
;;            (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;               (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;            2)
;;           140)))))
;;      :FORCES
;;      ((:GRAVITATION AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND
;;        ((/ 81
;;            (*
;;             (EXPT
;;              (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;              2)
;;             16))
;;         0))
;;       (:GRAVITATION AMES-SCENARIO::SECOND AMES-SCENARIO::FIRST
;;        ((-
;;          (/ 81
;;             (*
;;              (EXPT
;;               (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                  (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;               2)
;;              16)))
;;         0))
;;       (:NORMAL AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND
;;        (-
;;         (/
;;          (* 9
;;             (-
;;              (+ (* 315 (COS (/ (* 4 (AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)) 5)))
;;                 (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) 2)
;;                    (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))
;;                 (* 64 (EXPT (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) 2)
;;                    (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2)))
;;              (* 128 (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X)
;;                 (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;                 (EXPT (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0) 2))))
;;          (*
;;           (EXPT
;;            (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;               (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;            2)
;;           560)))))
;;      :POSITIONS ((AMES-SCENARIO::FIRST (:NO-CLOSED-FORM)) (AMES-SCENARIO::SECOND (:NO-CLOSED-FORM)))
;;      :VELOCITIES ((AMES-SCENARIO::FIRST (:NO-CLOSED-FORM)) (AMES-SCENARIO::SECOND (:NO-CLOSED-FORM)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::FIRST (0 0)) (AMES-SCENARIO::SECOND (0 0))) :END-EVENT
;;      (:TURNS AMES-SCENARIO::PAIR-0) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FIRST
;;        ((/ (+ 74 (* 35 (COS 406138636/129277943))) 28)
;;         (/
;;          (- (* 37687396795367442653444192429305923397870082757843664873165 (SIN 406138636/129277943))
;;             2)
;;          30149917436293954122755353943444738718296066206274931898532)))
;;       (AMES-SCENARIO::SECOND (37/14 -1/15074958718146977061377676971722369359148033103137465949266)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FIRST
;;        ((/
;;          (- (* 53384544845824193150482429159615478953228198678901554 (SIN 406138636/129277943))
;;             3735840683964395878449767129871012281)
;;          199436154529951818459451810832934784471302401703988722369910049853004342461049695123984674)
;;         (-
;;          (/
;;           (+ 3735840683964395878449767129871012281
;;              (* 6537721196937692723537778559828785921 (COS 406138636/129277943)))
;;           24423884827936238869525894015307500278981608910854524306313156603510895801))))
;;       (AMES-SCENARIO::SECOND
;;        (-1/53384544845824193150482429159615478953228198678901554
;;         -1/6537721196937692723537778559828785921)))
;;      :NUMERIC-TRAJECTORY
;;      ((:TERMS
;;        ((AMES-SCENARIO::PATH-POSITION AMES-SCENARIO::CONTACT-0)
;;         (AMES-SCENARIO::PATH-SPEED AMES-SCENARIO::CONTACT-0)
;;         (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X) (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :Y)
;;         (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X) (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :Y)
;;         (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :X) (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :Y)
;;         (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :X) (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :Y))
;;        :END-TIME 8.673617379884036d-22 :SAMPLES
;;        ((0.0d0 3.9269908169872414d0 0.0d0 1.3928571428571428d0 0.0d0 2.642857142857143d0 0.0d0 0.0d0
;;          0.0d0 0.0d0 0.0d0)
;;         (8.673617379884036d-22 3.9269908169872414d0 -2.6767736758485666d-37 1.3928571428571428d0
;;          4.975138002183464d-59 2.642857142857143d0 -6.633517336244623d-59 1.4049009917870752d-53
;;          1.1471887182208142d-37 -1.8732013223827668d-53 -1.5295849576277524d-37))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::FIRST
;;        (/
;;         (* 3
;;            (+ (EXPT (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :X) 2)
;;               (EXPT (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :Y) 2)))
;;         2))
;;       (:KINETIC AMES-SCENARIO::SECOND
;;        (/
;;         (* 9
;;            (+ (EXPT (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :X) 2)
;;               (EXPT (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :Y) 2)))
;;         8))
;;       (:POTENTIAL (:GRAVITATION AMES-SCENARIO::FIRST AMES-SCENARIO::SECOND)
;;        (/ 81
;;           (*
;;            (- (AMES-SCENARIO::POS AMES-SCENARIO::FIRST :X)
;;               (AMES-SCENARIO::POS AMES-SCENARIO::SECOND :X))
;;            16))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::FIRST
;;        ((* 3 (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :X))
;;         (* 3 (AMES-SCENARIO::VEL AMES-SCENARIO::FIRST :Y))))
;;       (:MOMENTUM AMES-SCENARIO::SECOND
;;        ((/ (* 9 (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :X)) 4)
;;         (/ (* 9 (AMES-SCENARIO::VEL AMES-SCENARIO::SECOND :Y)) 4))))))
;;    :OUTCOME :STATE-LIMIT :ANSWERS NIL)

;; witness's answer:
;;   (:STATUS :OK :SCHEME :CURVED :EVENTS
;;    ((:TIME 4.9786256373379825d0 :SPEED 2.1330729007715d0 :PAIRS ((:COLLISION "second" "first"))
;;      :POSITIONS (("first" (1.3928571428571446d0 0.0d0)) ("second" (2.6428571428571437d0 0.0d0)))
;;      :VELOCITIES (("first" (0.9141741003306431d0 0.0d0)) ("second" (-1.2188988004408567d0 0.0d0)))
;;      :AFTER (("first" (1.1102230246251565d-16 0.0d0)) ("second" (4.440892098500626d-16 0.0d0)))))
;;    :END
;;    (:TIME 4.980625637337982d0 :POSITIONS
;;     (("first" (1.3928571428571446d0 0.0d0)) ("second" (2.6428571428571437d0 0.0d0))) :VELOCITIES
;;     (("first" (1.1043018351604887d-16 0.0d0)) ("second" (4.448787017786849d-16 0.0d0)))))
