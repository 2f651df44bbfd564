;;;; src/simulator/history.lisp -- what a simulation returns: qualitative states and their history.
;;;;
;;;; A SIMULATION-HISTORY is the value of AMES:SIMULATE. It holds the validated scenario and one
;;;; QUALITATIVE-STATE per period that one mathematical model describes. Every expression in it is
;;;; in the prefix algebra over the scenario's parameters and the state-local time TAU.

(in-package #:ames.simulator)

(defclass qualitative-state ()
  ((index :initarg :index :reader state-index
          :documentation "0 for the first state, then 1, 2, ...")
   (start :initarg :start :reader state-start
          :documentation "Global time at which the state starts (an expression).")
   (duration :initarg :duration :initform :forever :accessor state-duration
             :documentation "How long the state lasts: an expression, :FOREVER,
(:NO-CLOSED-FORM ...) when the end is known only implicitly, or :UNDECIDED when the
assumptions do not decide which event ends it (see the history's notes).")
   (contacts :initarg :contacts :initform '() :reader state-contacts
             :documentation "List of (BODY1 BODY2 :FEATURE F): the simple contacts that hold.")
   (accelerations :initarg :accelerations :initform '() :accessor state-accelerations
                  :documentation "List of (BODY (AX AY)) in the fixed frame.")
   (forces :initarg :forces :initform '() :accessor state-forces
           :documentation "The entries the knowledge base reports, such as (:NORMAL B1 B2
MAGNITUDE), (:GRAVITY B (FX FY)), (:EXTERNAL NAME B (FX FY)).")
   (positions :initarg :positions :initform '() :accessor state-positions
              :documentation "List of (BODY (X-of-TAU Y-of-TAU)).")
   (initial-velocities :initarg :initial-velocities :initform '() :accessor state-initial-velocities
                       :documentation "List of (BODY (VX VY)) when the state starts: after an
impact, the velocities just after it.")
   (velocities :initarg :velocities :initform '() :accessor state-velocities
               :documentation "List of (BODY (VX-of-TAU VY-of-TAU)).")
   (end-event :initarg :end-event :initform :none :accessor state-end-event
              :documentation "How the state ends: (:LEAVES A B :ENDPOINT), (:LIFT-OFF A B),
(:CONTACT A B), (:COLLISION A B), (:TIME-LIMIT T), :UNDECIDED (an ambiguous end), or :NONE:
whatever event the knowledge base's component names for the condition that fired.")
   (final-positions :initarg :final-positions :initform '() :accessor state-final-positions
                    :documentation "List of (BODY (X Y)) at the end, or NIL when it never ends.")
   (final-velocities :initarg :final-velocities :initform '()
                     :accessor state-final-velocities
                     :documentation "List of (BODY (VX VY)) at the end, or NIL.")
   (notes :initarg :notes :initform '() :accessor state-notes
          :documentation "Extra facts a person should know: energy integrals, numeric values
under --set, contact-breaking positions ...; a plist.")
   (branches :initarg :branches :initform '() :accessor state-branches
             :documentation "For a fork (end event (:BRANCH)): the branches, each a plist
(:ASSUME FACT :STATES STATES :OUTCOME OUTCOME [:SELECTED T] [:SUBSTITUTION (P V)]).")
   (analysis :initarg :analysis :initform '() :accessor state-analysis
             :documentation "How AMES reached the state, for explanations: a plist with
:EQUATIONS (the model's equations), :CHOICES (the consistency argument: each
assignment of the open contacts and modes tried, and why it was kept or rejected),
:INTEGRATOR (how each group of bodies was integrated) and :CANDIDATES (every
termination condition with its time, or why it never fires)."))
  (:documentation "One qualitative state: a period over which one model describes the motion."))

(defclass simulation-history ()
  ((scenario :initarg :scenario :reader history-scenario
             :documentation "The validated SCENARIO that was simulated.")
   (states :initarg :states :initform '() :accessor history-states
           :documentation "The QUALITATIVE-STATEs in order.")
   (outcome :initarg :outcome :initform :complete :accessor history-outcome
            :documentation ":COMPLETE (nothing more changes), :STATE-LIMIT, :TIME-LIMIT,
:AMBIGUOUS, :BRANCHED (the last state is a fork: see STATE-BRANCHES), or :UNDECIDED
(a state's end could not be found: no closed form and no numbers to integrate with).")
   (parameter-values :initarg :parameter-values :initform '()
                     :reader history-parameter-values
                     :documentation "Alist (PARAMETER . NUMBER) used for numeric values.")
   (answers :initform '() :accessor history-answers
            :documentation "The answers to the scenario's queries (see ANSWER-QUERIES).")
   (notes :initform '() :accessor history-notes
          :documentation "A plist: :STOPPED-BY holds the condition that stopped the run early.")
   (rederived :initform '() :accessor history-rederived
              :documentation "How many component instances each transition re-derived."))
  (:documentation "The value of SIMULATE: a scenario's qualitative states in order."))

(defun body-entry (alist body)
  "The value recorded for BODY in a state's per-body list such as STATE-ACCELERATIONS."
  (second (assoc body alist)))
