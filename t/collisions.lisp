;;;; t/collisions.lisp -- impacts (thesis 3.3.2, "Collisions"): impulses along the contact
;;;; normals, Newton's restitution law, momentum conserved, the run going on after the
;;;; impact, and a geometric series of impacts summed.
;;;;
;;;; Every expected result is the textbook's, over the scenario's own parameters, compared by
;;;; Maxima-checked equivalence.

(in-package #:ames.tests)

(in-suite simulator)

(defun with-restitution (scenario-name e)
  "The form of scenarios/SCENARIO-NAME.lisp with its parameter E replaced by the number
E everywhere (its declaration dropped)."
  (let* ((form (first (ames:read-scenario-forms
                       (uiop:read-file-string
                        (find scenario-name (scenario-files) :key #'pathname-name :test #'string=)))))
         (parameter (find-if (lambda (x) (and (symbolp x) (string= (symbol-name x) "E")))
                             (alexandria:flatten form))))
    (labels ((walk (x)
               (cond ((eq x parameter) e)
                     ((atom x) x)
                     (t (mapcar #'walk x)))))
      (mapcar (lambda (clause)
                (if (and (consp clause) (same-name-p* (first clause) "PARAMETERS"))
                    (remove-if (lambda (spec) (and (consp spec) (eq (first spec) parameter))) clause)
                    (walk clause)))
              form))))

(defun impact-of (state)
  "The impact that ended STATE, as the simulator records it in its notes."
  (ames.simulator:state-impact state))

(test head-on-impacts-with-restitution
  "Block A (mass ma, speed v) hits block B (mass mb, at rest) on a frictionless floor:
just after, A moves at (ma - e mb) v / (ma + mb) and B at (1 + e) ma v / (ma + mb), the
impulse is (1 + e) ma mb v / (ma + mb) and the energy lost (1 - e^2) ma mb v^2 / (2 (ma +
mb)); with e = 0 they go on together in contact, with e > 0 they separate."
  (with-fixture simulator-bridge ()
    (dolist (e '(1 0 1/2))
      (let* ((form (with-restitution "blocks-colliding" e))
             (scenario (ames:parse-scenario form))
             (history (simulate-stopping-when-ambiguous scenario bridge))
             (states (ames::history-states history)))
        (flet ((x (expression) (in-scenario-terms scenario expression)))
          (is (eq :complete (ames::history-outcome history)) "e = ~A: ~S" e (ames::history-outcome history))
          (is (= 2 (length states)) "e = ~A: ~D states" e (length states))
          (destructuring-bind (&optional before after) states
            (when (and before after)
              (let ((event (ames::state-end-event before)))
                (is (equal '(:collision "BLOCK-A" "BLOCK-B") (event-names (subseq event 0 3))))
                (call-with-scenario-facts
                 bridge scenario
                 (lambda ()
                   (is-same bridge "time to the impact" (ames::state-duration before) (x '(/ d v)))
                   (is-same bridge "impulse" (getf (cdddr event) :impulse)
                            (x `(/ (* (+ 1 ,e) ma mb v) (+ ma mb))))
                   (is-same bridge "energy lost" (getf (cdddr event) :energy-lost)
                            (x `(/ (* (- 1 (expt ,e 2)) ma mb (expt v 2)) (* 2 (+ ma mb)))))
                   (is-same-vector bridge "A just after"
                                   (per-body (ames:state-initial-velocities after) "BLOCK-A")
                                   (x `((/ (* (- ma (* ,e mb)) v) (+ ma mb)) 0)))
                   (is-same-vector bridge "B just after"
                                   (per-body (ames:state-initial-velocities after) "BLOCK-B")
                                   (x `((/ (* (+ 1 ,e) ma v) (+ ma mb)) 0))))))
              (is (eq (zerop e)
                      (and (member '("BLOCK-A" "BLOCK-B") (contact-pairs after) :test #'equal) t))
                  "e = ~A: contacts after ~S" e (contact-pairs after)))))))))

(test incline-foot-plastic-impact-then-sliding-on
  "A particle slides down a fixed incline from its top onto the ground (e = 0): the
ground takes the normal part of its velocity, and it slides on along the ground with
speed sqrt(2 g L sin a) cos a = sqrt(2 g h) cos a, forever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-at-incline-top"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (destructuring-bind (&optional slope ground) states
          (when (and slope ground)
            (is (equal '(("PARTICLE" "FLOOR")) (contact-pairs ground)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "velocity just after"
                               (per-body (ames:state-initial-velocities ground) "PARTICLE")
                               (x '((* (sqrt (* 2 g h)) (cos a)) 0)))
               (is-same bridge "energy lost: the normal part"
                            (getf (impact-of slope) :energy-lost)
                            (x '(* m g h (expt (sin a) 2))))
               (is-same bridge "N on the ground" (normal-force-between ground "PARTICLE" "FLOOR")
                        (x '(* m g)))
               (is (eq :forever (ames::state-duration ground)))))))))))

(test bouncing-ball-heights-and-accumulation
  "A ball dropped from h with e = 1/2 rises to h/4 after the first bounce and h/16 after
the second; the impacts come at times in a geometric series and accumulate at
sqrt(2 h / g) (1 + e) / (1 - e) = 3 sqrt(2 h / g), after which it rests on the floor
(N = m g) forever, instead of running out of states."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "bouncing-ball"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
        (let* ((accumulating (find-if (lambda (s) (ames.simulator:state-accumulation s)) states))
               (rest-state (car (last states))))
          (is (not (null accumulating)) "the repeating impacts are recognised")
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (flet ((rise (velocities)
                      (let ((v (second (per-body velocities "BALL"))))
                        (x `(/ (expt ,v 2) (* 2 g))))))
               (is-same bridge "first bounce" (rise (ames:state-initial-velocities (second states)))
                        (x '(/ h 4)))
               ;; the second impact (the one that shows the pattern) leaves at a quarter
               (is-same bridge "second bounce"
                        (rise (getf (impact-of (second states)) :velocities-after))
                        (x '(/ h 16))))
             (when accumulating
               (let ((accumulation (ames.simulator:state-accumulation accumulating)))
                 (is-same bridge "factor" (getf accumulation :factor) 1/2)
                 (is-same bridge "accumulation time" (getf accumulation :time)
                          (x '(* 3 (sqrt (/ (* 2 h) g)))))
                 (is-same bridge "the resting state starts then" (ames::state-start rest-state)
                          (x '(* 3 (sqrt (/ (* 2 h) g)))))))
             (is (equal '(("BALL" "FLOOR")) (contact-pairs rest-state)))
             (is-same bridge "resting" (normal-force-between rest-state "BALL" "FLOOR") (x '(* m g)))
             (is (eq :forever (ames::state-duration rest-state))))))))))

(test block-pushed-into-wall-stays-there
  "A block pushed by f along a frictionless floor reaches the wall with speed
sqrt(2 f d / m); the plastic impact stops it (the energy f d is lost), and it stays
against the wall, which pushes back with N = f."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "block-pushed-into-wall"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (destructuring-bind (&optional push against) states
          (when (and push against)
            (is (member '("BLOCK" "WALL") (contact-pairs against) :test #'equal))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "time to the wall" (ames::state-duration push) (x '(sqrt (/ (* 2 m d) f))))
               (is-same bridge "energy lost" (getf (impact-of push) :energy-lost) (x '(* f d)))
               (is-same-vector bridge "at rest after" (per-body (ames:state-initial-velocities against) "BLOCK")
                               '(0 0))
               (is-same bridge "the wall pushes back" (normal-force-between against "BLOCK" "WALL") (x 'f))
               (is (eq :forever (ames::state-duration against)))))))))))

(test projectile-lands-and-slides-on
  "The particle off the table lands on the floor (e = 0) after sqrt(2 h / g) of flight
and slides on with its horizontal velocity v0."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "projectile-off-table"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 3 (length states)))
        (let ((ground (third states)))
          (when ground
            (is (equal '(("PARTICLE" "FLOOR")) (contact-pairs ground)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "sliding on" (per-body (ames:state-initial-velocities ground) "PARTICLE")
                               (x '(v0 0)))
               (is-same bridge "lands then" (ames::state-start ground)
                        (x '(+ (/ d v0) (sqrt (/ (* 2 h) g)))))))))))))
