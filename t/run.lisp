;;;; t/run.lisp -- command-line test entry: load the checkout's ames.asd, run every suite.
;;;; Used by `make test` and .ci/run. Exits 0 when every check passed, 1 otherwise.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames/tests")
(uiop:symbol-call :ames.tests :run-ames-tests :exit t)
