;;;; t/simulator-more-scenarios.lisp -- simulator tests for what first failed: the sphere, the incline,
;;;; the corner with the push's side assumed, and the cases the fuzz found (a collision at
;;;; once, leaving a face along its own line, parameter values keyed by strings).
;;;; Expected results are the scenario files' headers; helpers are in
;;;; t/simulator-scenarios.lisp.

(in-package #:ames.tests)

(in-suite simulator)

;;; The particle on a sphere (thesis 2.6.3)

(test sphere-lift-off-then-free-fall
  "The particle slides on the sphere until cos theta = (2/3) cos theta0, where it
lifts off at (r sin theta1, r cos theta1) with v^2 = (2/3) g r cos theta0 along the
tangent; the time is an incomplete elliptic integral of the first kind, 0.90711 s with
the defaults (g = 9.81, r = 1, theta0 = 0.1: an independent integration of the ODE gives
0.9071); then it falls freely, (0, -g), forever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-on-sphere"))
           (values (ames:scenario-parameter-values scenario))
           (history (simulate-stopping-when-ambiguous scenario bridge :parameter-values values))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (= 2 (length states)))
        (is (eq :complete (ames::history-outcome history)))
        (check-rederived history)
        (destructuring-bind (&optional slide flight) states
          (when (and slide flight)
            (is (equal '(("PARTICLE" "SPHERE")) (contact-pairs slide)))
            (is (equal '(:lift-off "PARTICLE" "SPHERE") (event-names (ames::state-end-event slide))))
            (let ((duration (ames::state-duration slide)))
              (is (not (and (consp duration) (keywordp (first duration)))) "a closed form: ~S" duration)
              (is (mentions-name-p "ELLIPTIC-F" duration) "an elliptic integral: ~S" duration))
            (let ((numeric (getf (ames.simulator:state-numbers slide) :duration)))
              (is (and (realp numeric) (< (abs (- numeric 0.90711d0)) 1d-4)) "numeric duration ~S" numeric))
            (is (null (ames::state-contacts flight)))
            (is (eq :forever (ames::state-duration flight)))
            (is (eq :none (ames::state-end-event flight)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((position (per-body (ames::state-final-positions slide) "PARTICLE"))
                     (velocity (per-body (ames::state-final-velocities slide) "PARTICLE")))
                 (is-same-vector bridge "lift-off point" position
                                 (x '((* r (sqrt (- 1 (* 4/9 (expt (cos theta0) 2)))))
                                      (* 2/3 r (cos theta0)))))
                 (when (and (consp position) (consp velocity))
                   (is-same bridge "v^2 at lift-off"
                            `(+ (expt ,(first velocity) 2) (expt ,(second velocity) 2))
                            (x '(* 2/3 g r (cos theta0))))
                   (is-same bridge "moving along the tangent"
                            `(+ (* ,(first position) ,(first velocity))
                                (* ,(second position) ,(second velocity)))
                            0)))
               (is-same-vector bridge "free fall"
                               (per-body (ames::state-accelerations flight) "PARTICLE")
                               (x '(0 (- g))))))))))))

;;; A block on an incline

(test incline-slides-to-the-foot-then-falls
  "The block slides with acceleration (g sin a cos a, -g sin^2 a) under N = m g cos a,
leaves the incline's end at t1 = sqrt((h/sin a + b)/(g sin a)) with speed g sin a t1
downhill, then falls freely forever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "block-on-incline"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (= 2 (length states)))
        (is (eq :complete (ames::history-outcome history)))
        (check-rederived history)
        (destructuring-bind (&optional slide fall) states
          (when (and slide fall)
            (is (equal '(("BLOCK" "INCLINE")) (contact-pairs slide)))
            (is (equal '(:leaves "BLOCK" "INCLINE" :endpoint)
                       (event-names (ames::state-end-event slide))))
            (is (null (ames::state-contacts fall)))
            (is (eq :forever (ames::state-duration fall)))
            (is (eq :none (ames::state-end-event fall)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((t1 (x '(sqrt (/ (+ (/ h (sin a)) b) (* g (sin a)))))))
                 (is-same-vector bridge "acceleration down the slope"
                                 (per-body (ames::state-accelerations slide) "BLOCK")
                                 (x '((* g (sin a) (cos a)) (- (* g (expt (sin a) 2))))))
                 (is-same bridge "N" (normal-force-between slide "BLOCK" "INCLINE")
                          (x '(* m g (cos a))))
                 (is-same bridge "t1" (ames::state-duration slide) t1)
                 (is-same-vector bridge "velocity at the end"
                                 (per-body (ames::state-final-velocities slide) "BLOCK")
                                 (x `((* g (sin a) ,t1 (cos a)) (- (* g (sin a) ,t1 (sin a))))))
                 (is-same-vector bridge "free fall"
                                 (per-body (ames::state-accelerations fall) "BLOCK")
                                 (x '(0 (- g)))))))))))))

;;; Two blocks in a corner, with the push's side of the threshold assumed

(defun corner-with-push-assumed (relation)
  "The two-blocks-in-corner form with f's assumption RELATION (> or <) against
mb g (l1 - l2)/l3 added (f declared last, after the lengths), run for one state."
  (let* ((form (first (ames:read-scenario-forms
                       (uiop:read-file-string
                        (find "two-blocks-in-corner" (scenario-files)
                              :key #'pathname-name :test #'string=)))))
         (scenario (ames:parse-scenario form))
         (f (in-scenario-terms scenario 'f))
         (threshold (in-scenario-terms scenario '(/ (* mb g (- l1 l2)) l3))))
    (mapcar (lambda (clause)
              (cond ((and (consp clause) (same-name-p* (first clause) "PARAMETERS"))
                     (append (remove-if (lambda (spec) (and (consp spec) (eq (first spec) f)))
                                        clause)
                             (list (list f :positive (list relation f threshold)))))
                    ((and (consp clause) (same-name-p* (first clause) "SIMULATE"))
                     (list (first clause) :states 1))
                    (t clause)))
            form)))

(test corner-block-b-rises-or-falls
  "With f > mb g (l1 - l2)/l3 assumed B rises, and B's corner reaches the upper end of
A's face at t1 = sqrt(l3 / a_Ax); with f < mb g (l1 - l2)/l3 it falls and reaches the
lower end at t1 = sqrt(-l3 / a_Ax), A then moving away from the wall. Either way the
contact between the blocks ends."
  (with-fixture simulator-bridge ()
    (dolist (relation '(> <))
      (let* ((form (corner-with-push-assumed relation))
             (scenario (ames:parse-scenario form))
             (history (simulate-stopping-when-ambiguous scenario bridge))
             (state (first (ames::history-states history))))
        (flet ((x (expression) (in-scenario-terms scenario expression)))
          (is (eq :state-limit (ames::history-outcome history))
              "~A: outcome ~S" relation (ames::history-outcome history))
          (is (not (null state)))
          (when state
            (let ((event (event-names (ames::state-end-event state)))
                  (a-ax (x '(/ (* l3 (- (* f l3) (* mb g (- l1 l2))))
                             (+ (* ma (expt l3 2)) (* mb (expt (- l1 l2) 2)))))))
              (is (and (consp event) (eq :leaves (first event))
                       (set-equal-p '("BLOCK-A" "BLOCK-B") (subseq event 1 3)))
                  "~A: end event ~S" relation event)
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "a_Ax" (first (per-body (ames::state-accelerations state) "BLOCK-A"))
                          a-ax)
                 (is-same bridge "t1" (ames::state-duration state)
                          (if (eq relation '>)
                              `(sqrt (/ ,(x 'l3) ,a-ax))
                              `(sqrt (- (/ ,(x 'l3) ,a-ax)))))
                 ;; A's speed at the end is a_Ax t1 = +-sqrt(+-l3 a_Ax): toward the wall
                 ;; when B rises, away from it when B falls
                 (is-same bridge "A's final velocity"
                          (first (per-body (ames::state-final-velocities state) "BLOCK-A"))
                          (if (eq relation '>)
                              `(sqrt (* ,(x 'l3) ,a-ax))
                              `(- (sqrt (- (* ,(x 'l3) ,a-ax)))))))))))))))

;;; Found while fuzzing (see the lead's report)

(defparameter *into-the-ground*
  '(scenario into-the-ground "A particle on the ground, moving down into it."
    (parameters (m :positive) (g :positive) (v :positive))
    (gravity g)
    (body ground :fixed t :shape (half-plane (1 0) (0 0)))
    (body particle :mass m :position (0 0) :velocity (0 (- v)) :shape point)
    (simulate :states 2))
  "A body that starts touching another and moving into it: today it passes through
(no contact, free fall forever).")

(test touching-and-approaching-is-a-collision-at-once
  "A particle that starts on the ground moving down into it collides at once: state 0
lasts 0 and ends in (:collision particle ground); the plastic impact stops it, and it
rests on the ground."
  (with-fixture simulator-bridge ()
    (let* ((history (simulate-stopping-when-ambiguous *into-the-ground* bridge))
           (state (first (ames::history-states history))))
      (is (eq :complete (ames::history-outcome history)))
      (is (not (null state)))
      (when state
        (is (equal '(:collision "PARTICLE" "GROUND") (event-names (ames::state-end-event state))))
        (is (eql 0 (ames::state-duration state)))
        (let ((rest (second (ames::history-states history))))
          (is (not (null rest)))
          (when rest
            (is (equal '(("PARTICLE" "GROUND")) (contact-pairs rest)))
            (is (equal '(0 0) (per-body (ames:state-initial-velocities rest) "PARTICLE")))))))))

(defparameter *down-a-wall*
  '(scenario down-a-wall "A particle slides down a frictionless vertical face and falls."
    (parameters (m :positive) (g :positive) (h :positive))
    (gravity g)
    (body block :fixed t :shape (polygon (0 0) (1 0) (1 h) (0 h)))
    (body particle :mass m :position (0 (/ h 2)) :velocity (0 0) :shape point)
    (simulate :states 3))
  "A particle that leaves the end of a face moving along the face's own line: today the
next state stops on the missing fact (:earliest-root-of (= 0 0) :candidates nil).")

(test leaving-a-face-along-its-line-is-free-fall
  "The particle slides down the block's left face (N = 0) for sqrt(h/g), leaves it at
the bottom vertex, then falls freely forever: its gap to the face's line stays 0, which
is no meeting and no ambiguity."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *down-a-wall*))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (when (= 2 (length states))
          (destructuring-bind (slide fall) states
            (is (equal '(:leaves "PARTICLE" "BLOCK" :endpoint)
                       (event-names (ames::state-end-event slide))))
            (is (eq :forever (ames::state-duration fall)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "t1" (ames::state-duration slide) (x '(sqrt (/ h g))))
               (is-same-vector bridge "free fall" (per-body (ames::state-accelerations fall) "PARTICLE")
                               (x '(0 (- g))))))))))))

(test parameter-values-by-name
  "Parameter values may be keyed by names (strings), as the command line's --set gives
them (AMES::RESOLVE-PARAMETER-VALUES's contract); today FIND-SCENARIO-PARAMETER signals
a TYPE-ERROR on a string."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "projectile-off-table"))
           (history (ames::simulate scenario :bridge bridge
                                             :parameter-values '(("g" . 10) ("h" . 5) ("d" . 1) ("v0" . 2))))
           (flight (second (ames::history-states history)))
           (landing (per-body (getf (ames.simulator:state-numbers flight) :final-positions)
                              "PARTICLE")))
      ;; t2 = sqrt(2h/g) = 1, so the particle lands at x = v0 = 2
      (is (and (realp (first landing)) (< (abs (- (first landing) 2)) 1d-9)) "landing at ~S" landing))))
