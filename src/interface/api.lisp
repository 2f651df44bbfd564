;;;; src/interface/api.lisp -- AMES's public API, read as a tour: every symbol the package AMES exports, in the order a session uses them.
;;;;
;;;; This file is the one list of AMES's exports (the DEFPACKAGE in package.lisp exports
;;;; nothing itself). Each section says what a part of the API is for and exports its
;;;; symbols; the functions are defined in the layers named, each with a docstring that
;;;; states its contract (t/api.lisp checks that every exported function, macro, class
;;;; and variable is documented).
;;;;
;;;; A session at the REPL:
;;;;   (defvar *wedge* (first (ames:read-scenario-file "scenarios/particle-on-wedge.lisp")))
;;;;   (defvar *history* (ames:simulate *wedge*))
;;;;   (ames:print-history-text *history* *standard-output*)
;;;;   (ames:explain *history* :state 0)
;;;; or, as bin/ames does it, (ames:run-file "scenarios/particle-on-wedge.lisp" :numeric t).

(in-package #:ames)

(defmacro define-api (&body symbols)
  "Export SYMBOLS (read in the package AMES, so a symbol of a layer below is re-exported)
from AMES, at compile time too: one section of the tour."
  `(eval-when (:compile-toplevel :load-toplevel :execute)
     (export ',symbols '#:ames)))

;;; 1. Reading a scenario (src/scenario/reader.lisp, objects.lisp).
;;; A scenario file is data: it is read with *READ-EVAL* NIL into the package
;;; AMES-SCENARIO, never evaluated, and validated into a SCENARIO object whose accessors
;;; give its parameters, bodies, forces, friction and queries. PARSE-SCENARIO validates a
;;; form typed at the REPL the same way.

(define-api
  read-scenario-file read-scenarios-from-string read-scenario-forms
  scenario parse-scenario scenario-p
  scenario-name scenario-description scenario-parameters scenario-gravity
  scenario-bodies scenario-forces scenario-states scenario-until
  scenario-queries scenario-source scenario-form scenario-positions
  scenario-parameter scenario-parameter-name scenario-parameter-assumptions
  scenario-parameter-value
  scenario-body scenario-body-name scenario-body-shape scenario-body-mass
  scenario-body-position scenario-body-velocity scenario-body-fixed-p scenario-body-driven-p
  scenario-force scenario-force-name scenario-force-body scenario-force-value
  scenario-frictions scenario-friction scenario-friction-bodies
  scenario-friction-static scenario-friction-kinetic find-scenario-friction
  find-scenario-parameter find-scenario-body find-scenario-force
  scenario-assumption-relations scenario-parameter-values admissible-parameter-values
  scenario-moving-bodies scenario-fixed-bodies
  scenario-branch scenario-all-branches scenario-restitutions scenario-restitution
  shape-kind constant-value)

;;; 2. Checking it through Maxima, and the world it builds (src/scenario/semantics.lisp,
;;; world.lisp).
;;; What numbers cannot decide (a positive mass, a counter-clockwise polygon, no overlap
;;; at the start) is decided under the scenario's assumptions. The check parses every
;;; shape and builds the contacts of every two bodies: that WORLD is what the simulation
;;; runs in, so the geometry is derived once.

(define-api
  check-scenario check-scenario-assumptions check-scenario-geometry
  world world-scenario world-shapes world-pairs world-shape world-simple-contacts
  missing-assumption-error missing-assumption-fact)

;;; 3. The numbers of a run (src/scenario/objects.lisp, values.lisp).
;;; A run may be given parameter values (bin/ames --set, --numeric for the (:value N)
;;; defaults): checked for their form once, by CHECK-PARAMETER-VALUES, and against every
;;; declared assumption by RUN-PARAMETER-VALUES.

(define-api
  check-parameter-values run-parameter-values
  parameter-values-error
  parameter-value-error parameter-value-error-parameter parameter-value-error-assumption)

;;; 4. Simulating (src/simulator/simulate.lisp).
;;; SIMULATE splits the motion into qualitative states and returns a SIMULATION-HISTORY.
;;; Where the assumptions leave a transition open it signals AMBIGUOUS-TRANSITION with the
;;; restart STOP-SIMULATION (or forks, when the scenario asks for branches).

(define-api
  simulate *bridge* current-bridge stop-simulation *all-branches*
  simulation-error ambiguous-transition ambiguous-transition-candidates
  ambiguous-transition-missing-fact unsolvable-model unsupported-situation)

;;; 5. What a simulation returns (src/simulator/history.lisp).
;;; A history holds its states in order; a state, the contacts that hold, the forces the
;;; knowledge base reports, the motion in closed form over the state's own time TAU, how
;;; it ends, and its notes, each through its own accessor.

(define-api
  simulation-history history-scenario history-states history-outcome
  history-notes history-rederived history-parameter-values history-answers
  qualitative-state state-index state-start state-duration state-contacts state-contact-points
  state-accelerations state-forces-of state-positions state-velocities
  state-initial-velocities state-end-event state-final-positions state-final-velocities
  state-analysis state-branches body-entry
  ;; the notes
  state-notes state-numbers state-accumulation state-impact state-end-arc-length
  state-numeric-trajectory state-simultaneous-events state-periodic
  state-undecided-detail state-path-coordinates state-line-coordinates
  state-missing-fact state-fork-p state-reported-sections)

;;; 6. Reports (src/report/).
;;; For programs, the readable s-expression of the scenario language's output section and
;;; the same as JSON; for people, text, LaTeX, an SVG picture and an HTML page; EXPLAIN
;;; tells how AMES reached a state (its consistency argument, equations and end).

(define-api
  history-sexp print-history-sexp history-json print-history-json json-to-sexp
  print-history-text print-history-latex print-history-html
  history-svg print-history-svg
  explain)

;;; 7. Running files as bin/ames does (src/interface/runs.lisp, command-line.lisp, cli.lisp).
;;; RUN-SCENARIO is one run with a fresh bridge, a budget and errors that say where;
;;; RUN-FILE and RUN-FILES run every scenario of files; MAIN is bin/ames.

(define-api
  run-scenario run-file run-files explain-files main
  skip-scenario usage-error internal-error
  +exit-complete+ +exit-scenario-error+ +exit-usage+ +exit-undecided+)

;;; 8. The budget of a run (src/base/limits.lisp).
;;; Every run has limits of wall time, of Maxima's time per request, and of the size of
;;; numbers and expressions; going over one signals BUDGET-EXCEEDED.

(define-api
  *limits* limits make-limits change-limits limits-time-limit
  limits-maxima-timeout limits-integer-bits limits-expression-size
  call-with-budget with-budget invalid-limit
  budget-exceeded budget-exceeded-quantity budget-exceeded-limit
  budget-exceeded-amount budget-exceeded-subject)

;;; 9. Conditions (src/base/conditions.lisp, src/scenario/conditions.lisp).
;;; Everything a user can meet is an AMES-ERROR; an error about a scenario is a
;;; SCENARIO-ERROR naming the clause, the body or the form at fault, with the place
;;; (ERROR-CONTEXT: file, line, scenario).

(define-api
  ames-error ames-error-context ames-error-full-report *full-reports*
  error-context error-context-file error-context-line error-context-scenario
  error-context-location
  scenario-error scenario-error-scenario scenario-error-location
  scenario-error-clause scenario-error-source scenario-error-cause
  scenario-read-error scenario-read-error-file scenario-read-error-line
  scenario-read-error-column scenario-read-error-position
  scenario-file-error
  scenario-syntax-error unknown-clause-error duplicate-clause-error
  missing-property-error undeclared-symbol-error duplicate-name-error
  scenario-expression-error scenario-shape-error
  contradictory-assumptions-error overlapping-bodies-error)

;;; The readers of the classes above are documented by their slots: each gets its slot's
;;; documentation as its docstring (DESCRIBE and the documentation test read it there).

(defun document-readers-from-slots (class)
  "Give every reader of the slots of the standard CLASS that has no docstring its slot's
documentation. Returns CLASS."
  (dolist (slot (sb-mop:class-direct-slots class) class)
    (let ((text (documentation slot t)))
      (when text
        (dolist (reader (sb-mop:slot-definition-readers slot))
          (unless (documentation reader 'function)
            (setf (documentation reader 'function) text)))))))

(do-external-symbols (symbol '#:ames)
  (let ((class (find-class symbol nil)))
    (when (typep class 'standard-class)
      (document-readers-from-slots class))))
