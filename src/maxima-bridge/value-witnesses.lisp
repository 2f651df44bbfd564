;;;; src/maxima-bridge/value-witnesses.lisp -- the run's parameter values as witnesses: the points at and around them.
;;;;
;;;; A run given values (bin/ames --set, --numeric) simulates the branch its values select,
;;;; so the values satisfy the facts in force there, however narrow the region those facts
;;;; leave (B rises only while f > mb g (l1 - l2)/l3): random points over each parameter's
;;;; own bounds seldom fall in it, points near the values do. The quick proofs of
;;;; witnesses.lisp (a relation that fails at an admissible point is not proven; one that
;;;; holds at one and fails at another is decided neither way) take these points as well,
;;;; after their random ones. Every point is still checked against every fact in force
;;;; before it counts, so no answer changes, only the cost of finding it; the messages
;;;; that name values (EXPLAIN-UNDECIDED) do not use them.

(in-package #:ames.maxima)

(defparameter *value-seed-spreads* '(0d0 1d-3 1d-2 3d-2 1d-1 3d-1)
  "The relative spreads of the points VALUE-SEED-POINTS offers around the run's parameter
values: the values themselves first, then one point at each spread.")

(defparameter *value-seed-repeats* 2
  "How many points VALUE-SEED-POINTS draws at each spread but the first.")

(defun seed-value (value spread random-state)
  "VALUE (a real) as a double float moved by a random relative SPREAD (keeping its sign;
a zero moved by SPREAD itself), or NIL when it has no double float."
  (let ((x (handler-case (coerce value 'double-float)
             ((or arithmetic-error type-error) () nil))))
    (when x
      (cond ((zerop spread) x)
            ((zerop x) (* spread (- (random 2d0 random-state) 1d0)))
            (t (* x (exp (* spread (- (random 2d0 random-state) 1d0)))))))))

(defun value-seed-points (subjects intervals random-state)
  "Points over SUBJECTS (alists subject -> double float) at and around the current run's
parameter values (see *VALUE-SEED-SPREADS*); a subject without a value takes a random
value within its interval of INTERVALS (see RANDOM-VALUE). NIL when the run has no
values or none of SUBJECTS has one."
  (let ((values *parameter-values*))
    (when (some (lambda (subject) (assoc subject values :test #'equal)) subjects)
      (loop for spread in *value-seed-spreads*
            nconc (loop repeat (if (zerop spread) 1 *value-seed-repeats*)
                        for point = (mapcar
                                     (lambda (subject)
                                       (let ((entry (assoc subject values :test #'equal)))
                                         (cons subject
                                               (or (and entry (seed-value (cdr entry) spread random-state))
                                                   (random-value (cdr (assoc subject intervals :test #'equal))
                                                                 random-state)))))
                                     subjects)
                        collect point)))))
