;;;; src/simulator/rotation.lisp -- the state variables of rotating bodies: their angle and angular
;;;; velocity at the start of a state, integrated over it, reported and carried over.
;;;;
;;;; A rotating body (one with an :inertia) has, beside its position and velocity, the state
;;;; variables (ames.kb:angle B) and (ames.kb:angvel B), whose ODEs the knowledge base declares
;;;; (src/kb/rotation.lisp). The run keeps their values at the start of the current state
;;;; (RUN-ROTATIONS); a group whose accelerations and angular accelerations are constant is
;;;; integrated in closed form (polynomials in TAU, as positions are); any other group that
;;;; rotates is integrated numerically (under parameter values): ROTATION-KIND is where a
;;;; closed-form integrator of rotating groups (one degree of freedom by its energy
;;;; integral) takes over. Like the positions, the
;;;; state reports them over TAU (:ANGLES, :ANGULAR-VELOCITIES), the angular accelerations,
;;;; and their values at the end (:FINAL-ANGLES, :FINAL-ANGULAR-VELOCITIES), which the next
;;;; state starts from.

(in-package #:ames.simulator)

(defun rotation-properties (body)
  "The properties a rotating scenario BODY's entity adds (see src/kb/rotation.lisp):
:ROTATING T, :INERTIA and, for a (circle R) shape, :RADIUS R. NIL for a body that only
translates, whose entity is unchanged."
  (when (and (scenario-body-rotating-p body) (not (scenario-body-fixed-p body)))
    (let ((shape (scenario-body-shape body)))
      (list* :rotating t :inertia (scenario-body-inertia body)
             (and (eq (shape-kind shape) :circle) (list :radius (second shape)))))))

(defun initial-rotations (scenario)
  "The alist body -> (THETA OMEGA) of SCENARIO's rotating free bodies at its start."
  (loop for body in (scenario-rotating-bodies scenario)
        unless (scenario-body-fixed-p body)
          collect (list (scenario-body-name body) (scenario-body-angle body)
                        (scenario-body-angular-velocity body))))

(defun rotating-p (run body)
  "True when BODY is a rotating free body of RUN."
  (and (assoc body (run-rotations run)) t))

(defun body-angle (run body) (second (assoc body (run-rotations run))))
(defun body-angular-velocity (run body) (third (assoc body (run-rotations run))))

(defun rotation-term-p (term)
  "True when TERM is a rotating body's state variable, (angle B) or (angvel B)."
  (and (consp term) (member (first term) '(ames.kb:angle ames.kb:angvel)) t))

(defun rotation-initial-value (run term)
  "The value at the start of the state of the rotation state variable TERM."
  (ecase (first term)
    (ames.kb:angle (body-angle run (second term)))
    (ames.kb:angvel (body-angular-velocity run (second term)))))

(defun group-rotating-bodies (run group)
  "The rotating bodies of GROUP."
  (remove-if-not (lambda (body) (rotating-p run body)) (group-bodies group)))

(defun angular-rate (solved body)
  "The rate of (angvel BODY) in SOLVED: its angular acceleration over the state terms."
  (cdr (assoc `(ames.kb:angvel ,body) (solved-model-rates solved) :test #'equal)))

(defun rotation-rates (run solved group)
  "The angular accelerations of GROUP's rotating bodies in SOLVED (for classifying it)."
  (mapcar (lambda (body) (angular-rate solved body)) (group-rotating-bodies run group)))

(defun integrate-rotation-constant (run solved group)
  "The motion entries of GROUP's rotating bodies under constant angular accelerations:
(angle B) and (angvel B) as polynomials in TAU."
  (loop for body in (group-rotating-bodies run group)
        for theta0 = (body-angle run body)
        for omega0 = (body-angular-velocity run body)
        for alpha = (substitute-expressions (solved-model-initial solved) (angular-rate solved body))
        collect (cons `(ames.kb:angle ,body)
                      (tidy run `(+ ,theta0 (* ,omega0 tau) (* 1/2 ,alpha (expt tau 2))) :full))
        collect (cons `(ames.kb:angvel ,body) (tidy run `(+ ,omega0 (* ,alpha tau)) :full))))

(defun rotation-kind (run solved group kind)
  "KIND, GROUP's integrator as CLASSIFY-GROUP found it over its accelerations and angular
accelerations (ROTATION-RATES), kept where its integrator covers the rotation: :CONSTANT
(polynomials in TAU) and :LINEAR (the linear solver takes the angles with the positions);
any other rotating group is :NUMERIC (the curve's and the line's integrators know one
coordinate along a path, not a turning body)."
  (declare (ignore solved))
  (if (or (null (group-rotating-bodies run group)) (member kind '(:constant :linear)))
      kind
      :numeric))

;;; What a state reports

(defun rotation-motion (run groups head)
  "Each rotating body's (HEAD B) over its group's variable, (B EXPRESSION), HEAD
ames.kb:angle or ames.kb:angvel; (B (:NO-CLOSED-FORM)) for a body integrated numerically."
  (loop for (body) in (run-rotations run)
        for group = (body-group groups body)
        collect (list body (if (eq (group-kind group) :numeric)
                               (list :no-closed-form)
                               (cdr (assoc (list head body) (group-motion group) :test #'equal))))))

(defun solved-angular-accelerations (run solved groups)
  "Each rotating body's angular acceleration in SOLVED over the state's motion, (B ALPHA)."
  (loop for (body) in (run-rotations run)
        collect (list body (over-motion run solved groups `(ames.kb:angacc ,body)))))

(defun rotation-final-values (run groups fired head)
  "Each rotating body's (HEAD B) when the state ends at FIRED, (B VALUE)."
  (loop for (body) in (run-rotations run)
        for group = (body-group groups body)
        for term = (list head body)
        collect (list body
                      (cond ((and (eq (group-kind group) :numeric) (null (group-end-state group)))
                             (rotation-initial-value run term))
                            ((eq (group-kind group) :numeric)
                             ;; flat on a face by two corners: flat-corner-snapping.lisp;
                             ;; numbers at the run's values (numeric-ends.lisp)
                             (valued-expression
                              run (snap-flat-rotation run group body head
                                                      (rational-of (cdr (assoc term (group-end-state group) :test #'equal)))
                                                      fired)))
                            (t (end-value run (substitute-expressions
                                               (list (cons (group-variable group)
                                                           (group-at-end run groups group fired)))
                                               (cdr (assoc term (group-motion group) :test #'equal)))))))))

(defun note-rotation-start (run state solved groups)
  "Record in STATE the rotating bodies' motion over it and their angular accelerations."
  (when (run-rotations run)
    (setf (state-angles state) (rotation-motion run groups 'ames.kb:angle)
          (state-angular-velocities state) (rotation-motion run groups 'ames.kb:angvel)
          (state-angular-accelerations state) (solved-angular-accelerations run solved groups))))

(defun note-rotation-end (run state groups fired)
  "Record in STATE the rotating bodies' angles and angular velocities at its end."
  (when (run-rotations run)
    (setf (state-final-angles state) (rotation-final-values run groups fired 'ames.kb:angle)
          (state-final-angular-velocities state)
          (rotation-final-values run groups fired 'ames.kb:angvel))))

(defun note-rotation-held (run state)
  "Record in STATE, which lasts no time (a fork), the rotating bodies' angles and angular
velocities now, as its motion and its end."
  (when (run-rotations run)
    (let ((angles (loop for (body theta) in (run-rotations run) collect (list body theta)))
          (omegas (loop for (body nil omega) in (run-rotations run) collect (list body omega))))
      (setf (state-angles state) angles
            (state-angular-velocities state) omegas
            (state-final-angles state) angles
            (state-final-angular-velocities state) omegas))))

(defun rotation-numbers (bridge entries values)
  "ENTRIES ((BODY EXPRESSION) ...), a state's final angles or angular velocities, as
((BODY NUMBER) ...) under the parameter VALUES (NUMBER NIL where it has none)."
  (loop for (body expression) in entries
        collect (list body (numeric-or-nil bridge expression values))))

(defun add-rotation-numbers (bridge state values)
  "Add to STATE's numbers, when it has rotating bodies, the numbers of their final angles
and angular velocities under the parameter VALUES (:FINAL-ANGLES, :FINAL-ANGULAR-VELOCITIES)."
  (when (state-final-angles state)
    (setf (state-numbers state)
          (append (state-numbers state)
                  (list :final-angles (rotation-numbers bridge (state-final-angles state) values)
                        :final-angular-velocities
                        (rotation-numbers bridge (state-final-angular-velocities state) values))))))

(defun carry-rotations-over (run state)
  "Start the next state from STATE's final angles and angular velocities."
  (when (state-final-angles state)
    (setf (run-rotations run)
          (loop for (body theta) in (state-final-angles state)
                collect (list body theta
                              (second (assoc body (state-final-angular-velocities state))))))))
