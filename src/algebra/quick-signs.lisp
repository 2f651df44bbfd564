;;;; src/algebra/quick-signs.lisp -- a relation decided by the signs of its parts alone, before Maxima is asked.
;;;;
;;;; Most questions a run asks are about sums and products of parameters whose signs the
;;;; scenario declares (w1 + w2 > 0, -(w1 w3) < 0, m1 g = 0): the rules of signs settle
;;;; them, and asking Maxima's is() one by one made a chain of N symbolic blocks cost
;;;; N^2 round trips before anything moved. QUICK-VERDICT applies those rules in Lisp:
;;;; the signs of the difference of the relation's sides from the exact ranges the facts
;;;; in force give each subject (SUBJECT-RANGES), through sums of terms of one sign,
;;;; products and quotients of signed factors (a divisor that may be zero stops it),
;;;; integer and rational powers, square roots of radicands proven >= 0 and abs. It is a
;;;; proof where it answers; where any part is not settled it answers :UNKNOWN and DECIDE
;;;; goes on as before. The ranges are computed once per set of facts in force.

(in-package #:ames.algebra)

(defvar *quick-verdicts* t
  "True when DECIDE first tries QUICK-VERDICT; NIL takes the long way only (for tests
that compare the two).")

(defvar *quick-ranges* nil
  "The bridge and assumption frames QUICK-RANGES last saw, consed to the subject ranges
they gave.")

(defun quick-ranges (bridge)
  "The exact ranges of the subjects under the facts in force in BRIDGE (see
SUBJECT-RANGES), remembered for as long as the same scopes are in force."
  (let ((key (cons bridge (bridge-frames bridge))))
    (if (and *quick-ranges* (eq (car (car *quick-ranges*)) bridge)
             (equal (cdr (car *quick-ranges*)) (cdr key)))
        (cdr *quick-ranges*)
        (let ((ranges (subject-ranges (flatten-facts (current-assumptions bridge)))))
          (setf *quick-ranges* (cons key ranges))
          ranges))))

(defun quick-signs (prover x)
  "The signs the arithmetic expression X may take at every admissible point, from the
signs of its parts by the rules of signs and the subjects' exact ranges only (no
Maxima): a list of :POSITIVE :ZERO :NEGATIVE, or NIL when the rules do not settle it or
X may be undefined somewhere."
  (labels ((signs (y) (quick-signs prover y))
           (ranged () (range-signs prover x)))
    (cond ((realp x) (number-signs x))
          ((constant-symbol-p x) '(:positive))
          ((subject-p x) (ranged))
          ((not (compound-expression-p x)) nil)
          (t
           (let ((arguments (expression-arguments x)))
             (case (expression-operator x)
               (+ (or (sum-signs (mapcar #'signs arguments)) (ranged)))
               (- (if (rest arguments)
                      (or (sum-signs (cons (signs (first arguments))
                                           (mapcar (lambda (a) (negated-signs (signs a)))
                                                   (rest arguments))))
                          (ranged))
                      (negated-signs (signs (first arguments)))))
               (* (let ((result '(:positive)))
                    (dolist (factor arguments result)
                      (let ((part (signs factor)))
                        (if part
                            (setf result (sign-product result part))
                            (return nil))))))
               (/ (let ((result (if (rest arguments) (signs (first arguments)) '(:positive))))
                    (dolist (divisor (if (rest arguments) (rest arguments) arguments) result)
                      (let ((part (signs divisor)))
                        (if (and part (not (member :zero part)) result)
                            (setf result (sign-product result part))
                            (return nil))))))
               (expt (let ((exponent (second arguments)))
                       (and (rationalp exponent)
                            (power-signs (signs (first arguments)) exponent))))
               (sqrt (let ((inner (signs (first arguments))))
                       (and (only-signs-p inner :positive :zero) inner)))
               (abs (let ((inner (signs (first arguments))))
                      (cond ((null inner) nil)
                            ((member :zero inner) (if (rest inner) '(:positive :zero) '(:zero)))
                            (t '(:positive)))))
               (t nil)))))))

(defun quick-verdict (bridge relation)
  "The truth of the relation RELATION (= /= < > <= >=) under the facts in force by the
rules of signs alone (QUICK-SIGNS of the difference of its sides): :TRUE, :FALSE, or
:UNKNOWN when they do not settle it (and always when *QUICK-VERDICTS* is NIL). Asks
Maxima nothing."
  (unless *quick-verdicts*
    (return-from quick-verdict :unknown))
  (let* ((prover (make-prover bridge (quick-ranges bridge)))
         (lhs (quick-signs prover (relation-lhs relation)))
         (rhs (and lhs (quick-signs prover (relation-rhs relation))))
         (difference (and rhs (sum-signs (list lhs (negated-signs rhs))))))
    (relation-verdict (expression-operator relation) difference)))
