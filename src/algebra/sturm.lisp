;;;; src/algebra/sturm.lisp -- signs a physicist reads off that sign() misses: a polynomial in one bounded quantity (Sturm), a multiple of what a fact bounds.
;;;;
;;;; A physicist reads off that 32 c^4 - 96 c^3 + 108 c - 81 < 0 for c = cos theta0 with
;;;; 0 < theta0 < pi/2 by looking at it on [0, 1]; Maxima's sign() cannot. When an
;;;; expression is a polynomial with rational coefficients in a single kernel (a subject,
;;;; or sin or cos of a subject) whose range the facts in force bound on both sides,
;;;; Maxima's nroots() (Sturm sequences, exact on rational coefficients) counts its real
;;;; roots in that interval. None inside means one sign throughout, read at the midpoint
;;;; by exact arithmetic; a root at a closed end adds zero. The interval may be wider
;;;; than the kernel's true range (ends that are not exact are widened outward): that
;;;; only ever loses a conclusion, never makes a wrong one.
;;;;
;;;; A branch assumes a fact about a compound expression (f l3 - mb g (l1 - l2) < 0);
;;;; sign() uses it only for that very form. A factor that is a constant multiple of it
;;;; (ratsimp of the ratio is a number) has its sign from the fact.

(in-package #:ames.algebra)

(defun polynomial-kernel (x)
  "The one kernel K such that X is a polynomial with rational coefficients in K: a
subject (a variable or quantity term), or sin or cos of a subject. NIL when X has no
kernel, more than one, or another form (pi, a root, a quotient ...)."
  (let ((kernel nil))
    (labels ((kernel-p (y)
               (or (subject-p y)
                   (and (compound-expression-p y)
                        (member (expression-operator y) '(sin cos))
                        (= (length (expression-arguments y)) 1)
                        (subject-p (first (expression-arguments y))))))
             (walk (y)
               (cond ((rationalp y) t)
                     ((kernel-p y)
                      (cond ((null kernel) (setf kernel y) t)
                            (t (equal kernel y))))
                     ((not (compound-expression-p y)) nil)
                     (t (let ((arguments (expression-arguments y)))
                          (case (expression-operator y)
                            ((+ - *) (every #'walk arguments))
                            (expt (and (integerp (second arguments))
                                       (>= (second arguments) 0)
                                       (walk (first arguments))))
                            (t nil)))))))
      (and (walk x) kernel))))

(defun kernel-polynomial-value (x kernel value)
  "The exact value of the polynomial X (see POLYNOMIAL-KERNEL) at KERNEL = VALUE (a
rational)."
  (labels ((value-of (y)
             (cond ((rationalp y) y)
                   ((equal y kernel) value)
                   (t (let ((arguments (mapcar #'value-of (expression-arguments y))))
                        (ecase (expression-operator y)
                          (+ (reduce #'+ arguments))
                          (- (if (rest arguments)
                                 (reduce #'- arguments)
                                 (- (first arguments))))
                          (* (reduce #'* arguments))
                          (expt (expt (first arguments) (second arguments)))))))))
    (value-of x)))

(defun range-end-rational (end side)
  "The PI-NUMBER END of a range as (values RATIONAL EXACT): exact when END has no pi
part, else a rational just outside it on SIDE (:LOWER or :UPPER)."
  (if (zerop (cdr end))
      (values (car end) t)
      (values (car (widened-bound (pn-float end) side)) nil)))

(defun circular-end-value (function end side)
  "FUNCTION (SIN or COS) at the range end END (a PI-NUMBER), as (values RATIONAL EXACT):
exact at the multiples of pi/2, else a rational just outside it on SIDE."
  (let ((quarter (and (zerop (car end)) (/ (cdr end) 1/2))))
    (if (integerp quarter)
        (values (let ((k (mod (if (eq function 'sin) quarter (1+ quarter)) 4)))
                  (case k (0 0) (1 1) (2 0) (3 -1)))
                t)
        (values (car (widened-bound (funcall function (pn-float end)) side)) nil))))

(defun kernel-interval (prover kernel)
  "An interval holding every admissible value of KERNEL, as (values LOW HIGH LOW-OPEN
HIGH-OPEN), rationals and flags; NIL when the facts do not bound it on both sides. An
end is open only when it is exact and the range excludes it."
  (flet ((subject-range (subject)
           (let ((range (cdr (assoc subject (prover-ranges prover) :test #'equal))))
             (and range (range-lower range) (range-upper range) range))))
    (if (subject-p kernel)
        (let ((range (subject-range kernel)))
          (when range
            (multiple-value-bind (low low-exact) (range-end-rational (range-lower range) :lower)
              (multiple-value-bind (high high-exact) (range-end-rational (range-upper range) :upper)
                (values low high
                        (and low-exact (range-lower-open range))
                        (and high-exact (range-upper-open range)))))))
        (let* ((function (expression-operator kernel))
               (range (subject-range (first (expression-arguments kernel))))
               (direction (and range (range-monotonicity function range))))
          (cond ((null direction) (values -1 1 nil nil))
                (t
                 (let ((first-end (if (eq direction :increasing) :lower :upper)))
                   (multiple-value-bind (low low-exact)
                       (circular-end-value function (if (eq first-end :lower)
                                                        (range-lower range) (range-upper range))
                                           :lower)
                     (multiple-value-bind (high high-exact)
                         (circular-end-value function (if (eq first-end :lower)
                                                          (range-upper range) (range-lower range))
                                             :upper)
                       (values low high
                               (and low-exact (if (eq first-end :lower)
                                                  (range-lower-open range)
                                                  (range-upper-open range)))
                               (and high-exact (if (eq first-end :lower)
                                                   (range-upper-open range)
                                                   (range-lower-open range)))))))))))))

(defun polynomial-interval-signs (prover x)
  "The signs X takes at every admissible point when X is a polynomial in one kernel
bounded on both sides (see this file's header), as a list of :POSITIVE :ZERO :NEGATIVE;
NIL when that does not apply or the roots are inside the interval."
  (let ((kernel (polynomial-kernel x)))
    (when kernel
      (multiple-value-bind (low high low-open high-open) (kernel-interval prover kernel)
        (when (and low high (< low high))
          (let* ((bridge (prover-bridge prover))
                 (variable 'sturm-variable)
                 (polynomial (subst variable kernel x :test #'equal))
                 (at-low (kernel-polynomial-value x kernel low))
                 (at-high (kernel-polynomial-value x kernel high))
                 (middle (kernel-polynomial-value x kernel (/ (+ low high) 2)))
                 (count (handler-case
                            (maxima-root-count bridge polynomial low high :datum x)
                          (maxima-error () nil))))
            ;; nroots counts the roots in (LOW, HIGH]
            (when (and (integerp count)
                       (= count (if (zerop at-high) 1 0))
                       (not (zerop middle)))
              (let ((signs (list (if (plusp middle) :positive :negative))))
                (when (or (and (zerop at-low) (not low-open))
                          (and (zerop at-high) (not high-open)))
                  (push :zero signs))
                signs))))))))

;;; Facts about compound expressions

(defun compound-fact-signs (bridge)
  "For each fact in force that bounds a compound expression (a branch's X > 0, with X
a sum such as f l3 - mb g (l1 - l2)), (DIFFERENCE . SIGNS): LHS - RHS and the signs the
fact gives it. Facts between plain subjects and constants are left out: sign() and
DECIDE's orders already use them."
  (loop for fact in (flatten-facts (current-assumptions bridge))
        for operator = (and (consp fact) (expression-operator fact))
        when (and (member operator '(< > <= >=))
                  (not (and (or (subject-p (relation-lhs fact))
                                (null (expression-variables (relation-lhs fact))))
                            (or (subject-p (relation-rhs fact))
                                (null (expression-variables (relation-rhs fact)))))))
          collect (cons (relation-difference fact)
                        (ecase operator
                          (> '(:positive)) (>= '(:positive :zero))
                          (< '(:negative)) (<= '(:negative :zero))))))

(defun compound-fact-multiple-signs (bridge x)
  "The signs of X when X is a constant multiple of the expression a fact in force bounds
(see COMPOUND-FACT-SIGNS), by Maxima's ratsimp of their ratio; NIL otherwise."
  (let ((variables (expression-variables x)))
    (loop for (difference . signs) in (compound-fact-signs bridge)
          when (subsetp (expression-variables difference) variables :test #'equal)
            do (let ((ratio (handler-case (simplify bridge (list '/ x difference))
                              (maxima-error () nil)
                              (untranslatable-result () nil))))
                 (when (and (rationalp ratio) (/= ratio 0))
                   (return (if (plusp ratio) signs (negated-signs signs))))))))
