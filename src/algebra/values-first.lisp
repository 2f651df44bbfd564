;;;; src/algebra/values-first.lisp -- under values, the values decide first: a cheap proof, else the values' verdict where the caller falls back to them anyway.
;;;;
;;;; A run given values (bin/ames --set, --numeric) needs a relation's truth at those
;;;; values, not its proof for every admissible parameter. DECIDE's full strategies spent
;;;; most of such a run's time on relations that turn out undecidable before the values
;;;; settle them. While *VALUES-FIRST* is true (CALL-WITH-VALUES-FIRST: the command line's
;;;; run of a scenario with values binds it around the simulation; the presentation of
;;;; formulas, after the run, never runs under it), the callers that fall back to the
;;;; values when DECIDE cannot settle a relation (the geometry's open facts, the order of
;;;; two event times) ask DECIDE-FIRST-CHEAPLY instead of DECIDE: the rules of signs
;;;; (QUICK-VERDICT, no Maxima), is() and sign() in a few forms (DECIDE's first, cheap
;;;; strategies), a proof where they answer;
;;;; else :UNKNOWN, and the caller's values decide, recording the fact as assumed from the
;;;; values (the report lists those apart from what is proven). A relation the values do
;;;; not decide (too close to call, a variable without a value) gets DECIDE's full work,
;;;; as without values, and so does one asked under a fact that fails at the values (a
;;;; branch the values do not select, simulated under --all-branches).
;;;; Only those callers: where :UNKNOWN makes a branch or an approximate root, the
;;;; values deciding would change the results, not just their wording.

(in-package #:ames.algebra)

(defvar *values-first* nil
  "True while the callers that fall back to the run's values decide relations cheaply
first (see this file's header and CALL-WITH-VALUES-FIRST).")

(defun call-with-values-first (thunk)
  "Call THUNK with the run's parameter values deciding first (see this file's header)
when the run has values; return THUNK's values."
  (let ((*values-first* (and (current-parameter-values) t)))
    (funcall thunk)))

(defun values-first-p ()
  "True when the current run has values and they decide first (see CALL-WITH-VALUES-FIRST)."
  (and *values-first* (current-parameter-values) t))

(defun valued-relation-p (relation)
  "True when RELATION, a relation of the algebra, names at least one variable and every
variable it names has a value in the current run."
  (let ((variables (expression-variables relation)))
    (and variables
         (every (lambda (v) (assoc v *parameter-values* :test #'equal)) variables))))

(defun cheap-proof (bridge relation)
  "The truth of RELATION proven within a small fixed budget: DECIDE's cached verdict, the
rules of signs, then Maxima's is() and the sign() of the difference of the sides in its
few simplified forms (DECIDE's first strategies; not asked of a relation with square
roots of negative radicands, which Maxima would take for real: see DECIDE-RELATION).
:UNKNOWN when none proves it."
  (multiple-value-bind (verdict found) (cached-answer bridge (verdict-key bridge relation) :count nil)
    (when found (return-from cheap-proof verdict)))
  (let ((quick (quick-verdict bridge relation))
        (operator (expression-operator relation)))
    (cond ((not (eq quick :unknown)) quick)
          ((imaginary-radicands bridge relation) :unknown)
          (t (handler-case
                 (let ((verdict (maxima-is bridge relation)))
                   (if (eq verdict :unknown)
                       (relation-verdict operator
                                         (maxima-difference-signs
                                          bridge (relation-lhs relation) (relation-rhs relation)
                                          :datum relation
                                          :enough (lambda (signs)
                                                    (not (eq (relation-verdict operator signs)
                                                             :unknown)))))
                       verdict))
               (maxima-condition () :unknown))))))

(defun facts-hold-at-values-p (bridge)
  "True when every fact in force in BRIDGE that is over valued parameters alone holds at
the run's values (under --all-branches, a branch the values do not select has a fact
that fails there: the values say nothing about it)."
  (every (lambda (fact)
           (or (not (and (consp fact) (valued-relation-p fact)))
               (eq (value-truth fact) :true)))
         (flatten-facts (current-assumptions bridge))))

(defun decide-first-cheaply (bridge relation)
  "DECIDE for a caller that falls back to the run's values on :UNKNOWN: while values
decide first (VALUES-FIRST-P), the facts in force hold at them and they settle RELATION
(a relation of the algebra over valued parameters), only CHEAP-PROOF's attempt (:TRUE,
:FALSE, or :UNKNOWN for the caller's values to settle); otherwise DECIDE itself.
Signals what DECIDE signals."
  (if (and (values-first-p)
           (relation-operator-p (expression-operator relation))
           (valued-relation-p relation)
           (value-truth relation)
           (facts-hold-at-values-p bridge))
      (cheap-proof bridge relation)
      (decide bridge relation)))

(defun signs-refuted-by-values (bridge x)
  "The signs (:POSITIVE :NEGATIVE :ZERO) that no sound proof can give X, an expression
over the parameters: where the run has values, the facts in force hold at them and X's
sign there is clear, the other two signs (a relation false at an admissible point is
never proven). NIL otherwise. Asks Maxima nothing."
  (when (and (current-parameter-values) (facts-hold-at-values-p bridge))
    (case (value-truth (list '> x 0))
      (:true (list :negative :zero))
      (:false (when (eq :true (value-truth (list '< x 0)))
                (list :positive :zero))))))
