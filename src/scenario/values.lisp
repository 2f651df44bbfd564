;;;; src/scenario/values.lisp -- the numbers of a run: --set values and (:value N) defaults, checked against every assumption.
;;;;
;;;; A run given numbers (bin/ames --set p=v, or --numeric for the (:value N) defaults,
;;;; --set overriding them) must not break what the scenario declares: m = -2 against
;;;; m :positive, d = 1 against (> d b) with b = 2. Such numbers would silently vanish
;;;; from a report, or print wrong-signed positions; they are a PARAMETER-VALUE-ERROR
;;;; naming the parameter and the assumption instead. An assumption is checked when every
;;;; parameter it names has a value: exactly where its sides are rational, else with
;;;; intervals that enclose the exact values (ames.algebra:VALUE-TRUTH); a value too close
;;;; to a bound to tell which side it lies on is refused too.

(in-package #:ames.scenario)

(define-condition parameter-value-error (scenario-error)
  ((parameter :initarg :parameter :initform nil :reader parameter-value-error-parameter
              :documentation "The parameter whose assumption the values break.")
   (assumption :initarg :assumption :initform nil :reader parameter-value-error-assumption
               :documentation "The assumption, as declared (:POSITIVE, (> D B) ...)."))
  (:documentation "A run's parameter values (given with --set, or (:value N) defaults)
break a declared assumption or a coefficient's physical range. DATUM is the
assumption's relation."))

(setf (documentation 'parameter-value-error-parameter 'function)
      "The parameter whose assumption the values break, or NIL."
      (documentation 'parameter-value-error-assumption 'function)
      "The assumption the values break, as declared (:POSITIVE, (> D B) ...), or NIL.")

(defun value-reject (scenario parameter datum control &rest arguments)
  "Signal PARAMETER-VALUE-ERROR about PARAMETER (a SCENARIO-PARAMETER or NIL) of SCENARIO."
  (error 'parameter-value-error
         :scenario (scenario-name scenario)
         :location (if parameter
                       (format nil "parameter ~A" (symbol-name (scenario-parameter-name parameter)))
                       "the parameter values")
         :source (scenario-source scenario)
         :datum datum
         :parameter (and parameter (scenario-parameter-name parameter))
         :detail (apply #'scenario-detail scenario control arguments)))

(defun check-values-against-assumptions (scenario values)
  "Check the alist VALUES ((PARAMETER-SYMBOL . NUMBER) ...) against every assumption of
SCENARIO's parameters whose parameters all have a value. Returns VALUES. Signals
PARAMETER-VALUE-ERROR naming the parameter and the assumption the values break, or that
they come too close to for the check to tell."
  (dolist (parameter (scenario-parameters scenario) values)
    (let ((name (scenario-parameter-name parameter)))
      (dolist (assumption (scenario-parameter-assumptions parameter))
        (let ((relation (assumption-relation name assumption)))
          (when (every (lambda (variable) (assoc variable values))
                       (expression-variables relation))
            (case (ames.algebra:value-truth relation values)
              (:true)
              (:false
               (value-reject scenario parameter relation
                             "the value ~A of ~A breaks its assumption ~S~@[ (with ~{~A = ~A~^, ~})~]"
                             (cdr (assoc name values)) name assumption
                             (loop for (other . value) in values
                                   when (and (not (eq other name))
                                             (member other (expression-variables relation)))
                                     append (list other value))))
              (t
               (value-reject scenario parameter relation
                             "the value ~A of ~A is too close to the bound of its assumption ~S to check"
                             (cdr (assoc name values)) name assumption)))))))))

(defun run-parameter-values (scenario &key settings numeric)
  "The parameter values of a run of SCENARIO: its (:value N) defaults when NUMERIC is
true, overridden by SETTINGS (an alist (NAME . NUMBER), names matched by name, checked
by CHECK-PARAMETER-VALUES), as an alist (PARAMETER-SYMBOL . NUMBER) in declaration
order, checked against every assumption (see CHECK-VALUES-AGAINST-ASSUMPTIONS) and every
physical range of a coefficient (CHECK-COEFFICIENT-VALUES). Signals
PARAMETER-VALUES-ERROR for malformed SETTINGS, UNDECLARED-SYMBOL-ERROR for a name that
is no parameter, PARAMETER-VALUE-ERROR for values that break an assumption."
  (let* ((given (check-parameter-values settings scenario))
         (defaults (and numeric (scenario-parameter-values scenario)))
         (values (loop for parameter in (scenario-parameters scenario)
                       for name = (scenario-parameter-name parameter)
                       for entry = (or (assoc name given) (assoc name defaults))
                       when entry collect entry)))
    (check-values-against-assumptions scenario values)
    (check-coefficient-values scenario values)))

(defparameter *illustrative-candidates* '(1 2 1/2 3/2 3 1/4 4 3/4 5 1/10 10)
  "The values tried, in order, for a parameter that has none (see ADMISSIBLE-PARAMETER-VALUES).")

(defun admissible-parameter-values (scenario &optional given)
  "An alist (PARAMETER-SYMBOL . NUMBER) for every parameter of SCENARIO, in declaration
order: the number GIVEN (an alist keyed by parameter symbols) holds for it, else its
(:value N) default, else the first of *ILLUSTRATIVE-CANDIDATES* with which every
assumption over the parameters valued so far surely holds (1 when none does). Second
value: the parameters whose number was chosen here. The result is checked by
CHECK-VALUES-AGAINST-ASSUMPTIONS only by the caller (a candidate search may fail)."
  (let ((defaults (scenario-parameter-values scenario))
        (facts (scenario-assumption-relations scenario))
        (values '()) (chosen '()))
    (flet ((admissible-p (point)
             (every (lambda (fact)
                      (or (set-difference (expression-variables fact) (mapcar #'car point))
                          (eq :true (ames.algebra:value-truth fact point))))
                    facts)))
      (dolist (parameter (scenario-parameters scenario))
        (let* ((name (scenario-parameter-name parameter))
               (known (or (assoc name given) (assoc name defaults))))
          (push (cons name
                      (if known
                          (cdr known)
                          (progn
                            (push name chosen)
                            (or (find-if (lambda (candidate) (admissible-p (acons name candidate values)))
                                         *illustrative-candidates*)
                                1))))
                values))))
    (values (nreverse values) (nreverse chosen))))
