;;;; t/run.lisp -- command-line test entry: load the checkout's ames.asd, run every suite
;;;; (or the suites and tests AMES_TESTS names, e.g. AMES_TESTS=simulator,cli make test).
;;;; Used by `make test` and .ci/run. The tests run in parallel worker processes (see
;;;; t/parallel-runner.lisp; AMES_TEST_JOBS sets how many, AMES_TEST_JOBS=1 still uses one
;;;; worker process). The last line is 'N passed, N failed'; exits 0 when every check passed,
;;;; 1 otherwise.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames/tests")
(uiop:symbol-call :ames.tests :run-ames-tests-in-parallel :exit t)
