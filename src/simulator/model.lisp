;;;; src/simulator/model.lisp -- a state's model solved: compact elimination, Maxima's solve,
;;;; the ODEs the components declare, and the local motion at the state's start.
;;;;
;;;; The engine hands over every equation the active instances assert. Most are
;;;; definitions (a force component, a frame or coordinate conversion, a fixed body's zero
;;;; acceleration): they are eliminated by substitution in Lisp first, so that Maxima
;;;; solves the compact system a person would write (Newton's law per body and one
;;;; constraint per contact); the JTMS still holds every equation with its justification.
;;;; The values are expressions over the parameters and the state variables (positions,
;;;; velocities, path coordinates: the terms of the DERIVATIVE beliefs), so one solution
;;;; serves the whole state whatever its integrator.

(in-package #:ames.simulator)

(defstruct (solved-model (:constructor %make-solved-model))
  "The solution of a state's model: VALUES, an alist quantity term -> expression over the
parameters and the STATE terms (those the DERIVATIVE beliefs declare); RATES, an alist
state term -> its rate's value; INITIAL, an alist state term -> its value at the start;
SERIES, a memo of local series; EQUATIONS, the compact system Maxima solved."
  (values '() :type list)
  (state '() :type list)
  (rates '() :type list)
  (initial '() :type list)
  (series (make-hash-table :test #'equal))
  (simplified (make-hash-table :test #'equal))
  (run nil)
  (equations '() :type list)
  (state-table nil))

(defun model-derivatives (model)
  "The ODEs the believed DERIVATIVE assertions of MODEL declare: an alist state term ->
rate term, in canonical order."
  (loop for belief in (ames.engine:model-beliefs model)
        when (eq (first belief) 'ames.kb:derivative)
          collect (cons (second belief) (third belief))))

(defun model-reported (model)
  "The believed REPORTED assertions of MODEL: a list of (SECTION ENTRY)."
  (loop for belief in (ames.engine:model-beliefs model)
        when (eq (first belief) 'ames.kb:reported)
          collect (list (second belief) (third belief))))

;;; Elimination of definitions: see elimination.lisp

(defun fold-zeros (expression)
  "EXPRESSION with products holding a literal 0 replaced by 0 and zero terms of sums and
differences dropped (a template's zero component times an unknown): no other change."
  (if (atom expression)
      expression
      (let ((arguments (mapcar #'fold-zeros (rest expression))))
        (case (first expression)
          (* (if (member 0 arguments) 0 (cons '* arguments)))
          (+ (let ((kept (remove 0 arguments)))
               (cond ((null kept) 0) ((null (rest kept)) (first kept)) (t (cons '+ kept)))))
          (- (cond ((null (rest arguments))
                    (let ((x (first arguments)))
                      (cond ((eql x 0) 0)
                            ((and (consp x) (eq (first x) '-) (null (cddr x))) (second x))
                            (t (list '- x)))))
                   ((every (lambda (a) (eql a 0)) (rest arguments)) (first arguments))
                   (t (cons '- arguments))))
          (t (if (quantity-term-p expression) expression (cons (first expression) arguments)))))))

(defun equation-unknowns (equations state)
  "The quantity terms of EQUATIONS that are not STATE terms nor a contact's path
coordinates (state quantities whatever the contact: on a straight one they only appear
multiplied by its zero curvature): the model's unknowns."
  (remove-if (lambda (term) (or (member term state :test #'equal)
                                (member (first term) '(ames.kb:path-position ames.kb:path-speed))))
             (remove-if-not #'quantity-term-p
                            (remove-duplicates (mapcan #'expression-variables
                                                       (copy-list equations))
                                               :test #'equal))))

(defun identity-p (run equation)
  "True when EQUATION holds whatever its unknowns (its sides' difference is 0 in rational
canonical form): a redundancy of the model, which Maxima's solve() must not see. A
polynomial difference is settled without Maxima (POLYNOMIAL-IDENTITY-VERDICT)."
  (let ((difference `(- ,(relation-lhs equation) ,(relation-rhs equation))))
    (case (polynomial-identity-verdict difference)
      (:zero t)
      (:nonzero nil)
      (t (eql 0 (tidy run difference))))))

(defun without-idle-path-terms (equations state)
  "EQUATIONS with the path coordinates of straight contacts (those that are not STATE
terms) set to 0: there they only appear multiplied by the contact's zero curvature."
  (let ((idle '()))
    (dolist (equation equations)
      (dolist (term (expression-variables equation))
        (when (and (quantity-term-p term)
                   (member (first term) '(ames.kb:path-position ames.kb:path-speed))
                   (not (member term state :test #'equal)))
          (pushnew (cons term 0) idle :test #'equal))))
    (if idle
        (mapcar (lambda (equation) (substitute-expressions idle equation)) equations)
        equations)))

(defun solve-compact (run equations unknowns)
  "Solve the compact EQUATIONS for UNKNOWNS through Maxima: the alist of the unique
solution, block by block where the structure allows (see structure.lisp). Signals
UNSOLVABLE-MODEL when there is none or several."
  (handler-case (or (solve-by-blocks run equations unknowns)
                    (solve-whole run equations unknowns))
    (ames.maxima:maxima-error (condition)
      ;; Maxima's solve() can fail on coefficients with radicals (sqrt(l^2 - d^2) beside
      ;; sqrt(g)...: "quotient by a polynomial of higher degree"); the same system with
      ;; each radical named apart solves
      (or (solve-with-radicals-named run equations unknowns)
          (error condition)))))

(defun solve-whole (run equations unknowns)
  "Solve the compact EQUATIONS for UNKNOWNS in one request: the alist of the unique
solution. Signals UNSOLVABLE-MODEL when there is none or several."
  (let ((solutions (handler-case (ames.maxima:solve-equations (run-bridge run) equations unknowns)
                     (ames.maxima:solve-failed (condition)
                       (error 'unsolvable-model
                              :datum equations
                              :detail (format nil "Maxima cannot solve the state's model: ~A"
                                              (ames-error-detail condition)))))))
    (cond ((null solutions)
           (error 'unsolvable-model :datum equations :detail "The state's model has no solution."))
          ((rest solutions)
           (error 'unsolvable-model :datum equations
                                    :detail "The state's model has several solutions."))
          (t (first solutions)))))

(defun back-substitute (solution definitions)
  "Every unknown's value: SOLUTION (alist) extended by DEFINITIONS (in elimination
order), each definition's expression with the later ones' values substituted."
  (let ((values (copy-list solution))
        ;; VALUES as a table, the first entry of a term winning as in ASSOC: each
        ;; substitution looks up only its expression's own terms (the same result as
        ;; SUBSTITUTE-EXPRESSIONS over the whole alist, without its N^2 list searches)
        (table (bindings-table solution)))
    (dolist (definition (reverse definitions) values)
      (let ((value (substitute-from-table table (cdr definition))))
        (setf (gethash (car definition) table) value)
        (push (cons (car definition) value) values)))))

(defun model-system (run model)
  "MODEL's equations as SOLVE-MODEL solves them, and their unknowns: (values EQUATIONS
UNKNOWNS STATE DERIVATIVES), STATE the state terms, DERIVATIVES the alist state term ->
rate term (MODEL-DERIVATIVES)."
  (let* ((derivatives (model-derivatives model))
         (state (mapcar #'car derivatives))
         (equations (without-idle-path-terms
                     (mapcar (lambda (e) (with-initial-positions run e))
                             (ames.engine:model-equations model))
                     state)))
    (values equations (equation-unknowns equations state) state derivatives)))

(defun solve-model (run model)
  "Solve MODEL's equations for every unknown quantity in terms of the parameters and
the state variables. Returns a SOLVED-MODEL whose rates and initial values are filled
in. Signals UNSOLVABLE-MODEL."
  (multiple-value-bind (equations unknowns state derivatives) (model-system run model)
    (multiple-value-bind (compact definitions) (eliminate-definitions equations unknowns)
      (let* ((compact (remove-if (lambda (equation) (identity-p run equation)) compact))
             (remaining (equation-unknowns compact state))
             (solution (if compact (solve-compact run compact remaining) '()))
             (values (back-substitute solution definitions))
             (statistics (run-statistics run)))
        (incf (getf statistics :equations-before) (length equations))
        (incf (getf statistics :equations-after) (length compact))
        (incf (getf statistics :solves))
        (setf (run-statistics run) statistics)
        (dolist (unknown unknowns)
          (unless (assoc unknown values :test #'equal)
            (error 'unsolvable-model :datum unknown
                                     :detail "The model does not determine this quantity.")))
        (let ((solved (%make-solved-model :values values :state state :equations compact
                                          :run run)))
          ;; the rates' simplifications asked together (prefetch-values.lisp)
          (prefetch-quantity-values run solved (mapcar #'cdr derivatives))
          (setf (solved-model-rates solved)
                (mapcar (lambda (entry)
                          (cons (car entry) (quantity-value solved (cdr entry))))
                        derivatives)
                (solved-model-initial solved)
                (mapcar (lambda (term) (cons term (initial-state-value run term))) state))
          solved)))))

(defun quantity-value (solved term)
  "The value of the quantity TERM in SOLVED, in its simplest form (Maxima's solve()
divides by factors that vanish at particular states, such as sin(s/r) where a curve's
normal is horizontal; simplification cancels them). A state term stands for itself."
  (if (member term (solved-model-state solved) :test #'equal)
      term
      (let ((entry (assoc term (solved-model-values solved) :test #'equal)))
        (unless entry
          (error 'unsolvable-model :datum term
                                   :detail "The model gives no value for this quantity."))
        (multiple-value-bind (value found) (gethash term (solved-model-simplified solved))
          (if found
              value
              (setf (gethash term (solved-model-simplified solved))
                    (tidy (solved-model-run solved) (cdr entry) :full)))))))

(defun expression-value-in (solved expression)
  "EXPRESSION with every quantity term the model solves replaced by its value (state
terms stay)."
  (substitute-expressions
   (loop for term in (expression-variables expression)
         when (and (quantity-term-p term)
                   (assoc term (solved-model-values solved) :test #'equal))
           collect (cons term (cdr (assoc term (solved-model-values solved) :test #'equal))))
   expression))

;;; Initial values of the state variables

(defun initial-state-value (run term)
  "The value of the state variable TERM at the start of the current state."
  (ecase (first term)
    (ames.kb:pos (axis-of (body-position run (second term)) (third term)))
    (ames.kb:vel (axis-of (body-velocity run (second term)) (third term)))
    (ames.kb:path-position (initial-arc-length run (second term)))
    (ames.kb:path-speed (initial-arc-speed run (second term)))
    ((ames.kb:angle ames.kb:angvel) (rotation-initial-value run term))))

(defun axis-of (vector axis)
  "The :X or :Y component of VECTOR."
  (ecase axis (:x (first vector)) (:y (second vector))))

(defun initial-arc-length (run contact)
  "The arc length of the observer's position on CONTACT at the start of the state."
  (tidy run (contact-parameter-of run (contact-geometry run contact)
                                  (relative-initial-state run contact))))

(defun initial-arc-speed (run contact)
  "The rate of the arc length along CONTACT at the start of the state."
  (let ((geometry (contact-geometry run contact)))
    (multiple-value-bind (q v) (relative-initial-state run contact)
      (declare (ignore q))
      (tidy run (ames.geometry:dot v (ames.geometry:contact-unit-tangent
                            geometry (initial-arc-length run contact)))))))

;;; Local series: every quantity near the start of the state, as a polynomial in TAU

(defparameter *series-order* 4
  "The highest power of TAU kept in a local series.")

(defun state-symbol (term)
  "A variable standing for the state term TERM while differentiating."
  (intern (format nil "~{~A~^.~}" term) '#:ames.simulator))

(defun time-derivative-in (solved expression)
  "The time derivative of EXPRESSION, a function of the state terms of SOLVED, by the
chain rule along the state's ODEs."
  (let ((sum 0)
        (mentioned (mentioned-terms expression)))
    (dolist (entry (solved-model-rates solved) sum)
      (let ((term (car entry)))
        (when (mentioned-p term mentioned expression)
          (let* ((symbol (state-symbol term))
                 (partial (substitute-expressions
                           (list (cons symbol term))
                           (ames.geometry:differentiate
                            (substitute-expressions (list (cons term symbol)) expression)
                            symbol))))
            (setf sum `(+ ,sum (* ,partial ,(cdr entry))))))))))

(defun series-coefficients (run solved expression count)
  "The first COUNT Taylor coefficients (C0 C1 ...) of EXPRESSION (a function of the
parameters and SOLVED's state terms, or of TAU) at the start of the state: the k-th is
the k-th time derivative there divided by k!, simplified. Computed as far as asked, one
derivative at a time, and memoized. Where a derivative cannot be evaluated at the start
\(0/0: |v| v at rest), the one-sided series for TAU > 0 (ONE-SIDED-SERIES) is taken."
  (let ((entry (or (gethash expression (solved-model-series solved))
                   (setf (gethash expression (solved-model-series solved))
                         ;; all exact numbers: power series (exact-series.lisp)
                         (let ((exact (exact-series-coefficients solved expression (1+ *series-order*))))
                           (if exact (list exact :exact 1) (list '() expression 1)))))))
    (when (and (eq (second entry) :exact) (< (length (first entry)) count))
      (setf (first entry) '() (second entry) expression (third entry) 1))
    (flet ((one-sided (condition)
             ;; no derivative at the start: the series for tau > 0, or CONDITION again
             (setf (first entry) (or (one-sided-series run solved expression count)
                                     (error condition))
                   (second entry) :one-sided)))
      (cond ((>= (length (first entry)) count))
            ((eq (second entry) :one-sided)
             (one-sided (make-condition 'ames.maxima:maxima-error
                                        :datum expression :message "no one-sided series")))
            (t (handler-case (extend-series run solved entry count)
                 (ames.maxima:maxima-error (condition) (one-sided condition))))))
    (subseq (first entry) 0 count)))

(defun extend-series (run solved entry count)
  "Extend the memoized series ENTRY (COEFFICIENTS DERIVATIVE FACTORIAL) of
SERIES-COEFFICIENTS to COUNT coefficients, one derivative at a time."
  (loop while (< (length (first entry)) count)
        do (destructuring-bind (coefficients derivative factorial) entry
             (let* ((k (length coefficients))
                    (factorial (if (> k 0) (* factorial k) factorial))
                    (c (tidy run (without-zeros
                                  (at-time (substitute-expressions (solved-model-initial solved)
                                                                   `(/ ,derivative ,factorial))
                                           0)))))
               (setf (first entry) (append coefficients (list c))
                     (third entry) factorial
                     (second entry) (if (< k *series-order*)
                                        (compact-derivative
                                         run (without-zeros
                                              `(+ ,(ames.geometry:differentiate derivative 'tau)
                                                  ,(time-derivative-in solved derivative))))
                                        derivative))))))

(defparameter *series-derivative-growth* 50
  "How many times the expression size limit (AMES.BASE:LIMITS-EXPRESSION-SIZE, in conses
here) a local series' next derivative may reach before the run is refused as over its
budget (COMPACT-DERIVATIVE).")

(defun size-beyond-p (expression size)
  "True when EXPRESSION has more than SIZE conses (counted no further)."
  (let ((count 0))
    (labels ((walk (x)
               (when (consp x)
                 (when (> (incf count) size) (return-from size-beyond-p t))
                 (walk (car x)) (walk (cdr x)))))
      (walk expression)
      nil)))

(defun compact-derivative (run derivative)
  "DERIVATIVE, a local series' next time derivative, after checking its size: each
differentiation by the chain rule multiplies the size of the unsimplified expression (a
block flush with a ledge's edge, its rates over the sine and cosine of its angle, grew
from 1,500 to 1,800,000 conses in three steps and the next step exhausted the heap).
Beyond *SERIES-DERIVATIVE-GROWTH* times the expression size limit, BUDGET-EXCEEDED (its
quantity :EXPRESSION-SIZE) refuses the run instead; simplifying it in Maxima there
outlasts Maxima's time limit."
  (declare (ignore run))
  (let* ((size (limits-expression-size (current-limits)))
         (limit (and size (* *series-derivative-growth* size))))
    (when (and limit (size-beyond-p derivative limit))
      (check-expression-size (1+ limit) :local-series-derivative)))
  derivative)

(defun local-series (run solved expression)
  "The Taylor coefficients (C0 C1 ... Cn), n = *SERIES-ORDER*, of EXPRESSION at the start
of the state (see SERIES-COEFFICIENTS)."
  (series-coefficients run solved expression (1+ *series-order*)))

(defun leading-sign-of (run solved expression)
  "LEADING-SIGN of EXPRESSION's local series, its coefficients computed only as far as
needed (the first whose sign is not zero decides)."
  (loop for k from 0 to *series-order*
        for c = (car (last (series-coefficients run solved expression (1+ k))))
        for signs = (sign-of run c)
        unless (eq (one-sign signs) :zero)
          do (return (values signs c))
        finally (return (values (list :zero) 0))))

(defun series-polynomial (coefficients)
  "The polynomial in TAU with COEFFICIENTS (C0 C1 ...)."
  (cons '+ (loop for c in coefficients for k from 0
                 collect `(* ,c (expt tau ,k)))))

(defun leading-sign (run coefficients)
  "The sign of a function just after the start, from its local series COEFFICIENTS:
(values SIGNS COEFFICIENT) with SIGNS the sign set (see SIGN-OF) of the first
coefficient not proven zero (one sign, or all three when it is not decided), or
(values (:ZERO) 0) when every coefficient is zero (the function vanishes identically,
as far as the series goes)."
  (dolist (c coefficients (values (list :zero) 0))
    (let ((signs (sign-of run c)))
      (unless (one-sign signs)
        ;; the series is only ratsimped: its trigonometric form may hide a fact the
        ;; assumptions decide (cos^2 + sin^2), so the simplest form gets a second look
        (setf c (tidy run c :full)
              signs (sign-of run c)))
      (unless (eq (one-sign signs) :zero)
        (return (values signs c))))))
