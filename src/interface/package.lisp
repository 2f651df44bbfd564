;;;; src/interface/package.lisp -- AMES's user-facing package: the REPL API and the command line.

(defpackage #:ames
  (:use #:cl #:ames.base #:ames.scenario #:ames.simulator #:ames.report)
  (:documentation "AMES's user-facing package: the REPL API (SIMULATE, RUN-FILE and the
accessors on a simulation history, the scenario language's reader and validator, all
re-exported from the layers below) and the command line of bin/ames.")
  (:export
   #:ames-error #:ames-error-context #:ames-error-full-report #:*full-reports*
   #:error-context #:error-context-file #:error-context-line #:error-context-scenario
   #:error-context-location
   ;; the budget of a scenario run (src/base/limits.lisp)
   #:*limits* #:limits #:make-limits #:change-limits #:limits-time-limit
   #:limits-maxima-timeout #:limits-integer-bits #:limits-expression-size
   #:call-with-budget #:with-budget #:invalid-limit
   #:budget-exceeded #:budget-exceeded-quantity #:budget-exceeded-limit
   #:budget-exceeded-amount #:budget-exceeded-subject
   ;; scenario conditions (src/scenario/)
   #:scenario-error #:scenario-error-scenario #:scenario-error-location
   #:scenario-error-clause #:scenario-error-source
   #:scenario-read-error #:scenario-read-error-file #:scenario-read-error-line
   #:scenario-read-error-column #:scenario-read-error-position
   #:scenario-file-error
   #:scenario-syntax-error #:unknown-clause-error #:duplicate-clause-error
   #:missing-property-error #:undeclared-symbol-error #:duplicate-name-error
   #:scenario-expression-error #:scenario-shape-error
   #:contradictory-assumptions-error #:overlapping-bodies-error
   #:scenario-error-cause
   #:skip-scenario
   #:parameter-values-error #:check-parameter-values #:scenario-positions
   ;; scenario objects and the validator (src/scenario/)
   #:scenario #:parse-scenario #:scenario-p
   #:scenario-name #:scenario-description #:scenario-parameters #:scenario-gravity
   #:scenario-bodies #:scenario-forces #:scenario-states #:scenario-until
   #:scenario-queries #:scenario-source #:scenario-form
   #:scenario-parameter #:scenario-parameter-name #:scenario-parameter-assumptions
   #:scenario-parameter-value
   #:scenario-body #:scenario-body-name #:scenario-body-shape #:scenario-body-mass
   #:scenario-body-position #:scenario-body-velocity #:scenario-body-fixed-p #:scenario-body-driven-p
   #:scenario-force #:scenario-force-name #:scenario-force-body #:scenario-force-value
   #:scenario-frictions #:scenario-friction #:scenario-friction-bodies
   #:scenario-friction-static #:scenario-friction-kinetic #:find-scenario-friction
   #:find-scenario-parameter #:find-scenario-body #:find-scenario-force
   #:scenario-assumption-relations #:scenario-parameter-values
   #:scenario-moving-bodies #:scenario-fixed-bodies
   #:shape-kind
   #:constant-value
   ;; reading scenario files (src/scenario/reader.lisp)
   #:read-scenario-forms #:read-scenarios-from-string #:read-scenario-file
   ;; the simulator and its history (src/simulator/, src/report/)
   #:simulate #:run-file #:run-files #:run-scenario #:main #:*bridge* #:current-bridge
   #:stop-simulation
   #:simulation-error #:ambiguous-transition #:ambiguous-transition-candidates
   #:ambiguous-transition-missing-fact #:unsolvable-model #:unsupported-situation
   #:usage-error #:internal-error
   #:simulation-history #:history-scenario #:history-states #:history-outcome
   #:history-notes #:history-rederived #:history-parameter-values
   #:qualitative-state #:state-index #:state-start #:state-duration #:state-contacts
   #:state-accelerations #:state-forces-of #:state-positions #:state-velocities
   #:state-end-event #:state-final-positions #:state-final-velocities #:state-notes
   #:state-initial-velocities #:state-analysis #:state-branches #:history-answers
   #:explain #:explain-files #:scenario-branch #:scenario-all-branches #:*all-branches* #:scenario-restitutions #:scenario-restitution
   #:body-entry
   #:history-sexp #:print-history-sexp #:print-history-text
   #:print-history-latex #:print-history-html #:print-history-svg #:history-svg
   #:history-json #:print-history-json #:json-to-sexp
   ;; the checks through Maxima (src/scenario/semantics.lisp)
   #:check-scenario #:check-scenario-assumptions #:check-scenario-geometry
   #:missing-assumption-error #:missing-assumption-fact
   ;; the numbers of a run (src/scenario/values.lisp)
   #:parameter-value-error #:parameter-value-error-parameter #:parameter-value-error-assumption
   #:check-parameter-values #:run-parameter-values
   #:+exit-complete+ #:+exit-scenario-error+ #:+exit-usage+ #:+exit-undecided+))
