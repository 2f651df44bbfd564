;;;; src/simulator/fork-boundaries.lisp -- a fork's boundary branch X = 0 (see
;;;; branching.lisp): the parameter the equation determines, solved for and put for its
;;;; value throughout the scenario (its own declaration and a query selecting it left out),
;;;; or, where none is solved for, the boundary listed unsimulated with why.

(in-package #:ames.simulator)

(defun boundary-substitution (run fact)
  "For the inequality FACT, (values PARAMETER VALUE) with the equation LHS = RHS solved
for a parameter of the scenario (the last declared one it determines uniquely, free of
itself; an angle met only under sin, cos and tan by its one root in its range and the
facts in force, ONE-ANGLE-ROOT), or NIL."
  (let ((equation `(= ,(relation-lhs fact) ,(relation-rhs fact))))
    (dolist (parameter (reverse (scenario-parameters (run-scenario run))))
      (let ((name (scenario-parameter-name parameter)))
        (unless (free-of-p name equation)
          (let ((solutions (handler-case (ames.maxima:solve-equations (run-bridge run)
                                                                      (list equation) (list name))
                             (ames.maxima:solve-failed () nil))))
            (when (and solutions (null (rest solutions)))
              (let ((value (tidy run (cdr (first (first solutions))) :full)))
                (when (free-of-p name value)
                  (return (values name value)))))
            ;; an angle met only in its sine, cosine and tangent (2 sin a - cos a = 0),
            ;; which solve() answers implicitly: its one root in its range, exactly
            (let ((value (ames.algebra:one-angle-root
                          (run-bridge run) `(- ,(relation-lhs fact) ,(relation-rhs fact)) name)))
              (when value
                (return (values name value))))))))))

(defun default-value-spec-p (spec)
  "True when SPEC, part of a parameter's declaration, is a default (:VALUE NUMBER)."
  (and (consp spec) (symbolp (first spec)) (string= (symbol-name (first spec)) "VALUE")))

(defun selects-parameter-p (clause parameter)
  "True when CLAUSE is a query selecting PARAMETER, (query NAME (parameter PARAMETER ...))."
  (and (consp clause) (symbolp (first clause)) (string= (symbol-name (first clause)) "QUERY")
       (consp (cddr clause)) (consp (third clause)) (symbolp (first (third clause)))
       (string= (symbol-name (first (third clause))) "PARAMETER")
       (symbolp (second (third clause)))
       (string= (symbol-name (second (third clause))) (symbol-name parameter))))

(defun substituted-form (form parameter value)
  "The scenario FORM with PARAMETER replaced by VALUE everywhere (in the other
parameters' assumptions too) but in its own declaration, which is dropped, and with no
parameter's default value. A query selecting PARAMETER is left out: its answer is read
off every path of the run (ANSWER-QUESTION), this boundary's among them, in the
scenario that declares it."
  (labels ((walk (x)
             (cond ((and (symbolp x) (string= (symbol-name x) (symbol-name parameter))) value)
                   ((atom x) x)
                   (t (cons (walk (car x)) (walk (cdr x)))))))
    (mapcar (lambda (clause)
              (if (and (consp clause) (symbolp (first clause))
                       (string= (symbol-name (first clause)) "PARAMETERS"))
                  (cons (first clause)
                        (mapcar (lambda (spec)
                                  ;; another parameter's assumptions may mention PARAMETER;
                                  ;; default values, chosen for the whole range, need not
                                  ;; lie on the boundary, and are dropped
                                  (if (consp spec)
                                      (cons (first spec)
                                            (walk (remove-if #'default-value-spec-p (rest spec))))
                                      spec))
                                (remove-if (lambda (spec)
                                             (let ((name (if (consp spec) (first spec) spec)))
                                               (and (symbolp name) (string= (symbol-name name)
                                                                            (symbol-name parameter)))))
                                           (rest clause))))
                  (walk clause)))
            (remove-if (lambda (clause) (selects-parameter-p clause parameter)) form))))

(defun parameter-facts (scenario parameter value)
  "The assumptions SCENARIO declares on PARAMETER, with VALUE put for it."
  (loop for relation in (scenario-assumption-relations scenario)
        unless (free-of-p parameter relation)
          collect (substitute-expressions (list (cons parameter value)) relation)))

(defun unsolved-boundary-branch (alternative selected)
  "The boundary ALTERNATIVE (X = 0) of a fork for which no parameter could be solved,
listed with its fact and why it is not simulated; :FAILED when the run's values lie on it
(SELECTED), so that the run does not pass for finished, else :NOT-SIMULATED."
  (append (list :assume (getf alternative :assume) :states '()
                :outcome (if selected :failed :not-simulated)
                :failure (getf alternative :unsolved))
          (and selected (list :selected t))))

