;;;; src/interface/package.lisp -- AMES's user-facing package: the REPL API and the command line.

(defpackage #:ames
  (:use #:cl #:ames.base #:ames.scenario #:ames.simulator #:ames.report)
  (:documentation "AMES's user-facing package: the REPL API (SIMULATE, RUN-FILE and the
accessors on a simulation history, the scenario language's reader and validator, all
re-exported from the layers below) and the command line of bin/ames. Its exports are
listed, section by section, in api.lisp: the tour of AMES."))
