;;;; t/truth-scenarios.lisp -- the scenarios of issue 9 run to their end; values checked against assumptions; exit codes.
;;;;
;;;; Each scenario file's header states its textbook results; they are asserted here by
;;;; Maxima-checked equivalence under the scenario's assumptions (the helpers of
;;;; t/simulator-scenarios.lisp), or, where equivalence of nested radicals is beyond
;;;; Maxima's simplifiers, by equality of values at admissible numbers.

(in-package #:ames.tests)

(def-suite truth-scenarios :in all-tests
  :description "Textbook scenarios that once stopped on decidable facts (issue 9), the
parameter values of a run, and bin/ames's exit codes.")

(in-suite truth-scenarios)

(defun numerically-same-p (scenario actual expected values)
  "True when ACTUAL and EXPECTED (over SCENARIO's parameters) have values within 1e-9
(relative) of each other at VALUES, an alist (NAME-STRING . NUMBER)."
  (let ((bindings (loop for (name . value) in values
                        collect (cons (ames:scenario-parameter-name
                                       (ames:find-scenario-parameter (make-symbol name) scenario))
                                      value))))
    (let ((x (and actual (not (keywordp actual)) (expression-value actual bindings)))
          (y (expression-value expected bindings)))
      (and x y (<= (abs (- x y)) (* 1d-9 (max 1 (abs y))))))))

(defun selected-states (history)
  "HISTORY's states along the branches its values select: a fork (end event (:BRANCH))
is followed into its branch marked :SELECTED (or its only branch)."
  (labels ((walk (states)
             (loop for state in states
                   for branches = (ames::state-branches state)
                   append (if branches
                              (let ((branch (or (find-if (lambda (b) (getf b :selected)) branches)
                                                (and (null (rest branches)) (first branches)))))
                                (and branch (walk (getf branch :states))))
                              (list state)))))
    (walk (ames::history-states history))))

(defun finished-p (history)
  "True when HISTORY ran to its end: no ambiguous or undecided outcome anywhere that
counts (see AMES::UNDECIDED-HISTORY-P)."
  (not (ames::undecided-history-p history)))

(defun end-event-is (state kind &rest bodies)
  "Check that STATE ended with an event of KIND between BODIES (names, either order)."
  (let ((event (event-names (ames::state-end-event state))))
    (is (and (consp event) (eq kind (first event))
             (set-equal-p bodies (subseq event 1 (1+ (length bodies)))))
        "end event ~S, expected ~S ~S" event kind bodies)))

;;; The scenarios of the issue

(test disc-down-a-wedge-of-symbolic-angle
  "cos(pi/2 - a) > 0 is decided; the disc meets the ground before the foot of the slope."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "disc-down-wedge"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (expression) (in-scenario-terms scenario expression)))
        (is (finished-p history))
        (end-event-is state :collision "DISC" "GROUND")
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "t1" (ames::state-duration state)
                    (x '(sqrt (/ (* (+ h (* 2 r (cos a)) (* -2 r)) (+ mw (* m (expt (sin a) 2))))
                                 (* (+ m mw) g (expt (sin a) 2))))))
           (is-same-vector bridge "A_wedge" (per-body (ames::state-accelerations state) "WEDGE")
                           (x '((- (/ (* m g (sin a) (cos a)) (+ mw (* m (expt (sin a) 2))))) 0)))
           (is-same-vector bridge "A_disc" (per-body (ames::state-accelerations state) "DISC")
                           (x '((/ (* mw g (sin a) (cos a)) (+ mw (* m (expt (sin a) 2))))
                                (- (/ (* (+ mw m) g (expt (sin a) 2)) (+ mw (* m (expt (sin a) 2))))))))))))))

(test particle-off-a-raised-ramp
  "sqrt(2 h0 + l tan a)/(sin a sqrt g) <= sqrt(l)/(sqrt(cos a sin a) sqrt g) is false:
the particle leaves the ramp first, flies, and lands."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-off-raised-ramp"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (expression) (in-scenario-terms scenario expression)))
        (is (finished-p history))
        (is (<= 2 (length states)))
        (when (<= 2 (length states))
          (destructuring-bind (slide flight &rest after) states
            (declare (ignore after))
            (end-event-is slide :leaves "PARTICLE" "RAMP")
            (end-event-is flight :collision "PARTICLE" "FLOOR")
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "t1" (ames::state-duration slide)
                        (x '(sqrt (/ l (* g (sin a) (cos a))))))
               (is-same-vector bridge "A on the ramp" (per-body (ames::state-accelerations slide) "PARTICLE")
                               (x '((* g (sin a) (cos a)) (- (* g (expt (sin a) 2))))))
               (is-same-vector bridge "A in flight" (per-body (ames::state-accelerations flight) "PARTICLE")
                               (x '(0 (- g))))))
            ;; the flight's time and landing point, t2 = (sqrt(v^2 sin^2 a + 2 g h0) - v sin a)/g
            ;; with v = sqrt(g l tan a), checked at admissible numbers
            (let* ((v '(sqrt (* g l (tan a))))
                   (t2 (x `(/ (- (sqrt (+ (* (expt ,v 2) (expt (sin a) 2)) (* 2 g h0))) (* ,v (sin a))) g)))
                   (landing (x `(+ l (* ,v (cos a) ,t2)))))
              (dolist (values '((("M" . 1) ("G" . 981/100) ("H0" . 1) ("L" . 2) ("A" . 1/2))
                                (("M" . 3) ("G" . 2) ("H0" . 1/10) ("L" . 7) ("A" . 6/5))))
                (is (numerically-same-p scenario (ames::state-duration flight) t2 values)
                    "t2 at ~S" values)
                (is (numerically-same-p scenario
                                        (first (per-body (ames::state-final-positions flight) "PARTICLE"))
                                        landing values)
                    "landing point at ~S" values)))))))))

(test disc-at-thirty-degrees
  "2 sqrt(h + (sqrt 3 - 2) r)/sqrt g <= 2 sqrt(h)/sqrt g is shown: the disc meets the
floor before its contact point reaches the foot of the incline."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "disc-at-30-degrees"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (expression) (in-scenario-terms scenario expression)))
        (is (finished-p history))
        (end-event-is state :collision "DISC" "FLOOR")
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "t1" (ames::state-duration state)
                    (x '(/ (* 2 (sqrt (+ h (* (- (sqrt 3) 2) r)))) (sqrt g))))
           (is-same-vector bridge "A" (per-body (ames::state-accelerations state) "DISC")
                           (x '((/ (* (sqrt 3) g) 4) (- (/ g 4)))))
           (is-same bridge "N" (normal-force-between state "DISC" "INCLINE")
                    (x '(/ (* (sqrt 3) m g) 2)))))))))

(test thirty-drops-land-in-the-order-of-their-heights
  "With 30 names the chain h1 < ... < h30 is still used: p1 lands first, at sqrt(2 h1/g),
then p2, ..., then p30, each landing proved to come before the others."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "thirty-drops"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (expression) (in-scenario-terms scenario expression)))
        (is (finished-p history))
        (is (<= 30 (length states)))
        (loop for state in states
              for i from 1 to 30
              do (end-event-is state :collision (format nil "P~D" i) "FLOOR"))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "t1" (ames::state-duration (first states)) (x '(sqrt (/ (* 2 h1) g))))
           (when (<= 2 (length states))
             (is-same bridge "t2 - t1" (ames::state-duration (second states))
                      (x '(- (sqrt (/ (* 2 h2) g)) (sqrt (/ (* 2 h1) g))))))))))))

(test two-blocks-in-a-corner-with-a-segment-wall
  "The wall as a thin segment: no fact that does not matter is asked. Whether B rises is
the real question (the run branches on it); with the defaults B rises, and B's corner
leaves A's face at sqrt(l3 / a_Ax)."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "two-blocks-in-corner-segment-wall")))
      (is (eq scenario (ames:check-scenario scenario bridge)))
      (let* ((values (ames:run-parameter-values scenario :numeric t))
             (history (ames.algebra:with-parameter-values (values)
                        (simulate-stopping-when-ambiguous scenario bridge :parameter-values values)))
             (state (first (selected-states history))))
        (flet ((x (expression) (in-scenario-terms scenario expression)))
          (is (finished-p history))
          (is (not (null state)))
          (when state
            (end-event-is state :leaves "BLOCK-A" "BLOCK-B")
            (let ((a-ax (x '(/ (* l3 (- (* f l3) (* mb g (- l1 l2))))
                             (+ (* ma (expt l3 2)) (* mb (expt (- l1 l2) 2)))))))
              (ames.maxima:with-assumptions
                  (bridge (append (ames:scenario-assumption-relations scenario)
                                  (list (x '(> (* f l3) (* mb g (- l1 l2)))))))
                (is-same bridge "a_Ax" (first (per-body (ames::state-accelerations state) "BLOCK-A"))
                         a-ax)
                (is-same bridge "t1" (ames::state-duration state) `(sqrt (/ ,(x 'l3) ,a-ax)))))))))))

(test two-blocks-in-a-corner-with-a-segment-wall-to-rest
  "The segment-wall corner run on, with its defaults and (simulate :states 6 :branch nil):
B's corner leaves A's face at t1 with v_B = (l1 - l2) sqrt(F/D) (F = f l3 - mb g (l1 - l2),
D = ma l3^2 + mb (l1 - l2)^2); B flies up and lands on A's top corner at
t1 + 2 v_B / g (a plastic collision: B stops); A, pushed, hits the wall with the speed the
work-energy balance gives, v_A^2 = (3 f l3 - mb (l1 - l2)^2 F/D - mb g (l1 - l2)) / ma, and
stops there (plastic); then nothing changes. Undecided facts that cannot matter (the wall's
top corner on the line of A's slope, a contact met only after an earlier event) are not
asked, and an impact is never taken for a touch without one."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (mapcar (lambda (clause)
                                (if (and (consp clause) (same-name-p* (first clause) "SIMULATE"))
                                    (list (first clause) :states 6 :branch nil)
                                    clause))
                              (ames:scenario-form (scenario-named "two-blocks-in-corner-segment-wall")))))
           (values (ames:run-parameter-values scenario :numeric t))
           (history (ames.algebra:with-parameter-values (values)
                      (simulate-stopping-when-ambiguous scenario bridge :parameter-values values)))
           (states (ames::history-states history)))
      (flet ((x (expression) (in-scenario-terms scenario expression)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 4 (length states)))
        (when (= 4 (length states))
          (destructuring-bind (lifting flying sliding resting) states
            (end-event-is lifting :leaves "BLOCK-A" "BLOCK-B")
            (end-event-is flying :collision "BLOCK-A" "BLOCK-B")
            (end-event-is sliding :collision "BLOCK-A" "WALL")
            (is (eq :none (ames::state-end-event resting)))
            (ames.maxima:with-assumptions
                (bridge (append (ames:scenario-assumption-relations scenario)
                                (list (x '(> (* f l3) (* mb g (- l1 l2)))))))
              (let* ((d (x '(+ (* ma (expt l3 2)) (* mb (expt (- l1 l2) 2)))))
                     (f (x '(- (* f l3) (* mb g (- l1 l2)))))
                     (t1 `(sqrt (/ ,d ,f)))
                     (v-b `(* ,(x '(- l1 l2)) (sqrt (/ ,f ,d)))))
                (is-same bridge "t1" (ames::state-duration lifting) t1)
                (is-same bridge "B lands" (ames::state-start sliding) `(+ ,t1 (/ (* 2 ,v-b) ,(x 'g))))
                (is-same bridge "v_A^2 at the wall"
                         `(expt ,(first (per-body (ames::state-final-velocities sliding) "BLOCK-A")) 2)
                         `(/ (- (* 3 ,(x 'f) ,(x 'l3)) (/ (* ,(x 'mb) ,(x '(expt (- l1 l2) 2)) ,f) ,d)
                                (* ,(x 'mb) ,(x 'g) ,(x '(- l1 l2))))
                             ,(x 'ma)))
                (is-same-vector bridge "A at rest" (per-body (ames::state-velocities resting) "BLOCK-A") '(0 0))
                (is-same-vector bridge "B at rest" (per-body (ames::state-velocities resting) "BLOCK-B") '(0 0))))))))))

;;; The values of a run

(defparameter *values-scenario*
  "(scenario sliding-block \"A block pushed along the floor toward a step.\"
     (parameters (m :positive (:value 2)) (g :positive (:value 981/100))
                 (b :positive (:value 1)) (d (> d b) (:value 3)) (f :positive (:value 5)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body step :fixed t :position (d 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
     (body block :mass m :position (0 0) :velocity (0 0)
           :shape (polygon ((- b) 0) (0 0) (0 b) ((- b) b)))
     (force push :on block :value (f 0))
     (simulate :states 1))"
  "A scenario with (:value N) defaults and an assumption between two parameters.")

(defun run-text (text &rest keys)
  "Run the scenarios of TEXT (written to a temporary file) through RUN-FILES with KEYS;
return the status, the output and the error output."
  (let ((path (write-temporary-scenarios text))
        (errors (make-string-output-stream))
        (output (make-string-output-stream)))
    (let ((status (let ((*error-output* errors))
                    (unwind-protect (apply #'ames:run-files (list (namestring path))
                                           :format :sexp :stream output keys)
                      (delete-file path)))))
      (values status (get-output-stream-string output) (get-output-stream-string errors)))))

(test values-that-break-an-assumption-are-rejected
  (let ((scenario (first (ames:read-scenarios-from-string *values-scenario*))))
    (flet ((rejected (settings &key numeric)
             (handler-case (progn (ames:run-parameter-values scenario :settings settings :numeric numeric)
                                  nil)
               (ames:parameter-value-error (c) c))))
      ;; m = -2 against m :positive
      (let ((condition (rejected '(("m" . -2)))))
        (is (typep condition 'ames:scenario-error))
        (is (string-equal "M" (symbol-name (ames:parameter-value-error-parameter condition))))
        (is (search ":POSITIVE" (princ-to-string condition)))
        (is (search "parameter M" (princ-to-string condition))))
      ;; d = 1 with b = 2 against (> d b), and the default of b against a --set d
      (is (search "(> D B)" (princ-to-string (rejected '(("d" . 1) ("b" . 2))))))
      (is (search "(> D B)" (princ-to-string (rejected '(("d" . 1/2)) :numeric t))))
      (is (null (rejected '(("d" . 1/2)))) "without --numeric, b has no value to check d against")
      ;; a name that is no parameter (CHECK-PARAMETER-VALUES, the one check of names)
      (signals ames:undeclared-symbol-error
        (ames:run-parameter-values scenario :settings '(("q" . 1))))
      ;; defaults are used with --numeric, and --set overrides them
      (is (equal '(2 981/100 1 3 5)
                 (mapcar #'cdr (ames:run-parameter-values scenario :numeric t))))
      (is (eql 7 (cdr (assoc "F" (ames:run-parameter-values scenario :settings '(("f" . 7)) :numeric t)
                             :key #'symbol-name :test #'string=))))
      (is (equal '(7) (mapcar #'cdr (ames:run-parameter-values scenario :settings '(("f" . 7)))))))))

(test run-files-rejects-bad-values-and-uses-the-defaults
  (with-fixture simulator-bridge ()
    (multiple-value-bind (status output errors)
        (run-text *values-scenario* :settings '(("m" . -2)) :bridge bridge)
      (declare (ignore output))
      (is (eql ames:+exit-scenario-error+ status))
      (is (search ":POSITIVE" errors)))
    (multiple-value-bind (status output) (run-text *values-scenario* :numeric t :bridge bridge)
      (is (eql ames:+exit-complete+ status))
      (let ((report (let ((*read-eval* nil) (*package* (find-package '#:ames-scenario)))
                      (read-from-string output))))
        (is (getf (first (getf report :states)) :numeric) "numbers printed beside the formulas")))))

(defparameter *particle-over-a-block*
  "(scenario particle-over-a-block \"A particle dropped from y0 over a block of height h.\"
     (parameters (m :positive) (g :positive) (h :positive) (y0 :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body block :fixed t :shape (polygon (-1 0) (1 0) (1 h) (-1 h)))
     (body particle :mass m :position (0 y0) :velocity (0 0) :shape point))"
  "A scenario whose start is valid only if y0 > h, which the assumptions leave open.")

(test a-geometric-fact-is-decided-by-the-values-and-reported
  (with-fixture simulator-bridge ()
    ;; without values: rejected, naming the fact and the values that decide it
    (multiple-value-bind (status output errors) (run-text *particle-over-a-block* :bridge bridge)
      (declare (ignore output))
      (is (eql ames:+exit-scenario-error+ status))
      (is (search "holds at" errors))
      (is (search "fails at" errors)))
    ;; with values that make the start valid: used, reported, and the run goes on
    (multiple-value-bind (status output)
        (run-text *particle-over-a-block* :settings '(("m" . 1) ("g" . 10) ("h" . 1) ("y0" . 3))
                                          :bridge bridge)
      (is (eql ames:+exit-complete+ status))
      (let ((report (let ((*read-eval* nil) (*package* (find-package '#:ames-scenario)))
                      (read-from-string output))))
        (is (not (member (getf report :outcome) '(:ambiguous :undecided))))
        (is (consp (getf report :assumed-from-values)))))))

(test an-ambiguous-run-exits-3
  (with-fixture simulator-bridge ()
    (is (eql ames:+exit-undecided+
             (run-text "(scenario push-or-fall \"Weight against a push.\"
                          (parameters (m :positive) (g :positive) (f :positive) (h :positive))
                          (gravity g)
                          (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                          (body wall :fixed t :shape (half-plane (1 1) (1 0)))
                          (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
                          (force push :on ball :value (f 0))
                          (simulate :branch nil))"
                       :bridge bridge)))))

(test bin-ames-exits-3-for-an-undecided-run
  (let ((path (write-temporary-scenarios
               "(scenario push-or-fall \"Weight against a push, without branching.\"
                  (parameters (m :positive (:value 1)) (g :positive (:value 10))
                              (f :positive (:value 1)) (h :positive (:value 1)))
                  (gravity g)
                  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                  (body wall :fixed t :shape (half-plane (1 1) (1 0)))
                  (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
                  (force push :on ball :value (f 0))
                  (simulate :states 1 :branch nil))")))
    (unwind-protect
         (progn
           (is (eql 3 (run-bin-ames "run" (namestring path))))
           (is (eql 0 (run-bin-ames "run" (namestring path) "--numeric")))
           (multiple-value-bind (code output) (run-bin-ames "run" (namestring path) "--set" "m=-2")
             (is (eql 1 code))
             (is (search ":POSITIVE" output))))
      (delete-file path))))
