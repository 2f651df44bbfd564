;;;; t/reliability-crash.lisp -- kill -9 of Maxima at random moments of scenario runs.
;;;;
;;;; Each run of a scenario of scenarios/ (taken in turn) has a thread that sleeps a random
;;;; time within the run's expected length and then kills the bridge's Maxima process with
;;;; SIGKILL. The run must either print exactly what it prints undisturbed or end in an
;;;; AMES-ERROR; and the next scenario, run undisturbed on the same bridge, must print
;;;; exactly what it should. The seed is fixed. *CRASH-RUNS* runs in `make test`; `make
;;;; fuzz` runs more (see t/fuzz.lisp).

(in-package #:ames.tests)

(in-suite reliability)

(defparameter *crash-runs* 18
  "How many runs of the crash-safety test of `make test` get a kill (two for each of the
sample *ORDER-CHECK-SCENARIOS*; `make fuzz` runs more, over every scenario).")

(defparameter *crash-seed* 1515
  "The seed of the crash-safety test's random kill times.")

(defun printed-run (scenario bridge)
  "What RUN-SCENARIO of SCENARIO on BRIDGE prints in the sexp format, or the AMES-ERROR
it ends in."
  (handler-case (with-output-to-string (stream)
                  (ames:print-history-sexp (ames:run-scenario scenario :bridge bridge) stream))
    (ames-error (condition) condition)))

(defun kill-maxima-after (bridge seconds)
  "A thread that kills BRIDGE's Maxima process, if one runs, after SECONDS."
  (sb-thread:make-thread
   (lambda ()
     (sleep seconds)
     (let ((pid (ames.maxima:bridge-process-id bridge)))
       (when pid (kill-process pid))
       pid))
   :name "AMES crash test: kill -9 of Maxima"))

(defun crash-safety-figures (runs &key (seed *crash-seed*) (stream nil)
                                       (files (scenario-files)))
  "Run the crash-safety experiment RUNS times (see the file header) and return a plist
:RUNS :KILLED :IDENTICAL :AMES-ERRORS :DIFFERENT (outputs that changed) :NEXT-FAILED
(undisturbed runs after a kill that failed or changed) and :FAILURES (descriptions).
With STREAM, print a line per run. The runs take the scenarios of FILES in turn (by
default every scenario file)."
  (let* ((scenarios (loop for file in files append (ames:read-scenario-file file)))
         (bridge (ames.maxima:make-bridge))
         (state (sb-ext:seed-random-state seed))
         (killed 0) (identical 0) (errors 0) (different 0) (next-failed 0) (failures '()))
    (unwind-protect
         (let* ((timings '())
                (expected (mapcar (lambda (scenario)
                                    (let ((start (get-internal-real-time)))
                                      (prog1 (printed-run scenario bridge)
                                        (push (max 0.05 (seconds-since start)) timings))))
                                  scenarios))
                (timings (nreverse timings)))
           (dotimes (i runs)
             (let* ((k (mod i (length scenarios)))
                    (scenario (nth k scenarios))
                    (delay (random (* 1.2 (nth k timings)) state))
                    (killer (kill-maxima-after bridge delay))
                    (outcome (printed-run scenario bridge)))
               (when (sb-thread:join-thread killer :default nil) (incf killed))
               (cond ((equal outcome (nth k expected)) (incf identical))
                     ((typep outcome 'ames-error) (incf errors))
                     (t (incf different)
                        (push (format nil "run ~D (~A, kill after ~,3F s): the output changed"
                                      i (ames:scenario-name scenario) delay)
                              failures)))
               (when stream
                 (format stream "~&run ~3D ~30A kill after ~,3F s: ~A~%" i
                         (ames:scenario-name scenario) delay
                         (cond ((equal outcome (nth k expected)) "identical")
                               ((typep outcome 'ames-error) (type-of outcome))
                               (t "CHANGED"))))
               ;; the next scenario runs, undisturbed, and prints what it should
               (let* ((next (mod (1+ k) (length scenarios)))
                      (after (printed-run (nth next scenarios) bridge)))
                 (unless (equal after (nth next expected))
                   (incf next-failed)
                   (push (format nil "run ~D: the next scenario, ~A, gave ~A"
                                 i (ames:scenario-name (nth next scenarios))
                                 (if (typep after 'condition) after "another output"))
                         failures))))))
      (ames.maxima:close-bridge bridge))
    (list :runs runs :killed killed :identical identical :ames-errors errors
          :different different :next-failed next-failed :failures (nreverse failures))))

(test kill-9-of-maxima-during-runs-changes-no-output
  "Kills of Maxima during runs of the sample *ORDER-CHECK-SCENARIOS* (`make fuzz`: more
runs, every scenario)."
  (let ((figures (crash-safety-figures *crash-runs* :files (order-check-files))))
    (is (zerop (getf figures :different)) "~{~A~%~}" (getf figures :failures))
    (is (zerop (getf figures :next-failed)) "~{~A~%~}" (getf figures :failures))
    ;; the kills happened, and mostly mid-run, where the bridge had to recover
    (is (< (/ *crash-runs* 2) (getf figures :killed)) "~S" figures)
    (is (< (getf figures :ames-errors) (/ *crash-runs* 5)) "~S" figures)))
