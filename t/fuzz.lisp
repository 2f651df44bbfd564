;;;; t/fuzz.lisp -- `make fuzz`: the nightly-size whole-path fuzz and crash-safety runs, their figures printed.
;;;;
;;;; FUZZ_FORMS (default 10000) whole-path fuzz cases (t/reliability-fuzz.lisp) and
;;;; FUZZ_CRASH_RUNS (default 500) runs with a kill -9 of Maxima (t/reliability-crash.lisp);
;;;; FUZZ_SEED changes the fuzz's seed; then the suite LONG-CHECKS (the order check over
;;;; every scenario, t/reliability-runs.lisp). Exits 0 when every target is met (no other
;;;; condition, no hang, no lost scenario, no changed output), 1 otherwise.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames/tests")

(in-package #:ames.tests)

(flet ((setting (name default)
         (let ((text (uiop:getenv name)))
           (or (and text (parse-integer text :junk-allowed t)) default))))
  (let* ((forms (setting "FUZZ_FORMS" 10000))
         (crash-runs (setting "FUZZ_CRASH_RUNS" 500))
         (seed (setting "FUZZ_SEED" *fuzz-seed*))
         (start (get-internal-real-time))
         (figures (fuzz-figures forms :seed seed))
         (fuzz-seconds (seconds-since start))
         (crash (crash-safety-figures crash-runs :seed (+ seed 1)))
         (crash-seconds (- (seconds-since start) fuzz-seconds)))
    (print-fuzz-figures figures)
    (format t "  (~,1F s)~%" fuzz-seconds)
    (format t "Crash safety: ~D runs with a kill -9 of Maxima (~D killed mid-run or between ~
               requests): ~D identical outputs, ~D AMES-ERRORs, ~D changed outputs, ~D next ~
               scenarios that failed (~,1F s)~%~{  ~A~%~}"
            (getf crash :runs) (getf crash :killed) (getf crash :identical)
            (getf crash :ames-errors) (getf crash :different) (getf crash :next-failed)
            crash-seconds (getf crash :failures))
    (finish-output)
    ;; the full-size repetitions of checks `make test` runs on a sample
    (let ((long (explain! (run 'long-checks))))
      (finish-output)
      (uiop:quit (if (and long
                          (every #'zerop (list (getf figures :other) (getf figures :hangs)
                                               (getf figures :lost) (getf figures :control-failed)
                                               (getf crash :different) (getf crash :next-failed))))
                     0 1)))))
