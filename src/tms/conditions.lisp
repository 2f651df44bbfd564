;;;; src/tms/conditions.lisp -- the conditions the JTMS signals, and the restart functions.

(in-package #:ames.tms)

(define-condition tms-error (ames-error) ()
  (:documentation "The parent of every condition the JTMS signals."))

(define-condition contradiction (tms-error)
  ((node :initarg :node :reader contradiction-node
         :documentation "The contradiction node that came IN.")
   (assumptions :initarg :assumptions :initform '() :reader contradiction-assumptions
                :documentation "The enabled assumptions the contradiction rests on."))
  (:documentation "Signalled (with ERROR) when a node made with :CONTRADICTION T comes
IN. Two restarts are offered while it is signalled: RETRACT-CULPRIT, which takes one
of CONTRADICTION-ASSUMPTIONS and retracts it (the contradiction is signalled again
if it is still believed afterwards), and CONTINUE, which leaves the contradiction
believed. DATUM is the contradiction node's datum.")
  (:report (lambda (condition stream)
             (let ((node (contradiction-node condition)))
               (format-report stream "Contradiction: ~A is believed.~%  It rests on ~
                                      ~:[no assumption (premises only)~;the assumptions~
                                      ~:*~{~%    ~A~}~]"
                              (node-string node)
                              (mapcar #'node-string (contradiction-assumptions condition)))))))

(define-condition not-an-assumption (tms-error) ()
  (:documentation "An assumption operation (enable, retract, retract-culprit) was
applied to a node that is not an assumption, or RETRACT-CULPRIT was given an
assumption that does not support the contradiction. DATUM is the node.")
  (:report (lambda (condition stream)
             (format-report stream "~A~%  node: ~A" (ames-error-detail condition)
                            (let ((node (ames-error-datum condition)))
                              (if (node-p node) (node-string node) node))))))

(define-condition foreign-node (tms-error) ()
  (:documentation "A justification mixed nodes of different JTMSs, or a node was
given where none is expected. DATUM is the offending object. (Its report is
AMES-ERROR's: the detail and the datum.)"))

(defun retract-culprit (assumption &optional condition)
  "Invoke the RETRACT-CULPRIT restart of CONDITION (a CONTRADICTION; the most recent
one when NIL) so that ASSUMPTION is retracted. ASSUMPTION must be one of the
condition's CONTRADICTION-ASSUMPTIONS, else NOT-AN-ASSUMPTION is signalled by the
restart. Signals CONTROL-ERROR when no such restart is active."
  (let ((restart (find-restart 'retract-culprit condition)))
    (unless restart
      (error 'control-error))
    (invoke-restart restart assumption)))
