;;;; src/algebra/admissible-pools.lisp -- the admissible points of a set of facts, drawn once.
;;;;
;;;; The numeric witnesses (witnesses.lisp) show at once that a relation is decided by no
;;;; strategy, when it holds at one admissible point and fails at another. Drawn anew for
;;;; every relation, 80 random points found few admissible ones where the facts in force
;;;; leave a thin region: the branches of a nested fork (a pushed block that tips, under
;;;; its tipping criterion and both friction limits of its edge: 11 facts) kept 1 to 13
;;;; of 80 draws, found no witness for relations that 2000 draws show undecided, and
;;;; every strategy then failed in turn (1 to 23 s each, 42 such questions: two thirds of
;;;; the symbolic run's time). The points that satisfy a set of facts do not depend on
;;;; the relation asked under them, so they are drawn once per set of facts (until
;;;; *WITNESS-ADMISSIBLE-POINTS* are found, up to *POOL-DRAWS* draws; a set with none in
;;;; its first *EMPTY-POOL-DRAWS*, such as one with an equation, which no point surely
;;;; satisfies, stops there) and kept; each relation's own subjects, which the facts do
;;;; not constrain, are drawn beside them. Only the cost changes: a point is offered only
;;;; when every fact surely holds at it, as before.

(in-package #:ames.algebra)

(defparameter *pool-draws* 2000
  "How many random points ADMISSIBLE-POOL draws at most for one set of facts.")

(defparameter *empty-pool-draws* 200
  "After how many draws without an admissible point ADMISSIBLE-POOL gives up.")

(defparameter *pool-limit* 4000
  "How many sets of facts *ADMISSIBLE-POOLS* holds before it is emptied.")

(defvar *admissible-pools* (make-hash-table :test #'equal)
  "(*WITNESS-ADMISSIBLE-POINTS* . the flattened facts) -> their admissible points (see
ADMISSIBLE-POOL). The facts themselves are the key, so a pool is never used for others.")

(defun facts-subjects (facts)
  "The subjects of FACTS, without repetitions (as DISTINCT-SUBJECTS keeps them)."
  (distinct-subjects (mapcan #'expression-variables facts)))

(defun draw-admissible-points (facts)
  "Up to *WITNESS-ADMISSIBLE-POINTS* points (alists subject -> double float over FACTS'
subjects) that surely satisfy every one of FACTS (flattened), drawn from a fixed seed
within each subject's numeric bounds, in at most *POOL-DRAWS* draws (*EMPTY-POOL-DRAWS*
when none of those is admissible)."
  (let* ((subjects (facts-subjects facts))
         (intervals (let ((table (make-hash-table :test #'equal)))
                      (dolist (entry (reverse (subject-intervals facts)))
                        (setf (gethash (car entry) table) (cdr entry)))
                      (mapcar (lambda (subject) (values (gethash subject table))) subjects)))
         (random-state (sb-ext:seed-random-state 1994))
         (points '()))
    (loop for draw from 1 to *pool-draws*
          while (< (length points) *witness-admissible-points*)
          until (and (null points) (> draw *empty-pool-draws*))
          do (let ((point (mapcar (lambda (subject interval)
                                    (cons subject (random-value interval random-state)))
                                  subjects intervals)))
               (when (every (lambda (fact) (eq (condition-truth fact point) :true)) facts)
                 (push point points))))
    (nreverse points)))

(defun admissible-pool (facts)
  "The admissible points of the flattened FACTS (DRAW-ADMISSIBLE-POINTS), drawn on the
first call for these facts (and this *WITNESS-ADMISSIBLE-POINTS*) and kept."
  (let ((key (cons *witness-admissible-points* facts)))
    (multiple-value-bind (pool found) (gethash key *admissible-pools*)
      (if found
          pool
          (progn
            (when (>= (hash-table-count *admissible-pools*) *pool-limit*)
              (clrhash *admissible-pools*))
            (setf (gethash key *admissible-pools*) (draw-admissible-points facts)))))))

(defun pooled-admissible-points (facts relation function)
  "Call FUNCTION on each point of FACTS' pool (ADMISSIBLE-POOL), completed with random
values for RELATION's subjects that FACTS do not mention, until it returns true."
  (let* ((pool (admissible-pool facts))
         (own (and pool (remove-if (lambda (subject) (assoc subject (first pool) :test #'equal))
                                   (distinct-subjects (expression-variables relation)))))
         (random-state (sb-ext:seed-random-state 1994)))
    (dolist (point pool)
      (when (funcall function
                     (append (mapcar (lambda (subject) (cons subject (random-value nil random-state)))
                                     own)
                             point))
        (return)))))
