;;;; t/wound-rope-slack.lisp -- a rope wound on a turning disc going slack and taut again
;;;; (issue 23): the Atwood machine over a massive pulley after its heavier mass lands.
;;;;
;;;; Expected results (textbook; scenarios/atwood-massive-pulley.lisp's header), with
;;;; K = I + (m1 + m2) R^2 and v = R sqrt(2 (m1 - m2) g h / K) the landing speed:
;;;;   after the landing m2 and the pulley turn on together, the heavy side's rope slack:
;;;;     m2's acceleration -m2 g R^2 / (I + m2 R^2), the right rope's tension
;;;;     m2 I g / (I + m2 R^2), the left one's 0; m2 stops after v / a;
;;;;   m2's highest point 3 h / 2 + (m1 - m2) h (I + m2 R^2) / (m2 K) below top or not is
;;;;     the run's branch;
;;;;   the slack rope taut again (m2 back at 3 h / 2, falling at v): a plastic jerk, the
;;;;     angular momentum about the axle kept: m1 rises at v (I + m2 R^2) / K, the energy
;;;;     lost m1 (m1 - m2) (I + m2 R^2) R^2 g h / K^2.
;;;; The formulas are compared by Maxima-checked equivalence over the parameters; the
;;;; continuation is the branch the scenario's values select.

(in-package #:ames.tests)

(def-suite wound-rope-slack :in all-tests
  :description "A wound rope going slack and taut again: the massive-pulley Atwood machine after its landing.")

(in-suite wound-rope-slack)

(defun massive-atwood-rebound-expectations (x)
  "The textbook results after the landing, a plist over the scenario's parameters (X maps
this file's symbols to them)."
  (let* ((k '(+ i (* (+ m1 m2) (expt big-r 2))))
         (v `(* big-r (sqrt (/ (* 2 (- m1 m2) g h) ,k))))
         (a '(/ (* m2 g (expt big-r 2)) (+ i (* m2 (expt big-r 2))))))
    (list :a (funcall x `(- ,a))
          :tension (funcall x '(/ (* m2 i g) (+ i (* m2 (expt big-r 2)))))
          :rise-time (funcall x `(/ ,v ,a))
          :apex (funcall x `(+ (/ (* 3 h) 2)
                               (/ (* (- m1 m2) h (+ i (* m2 (expt big-r 2)))) (* m2 ,k))))
          :lifted (funcall x `(/ (* ,v (+ i (* m2 (expt big-r 2)))) ,k))
          :lost (funcall x `(/ (* m1 (- m1 m2) (+ i (* m2 (expt big-r 2))) (expt big-r 2) g h)
                               (expt ,k 2))))))

(defun check-apex-fork (bridge scenario fork apex)
  "Check that the FORK of SCENARIO's run branches on a readable fact whose boundary is
m2's highest point APEX at the pulley: the difference of its sides vanishes at top =
APEX and is linear in top (the gap to the pulley's rim is a square, its square-free
part read)."
  (let ((top (in-scenario-terms scenario 'top)))
    (dolist (branch (ames::state-branches fork))
      (let ((fact (getf branch :assume)))
        (is (member (first fact) '(< > <= >= =)) "a readable fact, not ~S" fact)
        (when (member (first fact) '(< > <= >=))
          (let ((difference `(- ,(second fact) ,(third fact))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "the fact's boundary is m2's highest point at the pulley"
                        (subst apex top difference) 0)
               (is (free-of-p top (ames.geometry:differentiate difference top))
                   "the fact is linear in top: ~S" fact)))))))))

(test massive-pulley-rope-slack-and-taut-again
  "After the landing the run branches on whether m2 climbs to the pulley (CHECK-APEX-FORK).
Under the scenario's values (m2 stops below the pulley): m2 and the pulley slow down
together on the taut right rope, the left one slack; they turn back; the left rope is
jerked taut when the pulley is back at its angle of the landing, lifting m1 with the
angular momentum about the axle kept (formulas Maxima-checked)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "atwood-massive-pulley"))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (fork (second (ames::history-states history)))
           (branch (find-if (lambda (b) (getf b :selected)) (and fork (ames::state-branches fork))))
           (states (getf branch :states))
           (expected (massive-atwood-rebound-expectations
                      (lambda (form) (in-scenario-terms scenario form)))))
      (is (not (null fork)))
      (when fork (check-apex-fork bridge scenario fork (getf expected :apex)))
      (is (= 2 (length states)) "the selected branch's states: ~S" states)
      (when (= 2 (length states))
        (destructuring-bind (rising falling) states
          (is (equal '(:turns "PULLEY") (event-names (ames::state-end-event rising))))
          (is (equal '(:tightens "LEFT") (event-names (ames::state-end-event falling)))
              "the slack rope is taut again: ~S" (ames::state-end-event falling))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (ames.maxima:with-assumptions (bridge (list (getf branch :assume)))
               (dolist (state states)
                 (is-same bridge "m2 slowed by its weight alone"
                          (second (per-body (ames::state-accelerations state) "LIGHT"))
                          (getf expected :a))
                 (is-same bridge "the right rope's tension"
                          (car (last (force-entry state :tension "RIGHT"))) (getf expected :tension))
                 (is-same bridge "the left rope slack" (car (last (force-entry state :tension "LEFT"))) 0))
               (is-same bridge "m2 stops after v / a" (ames::state-duration rising)
                        (getf expected :rise-time))
               (is-same bridge "and falls as long back to the landing's angle"
                        (ames::state-duration falling) (getf expected :rise-time))
               (let ((impact (ames::state-impact falling)))
                 (is (not (null impact)))
                 (when impact
                   (is-same bridge "the jerk lifts m1"
                            (second (per-body (getf impact :velocities-after) "HEAVY"))
                            (getf expected :lifted))
                   (is-same bridge "m2 slowed to the same speed"
                            (second (per-body (getf impact :velocities-after) "LIGHT"))
                            `(- ,(getf expected :lifted)))
                   (is-same bridge "energy lost in the jerk" (getf impact :energy-lost)
                            (getf expected :lost))))))))))))
