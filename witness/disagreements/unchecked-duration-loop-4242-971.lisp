;;;; unchecked-duration-loop-4242-971 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong (the comparator's); examined by hand: AMES's state 2 (sliding after
;;;; its landing, turning back) has a travel-time integral as its duration, and in a scenario
;;;; without parameters its number was never recorded (the quadrature itself gives 0.80868 s):
;;;; the self-check said "state 2 not checked (its duration has no number)" and the comparator
;;;; counted the missing time as "AMES wrong". Fixed: a state without a number to compare is
;;;; :unchecked (a verdict of its own); such a duration's number is recorded (simulator/
;;;; state-numbers.lisp), so the self-check checks state 2; and the comparator evaluates the
;;;; sines and inverse tangents of 40-digit radicals to 160 digits (precise-functions.lisp),
;;;; where the speed at the turning point is exactly 0. Now agrees (end 2.385584692 s).
;;;; reason: state 2: AMES ends the state with (:TURNS PARTICLE) at NIL; the witness has no more events
;;;; Run: bin/ames check /work/main/t/../witness/disagreements/unchecked-duration-loop-4242-971.lisp --numeric

(scenario loop-971 "A particle launched inside a vertical loop." (gravity 21/2) (restitution 0)
 (body loop :fixed t :shape (arc :center (0 7/4) :radius 7/4 :from 0 :to (* 2 pi) :solid :outside))
 (body particle :mass 1 :position (0 0) :velocity (31/4 0) :shape point) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::LOOP-971 :STATES
;;    ((:INDEX 0 :START 0 :DURATION
;;      (-
;;       (/
;;        (AMES-SCENARIO::ELLIPTIC-F
;;         (- (ASIN (/ (* 14 (SQRT 6) (SIN (/ (+ PI (* 2 (ASIN 373/882))) 4))) 31))) 961/1176)
;;        (* (SQRT 2) (SQRT 3))))
;;      :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP :FEATURE (:ARC 0 :OF AMES-SCENARIO::LOOP)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/ (* (COS (/ (* 4 AMES-SCENARIO::S) 7)) (+ 373 (* 882 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))))
;;             28))
;;         (/
;;          (-
;;           (+ (* 373 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;              (* 882 (EXPT (SIN (/ (* 4 AMES-SCENARIO::S) 7)) 2)))
;;           294)
;;          28))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP
;;        (/ (+ 373 (* 882 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))) 28)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/ (* 7 (COS (/ (* 4 AMES-SCENARIO::S) 7))) 4)
;;          (- (/ (- (* 7 (SIN (/ (* 4 AMES-SCENARIO::S) 7))) 7) 4)))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/
;;           (* (SIN (/ (* 4 AMES-SCENARIO::S) 7))
;;              (SQRT (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7))))))
;;           4)
;;          (/
;;           (* (COS (/ (* 4 AMES-SCENARIO::S) 7))
;;              (SQRT (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7))))))
;;           4))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES ((AMES-SCENARIO::LOOP (0 0)) (AMES-SCENARIO::PARTICLE (31/4 0))) :END-EVENT
;;      (:LIFT-OFF AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0)) (AMES-SCENARIO::PARTICLE ((/ (SQRT 638795) 504) 1255/504)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;         (/ (* (SQRT 373) (SQRT 638795)) (* (EXPT 3 5/2) 392)))))
;;      :END-ARC-LENGTH (- (/ (* 7 (ASIN 373/882)) 4)) :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP) :ARC-LENGTH-FROM (/ (* 7 PI) 8)
;;       :DIRECTION -1 :TANGENTIAL-ACCELERATION (/ (* 21 (COS (/ (* 4 AMES-SCENARIO::S) 7))) 2)
;;       :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2) (/ (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))) 16)) :ODE
;;       :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE (/ (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))) 32))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 147 (SIN (/ (* 4 AMES-SCENARIO::S) 7))) 147) 8))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((/
;;          (* (SIN (/ (* 4 AMES-SCENARIO::S) 7))
;;             (SQRT (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7))))))
;;          4)
;;         (/
;;          (* (COS (/ (* 4 AMES-SCENARIO::S) 7))
;;             (SQRT (+ 373 (* 588 (SIN (/ (* 4 AMES-SCENARIO::S) 7))))))
;;          4)))))
;;     (:INDEX 1 :START
;;      (-
;;       (/
;;        (AMES-SCENARIO::ELLIPTIC-F
;;         (- (ASIN (/ (* 14 (SQRT 6) (SIN (/ (+ PI (* 2 (ASIN 373/882))) 4))) 31))) 961/1176)
;;        (* (SQRT 2) (SQRT 3))))
;;      :DURATION (/ (* (SQRT 373) (SQRT 638795)) (* (EXPT 3 7/2) 343)) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::LOOP (0 0)) (AMES-SCENARIO::PARTICLE (0 -21/2))) :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))) :POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/ (- (* (EXPT 373 3/2) AMES.BASE:TAU) (* 7 (SQRT 3) (SQRT 638795))) (* (EXPT 3 5/2) 392)))
;;         (-
;;          (/
;;           (- (* 686 (EXPT 3 7/2) (EXPT AMES.BASE:TAU 2)) (* 8785 (SQRT 3))
;;              (* (SQRT 373) (SQRT 638795) AMES.BASE:TAU))
;;           (* (EXPT 3 5/2) 392))))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;         (-
;;          (/ (- (* 1372 (EXPT 3 7/2) AMES.BASE:TAU) (* (SQRT 373) (SQRT 638795)))
;;             (* (EXPT 3 5/2) 392))))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;         (/ (* (SQRT 373) (SQRT 638795)) (* (EXPT 3 5/2) 392)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP :IMPULSE
;;       (/ (* (EXPT 373 3/2) (EXPT 638795 3/2)) (* (EXPT 3 17/2) 46118408)) :ENERGY-LOST
;;       13527296830499201145380375/549338377052922366075264)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE ((/ (* 6919 (SQRT 638795)) 12252303) 725390/12252303)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;         (- (/ (* (SQRT 373) (SQRT 638795)) (* (EXPT 3 3/2) 392))))))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP :FEATURE (:ARC 0 :OF AMES-SCENARIO::LOOP)
;;         :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP
;;         (/ (* (EXPT 373 3/2) (EXPT 638795 3/2)) (* (EXPT 3 17/2) 46118408))))
;;       :ENERGY-LOST 13527296830499201145380375/549338377052922366075264 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::LOOP (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;          (- (/ (* (SQRT 373) (SQRT 638795)) (* (EXPT 3 3/2) 392))))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::LOOP (0 0))
;;        (AMES-SCENARIO::PARTICLE
;;         ((- (/ (* 18649269835230541 (EXPT 373 3/2)) (* (EXPT 3 29/2) 5425784582792)))
;;          (- (/ (* 580824813037447 (SQRT 373) (SQRT 638795)) (* (EXPT 3 29/2) 1356446145698)))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/
;;         (- (+ 7833 (* 111132 (EXPT AMES.BASE:TAU 2)))
;;            (* 2 (SQRT 3) (SQRT 373) (SQRT 638795) AMES.BASE:TAU))
;;         2016))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (-
;;         (/
;;          (- (* 686 (EXPT 3 7/2) (EXPT AMES.BASE:TAU 2)) (* 8785 (SQRT 3))
;;             (* (SQRT 373) (SQRT 638795) AMES.BASE:TAU))
;;          (* (EXPT 3 3/2) 112)))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((- (/ (EXPT 373 3/2) (* (EXPT 3 5/2) 392)))
;;         (-
;;          (/ (- (* 1372 (EXPT 3 7/2) AMES.BASE:TAU) (* (SQRT 373) (SQRT 638795)))
;;             (* (EXPT 3 5/2) 392)))))))
;;     (:INDEX 2 :START
;;      (-
;;       (/
;;        (-
;;         (* 343 (EXPT 3 7/2)
;;            (AMES-SCENARIO::ELLIPTIC-F
;;             (- (ASIN (/ (* 14 (SQRT 6) (SIN (/ (+ PI (* 2 (ASIN 373/882))) 4))) 31))) 961/1176))
;;         (* (SQRT 2) (SQRT 3) (SQRT 373) (SQRT 638795)))
;;        (* (SQRT 2) 27783)))
;;      :DURATION
;;      (:NO-CLOSED-FORM :FROM-ARC-LENGTH (/ (* 7 (ATAN (/ 82864561 (* (SQRT 638795) 27676)))) 4)
;;       :TO-ARC-LENGTH
;;       (/
;;        (+ (* 7 (ATAN (/ 82864561 (* (SQRT 638795) 27676))))
;;           (* 14
;;              (ATAN
;;               (/
;;                (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                   (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                (* (EXPT 5 3/2) 3375334010668099787897839)))))
;;        4)
;;       :SPEED-SQUARED
;;       (/
;;        (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;           7124071372976074815815579)
;;        274669188526461183037632))
;;      :CONTACTS
;;      ((AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP :FEATURE (:ARC 0 :OF AMES-SCENARIO::LOOP)
;;        :OBSERVER-FEATURE (:POINT :OF AMES-SCENARIO::PARTICLE)))
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (-
;;            (* 15141139017521172714949464 (COS (/ (* 4 AMES-SCENARIO::S) 7))
;;               (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;            (* 7124071372976074815815579 (COS (/ (* 4 AMES-SCENARIO::S) 7))))
;;           480671079921307070315856))
;;         (/
;;          (- (* 15141139017521172714949464 (EXPT (SIN (/ (* 4 AMES-SCENARIO::S) 7)) 2))
;;             5047046339173724238316488
;;             (* 7124071372976074815815579 (SIN (/ (* 4 AMES-SCENARIO::S) 7))))
;;          480671079921307070315856))))
;;      :FORCES
;;      ((:GRAVITY AMES-SCENARIO::PARTICLE (0 -21/2))
;;       (:NORMAL AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP
;;        (/
;;         (- (* 15141139017521172714949464 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;            7124071372976074815815579)
;;         480671079921307070315856)))
;;      :POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((/ (* 7 (COS (/ (* 4 AMES-SCENARIO::S) 7))) 4)
;;          (- (/ (- (* 7 (SIN (/ (* 4 AMES-SCENARIO::S) 7))) 7) 4)))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        (:ON-PATH
;;         ((-
;;           (/
;;            (* (SIN (/ (* 4 AMES-SCENARIO::S) 7))
;;               (SQRT
;;                (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;                   7124071372976074815815579)))
;;            (* (EXPT 3 17/2) 46118408)))
;;          (-
;;           (/
;;            (* (COS (/ (* 4 AMES-SCENARIO::S) 7))
;;               (SQRT
;;                (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;                   7124071372976074815815579)))
;;            (* (EXPT 3 17/2) 46118408))))
;;         :ARC-LENGTH AMES-SCENARIO::S)))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((- (/ (* 18649269835230541 (EXPT 373 3/2)) (* (EXPT 3 29/2) 5425784582792)))
;;         (- (/ (* 580824813037447 (SQRT 373) (SQRT 638795)) (* (EXPT 3 29/2) 1356446145698))))))
;;      :END-EVENT (:TURNS AMES-SCENARIO::PARTICLE) :FINAL-POSITIONS
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((/
;;          (* 7
;;             (COS
;;              (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                 (* 2
;;                    (ATAN
;;                     (/
;;                      (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                         (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                      (* (EXPT 5 3/2) 3375334010668099787897839)))))))
;;          4)
;;         (-
;;          (/
;;           (-
;;            (* 7
;;               (SIN
;;                (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                   (* 2
;;                      (ATAN
;;                       (/
;;                        (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                           (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                        (* (EXPT 5 3/2) 3375334010668099787897839)))))))
;;            7)
;;           4)))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::LOOP (0 0))
;;       (AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (*
;;            (SIN
;;             (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                (* 2
;;                   (ATAN
;;                    (/
;;                     (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                        (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                     (* (EXPT 5 3/2) 3375334010668099787897839))))))
;;            (SQRT
;;             (-
;;              (* 10094092678347448476632976
;;                 (SIN
;;                  (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                     (* 2
;;                        (ATAN
;;                         (/
;;                          (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                             (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                          (* (EXPT 5 3/2) 3375334010668099787897839)))))))
;;              7124071372976074815815579)))
;;           (* (EXPT 3 17/2) 46118408)))
;;         (-
;;          (/
;;           (*
;;            (COS
;;             (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                (* 2
;;                   (ATAN
;;                    (/
;;                     (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                        (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                     (* (EXPT 5 3/2) 3375334010668099787897839))))))
;;            (SQRT
;;             (-
;;              (* 10094092678347448476632976
;;                 (SIN
;;                  (+ (ATAN (/ 82864561 (* (SQRT 638795) 27676)))
;;                     (* 2
;;                        (ATAN
;;                         (/
;;                          (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                             (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;                          (* (EXPT 5 3/2) 3375334010668099787897839)))))))
;;              7124071372976074815815579)))
;;           (* (EXPT 3 17/2) 46118408))))))
;;      :END-ARC-LENGTH
;;      (/
;;       (+ (* 7 (ATAN (/ 82864561 (* (SQRT 638795) 27676))))
;;          (* 14
;;             (ATAN
;;              (/
;;               (+ (* 3257278115282186821056 (SQRT 5) (SQRT 638795))
;;                  (* 5 (SQRT 10227662814362070048506094859347167840147774302267)))
;;               (* (EXPT 5 3/2) 3375334010668099787897839)))))
;;       4)
;;      :PATH-COORDINATES
;;      (:CONTACT (AMES-SCENARIO::PARTICLE AMES-SCENARIO::LOOP) :ARC-LENGTH-FROM
;;       (/ (* 7 (ATAN (/ 82864561 (* (SQRT 638795) 27676)))) 4) :DIRECTION 1 :TANGENTIAL-ACCELERATION
;;       (/ (* 21 (COS (/ (* 4 AMES-SCENARIO::S) 7))) 2) :ENERGY-INTEGRAL
;;       (= (EXPT AMES-SCENARIO::SDOT 2)
;;          (/
;;           (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;              7124071372976074815815579)
;;           274669188526461183037632))
;;       :ODE :ENERGY-INTEGRAL)
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::PARTICLE
;;        (/
;;         (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;            7124071372976074815815579)
;;         549338377052922366075264))
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::PARTICLE)
;;        (- (/ (- (* 147 (SIN (/ (* 4 AMES-SCENARIO::S) 7))) 147) 8))))
;;      :MOMENTUM
;;      ((:MOMENTUM AMES-SCENARIO::PARTICLE
;;        ((-
;;          (/
;;           (* (SIN (/ (* 4 AMES-SCENARIO::S) 7))
;;              (SQRT
;;               (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;                  7124071372976074815815579)))
;;           (* (EXPT 3 17/2) 46118408)))
;;         (-
;;          (/
;;           (* (COS (/ (* 4 AMES-SCENARIO::S) 7))
;;              (SQRT
;;               (- (* 10094092678347448476632976 (SIN (/ (* 4 AMES-SCENARIO::S) 7)))
;;                  7124071372976074815815579)))
;;           (* (EXPT 3 17/2) 46118408))))))))
;;    :OUTCOME :STATE-LIMIT :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED ((:STATE 2 :REASON "its duration has no number")) :NUMBERS (0 0)
;;     :EQUATIONS (31 31) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :CURVED :EVENTS
;;    ((:TIME 0.6145938874668151d0 :SPEED 0.0d0 :PAIRS ((:LIFT-OFF "particle" "loop")) :POSITIONS
;;      (("particle" (1.5858065873989033d0 2.4900793655832683d0))) :VELOCITIES
;;      (("particle" (-1.1788920633054836d0 2.5260734007204992d0))) :AFTER
;;      (("particle" (-1.1788920633054836d0 2.5260734007204992d0))))
;;     (:TIME 1.5769075645301887d0 :SPEED 7.017792738207492d0 :PAIRS ((:COLLISION "particle" "loop"))
;;      :POSITIONS (("particle" (0.4513426310985751d0 0.05920437978062054d0))) :VELOCITIES
;;      (("particle" (-1.1788920633054836d0 -7.578220208444927d0))) :AFTER
;;      (("particle" (-2.9888515141437875d0 -0.7978469368057546d0)))))
;;    :END
;;    (:TIME 1.598d0 :POSITIONS (("particle" (0.387441501143615d0 0.04342768005819887d0))) :VELOCITIES
;;     (("particle" (-3.0685164467265515d0 -0.6966423892566775d0)))))
