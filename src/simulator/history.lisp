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
   (contact-points :initarg :contact-points :initform '() :reader state-contact-points
                   :documentation "A list parallel to CONTACTS: for each, where its bodies
touch at the state's start, a plist (:POINT (X Y) :NORMAL (NX NY)) in the fixed frame
with NORMAL the unit normal from its second body (the obstacle) into its first, or NIL
when not known (see touching.lisp).")
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
   ;; rotating bodies (rotation.lisp): NIL when no body rotates
   (angles :initform '() :accessor state-angles
           :documentation "List of (BODY THETA-of-TAU) for the rotating bodies.")
   (angular-velocities :initform '() :accessor state-angular-velocities
                       :documentation "List of (BODY OMEGA-of-TAU).")
   (angular-accelerations :initform '() :accessor state-angular-accelerations
                          :documentation "List of (BODY ALPHA).")
   (final-angles :initform '() :accessor state-final-angles
                 :documentation "List of (BODY THETA) at the end, or NIL.")
   (final-angular-velocities :initform '() :accessor state-final-angular-velocities
                             :documentation "List of (BODY OMEGA) at the end, or NIL.")
   ;; what a person should know beside the motion (STATE-NOTES lists them as a plist)
   (numbers :initform '() :accessor state-numbers
            :documentation "Under the history's parameter values, the numbers beside the
formulas: a plist (:START N :DURATION N :FINAL-POSITIONS ((BODY (X Y))...)
:FINAL-VELOCITIES ((BODY (VX VY))...) :PERIOD N), each the value of the formula it is
printed beside (NIL where it has none); NIL without values (see ADD-NUMERIC-VALUES).")
   (accumulation :initform nil :accessor state-accumulation
                 :documentation "When the impacts ending the states repeat scaled (a bouncing
ball), the point they accumulate at: a plist (:FACTOR R :CYCLE T1 :TIME T), else NIL
(see ZENO-ACCUMULATION).")
   (impact :initform nil :accessor state-impact
           :documentation "The impact that ends the state: a plist (:CONTACTS :IMPULSES
:ENERGY-LOST :VELOCITIES-BEFORE :VELOCITIES-AFTER :CHOICES), else NIL (see impacts.lisp).")
   (end-arc-length :initform nil :accessor state-end-arc-length
                   :documentation "The arc length at which a motion along a curve or a line
ends, else NIL.")
   (numeric-trajectory :initform '() :accessor state-numeric-trajectory
                       :documentation "The samples of the motions integrated numerically
(no closed form): a list of plists (:TERMS TERMS :SAMPLES ((TIME . VALUES)...)).")
   (simultaneous-events :initform '() :accessor state-simultaneous-events
                        :documentation "Every event that ends the state when several
fire at once (the end event is one of them), else NIL.")
   (periodic :initform nil :accessor state-periodic
             :documentation "For a motion that repeats forever (between two turning points,
or one frequency for every body): a plist (:PERIOD T :BETWEEN (A B) [:COORDINATE Q] ...),
else NIL (see turns.lisp, oscillation.lisp).")
   (undecided-detail :initform nil :accessor state-undecided-detail
                     :documentation "Why the state's end could not be found (no closed
form and no numbers), a string, else NIL.")
   (path-coordinates :initarg :path-coordinates :initform nil :reader state-path-coordinates
                     :documentation "For a motion along a curve: a plist (:CONTACT (A B)
:ARC-LENGTH-FROM S0 :DIRECTION D :TANGENTIAL-ACCELERATION A :ENERGY-INTEGRAL E :ODE K),
else NIL.")
   (line-coordinates :initarg :line-coordinates :initform '() :reader state-line-coordinates
                     :documentation "The simulator's coordinates along the lines of bodies
moving together (plists with :FROM, the coordinate's start), else NIL.")
   (missing-fact :initarg :missing-fact :initform nil :reader state-missing-fact
                 :documentation "For a fork: the fact the assumptions leave open.")
   (fork :initarg :fork :initform nil :reader state-fork-p
         :documentation "True for a fork: no period of motion, the state its branches split.")
   (reported-sections :initarg :reported-sections :initform '() :reader state-reported-sections
                      :documentation "Every section the knowledge base reports beside the
forces, a plist section -> entries with their values over the state: :ENERGY ((:KINETIC
BODY E) (:POTENTIAL SOURCE E)...), :MOMENTUM ((:MOMENTUM BODY (PX PY))...), and so on
(see src/kb/energy.lisp).")
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
          :documentation "What the run says of itself, a plist: :STOPPED-BY the condition
that stopped it early; :ASSUMED the facts the parameter values decided, each (:STATE N
:FACT RELATION) (N NIL outside a transition); :DECIDED-BY-VALUES the same, as the run
recorded them; :MODEL-SIZES the model's sizes before and after elimination (for
benchmarks); :SELF-CHECK what the self-check verified (see AMES.CHECK).")
   (rederived :initform '() :accessor history-rederived
              :documentation "How many component instances each transition re-derived."))
  (:documentation "The value of SIMULATE: a scenario's qualitative states in order."))

(defparameter +note-readers+
  '((:numeric . state-numbers) (:accumulation . state-accumulation) (:impact . state-impact)
    (:end-arc-length . state-end-arc-length) (:numeric-trajectory . state-numeric-trajectory)
    (:events . state-simultaneous-events) (:periodic . state-periodic)
    (:undecided . state-undecided-detail) (:path-coordinates . state-path-coordinates)
    (:line-coordinates . state-line-coordinates) (:missing-fact . state-missing-fact)
    (:fork . state-fork-p))
  "Each note of a state, as STATE-NOTES names it, with the reader of its slot, in the
order the notes are listed.")

(defun state-notes (state)
  "What a person should know of STATE beside its motion, as a plist: each note of
+NOTE-READERS+ that STATE has (not NIL) under its key, then the sections the knowledge
base reported (STATE-REPORTED-SECTIONS). Read a note through its own accessor; this list
is for reports that show every note."
  (append (loop for (key . reader) in +note-readers+
                for value = (funcall reader state)
                when value append (list key value))
          (state-reported-sections state)))

(defun body-entry (alist body)
  "The value recorded for BODY in a state's per-body list such as STATE-ACCELERATIONS."
  (second (assoc body alist)))
