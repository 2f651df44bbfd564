;;;; witness-wrong-rod-ledge-2027-773 -- a disagreement found by the witness (make crosscheck).
;;;; verdict: ames-wrong (the comparator's); examined: the witness is wrong (a graze)
;;;; reason: at the witness's step 6.25e-5 s: state 1: end time: AMES 0.5263276733272356d0, witness 0.494375d0; at its step 0.001 s: state 1: end time: AMES 0.5263276733272356d0, witness 0.492d0
;;;; Examined (lead, session 6): AMES IS RIGHT; the witness's first-order step cannot resolve
;;;; a graze. The rod lands with its left end on the ledge's top (0.4065 s, agreed) and flies
;;;; off spinning clockwise; its lower face then passes over the ledge's edge (0, 0) without
;;;; touching it. The gap of that corner on the rod's face over AMES's exact closed-form
;;;; flight (the scenario's numbers put in; the face-on-vertex condition's gap), evaluated by
;;;; Maxima with 40-digit bigfloats: 0.05523 at the state's start, least at tau = 0.0894945
;;;; (t = 0.49597), where it is 1.137e-5 (11 micrometres), then growing. A double-precision
;;;; sampling of the same function agrees (1.49e-5 at tau = 0.0899). The witness (Moreau-Jean,
;;;; first order) knows the rod's state after the first impact only to O(step) (about 3 m/s x
;;;; 6.25e-5 s = 2e-4 m at its finest step), more than the clearance, so it strikes the edge
;;;; (at 0.4944 s with step 6.25e-5, 0.492 s with 1e-3: the time moves with the step). AMES
;;;; flies on to the rod's right end striking the floor at 0.5263 s. What the comparator could
;;;; do (not built): where AMES's least gap of a pair over a state is below the witness's
;;;; resolution at its step, call a witness strike of that pair "unsupported", with the
;;;; clearance as the reason.
;;;; Done (witness helper, session 7: src/witness/compare-grazes.lisp): the verdict is now
;;;; "unsupported: ... AMES's least gap of that pair over the state is 1.143e-5 m (at 0.495914 s,
;;;; positive), below the witness's resolution 1.176e-2 m (20 steps of 6.25e-5 s at 9.409 m/s)",
;;;; the gap sampled along AMES's closed forms with the witness's own gap functions
;;;; (witness/siconos_probe_gaps.py); t/witness-ropes.lisp checks it from the answers kept here.
;;;; Run: bin/ames check witness/disagreements/witness-wrong-rod-ledge-2027-773.lisp --numeric

(scenario rod-ledge-773 "A rod or a block falls across the edge of a ledge." (gravity 23/2)
 (body floor :fixed t :shape (half-plane (1 -3/4) (0 -3/4)))
 (body ledge :fixed t :shape (polygon (-3 -3/4) (0 -3/4) (0 0) (-3 0)))
 (body rod :mass 3/2 :inertia :uniform :shape (segment (-1/2 0) (1/2 0)) :position
  (277/820 869/820) :angle (atan 9/40) :velocity (-1/4 0))
 (restitution 1/2) (simulate :states 3))


;; AMES's answer:
;;   (:SCENARIO AMES-SCENARIO::ROD-LEDGE-773 :STATES
;;    ((:INDEX 0 :START 0 :DURATION (/ (SQRT 19) (SQRT 115)) :CONTACTS NIL :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 -23/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::ROD (0 -69/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        ((- (/ (- (* 205 AMES.BASE:TAU) 277) 820))
;;         (- (/ (- (* 4715 (EXPT AMES.BASE:TAU 2)) 869) 820)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (-1/4 (- (/ (* 23 AMES.BASE:TAU) 2)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (-1/4 0)))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :IMPULSE
;;       (/ (* 15129 (SQRT 19) (SQRT 115)) 259240) :ENERGY-LOST 6611373/2073920)
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD ((/ (- (* 277 (SQRT 115)) (* 205 (SQRT 19))) (* (SQRT 115) 820)) 9/82)))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (-1/4 (- (/ (* 23 (SQRT 19)) (* (SQRT 115) 2))))))
;;      :ANGLES ((AMES-SCENARIO::ROD (ATAN 9/40))) :ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD 0))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::ROD 0)) :FINAL-ANGLES ((AMES-SCENARIO::ROD (ATAN 9/40)))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD 0)) :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE :FEATURE (:EDGE 2) :OBSERVER-FEATURE (:VERTEX 0)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::ROD AMES-SCENARIO::LEDGE (/ (* 15129 (SQRT 19) (SQRT 115)) 259240)))
;;       :ENERGY-LOST 6611373/2073920 :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (-1/4 (- (/ (* 23 (SQRT 19)) (* (SQRT 115) 2))))))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (-1/4 (- (/ (* 7919 (SQRT 19) (SQRT 115)) 129620)))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::ROD 0)) :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::ROD (- (/ (* 1476 (SQRT 19) (SQRT 115)) 6481)))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::ROD (/ (+ 3 (* 6348 (EXPT AMES.BASE:TAU 2))) 64))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::ROD) 0)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::ROD)
;;        (- (/ (- (* 325335 (EXPT AMES.BASE:TAU 2)) 59961) 3280))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::ROD
;;        (/ (- (+ 2607 (* 14145 (EXPT AMES.BASE:TAU 2))) (* 38226 AMES.BASE:TAU)) 6560))
;;       (:MOMENTUM AMES-SCENARIO::ROD (-3/8 (- (/ (* 69 AMES.BASE:TAU) 4))))))
;;     (:INDEX 1 :START (/ (SQRT 19) (SQRT 115)) :DURATION 0.11985825097870542d0 :CONTACTS NIL
;;      :ACCELERATIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0)) (AMES-SCENARIO::ROD (0 -23/2)))
;;      :FORCES ((:GRAVITY AMES-SCENARIO::ROD (0 -69/4))) :POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        ((-
;;          (/ (- (+ (* 205 (SQRT 19)) (* 205 (SQRT 115) AMES.BASE:TAU)) (* 277 (SQRT 115)))
;;             (* (SQRT 115) 820)))
;;         (-
;;          (/
;;           (- (+ (* 324679 (SQRT 19) (SQRT 115) AMES.BASE:TAU) (* 30557915 (EXPT AMES.BASE:TAU 2)))
;;              583290)
;;           5314420)))))
;;      :VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        (-1/4 (- (/ (+ (* 7919 (SQRT 19) (SQRT 115)) (* 1490630 AMES.BASE:TAU)) 129620)))))
;;      :INITIAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (-1/4 (- (/ (* 7919 (SQRT 19) (SQRT 115)) 129620)))))
;;      :END-EVENT
;;      (:COLLISION AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR :IMPULSE
;;       (/
;;        (+ 10943271502533
;;           (* 294303725568 (SQRT 19) (SQRT 115)
;;              (COS
;;               (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))))
;;        (+ 1148679581696
;;           (* 3446038745088
;;              (EXPT
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;               2))))
;;       :ENERGY-LOST
;;       (/
;;        (+ 13306132353127873713935121
;;           (* 715699016243908233080832 (SQRT 19) (SQRT 115)
;;              (COS
;;               (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506)))
;;           (* 21028120233311352819548160
;;              (EXPT
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;               2)))
;;        (+ 1319464781405297538236416
;;           (* 3958394344215892614709248
;;              (EXPT
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;               2)))))
;;      :FINAL-POSITIONS
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD
;;        (84026349/407453899
;;         (-
;;          (/
;;           (+ 3
;;              (* 2
;;                 (SIN
;;                  (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115)))
;;                     10667894506))))
;;           4)))))
;;      :FINAL-VELOCITIES
;;      ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;       (AMES-SCENARIO::ROD (-1/4 -187612877/44309504)))
;;      :ANGLES
;;      ((AMES-SCENARIO::ROD
;;        (- (/ (- (* 1476 (SQRT 19) (SQRT 115) AMES.BASE:TAU) (* 6481 (ATAN 9/40))) 6481))))
;;      :ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD (- (/ (* 1476 (SQRT 19) (SQRT 115)) 6481))))
;;      :ANGULAR-ACCELERATIONS ((AMES-SCENARIO::ROD 0)) :FINAL-ANGLES
;;      ((AMES-SCENARIO::ROD
;;        (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506)))
;;      :FINAL-ANGULAR-VELOCITIES ((AMES-SCENARIO::ROD (- (/ (* 1476 (SQRT 19) (SQRT 115)) 6481))))
;;      :IMPACT
;;      (:CONTACTS
;;       ((AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR :FEATURE (:EDGE 0) :OBSERVER-FEATURE (:VERTEX 1)))
;;       :IMPULSES
;;       ((:IMPULSE AMES-SCENARIO::ROD AMES-SCENARIO::FLOOR
;;         (/
;;          (+ 10943271502533
;;             (* 294303725568 (SQRT 19) (SQRT 115)
;;                (COS
;;                 (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))))
;;          (+ 1148679581696
;;             (* 3446038745088
;;                (EXPT
;;                 (COS
;;                  (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;                 2))))))
;;       :ENERGY-LOST
;;       (/
;;        (+ 13306132353127873713935121
;;           (* 715699016243908233080832 (SQRT 19) (SQRT 115)
;;              (COS
;;               (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506)))
;;           (* 21028120233311352819548160
;;              (EXPT
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;               2)))
;;        (+ 1319464781405297538236416
;;           (* 3958394344215892614709248
;;              (EXPT
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;               2))))
;;       :VELOCITIES-BEFORE
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD (-1/4 -187612877/44309504)))
;;       :VELOCITIES-AFTER
;;       ((AMES-SCENARIO::FLOOR (0 0)) (AMES-SCENARIO::LEDGE (0 0))
;;        (AMES-SCENARIO::ROD
;;         (-1/4
;;          (-
;;           (/
;;            (-
;;             (* 7295514335022
;;                (EXPT
;;                 (COS
;;                  (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;                 2))
;;             1215919055837
;;             (* 98101241856 (SQRT 19) (SQRT 115)
;;                (COS
;;                 (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))))
;;            (+ 574339790848
;;               (* 1723019372544
;;                  (EXPT
;;                   (COS
;;                    (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115)))
;;                       10667894506))
;;                   2))))))))
;;       :ANGULAR-VELOCITIES-BEFORE ((AMES-SCENARIO::ROD (- (/ (* 1476 (SQRT 19) (SQRT 115)) 6481))))
;;       :ANGULAR-VELOCITIES-AFTER
;;       ((AMES-SCENARIO::ROD
;;         (/
;;          (-
;;           (+
;;            (* 10943271502533
;;               (COS
;;                (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506)))
;;            (* 98101241856 (SQRT 19) (SQRT 115)
;;               (EXPT
;;                (COS
;;                 (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;                2)))
;;           (* 65400827904 (SQRT 19) (SQRT 115)))
;;          (+ 287169895424
;;             (* 861509686272
;;                (EXPT
;;                 (COS
;;                  (/ (- (* 10667894506 (ATAN 9/40)) (* 291199741 (SQRT 19) (SQRT 115))) 10667894506))
;;                 2)))))))
;;      :ENERGY
;;      ((:KINETIC AMES-SCENARIO::ROD
;;        (/
;;         (+ 41421797943 (* 7082579382 (SQRT 19) (SQRT 115) AMES.BASE:TAU)
;;            (* 666593339070 (EXPT AMES.BASE:TAU 2)))
;;         6720537760))
;;       (:KINETIC (:ROTATION AMES-SCENARIO::ROD) 297511785/42003361)
;;       (:POTENTIAL (:GRAVITY AMES-SCENARIO::ROD)
;;        (-
;;         (/
;;          (- (+ (* 22402851 (SQRT 19) (SQRT 115) AMES.BASE:TAU) (* 2108496135 (EXPT AMES.BASE:TAU 2)))
;;             40247010)
;;          21257680))))
;;      :MOMENTUM
;;      ((:ANGULAR-MOMENTUM AMES-SCENARIO::ROD
;;        (/
;;         (-
;;          (+ (* 20256573 (SQRT 115))
;;             (* (- (* 183347490 (SQRT 19)) (* 247742706 (SQRT 115))) AMES.BASE:TAU)
;;             (* 797163 (EXPT 115 3/2) (EXPT AMES.BASE:TAU 2)))
;;          (* 290542647 (SQRT 19)))
;;         (* (SQRT 115) 42515360)))
;;       (:MOMENTUM AMES-SCENARIO::ROD
;;        (-3/8 (- (/ (+ (* 23757 (SQRT 19) (SQRT 115)) (* 4471890 AMES.BASE:TAU)) 259240)))))))
;;    :OUTCOME :STOPPED :ANSWERS NIL :SELF-CHECK
;;    (:CHECKED (0 1) :UNCHECKED NIL :NUMBERS (0 0) :EQUATIONS (30 30) :FAILURES NIL))

;; witness's answer:
;;   (:STATUS :OK :SCHEME :MOREAU-JEAN :STEP 6.25d-5 :COLLISION-SPEED 0.05d0 :EVENTS
;;    ((:TIME 0.4065625d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.23617987804869706d0 0.10961316006099123d0))) :VELOCITIES
;;      (("rod" (-0.25d0 -4.67474999999983d0))) :ANGLES (("rod" 0.2213144423477913d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.4065625d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.23616425304869706d0 0.10943381810639151d0))) :VELOCITIES
;;      (("rod" (-0.25d0 -2.8565225466747917d0))) :ANGLES (("rod" 0.220653818515523d0))
;;      :ANGULAR-VELOCITIES (("rod" -10.64748997068315d0)) :HINGES NIL)
;;     (:TIME 0.494375d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.21422675304869956d0 -0.18550139473932079d0))) :VELOCITIES
;;      (("rod" (-0.25d0 -3.8656475466747766d0))) :ANGLES (("rod" -0.7136634264119296d0))
;;      :ANGULAR-VELOCITIES (("rod" -10.64748997068315d0)) :HINGES NIL)
;;     (:TIME 0.494375d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.21421213732476135d0 -0.18574185450779093d0))) :VELOCITIES
;;      (("rod" (-0.21547478987388527d0 -3.826495107344529d0))) :ANGLES (("rod" -0.7143341376109631d0))
;;      :ANGULAR-VELOCITIES (("rod" -10.826841371432806d0)) :HINGES NIL)
;;     (:TIME 0.5263511063578165d0 :PAIRS ((:TURNS "rod" "rod")) :POSITIONS
;;      (("rod" (0.20732209252632416d0 -0.3138158295508303d0))) :VELOCITIES
;;      (("rod" (-0.21547478987388527d0 -0.5023580437418835d0))) :ANGLES (("rod" -1.0600603262212591d0))
;;      :ANGULAR-VELOCITIES (("rod" 0.0d0)) :HINGES NIL)
;;     (:TIME 0.526375d0 :PAIRS ((:COLLISION "rod" "floor")) :POSITIONS
;;      (("rod" (0.20733041122316248d0 -0.31381556445954384d0))) :VELOCITIES
;;      (("rod" (-0.21547478987388527d0 -4.1937763573445475d0))) :ANGLES (("rod" -1.060116383911099d0))
;;      :ANGULAR-VELOCITIES (("rod" -10.826841371432806d0)) :HINGES NIL)
;;     (:TIME 0.526375d0 :PAIRS ((:LIFT-OFF "rod" "floor")) :POSITIONS
;;      (("rod" (0.20731694404879536d0 -0.31381599361697654d0))) :VELOCITIES
;;      (("rod" (-0.21547478987388527d0 1.7822767501967327d0))) :ANGLES (("rod" -1.0600256318740475d0))
;;      :ANGULAR-VELOCITIES (("rod" 6.700779051369235d0)) :HINGES NIL)
;;     (:TIME 0.5424375d0 :PAIRS ((:COLLISION "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20386934741081236d0 -0.2867715656138288d0))) :VELOCITIES
;;      (("rod" (-0.21547478987388527d0 1.598276750196728d0))) :ANGLES (("rod" -0.9528131670521441d0))
;;      :ANGULAR-VELOCITIES (("rod" 6.700779051369235d0)) :HINGES NIL)
;;     (:TIME 0.5424375d0 :PAIRS ((:LIFT-OFF "rod" "ledge")) :POSITIONS
;;      (("rod" (0.20388549202606832d0 -0.2866506435392028d0))) :VELOCITIES
;;      (("rod" (0.5752213038060907d0 2.15963904502233d0))) :ANGLES (("rod" -0.9525477666283058d0))
;;      :ANGULAR-VELOCITIES (("rod" 2.6046960212500947d0)) :HINGES NIL))
;;    :END
;;    (:TIME 0.5463125d0 :POSITIONS (("rod" (0.20611447457831739d0 -0.2783683820834912d0))) :VELOCITIES
;;     (("rod" (0.5752213038060907d0 2.11507654502234d0))) :ANGLES (("rod" -0.9424545695459603d0))
;;     :ANGULAR-VELOCITIES (("rod" 2.6046960212500947d0)) :HINGES NIL))
