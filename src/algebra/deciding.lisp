;;;; src/algebra/deciding.lisp -- DECIDE: the truth of a relation under the facts in force, three-valued and cached.
;;;;
;;;; A relation between constants whose sides agree to round-off is decided exactly first
;;;; (constant-zero.lisp: Maxima's sign() would take the float's sign). The strategies,
;;;; cheapest first: Maxima's is(); numeric witnesses that no strategy can
;;;; decide it (witnesses.lisp); sign() of the difference of the sides in several forms;
;;;; clearing one square root; equivalence for = and /=; what a physicist knows
;;;; (truth.lisp: trigonometric signs from the angles' ranges, monotonicity, squares,
;;;; signed factors); and, last, the orderings of the parameters substituted (orders.lisp). Each is
;;;; sound, so the first that decides gives the verdict; :UNKNOWN is never a guess.
;;;;
;;;; Speed: sign() requests are asked one at a time until the relation is decided, and
;;;; DECIDE caches its verdicts.

(in-package #:ames.algebra)

;;; Deciding relations

(defvar *substituting-orders* nil
  "True while DECIDE-BY-ORDER-SUBSTITUTION works, so that it does not recurse.")

(defvar *sides-differ* nil
  "True while DECIDE-RELATION works on an equation (or, in DECIDE-BY-ORDER-SUBSTITUTION,
on its rewriting) whose sides were seen to differ both ways at admissible points.")

(defun radical-signs (bridge lhs rhs &key datum)
  "The signs of LHS - RHS found by clearing one square root: written as
(a + b sqrt(A)) / c, its numerator has the sign of a when b = 0 and, when a and b have
opposite signs, the sign of b^2 A - a^2 times that of b. NIL when no square root is
there or the form is not linear in it (see SQUARE-ROOT-PART-SIGNS)."
  (let ((parts (square-root-part-signs bridge lhs rhs :datum datum)))
    (when parts
      (destructuring-bind (a-signs b-signs gap-signs radicand-signs denominator-signs) parts
        (flet ((only (signs &rest allowed) (and signs (subsetp signs allowed))))
          (let* ((real (only radicand-signs :positive :zero))
                 (numerator-signs
                   (cond ((or (null a-signs) (null b-signs)) nil)
                         ;; b sqrt(A) against a: the larger in size wins. When
                         ;; b^2 A > a^2 >= 0, A > 0 follows, so sqrt(A) is real.
                         ((and (only a-signs :negative :zero) (only b-signs :positive))
                          (cond ((only gap-signs :positive) '(:positive))
                                (real gap-signs)))
                         ((and (only a-signs :positive :zero) (only b-signs :negative))
                          (cond ((only gap-signs :positive) '(:negative))
                                (real (sign-product gap-signs '(:negative)))))
                         ((not real) nil)
                         ;; a and b sqrt(A) of one sign
                         ((and (only a-signs :positive :zero) (only b-signs :positive :zero))
                          (if (or (only a-signs :positive)
                                  (and (only b-signs :positive) (only radicand-signs :positive)))
                              '(:positive) '(:positive :zero)))
                         ((and (only a-signs :negative :zero) (only b-signs :negative :zero))
                          (if (or (only a-signs :negative)
                                  (and (only b-signs :negative) (only radicand-signs :positive)))
                              '(:negative) '(:negative :zero)))
                         (t nil))))
            (and numerator-signs (only denominator-signs :positive :negative)
                 (sign-product numerator-signs denominator-signs))))))))

(defun opposite-truth (bridge relation)
  "The truth of RELATION that is() gives through the opposite relation (X <= 0 for
X > 0, equal for notequal ...): :FALSE when is() proves the opposite, :TRUE when it
refutes it, else :UNKNOWN."
  (ecase (maxima-is-opposite bridge relation)
    (:true :false)
    (:false :true)
    (:unknown :unknown)))

(defun decide-relation (bridge relation)
  "The truth of one RELATION (= /= < > <= >=) under the current assumptions: is(), then
numeric witnesses that no strategy can decide it (see RELATION-WITNESSES), then the
signs of the difference of its sides, after clearing a square root, equivalence (for =
and /=), what a physicist knows (truth.lisp) and the order substitution. A relation
with a product of square roots of negative radicands, which Maxima's is() and sign()
would take for real (or imaginary) square roots, is first decided in real terms by
DECIDE-WITH-IMAGINARY-RADICANDS. The rules of signs over the subjects' ranges answer
first where they settle it (QUICK-VERDICT, no Maxima); a relation between constants
whose sides agree to round-off is decided exactly or left :UNKNOWN
(DECIDE-CONSTANT-NEAR-ZERO), never by sign()'s float."
  (let ((quick (quick-verdict bridge relation)))
    (unless (eq quick :unknown)
      (return-from decide-relation quick)))
  (let ((constant (decide-constant-near-zero bridge relation)))
    (unless (eq constant :not-applicable)
      (return-from decide-relation constant)))
  ;; the same for a constant factor or term of a relation with variables
  (let ((constant (decide-near-zero-constants bridge relation)))
    (unless (eq constant :not-applicable)
      (return-from decide-relation constant)))
  (when (imaginary-radicands bridge relation)
    (let ((verdict (decide-with-imaginary-radicands bridge relation)))
      (unless (eq verdict :fall-back)
        (return-from decide-relation verdict))))
  (handler-case (decide-relation-in-maxima bridge relation)
    ;; is() and sign() refused the relation (logarc() knows no atan2): what a physicist
    ;; knows may still rewrite it into a form they take
    (maxima-error () (decide-by-reasoning bridge relation))))

(defun decide-relation-in-maxima (bridge relation)
  "The truth of RELATION by Maxima's is(); when it does not know, :UNKNOWN if numeric
witnesses show that no strategy can decide it, else as DECIDE-RELATION-BY-STRATEGIES
finds it."
  (let* ((operator (expression-operator relation))
         (equation (member operator '(= /=)))
         (lhs (relation-lhs relation))
         (rhs (relation-rhs relation))
         (verdict (maxima-is bridge relation)))
    (unless (eq verdict :unknown)
      (return-from decide-relation-in-maxima verdict))
    ;; an inequality seen to hold at one admissible point and to fail at another, or an
    ;; equation whose sides cross between two such points, is decided by no strategy
    (multiple-value-bind (holds fails facts)
        (and (not *substituting-orders*)
             (relation-witnesses bridge (if equation
                                            (list '> (relation-lhs relation) (relation-rhs relation))
                                            relation)))
      (when (and holds
                 (or (not equation)
                     (continuous-and-admissible-between-p
                      (list '- (relation-lhs relation) (relation-rhs relation)) facts holds fails)))
        (return-from decide-relation-in-maxima :unknown))
      (decide-relation-by-strategies bridge relation lhs rhs holds))))

(defun decide-relation-by-strategies (bridge relation lhs rhs holds)
  "The truth of RELATION, whose sides are LHS and RHS, that is() did not decide: by the
opposite relation, the signs of the difference of its sides (after clearing a square
root), equivalence (for = and /=, unless HOLDS, a point where the sides differ, was
seen), what a physicist knows, one square root by cases on the sign beside it
(radical-cases.lisp), the order substitution, two bounds combined
(combined-bounds.lisp) and concavity between two bounds (convex-bounds.lisp); :UNKNOWN when none decides it."
  (let* ((operator (expression-operator relation))
         (equation (member operator '(= /=)))
         ;; is() proves X <= 0 from the fact X <= 0 but not that X > 0 fails: ask the
         ;; opposite relation too (asked with the signs below, in one round trip)
         (verdict (progn (prefetch-opposite-and-signs bridge relation)
                         (opposite-truth bridge relation))))
    (unless (eq verdict :unknown)
      (return-from decide-relation-by-strategies verdict))
    ;; the signs are asked for only until they decide the relation
    (setf verdict (relation-verdict operator
                                    (maxima-difference-signs
                                     bridge lhs rhs
                                     :datum relation
                                     :enough (lambda (signs)
                                               (not (eq (relation-verdict operator signs)
                                                        :unknown))))))
    (when (eq verdict :unknown)
      (let ((signs (radical-signs bridge lhs rhs :datum relation)))
        (when signs (setf verdict (relation-verdict operator signs)))))
    ;; sides seen to differ both ways are not equal: equivalence cannot be proven,
    ;; here nor after the order substitution
    (let ((*sides-differ* (or *sides-differ* (and equation holds t))))
      (when (and (eq verdict :unknown) equation (not *sides-differ*)
                 (equivalent-p bridge (relation-lhs relation) (relation-rhs relation)))
        (setf verdict (if (eq operator '=) :true :false)))
      (when (eq verdict :unknown)
        (setf verdict (decide-by-reasoning bridge relation)))
      (when (eq verdict :unknown)
        (setf verdict (decide-by-radical-cases bridge relation)))
      (when (eq verdict :unknown)
        (setf verdict (decide-by-order-substitution bridge relation)))
      (when (eq verdict :unknown)
        (setf verdict (decide-by-combined-bounds bridge relation)))
      (when (eq verdict :unknown)
        (setf verdict (decide-by-convexity bridge relation))))
    verdict))

(defvar *deciding* '()
  "The verdict keys (see VERDICT-KEY) of the DECIDE calls under way, innermost first.")

(defvar *decide-cheaply* nil
  "T while DECIDE tries only CHEAP-PROOF's strategies on a question it has no verdict for
(a screen whose :UNKNOWN costs nothing but a proof not made: angle-horizon-proofs.lisp);
an internal real time: from then on.")

(defvar *cut-short* '()
  "The verdict keys of questions that DECIDE answered :UNKNOWN without trying, because
they were already under way (or :DEPTH, because the questions nested too deep), while
deciding the innermost question under way.")

(defparameter *deepest-decision* 8
  "How many DECIDE calls may be under way at once (the reasoning of truth.lisp and the
order substitution ask DECIDE about rewritten relations).")

(defun decide (bridge relation)
  "Decide RELATION (a relation of the algebra, or AND / OR / NOT of relations) under the
current assumptions: :TRUE, :FALSE or :UNKNOWN. Uses Maxima's is(), then the sign of the
difference of the two sides in several simplified forms, then the same after clearing a
square root (so that roots of quadratics can be compared), then what a physicist knows
(truth.lisp), then the orderings of the parameters; connectives are combined in
three-valued logic. Verdicts are cached under the facts in force, like requests. A
question asked again while it is being decided (by the reasoning about a rewritten
relation) is answered :UNKNOWN there, and so is one nested too deep; an :UNKNOWN that
owes something to such a cut is not cached.
Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT, and BUDGET-EXCEEDED when
the running budget's deadline has passed (even for a relation it could decide without
Maxima)."
  (check-translatable relation :condition)
  (check-deadline relation)
  (let ((key (verdict-key bridge relation)))
    (multiple-value-bind (verdict found) (cached-answer bridge key)
      (unless found
        ;; proven under facts that the facts in force include: proven now
        (setf verdict (inherited-verdict bridge relation)
              found (and verdict (cache-answer bridge key verdict) t)))
      (cond (found verdict)
            ((and *decide-cheaply*
                  (or (eq *decide-cheaply* t) (> (get-internal-real-time) *decide-cheaply*))
                  (relation-operator-p (expression-operator relation)))
             ;; only the cheap strategies (values-first.lisp; a connective's parts come
             ;; back here one by one); an :UNKNOWN here is not cached
             (when *deciding* (push :cheaply *cut-short*))
             (cheap-proof bridge relation))
            ((member key *deciding* :test #'equal)
             (push key *cut-short*)
             :unknown)
            ((>= (length *deciding*) *deepest-decision*)
             (push :depth *cut-short*)
             :unknown)
            (t (let* ((outermost (null *deciding*))
                      (cuts '())
                      (verdict (let ((*deciding* (cons key *deciding*))
                                     (*cut-short* '()))
                                 (prog1 (decide-uncached bridge relation)
                                   (setf cuts (remove key *cut-short* :test #'equal))
                                   (when outermost (setf cuts (remove :depth cuts)))))))
                 (when (or (not (eq verdict :unknown)) (null cuts))
                   (cache-answer bridge key verdict))
                 (setf *cut-short* (append cuts *cut-short*))
                 verdict))))))

(defun inherited-verdict (bridge relation)
  "DECIDE's verdict :TRUE or :FALSE on RELATION cached under facts that are a strict part
of the facts in force (see WEAKER-ASSUMPTION-KEYS), or NIL. Sound: more facts keep what
fewer proved. An :UNKNOWN is not taken over (more facts may decide it)."
  (dolist (id (weaker-assumption-keys bridge) nil)
    (let ((verdict (cached-answer bridge (list* :decide *substituting-orders* relation id)
                                  :count nil)))
      (when (member verdict '(:true :false))
        (return verdict)))))

(defun verdict-key (bridge relation)
  "The key of DECIDE's verdict on RELATION in BRIDGE's cache, under the facts in force."
  (list* :decide *substituting-orders* relation (assumption-key bridge)))

(defun decide-uncached (bridge relation)
  "DECIDE's work, without its cache of verdicts. A relation whose Lisp-side reasoning
meets an arithmetic error (it divides by a literal 0), or one a request of which Maxima
refuses with an error (not a timeout), is :UNKNOWN."
  (labels ((verdict (condition)
             (case (expression-operator condition)
               (not (ecase (verdict (second condition))
                      (:true :false) (:false :true) (:unknown :unknown)))
               (and (let ((result :true))
                      (dolist (part (expression-arguments condition) result)
                        (ecase (verdict part)
                          (:false (return :false))
                          (:unknown (setf result :unknown))
                          (:true)))))
               (or (let ((result :false))
                     (dolist (part (expression-arguments condition) result)
                       (ecase (verdict part)
                         (:true (return :true))
                         (:unknown (setf result :unknown))
                         (:false)))))
               (t (let ((answer (handler-case (or (constant-relation-by-intervals condition)
                                                  (decide-relation bridge condition))
                                  ;; the reasoning's own arithmetic met a division by a
                                  ;; literal zero (the relation is undefined): nothing is proven
                                  (arithmetic-error () :unknown)
                                  ;; Maxima refused a request of the deciding (logarc()
                                  ;; knows no atan2): nothing is proven either
                                  (maxima-error () :unknown))))
                    (if (eq answer :unknown)
                        (decide-by-cases-of-abs bridge condition)
                        answer))))))
    (verdict relation)))

(defun innermost-abs-argument (expression)
  "The argument U of an abs(U) in EXPRESSION with no abs inside U, or NIL."
  (and (consp expression)
       (or (some #'innermost-abs-argument (expression-arguments expression))
           (and (eq (expression-operator expression) 'abs) (second expression)))))

(defun decide-by-cases-of-abs (bridge relation)
  "RELATION, which has an abs(U), decided in the two cases U >= 0 (abs(U) = U) and U <= 0
(abs(U) = -U): :TRUE or :FALSE when both cases agree (a case the facts in force exclude
agrees with anything), else :UNKNOWN (|u| >= u holds whatever the sign of u)."
  (let ((u (innermost-abs-argument relation)))
    (if (null u)
        :unknown
        (flet ((case-verdict (fact value)
                 (handler-case
                     (with-assumptions (bridge (list fact))
                       (decide bridge (substitute-abs relation u value)))
                   (inconsistent-assumptions () :excluded))))
          (let ((verdicts (remove :excluded (list (case-verdict `(>= ,u 0) u)
                                                  (case-verdict `(<= ,u 0) `(- ,u))))))
            (cond ((null verdicts) :unknown)
                  ((every (lambda (v) (eq v :true)) verdicts) :true)
                  ((every (lambda (v) (eq v :false)) verdicts) :false)
                  (t :unknown)))))))

(defun substitute-abs (expression argument value)
  "EXPRESSION with every abs(ARGUMENT) replaced by VALUE."
  (cond ((atom expression) expression)
        ((and (eq (expression-operator expression) 'abs) (equal (second expression) argument)) value)
        (t (cons (first expression)
                 (mapcar (lambda (x) (substitute-abs x argument value)) (rest expression))))))

(defun holds-p (bridge relation)
  "True when DECIDE answers :TRUE for RELATION (a relation or a logical form), found
faster where it does not: a point that surely satisfies the facts in force and surely
violates RELATION settles it without asking Maxima, since no sound strategy proves a
relation that fails somewhere (see RELATION-REFUTED-P). For callers that act only on
:TRUE. Signals what DECIDE signals."
  (check-translatable relation :condition)
  (multiple-value-bind (verdict found) (cached-answer bridge (verdict-key bridge relation) :count nil)
    (cond (found (eq verdict :true))
          ((relation-refuted-p bridge relation) nil)
          (t (eq (decide bridge relation) :true)))))

(defun refuted-p (bridge relation &key assuming)
  "True when RELATION (a relation or a logical form of the algebra) is seen to fail at a
point that satisfies the facts in force and the facts ASSUMING (e.g. ((> tau 0))): then
it does not follow from them, and no sound proof of it exists. NIL proves nothing. Asks
Maxima nothing. Signals UNTRANSLATABLE-EXPRESSION for a RELATION or fact outside the
algebra."
  (check-translatable relation :condition)
  (dolist (fact assuming) (check-translatable fact :condition))
  (relation-refuted-p bridge relation assuming))

(defun sign-varies-p (bridge expression)
  "True when the arithmetic EXPRESSION is seen to be positive at one point that satisfies
the facts in force and negative at another: then no relation of EXPRESSION with 0 is
decided, and EXPRESSION is not identically 0. NIL proves nothing. Asks Maxima nothing.
Signals UNTRANSLATABLE-EXPRESSION for an EXPRESSION outside the algebra."
  (check-translatable expression :arithmetic)
  (witnessed-both-ways-p bridge (list '> expression 0)))
