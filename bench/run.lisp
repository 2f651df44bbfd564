;;;; bench/run.lisp -- `make bench`: load AMES, then run every bench/bench-*.lisp in name order.
;;;; Benchmarks print numbers; they assert nothing.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")
(dolist (file (sort (directory (merge-pathnames "bench-*.lisp" *load-truename*))
                    #'string< :key #'namestring))
  (format t "~&~%==== ~A ====~%" (pathname-name file))
  (finish-output)
  (load file))
