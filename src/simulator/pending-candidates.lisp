;;;; src/simulator/pending-candidates.lisp -- candidates along a rotation path worked out only
;;;; where they may come first.
;;;;
;;;; Along a :ROTATION-PATH motion (rotation-path.lisp) every termination condition that
;;;; fires gets an angle, and firing there costs a travel time (an integral of 1/sqrt(E),
;;;; elliptic for a tipping block) and the sign of the rate at which the condition is
;;;; reached. The body moves one way along its angle until it turns back (a candidate is
;;;; only made for an angle reached before that), so a condition whose angle is proven
;;;; beyond another candidate's on the same path fires later and never ends the state:
;;;; its time and rate are never needed. Such candidates are made PENDING (their TIME is
;;;; (:PENDING THUNK)); SETTLE-PENDING-CANDIDATES drops those proven beyond another and
;;;; works the others out, before anything reads a candidate's time.

(in-package #:ames.simulator)

(defun make-pending-candidate (condition s group thunk)
  "A CANDIDATE of CONDITION at the angle S of GROUP whose time, event and rate THUNK
works out (it returns the complete CANDIDATE)."
  (make-candidate condition nil (list :pending thunk) :at-arc s :group group))

(defun pending-candidate-p (candidate)
  "True when CANDIDATE's time is still to be worked out."
  (let ((time (candidate-time candidate)))
    (and (consp time) (eq (first time) :pending))))

(defun proven-beyond-another-p (run candidate candidates)
  "True when another of CANDIDATES on CANDIDATE's path fires at an angle proven nearer
than CANDIDATE's."
  (let ((group (candidate-group candidate)))
    (some (lambda (other)
            (and (not (eq other candidate))
                 (eq (candidate-group other) group)
                 (candidate-at-arc other)
                 (eq :true (nearer-p run group (candidate-at-arc other) (candidate-at-arc candidate)))))
          candidates)))

(defun settle-pending-candidates (run candidates)
  "CANDIDATES without the pending ones proven to fire beyond another on their path, the
other pending ones worked out (see the file header)."
  (if (notany #'pending-candidate-p candidates)
      candidates
      (loop for candidate in candidates
            unless (and (pending-candidate-p candidate)
                        (proven-beyond-another-p run candidate candidates))
              collect (if (pending-candidate-p candidate)
                          (funcall (second (candidate-time candidate)))
                          candidate))))
