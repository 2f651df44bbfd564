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
;;;; them (the report lists it). A sign the values leave open (too close to call, a zero)
;;;; still gets DECIDE's full work.

(in-package #:ames.simulator)

(defun approximate-start-p (run)
  "True when the run has parameter values deciding first (AMES.ALGEBRA:VALUES-FIRST-P) and
the current state starts at a time with no closed form: an earlier state's end was found
with numbers."
  (and (run-values run)
       (ames.algebra:values-first-p)
       (not (closed-form-time-p (run-time run)))))

(defun sign-at-approximate-start (run x refuted)
  "X's sign set at the start of a state that starts where numbers put it
(APPROXIMATE-START-P), when the run's values give X one strict sign (REFUTED, from
AMES.ALGEBRA:SIGNS-REFUTED-BY-VALUES, holds the other two) and a cheap proof or the values
settle it (DECIDED-OR-BY-VALUES-FIRST); else NIL (SIGN-OF goes on as elsewhere)."
  (when (and refuted (= 2 (length refuted)) (approximate-start-p run))
    (let ((sign (first (set-difference '(:positive :negative) refuted))))
      (when sign
        (when (eq :true (decided-or-by-values-first
                         run (if (eq sign :positive) `(> ,x 0) `(< ,x 0))))
          (list sign))))))
