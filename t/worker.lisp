;;;; t/worker.lisp -- one test worker process of `make test` (see t/parallel-runner.lisp):
;;;; loads the compiled system once, then runs the tests named on its standard input one by
;;;; one, answering each with its result on its standard output.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(let ((*standard-output* *error-output*))   ; compiler chatter stays off the result channel
  (asdf:load-system "ames/tests"))
(uiop:symbol-call :ames.tests :serve-tests)
