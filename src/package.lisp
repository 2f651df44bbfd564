;;;; src/package.lisp -- AMES's user-facing package: the simulator, the REPL API, the CLI.

(defpackage #:ames
  (:use #:cl #:ames.base)
  (:documentation "The qualitative-state simulator and the user-facing API:
SIMULATE, RUN-FILE and the accessors on a simulation history.")
  (:export #:ames-error))
