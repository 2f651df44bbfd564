;;;; src/geometry/decide.lisp -- deciding geometric facts: exact fast paths, else the Maxima bridge.
;;;;
;;;; Every comparison geometry makes (is this turn convex? does this point lie on that
;;;; edge?) is the sign of an expression in the shapes' coordinates. A DECIDER answers it:
;;;;   1. exact rational arithmetic, when the expression is rational;
;;;;   2. double-float evaluation, when the expression is a constant (no parameters) whose
;;;;      value is clearly away from zero (|v| > 1e-9): a constant like cos(1) - 1/2;
;;;;   3. otherwise the Maxima bridge, (ames.maxima:decide bridge relation), under the
;;;;      assumptions the caller has established with ames.maxima:with-assumptions.
;;;; When none answers, UNDECIDABLE-GEOMETRIC-FACT is signalled, naming the fact and the
;;;; subject (shape form or body pair), with restarts ASSUME-TRUE and ASSUME-FALSE.

(in-package #:ames.geometry)

(defstruct (decider (:constructor make-decider (&key bridge subject)))
  "What geometry needs to decide facts: the Maxima bridge (or NIL: exact and constant
facts only) and the subject named when a fact cannot be decided."
  (bridge nil)
  (subject nil))

(defun decider-about (decider subject)
  "A decider like DECIDER whose undecidable facts name SUBJECT."
  (make-decider :bridge (decider-bridge decider) :subject subject))

(defun ensure-decider (bridge-or-decider &optional subject)
  "A DECIDER from a bridge, NIL or an existing decider."
  (if (decider-p bridge-or-decider)
      (if subject (decider-about bridge-or-decider subject) bridge-or-decider)
      (make-decider :bridge bridge-or-decider :subject subject)))

(defun bridge-decide (bridge relation)
  "Ask the Maxima bridge whether RELATION holds: :TRUE, :FALSE or :UNKNOWN."
  (ames.maxima:decide bridge relation))

(defun undecidable (decider relation &optional detail)
  "Signal UNDECIDABLE-GEOMETRIC-FACT for RELATION. Restarts: ASSUME-TRUE returns T,
ASSUME-FALSE returns NIL."
  (restart-case
      (error 'undecidable-geometric-fact
             :fact relation :datum relation
             :subject (decider-subject decider)
             :detail (or detail
                         (if (decider-bridge decider)
                             "neither exact arithmetic nor Maxima can decide it under the current assumptions"
                             "no Maxima bridge was given to decide a symbolic fact")))
    (assume-true ()
      :report "Take the fact as true."
      t)
    (assume-false ()
      :report "Take the fact as false."
      nil)))

(defun fast-sign (expression)
  "The sign (:NEGATIVE, :ZERO or :POSITIVE) of EXPRESSION when arithmetic alone settles
it (see CONSTANT-SIGN), else NIL."
  (case (constant-sign expression)
    (-1 :negative) (0 :zero) (1 :positive)))

(defun bridge-truth (decider relation)
  "The bridge's answer on RELATION (:TRUE, :FALSE or :UNKNOWN); :UNKNOWN without a bridge."
  (let ((bridge (decider-bridge decider)))
    (if bridge (bridge-decide bridge relation) :unknown)))

(defun sign-of (decider expression)
  "The sign of EXPRESSION: :NEGATIVE, :ZERO or :POSITIVE. Signals
UNDECIDABLE-GEOMETRIC-FACT (naming (> EXPRESSION 0)) when it cannot be settled; the
restarts ASSUME-TRUE / ASSUME-FALSE then answer :POSITIVE / :NEGATIVE."
  (or (fast-sign expression)
      (let ((positive (bridge-truth decider (list '> expression 0))))
        (if (eq positive :true)
            :positive
            (let ((negative (bridge-truth decider (list '< expression 0))))
              (cond ((eq negative :true) :negative)
                    ((and (eq positive :false) (eq negative :false)) :zero)
                    ((eq (bridge-truth decider (list '= expression 0)) :true) :zero)
                    ((undecidable decider (list '> expression 0)) :positive)
                    (t :negative)))))))

(defun sign-satisfies-p (operator sign)
  "True when (OPERATOR D 0) holds for a D of SIGN (:NEGATIVE, :ZERO or :POSITIVE);
OPERATOR is one of = /= < > <= >=."
  (ecase operator
    (= (eq sign :zero)) (/= (not (eq sign :zero)))
    (< (eq sign :negative)) (> (eq sign :positive))
    (<= (not (eq sign :positive))) (>= (not (eq sign :negative)))))

(defun fact-holds-p (decider relation)
  "True when RELATION, (REL LHS RHS) with REL one of = /= < > <= >=, holds; false when
it fails. Exact and constant facts are settled in Lisp, others by the bridge. Signals
UNDECIDABLE-GEOMETRIC-FACT naming RELATION when neither can tell."
  (let* ((operator (car relation))
         (difference (e- (relation-lhs relation) (relation-rhs relation)))
         (sign (fast-sign difference)))
    (if sign
        (sign-satisfies-p operator sign)
        (case (bridge-truth decider (list operator difference 0))
          (:true t)
          (:false nil)
          (t (undecidable decider relation))))))

(defun fact-known-p (decider relation)
  "True when RELATION is known to hold (by arithmetic or the bridge); NIL when it fails
or cannot be decided. Never signals: for optional simplifications only."
  (let* ((operator (car relation))
         (difference (e- (relation-lhs relation) (relation-rhs relation)))
         (sign (fast-sign difference)))
    (if sign
        (sign-satisfies-p operator sign)
        (eq (bridge-truth decider (list operator difference 0)) :true))))

(defun positive-p (decider x) "X > 0." (fact-holds-p decider (list '> x 0)))
(defun negative-p (decider x) "X < 0." (fact-holds-p decider (list '< x 0)))
(defun zero-p (decider x) "X = 0." (fact-holds-p decider (list '= x 0)))
(defun nonnegative-p (decider x) "X >= 0." (fact-holds-p decider (list '>= x 0)))

(defun tidy (decider expression)
  "EXPRESSION in a simpler equal form: unchanged when it is a number or an atom or when
there is no bridge, else Maxima's :FULL simplification under the current assumptions
(unchanged too when Maxima's answer falls outside the algebra, e.g. an absolute value)."
  (let ((bridge (decider-bridge decider)))
    (if (or (null bridge) (atom expression) (rational-value expression))
        expression
        (handler-case (ames.maxima:simplify bridge expression :strategy :full)
          (ames.maxima:untranslatable-result () expression)))))

(defun tidy-vector (decider v)
  "The vector V with both components tidied."
  (list (tidy decider (first v)) (tidy decider (second v))))
