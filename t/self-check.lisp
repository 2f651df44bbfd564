;;;; t/self-check.lisp -- the self-check (src/check/) and numbers that are their formulas' values.
;;;;
;;;; The mechanism is shown to pass right claims and to catch wrong ones: a state's closed
;;;; form, end time, final values or a printed number perturbed on purpose must each fail,
;;;; naming the claim. Numbers beside formulas (issue 20, class 4) are checked on fresh
;;;; scenarios whose impacts accumulate (a Zeno series): the formula is compared with the
;;;; textbook's by Maxima equivalence, the number with the formula's value. Finally every
;;;; scenario of scenarios/ is run with its (:value N) defaults (--numeric), and values
;;;; chosen to satisfy its assumptions for the parameters without one, the self-check on,
;;;; along the branch the values select: no file may escape the check (a refused run, no
;;;; state checked) but those listed in +KNOWN-SELF-CHECK-ESCAPES+, and no claim may fail
;;;; but the known failures listed in +KNOWN-SELF-CHECK-FAILURES+.

(in-package #:ames.tests)

(def-suite self-check :in all-tests
  :description "The self-check of every state under parameter values, and printed
numbers that are their formulas' values.")

(in-suite self-check)

(defun numeric-history (text bridge &rest settings)
  "The history of the scenario written in TEXT, run as bin/ames run --numeric does (the
self-check on), with SETTINGS (an alist parameter name -> number) over its defaults."
  (let ((scenario (first (ames:read-scenarios-from-string text))))
    (ames:run-scenario scenario :bridge bridge :numeric t
                                :settings (mapcar (lambda (entry) (cons (string-upcase (car entry)) (cdr entry)))
                                                  settings))))

(defun self-check-of (history)
  "HISTORY's self-check result (see AMES.CHECK)."
  (ames.check:self-check-result history))

(defparameter *dropped-ball*
  "(scenario ball-dropped-on-a-slab
     \"A ball dropped on a slab bounces with e = 1/3 until it rests.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (h :positive (:value 2)))
     (gravity g)
     (restitution 1/3)
     (body slab :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
     (simulate :states 6))"
  "A fresh Zeno scenario: the impacts accumulate at sqrt(2 h / g) (1 + e) / (1 - e) =
2 sqrt(2 h / g).")

(defparameter *pushed-crate*
  "(scenario crate-pushed-against-a-bulkhead
     \"A crate pushed by a constant force into a bulkhead bounces with e = 1/3 until it rests.\"
     (parameters (m :positive (:value 2)) (g :positive (:value 10))
                 (f :positive (:value 4)) (d :positive (:value 1)))
     (gravity g)
     (restitution 1/3)
     (body deck :fixed t :shape (half-plane (1 0) (0 0)))
     (body bulkhead :fixed t :shape (half-plane ((+ d 2) 1) ((+ d 2) 0)))
     (body crate :mass m :position (0 0) :velocity (0 0) :shape (polygon (0 0) (2 0) (2 1) (0 1)))
     (force push :on crate :value (f 0))
     (simulate :states 4))"
  "A fresh Zeno scenario along the floor: first impact after t1 = sqrt(2 m d / f), each
return trip 2 e times the one before, at rest from t1 (1 + e) / (1 - e) = 2 t1.")

(defun rest-state (history)
  "The last state of HISTORY (the one at rest after the impacts accumulate)."
  (car (last (ames:history-states history))))

(defun check-accumulated-start (bridge history expected)
  "The rest state of HISTORY starts at EXPECTED (a formula over the scenario's
parameters, Maxima-equivalent), and the number printed beside it is that formula's
value under the run's values; the self-check passes."
  (let* ((scenario (ames:history-scenario history))
         (state (rest-state history))
         (expected (in-scenario-terms scenario expected))
         (number (getf (ames.simulator:state-numbers state) :start))
         (value (ames.maxima:numeric-value bridge expected (ames:history-parameter-values history))))
    (call-with-scenario-facts
     bridge scenario
     (lambda () (is-same bridge "the start of the rest state" (ames:state-start state) expected)))
    (is (realp number) "no number beside the start ~S" (ames:state-start state))
    (is (and (realp number) (< (abs (- number value)) (* 1d-9 (abs value))))
        "printed ~A beside the start, its formula's value is ~A" number value)
    ;; the number is not the sum of the printed durations (the series is summed)
    (let ((durations (loop for s in (butlast (ames:history-states history))
                           sum (getf (ames.simulator:state-numbers s) :duration))))
      (is (> (abs (- durations value)) 1d-3) "the start is the durations' sum ~A" durations))
    (let ((check (self-check-of history)))
      (is (null (getf check :failures)) "self-check failures: ~S" (getf check :failures))
      (is (= (first (getf check :numbers)) (second (getf check :numbers))))
      (is (plusp (first (getf check :numbers)))))
    ;; the number the report printed before (the durations summed) is caught as a wrong claim
    (let ((numeric (ames.simulator:state-numbers state))
          (durations (loop for s in (butlast (ames:history-states history))
                           sum (getf (ames.simulator:state-numbers s) :duration))))
      (setf (getf (ames.simulator:state-numbers state) :start) durations)
      (let ((check (ames.check:self-check-history history)))
        (is (some (lambda (f) (search "number printed for the start time" (getf f :claim)))
                  (getf check :failures))
            "~S" (getf check :failures)))
      (setf (ames.simulator:state-numbers state) numeric)
      (ames.check:self-check-history history))))

(test numbers-after-a-summed-series-are-their-formulas
  "After impacts that accumulate, the rest state's start is the series' sum, and the
number beside it that sum's value (not the sum of the durations printed before it)."
  (with-fixture simulator-bridge ()
    (check-accumulated-start bridge (numeric-history *dropped-ball* bridge)
                             '(* 2 (sqrt (/ (* 2 h) g))))
    (check-accumulated-start bridge (numeric-history *pushed-crate* bridge)
                             '(* 2 (sqrt (/ (* 2 m d) f))))
    ;; other values, set on the command line
    (check-accumulated-start bridge (numeric-history *dropped-ball* bridge '("h" . 5) '("g" . 981/100))
                             '(* 2 (sqrt (/ (* 2 h) g))))))

;;; The mechanism: right claims pass, wrong ones fail

(defparameter *thrown-ball*
  "(scenario ball-thrown-up-over-a-floor
     \"A ball thrown up and sideways falls back to the floor.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (v0 :positive (:value 3)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass m :position (0 1) :velocity (1 v0) :shape point)
     (simulate :states 2))"
  "A fresh scenario with a parabola ending at an impact.")

(defun state-check (state history)
  "CHECK-STATE's verdict on STATE under HISTORY's values."
  (ames.check:check-state state (ames:history-parameter-values history) :horizon 5))

(defun failed-claims (verdict)
  "The claims named by a failed VERDICT."
  (mapcar #'ames.check:check-failure-claim (getf verdict :failures)))

(test the-self-check-passes-right-claims-and-catches-wrong-ones
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *thrown-ball* bridge))
           (state (first (ames:history-states history)))
           (ball (find "BALL" (ames:state-positions state) :key (lambda (e) (symbol-name (first e))) :test #'string=))
           (name (first ball)))
      (is (eq :checked (getf (state-check state history) :status)))
      (is (member 0 (getf (self-check-of history) :checked)))
      (is (null (getf (self-check-of history) :failures)))
      ;; a closed form off by 1e-6 of its size
      (let ((right (copy-tree (ames:state-positions state))))
        (setf (ames::state-positions state)
              (mapcar (lambda (entry)
                        (if (eq (first entry) name)
                            (list name (list (first (second entry)) `(* ,(+ 1 1/1000000) ,(second (second entry)))))
                            entry))
                      right))
        (let ((verdict (state-check state history)))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "position_y at tau" claim)) (failed-claims verdict))
              "~S" (failed-claims verdict))
          (is (every (lambda (f) (< 1d-7 (ames.check:check-failure-discrepancy f) 1d-5))
                     (getf verdict :failures))))
        (setf (ames::state-positions state) right))
      ;; a velocity that is wrong
      (let ((right (copy-tree (ames:state-velocities state))))
        (setf (ames::state-velocities state)
              (mapcar (lambda (entry) (if (eq (first entry) name) (list name (list 1 0)) entry)) right))
        (is (eq :failed (getf (state-check state history) :status)))
        (setf (ames::state-velocities state) right))
      ;; an end time too late: the floor is met before it
      (let ((right (ames:state-duration state)))
        (setf (ames::state-duration state) `(* 11/10 ,right))
        (let ((verdict (state-check state history)))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "before the end" claim)) (failed-claims verdict))
              "~S" (failed-claims verdict)))
        ;; too early: the claimed impact is not there then
        (setf (ames::state-duration state) `(* 9/10 ,right))
        (let ((verdict (state-check state history)))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "the claimed end" claim)) (failed-claims verdict))
              "~S" (failed-claims verdict)))
        (setf (ames::state-duration state) right))
      ;; a final velocity that is not the motion's
      (let ((right (copy-tree (ames:state-final-velocities state))))
        (setf (ames::state-final-velocities state)
              (mapcar (lambda (entry) (if (eq (first entry) name) (list name (list 1 -5)) entry)) right))
        (is (some (lambda (claim) (search "final velocity" claim))
                  (failed-claims (state-check state history))))
        (setf (ames::state-final-velocities state) right))
      (is (eq :checked (getf (state-check state history) :status)))
      ;; a solve that is wrong: the solved quantities put in the model's equations leave
      ;; one side 1/1000 off
      (let* ((model (getf (ames:state-analysis state) :check-model))
             (right (getf model :equations)))
        (setf (getf (getf (ames::state-analysis state) :check-model) :equations)
              (mapcar (lambda (equation) (list (first equation) `(* 1001/1000 ,(second equation))))
                      right))
        (let ((verdict (state-check state history)))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "the model equation" claim)) (failed-claims verdict))
              "~S" (failed-claims verdict)))
        (setf (getf (getf (ames::state-analysis state) :check-model) :equations) right))
      (is (equal '(:status :checked) (subseq (state-check state history) 0 2)))
      ;; a printed number that is not its formula's value: the history's check fails
      (let ((numeric (ames.simulator:state-numbers state)))
        (setf (getf (ames.simulator:state-numbers state) :duration)
              (* 2/3 (getf numeric :duration)))
        (let ((check (ames.check:self-check-history history)))
          (is (some (lambda (f) (search "number printed for the duration" (getf f :claim)))
                    (getf check :failures))
              "~S" (getf check :failures))
          (is (ames.check:self-check-failed-p history)))))))

(test a-state-that-lasts-forever-is-searched-up-to-a-horizon
  "A state claimed to last forever while a condition fires fails the check."
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *thrown-ball* bridge))
           (state (first (ames:history-states history))))
      (setf (ames::state-duration state) :forever
            (ames::state-end-event state) :none
            (ames::state-final-positions state) '()
            (ames::state-final-velocities state) '())
      (let ((verdict (state-check state history)))
        (is (eq :failed (getf verdict :status)))
        (is (some (lambda (claim) (search "before the end" claim)) (failed-claims verdict)))))))

(test no-check-skips-and-says-so-and-a-failed-check-has-its-exit-status
  (with-fixture simulator-bridge ()
    ;; a check that can never be met (a negative tolerance) fails: the status is 5
    (let ((file (find "particle-under-plane" (scenario-files) :key #'pathname-name :test #'string=)))
      (is (eql ames::+exit-check-failed+
               (let ((ames.check::*relative-tolerance* -1d0)
                     (*error-output* (make-broadcast-stream)))
                 (ames:run-files (list file) :numeric t :bridge bridge :stream (make-broadcast-stream)))))
      (is (eql 0 (ames:run-files (list file) :numeric t :bridge bridge :stream (make-broadcast-stream))))
      (is (eql 0 (let ((ames.check:*self-check* nil)
                       (ames.check::*relative-tolerance* -1d0))
                   (ames:run-files (list file) :numeric t :bridge bridge :stream (make-broadcast-stream))))))
    (is (eql 5 (ames::worse-status 3 5)))
    (is (eql 1 (ames::worse-status 5 1)))
    (let ((history (let ((ames.check:*self-check* nil)) (numeric-history *thrown-ball* bridge))))
      (is (equal '(:skipped t) (self-check-of history))))
    (let ((options (ames::parse-command-line '("run" "a.lisp" "--no-check"))))
      (is-true (getf options :no-check)))))

;;; Every scenario of scenarios/, under its (:value N) defaults or values chosen for it

(defparameter +known-self-check-failures+ '()
  "Claims of the scenarios of scenarios/ the self-check finds wrong and that are not fixed
yet: a list of (SCENARIO-FILE-NAME STATE-INDEX CLAIM-PREFIX). Listed, never hidden.")

(defparameter +known-self-check-escapes+ '()
  "Scenario files of scenarios/ the self-check cannot check at all yet (a run refused
under the values, or no state checked): a list of (SCENARIO-FILE-NAME REASON). Listed,
never hidden.")

(defun known-failure-p (file failure)
  "True when FAILURE (a plist of the self-check) of the scenario FILE is a known one."
  (some (lambda (known)
          (destructuring-bind (name index prefix) known
            (and (string= name (pathname-name file))
                 (eql index (getf failure :state))
                 (eql 0 (search prefix (getf failure :claim))))))
        +known-self-check-failures+))

(defun self-checked-history (scenario bridge)
  "SCENARIO run with --numeric: its (:value N) defaults, and for each parameter without
one a value satisfying every assumption (ADMISSIBLE-PARAMETER-VALUES), so every
scenario has numbers to check with; along the branch those values select. Returns the
history, or the AMES-ERROR that refused the run."
  (handler-case
      (ames:run-scenario scenario :numeric t :bridge bridge
                                  :settings (ames:admissible-parameter-values scenario))
    (ames:ames-error (condition) condition)))

(defun check-scenario-file-self-check (file bridge)
  "Run every scenario of FILE as SELF-CHECKED-HISTORY does and assert that its self-check
ran (not skipped, at least one state checked), accounts for every state of the selected
path, and finds no claim wrong but the known failures. A file that escapes the check
fails the test unless it is listed in +KNOWN-SELF-CHECK-ESCAPES+."
  (let ((name (pathname-name file)))
    (flet ((escape (control &rest arguments)
             (unless (assoc name +known-self-check-escapes+ :test #'string=)
               (fail "~A escapes the self-check: ~?" name control arguments))))
      (let ((scenarios (handler-case (ames:read-scenario-file file)
                         (ames:ames-error (condition) (escape "it is refused: ~A" condition) '()))))
        (unless scenarios (escape "it holds no scenario"))
        (dolist (scenario scenarios)
          (let ((history (self-checked-history scenario bridge)))
            (if (typep history 'ames:ames-error)
                (escape "the run under ~S is refused: ~A"
                        (ames:admissible-parameter-values scenario) history)
                (let ((check (self-check-of history)))
                  (cond ((or (null check) (getf check :skipped))
                         (escape "the self-check did not run"))
                        ((null (getf check :checked))
                         (escape "no state is checked: ~S" (getf check :unchecked))))
                  (when (and check (not (getf check :skipped)))
                    ;; every state of the path is accounted for: checked, failed, or not checked and why
                    (dolist (state (ames.check::checked-path (ames:history-states history)))
                      (is (or (member (ames:state-index state) (getf check :checked))
                              (find (ames:state-index state) (getf check :unchecked) :key (lambda (u) (getf u :state)))
                              (find (ames:state-index state) (getf check :failures) :key (lambda (f) (getf f :state))))
                          "~A: state ~D is not accounted for" name (ames:state-index state))))
                  (dolist (failure (getf check :failures))
                    (unless (known-failure-p file failure)
                      (fail "~A: state ~A: ~A (off by ~A): ~A" name (getf failure :state)
                            (getf failure :claim) (getf failure :discrepancy) (getf failure :detail))))))))))))

(test every-scenario-passes-its-self-check
  "Each scenario of scenarios/ run with --numeric under its defaults and values chosen
to satisfy its assumptions (along the branch they select): the self-check runs on it,
and no claim it can test is wrong, but the known failures listed."
  (with-fixture simulator-bridge ()
    (dolist (file (scenario-files))
      (check-scenario-file-self-check file bridge))))

(defun perturbed-verdict (state history accessor setter change)
  "CHECK-STATE's verdict on STATE with the slot read by ACCESSOR replaced by CHANGE of
it (SETTER writes it), restored afterwards."
  (let ((right (funcall accessor state)))
    (funcall setter (funcall change right) state)
    (unwind-protect (state-check state history)
      (funcall setter right state))))

(test the-self-check-on-a-curve-and-on-a-spring
  "A particle sliding on a sphere until it leaves it (its motion over the arc length, its
end a normal force reaching zero) and two masses on a spring (trigonometric closed
forms): the right claims pass, perturbed ones fail."
  (with-fixture simulator-bridge ()
    (let* ((history (first (ames:run-file (find "particle-on-sphere" (scenario-files) :key #'pathname-name
                                                                                     :test #'string=)
                                          :numeric t :bridge bridge)))
           (state (first (ames:history-states history))))
      (is (eq :checked (getf (state-check state history) :status)))
      (flet ((set-duration (value state) (setf (ames::state-duration state) value))
             (set-finals (value state) (setf (ames::state-final-velocities state) value))
             (set-velocities (value state) (setf (ames::state-velocities state) value)))
        ;; the velocity over the arc length (from the energy integral) a little off
        (let ((verdict (perturbed-verdict
                        state history #'ames:state-velocities #'set-velocities
                        (lambda (velocities)
                          (mapcar (lambda (entry)
                                    (destructuring-bind (body motion) entry
                                      (list body (if (and (consp motion) (eq (first motion) :on-path))
                                                     (list* :on-path (mapcar (lambda (c) `(* 1000001/1000000 ,c))
                                                                             (second motion))
                                                            (cddr motion))
                                                     motion))))
                                  velocities)))))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "velocity_x at tau" claim)) (failed-claims verdict))
              "~S" (failed-claims verdict)))
        (dolist (factor '(99/100 101/100))
          (is (eq :failed (getf (perturbed-verdict state history #'ames:state-duration #'set-duration
                                                   (lambda (d) `(* ,factor ,d)))
                                :status))
              "a lift-off time ~A times the right one is not caught" factor))
        (is (eq :failed (getf (perturbed-verdict state history #'ames:state-final-velocities #'set-finals
                                                 (lambda (finals)
                                                   (mapcar (lambda (entry)
                                                             (list (first entry)
                                                                   (mapcar (lambda (c) `(* 1000001/1000000 ,c))
                                                                           (second entry))))
                                                           finals)))
                              :status)))))
    (let* ((history (first (ames:run-file (find "two-masses-on-a-spring" (scenario-files) :key #'pathname-name
                                                                                         :test #'string=)
                                          :numeric t :bridge bridge)))
           (state (first (ames:history-states history))))
      (is (eq :checked (getf (state-check state history) :status)))
      (flet ((set-positions (value state) (setf (ames::state-positions state) value)))
        (is (eq :failed (getf (perturbed-verdict state history #'ames:state-positions #'set-positions
                                                 (lambda (positions)
                                                   (mapcar (lambda (entry)
                                                             (list (first entry)
                                                                   (mapcar (lambda (c) `(+ ,c (* 1/10000000 (sin tau))))
                                                                           (second entry))))
                                                           positions)))
                              :status)))))))

(defparameter *hanging-mass*
  "(scenario mass-hanging-on-a-spring
     \"A mass hangs from a ceiling hook on a spring, released below its rest point.\"
     (parameters (m :positive (:value 1)) (k :positive (:value 4)) (g :positive (:value 10)))
     (gravity g)
     (body hook :fixed t :position (0 5) :shape point)
     (body bob :mass m :position (0 1) :velocity (0 0) :shape point)
     (spring coil :from (hook (0 0)) :to (bob (0 0)) :stiffness k)
     (simulate :states 2))"
  "A fresh scenario: an oscillation that lasts forever, of period 2 pi sqrt(m / k).")

(test a-periodic-state-comes-back-after-its-period
  "A state said periodic (its notes' :PERIODIC, see the scenario language) is integrated
over its period and must be back at its start: 2 pi sqrt(m/k) passes, a period 1% off
fails."
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *hanging-mass* bridge))
           (state (first (ames:history-states history)))
           (scenario (ames:history-scenario history)))
      (is (eq :forever (ames:state-duration state)))
      (is (eq :checked (getf (state-check state history) :status)))
      (flet ((with-period (period)
               (setf (ames.simulator:state-periodic state)
                     (list :period (in-scenario-terms scenario period)))
               (prog1 (state-check state history)
                 (setf (ames.simulator:state-periodic state) nil))))
        (is (eq :checked (getf (with-period '(* 2 pi (sqrt (/ m k)))) :status)))
        (let ((verdict (with-period '(* 101/100 2 pi (sqrt (/ m k))))))
          (is (eq :failed (getf verdict :status)))
          (is (some (lambda (claim) (search "the period" claim)) (failed-claims verdict))))))))
