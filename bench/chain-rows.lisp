;;;; bench/chain-rows.lisp -- the chain rows of issue 24's table alone (bench-issue-24.lisp
;;;; runs them with every other row): a chain of N blocks pushed into a wall, every mass
;;;; and width symbolic (N = 8 ... 64, with the growth exponents), and the same chain with
;;;; numbers (N = 32, 64, 128). Run: sbcl --script bench/chain-rows.lisp (or --load it).
;;;; Prints wall times of whole bin/ames runs; asserts nothing. The figures measured are in
;;;; bench/results-issue-24-chains.txt.

(require :asdf)
(defvar cl-user::*issue-24-chains-only* t)
(load (merge-pathnames "bench-issue-24.lisp" *load-truename*))

(in-package #:ames.bench.issue-24)

(let* ((baseline (timed-run '("maxima" "--very-quiet" "--batch-string" "quit();") :runs 3))
       (directory (uiop:ensure-directory-pathname
                   (merge-pathnames (format nil "ames-chains-24-~36R" (random (expt 36 6) (make-random-state t)))
                                    (uiop:temporary-directory)))))
  (ensure-directories-exist directory)
  (row "a bare Maxima start (the baseline)" baseline 0)
  (timed-run (ames "help"))              ; the image built first
  (bench-chain '(8 16 24 32 48 64) directory baseline)
  (format t "  goal: N = 32 under 10 s, growth at most N^1.5, N = 64 under a minute~%")
  (bench-chain '(32 64 128) directory baseline :numbers t)
  (format t "  goal: N = 128 under 10 s~%")
  (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))
