;;;; src/witness/compare-angles.lisp -- the comparator's angles: a rotating body's angle and
;;;; angular velocity, per state, beside the witness's (witness/siconos_rotation.py reports
;;;; :angles and :angular-velocities with every event and at its end).
;;;;
;;;; AMES reports them (the language's "Rotation") as :final-angles and
;;;; :final-angular-velocities of a state that ends with an event (numbers in its :numeric
;;;; plist when it printed them, else its closed forms evaluated), and as the closed forms
;;;; :angles and :angular-velocities in tau of a state that lasts forever (evaluated at the
;;;; witness's end). Both are counter-clockwise and unwrapped (an angle goes on past 2 pi),
;;;; so they are compared as they are, to the walk's tolerance. Only the bodies that both
;;;; report are compared: a translating body has no angle on either side.

(in-package #:ames.witness)

(defun evaluate-scalars (entries bindings)
  "ENTRIES ((BODY X) ...) with X a number or a closed form, evaluated under BINDINGS."
  (loop for (body x) in entries
        collect (list body (number-of x bindings))))

(defun compare-scalars (walk what ames-entries witness-entries)
  "Compare, body by body, the numbers (BODY X) of AMES-ENTRIES with the witness's, for the
bodies both give."
  (loop for (name w) in witness-entries
        for entry = (find name ames-entries :key #'first :test (lambda (n s) (name= s n)))
        when entry
          do (compare-number walk (format nil "~A ~A" what name) (second entry) w)))

(defun state-scalars (state numeric key bindings)
  "AMES's numbers under KEY (:FINAL-ANGLES, :FINAL-ANGULAR-VELOCITIES) for STATE: those of
its NUMERIC plist when it has them, else its closed forms evaluated under BINDINGS."
  (or (getf numeric key)
      (evaluate-scalars (getf state key) bindings)))

(defun compare-final-angles (walk state numeric witness-event)
  "The angles and angular velocities at the end of STATE (an event state) beside those of
the witness's event that ends it."
  (let ((values (walk-values walk)))
    (compare-scalars walk "final angle" (state-scalars state numeric :final-angles values)
                     (getf witness-event :angles))
    (compare-scalars walk "final angular velocity"
                     (state-scalars state numeric :final-angular-velocities values)
                     (getf witness-event :angular-velocities))))

(defun compare-angles-at-end (walk state bindings end)
  "The closed forms of the angles and angular velocities of STATE (a state that lasts
forever) under BINDINGS (tau the time since its start) beside the witness's END."
  (compare-scalars walk "angle at the witness's end"
                   (evaluate-scalars (getf state :angles) bindings) (getf end :angles))
  (compare-scalars walk "angular velocity at the witness's end"
                   (evaluate-scalars (getf state :angular-velocities) bindings)
                   (getf end :angular-velocities)))
