;;;; src/simulator/rootless-ends.lisp -- a state whose end is a root the algebra cannot
;;;; find, in a run without numbers (issue 23).
;;;;
;;;; Where a state's end lies at a root of a function of its time or its angle that has no
;;;; closed form (a block tipping about its edge lifts off where its normal force,
;;;; quadratic in the sine and cosine of its angle, reaches zero), the ambiguity's missing
;;;; fact is (:ROOTS-OF (= F 0)): no inequality over the parameters, which no fork can
;;;; assume and no fact will decide. Without parameter values the state's motion is
;;;; still known in closed form; only its end is not. It is reported as a state whose
;;;; motion has no closed form is (STATE-END-CANDIDATES): undecided, its duration waiting
;;;; for parameter values, rather than lost with an ambiguity.

(in-package #:ames.simulator)

(defun rootless-end-p (run condition)
  "True when the AMBIGUOUS-TRANSITION CONDITION is a state's end at a root without closed
form ((:ROOTS-OF ...)), carrying that state, in a RUN that has no numbers to find the
root with."
  (let ((fact (ambiguous-transition-missing-fact condition)))
    (and (consp fact) (eq (first fact) :roots-of)
         (ambiguous-transition-state condition)
         (not (run-numbers-known-p run)))))

(defun note-rootless-end (run history index condition)
  "When CONDITION is a rootless end (ROOTLESS-END-P) of the state INDEX: that state,
with its motion, appended to HISTORY as undecided (its duration needs parameter values),
and the history's outcome :UNDECIDED; true then, else NIL."
  (let ((state (ambiguous-transition-state condition)))
    (when (and (rootless-end-p run condition) (eql (state-index state) index))
      (setf (state-duration state) (list :no-closed-form :needs :parameter-values)
            (state-end-event state) :undecided
            (state-undecided-detail state)
            (concatenate 'string "Where the state ends is a root the algebra cannot find in"
                         " closed form; give the parameters numbers (--set) to find it.")
            (history-states history) (append (history-states history) (list state))
            (history-outcome history) :undecided)
      (when (and *state-hook* (> index *states-reported-before*))
        (funcall *state-hook* history state))
      t)))
