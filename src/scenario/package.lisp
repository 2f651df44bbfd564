;;;; src/scenario/package.lisp -- the scenario language's packages: the one scenario files are read
;;;; into, and the one of the reader and validator.

(defpackage #:ames-scenario
  (:use)
  (:import-from #:cl
                ;; the prefix algebra's operators, so that a file read here and a form
                ;; typed at the REPL (in CL-USER) hold the very same operator symbols
                #:+ #:- #:* #:/ #:expt #:sqrt #:exp #:log
                #:sin #:cos #:tan #:asin #:acos #:atan #:abs
                #:= #:/= #:< #:> #:<= #:>= #:and #:or #:not
                #:pi #:t #:nil)
  (:import-from #:ames.base #:tau)
  (:export
   ;; the words of the scenario language; validated scenarios hold their shapes with
   ;; these symbols whatever package the user's form was written in
   #:scenario #:parameters #:gravity #:body #:force #:simulate #:query
   #:restitution
   #:friction
   #:spring #:pulley #:rope #:gravitation #:hinge
   #:drag
   #:point #:circle #:polygon #:outline #:line #:arc #:segment #:half-plane)
  (:documentation "The package scenario files are read into (with *READ-EVAL* nil and
a restricted readtable). It uses no package: it holds the user's names, and imports
from COMMON-LISP only the prefix algebra's operators, PI, T and NIL. Nothing in it
is ever evaluated."))

(defpackage #:ames.scenario
  (:use #:cl #:ames.base)
  (:documentation "The scenario language: the restricted reader of scenario files (data,
never code), the validator that turns a scenario form into a SCENARIO object or signals a
SCENARIO-ERROR naming the clause or body at fault, and the checks that need the geometry
and Maxima (assumptions, overlaps).")
  (:export
   ;; the event kinds a query may name, set by the knowledge base (queries.lisp)
   #:*event-kinds*
   ;; conditions (conditions.lisp)
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
   #:parameter-values-error
   ;; scenario objects and the validator
   #:scenario #:parse-scenario #:scenario-p #:scenario-positions #:scenario-body-source
   #:scenario-name #:scenario-description #:scenario-parameters #:scenario-gravity
   #:scenario-bodies #:scenario-forces #:scenario-states #:scenario-until
   #:scenario-branch #:scenario-all-branches
   #:scenario-queries #:scenario-source #:scenario-form
   #:scenario-restitutions #:scenario-restitution
   ;; springs, pulleys, ropes, universal gravitation (extensions.lisp)
   #:scenario-extensions #:scenario-springs #:scenario-pulleys #:scenario-ropes
   #:scenario-gravitation #:scenario-spring #:scenario-spring-name #:scenario-spring-from
   #:scenario-spring-to #:scenario-spring-toward #:scenario-spring-stiffness
   #:scenario-spring-rest-length #:scenario-spring-bumper-p
   #:scenario-pulley #:scenario-pulley-name #:scenario-pulley-body #:scenario-pulley-point
   #:find-scenario-pulley
   #:scenario-rope #:scenario-rope-name #:scenario-rope-length #:scenario-rope-through
   #:rope-point-position
   ;; clauses the knowledge base reads as entities (kb-clauses.lisp, drag.lisp)
   #:scenario-kb-clauses
   #:scenario-parameter #:scenario-parameter-name #:scenario-parameter-assumptions
   #:scenario-parameter-value
   #:scenario-body #:scenario-body-name #:scenario-body-shape #:scenario-body-mass
   #:scenario-body-position #:scenario-body-velocity #:scenario-body-fixed-p
   #:scenario-body-driven-p
   ;; rotation (rotation.lisp, inertia.lisp)
   #:scenario-body-inertia #:scenario-body-inertia-kind #:scenario-body-angle
   #:scenario-body-angular-velocity #:scenario-body-rotating-p #:scenario-rotating-bodies
   #:scenario-force-point #:scenario-rope-wound-ends
   #:scenario-hinge #:scenario-hinges #:scenario-hinge-name #:scenario-hinge-body
   #:scenario-hinge-point #:find-scenario-hinge #:shape-inertia #:centroid
   #:scenario-awaiting #:scenario-body-start-shape #:turned-shape
   #:scenario-force #:scenario-force-name #:scenario-force-body #:scenario-force-value
   #:scenario-frictions #:scenario-friction #:scenario-friction-bodies
   #:scenario-friction-static #:scenario-friction-kinetic #:find-scenario-friction
   #:find-scenario-parameter #:find-scenario-body #:find-scenario-force
   #:scenario-assumption-relations #:scenario-parameter-values
   #:scenario-moving-bodies #:scenario-fixed-bodies
   #:shape-kind
   #:constant-value
   ;; reading scenario files
   #:read-scenario-forms #:read-scenarios-from-string #:read-scenario-file
   #:source-text #:source-text-p #:source-text-file #:form-line #:decode-utf-8
   ;; the checks through Maxima and the geometry
   #:check-scenario #:check-scenario-assumptions #:check-scenario-geometry
   #:missing-assumption-error #:missing-assumption-fact
   ;; the world the checks built and the run receives (world.lisp)
   #:world #:make-world #:world-scenario #:world-shapes #:world-pairs #:world-shape
   #:world-simple-contacts #:world-deferred-pairings #:world-pair-ordinals
   #:*pair-screen* #:world-with-pairings
   ;; the numbers of a run (values.lisp)
   #:parameter-value-error #:parameter-value-error-parameter #:parameter-value-error-assumption
   #:check-parameter-values #:run-parameter-values #:admissible-parameter-values))
