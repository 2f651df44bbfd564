;;;; t/runner.lisp -- runs every suite and reports FiveAM's result as a plain line.

(in-package #:ames.tests)

(define-condition tests-failed (error)
  ((failed :initarg :failed :reader tests-failed-count))
  (:documentation "Signalled by RUN-ALL-TESTS when any check failed, so that
ASDF:TEST-SYSTEM fails loudly.")
  (:report (lambda (condition stream)
             (format stream "~D AMES test check~:P failed." (tests-failed-count condition)))))

(defun run-ames-tests (&key exit)
  "Run the suite ALL-TESTS, explain the results, and print the plain closing line
'N passed, N failed' (skipped checks are counted on the line before it). With EXIT true, quit Lisp with status 0 when
nothing failed and 1 otherwise; without it, signal TESTS-FAILED on any failure
and return the number of passed checks otherwise."
  (let ((results (run 'all-tests)))
    (explain! results)
    (multiple-value-bind (ok failed skipped) (results-status results)
      (declare (ignore ok))
      (let* ((n-failed (length failed))
             (n-skipped (length skipped))
             (n-passed (- (length results) n-failed n-skipped)))
        (finish-output *error-output*)
        (when (plusp n-skipped)
          (format t "~&~D skipped~%" n-skipped))
        (format t "~&~D passed, ~D failed~%" n-passed n-failed)
        (finish-output)
        (cond (exit (uiop:quit (if (zerop n-failed) 0 1)))
              ((plusp n-failed) (error 'tests-failed :failed n-failed))
              (t n-passed))))))
