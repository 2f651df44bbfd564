;;;; src/simulator/choice-subsets.lisp -- where pivoting (choice.lisp) cannot settle a state's
;;;; start: every subset of the lone contacts, and forced mode exits that no longer apply.
;;;;
;;;; Pivoting flips the lone contacts one at a time and stops, inconsistent, where a mode's
;;;; exit fires beside a contact's violation: a rolling disc landing in an incline's corner
;;;; has the incline's friction impulse slipping in either mode while that impulse would
;;;; pull; the consistent set (the incline's impulse inactive: the disc leaves the slope) is
;;;; never reached. Before refusing, SETTLE-CHOICES tries every subset of the lone contacts
;;;; with every combination of modes, each checked as it stands. A forced exit (FORCED-EXIT)
;;;; of an instance that pivoting then deactivated is neither undone nor applied again.

(in-package #:ames.simulator)

(defun mode-change-applies-p (run change)
  "True when the mode CHANGE (:MODE KEY :FROM A :TO B) fits the current model: its
instance is active and in mode A. A forced exit of an instance that pivoting then
deactivated (a contact found pulling) no longer does: its mode went with it."
  (destructuring-bind (key &key from &allow-other-keys) (rest change)
    (let ((instance (ames.engine:find-instance (run-model run) key)))
      (and instance (ames.engine:instance-active-p instance)
           (eq (ames.engine:instance-mode instance) from)))))

(defun subset-trials (run points combo lone)
  "The trials of COMBO (an assignment of the alternatives and modes) with each subset of
the LONE activation points (LONE-SUBSETS), checked as they stand (no pivoting)."
  (loop for subset in (lone-subsets lone)
        collect (progn (apply-assignment run points (append combo subset))
                       (let ((trial (pivot run points '())))
                         (undo-forced-changes run trial)
                         trial))))
