;;;; src/scenario/parameters.lisp -- the parameters of a scenario: their assumptions,
;;;; numeric bounds that exclude each other, and default values that violate them.

(in-package #:ames.scenario)


(defun parameter-spec-name (spec)
  "The name in a parameter SPEC (SYMBOL or (SYMBOL ASSUMPTION ...)), or SPEC itself."
  (if (consp spec) (car spec) spec))

(defparameter +bound-operators+ '(> < >= <=)
  "The relations an assumption may state.")

(defun checked-assumption (validation name assumption)
  "ASSUMPTION about the parameter NAME, canonical: :POSITIVE, :NONNEGATIVE or
(REL NAME EXPR). (:value N) is handled by the caller."
  (flet ((bad ()
           (reject validation 'scenario-syntax-error assumption
                   "~A is not an assumption; an assumption is :positive, :nonnegative, ~
                    (> ~A EXPR), (< ~A EXPR), (>= ~A EXPR), (<= ~A EXPR) or (:value NUMBER)"
                   (show assumption) (show name) (show name) (show name) (show name))))
    (cond ((keyword-named-p assumption "POSITIVE") :positive)
          ((keyword-named-p assumption "NONNEGATIVE") :nonnegative)
          ((not (and (consp assumption) (proper-list-p assumption))) (bad))
          ((not (find (algebra-operator-named (first assumption)) +bound-operators+)) (bad))
          ((/= (length assumption) 3) (bad))
          ((not (and (symbolp (second assumption)) (second assumption)
                     (same-name-p (second assumption) name)))
           (reject validation 'scenario-syntax-error assumption
                   "an assumption about ~A must have the form (~A ~A EXPR)"
                   (show name) (show (first assumption)) (show name)))
          (t (make-relation (algebra-operator-named (first assumption)) name
                            (checked-expression validation (third assumption)))))))

(defun checked-parameter (validation spec)
  "The SCENARIO-PARAMETER that SPEC, (SYMBOL ASSUMPTION ...) or SYMBOL, declares."
  (let ((name (cdr (declared validation (parameter-spec-name spec))))
        (assumptions '())
        (value nil))
    (enter validation (format nil "parameter ~A" (symbol-name name)) spec)
    (dolist (assumption (if (consp spec) (rest spec) '()))
      (if (and (consp assumption) (keyword-named-p (first assumption) "VALUE"))
          (progn
            (when value
              (reject validation 'duplicate-clause-error assumption
                      "~A has two default values" (show name)))
            (unless (and (proper-list-p assumption) (= (length assumption) 2))
              (reject validation 'scenario-expression-error assumption
                      "a default value is (:value NUMBER) with a finite real NUMBER, not ~A"
                      (show assumption)))
            (setf value (default-value validation assumption)))
          (push (checked-assumption validation name assumption) assumptions)))
    (make-instance 'scenario-parameter :name name :assumptions (nreverse assumptions)
                                       :value value)))

(defun constant-bounds (parameter)
  "The bounds that PARAMETER's assumptions put on it with a numeric value: a list of
(SIDE VALUE EXACT STRICT ASSUMPTION), SIDE :LOWER or :UPPER."
  (loop with name = (scenario-parameter-name parameter)
        for assumption in (scenario-parameter-assumptions parameter)
        for relation = (assumption-relation name assumption)
        for operator = (first relation)
        append (multiple-value-bind (value exact) (expression-value (relation-rhs relation))
                 (and value
                      (list (list (if (member operator '(> >=)) :lower :upper)
                                  value exact (and (member operator '(> <)) t)
                                  assumption))))))

(defun check-parameter-bounds (validation parameter)
  "Signal CONTRADICTORY-ASSUMPTIONS-ERROR when two numeric bounds of PARAMETER
exclude each other (a (> x 2) with a (< x 1))."
  (let ((bounds (constant-bounds parameter)))
    (dolist (lower (remove :upper bounds :key #'first))
      (dolist (upper (remove :lower bounds :key #'first))
        (destructuring-bind (side-l low low-exact low-strict low-assumption) lower
          (declare (ignore side-l))
          (destructuring-bind (side-u high high-exact high-strict high-assumption) upper
            (declare (ignore side-u))
            (let ((order (compare-values low low-exact high high-exact)))
              (when (or (eq order :greater)
                        (and (eq order :equal) (or low-strict high-strict)))
                (reject validation 'contradictory-assumptions-error
                        (list low-assumption high-assumption)
                        "the assumptions ~A and ~A on ~A cannot both hold"
                        (show low-assumption) (show high-assumption)
                        (show (scenario-parameter-name parameter)))))))))))

(defun check-default-values (validation parameters)
  "Signal CONTRADICTORY-ASSUMPTIONS-ERROR when the default :values of PARAMETERS
violate one of their assumptions (decided where every parameter involved has one)."
  (let ((bindings (loop for parameter in parameters
                        when (scenario-parameter-value parameter)
                          collect (cons (scenario-parameter-name parameter)
                                        (scenario-parameter-value parameter)))))
    (dolist (parameter parameters)
      (let ((name (scenario-parameter-name parameter)))
        (dolist (assumption (scenario-parameter-assumptions parameter))
          (let ((relation (assumption-relation name assumption)))
            (multiple-value-bind (lhs lhs-exact) (expression-value (relation-lhs relation) bindings)
              (multiple-value-bind (rhs rhs-exact) (expression-value (relation-rhs relation) bindings)
                (when (and lhs rhs
                           (eq (relation-holds-p (first relation) lhs lhs-exact rhs rhs-exact)
                               :false))
                  (enter validation (format nil "parameter ~A" (symbol-name name)) nil)
                  (reject validation 'contradictory-assumptions-error assumption
                          "the default value ~A of ~A violates its assumption ~A"
                          lhs (show name) (show assumption)))))))))))
