;;;; src/scenario/numbers.lisp -- comparing the numeric values of constant expressions, for the validator's cheap checks.
;;;;
;;;; The validator decides some facts itself, without Maxima, when the numbers settle
;;;; them: (> x 2) with (< x 1), a radius of -1, a clockwise polygon with numeric
;;;; vertices, a default :value outside its parameter's bounds. The values come from
;;;; AMES.BASE:EXPRESSION-VALUE (exact rationals where it can, else double-floats); this
;;;; file orders them, leaving undecided (for Maxima) the approximations too close to
;;;; call.

(in-package #:ames.scenario)

(defconstant +relative-tolerance+ 1d-9
  "Approximate values closer than this (relative) are not ordered by COMPARE-VALUES.")

(defun constant-value (expression &optional bindings)
  "The scenario API's name for AMES.BASE:EXPRESSION-VALUE: the real value of EXPRESSION
with its variables bound by the alist BINDINGS, and whether it is exact,
(values VALUE EXACTP); NIL when it has none. Signals nothing."
  (expression-value expression bindings))

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

;;; Numbers people write (issue 26): degrees and defaults that are expressions

(defun degrees-expression (validation form walk)
  "The expression of (deg X): X degrees in radians, X pi / 180, with X checked by WALK."
  (unless (and (proper-list-p form) (= 2 (length form)))
    (reject validation 'scenario-expression-error form "(deg X) takes one number of degrees, not ~A" (show form)))
  `(/ (* ,(funcall walk (second form)) pi) 180))

(defun default-value (validation assumption)
  "The number of the default (:value X): X a finite real, or a constant expression such
as (deg 30) or (/ pi 6) (its value, exact where it is rational, else a double-float)."
  (let ((x (second assumption)))
    (if (realp x)
        (if (finite-real-p x)
            x
            (reject validation 'scenario-expression-error assumption
                    "a default value is (:value NUMBER) with a finite real NUMBER, not ~A" (show assumption)))
        (let ((value (and (consp x)
                          (constant-value (handler-case (checked-expression validation x)
                                            (scenario-error ()
                                              (reject validation 'scenario-expression-error assumption
                                                      "a default value is a number or an expression of numbers and pi, not ~A"
                                                      (show assumption))))))))
          (unless (and (realp value) (finite-real-p value))
            (reject validation 'scenario-expression-error assumption
                    "a default value is a number or an expression of numbers and pi, not ~A" (show assumption)))
          (if (and (floatp value) (= value (rational value)) (integerp (rational value)))
              (rational value)
              value)))))
