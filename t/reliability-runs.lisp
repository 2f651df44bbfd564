;;;; t/reliability-runs.lisp -- runs of scenario files: messages that say where, the time limit, a closed pipe, the same bytes.
;;;;
;;;; Determinism: every scenario file of scenarios/ (whatever files there are) is run
;;;; alone, each in a fresh bin/ames process, and then all of them twice over in one
;;;; process, so that the second time each runs after all the others; the bytes printed
;;;; must be the same.

(in-package #:ames.tests)

(in-suite reliability)

(defun write-scenario-text (text)
  "Write TEXT to a fresh temporary scenario file; return its namestring."
  (let ((path (uiop:tmpize-pathname (merge-pathnames "ames-reliability.lisp"
                                                     (uiop:temporary-directory)))))
    (with-open-file (out path :direction :output :if-exists :supersede)
      (write-string text out))
    (namestring path)))

(defparameter *drop-text*
  "(scenario drop \"A ball dropped from height h.\"
  (parameters (m :positive) (g :positive) (h :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :position (0 h) :velocity (0 0) :shape point))
"
  "A quick scenario that always completes.")

(defun big-polygon-text (vertices)
  "A scenario dropping a ball on a fixed regular polygon of VERTICES integer vertices."
  (format nil "(scenario big-polygon \"A ball dropped on a ~D-gon.\"
  (parameters (m :positive) (g :positive))
  (gravity g)
  (body rock :fixed t :shape (polygon ~{(~D ~D)~^ ~}))
  (body ball :mass m :position (0 200000) :velocity (0 0) :shape point))~%"
          vertices
          (loop for k below vertices
                for angle = (/ (* 2 pi k) vertices)
                append (list (round (* 100000 (cos angle))) (round (* 100000 (sin angle)))))))

(test errors-of-a-run-name-the-file-the-scenario-and-the-line
  (let* ((path (write-scenario-text
                (concatenate 'string "; a file of two scenarios
(scenario huge \"A coordinate with an exact power of ten to the billion.\"
  (parameters (m :positive) (g :positive) (h :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :position (0 (/ h (expt 10 (expt 10 9)))) :velocity (0 0)
        :shape point))
" *drop-text*)))
         (errors (make-string-output-stream))
         (output (make-string-output-stream)))
    (unwind-protect
         (let ((status (within-seconds (20)
                         (let ((*error-output* errors))
                           (ames:run-files (list path) :format :sexp :stream output)))))
           (is (eql 1 status))
           (let ((message (get-output-stream-string errors)))
             (is (search path message) "~A" message)
             (is (search "Scenario HUGE" message) "~A" message)
             (is (search "line " message) "~A" message)
             (is (search "BALL" message) "~A" message)
             (is (search "bits" message) "~A" message))
           ;; the next scenario ran
           (is (search "drop" (get-output-stream-string output))))
      (delete-file path)))
  ;; the context of a condition whose datum names bodies: their clause's line
  (let* ((scenario (first (ames:read-scenarios-from-string
                           (concatenate 'string (string #\Newline) *drop-text*)
                           :file "drop.lisp")))
         (ball (find "BALL" (mapcar #'ames:scenario-body-name (ames:scenario-bodies scenario))
                     :test #'string= :key #'symbol-name))
         (floor (find "FLOOR" (mapcar #'ames:scenario-body-name (ames:scenario-bodies scenario))
                      :test #'string= :key #'symbol-name))
         (context (ames::run-error-context
                   scenario (make-condition 'ames-error :datum `(= (acc ,ball :y) (- g))))))
    (is (equal "drop.lisp" (ames:error-context-file context)))
    (is (eql 6 (ames:error-context-line context)))
    (is (equal "body BALL" (ames:error-context-location context)))
    (is (equal "bodies BALL and FLOOR"
               (ames:error-context-location
                (ames::run-error-context
                 scenario (make-condition 'ames-error :datum (list ball :on floor))))))
    (is (eql 2 (ames:error-context-line
                (ames::run-error-context scenario (make-condition 'ames-error :datum 'g)))))))

(test the-time-limit-stops-a-run-and-the-next-scenario-runs
  (let ((path (write-scenario-text (concatenate 'string (big-polygon-text 4000) *drop-text*))))
    (unwind-protect
         (multiple-value-bind (code output)
             (within-seconds (40)
               (run-bin-ames "run" path "--time-limit" "2" "--format" "sexp"))
           (is (eql 1 code))
           (is (search "time limit of 2 s" output) "~A" output)
           (is (search "Scenario BIG-POLYGON" output) "~A" output)
           (is (search ":scenario drop" output) "~A" output))
      (delete-file path))))

(test a-closed-pipe-ends-the-run-quietly
  (let ((path (write-scenario-text (format nil "~{~A~}" (make-list 40 :initial-element *drop-text*))))
        (program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames")))))
    (unwind-protect
         (let ((result (uiop:run-program
                        (list "bash" "-c"
                              (format nil "~A run ~A 2>~A.err | head -c 10 >/dev/null; echo ${PIPESTATUS[0]}"
                                      program path path))
                        :output :string)))
           (is (equal "141" (string-trim '(#\Newline #\Space) result)))
           (is (zerop (length (uiop:read-file-string (format nil "~A.err" path))))))
      (delete-file path)
      (uiop:delete-file-if-exists (format nil "~A.err" path)))))

(defun bin-ames-output (&rest arguments)
  "The standard output of bin/ames run with ARGUMENTS (its status is not looked at)."
  (let ((program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames")))))
    (uiop:run-program (cons program arguments) :output :string :error-output :string
                                               :ignore-error-status t)))

(defparameter *order-check-scenarios*
  '("atwood-machine" "ball-toward-low-wall" "block-bouncing-on-rough-floor" "block-hits-bumper"
    "bouncing-ball" "particle-down-quarter-circle" "particle-under-plane" "projectile-off-table"
    "stack-of-four-blocks")
  "The scenarios of scenarios/ that `make test` runs again and again to check that a run's
output does not depend on what ran before it or on a kill of Maxima: quick ones, with a
rope, a spring, friction, impacts, a Zeno sequence, a curve and a fork among them. `make
fuzz` checks every scenario (see the suite LONG-CHECKS).")

(def-suite long-checks
  :description "The full-size repetitions of checks `make test` runs on a sample: every
scenario of scenarios/ instead of *ORDER-CHECK-SCENARIOS*. Not part of ALL-TESTS: `make
fuzz` runs it.")

(defun order-check-files (&optional all)
  "The scenario files of the order and crash checks: every one with ALL, else those named
in *ORDER-CHECK-SCENARIOS*."
  (if all
      (scenario-files)
      (remove-if-not (lambda (file) (member (pathname-name file) *order-check-scenarios*
                                            :test #'string=))
                     (scenario-files))))

(defun check-same-bytes-alone-and-after-others (files)
  "Check that each scenario of FILES prints the same bytes alone and after all the others:
through bin/ames (each alone, then all twice in one process) and in one Lisp (each alone
on a fresh bridge, then after all the others on one bridge)."
  (let* ((names (mapcar #'namestring files))
         (alone (mapcar (lambda (file) (bin-ames-output "run" file "--format" "sexp")) names))
         (together (apply #'bin-ames-output "run" (append names names (list "--format" "sexp"))))
         (expected (format nil "~{~A~}~:*~{~A~}" alone)))
    (is (plusp (length names)))
    (is (every (lambda (text) (plusp (length text))) alone))
    (is (string= expected together)
        "the output differs from byte ~D on"
        (or (mismatch expected together) -1)))
  ;; the same in one Lisp: each scenario alone on a fresh bridge, and after all others
  (let ((bridge (ames.maxima:make-bridge)))
    (flet ((printed (scenario bridge)
             (with-output-to-string (stream)
               (handler-case (ames:print-history-sexp (ames:run-scenario scenario :bridge bridge)
                                                      stream)
                 (ames-error (condition) (format stream "error: ~A" condition))))))
      (unwind-protect
           (let* ((scenarios (loop for file in files
                                   append (ames:read-scenario-file file)))
                  (alone (mapcar (lambda (scenario)
                                   (let ((fresh (ames.maxima:make-bridge)))
                                     (unwind-protect (printed scenario fresh)
                                       (ames.maxima:close-bridge fresh))))
                                 scenarios)))
             (dolist (scenario scenarios) (printed scenario bridge))
             (loop for scenario in scenarios
                   for expected in alone
                   do (is (string= expected (printed scenario bridge))
                          "~A prints otherwise after the others" (ames:scenario-name scenario))))
        (ames.maxima:close-bridge bridge)))))

(test a-scenario-prints-the-same-bytes-alone-and-after-all-others
  "The order check on the sample *ORDER-CHECK-SCENARIOS* (every scenario: `make fuzz`)."
  (check-same-bytes-alone-and-after-others (order-check-files)))

(test (every-scenario-prints-the-same-bytes-alone-and-after-all-others :suite long-checks)
  "The order check on every scenario of scenarios/."
  (check-same-bytes-alone-and-after-others (order-check-files t)))
