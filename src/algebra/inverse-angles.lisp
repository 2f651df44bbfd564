;;;; src/algebra/inverse-angles.lisp -- relations with sin, cos or tan of an inverse
;;;; trigonometric angle, decided once those are algebraic.
;;;;
;;;; A duration or an angle found by solving often comes as 2 atan(u), pi + 2 atan(u) or
;;;; asin(c) - acos(d); the sign of g sin(2 atan u) sqrt(m k) + k cos(2 atan u) sqrt(2 g h)
;;;; is then asked (a body leaving a vertical bumper: the sign of its velocity). sign()
;;;; and is() do not see that sin(2 atan u) = 2 u/(1 + u^2) and cos(2 atan u) = (1 -
;;;; u^2)/(1 + u^2), so the run forked on a fact that always holds. Expanding the multiple
;;;; and compound angles (trigexpand, twice, after expand; Maxima writes sin(atan u), cos(asin
;;;; c), ... algebraically) turns such a relation into an algebraic one, which sign()
;;;; decides. The rewriting is an identity, so the verdict on the rewritten relation is the
;;;; verdict on the relation.

(in-package #:ames.algebra)

(defun inverse-trigonometric-p (expression)
  "True when EXPRESSION holds asin, acos or atan of something that is not a number."
  (and (consp expression)
       (or (and (member (expression-operator expression) '(asin acos atan))
                (not (numeric-constant-p (first (expression-arguments expression)))))
           (some #'inverse-trigonometric-p (expression-arguments expression)))))

(defun inverse-angle-kernel-p (expression)
  "True when EXPRESSION holds sin, cos or tan of an angle with an inverse trigonometric
function of a non-number in it."
  (and (consp expression)
       (or (and (member (expression-operator expression) '(sin cos tan))
                (inverse-trigonometric-p (first (expression-arguments expression))))
           (some #'inverse-angle-kernel-p (expression-arguments expression)))))

(defun numeric-constant-p (expression)
  "True when EXPRESSION has no symbol but pi."
  (cond ((numberp expression) t)
        ((symbolp expression) (eq expression 'pi))
        ((consp expression) (every #'numeric-constant-p (expression-arguments expression)))
        (t nil)))

(defun decide-by-inverse-angle-expansion (prover relation)
  "Step 7: RELATION (= /= < > <= >=) whose sides hold sin, cos or tan of an inverse
trigonometric angle, with the difference of its sides expanded (SIMPLIFY's
:EXPANDED-TRIGEXPAND) so that those kernels become algebraic, decided afresh against
0. :UNKNOWN when the expansion leaves such a kernel or leaves the algebra."
  (let ((difference (relation-difference relation))
        (bridge (prover-bridge prover)))
    (if (not (inverse-angle-kernel-p difference))
        :unknown
        (let ((expanded (handler-case (simplify bridge difference :strategy :expanded-trigexpand)
                          (untranslatable-result () nil))))
          (if (or (null expanded) (inverse-angle-kernel-p expanded))
              :unknown
              (decide bridge (list (expression-operator relation) expanded 0)))))))

;;; Polar angles: atan2(y, x) with y of a known sign

(defun polar-angles (expression)
  "The atan(Y, X) (two arguments: the polar angle of (X, Y)) in EXPRESSION, innermost first."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (mapc #'walk (expression-arguments x))
                 (when (and (eq (expression-operator x) 'atan) (= 2 (length (expression-arguments x))))
                   (pushnew x found :test #'equal)))))
      (walk expression))
    (nreverse found)))

(defun decide-by-polar-angles (prover relation)
  "Step 8: each polar angle atan2(Y, X) of RELATION whose Y is proven positive (negative)
written pi/2 - atan(X/Y) (-pi/2 - atan(X/Y)), an identity on that side of the x axis, so
that its range is (0, pi) ((-pi, 0)); the relation decided afresh. :UNKNOWN when no Y's
sign is known."
  (let* ((bridge (prover-bridge prover))
         (bindings (loop for angle in (polar-angles relation)
                         for (y x) = (expression-arguments angle)
                         for quarter = (cond ((holds-p bridge (list '> y 0)) '(/ pi 2))
                                             ((holds-p bridge (list '< y 0)) '(- (/ pi 2))))
                         when quarter
                           collect (cons angle `(- ,quarter (atan (/ ,x ,y)))))))
    (if (null bindings)
        :unknown
        (decide bridge (substitute-subexpressions bindings relation)))))
