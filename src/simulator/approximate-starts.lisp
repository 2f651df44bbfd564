;;;; src/simulator/approximate-starts.lisp -- signs at the start of a state that an earlier
;;;; state ended at a time or angle found with numbers.
;;;;
;;;; Under parameter values, a state whose end has no closed form (a numeric integration, a
;;;; root along a rotation path searched with numbers: numeric-angle-roots.lisp) hands the
;;;; next state a start known only at those values: its angle is a rational near the root,
;;;; its time a number. A proof over every admissible parameter of a relation written at
;;;; that start (a pivot's friction limit at the angle 23834928/57948097) proves nothing the
;;;; values do not already settle, and DECIDE's full strategies spent minutes on such
;;;; relations, with sines and cosines of the angle, in the next state's choice search. So
;;;; there, as for the order of two event times, the values decide first: a cheap proof
;;;; (AMES.ALGEBRA:DECIDE-FIRST-CHEAPLY), else the values' verdict, recorded as assumed from
;;;; them (the report lists it). A value within a small tolerance of the size of its
;;;; terms is zero there, also recorded as assumed from the values: what vanishes at the
;;;; event (the friction limit that ended the state) is only near zero at the rational
;;;; angle that approximates it, and no proof over the parameters can say more (DECIDE's
;;;; full strategies on it ran past the run's time limit).

(in-package #:ames.simulator)

(defun approximate-start-p (run)
  "True when the run has parameter values deciding first (AMES.ALGEBRA:VALUES-FIRST-P) and
the current state starts at a time with no closed form: an earlier state's end was found
with numbers."
  (and (run-values run)
       (ames.algebra:values-first-p)
       (not (closed-form-time-p (run-time run)))))

(defparameter *approximate-start-tolerance* 1d-9
  "How small, relative to the size of its terms (TERM-MAGNITUDE), a value at a start that
numbers put there is taken as too close to zero for the values to give its sign: a
quantity that vanishes at the event found with numbers (a friction limit reached) is only
near zero at the rational angle that approximates it.")

(defun term-magnitude (expression bindings)
  "The size of EXPRESSION's terms at BINDINGS (an alist name -> double): sums and
differences add their parts' sizes, products multiply them, a quotient divides by its
divisor's value, anything else is its own absolute value; NIL where a value is missing."
  (flet ((value (x) (let ((v (expression-value x bindings))) (and (realp v) (abs v)))))
    (if (and (consp expression) (not (quantity-term-p expression)))
        (let ((parts (mapcar (lambda (a) (term-magnitude a bindings)) (rest expression))))
          (case (first expression)
            ((+ -) (and (every #'realp parts) (reduce #'+ parts)))
            (* (and (every #'realp parts) (reduce #'* parts)))
            (/ (let ((divisor (value (third expression))))
                 (and (realp (first parts)) divisor (plusp divisor) (/ (first parts) divisor))))
            (t (value expression))))
        (value expression))))

(defun clearly-nonzero-at-values-p (run x)
  "True when X's value at the run's values is larger than *APPROXIMATE-START-TOLERANCE*
times the size of its terms."
  (let* ((bindings (numeric-bindings run))
         (value (expression-value x bindings))
         (size (term-magnitude x bindings)))
    (and (realp value) (realp size)
         (> (abs value) (* *approximate-start-tolerance* (max size least-positive-normalized-double-float))))))

(defun sign-at-approximate-start (run x refuted)
  "X's sign set at the start of a state that starts where numbers put it
(APPROXIMATE-START-P), when the run's values give X one strict sign (REFUTED, from
AMES.ALGEBRA:SIGNS-REFUTED-BY-VALUES, holds the other two) and a cheap proof or the values
settle it (DECIDED-OR-BY-VALUES-FIRST); else NIL (SIGN-OF goes on as elsewhere)."
  (when (approximate-start-p run)
    (cond ((and refuted (= 2 (length refuted)) (clearly-nonzero-at-values-p run x))
           (let ((sign (first (set-difference '(:positive :negative) refuted))))
             (when (and sign
                        (eq :true (decided-or-by-values-first
                                   run (if (eq sign :positive) `(> ,x 0) `(< ,x 0)))))
               (list sign))))
          ((near-zero-at-values-p run x)
           ;; vanishing at the event found with numbers: zero, as the values have it
           (push (list :fact `(= ,x 0) :from :values) (run-assumed run))
           (list :zero)))))

(defun near-zero-at-values-p (run x)
  "True when X mentions a parameter, has a value at the run's values, and that value is
within *APPROXIMATE-START-TOLERANCE* of the size of its terms (not one proven zero: a
quantity that vanishes at the approximate start, as at the event it approximates)."
  (let* ((bindings (numeric-bindings run))
         (value (expression-value x bindings))
         (size (term-magnitude x bindings)))
    (and (expression-variables x) (realp value) (realp size) (plusp size)
         (<= (abs value) (* *approximate-start-tolerance* size)))))
