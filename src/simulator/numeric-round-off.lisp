;;;; src/simulator/numeric-round-off.lisp -- a numeric root search's crossing is a sign
;;;; change the float can tell: beyond the round-off of the event function's value.
;;;;
;;;; The closed-form numeric root search (numeric-roots.lisp) samples an event function
;;;; and bisects where it goes below zero. A function that only tends to zero (a gap under
;;;; drag closing on its reach, a difference of two equal closed forms) evaluates to a few
;;;; units of round-off of either sign, and a first negative double was once taken for a
;;;; crossing. Here a value counts as negative only beyond a margin from its magnitudes
;;;; (ames.algebra:ROUND-OFF-SCALE: a sum's terms' sizes added); one below zero only
;;;; within it is a sign change only when the function is negative beyond round-off a
;;;; step later, else the search answers (:ROUND-OFF TAU) and the condition stays
;;;; undecided: a zero the float cannot tell from a touch is no root.

(in-package #:ames.simulator)

(defparameter *crossing-round-off* (* 256 double-float-epsilon)
  "A value of an event function within this of its round-off scale (ROUND-OFF-SCALE of
its expression at that time) is zero as far as the float can tell: no sign change.")

(defun below-round-off-p (value tolerance)
  "True when VALUE is negative beyond TOLERANCE (a non-negative number): a sign a float
can tell."
  (< value (- tolerance)))

(defun round-off-crossing (function time next step tolerance)
  "FUNCTION, >= 0 at TIME, is negative at NEXT but within its round-off (TOLERANCE, a
function of the time): a sign change only when it is negative beyond round-off one STEP
later, and then its crossing bisected over [TIME, NEXT + STEP]; else (:ROUND-OFF NEXT),
a zero the float cannot tell from a touch or a crossing."
  (let* ((later (+ next step)) (value (funcall function later)))
    (if (and value (below-round-off-p value (funcall tolerance later)))
        (bisect-crossing function time later)
        (list :round-off next))))

(defun crossing-tolerance (run solved groups condition)
  "The round-off margin of CONDITION's violation function over the closed-form motion of
GROUPS, a function of the time: *CROSSING-ROUND-OFF* times its ROUND-OFF-SCALE with the
run's numbers (0 where it has none: an OR of conditions, a value that is not real)."
  (let ((expression (substitute-expressions (numeric-bindings run)
                                            (condition-time-function run solved groups condition))))
    (lambda (time)
      (let ((scale (ames.algebra:round-off-scale expression (list (cons 'tau time)))))
        (if scale (* *crossing-round-off* scale) 0d0)))))

