;;;; t/fuzz.lisp -- `make fuzz`: the nightly-size whole-path fuzz and crash-safety runs, their figures printed.
;;;;
;;;; FUZZ_FORMS (default 10000) whole-path fuzz cases (t/reliability-fuzz.lisp),
;;;; FUZZ_CRASH_RUNS (default 500) runs with a kill -9 of Maxima (t/reliability-crash.lisp),
;;;; FUZZ_OUTPUT_FORMS (default 500) hostile scenarios, with extension clauses, written in
;;;; every format and checked well-formed, and FUZZ_PROCESS_RUNS (default 60) runs of
;;;; bin/ames under signals and through pipes (t/hardening-fuzz.lisp); each 0 skips its
;;;; part. FUZZ_SEED changes the fuzz's seed; then the suite LONG-CHECKS (the order check over
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
         (crash-seconds (- (seconds-since start) fuzz-seconds))
         (output (output-fuzz-figures (setting "FUZZ_OUTPUT_FORMS" 500) :seed seed))
         (output-seconds (- (seconds-since start) fuzz-seconds crash-seconds))
         (process (process-fuzz-figures (setting "FUZZ_PROCESS_RUNS" 60) :seed seed))
         (process-seconds (- (seconds-since start) fuzz-seconds crash-seconds output-seconds)))
    (print-fuzz-figures figures)
    (format t "  (~,1F s)~%" fuzz-seconds)
    (format t "Crash safety: ~D runs with a kill -9 of Maxima (~D killed mid-run or between ~
               requests): ~D identical outputs, ~D AMES-ERRORs, ~D changed outputs, ~D next ~
               scenarios that failed (~,1F s)~%~{  ~A~%~}"
            (getf crash :runs) (getf crash :killed) (getf crash :identical)
            (getf crash :ames-errors) (getf crash :different) (getf crash :next-failed)
            crash-seconds (getf crash :failures))
    (print-output-fuzz-figures output)
    (format t "  (~,1F s)~%" output-seconds)
    (print-process-fuzz-figures process)
    (format t "  (~,1F s)~%" process-seconds)
    (finish-output)
    ;; the full-size repetitions of checks `make test` runs on a sample
    (let ((long (explain! (run 'long-checks))))
      (finish-output)
      (uiop:quit (if (and long
                          (every #'zerop (list (getf figures :other) (getf figures :hangs)
                                               (getf figures :lost) (getf figures :control-failed)
                                               (getf crash :different) (getf crash :next-failed)
                                               (getf process :failed)))
                          (output-fuzz-clean-p output))
                     0 1)))))
