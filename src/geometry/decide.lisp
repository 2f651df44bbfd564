;;;; src/geometry/decide.lisp -- deciding geometric facts: exact fast paths, else the Maxima bridge; only the facts that matter.
;;;;
;;;; Every comparison geometry makes (is this turn convex? does this point lie on that
;;;; edge?) is the sign of an expression in the shapes' coordinates. A DECIDER answers it:
;;;;   1. exact rational arithmetic, when the expression is rational;
;;;;   2. double-float evaluation, when the expression is a constant (no parameters) whose
;;;;      value is clearly away from zero (|v| > 1e-9): a constant like cos(1) - 1/2;
;;;;   3. otherwise the Maxima bridge, (ames.algebra:decide bridge relation), under the
;;;;      assumptions the caller has established with ames.maxima:with-assumptions.
;;;; When none answers, the fact is open. Inside a predicate run by
;;;; CALL-DECIDING-WHAT-MATTERS (a point on a piece, bodies overlapping), each open fact
;;;; is tried both ways (and a sign all three): when every choice gives the predicate the
;;;; same answer, the fact does not matter and is never asked (a point whose coordinate
;;;; lies outside a segment's span is not on it, whether or not it is on its line). A
;;;; fact that matters is decided by the run's parameter values when there are some
;;;; (ames.algebra:decide-by-values, which records it), else UNDECIDABLE-GEOMETRIC-FACT is
;;;; signalled, naming the fact, the subject (shape form or body pair) and, when found,
;;;; which parameter values make it hold and which make it fail, with restarts
;;;; ASSUME-TRUE and ASSUME-FALSE.

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
  "Ask the Maxima bridge whether RELATION holds: :TRUE, :FALSE or :UNKNOWN. Under values
that decide first, a relation they settle gets only a cheap proof: an :UNKNOWN is an
open fact, which the values then settle where it matters (see
AMES.ALGEBRA:DECIDE-FIRST-CHEAPLY)."
  (ames.algebra:decide-first-cheaply bridge relation))

(defun undecidable (decider relation &optional detail)
  "Signal UNDECIDABLE-GEOMETRIC-FACT for RELATION, its detail saying which parameter
values make it hold and which make it fail when such values are found. Restarts:
ASSUME-TRUE returns T, ASSUME-FALSE returns NIL."
  (let ((bridge (decider-bridge decider)))
    (restart-case
        (error 'undecidable-geometric-fact
               :fact relation :datum relation
               :subject (decider-subject decider)
               :detail (or detail
                           (if bridge
                               (format nil "neither exact arithmetic nor Maxima can decide it under the current assumptions~@[; ~A~]"
                                       (ames.algebra:explain-undecided bridge relation))
                               "no Maxima bridge was given to decide a symbolic fact")))
      (assume-true ()
        :report "Take the fact as true."
        t)
      (assume-false ()
        :report "Take the fact as false."
        nil))))

;;; Deciding only what matters

(defvar *fact-choices* :none
  "While CALL-DECIDING-WHAT-MATTERS explores a predicate: an alist (FACT . OUTCOME) of
the open facts taken one way on the branch being run; :NONE otherwise.")

(defparameter *most-exploration-runs* 64
  "How many times CALL-DECIDING-WHAT-MATTERS may run its predicate at most; beyond, open
facts are asked as they come, in the order met.")

(define-condition open-fact (condition)
  ((fact :initarg :fact :reader open-fact-relation)
   (outcomes :initarg :outcomes :reader open-fact-outcomes))
  (:documentation "Internal to CALL-DECIDING-WHAT-MATTERS: the predicate met a fact that
is open and not yet chosen on this branch. Never escapes the exploration."))

(defun sign-fact-p (fact)
  "True for an open fact (:SIGN X), the sign of X, as SIGN-OF asks it."
  (and (consp fact) (eq (first fact) :sign)))

(defun fact-relation (fact)
  "The relation an open FACT asks about: FACT itself, or (> X 0) for a sign fact (:SIGN X)."
  (if (sign-fact-p fact) (list '> (second fact) 0) fact))

(defun value-outcome (fact outcomes)
  "The outcome of OUTCOMES (T / NIL for a relation, :POSITIVE :ZERO :NEGATIVE for a sign
fact (:SIGN X)) that the run's parameter values give FACT, or :NONE."
  (if (not (sign-fact-p fact))
      (case (ames.algebra:decide-by-values fact)
        (:true t) (:false nil) (t :none))
      (let ((x (second fact)))
        (cond ((and (member :positive outcomes)
                    (eq (ames.algebra:value-truth (list '> x 0)) :true))
               (ames.algebra:decide-by-values (list '> x 0)) :positive)
              ((and (member :negative outcomes)
                    (eq (ames.algebra:value-truth (list '< x 0)) :true))
               (ames.algebra:decide-by-values (list '< x 0)) :negative)
              ((and (member :zero outcomes)
                    (eq (ames.algebra:value-truth (list '= x 0)) :true))
               (ames.algebra:decide-by-values (list '= x 0)) :zero)
              (t :none)))))

(defun restart-outcome (decider fact)
  "The outcome of FACT that the caller chooses through UNDECIDABLE's restarts: T or NIL
for a relation, :POSITIVE or :NEGATIVE for a sign fact."
  (let ((true (undecidable decider (fact-relation fact))))
    (if (sign-fact-p fact)
        (if true :positive :negative)
        true)))

(defun open-fact-outcome (decider fact outcomes)
  "The outcome chosen for the open FACT (a relation, or (:SIGN X)), which may have any
of OUTCOMES: on an explored
branch, the branch's choice; else the one the run's values give, else the one the
caller chooses through UNDECIDABLE's restarts."
  (if (listp *fact-choices*)
      (let ((entry (assoc fact *fact-choices* :test #'equal)))
        (if entry
            (cdr entry)
            (progn (signal 'open-fact :fact fact :outcomes outcomes)
                   (restart-outcome decider fact))))
      (let ((outcome (value-outcome fact outcomes)))
        (if (eq outcome :none) (restart-outcome decider fact) outcome))))

(defun exploration-tree (thunk choices budget)
  "Run THUNK on the branch CHOICES; the tree of its answers over the open facts met:
(:VALUE V), or (:SPLIT FACT OUTCOMES (OUTCOME . TREE) ...). A split whose subtrees are
all alike is replaced by one of them: that fact does not matter. BUDGET is a list whose
CAR counts the runs left; when none is left the tree is :EXHAUSTED."
  (if (minusp (decf (car budget)))
      :exhausted
      (handler-case (let ((*fact-choices* choices)) (list :value (funcall thunk)))
        (open-fact (condition)
          (let* ((fact (open-fact-relation condition))
                 (outcomes (open-fact-outcomes condition))
                 (branches (loop for outcome in outcomes
                                 collect (cons outcome
                                               (exploration-tree thunk (acons fact outcome choices)
                                                                 budget)))))
            (cond ((find :exhausted branches :key #'cdr) :exhausted)
                  ((every (lambda (branch) (equal (cdr branch) (cdr (first branches)))) branches)
                   (cdr (first branches)))
                  (t (list* :split fact outcomes branches))))))))

(defun call-deciding-what-matters (decider thunk)
  "Call THUNK, a geometric predicate that asks facts of DECIDER, and return its answer,
asking the caller (values, then UNDECIDABLE's restarts) only for the open facts whose
outcome changes that answer (see this file's header). Within an exploration already
under way, just calls THUNK. Signals UNDECIDABLE-GEOMETRIC-FACT for a fact that matters
and that the run's values do not decide."
  (if (listp *fact-choices*)
      (funcall thunk)
      (let ((tree (exploration-tree thunk '() (list *most-exploration-runs*))))
        (loop
          (cond ((eq tree :exhausted) (return (funcall thunk)))
                ((eq (first tree) :value) (return (second tree)))
                (t (destructuring-bind (fact outcomes &rest branches) (rest tree)
                     (let ((outcome (open-fact-outcome decider fact outcomes)))
                       (setf tree (or (cdr (assoc outcome branches))
                                      ;; a restart chose an outcome the branch never had
                                      (list :value (let ((*fact-choices* (list (cons fact outcome))))
                                                     (funcall thunk)))))))))))))

(defmacro deciding-what-matters ((decider) &body body)
  "Run BODY, a geometric predicate, asking only the facts that change its answer: see
CALL-DECIDING-WHAT-MATTERS."
  `(call-deciding-what-matters ,decider (lambda () ,@body)))

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
  "The sign of EXPRESSION: :NEGATIVE, :ZERO or :POSITIVE. When it cannot be settled, an
open fact (> EXPRESSION 0) (see OPEN-FACT-OUTCOME): UNDECIDABLE-GEOMETRIC-FACT is
signalled when it matters, the restarts ASSUME-TRUE / ASSUME-FALSE then answer
:POSITIVE / :NEGATIVE."
  (or (fast-sign expression)
      (let ((positive (bridge-truth decider (list '> expression 0))))
        (if (eq positive :true)
            :positive
            (let ((negative (bridge-truth decider (list '< expression 0))))
              (cond ((eq negative :true) :negative)
                    ((and (eq positive :false) (eq negative :false)) :zero)
                    (t (let ((zero (bridge-truth decider (list '= expression 0))))
                         (if (eq zero :true)
                             :zero
                             (open-fact-outcome decider (list :sign expression)
                                                (remove nil (list (and (not (eq positive :false)) :positive)
                                                                  (and (not (eq zero :false)) :zero)
                                                                  (and (not (eq negative :false)) :negative)))))))))))))

(defun sign-satisfies-p (operator sign)
  "True when (OPERATOR D 0) holds for a D of SIGN (:NEGATIVE, :ZERO or :POSITIVE);
OPERATOR is one of = /= < > <= >=."
  (and (member sign (ames.algebra:relation-signs operator)) t))

(defun fact-holds-p (decider relation)
  "True when RELATION, (REL LHS RHS) with REL one of = /= < > <= >=, holds; false when
it fails. Exact and constant facts are settled in Lisp, others by the bridge. When
neither can tell, RELATION is an open fact (see OPEN-FACT-OUTCOME): signals
UNDECIDABLE-GEOMETRIC-FACT naming RELATION when it matters and the run's values do not
decide it."
  (let* ((operator (car relation))
         (difference (e- (relation-lhs relation) (relation-rhs relation)))
         (sign (fast-sign difference)))
    (if sign
        (sign-satisfies-p operator sign)
        (case (bridge-truth decider (list operator difference 0))
          (:true t)
          (:false nil)
          (t (open-fact-outcome decider relation '(t nil)))))))

(defun fact-known-p (decider relation)
  "True when RELATION is known to hold (by arithmetic or the bridge); NIL when it fails
or cannot be decided. Never signals: for optional simplifications only. (The bridge's
HOLDS-P: a relation seen to fail at an admissible point costs no round trip.)"
  (let* ((operator (car relation))
         (difference (e- (relation-lhs relation) (relation-rhs relation)))
         (sign (fast-sign difference))
         (bridge (decider-bridge decider)))
    (cond (sign (sign-satisfies-p operator sign))
          (bridge (ames.algebra:holds-p bridge (list operator difference 0))))))

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
