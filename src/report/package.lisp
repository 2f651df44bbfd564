;;;; src/report/package.lisp -- the package of the reports: a simulation history for people and
;;;; for programs.

(defpackage #:ames.report
  (:use #:cl #:ames.base #:ames.scenario #:ames.simulator)
  (:documentation "Reports of a simulation history: the text report for people and the
readable s-expression of the scenario language's output section.")
  (:export #:history-sexp #:state-sexp #:state-forces-of #:print-history-sexp
           #:print-history-text #:infix))
