;;;; src/algebra/radical-cases.lisp -- a strategy of DECIDE: one square root cleared by cases
;;;; on the sign of the part beside it.
;;;;
;;;; A relation whose sides differ by (a + b sqrt(A)) / c is decided by RADICAL-SIGNS
;;;; (deciding.lisp) when sign() gives the signs of a, b, A and b^2 A - a^2 outright. Two
;;;; things defeat it on a root of a quadratic met in a run (the rocking block's turning
;;;; point, tan(s*/2) = (sqrt(A) - 3 g w) / B, against -1): the radicand's sign follows
;;;; from the facts only through DECIDE's own strategies (the convexity of A between a
;;;; declared bound's ends), and the sign of a (here B - 3 g w) is not fixed by the facts at
;;;; all: a + b sqrt(A) > 0 holds because it holds trivially where a >= 0 and, where a < 0,
;;;; b^2 A - a^2 > 0 follows from the facts together with a < 0. DECIDE-BY-RADICAL-CASES
;;;; makes that case split: with b of a proven strict sign s and A > 0 proven,
;;;;   - a + b sqrt(A) has the sign s when b^2 A - a^2 > 0 is proven under the extra
;;;;     fact s a < 0 (where s a >= 0 the two terms agree and b sqrt(A) /= 0);
;;;;   - it has the sign -s when s a < 0 and b^2 A - a^2 < 0 are proven;
;;;; and c's proven strict sign gives the sign of the difference. Sound: each case is an
;;;; equivalence of real numbers (A > 0 makes the root real), and an extra fact that
;;;; contradicts the facts in force makes its case vacuous. The case's gap is factored and
;;;; each factor's sign found by the rules of signs, or from the case's fact and a
;;;; remainder of proven sign (fact-remainders.lisp; not by DECIDE under the fact, whose
;;;; depth bounds would cut it when the question is itself nested, and which costs much on
;;;; every relation with a root); only A > 0 is asked of DECIDE, last. Tried after the reasoning of
;;;; truth.lisp, on small relations; it does not recurse into itself.

(in-package #:ames.algebra)

(defvar *deciding-radical-cases* nil
  "True while DECIDE-BY-RADICAL-CASES decides its parts, so that it does not recurse.")

(defparameter *largest-relation-for-radical-cases* 400
  "The largest relation (EXPRESSION-SIZE) DECIDE-BY-RADICAL-CASES works on.")

(defun cheap-strict-sign (bridge x)
  "+1 or -1 when the rules of signs (with Maxima's sign() on the leaves:
EXPRESSION-SIGNS) give X one strict sign, else NIL. Far cheaper than DECIDE."
  (let ((signs (expression-signs (prover-for bridge) x)))
    (cond ((equal signs '(:positive)) 1)
          ((equal signs '(:negative)) -1))))

(defun product-factors (expression)
  "EXPRESSION as a product: (values SIGN FACTORS), SIGN +1 or -1 from its numbers and
negations, FACTORS the rest (powers kept whole); NIL for a zero number."
  (let ((sign 1) (factors '()))
    (labels ((walk (x)
               (cond ((realp x) (cond ((zerop x) (return-from product-factors nil))
                                      ((minusp x) (setf sign (- sign)))))
                     ((and (consp x) (eq (expression-operator x) '-) (null (cddr x)))
                      (setf sign (- sign))
                      (walk (second x)))
                     ((and (consp x) (eq (expression-operator x) '*))
                      (mapc #'walk (expression-arguments x)))
                     (t (push x factors)))))
      (walk expression))
    (values sign (nreverse factors))))

(defun factor-sign-under (bridge factor fact)
  "The strict sign (+1, -1) of FACTOR by the rules of signs, or under the facts in force
and FACT by FACT and a remainder of proven sign (fact-remainders.lisp); NIL when not
proven. A power FACTOR^n counts as FACTOR n times."
  (if (and (consp factor) (eq (expression-operator factor) 'expt) (integerp (third factor))
           (plusp (third factor)))
      (let ((base (factor-sign-under bridge (second factor) fact)))
        (and base (expt base (third factor))))
      (or (cheap-strict-sign bridge factor)
          (and fact (goal-proven-by-one-fact-p bridge factor t (list fact)) 1)
          (and fact (goal-proven-by-one-fact-p bridge `(- ,factor) t (list fact)) -1))))

(defun factored-sign (bridge x fact)
  "The strict sign of X from its factors' (FACTOR-SIGN-UNDER, FACT or NIL), or NIL."
  (let ((factored (handler-case (simplify bridge x :strategy :full)
                    ((or maxima-error untranslatable-result) () nil))))
    (when factored
      (multiple-value-bind (sign factors) (product-factors factored)
        (when sign
          (let ((signs (mapcar (lambda (f) (factor-sign-under bridge f fact)) factors)))
            (and (notany #'null signs) (apply #'* sign signs))))))))

(defun strict-of (signs)
  "+1 or -1 for the sign sets (:POSITIVE) and (:NEGATIVE), else NIL."
  (cond ((equal signs '(:positive)) 1)
        ((equal signs '(:negative)) -1)))

(defun radical-numerator-sign (bridge a b radicand part-signs)
  "The strict sign (+1 or -1) of a + b sqrt(A), A = RADICAND, found by cases on the sign
of a (see this file's header), or NIL. PART-SIGNS are sign() of a, b, b^2 A - a^2, A and
the denominator (SQUARE-ROOT-PART-SIGNS, asked already by RADICAL-SIGNS). Only the
radicand's sign is asked of DECIDE (its proof may need DECIDE's costlier strategies),
last, where the rest is settled."
  (destructuring-bind (a-signs b-signs gap-signs radicand-signs denominator-signs) part-signs
    (declare (ignore denominator-signs))
    (let ((s (strict-of b-signs)))
      (when s
        (let* ((gap `(- (* (expt ,b 2) ,radicand) (expt ,a 2)))
               ;; s a < 0: a against the side b sqrt(A) is on
               (against (if (= s 1) `(< ,a 0) `(> ,a 0)))
               (a-sign (strict-of a-signs))
               (sign (cond ((eql a-sign s) s)
                           ((and (eql a-sign (- s)) (eql -1 (strict-of gap-signs))) (- s))
                           ((eql a-sign (- s)) nil)
                           ((eql 1 (factored-sign bridge gap against)) s))))
          (and sign
               (or (member radicand-signs '((:positive)) :test #'equal)
                   (holds-p bridge (list '> radicand 0)))
               sign))))))

(defun decide-by-radical-cases (bridge relation)
  "RELATION (< <= > >=) whose sides differ by (a + b sqrt(A)) / c, decided from the
strict signs of the numerator (found by cases, RADICAL-NUMERATOR-SIGN) and of c;
:UNKNOWN when they are not proven or the relation is not of that form."
  (let ((operator (expression-operator relation)))
    (if (or *deciding-radical-cases*
            (not (member operator '(< <= > >=)))
            (not (radical-expression-p relation))
            (> (expression-size relation) *largest-relation-for-radical-cases*))
        :unknown
        (let ((*deciding-radical-cases* t))
          (multiple-value-bind (a b radicand denominator)
              (handler-case (square-root-parts bridge (relation-lhs relation) (relation-rhs relation)
                                               :datum relation)
                (maxima-error () nil))
            (declare (ignore denominator))
            (let* ((part-signs (and radicand
                                    (handler-case (square-root-part-signs bridge (relation-lhs relation)
                                                                          (relation-rhs relation) :datum relation)
                                      (maxima-error () nil))))
                   (denominator-sign (and part-signs (strict-of (fifth part-signs))))
                   (numerator-sign (and denominator-sign
                                        (radical-numerator-sign bridge a b radicand part-signs))))
              (if (null numerator-sign)
                  :unknown
                  (relation-verdict operator
                                    (if (plusp (* numerator-sign denominator-sign))
                                        '(:positive)
                                        '(:negative))))))))))
