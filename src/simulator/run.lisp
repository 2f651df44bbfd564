;;;; src/simulator/run.lisp -- one simulation's working context: the scenario's bodies and
;;;; contacts, the situation the knowledge base reads, and the decider of a state's
;;;; initial conditions.
;;;;
;;;; The simulator speaks the knowledge base's kinematic vocabulary (positions,
;;;; velocities, accelerations, the path coordinates and gap of a contact: see
;;;; src/kb/mechanics.lisp) and the geometry's; it knows no force, event or mode by name.

(in-package #:ames.simulator)

(defvar *all-branches* nil
  "True when every branch of a fork is simulated even where the parameter values select
one (the command line's --all-branches); see also SCENARIO-ALL-BRANCHES.")

(defvar *history-clock* 0
  "The number at which the first state of the history being simulated starts under the
values: 0, or a continued branch's start (see CONTINUE-BRANCH), or NIL when unknown.")

(defvar *branching* nil
  "The current run's tree while it grows (see branching.lisp): a plist (:COUNT branches
so far on the current path :TREE a cell holding the whole tree's :DEPTH forking states
on the current path :STATE the index of its last fork :NESTED forks nested at that
state :EXTRA-FACTS facts of the current branch [:REFUSAL why the last fork was refused:
:BOUND, :ASSUMED or :NOT-BRANCHABLE]), or NIL at the root.")

(defclass run ()
  ((scenario :initarg :scenario :reader run-scenario)
   (bridge :initarg :bridge :reader run-bridge)
   (shapes :initarg :shapes :reader run-shapes
           :documentation "Alist body name -> ames.geometry shape.")
   (contacts :initarg :contacts :reader run-contacts
             :documentation "Alist contact entity name -> ames.geometry simple contact.")
   (contact-table :initform nil :accessor run-contact-table
                  :documentation "The contacts as a hash table, made on first use.")
   (parameter-signs :initform :unset :accessor run-parameter-signs-cache
                    :documentation "The parameters' declared signs (see PARAMETER-SIGNS),
made on first use.")
   (locus-kinds :initarg :locus-kinds :initform '() :reader run-locus-kinds
                :documentation "Alist contact name -> (:KIND K :POINT P) for the loci of points
attached to bodies (see src/simulator/attachments.lisp); the other contacts are loci of two
bodies' shapes.")
   (alternatives :initarg :alternatives :initform '() :reader run-alternatives
                 :documentation "Alist contact name -> the contacts that meet it at a convex
or smooth corner of the configuration-space obstacle: where the observer sits on both,
they are alternatives (it must stay outside one of them), never both active.")
   (model :initform nil :accessor run-model)
   (decider :initform nil :accessor run-decider-override
            :documentation "While an impact is resolved, the decider of its model (see
RUN-DECIDER); NIL otherwise.")
   (positions :initarg :positions :accessor run-positions
              :documentation "Alist body -> (X Y) at the start of the current state.")
   (velocities :initarg :velocities :accessor run-velocities
               :documentation "Alist body -> (VX VY) at the start of the current state.")
   (rotations :initarg :rotations :initform '() :accessor run-rotations
              :documentation "Alist rotating body -> (THETA OMEGA), its angle and angular
velocity at the start of the current state (see rotation.lisp).")
   (time :initform 0 :accessor run-time
         :documentation "Global time at which the current state starts: an expression.")
   (values :initarg :values :initform '() :reader run-values
           :documentation "Alist parameter -> number given for this run (--set), or NIL.")
   (assumed :initform '() :accessor run-assumed
            :documentation "Facts assumed because the parameter values decide them: a list
of (:state N :fact RELATION).")
   (impacts :initform '() :accessor run-impacts
            :documentation "The impacts so far, newest first: plists (:TIME :POSITIONS
:AFTER :CONTACTS), to recognise a repeating sequence (see ZENO-ACCUMULATION).")
   (rederived :initform '() :accessor run-rederived
              :documentation "Instances re-derived at each transition (for benchmarks).")
   (statistics :initform (list :equations-before 0 :equations-after 0 :solves 0)
               :accessor run-statistics
               :documentation "Model sizes before and after elimination (for benchmarks)."))
  (:documentation "The working context of one simulation."))

;;; The algebra, through the bridge (the only place these are written)

(defun tidy (run expression &optional (strategy :ratsimp))
  "EXPRESSION simplified by Maxima (rational canonical form unless STRATEGY says)."
  (ames.maxima:simplify (run-bridge run) expression :strategy strategy))

(defun tidy-real (run expression)
  "EXPRESSION simplified fully, products of square roots of negative quantities written
with real roots (ames.algebra:SIMPLIFY-REAL): how values at a state's end are reported."
  (ames.algebra:simplify-real (run-bridge run) expression))

(defun decide (run relation)
  "RELATION decided under the scenario's assumptions: :TRUE, :FALSE or :UNKNOWN."
  (ames.algebra:decide (run-bridge run) relation))

(defun holds (run relation)
  "True when RELATION is decided :TRUE under the scenario's assumptions."
  (ames.algebra:holds-p (run-bridge run) relation))

(defun run-parameter-signs (run)
  "The alist parameter -> declared sign of RUN's scenario (see PARAMETER-SIGNS)."
  (let ((signs (run-parameter-signs-cache run)))
    (if (eq signs :unset)
        (setf (run-parameter-signs-cache run) (parameter-signs (run-scenario run)))
        signs)))

(defun one-sign (signs)
  "The one sign (:POSITIVE, :NEGATIVE or :ZERO) the sign set SIGNS allows, or NIL when it
allows several (or none)."
  (and signs (null (rest signs)) (first signs)))

(defun sign-direction (signs)
  "The direction, 1 or -1, that the sign set SIGNS gives a motion or an orientation:
1 for (:POSITIVE), -1 for (:NEGATIVE), else NIL (no direction: zero or undecided)."
  (case (one-sign signs) (:positive 1) (:negative -1)))

(defun sign-of (run x)
  "The sign set of X under the assumptions: one sign, (:POSITIVE), (:NEGATIVE) or
(:ZERO), when it is decided, else all three (AMES.ALGEBRA:+ALL-SIGNS+). Sign sets,
AMES.ALGEBRA's, are the simulator's one way of writing signs. The rules of signs over
the parameters' declared signs (SIGN-ALGEBRA) answer first; Maxima where they do not,
for the signs the run's values do not refute (SIGNS-REFUTED-BY-VALUES)."
  (let ((refuted '()))
    (cond ((realp x) (ames.algebra:number-signs x))
          ((one-sign (sign-algebra (run-parameter-signs run) x))
           (sign-algebra (run-parameter-signs run) x))
          ;; under values, a sign that fails at them is not tried (no proof exists)
          ((progn (setf refuted (ames.algebra:signs-refuted-by-values (run-bridge run) x))
                  nil))
          ;; at a start that numbers put there, the values decide first (approximate-starts.lisp)
          ((sign-at-approximate-start run x refuted))
          ((and (not (member :positive refuted)) (holds run `(> ,x 0))) (list :positive))
          ((and (not (member :negative refuted)) (holds run `(< ,x 0))) (list :negative))
          ((and (not (member :zero refuted))
                (not (ames.algebra:sign-varies-p (run-bridge run) x))
                (holds run `(= ,x 0)))
           (list :zero))
          (t ames.algebra:+all-signs+))))

(defun sign-is (run x &rest signs)
  "True when X's sign is decided (SIGN-OF gives one sign) and it is among SIGNS."
  (and (member (one-sign (sign-of run x)) signs) t))

(defun at-time (expression time)
  "EXPRESSION with TAU replaced by TIME."
  (substitute-expressions (list (cons 'tau time)) expression))

;;; Bodies and contacts

(defun run-body (run name)
  "The scenario body called NAME."
  (find-scenario-body name (run-scenario run)))

(defun body-fixed-p (run name)
  "True when body NAME is glued to the fixed frame."
  (scenario-body-fixed-p (run-body run name)))

(defun body-names (run)
  "The names of the scenario's bodies, in order."
  (mapcar #'scenario-body-name (scenario-bodies (run-scenario run))))

(defun free-body-names (run)
  "The names of the scenario's free (not fixed) bodies, in order."
  (mapcar #'scenario-body-name (scenario-moving-bodies (run-scenario run))))

(defun contact-geometry (run contact)
  "The ames.geometry simple contact behind the contact entity CONTACT."
  (let ((table (or (run-contact-table run)
                   (let ((table (make-hash-table :test #'eq)))
                     (loop for (name . geometry) in (run-contacts run)
                           do (setf (gethash name table) geometry))
                     (setf (run-contact-table run) table)))))
    (values (gethash contact table))))

(defun contact-bodies (run contact)
  "The observer and obstacle names of CONTACT, as a list."
  (let ((geometry (contact-geometry run contact)))
    (list (ames.geometry:contact-observer geometry) (ames.geometry:contact-obstacle geometry))))

(defun curved-contact-p (run contact)
  "True when CONTACT's locus is an arc or a circle."
  (member (ames.geometry:contact-kind (contact-geometry run contact)) '(:arc :circle)))

(defun body-position (run body) (second (assoc body (run-positions run))))
(defun body-velocity (run body) (second (assoc body (run-velocities run))))

(defun inverse-angle-function-p (expression &optional inside)
  "True when EXPRESSION holds sin, cos or tan of an angle with asin, acos or atan in it
(of anything, constants too). INSIDE: within such a sin, cos or tan already."
  (and (consp expression)
       (or (and inside (member (first expression) '(asin acos atan)))
           (let ((inside (or inside (member (first expression) '(sin cos tan)))))
             (some (lambda (x) (inverse-angle-function-p x inside)) (rest expression))))))

(defun contact-parameter-of (run geometry q)
  "The arc length at which the relative position Q lies on the contact GEOMETRY
(AMES.GEOMETRY:CONTACT-PARAMETER). A position with sin or cos of an inverse
trigonometric angle (a state that ended at a root 2 atan(u)) that the geometry cannot
place is placed once those are expanded into algebra (an identity, the same point)."
  (handler-case (ames.geometry:contact-parameter geometry q)
    (ames.geometry:position-not-on-contact (condition)
      (if (some #'inverse-angle-function-p q)
          (ames.geometry:contact-parameter
           geometry (mapcar (lambda (x) (tidy run x :expanded-trigexpand)) q))
          (error condition)))))

(defun relative-initial-state (run contact)
  "The observer's position and velocity relative to the obstacle at the state's start."
  (destructuring-bind (observer obstacle) (contact-bodies run contact)
    (values (ames.geometry:v- (body-position run observer) (body-position run obstacle))
            (ames.geometry:v- (body-velocity run observer) (body-velocity run obstacle)))))

;;; Setting a run up

(defun contact-entity-name (index)
  "The symbol naming the INDEXth simple contact in the engine's situation."
  (intern (format nil "CONTACT-~D" index) '#:ames.simulator))

(defun world-contacts (world)
  "Alist contact entity name -> geometry contact for every simple contact of WORLD's
pairs (every two bodies not both fixed), numbered from 0 in the world's order."
  (loop for contact in (world-simple-contacts world)
        for index from 0
        collect (cons (contact-entity-name index) contact)))

(defun corner-alternatives (bridge contacts)
  "For CONTACTS (alist name -> geometry contact), the alist name -> names of the
contacts that continue it past one of its ends at a corner that is not concave (the
turn from its tangent to the next one's is to the left or none): an observer at such
a corner is outside the obstacle when it is outside either face, so the two contacts
are alternatives. At a concave corner both faces can push at once."
  (let ((by-geometry (make-hash-table :test #'eq))
        (alternatives '())
        (entries (make-hash-table :test #'eq)))
    (loop for (name . geometry) in contacts
          do (setf (gethash geometry by-geometry) name))
    (loop for (name . geometry) in contacts
          do (loop for (end . neighbour) in (ames.geometry:contact-neighbours geometry)
                   for other = (gethash neighbour by-geometry)
                   when (and other (eq end :end))
                     do (let* ((length (ames.geometry:contact-length geometry))
                               (turn (ames.geometry:cross (ames.geometry:contact-unit-tangent geometry length)
                                                (ames.geometry:contact-unit-tangent neighbour 0))))
                          (when (ames.algebra:holds-p bridge `(>= ,turn 0))
                            (flet ((entry (key)
                                     ;; ALTERNATIVES's entry of KEY (as ASSOC finds it), made when new
                                     (or (gethash key entries)
                                         (setf (gethash key entries)
                                               (car (push (list key) alternatives))))))
                              (push other (cdr (entry name)))
                              (push name (cdr (entry other))))))))
    alternatives))

(defun body-entity (body &rest properties)
  "The entity of the scenario BODY, with PROPERTIES: a fixed body's carries its :position."
  (list* 'ames.kb:body (scenario-body-name body)
         :fixed (and (scenario-body-fixed-p body) t)
         :mass (scenario-body-mass body)
         (append (and (scenario-body-driven-p body) (list :driven t)) (and (scenario-body-fixed-p body) (list :position (scenario-body-position body)))
                 (rotation-properties body)
                 properties)))

(defun situation-entities (run)
  "The entities the mechanics knowledge base reads: the bodies, the contacts (between
shapes, and the loci of the phenomena's probes), then what each phenomenon makes of its
scenario clause (AMES.KB:SITUATION-ENTITIES-OF; see src/kb/phenomena.lisp)."
  (let ((scenario (run-scenario run)))
    (append
     (mapcar #'body-entity (scenario-bodies scenario))
     (mapcar (lambda (entry) (contact-entity run (car entry) (cdr entry)))
             (run-contacts run))
     (corner-contact-entities run)
     (ames.kb:situation-entities-of scenario))))
