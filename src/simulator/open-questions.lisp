;;;; src/simulator/open-questions.lisp -- a sign question Maxima asks while integrating, which the
;;;; assumptions leave open, turned into the run's ambiguity (a branch).
;;;;
;;;; A closed-form integrator may need the sign of an expression over the parameters alone:
;;;; the discriminant of a damped oscillator (c^2 - 4 m k: over-, critically or under-damped),
;;;; of a Riccati equation, ... Each sign gives another closed form, all of them right under
;;;; their own fact, and none may be guessed. When the assumptions do not decide it, the
;;;; integrator signals AMBIGUOUS-TRANSITION with the missing fact X > 0: the run branches on
;;;; X > 0, X < 0 and the boundary X = 0 (see branching.lisp), and parameter values select
;;;; one branch. An expression that mentions the state or the time is no such fact.

(in-package #:ames.simulator)

(defun parameter-expression-p (run expression)
  "True when EXPRESSION is over the scenario's parameters, PI and numbers only."
  (let ((names (mapcar #'scenario-parameter-name (scenario-parameters (run-scenario run)))))
    (every (lambda (variable) (or (eq variable 'pi) (member variable names)))
           (expression-variables expression))))

(defun open-sign-question (run expression what)
  "Signal AMBIGUOUS-TRANSITION for the missing fact EXPRESSION > 0 (WHAT says what needs
its sign) when EXPRESSION is over the parameters and the assumptions leave its sign open;
return NIL otherwise (the caller goes on without a closed form)."
  (when (and expression (parameter-expression-p run expression)
             (null (one-sign (sign-of run expression))))
    (error 'ambiguous-transition :datum expression :missing-fact `(> ,expression 0)
                                 :detail what)))

(defun question-as-ambiguity (run question what)
  "The Maxima QUESTION (a MAXIMA-QUESTION) asked while integrating: when it is the sign of
one expression over the parameters that the assumptions leave open, the run's ambiguity
(see OPEN-SIGN-QUESTION); else NIL."
  (let ((expressions (ames.maxima:maxima-question-expressions question)))
    (when (and expressions (null (rest expressions)))
      (open-sign-question run (first expressions) what))))

(defparameter *sign-answers* 3
  "The most sign questions one integration gets answered from the assumptions before it
gives up (Maxima asking again what it was told would otherwise never end).")

(defun call-answering-sign-questions (run what function)
  "Call FUNCTION, answering each sign question Maxima asks during it: a sign the
assumptions decide (SIGN-OF, which also reasons where Maxima's own database does not, as
from k > c^2 / (4 m) to c^2 - 4 m k < 0) is assumed and the request retried (the
bridge's restart ASSUME-AND-RETRY); an open one is the run's ambiguity (see
QUESTION-AS-AMBIGUITY, WHAT saying what needs it). Other questions, and more than
*SIGN-ANSWERS*, end the call with the MAXIMA-QUESTION as before."
  (let ((answered 0))
    (handler-bind
        ((ames.maxima:maxima-question
           (lambda (question)
             (let* ((expressions (ames.maxima:maxima-question-expressions question))
                    (x (and expressions (null (rest expressions)) (first expressions)))
                    (signs (and x (parameter-expression-p run x) (sign-of run x))))
               (cond ((and (one-sign signs) (< answered *sign-answers*)
                           (find-restart 'ames.maxima:assume-and-retry question))
                      (incf answered)
                      (invoke-restart 'ames.maxima:assume-and-retry
                                      (list (list (ames.algebra:signs-relation signs) x 0))))
                     ((and signs (null (one-sign signs)))
                      (question-as-ambiguity run question what)))))))
      (funcall function))))
