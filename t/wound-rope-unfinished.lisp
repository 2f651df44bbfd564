;;;; t/wound-rope-unfinished.lisp -- a branch the knowledge base stops keeps the states it
;;;; finished (issue 23): the massive-pulley Atwood machine whose lighter mass climbs to the
;;;; pulley after the heavier one lands.
;;;;
;;;; Expected results (textbook; scenarios/atwood-massive-pulley.lisp's header), with
;;;; K = I + (m1 + m2) R^2, v = R sqrt(2 (m1 - m2) g h / K) the landing speed and
;;;; a = m2 g R^2 / (I + m2 R^2) m2's deceleration after the landing: with the pulley
;;;; below m2's highest point (top = 11/5 under the scenario's other values, the apex
;;;; 2.3), m2 and the pulley turn on together on the taut right rope (tension
;;;; m2 I g / (I + m2 R^2), the left rope slack) until m2 reaches the pulley's rim at the
;;;; rope's tangent point (R, top), at the speed sqrt(v^2 - 2 a (top - 3 h / 2)), after
;;;; (v - that speed) / a. What follows (m2 carried round the rim, its rope wound in to
;;;; nothing) is not modelled: the branch ends failed, its first state kept, and the run
;;;; does not exit 0.
;;;; Also here: past the jerk that takes up the slack rope (the values' branch, a fourth
;;;; state) m1 rises at v' = v (I + m2 R^2) / K slowed by a0 = (m1 - m2) g R^2 / K to
;;;; h (I + m2 R^2)^2 / K^2; and the witness (Siconos) turns the pulley back with the left
;;;; rope slack, taut again only at the landing's angle, after sqrt(2 h / a0) + 2 v / a.

(in-package #:ames.tests)

(def-suite wound-rope-unfinished :in all-tests
  :description "A branch stopped by a refusal keeps its finished states: m2 rising to the massive pulley.")

(in-suite wound-rope-unfinished)

(defun massive-atwood-climb-expectations (x)
  "The textbook results of m2's climb to the pulley after the landing, a plist over the
scenario's parameters (X maps this file's symbols to them)."
  (let* ((k '(+ i (* (+ m1 m2) (expt big-r 2))))
         (v `(* big-r (sqrt (/ (* 2 (- m1 m2) g h) ,k))))
         (a '(/ (* m2 g (expt big-r 2)) (+ i (* m2 (expt big-r 2)))))
         (arrival `(sqrt (- (expt ,v 2) (* 2 ,a (- top (/ (* 3 h) 2)))))))
    (list :a (funcall x `(- ,a))
          :tension (funcall x '(/ (* m2 i g) (+ i (* m2 (expt big-r 2)))))
          :arrival (funcall x arrival)
          :duration (funcall x `(/ (- ,v ,arrival) ,a)))))

(test massive-pulley-m2-climbs-to-the-pulley
  "Under values that put the pulley below m2's highest point the selected branch is
stopped by a refusal past m2's arrival at the rim; it keeps its finished state, whose
formulas are the textbook's (Maxima-checked), and the run is not complete."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "atwood-massive-pulley"))
           (history (ames:run-scenario scenario :bridge bridge :numeric t
                                                :settings '(("top" . 11/5))))
           (fork (second (ames::history-states history)))
           (branch (find-if (lambda (b) (getf b :selected)) (and fork (ames::state-branches fork))))
           (states (getf branch :states))
           (expected (massive-atwood-climb-expectations
                      (lambda (form) (in-scenario-terms scenario form)))))
      (is (not (null branch)) "the values select a branch")
      (is (eq :failed (getf branch :outcome)) "the branch stops at a refusal: ~S" (getf branch :outcome))
      (is (stringp (getf branch :failure)) "and says why")
      (is (not (eq :complete (ames::history-outcome history))))
      (is (= 1 (length states)) "the finished state is kept: ~S" states)
      (when (= 1 (length states))
        (let ((climb (first states)))
          (is (eql 0 (search '(:contact "LIGHT" "PULLEY")
                             (event-names (ames::state-end-event climb)) :test #'equal))
              "m2 reaches the pulley: ~S" (ames::state-end-event climb))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (ames.maxima:with-assumptions (bridge (list (getf branch :assume)))
               (is-same bridge "m2 slowed by its weight alone"
                        (second (per-body (ames::state-accelerations climb) "LIGHT"))
                        (getf expected :a))
               (is-same bridge "the right rope's tension"
                        (car (last (force-entry climb :tension "RIGHT"))) (getf expected :tension))
               (is-same bridge "the left rope slack" (car (last (force-entry climb :tension "LEFT"))) 0)
               (is-same bridge "m2 reaches the rim after (v - v_top) / a"
                        (ames::state-duration climb) (getf expected :duration))
               (is-same bridge "at the rope's tangent point"
                        (second (per-body (ames.simulator::state-final-positions climb) "LIGHT"))
                        (in-scenario-terms scenario 'top))
               (is-same bridge "at the speed v^2 - 2 a (top - 3 h / 2) gives"
                        (second (per-body (ames.simulator::state-final-velocities climb) "LIGHT"))
                        (getf expected :arrival))))))))))

(test massive-pulley-m1-lifted-after-the-jerk
  "Past the jerk that takes up the slack left rope (the fourth state, the values'
branch): both ropes taut again, m1 rises from the floor at v' = v (I + m2 R^2) / K
slowed by a = (m1 - m2) g R^2 / K, the tensions the first state's, and stops after v'/a
at h (I + m2 R^2)^2 / K^2 (v'^2 / (2 a)); formulas Maxima-checked."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named-with-states "atwood-massive-pulley" 4))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (fork (second (ames::history-states history)))
           (branch (find-if (lambda (b) (getf b :selected)) (and fork (ames::state-branches fork))))
           (lifted (third (getf branch :states))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (let* ((k '(+ i (* (+ m1 m2) (expt big-r 2))))
               (a (x `(/ (* (- m1 m2) g (expt big-r 2)) ,k)))
               (speed (x `(/ (* big-r (sqrt (/ (* 2 (- m1 m2) g h) ,k)) (+ i (* m2 (expt big-r 2)))) ,k))))
          (is (not (null lifted)) "the branch's third state: ~S" (getf branch :states))
          (when lifted
            (is (equal '(:turns "PULLEY") (event-names (ames::state-end-event lifted))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (ames.maxima:with-assumptions (bridge (list (getf branch :assume)))
                 (is-same bridge "m1 slowed as in the first state"
                          (second (per-body (ames::state-accelerations lifted) "HEAVY")) `(- ,a))
                 (is-same bridge "the left rope's tension m1 (I + 2 m2 R^2) g / K"
                          (car (last (force-entry lifted :tension "LEFT")))
                          (x `(/ (* m1 (+ i (* 2 m2 (expt big-r 2))) g) ,k)))
                 (is-same bridge "the right rope's tension m2 (I + 2 m1 R^2) g / K"
                          (car (last (force-entry lifted :tension "RIGHT")))
                          (x `(/ (* m2 (+ i (* 2 m1 (expt big-r 2))) g) ,k)))
                 (is-same bridge "m1 stops after v' / a" (ames::state-duration lifted) `(/ ,speed ,a))
                 (is-same bridge "at h (I + m2 R^2)^2 / K^2"
                          (second (per-body (ames.simulator::state-final-positions lifted) "HEAVY"))
                          (x `(/ (* h (expt (+ i (* m2 (expt big-r 2))) 2)) (expt ,k 2)))))))))))))

(test witness-massive-pulley-turns-back-slack
  "The witness (Siconos) past the landing: m2 and the pulley turn on together, the left
rope slack, and turn back; the left rope is taut again (:tightens) only when the pulley
is back at its angle of the landing, at t = sqrt(2 h / a0) + 2 v / a1 (a0 = (m1 - m2) g
R^2 / K, v = a0 sqrt(2 h / a0), a1 = m2 g R^2 / (I + m2 R^2)), m2 falling at v there.
Once, a slack rope's stale output kept it active in Moreau-Jean's index set and the
pulley was jerked as soon as it turned back."
  (with-siconos
    (multiple-value-bind (answer values) (rotation-witness "atwood-massive-pulley" 1.9d0)
      (flet ((v (name) (value-of-parameter values name)))
        (let* ((g (v "g")) (m1 (v "m1")) (m2 (v "m2")) (i (v "i")) (r (v "big-r")) (h (v "h"))
               (k (+ i (* (+ m1 m2) r r)))
               (a0 (/ (* (- m1 m2) g r r) k))
               (landing (sqrt (/ (* 2 h) a0)))
               (speed (* a0 landing))
               (a1 (/ (* m2 g r r) (+ i (* m2 r r))))
               (jerk (find-if (lambda (e)
                                (and (> (getf e :time) (+ landing 0.01d0))
                                     (find :tightens (getf e :pairs) :key #'first)))
                              (ames.witness:witness-events answer))))
          (is (eq :ok (ames.witness:witness-status answer)))
          (is (not (null jerk)) "the left rope taut again: ~S" (ames.witness:witness-events answer))
          (when jerk
            (is (relatively-near (+ landing (/ (* 2 speed) a1)) (getf jerk :time) 5d-3)
                "at ~F, expected ~F" (getf jerk :time) (+ landing (/ (* 2 speed) a1)))
            (is (relatively-near (* 3/2 h) (second (state-entry jerk :positions "light")) 1d-2))
            (is (relatively-near (- speed) (second (state-entry jerk :velocities "light")) 1d-2))))))))
