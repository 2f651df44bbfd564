;;;; src/engine/conditions.lisp -- the conditions of the component engine, and its restarts.

(in-package #:ames.engine)

(define-condition engine-error (ames-error) ()
  (:documentation "The parent of every condition the component engine signals (its
report, unless a subclass has its own, is AMES-ERROR's: the detail and the datum)."))

(define-condition component-definition-error (engine-error)
  ((component :initarg :component :initform nil
              :reader component-definition-error-component
              :documentation "The name of the component being defined.")
   (section :initarg :section :initform nil
            :documentation "The section enclosing the faulty clause, when it helps."))
  (:documentation "A DEFCOMPONENT form (or the data given to PARSE-COMPONENT) is
malformed. DATUM is the smallest clause at fault (read it with
COMPONENT-DEFINITION-ERROR-CLAUSE); DETAIL says what is wrong. DEFCOMPONENT signals
it at macroexpansion time.")
  (:report (lambda (condition stream)
             (format-report stream "Malformed DEFCOMPONENT ~S: ~A~%  clause: ~S~
                                    ~@[~%  in section: ~S~]"
                            (component-definition-error-component condition)
                            (ames-error-detail condition)
                            (ames-error-datum condition)
                            (let ((section (slot-value condition 'section)))
                              (and (not (eq section (ames-error-datum condition))) section))))))

(defun component-definition-error-clause (condition)
  "The clause at fault in a COMPONENT-DEFINITION-ERROR."
  (ames-error-datum condition))

(define-condition component-dependency-cycle (engine-error)
  ((components :initarg :components :reader dependency-cycle-components
               :documentation "The names of the components on the cycle, in order."))
  (:documentation "The qualitative data dependencies of a knowledge base's components
form a cycle (each reads a belief the previous one asserts), so there is no order
in which to instantiate them.")
  (:report (lambda (condition stream)
             (format-report stream "The components ~{~S~^ -> ~} -> ~S depend on each other's ~
                                    assertions: there is no order to instantiate them in."
                            (dependency-cycle-components condition)
                            (first (dependency-cycle-components condition))))))

(define-condition unknown-component (engine-error) ()
  (:documentation "A knowledge base has no component of the name given (DATUM)."))

(define-condition situation-error (engine-error) ()
  (:documentation "The entities given to MAKE-SITUATION are malformed. DATUM is the
faulty entity description."))

(define-condition template-expansion-error (engine-error)
  ((instance :initarg :instance :initform nil
             :documentation "The key of the instance whose template was expanded.")
   (template :initarg :template :initform nil
             :documentation "The template form as the component wrote it."))
  (:documentation "Expanding a component's condition or equation template for an
instance did not give an expression of the algebra of the right kind (or template
functions called each other without end). DATUM is the expansion at fault.")
  (:report (lambda (condition stream)
             (format-report stream "~A~%  instance: ~S~%  template: ~S~%  expansion: ~S"
                            (ames-error-detail condition)
                            (slot-value condition 'instance) (slot-value condition 'template)
                            (ames-error-datum condition)))))

(define-condition duplicate-instance (engine-error) ()
  (:documentation "Two different bindings of a component's arguments give the same
instance key (the values of its declared argument variables). DATUM is the key. The
component's arguments should name what distinguishes the bindings."))

(define-condition missing-decider (engine-error) ()
  (:documentation "A quantitative condition must be decided but no decider was
given. DATUM is the relation."))

(define-condition invalid-decision (engine-error) ()
  (:documentation "A decider returned something other than :TRUE, :FALSE or
:UNKNOWN, or a restart was given such a value. DATUM is the value."))

(define-condition undecided-relation (engine-error)
  ((instance :initarg :instance :reader undecided-relation-instance
             :documentation "The key of the instance whose condition is undecided.")
   (relation :initarg :relation :reader undecided-relation-relation
             :documentation "The relation the decider answered :UNKNOWN for."))
  (:documentation "The decider could not decide a quantitative activation or mode
entry condition (it answered :UNKNOWN): the engine does not guess. The restart
USE-DECISION (value :TRUE or :FALSE) supplies the answer, which the model records as
assumed. DATUM is the relation.")
  (:report (lambda (condition stream)
             (format-report stream "Cannot decide whether ~S holds in the initial state,~%  ~
                                    needed by the instance ~S."
                            (undecided-relation-relation condition)
                            (undecided-relation-instance condition)))))

(defun use-decision (decision &optional condition)
  "Invoke the USE-DECISION restart of CONDITION (an UNDECIDED-RELATION, the most
recent when NIL) with DECISION, :TRUE or :FALSE."
  (let ((restart (find-restart 'use-decision condition)))
    (unless restart (error 'control-error))
    (invoke-restart restart decision)))

(define-condition mode-selection-error (engine-error)
  ((instance :initarg :instance :initform nil
             :documentation "The key of the instance whose mode is sought.")
   (candidates :initarg :candidates :initform '() :reader mode-selection-error-candidates
               :documentation "The modes whose entry conditions hold (several), or
NIL when none holds."))
  (:documentation "The entry conditions of an active instance's modes, which must be
exhaustive and mutually exclusive, hold for none or for several of them. The restart
CHOOSE-MODE (a mode name) picks one.")
  (:report (lambda (condition stream)
             (let ((candidates (mode-selection-error-candidates condition)))
               (format-report stream "~:[No mode's entry conditions hold~;~:*The entry conditions ~
                                      of several modes hold (~{~S~^, ~})~] for the instance ~S."
                              candidates (slot-value condition 'instance))))))

(defun choose-mode (mode &optional condition)
  "Invoke the CHOOSE-MODE restart of CONDITION (a MODE-SELECTION-ERROR, the most
recent when NIL) with the name of a MODE."
  (let ((restart (find-restart 'choose-mode condition)))
    (unless restart (error 'control-error))
    (invoke-restart restart mode)))

(define-condition invalid-change (engine-error) ()
  (:documentation "A change given to APPLY-TRANSITION is malformed or does not fit
the model: an unknown instance, deactivating an inactive instance, activating one
that is active or lacks its qualitative prerequisites, a mode change whose :FROM is
not the current mode. DATUM is the change."))

(define-condition incremental-mismatch (engine-error)
  ((difference :initarg :difference :reader incremental-mismatch-difference
               :documentation "What differs, as MODEL-DIFFERENCE reports it."))
  (:documentation "The incrementally updated model differs from the model rebuilt
from scratch from the same situation and decisions.")
  (:report (lambda (condition stream)
             (format-report stream "The incremental model differs from the rebuild from scratch:~
                                    ~{~%  ~S~}"
                            (incremental-mismatch-difference condition)))))
