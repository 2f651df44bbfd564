;;;; src/algebra/combined-bounds.lisp -- a strategy of DECIDE: two facts that bound one variable, combined.
;;;;
;;;; The order substitution (orders.lisp) writes a variable V as its bound plus an excess,
;;;; one fact at a time. A relation that follows from two facts together, each linear in
;;;; V, is not found that way: under P > mu m g and T: (k/2)(P - mu m g) - tau >= 0 (tau
;;;; linear in P), Q = 2 D (P - mu m g) - 3 (k + mu w) tau > 0 holds because
;;;; Q = 3 (k + mu w) T + (4 w^2 + k^2 - 3 mu w k)/2 (P - mu m g), a sum of facts with
;;;; nonnegative multipliers (Farkas's lemma in the one variable P). DECIDE-BY-COMBINED-BOUNDS
;;;; looks for that: a relation f > 0 (or >= 0) whose f is of degree 1 in a variable V,
;;;; and two facts s1 >= 0, s2 >= 0 (or > 0) of degree 1 in V, with f = a s1 + b s2 exactly
;;;; (a and b free of V, solved from the coefficients of V^0 and V^1); when a >= 0 and b >= 0
;;;; are proven (and f's strictness follows, with a's and b's divisors nonzero: the
;;;; identity then holds everywhere), f > 0 holds wherever the facts do. Sound:
;;;; every step is an identity or a proven sign. Costly, so tried last, on small relations,
;;;; and the multipliers are first evaluated at admissible points (witnesses.lisp): a pair
;;;; whose multiplier is negative at one is not asked of Maxima.

(in-package #:ames.algebra)

(defvar *combining-bounds* nil
  "True while DECIDE-BY-COMBINED-BOUNDS decides the signs of multipliers, so that it does
not recurse.")

(defvar *combined-bounds-wanted* t
  "NIL where a caller wants only the cheaper strategies (the presentation's sign questions,
asked for every term of every printed form): DECIDE-BY-COMBINED-BOUNDS then answers
:UNKNOWN as a cut, not cached, so that a later question may still be proven by it.")

(defparameter *largest-relation-for-combined-bounds* 400
  "The largest relation (EXPRESSION-SIZE) DECIDE-BY-COMBINED-BOUNDS works on.")

(defparameter *deepest-combined-bounds* 2
  "How many DECIDE calls may be under way (the relation asked and the rewritten ones its
reasoning asks) for DECIDE-BY-COMBINED-BOUNDS to work; deeper, it answers :UNKNOWN as a
cut (not cached).")

(defparameter *most-combined-facts* 8
  "The most facts linear in one variable whose pairs DECIDE-BY-COMBINED-BOUNDS tries.")

(defun slack-of (relation)
  "RELATION (> >= < <=) as (values S STRICT): RELATION says S > 0 (STRICT) or S >= 0.
NIL for another operator."
  (let ((lhs (relation-lhs relation)) (rhs (relation-rhs relation)))
    (case (expression-operator relation)
      (> (values `(- ,lhs ,rhs) t))
      (>= (values `(- ,lhs ,rhs) nil))
      (< (values `(- ,rhs ,lhs) t))
      (<= (values `(- ,rhs ,lhs) nil)))))

(defun linear-coefficients (bridge expression variable)
  "(C0 C1) with EXPRESSION = C0 + C1 VARIABLE, C1 not zero and both free of VARIABLE, or NIL."
  (let ((coefficients (handler-case (polynomial-coefficients-in bridge expression variable)
                        (maxima-condition () nil))))
    (and (= 2 (length coefficients))
         (not (eql 0 (second coefficients)))
         coefficients)))

(defun multiplier-refuted-p (bridge x)
  "True when X is surely negative at an admissible point (X >= 0 cannot be proven)."
  (relation-refuted-p bridge (list '>= x 0)))

(defparameter *multiplier-nesting* 2
  "How many DECIDE calls deep a multiplier's proof may go below the question that
combines the bounds: its own DECIDE and one rewritten relation (the order substitution
writing a variable as its bound plus an excess, say); deeper questions are cut short.")

(defun proven-nonnegative-p (bridge x strict)
  "True when X > 0 (STRICT) or X >= 0 is proven under the facts in force (DECIDE, without
this strategy, and at most *MULTIPLIER-NESTING* calls deep: a multiplier of two facts
that is not proven at once by the signs, is() or one substitution is rarely proven
deeper, and the reasoning's nested questions on it took minutes on a pushed block's
choice search)."
  (let ((*combining-bounds* t)
        (*deepest-decision* (min *deepest-decision* (+ (length *deciding*) *multiplier-nesting*))))
    (eq :true (decide bridge (list (if strict '> '>=) x 0)))))

(defun divisors (expression)
  "The non-numeric divisors of EXPRESSION: D of each (/ X D) and of each (EXPT D -N)."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (case (expression-operator x)
                   (/ (dolist (d (rest (expression-arguments x))) (pushnew d found :test #'equal)))
                   (expt (when (and (realp (third x)) (minusp (third x)))
                           (pushnew (second x) found :test #'equal))))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    (remove-if #'numberp found)))

(defun divisors-nonzero-p (bridge &rest expressions)
  "True when every divisor of EXPRESSIONS is proven nonzero (of one strict sign): the
identity GOAL = a s1 + b s2 then holds at every admissible point, not only where the
multipliers are defined (which is enough for GOAL >= 0, by continuity, but not for > 0)."
  (every (lambda (d) (or (proven-nonnegative-p bridge d t)
                         (proven-nonnegative-p bridge (list '- d) t)))
         (reduce #'union (mapcar #'divisors expressions) :initial-value '())))

(defun combination-proves-p (bridge goal strict variable first second)
  "True when GOAL = a FIRST + b SECOND (entries (C0 C1 STRICT) of facts linear in
VARIABLE, GOAL's own (C0 C1) in GOAL) with a, b proven >= 0, and GOAL > 0 when STRICT."
  (destructuring-bind ((e c) (r1 b1 strict1) (r2 b2 strict2)) (list goal first second)
    (let* ((det `(- (* ,b1 ,r2) (* ,b2 ,r1)))
           (det (simplified bridge det :ratsimp)))
      (unless (eql det 0)
        (let ((a (simplified bridge `(/ (- (* ,c ,r2) (* ,e ,b2)) ,det) :ratsimp))
              (b (simplified bridge `(/ (- (* ,e ,b1) (* ,c ,r1)) ,det) :ratsimp)))
          (declare (ignorable variable))
          (flet ((part (multiplier fact-strict)
                   ;; :STRICT when the part a s is proven > 0, :WEAK when >= 0, else NIL
                   (cond ((eql multiplier 0) :weak)
                         ((and fact-strict strict (proven-nonnegative-p bridge multiplier t)) :strict)
                         ((proven-nonnegative-p bridge multiplier nil) :weak))))
            (let ((pa (and (not (multiplier-refuted-p bridge a))
                           (not (multiplier-refuted-p bridge b))
                           (part a strict1))))
              (when pa
                (let ((pb (part b strict2)))
                  (and pb (or (not strict)
                              (and (or (eq pa :strict) (eq pb :strict))
                                   (divisors-nonzero-p bridge a b)))))))))))))

(defun bound-fact-p (fact)
  "True when FACT (a relation) can bound a variable against others: an inequality that
is not a variable against a number (a sign or a range, which the other strategies use)."
  (and (consp fact)
       (member (expression-operator fact) '(> >= < <=))
       (not (and (or (variable-symbol-p (relation-lhs fact)) (variable-symbol-p (relation-rhs fact)))
                 (or (numberp (relation-lhs fact)) (numberp (relation-rhs fact)))))))

(defun goal-proven-by-pairs-p (bridge goal strict)
  "True when GOAL > 0 (STRICT) or GOAL >= 0 follows from two facts in force linear in one
of its variables (see the file header). Maxima is asked for the coefficients only where
two such facts mention the variable."
  (let ((facts (remove-if-not #'bound-fact-p (flatten-facts (current-assumptions bridge)))))
    (dolist (variable (remove-if-not #'variable-symbol-p (expression-variables goal)) nil)
      (let ((mentioning (remove-if (lambda (fact) (free-of-p variable fact)) facts)))
        (when (<= 2 (length mentioning) *most-combined-facts*)
          (let ((own (linear-coefficients bridge goal variable)))
            (when own
              (let ((linear (loop for fact in mentioning
                                  for (slack fact-strict) = (multiple-value-list (slack-of fact))
                                  for coefficients = (linear-coefficients bridge slack variable)
                                  when coefficients
                                    collect (append coefficients (list fact-strict)))))
                (loop for (first . others) on linear
                      do (dolist (second others)
                           (when (combination-proves-p bridge own strict variable first second)
                             (return-from goal-proven-by-pairs-p t))))))))))))

(defun decide-by-combined-bounds (bridge relation)
  "RELATION (< > <= >=) decided by two facts in force that bound one of its variables,
combined (see the file header): :TRUE, :FALSE (its negation so proven) or :UNKNOWN."
  (unless *combined-bounds-wanted*
    (push :not-wanted *cut-short*)
    (return-from decide-by-combined-bounds :unknown))
  (when (> (length *deciding*) *deepest-combined-bounds*)
    ;; too deep among rewritten relations: a verdict cut short, not cached (DECIDE)
    (push :depth *cut-short*)
    (return-from decide-by-combined-bounds :unknown))
  (if (or *combining-bounds* *substituting-orders*
          (not (member (expression-operator relation) '(> >= < <=)))
          (> (expression-size relation) *largest-relation-for-combined-bounds*))
      :unknown
      (flet ((proven (relation)
               ;; a relation that fails at an admissible point cannot be proven
               (and (not (relation-refuted-p bridge relation))
                    (multiple-value-bind (slack strict) (slack-of relation)
                      (let ((goal (simplified bridge slack :ratsimp)))
                        ;; one fact and a remainder of one sign (fact-remainders.lisp), then pairs
                        (or (goal-proven-by-one-fact-p
                             bridge goal strict
                             (remove-if-not #'bound-fact-p (flatten-facts (current-assumptions bridge))))
                            (goal-proven-by-pairs-p bridge goal strict)))))))
        (cond ((proven relation) :true)
              ((proven (negate-condition relation)) :false)
              (t :unknown)))))
