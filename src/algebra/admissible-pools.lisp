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
;;;; its first *EMPTY-POOL-DRAWS* stops there, and one with an equation, which no point
;;;; surely satisfies, at once) and kept; each relation's own subjects, which the facts do
;;;; not constrain, are drawn beside them. Past *PLAIN-DRAWS* independent draws, a point
;;;; that misses is drawn again subject by subject within the bounds that the facts
;;;; linear in that subject give at the others' values (a block pushed low, on the side of
;;;; its criterion where it tips, lies where k^2 > 26 w^2 and mu and P in narrow bands:
;;;; 2000 independent draws found no point there). Only the cost changes: a point is
;;;; offered only when every fact surely holds at it, as before.

(in-package #:ames.algebra)

(defparameter *pool-draws* 2000
  "How many random points ADMISSIBLE-POOL draws at most for one set of facts.")

(defparameter *empty-pool-draws* 300
  "After how many draws without an admissible point ADMISSIBLE-POOL gives up.")

(defparameter *pool-limit* 4000
  "How many sets of facts *ADMISSIBLE-POOLS* holds before it is emptied.")

(defvar *admissible-pools* (make-hash-table :test #'equal)
  "(*WITNESS-ADMISSIBLE-POINTS* . the flattened facts) -> their admissible points (see
ADMISSIBLE-POOL). The facts themselves are the key, so a pool is never used for others.")

(defun facts-subjects (facts)
  "The subjects of FACTS, without repetitions (as DISTINCT-SUBJECTS keeps them)."
  (distinct-subjects (mapcan #'expression-variables facts)))

(defparameter *plain-draws* 200
  "How many independent draws DRAW-ADMISSIBLE-POINTS makes before it narrows its draws.")

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
    ;; an equation holds surely at no point (CONDITION-TRUTH): no point is admissible
    (when (some (lambda (fact) (eq (expression-operator fact) '=)) facts)
      (return-from draw-admissible-points '()))
    (flet ((admissible-p (point)
             (every (lambda (fact) (eq (condition-truth fact point) :true)) facts)))
      (loop for draw from 1 to *pool-draws*
            while (< (length points) *witness-admissible-points*)
            until (and (null points) (> draw *empty-pool-draws*))
            do (let ((point (mapcar (lambda (subject interval)
                                      (cons subject (random-value interval random-state)))
                                    subjects intervals)))
                 ;; past the plain draws, each subject is drawn again within what the
                 ;; facts linear in it leave (a thin region: a few plain draws land in it)
                 (when (and (> draw *plain-draws*) (not (admissible-p point)))
                   (setf point (narrowed-point facts subjects intervals point random-state)))
                 (when (admissible-p point)
                   (push (mapcar (lambda (subject) (assoc subject point :test #'equal)) subjects)
                         points)))))
    (nreverse points)))

;;; Draws narrowed by the facts linear in one subject

(defun value-with (expression subject value point)
  "EXPRESSION's value (the centre of its ball) at POINT with SUBJECT set to VALUE, or NIL."
  (let ((ball (expression-ball expression (acons subject value point))))
    (and ball (ball-center ball))))

(defun linear-bound (fact subject point)
  "When the inequality FACT is seen to be linear in SUBJECT at POINT (its sides'
difference takes values on a line at SUBJECT = 0, 1 and 2), the side of the root it
holds on: (values :LOWER ROOT) or (values :UPPER ROOT); else NIL. A guess that only steers
the draws: every point is checked against the facts before it is offered."
  (let* ((difference (list '- (relation-lhs fact) (relation-rhs fact)))
         (f0 (value-with difference subject 0d0 point))
         (f1 (and f0 (value-with difference subject 1d0 point)))
         (f2 (and f1 (value-with difference subject 2d0 point))))
    (when (and f2 (/= f1 f0)
               (<= (abs (+ f2 (* -2 f1) f0)) (* 1d-9 (+ (abs f0) (abs f1) (abs f2)))))
      (let ((root (/ f0 (- f0 f1)))
            (above (eq (> (- f1 f0) 0) (and (member (expression-operator fact) '(> >=)) t))))
        (values (if above :lower :upper) root)))))

(defun narrowed-value (fact-list subject interval point random-state)
  "A random value of SUBJECT within INTERVAL ((LOWER . UPPER) of BOUNDs) narrowed by the
inequalities of FACT-LIST linear in it at POINT (LINEAR-BOUND), or NIL when they leave
nothing."
  (let ((lower (and (car interval) (bound-value (car interval))))
        (upper (and (cdr interval) (bound-value (cdr interval)))))
    (dolist (fact fact-list)
      (when (and (member (expression-operator fact) '(< > <= >=))
                 (member subject (expression-variables fact) :test #'equal))
        (multiple-value-bind (side root) (linear-bound fact subject point)
          (case side
            (:lower (setf lower (if lower (max lower root) root)))
            (:upper (setf upper (if upper (min upper root) root)))))))
    (unless (and lower upper (>= lower upper))
      (random-value (cons (and lower (make-bound lower t)) (and upper (make-bound upper t)))
                    random-state))))

(defparameter *narrowing-sweeps* 3
  "How many times NARROWED-POINT draws each subject again.")

(defun narrowed-point (facts subjects intervals point random-state)
  "POINT with each subject in turn drawn again within the bounds the facts linear in it
give at the others' values (NARROWED-VALUE), where they leave room, *NARROWING-SWEEPS*
times over."
  (loop repeat *narrowing-sweeps*
        do (loop for subject in subjects
                 for interval in intervals
                 for value = (narrowed-value facts subject interval point random-state)
                 when value
                   do (setf point (acons subject value
                                         (remove subject point :key #'car :test #'equal)))))
  point)

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
