;;;; src/maxima-bridge/exact-constants.lisp -- expressions whose value is an exact rational, simplified without Maxima.
;;;;
;;;; A state's reports and models ask many simplifications of expressions that are
;;;; rational numbers once their arithmetic is done: a body at rest has kinetic energy
;;;; m (0^2 + 0^2) / 2, a template's zero component times an unknown is 0. Maxima's
;;;; ratsimp() of such an expression is that rational, and so is the simplest of the
;;;; :FULL candidates (a rational is an atom: no candidate is smaller). SIMPLIFY answers
;;;; them here, without a round trip; every other expression goes to Maxima unchanged.

(in-package #:ames.maxima)

(defun polynomial-expression-p (expression)
  "True when EXPRESSION is built of rationals, variables and quantity terms with + - *
and non-negative integer powers only: defined wherever its parts are, so that a product
of it with 0 is 0 (Maxima's simplifier writes 0 for it too)."
  (cond ((rationalp expression) t)
        ((or (variable-symbol-p expression) (quantity-term-p expression)) t)
        ((atom expression) nil)
        ((member (first expression) '(+ - *))
         (and (rest expression) (every #'polynomial-expression-p (rest expression))))
        ((eq (first expression) 'expt)
         (and (integerp (third expression)) (>= (third expression) 0)
              (polynomial-expression-p (second expression))))
        (t nil)))

(defun exact-constant-value (expression)
  "The rational value of EXPRESSION when its arithmetic on rationals gives one: sums,
differences, products (a product with a factor of value 0 and every factor polynomial,
POLYNOMIAL-EXPRESSION-P, is 0), quotients by a non-zero rational, integer powers (0 to
a power of 0 or less excluded); NIL otherwise (floats, functions, variables left)."
  (labels ((value (x)
             (cond ((rationalp x) x)
                   ((or (atom x) (null (rest x))) nil)
                   (t (case (first x)
                        (+ (let ((values (mapcar #'value (rest x))))
                             (and (every #'rationalp values) (reduce #'+ values))))
                        (- (let ((values (mapcar #'value (rest x))))
                             (and (every #'rationalp values) (apply #'- values))))
                        (* (let ((values (mapcar #'value (rest x))))
                             (cond ((and (member 0 values)
                                         (every #'polynomial-expression-p (rest x)))
                                    0)
                                   ((every #'rationalp values) (reduce #'* values)))))
                        (/ (let ((values (mapcar #'value (rest x))))
                             (and (every #'rationalp values)
                                  (notany #'zerop (if (rest values) (rest values) values))
                                  (apply #'/ values))))
                        (expt (let ((base (value (second x))) (power (third x)))
                                (and (rationalp base) (integerp power) (null (cdddr x))
                                     (not (and (zerop base) (<= power 0)))
                                     (expt base power))))
                        (t nil))))))
    (value expression)))
