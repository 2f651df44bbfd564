;;;; src/algebra/convex-bounds.lisp -- a strategy of DECIDE: a polynomial in a variable that the
;;;; facts bound on both sides, concave there, is at least its values at the bounds.
;;;;
;;;; A declared bound 0 < w0 < sqrt(3 g (sqrt(w^2 + k^2) - k) / (w^2 + k^2)) (a rocking block
;;;; that does not go over its edge) says that (w^2 + k^2)^2 w0^4 + 6 g k (w^2 + k^2) w0^2
;;;; - 9 g^2 w^2 < 0: at w0 = 0 it is -9 g^2 w^2 < 0, at the bound it is 0 (the bound is its
;;;; root), and in between it is convex in w0, so never above the chord between those two.
;;;; Neither sign() nor the order substitution sees it (the bound is a nested root, the
;;;; relation of degree 4). DECIDE-BY-CONVEXITY looks for that: a relation s > 0 (or >= 0)
;;;; whose s is a polynomial of degree 2 or more in a variable V (coefficients free of V),
;;;; two facts V > LO (or >=) and V < HI (or <=) with LO and HI free of V, s'' <= 0 proven
;;;; (s concave on the interval: the facts of the interval are in force), and s(LO) >= 0,
;;;; s(HI) >= 0 proven. Then s(V) >= (1 - t) s(LO) + t s(HI) >= 0 for V = (1 - t) LO + t HI;
;;;; s > 0 follows where V is strictly inside and one end is > 0, and at an end V may reach
;;;; (a weak bound) when s is > 0 there. The opposite relation (s < 0, s convex) is the
;;;; same question on -s. Sound: concavity on the interval, and proven signs at its ends.
;;;; Costly (two or three DECIDE calls per pair of bounds), so tried last, on small
;;;; relations, after a point where the relation fails is looked for (witnesses.lisp).

(in-package #:ames.algebra)

(defvar *deciding-by-convexity* nil
  "True while DECIDE-BY-CONVEXITY decides its concavity and its ends, so that it does
not recurse.")

(defparameter *largest-relation-for-convexity* 300
  "The largest relation (EXPRESSION-SIZE) DECIDE-BY-CONVEXITY works on.")

(defparameter *most-convexity-bound-pairs* 4
  "The most pairs of bounds (a lower and an upper) of one variable DECIDE-BY-CONVEXITY tries.")

(defun bounds-of-variable (bridge variable)
  "The bounds the facts in force put on VARIABLE alone against an expression free of it:
(values LOWER UPPER), each a list of (EXPRESSION STRICT)."
  (let ((lower '()) (upper '()))
    (dolist (fact (flatten-facts (current-assumptions bridge)))
      (let ((operator (and (consp fact) (expression-operator fact))))
        (when (member operator '(> >= < <=))
          (let* ((lhs (relation-lhs fact)) (rhs (relation-rhs fact))
                 (strict (and (member operator '(> <)) t))
                 (greater (member operator '(> >=))))
            (cond ((and (eq lhs variable) (free-of-p variable rhs))
                   (if greater (push (list rhs strict) lower) (push (list rhs strict) upper)))
                  ((and (eq rhs variable) (free-of-p variable lhs))
                   (if greater (push (list lhs strict) upper) (push (list lhs strict) lower))))))))
    (values (nreverse lower) (nreverse upper))))

(defun polynomial-at-point (coefficients x)
  "The polynomial with COEFFICIENTS (c0 c1 ... cd) at X, a prefix sum."
  (cons '+ (loop for c in coefficients for i from 0
                 collect (if (zerop i) c (list '* c (list 'expt x i))))))

(defun second-derivative-polynomial (coefficients variable)
  "The second derivative in VARIABLE of the polynomial with COEFFICIENTS, a prefix sum."
  (cons '+ (loop for c in (cddr coefficients) for i from 2
                 collect (list '* (* i (1- i)) c (list 'expt variable (- i 2))))))

(defun convexity-proven-p (bridge x strict)
  "True when X > 0 (STRICT) or X >= 0 is proven under the facts in force, without this
strategy and the combined bounds."
  (let ((*deciding-by-convexity* t))
    (proven-nonnegative-p bridge x strict)))

(defun concave-between-p (bridge coefficients variable lower upper goal-strict)
  "True when the polynomial with COEFFICIENTS in VARIABLE is proven >= 0 (> 0 when
GOAL-STRICT) for VARIABLE between LOWER and UPPER, entries (EXPRESSION STRICT), by its
concavity there and its values at the ends (see the file header)."
  (destructuring-bind ((lo lo-strict) (hi hi-strict)) (list lower upper)
    (and (convexity-proven-p bridge (list '- (second-derivative-polynomial coefficients variable)) nil)
         (let ((at-lo (simplified bridge (polynomial-at-point coefficients lo) :ratsimp))
               (at-hi (simplified bridge (polynomial-at-point coefficients hi) :ratsimp)))
           (flet ((positive (x) (convexity-proven-p bridge x t)))
             (and (convexity-proven-p bridge at-lo nil)
                  (convexity-proven-p bridge at-hi nil)
                  (or (not goal-strict)
                      (let ((lo-positive (positive at-lo)))
                        (and (or lo-positive (and lo-strict (positive at-hi)))
                             (or (positive at-hi) (and hi-strict lo-positive)))))))))))

(defun goal-proven-by-convexity-p (bridge goal strict)
  "True when GOAL > 0 (STRICT) or GOAL >= 0 follows from its concavity in one of its
variables between two bounds in force (see the file header)."
  (dolist (variable (remove-if-not #'variable-symbol-p (expression-variables goal)) nil)
    (multiple-value-bind (lower upper) (bounds-of-variable bridge variable)
      (when (and lower upper)
        (let ((coefficients (handler-case (polynomial-coefficients-in bridge goal variable)
                              (maxima-condition () nil))))
          (when (and coefficients (<= 3 (length coefficients)))
            (let ((pairs 0))
              (dolist (lo lower)
                (dolist (hi upper)
                  (when (<= (incf pairs) *most-convexity-bound-pairs*)
                    (when (concave-between-p bridge coefficients variable lo hi strict)
                      (return-from goal-proven-by-convexity-p t))))))))))))

(defun decide-by-convexity (bridge relation)
  "RELATION (< > <= >=) decided by the concavity of its slack in a variable the facts
bound on both sides (see the file header): :TRUE, :FALSE (its negation so proven) or
:UNKNOWN."
  (unless *combined-bounds-wanted*
    (push :not-wanted *cut-short*)
    (return-from decide-by-convexity :unknown))
  (when (> (length *deciding*) *deepest-combined-bounds*)
    (push :depth *cut-short*)
    (return-from decide-by-convexity :unknown))
  (if (or *deciding-by-convexity* *combining-bounds* *substituting-orders*
          (not (member (expression-operator relation) '(> >= < <=)))
          (> (expression-size relation) *largest-relation-for-convexity*))
      :unknown
      (flet ((proven (relation)
               (and (not (relation-refuted-p bridge relation))
                    (multiple-value-bind (slack strict) (slack-of relation)
                      (goal-proven-by-convexity-p bridge (simplified bridge slack :ratsimp) strict)))))
        (cond ((proven relation) :true)
              ((proven (negate-condition relation)) :false)
              (t :unknown)))))
