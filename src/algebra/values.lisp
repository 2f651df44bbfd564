;;;; src/algebra/values.lisp -- numbers before proofs: the parameter values of a run, and the values that show a fact undecided.
;;;;
;;;; DECIDE never guesses: it answers :TRUE or :FALSE only with a proof. Two things a user
;;;; needs besides, both numeric:
;;;;   - when the run was given values (bin/ames --set p=v), a fact the assumptions leave
;;;;     open but the values decide is used for that run and reported
;;;;     (CALL-WITH-PARAMETER-VALUES, DECIDE-BY-VALUES, FACTS-FROM-VALUES);
;;;;   - without values, a fact that holds at one admissible point and fails at another
;;;;     is a real ambiguity, and the message says which values give which outcome
;;;;     (EXPLAIN-UNDECIDED).
;;;; Values are exact rationals (or floats taken as given). A relation is evaluated exactly
;;;; where its sides are rational, else as balls that enclose the exact value (see
;;;; witnesses.lisp): a value too close to call decides nothing.

(in-package #:ames.algebra)

(defvar *parameter-values* '()
  "The parameter values of the current run: an alist (PARAMETER . NUMBER), bound by
CALL-WITH-PARAMETER-VALUES; NIL when the run has none.")

(defvar *facts-from-values* nil
  "A list holding, in its CAR, the facts DECIDE-BY-VALUES has decided in the current run
(each as it holds), newest first.")

(defun call-with-parameter-values (values thunk)
  "Call THUNK with VALUES (an alist (PARAMETER . NUMBER), NUMBER an exact rational or a
float) as the current run's parameter values, and a fresh record of the facts decided by
them; return THUNK's values. Signals INVALID-BRIDGE-ARGUMENT when VALUES is not such an
alist."
  (unless (and (alexandria:proper-list-p values)
               (every (lambda (entry) (and (consp entry) (subject-p (car entry))
                                           (realp (cdr entry)) (finite-real-p (cdr entry))))
                      values))
    (error 'invalid-bridge-argument :datum values
                                    :detail "parameter values must be an alist (PARAMETER . NUMBER)"))
  (let ((*parameter-values* values)
        (*facts-from-values* (list '())))
    (funcall thunk)))

(defun current-parameter-values ()
  "The parameter values of the current run (see CALL-WITH-PARAMETER-VALUES), an alist."
  *parameter-values*)

(defmacro with-parameter-values ((values) &body body)
  "Run BODY with VALUES as the current run's parameter values: see
CALL-WITH-PARAMETER-VALUES."
  `(call-with-parameter-values ,values (lambda () ,@body)))

(defun value-point (values)
  "VALUES as a point of balls (see EXPRESSION-BALL) that enclose them exactly."
  (mapcar (lambda (entry)
            (cons (car entry)
                  (let ((x (cdr entry)))
                    (if (rationalp x)
                        (rounded-ball (coerce x 'double-float) 0d0)
                        (make-ball (coerce x 'double-float) 0d0)))))
          values))

(defun exact-relation-truth (relation values)
  "The truth of the relation RELATION at VALUES when both sides have exact rational
values there: :TRUE or :FALSE; else NIL."
  (multiple-value-bind (lhs lhs-exact) (expression-value (relation-lhs relation) values)
    (multiple-value-bind (rhs rhs-exact) (expression-value (relation-rhs relation) values)
      (when (and (rationalp lhs) (rationalp rhs) lhs-exact rhs-exact)
        (if (ecase (expression-operator relation)
              (= (= lhs rhs)) (/= (/= lhs rhs))
              (< (< lhs rhs)) (> (> lhs rhs)) (<= (<= lhs rhs)) (>= (>= lhs rhs)))
            :true
            :false)))))

(defun value-truth (relation &optional (values *parameter-values*))
  "The truth of RELATION (a relation or a logical form) at the parameter VALUES (an
alist, by default the current run's): :TRUE or :FALSE, or NIL when the values do not
settle it (a variable without a value, a value too close to call, a side undefined).
Asks Maxima nothing."
  (labels ((truth (condition)
             (case (expression-operator condition)
               (not (case (truth (second condition)) (:true :false) (:false :true)))
               (and (let ((truths (mapcar #'truth (expression-arguments condition))))
                      (cond ((member :false truths) :false)
                            ((every (lambda (x) (eq x :true)) truths) :true))))
               (or (let ((truths (mapcar #'truth (expression-arguments condition))))
                     (cond ((member :true truths) :true)
                           ((every (lambda (x) (eq x :false)) truths) :false))))
               (t (or (exact-relation-truth condition values)
                      (condition-truth condition (value-point values)))))))
    (and values (truth relation))))

(defun negated-relation (relation)
  "The relation saying the opposite of RELATION (a relation of the algebra)."
  (negate-condition relation))

(defun decide-by-values (relation)
  "The truth of RELATION at the current run's parameter values (see VALUE-TRUTH), or NIL
when there are none or they do not settle it. A fact settled is recorded, as it holds
(RELATION or its negation), among the FACTS-FROM-VALUES of the run."
  (let ((truth (value-truth relation)))
    (when (and truth *facts-from-values*)
      (pushnew (if (eq truth :true) relation (negated-relation relation))
               (car *facts-from-values*) :test #'equal))
    truth))

(defun facts-from-values ()
  "The facts the current run's parameter values decided (see DECIDE-BY-VALUES), oldest
first, each as it holds."
  (and *facts-from-values* (reverse (car *facts-from-values*))))

;;; Which values give which outcome

(defun rounded-value (x digits)
  "The rational with DIGITS significant decimal digits nearest the real X."
  (if (zerop x)
      0
      (let* ((exponent (- (floor (log (abs x) 10)) (1- digits)))
             (unit (expt 10 exponent)))
        (* unit (round (rational x) unit)))))

(defun nice-point (point relation facts truth)
  "POINT (an alist subject -> double float) with its values rounded to as few
significant digits as keep every fact of FACTS surely true and RELATION surely of TRUTH
there; POINT itself, with its values as rationals, when no rounding does."
  (loop for digits from 1 to 6
        for rounded = (mapcar (lambda (entry) (cons (car entry) (rounded-value (cdr entry) digits)))
                              point)
        when (and (every (lambda (fact) (eq (value-truth fact rounded) :true)) facts)
                  (eq (value-truth relation rounded) truth))
          return rounded
        finally (return (mapcar (lambda (entry) (cons (car entry) (rational (cdr entry)))) point))))

(defun point-description (point subjects)
  "The values of SUBJECTS at POINT, as text: \"a = 0.3, h = 2\"."
  (let ((*print-case* :downcase) (*read-default-float-format* 'double-float))
    (format nil "~{~A~^, ~}"
            (loop for subject in subjects
                  for entry = (assoc subject point :test #'equal)
                  when entry
                    collect (format nil "~A = ~A" (prin1-to-string subject)
                                    (let ((x (cdr entry)))
                                      (if (integerp x) x (coerce x 'double-float))))))))

(defun undecided-witnesses (bridge relation)
  "Two admissible points (alists subject -> rational) at which the inequality RELATION
holds and fails, as (values HOLDS FAILS), found numerically; NIL when none are found.
For an equation, the points where its left side is above and below its right."
  (check-translatable relation :condition)
  (let ((inequality (if (member (expression-operator relation) '(= /=))
                        (list '> (relation-lhs relation) (relation-rhs relation))
                        relation)))
    (when (relation-operator-p (expression-operator inequality))
      (multiple-value-bind (holds fails facts) (relation-witnesses bridge inequality)
        (when holds
          (values (nice-point holds inequality facts :true)
                  (nice-point fails inequality facts :false)))))))

(defun explain-undecided (bridge relation)
  "A sentence saying which admissible parameter values make the relation RELATION hold
and which make it fail (\"it holds at a = 0.3, h = 2 and fails at a = 1.2, h = 2\"), or
NIL when no such values are found. For an equation, which values make its left side the
larger and which the smaller. Asks Maxima nothing."
  (multiple-value-bind (holds fails) (undecided-witnesses bridge relation)
    (when holds
      (let ((subjects (expression-variables relation))
            (equation (member (expression-operator relation) '(= /=))))
        (format nil "~:[it holds~;the left side is larger~] at ~A and ~:[fails~;smaller~] at ~A"
                equation (point-description holds subjects)
                equation (point-description fails subjects))))))
