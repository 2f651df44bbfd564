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
             (eq (sign-of run expression) :unknown))
    (error 'ambiguous-transition :datum expression :missing-fact `(> ,expression 0)
                                 :detail what)))

(defun question-as-ambiguity (run question what)
  "The Maxima QUESTION (a MAXIMA-QUESTION) asked while integrating: when it is the sign of
one expression over the parameters that the assumptions leave open, the run's ambiguity
(see OPEN-SIGN-QUESTION); else NIL."
  (let ((expressions (ames.maxima:maxima-question-expressions question)))
    (when (and expressions (null (rest expressions)))
      (open-sign-question run (first expressions) what))))
