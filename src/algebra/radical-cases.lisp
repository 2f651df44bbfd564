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
;;;; each factor's sign proven from the facts in force, or from the case's fact and a
;;;; remainder of proven sign (fact-remainders.lisp; not by DECIDE under the fact, whose
;;;; depth bounds would cut it when the question is itself nested). Tried after the reasoning of
;;;; truth.lisp, on small relations; it does not recurse into itself.

(in-package #:ames.algebra)

(defvar *deciding-radical-cases* nil
  "True while DECIDE-BY-RADICAL-CASES decides its parts, so that it does not recurse.")

(defparameter *largest-relation-for-radical-cases* 400
  "The largest relation (EXPRESSION-SIZE) DECIDE-BY-RADICAL-CASES works on.")

(defun proven-strict-sign (bridge x)
  "+1 when X > 0 is proven under the facts in force, -1 when X < 0 is, else NIL."
  (cond ((numberp x) (and (/= x 0) (if (plusp x) 1 -1)))
        ((holds-p bridge (list '> x 0)) 1)
        ((holds-p bridge (list '< x 0)) -1)))

(defun holds-under-p (bridge fact relation)
  "True when RELATION is proven under the facts in force and FACT; also when FACT
contradicts the facts in force (the case is vacuous)."
  (handler-case (call-with-assumptions bridge (list fact) (lambda () (holds-p bridge relation)))
    (inconsistent-assumptions () t)
    (maxima-error () nil)))

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
  "The strict sign (+1, -1) of FACTOR under the facts in force, or under them and FACT
by FACT and a remainder of proven sign (fact-remainders.lisp); NIL when not proven. A
power FACTOR^n counts as FACTOR n times."
  (if (and (consp factor) (eq (expression-operator factor) 'expt) (integerp (third factor))
           (plusp (third factor)))
      (let ((base (factor-sign-under bridge (second factor) fact)))
        (and base (expt base (third factor))))
      (or (proven-strict-sign bridge factor)
          (and (goal-proven-by-one-fact-p bridge factor t (list fact)) 1)
          (and (goal-proven-by-one-fact-p bridge `(- ,factor) t (list fact)) -1))))

(defun positive-under-p (bridge gap fact)
  "True when GAP > 0 is proven under the facts in force and FACT: GAP factored, each
factor's strict sign proven (FACTOR-SIGN-UNDER), or else DECIDE under FACT."
  (let ((factored (handler-case (simplify bridge gap :strategy :full)
                    ((or maxima-error untranslatable-result) () nil))))
    (or (and factored
             (multiple-value-bind (sign factors) (product-factors factored)
               (and sign
                    (let ((signs (mapcar (lambda (f) (factor-sign-under bridge f fact)) factors)))
                      (and (notany #'null signs)
                           (= 1 (apply #'* sign signs)))))))
        (holds-under-p bridge fact `(> ,gap 0)))))

(defun radical-numerator-sign (bridge a b radicand)
  "The strict sign (+1 or -1) of a + b sqrt(A), A = RADICAND, found by cases on the sign
of a (see this file's header), or NIL."
  (let ((s (proven-strict-sign bridge b)))
    (when (and s (holds-p bridge (list '> radicand 0)))
      (let ((gap `(- (* (expt ,b 2) ,radicand) (expt ,a 2)))
            ;; s a < 0: a against the side b sqrt(A) is on
            (against (if (= s 1) `(< ,a 0) `(> ,a 0))))
        (cond ((positive-under-p bridge gap against) s)
              ((and (holds-p bridge against) (holds-p bridge `(< ,gap 0))) (- s))
              (t nil))))))

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
            (let* ((numerator-sign (and radicand (radical-numerator-sign bridge a b radicand)))
                   (denominator-sign (and numerator-sign (proven-strict-sign bridge denominator))))
              (if (null denominator-sign)
                  :unknown
                  (relation-verdict operator
                                    (if (plusp (* numerator-sign denominator-sign))
                                        '(:positive)
                                        '(:negative))))))))))
