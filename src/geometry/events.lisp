;;;; src/geometry/events.lisp -- when a relative trajectory meets or leaves a simple contact.
;;;;
;;;; CONTACT-MEETING and CONTACT-LEAVINGS (contacts.lisp) give the conditions as
;;;; relations over the state's time tau; these functions solve them through the bridge:
;;;; the earliest root of the gap (or of s - end) after a given time that satisfies the
;;;; rest of the conditions. Call them under the scenario's assumptions.

(in-package #:ames.geometry)

(defun holds-at (bridge relation time value)
  "The bridge's verdict on RELATION with TIME replaced by VALUE."
  (ames.maxima:decide bridge (substitute-expressions (list (cons time value)) relation)))

(defun earliest-satisfying-root (bridge expression conditions time after attempts)
  "The earliest root of EXPRESSION = 0 in TIME after AFTER at which every relation of
CONDITIONS holds: (values ROOT :FOUND), (values :NONE NIL) or (values :UNKNOWN
CANDIDATES). Roots where a condition fails are skipped (at most ATTEMPTS roots)."
  (loop repeat attempts
        do (multiple-value-bind (root status)
               (ames.maxima:earliest-root bridge expression time :after after :strictly t)
             (case root
               (:none (return (values :none nil)))
               (:unknown (return (values :unknown status)))
               (t (let ((verdicts (mapcar (lambda (relation) (holds-at bridge relation time root))
                                          conditions)))
                    (cond ((every (lambda (v) (eq v :true)) verdicts)
                           (return (values root :found)))
                          ((member :false verdicts) (setf after root))
                          (t (return (values :unknown (list root)))))))))
        finally (return (values :unknown '()))))

(defun earliest-meeting (contact trajectory bridge &key (time tau) (after 0) (attempts 6))
  "The earliest time after AFTER at which the relative trajectory TRAJECTORY, a list
(X(TIME) Y(TIME)), meets CONTACT from its exterior side, within its ends. Returns
(values TIME :FOUND), (values :NONE NIL) when it provably never does, or (values
:UNKNOWN CANDIDATES) when Maxima cannot tell. Signals what the bridge signals."
  (let ((meeting (contact-meeting contact trajectory :time time)))
    (earliest-satisfying-root bridge (meeting-gap meeting) (rest (meeting-conditions meeting))
                              time after attempts)))

(defun earliest-leaving (contact s sdot bridge &key (time tau) (after 0) (attempts 6))
  "The earliest time after AFTER at which an observer at arc length S (an expression in
TIME, with speed SDOT) leaves CONTACT past one of its ends. Returns (values TIME
LEAVING) for the first end reached, :NONE when neither end is reached (or the contact
has no ends), or (values :UNKNOWN CANDIDATES)."
  (let ((best nil) (best-leaving nil) (unknown '()))
    (dolist (leaving (contact-leavings contact s sdot))
      (let ((equation (leaving-equation leaving)))
        (multiple-value-bind (root status)
            (earliest-satisfying-root bridge (e- (relation-lhs equation) (relation-rhs equation))
                                      (list (leaving-direction leaving)) time after attempts)
          (case root
            (:none)
            (:unknown (setf unknown (append unknown (or status (list :no-candidate)))))
            (t (if (or (null best) (eq (ames.maxima:decide bridge (list '< root best)) :true))
                   (setf best root best-leaving leaving)
                   (unless (eq (ames.maxima:decide bridge (list '>= root best)) :true)
                     (push root unknown))))))))
    (cond (unknown (values :unknown (if best (cons best unknown) unknown)))
          (best (values best best-leaving))
          (t (values :none nil)))))
