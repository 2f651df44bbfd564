;;;; src/engine/package.lisp -- the package of the model-component engine and DEFCOMPONENT.

(defpackage #:ames.engine
  (:use #:cl #:ames.base)
  (:documentation "DEFCOMPONENT and the engine that builds the model of a qualitative
state (thesis sections 3.2.2 and 3.2.3). Domain-free: a KNOWLEDGE-BASE holds model
components and named template functions; a SITUATION holds the scenario's entities
as data; an ENGINE instantiates every component for every binding of its arguments,
in the order of the components' qualitative data dependencies, and records every
instance and assertion as a justified belief in a JTMS (package AMES.TMS). The
resulting MODEL yields the equations of the state and its termination conditions;
APPLY-TRANSITION updates it incrementally and CHECK-INCREMENTAL compares it with a
rebuild from scratch. Quantitative conditions are decided by a caller's DECIDER
function, so the engine never talks to Maxima itself.")
  (:export
   ;; knowledge bases and components
   #:knowledge-base #:make-knowledge-base #:knowledge-base-p #:knowledge-base-name
   #:knowledge-base-components #:find-component #:register-component #:remove-component
   #:register-template #:find-template #:template-function #:template-documentation
   #:component-order #:component-dependencies
   #:defcomponent #:parse-component
   #:component #:component-p #:component-name #:component-documentation
   #:component-definition #:component-argument-variables #:component-mode-names
   ;; situations
   #:situation #:make-situation #:situation-p #:situation-entities #:situation-data
   #:find-entity #:entities-of-kind
   #:entity #:entity-p #:entity-kind #:entity-name #:entity-properties #:entity-property
   ;; engines and models
   #:engine #:make-engine #:engine-p #:engine-knowledge-base
   #:build-model #:model #:model-p #:model-engine #:model-situation #:model-jtms
   #:model-decider
   #:model-equations #:model-beliefs #:model-active-instances #:model-instances
   #:model-termination-conditions #:model-decisions #:model-basis-decisions
   #:find-instance #:find-node #:explain
   #:instance #:instance-p #:instance-key #:instance-component #:instance-bindings
   #:instance-node #:instance-active-p #:instance-qualified-p #:instance-mode
   #:instance-equations #:instance-collections
   #:termination-condition #:termination-condition-p #:termination-condition-kind
   #:termination-condition-instance #:termination-condition-relation
   #:termination-condition-change #:termination-condition-event
   #:termination-condition-impact
   ;; choices left open at the start of a state
   #:choice-point #:choice-point-p #:choice-point-instance #:choice-point-kind
   #:choice-point-options #:choice-point-current #:choice-point-relations
   #:model-choice-points #:choice-change #:stale-activation-changes #:stale-mode-changes
   ;; the equalities the current modes hold (held-entries.lisp)
   #:held-entry-equations
   #:unsettled-active-instances
   ;; transitions and the incremental check
   #:apply-transition #:transition-report #:transition-report-changes
   #:transition-report-rederived #:transition-report-rederived-count
   #:rebuild-from-scratch #:model-difference #:check-incremental
   ;; conditions and restarts
   #:engine-error #:component-definition-error #:component-definition-error-component
   #:component-definition-error-clause
   #:component-dependency-cycle #:dependency-cycle-components
   #:unknown-component #:situation-error #:template-expansion-error
   #:duplicate-instance #:missing-decider #:invalid-decision
   #:undecided-relation #:undecided-relation-instance #:undecided-relation-relation
   #:use-decision
   #:mode-selection-error #:mode-selection-error-candidates #:choose-mode
   #:invalid-change #:incremental-mismatch #:incremental-mismatch-difference))
