;;;; src/simulator/conditions.lisp -- the conditions a simulation signals, and its restart.

(in-package #:ames.simulator)

(define-condition simulation-error (ames-error) ()
  (:documentation "The simulation cannot go on. DATUM names the state, model or fact."))

(define-condition ambiguous-transition (simulation-error)
  ((candidates :initarg :candidates :initform '() :reader ambiguous-transition-candidates
               :documentation "The alternatives: termination candidates as (EVENT TIME), or
the consistent contact and mode assignments.")
   (missing-fact :initarg :missing-fact :reader ambiguous-transition-missing-fact
                 :documentation "A relation the assumptions do not decide.")
   (state :initarg :state :initform nil :accessor ambiguous-transition-state
          :documentation "The state whose end (or start) is ambiguous, as far as it is
known (its model and motion), or NIL."))
  (:documentation "Which termination condition comes first, or which contacts and modes
hold at the start of a state, cannot be decided under the scenario's assumptions.
Restart: STOP-SIMULATION.")
  (:report (lambda (condition stream)
             (format stream "Ambiguous ~A: the assumptions do not decide it.~%  missing fact: ~S~%  candidates:~{~%    ~S~}"
                     (or (ames-error-detail condition) "transition")
                     (ambiguous-transition-missing-fact condition)
                     (ambiguous-transition-candidates condition)))))

(setf (documentation 'ambiguous-transition-candidates 'function)
      "The alternatives the assumptions leave open: termination candidates as (EVENT
TIME), or the consistent assignments of contacts and modes."
      (documentation 'ambiguous-transition-missing-fact 'function)
      "A relation the assumptions do not decide, whose truth would settle the transition.")

(define-condition unsolvable-model (simulation-error) ()
  (:documentation "The state's model has no solution, or no unique one."))

(define-condition unsupported-situation (simulation-error) ()
  (:documentation "The state is outside what AMES can model yet (named in DETAIL)."))

(defun stop-simulation (&optional condition)
  "Invoke the STOP-SIMULATION restart: end the simulation and return the history so far."
  (invoke-restart 'stop-simulation condition))
