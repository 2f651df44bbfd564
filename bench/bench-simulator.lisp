;;;; bench/bench-simulator.lisp -- the simulator end to end on every scenario file, against a bare Maxima.
;;;;
;;;; For each scenario of scenarios/: the wall time of AMES::SIMULATE on a fresh bridge
;;;; (Maxima's start included) and again on the same, warm bridge; Maxima round trips per
;;;; state and cache hits (AMES.MAXIMA:BRIDGE-STATISTICS); the instances the engine
;;;; re-derived at each transition (HISTORY-REDERIVED); and the ratio of the cold
;;;; end-to-end time to one bare `maxima -b` script that solves the same models (the
;;;; SOLVE-EQUATIONS requests of the run, recorded by encapsulating that function, written
;;;; out by AMES.MAXIMA:SOLVE-SCRIPT). The target for that ratio is 1.5 at most.
;;;; The first cold run is instrumented (time by bridge operation); the ratio compares the
;;;; best of *RUNS* uninstrumented cold runs (each on a fresh bridge) with the best of
;;;; *RUNS* runs of the bare script, since the machine's noise is large.
;;;; Prints numbers; asserts nothing.

(defpackage #:ames.bench.simulator
  (:use #:cl)
  (:documentation "The simulator benchmark."))

(in-package #:ames.bench.simulator)

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) (float internal-time-units-per-second 1d0)))

(defparameter *runs* 3
  "How many times the cold run and the bare script are timed (the best counts).")

(defun scenario-files ()
  "The scenario files of the checkout, sorted by name."
  (sort (directory (merge-pathnames "../scenarios/*.lisp" *load-truename*))
        #'string< :key #'pathname-name))

(defun call-recording-solves (function)
  "Call FUNCTION; return its value and the list of (EQUATIONS UNKNOWNS FACTS) of every
AMES.MAXIMA:SOLVE-EQUATIONS request made meanwhile (FACTS: the assumptions in force)."
  (let ((solves '()))
    (sb-int:encapsulate 'ames.maxima:solve-equations 'bench-record
                        (lambda (solve bridge equations unknowns)
                          (push (list equations unknowns (ames.maxima:current-assumptions bridge))
                                solves)
                          (funcall solve bridge equations unknowns)))
    (unwind-protect (values (funcall function) (reverse solves))
      (sb-int:unencapsulate 'ames.maxima:solve-equations 'bench-record))))

(defparameter *bridge-operations*
  '(ames.maxima:simplify ames.maxima:solve-equations ames.algebra:decide ames.maxima:equivalent-p
    ames.algebra:earliest-root ames.maxima:numeric-value ames.maxima:call-with-assumptions)
  "The bridge's operations whose calls and time the benchmark breaks the run down by.")

(defun call-timing-bridge-operations (function)
  "Call FUNCTION; return its value and an alist (OPERATION CALLS SECONDS) of the
outermost calls of each of *BRIDGE-OPERATIONS* made meanwhile: an operation called by
another is not counted apart, and CALL-WITH-ASSUMPTIONS counts its set-up and
tear-down, not its body."
  (let ((table (mapcar (lambda (operation) (list operation 0 0d0)) *bridge-operations*))
        (depth 0))
    (flet ((timer (entry)
             (lambda (original &rest arguments)
               (if (plusp depth)
                   (apply original arguments)
                   (let ((start (get-internal-real-time)))
                     (incf (second entry))
                     (incf depth)
                     (unwind-protect
                          (if (eq (first entry) 'ames.maxima:call-with-assumptions)
                              (destructuring-bind (bridge facts thunk) arguments
                                (funcall original bridge facts
                                         (lambda ()
                                           (incf (third entry) (seconds-since start))
                                           (decf depth)
                                           (unwind-protect (funcall thunk)
                                             (incf depth)
                                             (setf start (get-internal-real-time))))))
                              (apply original arguments))
                       (decf depth)
                       (incf (third entry) (seconds-since start))))))))
      (dolist (entry table)
        (sb-int:encapsulate (first entry) 'bench-timing (timer entry))))
    (unwind-protect (values (funcall function) table)
      (dolist (entry table)
        (sb-int:unencapsulate (first entry) 'bench-timing)))))

(defun simulate-outcome (scenario bridge)
  "The history of SCENARIO (an ambiguous transition stops the run), or the AMES-ERROR
that ended it."
  (handler-case (handler-bind ((ames::ambiguous-transition #'ames::stop-simulation))
                  (ames::simulate scenario :bridge bridge))
    (ames:ames-error (condition) condition)))

(defun bare-maxima-seconds (solves)
  "Wall seconds of one `maxima -b` run of a script solving every model of SOLVES, and
its exit code."
  (let ((file (uiop:tmpize-pathname (merge-pathnames "ames-bench-solve.mac"
                                                     (uiop:temporary-directory)))))
    (unwind-protect
         (progn
           (with-open-file (stream file :direction :output :if-exists :supersede)
             (dolist (solve solves)
               (destructuring-bind (equations unknowns facts) solve
                 (write-string (ames.maxima:solve-script equations unknowns :facts facts) stream))))
           (let ((start (get-internal-real-time)))
             (multiple-value-bind (output error-output code)
                 (uiop:run-program (list "maxima" "--very-quiet" "-b" (namestring file))
                                   :output :string :error-output :string :ignore-error-status t)
               (declare (ignore output error-output))
               (values (seconds-since start) code))))
      (delete-file file))))

(defun cold-seconds (scenario)
  "Wall seconds of one uninstrumented run of SCENARIO on a fresh bridge, Maxima's start
included."
  (let ((bridge (ames.maxima:make-bridge))
        (start (get-internal-real-time)))
    (unwind-protect (progn (simulate-outcome scenario bridge) (seconds-since start))
      (ames.maxima:close-bridge bridge))))

(defun describe-outcome (outcome)
  "One word or so on how a run ended."
  (if (typep outcome 'ames::simulation-history)
      (format nil "~(~A~), ~D state~:P" (ames::history-outcome outcome)
              (length (ames::history-states outcome)))
      (format nil "~A" (type-of outcome))))

(defun bench-scenario (scenario)
  "Measure SCENARIO and print one block of numbers."
  (let ((bridge (ames.maxima:make-bridge)))
    (unwind-protect
         (let* ((start (get-internal-real-time))
                (outcome nil) (solves nil) (operation-times nil))
           (let ((timings nil))
             (multiple-value-setq (outcome solves)
               (call-recording-solves
                (lambda ()
                  (multiple-value-bind (outcome table)
                      (call-timing-bridge-operations (lambda () (simulate-outcome scenario bridge)))
                    (setf timings table)
                    outcome))))
             (setf operation-times timings))
           (let* ((cold (seconds-since start))
                  (statistics (ames.maxima:bridge-statistics bridge))
                  (states (if (typep outcome 'ames::simulation-history)
                              (length (ames::history-states outcome))
                              0))
                  (rederived (and (typep outcome 'ames::simulation-history)
                                  (ames::history-rederived outcome))))
             (ames.maxima:reset-bridge-statistics bridge)
             (let* ((warm-start (get-internal-real-time))
                    (warm-outcome (simulate-outcome scenario bridge))
                    (warm (seconds-since warm-start))
                    (warm-statistics (ames.maxima:bridge-statistics bridge)))
               (declare (ignore warm-outcome))
               (format t "~&~(~A~): ~A~%" (ames:scenario-name scenario) (describe-outcome outcome))
               (format t "  wall time: ~,3F s cold (Maxima started), ~,3F s warm (cached)~%"
                       cold warm)
               (format t "  Maxima: ~D requests, ~D round trips (~:[no state recorded~;~:*~,1F per state~]), ~D cache hits; ~,3F s inside Maxima~%"
                       (getf statistics :calls) (getf statistics :maxima-calls)
                       (and (plusp states) (/ (getf statistics :maxima-calls) states))
                       (getf statistics :cache-hits) (getf statistics :maxima-seconds))
               (format t "  time by bridge operation (outermost calls; the first one starts Maxima):~%")
               (loop for (operation calls seconds) in operation-times
                     when (plusp calls)
                       do (format t "    ~(~22A~) ~4D calls ~7,3F s~%" operation calls seconds))
               (format t "  warm run: ~D requests, ~D round trips, ~D cache hits~%"
                       (getf warm-statistics :calls) (getf warm-statistics :maxima-calls)
                       (getf warm-statistics :cache-hits))
               (format t "  instances re-derived per transition: ~:[none (no transition)~;~:*~{~D~^ ~}~]~%"
                       rederived)
               (when (typep outcome 'ames::simulation-history)
                 (let* ((sizes (getf (ames::history-notes outcome) :model-sizes))
                        (solves (getf sizes :solves))
                        (free (length (ames:scenario-moving-bodies scenario))))
                   (when (and solves (plusp solves) (plusp free))
                     (format t "  equations per free body in a solved model: ~,1F as the components assert them, ~,1F after eliminating definitions (target <= 6; ~D solves)~%"
                             (/ (getf sizes :equations-before) solves free)
                             (/ (getf sizes :equations-after) solves free)
                             solves))))
               (let ((best-cold (reduce #'min (loop repeat *runs* collect (cold-seconds scenario)))))
                 (format t "  cold, uninstrumented: ~,3F s (best of ~D)~%" best-cold *runs*)
                 (if solves
                     (let ((code 0) (bare nil))
                       (loop repeat *runs*
                             do (multiple-value-bind (seconds exit) (bare-maxima-seconds solves)
                                  (setf bare (if bare (min bare seconds) seconds))
                                  (unless (eql exit 0) (setf code exit))))
                       (format t "  bare maxima -b solving the same ~D model~:P: ~,3F s (best of ~D)~@[ (exit ~D)~]; ratio ~,2F (target <= 1.5)~%"
                               (length solves) bare *runs* (and (/= code 0) code) (/ best-cold bare)))
                     (format t "  no model was solved (nothing to compare with a bare Maxima)~%"))))))
      (ames.maxima:close-bridge bridge))))

(dolist (file (scenario-files))
  (multiple-value-bind (scenarios conditions) (ames:read-scenario-file file :on-error :collect)
    (dolist (condition conditions)
      (format t "~&~A: ~A~%" (pathname-name file) condition))
    (mapc #'bench-scenario scenarios)))
