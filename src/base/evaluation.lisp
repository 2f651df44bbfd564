;;;; src/base/evaluation.lisp -- the numeric value of a constant expression of the algebra, exact when it can be.
;;;;
;;;; Several layers settle facts by arithmetic before they ask Maxima: the scenario
;;;; validator ((> x 2) against (< x 1), a radius of -1), geometry (the sign of a turn
;;;; with rational coordinates). They share EXPRESSION-VALUE, a small interpreter of the
;;;; algebra's arithmetic operators over numbers. It is not EVAL: no symbol is ever called,
;;;; and a variable has a value only when the caller's bindings give it one.
;;;;
;;;; Exactness: rationals met by + - * / (within the current limits' size, see limits.lisp),
;;;; integer powers of a bounded size, and roots
;;;; whose value is rational ((sqrt 9/4) = 3/2, (expt 8 2/3) = 4) stay exact rationals.
;;;; Everything else (PI, the transcendental functions, irrational roots, floats) is a
;;;; double-float approximation. Where the value is not a finite real (division by zero,
;;;; the square root of a negative, overflow...) the answer is NIL: no arithmetic error
;;;; escapes.

(in-package #:ames.base)

(defconstant +largest-exact-power-bits+ 65536
  "An exact power whose result could need more bits than this is computed as a float
instead (so that (expt 10 (expt 10 10)) overflows to NIL rather than filling memory).")

(defconstant +deepest-evaluated-expression+ 1000
  "EXPRESSION-VALUE gives no value (NIL) for an expression nested deeper than this,
rather than exhaust the stack: no caller needs one (scenario forms are at most 100
deep), and NIL only leaves a fact for Maxima to decide.")

(defconstant +largest-exact-root-degree+ 64
  "A rational exponent P/Q with Q above this is taken in floating point, without looking
for an exact Q-th root.")

(defun integer-root (n degree)
  "The greatest integer R with R^DEGREE <= N, for an integer N >= 0 and an integer
DEGREE >= 1 (Newton's iteration on integers, from above)."
  (cond ((< n 2) n)
        ((= degree 2) (isqrt n))
        (t
         ;; 2^ceiling(length/degree) exceeds the root, and the iteration decreases
         ;; strictly until it reaches the floor of the root.
         (let ((r (ash 1 (ceiling (integer-length n) degree))))
           (loop (let ((next (floor (+ (* (1- degree) r) (floor n (expt r (1- degree))))
                                    degree)))
                   (if (>= next r) (return r) (setf r next))))))))

(defun rational-root (x degree)
  "The non-negative rational R with R^DEGREE = X, when X is a non-negative rational that
has one; else NIL. DEGREE is a positive integer. (rational-root 9/4 2) = 3/2,
(rational-root 2 2) = NIL."
  (when (and (rationalp x) (>= x 0))
    (let* ((top (numerator x)) (bottom (denominator x))
           (r (integer-root top degree)) (s (integer-root bottom degree)))
      ;; X is in lowest terms, so it is a DEGREE-th power of a rational exactly when its
      ;; numerator and denominator are DEGREE-th powers of integers.
      (when (and (= (expt r degree) top) (= (expt s degree) bottom))
        (/ r s)))))

(defun exact-power (base exponent)
  "BASE^EXPONENT as a rational, when both are rationals, the power is a rational (its
root exists) and its size is within +LARGEST-EXACT-POWER-BITS+ and the current limits'
integer size (see CURRENT-LIMITS); else NIL. 0^0 = 1; a
zero BASE with a negative EXPONENT gives NIL."
  (when (and (rationalp base) (rationalp exponent)
             (not (and (zerop base) (minusp exponent))))
    (let* ((degree (denominator exponent))
           (root (cond ((= degree 1) base)
                       ((<= degree +largest-exact-root-degree+) (rational-root base degree))
                       (t nil))))
      (when (and root
                 (<= (* (max 1 (integer-length (numerator root))
                             (integer-length (denominator root)))
                        (abs (numerator exponent)))
                     (min +largest-exact-power-bits+
                          (limits-integer-bits (current-limits)))))
        (expt root (numerator exponent))))))

(defun float-power (base exponent)
  "BASE^EXPONENT as a double-float, for the reals BASE and EXPONENT; NIL when it is not
real: a zero BASE with an EXPONENT <= 0 other than 0 itself, a negative BASE with an
EXPONENT that is not an integer. May signal FLOATING-POINT-OVERFLOW."
  (cond ((zerop base)
         (cond ((plusp exponent) 0d0) ((zerop exponent) 1d0) (t nil)))
        ((plusp base)
         (expt (float base 1d0) (float exponent 1d0)))
        ((and (floatp exponent) (= exponent (ftruncate exponent)))
         (expt (float base 1d0) (truncate exponent)))
        ((integerp exponent)
         (expt (float base 1d0) exponent))
        (t nil)))

(defun exact-arithmetic-fits-p (arguments)
  "True when + - * or / over the rational ARGUMENTS cannot build a number larger than
the current limits allow (the sum of their sizes in bits bounds the result's)."
  (<= (loop for x in arguments sum (if (rationalp x) (rational-bits x) 0))
      (limits-integer-bits (current-limits))))

(defun apply-arithmetic-operator (operator arguments)
  "The value of the arithmetic OPERATOR applied to the real ARGUMENTS (rationals or
double-floats, as many as OPERATOR takes): a rational when exact (see EXACT-POWER) and
within the current limits' integer size, else a double-float; NIL when the result is not
a real. May signal ARITHMETIC-ERROR on overflow."
  (when (and (member operator '(+ - * /)) (not (exact-arithmetic-fits-p arguments)))
    ;; exact numbers this large are taken in floating point (or overflow to NIL)
    (setf arguments (mapcar (lambda (x) (float x 1d0)) arguments)))
  (flet ((argument () (first arguments))
         (approximate (function &rest reals)
           (apply function (mapcar (lambda (x) (float x 1d0)) reals))))
    (ecase operator
      (+ (reduce #'+ arguments))
      (* (reduce #'* arguments))
      (- (if (rest arguments) (reduce #'- arguments) (- (argument))))
      (/ (cond ((some #'zerop (if (rest arguments) (rest arguments) arguments)) nil)
               ((rest arguments) (reduce #'/ arguments))
               (t (/ (argument)))))
      (expt (destructuring-bind (base exponent) arguments
              (or (exact-power base exponent) (float-power base exponent))))
      (sqrt (cond ((minusp (argument)) nil)
                  ((rational-root (argument) 2))
                  (t (approximate #'sqrt (argument)))))
      (abs (abs (argument)))
      (exp (approximate #'exp (argument)))
      (log (and (plusp (argument)) (approximate #'log (argument))))
      (sin (approximate #'sin (argument)))
      (cos (approximate #'cos (argument)))
      (tan (approximate #'tan (argument)))
      (asin (and (<= -1 (argument) 1) (approximate #'asin (argument))))
      (acos (and (<= -1 (argument) 1) (approximate #'acos (argument))))
      (atan (if (rest arguments)
                (destructuring-bind (y x) arguments
                  (and (not (and (zerop y) (zerop x))) (approximate #'atan y x)))
                (approximate #'atan (argument))))
      ((sinh cosh tanh asinh acosh atanh elliptic-f elliptic-k elliptic-e
        jacobi-sn jacobi-cn jacobi-dn jacobi-am gamma-function)
       (special-function-value operator arguments)))))

(defun arity-allows-p (operator count)
  "True when the arithmetic OPERATOR takes COUNT arguments."
  (destructuring-bind (least most) (rest (assoc operator +arithmetic-operators+))
    (and (<= least count) (or (null most) (<= count most)))))

(defun expression-value (expression &optional bindings)
  "The real value of the arithmetic EXPRESSION of the algebra, and whether it is exact:
(values VALUE EXACTP).

Variables and quantity terms take their values from the alist BINDINGS ((X . REAL) ...,
looked up with EQUAL); PI is the double-float PI. VALUE is a rational when it was
computed exactly from rationals: with + - * /, integer powers (of at most
+LARGEST-EXACT-POWER-BITS+ bits), and roots or rational powers whose value is rational,
such as (sqrt 9/4) = 3/2 or (expt 8 2/3) = 4. Otherwise VALUE is a double-float: every
float in EXPRESSION or BINDINGS is taken as a double-float, and PI and the transcendental
functions are computed in double precision. An inexact value of an expression holding
numbers beyond a double's 53 bits is taken from exact intervals instead
(ACCURATE-VALUE, exact-intervals.lisp) where they bound it: its terms may cancel far
beyond a double's digits.

EXACTP is true when VALUE is a rational, and when EXPRESSION is itself a number or a
bound variable or term (its value is then taken as given, float or not).

VALUE and EXACTP are NIL when EXPRESSION has a variable or term that BINDINGS leave
unbound or bind to something other than a finite real, when it is not an arithmetic
expression of the algebra (a relation, an unknown operator, a wrong number of
arguments, an improper list), when it is nested deeper than
+DEEPEST-EVALUATED-EXPRESSION+ (1000), and when its value is not a finite real:
division by zero, 0 to a negative power, a negative number to a non-integer power, the
square root or logarithm of a negative, ASIN or ACOS outside [-1, 1], (atan 0 0), a
hyperbolic, elliptic or Jacobi function where SPECIAL-FUNCTION-VALUE gives none, or
overflow.

Exact values stay within the current limits (CURRENT-LIMITS): an operation whose exact
result could need more bits than they allow is computed in double precision instead.
Signals nothing but BUDGET-EXCEEDED (quantity :TIME), when the deadline of the scenario
run in progress passes during the evaluation."
  (labels ((give-up () (return-from expression-value (values nil nil)))
           (finite-or-give-up (x)
             (if (and (realp x) (finite-real-p x))
                 (if (floatp x) (float x 1d0) x)
                 (give-up)))
           (bound-value (x)
             (let ((entry (assoc x bindings :test #'equal)))
               (if entry (finite-or-give-up (cdr entry)) (give-up))))
           (value (x depth)
             (check-budget expression)
             (cond ((realp x) (finite-or-give-up x))
                   ((constant-symbol-p x) (float pi 1d0))
                   ((and (consp x) (arithmetic-operator-p (car x)))
                    (unless (and (< depth +deepest-evaluated-expression+)
                                 (alexandria:proper-list-p x)
                                 (arity-allows-p (car x) (length (cdr x))))
                      (give-up))
                    (finite-or-give-up
                     (or (apply-arithmetic-operator
                          (car x) (mapcar (lambda (argument) (value argument (1+ depth)))
                                          (cdr x)))
                         (give-up))))
                   ((or (variable-symbol-p x) (quantity-term-p x)) (bound-value x))
                   (t (give-up)))))
    (handler-case
        (let ((result (value expression 0)))
          ;; big exact numbers times radicals may cancel beyond a double's digits
          (when (and (floatp result) (big-number-p expression))
            (setf result (or (accurate-value expression bindings) result)))
          (values result (or (rationalp result)
                             (realp expression)
                             (variable-symbol-p expression)
                             (quantity-term-p expression))))
      (arithmetic-error () (values nil nil)))))
