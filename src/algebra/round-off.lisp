;;;; src/algebra/round-off.lisp -- how large the round-off of a double evaluation can be,
;;;; from the magnitudes of the terms it adds: the scale below which a float value is no sign.
;;;;
;;;; A constant sum of radicals that is exactly zero, such as sqrt(2) sqrt(11) - sqrt(22),
;;;; evaluates to a few units of round-off in the last place of its largest term, of either
;;;; sign; Maxima's sign() of such a constant takes a float's sign ("neg" for a sum of
;;;; products of square roots whose double value is +5e-14). The root search asked the sign
;;;; of the product of a quadratic's roots written that way, was told "negative" for a
;;;; product that is 0, and returned as the "next" root the very root it was asked to look
;;;; past (a particle crossing the line of a step's bottom face beyond its end at the moment
;;;; it lands on the floor: the search for a later crossing met that root again and again).
;;;;
;;;; ROUND-OFF-SCALE bounds the magnitude the round-off of a double evaluation is relative
;;;; to (sums add their terms' magnitudes, products multiply them); a value within
;;;; *FLOAT-ROUND-OFF* of it is no sign. CONSTANT-ZERO-SIGNS decides such a constant
;;;; exactly (EXACTLY-ZERO-P, constant-zero.lisp) or leaves its sign open, never the float's.

(in-package #:ames.algebra)

(defparameter *float-round-off* 1d-12
  "A double value within this of its ROUND-OFF-SCALE (relative) may be round-off of an
exact zero (a few thousand units in the last place: the terms' own errors added up);
beyond it, its sign is the float's.")

(defun round-off-scale (expression &optional bindings)
  "A magnitude the round-off of EXPRESSION's double value (under BINDINGS, as
EXPRESSION-VALUE takes them) is relative to: for a sum or difference, the sum of its
terms' scales; for a product, their product; for a quotient, the numerator's scale over
the denominator's size; for a power with a non-negative constant exponent, the base's
scale to that power; for a sine or cosine, its size plus its argument's scale (an error
in the argument moves it by as much), for an exponential its size times one plus its
argument's scale; else the size of the value. NIL when a value is not real."
  (labels ((size (x) (let ((v (expression-value x bindings))) (and (realp v) (abs v))))
           (scale (x)
             (if (atom x)
                 (size x)
                 (let ((arguments (expression-arguments x)))
                   (case (expression-operator x)
                     ((+ -) (sum-of (mapcar #'scale arguments)))
                     (* (product-of (mapcar #'scale arguments)))
                     (/ (let ((numerator (scale (first arguments)))
                              (denominators (mapcar #'size (rest arguments))))
                          (and numerator (every (lambda (d) (and d (plusp d))) denominators)
                               (/ numerator (product-of denominators)))))
                     (sqrt (let ((s (scale (first arguments)))) (and s (sqrt (float s 1d0)))))
                     (expt (let ((exponent (expression-value (second arguments) bindings))
                                 (base (scale (first arguments))))
                             (if (and (realp exponent) (>= exponent 0) base)
                                 (expt (float base 1d0) exponent)
                                 (size x))))
                     ;; an argument's round-off moves these by as much times the slope
                     ((sin cos) (let ((s (scale (first arguments))) (v (size x)))
                                  (and s v (+ v s))))
                     (exp (let ((s (scale (first arguments))) (v (size x)))
                            (and s v (* v (+ 1 s)))))
                     (t (size x))))))
           (sum-of (scales) (and (every #'realp scales) (reduce #'+ scales)))
           (product-of (scales) (and (every #'realp scales) (reduce #'* scales))))
    (let ((s (ignore-errors (scale expression))))
      (and (realp s) (float s 1d0)))))

(defun zero-to-round-off-p (expression &optional bindings)
  "True when EXPRESSION's double value (under BINDINGS) is within *FLOAT-ROUND-OFF*
of its ROUND-OFF-SCALE: its sign is beyond what the float can tell. NIL when its value is
not real or is exact (a rational is its own sign)."
  (multiple-value-bind (value exact) (expression-value expression bindings)
    (and (realp value) (not exact)
         (let ((scale (round-off-scale expression bindings)))
           (and scale (<= (abs value) (* *float-round-off* (max scale least-positive-normalized-double-float))))))))

(defun constant-zero-signs (bridge expression)
  "For a constant EXPRESSION (no variables) whose double value is zero to round-off
(ZERO-TO-ROUND-OFF-P): its sign when exact interval arithmetic proves it
(EXACT-CONSTANT-SIGN: numbers and radicals whose terms cancel far beyond a double's
digits), (:ZERO) when it is proven exactly zero (EXACTLY-ZERO-P), else all three signs
(the float's sign is no proof). NIL when EXPRESSION has variables or is clear of
round-off, which Maxima's sign() decides."
  (when (and (null (expression-variables expression)) (zero-to-round-off-p expression))
    (let ((exact (exact-constant-sign expression)))
      (cond ((member exact '(:positive :negative :zero)) (list exact))
            ((exactly-zero-p bridge expression) (list :zero))
            (t (list :positive :negative :zero))))))
