;;;; src/scenario-numbers.lisp -- numeric values of constant expressions, for the validator's cheap checks.
;;;;
;;;; The validator decides some facts itself, without Maxima, when the numbers settle
;;;; them: (> x 2) with (< x 1), a radius of -1, a clockwise polygon with numeric
;;;; vertices, a default :value outside its parameter's bounds. This file computes the
;;;; value of an expression of the prefix algebra whose symbols are all bound. It is a
;;;; small interpreter of the algebra's arithmetic operators over numbers, not EVAL: no
;;;; user symbol is ever called or looked up outside the bindings given.
;;;;
;;;; A value is EXACT when it is a rational (integers and ratios only ever met + - * /
;;;; and small integer powers) or a float literal taken as given; otherwise it is a
;;;; double-float approximation, and comparisons that it leaves too close to call are
;;;; left undecided (for Maxima).

(in-package #:ames)

(defconstant +largest-exact-power-bits+ 65536
  "Exact powers whose result would exceed this many bits are computed as floats.")

(defconstant +relative-tolerance+ 1d-9
  "Approximate values closer than this (relative) are not ordered by COMPARE-VALUES.")

(defun finite-real-p (x)
  "True when X is a rational or a finite float."
  (or (rationalp x)
      (and (floatp x) (= x x) (< (abs x) most-positive-double-float))))

(defun constant-value (expression &optional bindings)
  "The real value of the algebra EXPRESSION, whose variables are looked up in the
alist BINDINGS (symbol . real), and whether it is exact: (values VALUE EXACTP).
VALUE is NIL when EXPRESSION has an unbound variable or a quantity term, is not real
(sqrt of a negative, log of zero...), overflows, or is not in the algebra. PI is
taken as a double-float. Signals nothing."
  (labels ((give-up () (return-from constant-value (values nil nil)))
           (real-or-give-up (x)
             (if (and (realp x) (finite-real-p x)) x (give-up)))
           (exact-power (base exponent)
             (and (rationalp base) (integerp exponent)
                  (<= (abs exponent) 4096)
                  (<= (* (max (integer-length (numerator base))
                              (integer-length (denominator base)))
                         (abs exponent))
                      +largest-exact-power-bits+)
                  (not (and (zerop base) (minusp exponent)))))
           (value (x)
             (cond ((realp x) (real-or-give-up x))
                   ((eq x 'pi) pi)
                   ((variable-symbol-p x)
                    (let ((entry (assoc x bindings)))
                      (if (and entry (realp (cdr entry)))
                          (real-or-give-up (cdr entry))
                          (give-up))))
                   ((and (consp x) (alexandria:proper-list-p x)
                         (arithmetic-operator-p (car x)))
                    (apply-operator (car x) (mapcar #'value (cdr x))))
                   (t (give-up))))
           (apply-operator (operator arguments)
             (let ((n (length arguments)))
               (real-or-give-up
                (case operator
                  (+ (reduce #'+ arguments))
                  (* (reduce #'* arguments))
                  (- (if (= n 1) (- (first arguments)) (reduce #'- arguments)))
                  (/ (when (some #'zerop (if (= n 1) arguments (rest arguments)))
                       (give-up))
                     (if (= n 1) (/ (first arguments)) (reduce #'/ arguments)))
                  (expt (destructuring-bind (base exponent) arguments
                          (cond ((exact-power base exponent) (expt base exponent))
                                ((and (zerop base) (not (plusp exponent))) (give-up))
                                ((and (minusp base) (not (integerp exponent))) (give-up))
                                (t (expt (float base 1d0) (float exponent 1d0))))))
                  (sqrt (let ((x (first arguments)))
                          (when (minusp x) (give-up))
                          (sqrt (float x 1d0))))
                  (exp (exp (float (first arguments) 1d0)))
                  (log (let ((x (first arguments)))
                         (unless (plusp x) (give-up))
                         (log (float x 1d0))))
                  (sin (sin (float (first arguments) 1d0)))
                  (cos (cos (float (first arguments) 1d0)))
                  (tan (tan (float (first arguments) 1d0)))
                  (asin (let ((x (first arguments)))
                          (unless (<= -1 x 1) (give-up))
                          (asin (float x 1d0))))
                  (acos (let ((x (first arguments)))
                          (unless (<= -1 x 1) (give-up))
                          (acos (float x 1d0))))
                  (atan (if (= n 1)
                            (atan (float (first arguments) 1d0))
                            (destructuring-bind (y x) arguments
                              (when (and (zerop y) (zerop x)) (give-up))
                              (atan (float y 1d0) (float x 1d0)))))
                  (t (give-up)))))))
    (handler-case
        (let ((result (value expression)))
          (values result (or (rationalp result) (realp expression)
                             (variable-symbol-p expression))))
      (arithmetic-error () (values nil nil)))))

(defun constant-expression-p (expression)
  "True when EXPRESSION has a numeric value without any binding."
  (and (constant-value expression) t))

(defun compare-values (a exact-a b exact-b)
  "Order two reals: :LESS, :EQUAL or :GREATER, or NIL when A and B are approximations
too close to order with confidence. Exact values are compared exactly. Signals nothing."
  (flet ((order (x y) (cond ((< x y) :less) ((> x y) :greater) (t :equal))))
    (handler-case
        (if (and exact-a exact-b)
            (order a b)
            (let* ((x (float a 1d0)) (y (float b 1d0))
                   (scale (max 1d0 (abs x) (abs y))))
              (if (<= (abs (- x y)) (* +relative-tolerance+ scale))
                  nil
                  (order x y))))
      (arithmetic-error () nil))))

(defun relation-holds-p (operator lhs lhs-exact rhs rhs-exact)
  "Whether the relation (OPERATOR LHS RHS) holds between two values: T, :FALSE, or NIL
when undecided. OPERATOR is one of < > <= >= = /=."
  (let ((order (compare-values lhs lhs-exact rhs rhs-exact)))
    (if (null order)
        nil
        (let ((holds (ecase operator
                       (< (eq order :less))
                       (> (eq order :greater))
                       (<= (not (eq order :greater)))
                       (>= (not (eq order :less)))
                       (= (eq order :equal))
                       (/= (not (eq order :equal))))))
          (if holds t :false)))))
