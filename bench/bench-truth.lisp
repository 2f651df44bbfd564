;;;; bench/bench-truth.lisp -- how often DECIDE answers :UNKNOWN on the scenarios of scenarios/.
;;;;
;;;; Every scenario of scenarios/ is simulated on a fresh bridge twice: with its parameters
;;;; symbolic, and with its (:value N) defaults as parameter values (when it has any), an
;;;; ambiguity stopping the run. Every call of ames.algebra:DECIDE made by the layers above
;;;; the bridge (not the bridge's own nested calls; cache hits included) is counted by
;;;; verdict, by encapsulating the function, so the script runs unchanged on an older
;;;; checkout (load that checkout's ames.asd first, then this file) for a before/after
;;;; comparison. Prints numbers; asserts nothing.

(defpackage #:ames.bench.truth
  (:use #:cl)
  (:documentation "The truth benchmark: the share of DECIDE calls answered :UNKNOWN."))

(in-package #:ames.bench.truth)

(defun scenario-files ()
  "The scenario files next to this benchmark, sorted by name."
  (sort (directory (merge-pathnames "../scenarios/*.lisp" *load-truename*))
        #'string< :key #'pathname-name))

(defvar *depth* 0 "How many counted DECIDE calls are under way.")

(defvar *tally* nil "A plist :TRUE :FALSE :UNKNOWN of the outermost DECIDE verdicts.")

(defun call-counting-verdicts (function)
  "Call FUNCTION and return its value and the tally (:TRUE N :FALSE N :UNKNOWN N) of the
outermost DECIDE calls made meanwhile."
  (let ((*tally* (list :true 0 :false 0 :unknown 0)))
    (sb-int:encapsulate 'ames.algebra:decide 'bench-truth
                        (lambda (decide bridge relation)
                          (let ((verdict (let ((*depth* (1+ *depth*)))
                                           (funcall decide bridge relation))))
                            (when (zerop *depth*)
                              (incf (getf *tally* verdict)))
                            verdict)))
    (unwind-protect (values (funcall function) *tally*)
      (sb-int:unencapsulate 'ames.algebra:decide 'bench-truth))))

(defun run-outcome (scenario bridge values)
  "Simulate SCENARIO on BRIDGE with the parameter VALUES; its outcome, or the type of
the condition that ended it."
  (handler-case
      (let ((history (handler-bind ((ames:ambiguous-transition #'ames:stop-simulation))
                       (ames:simulate scenario :bridge bridge :parameter-values values))))
        (ames:history-outcome history))
    (ames:ames-error (condition) (type-of condition))
    ;; a failure of the simulator itself is shown as the outcome, not hidden: the
    ;; benchmark goes on with the next scenario
    (error (condition) (list :failed (type-of condition)))))

(defun measure ()
  "Print the tallies per scenario and run, then the totals."
  (let ((totals (list :true 0 :false 0 :unknown 0)))
    (format t "~&~36A ~8A ~6@A ~6@A ~6@A ~8@A  ~A~%"
            "scenario" "values" "true" "false" "unknown" "unknown%" "outcome")
    (dolist (file (scenario-files))
      (dolist (scenario (ames:read-scenario-file file))
        (dolist (values (remove-duplicates (list '() (ames:scenario-parameter-values scenario))
                                           :test #'equal))
          (let ((bridge (ames.maxima:make-bridge)))
            (unwind-protect
                 (multiple-value-bind (outcome tally)
                     (call-counting-verdicts (lambda () (run-outcome scenario bridge values)))
                   (let ((calls (+ (getf tally :true) (getf tally :false) (getf tally :unknown))))
                     (loop for (key count) on tally by #'cddr do (incf (getf totals key) count))
                     (format t "~36A ~8A ~6D ~6D ~6D ~7,1F%  ~(~A~)~%"
                             (string-downcase (symbol-name (ames:scenario-name scenario)))
                             (if values "defaults" "symbolic")
                             (getf tally :true) (getf tally :false) (getf tally :unknown)
                             (if (plusp calls) (* 100 (/ (getf tally :unknown) calls)) 0)
                             outcome)
                     (finish-output)))
              (ames.maxima:close-bridge bridge))))))
    (let ((calls (+ (getf totals :true) (getf totals :false) (getf totals :unknown))))
      (format t "~&all: ~D DECIDE calls, ~D :TRUE, ~D :FALSE, ~D :UNKNOWN: ~,1F% unknown~%"
              calls (getf totals :true) (getf totals :false) (getf totals :unknown)
              (if (plusp calls) (* 100 (/ (getf totals :unknown) calls)) 0)))))

(measure)
