;;;; src/simulator/earliest.lisp -- which termination candidates fire first, proven, and the
;;;; fact that is missing when that cannot be proven.

(in-package #:ames.simulator)

(defun factors-of (expression)
  "The factors of a product or quotient EXPRESSION, each as (FACTOR . POWER-SIGN),
POWER-SIGN -1 for a denominator."
  (cond ((and (consp expression) (eq (first expression) '*))
         (mapcan #'factors-of (rest expression)))
        ((and (consp expression) (eq (first expression) '/) (rest expression))
         (append (factors-of (second expression))
                 (mapcar (lambda (f) (cons (car f) (- (cdr f))))
                         (mapcan #'factors-of (cddr expression)))))
        ((and (consp expression) (eq (first expression) '-) (null (cddr expression)))
         (cons (cons -1 1) (factors-of (second expression))))
        (t (list (cons expression 1)))))

(defun core-fact (run fact)
  "FACT, a relation (> X 0), (< X 0) ... with X factored and every factor whose sign the
assumptions decide divided out: (> (* (- l1 l2) (- f k)) 0) with l1 > l2 becomes
(> (- f k) 0); a square root left alone stands for its radicand. FACT itself when
nothing can be divided out or it is no such relation."
  (if (not (and (consp fact) (member (first fact) '(< > <= >=))
                (notany #'keywordp (alexandria:flatten fact))))
      fact
      (let* ((x (tidy run `(- ,(relation-lhs fact) ,(relation-rhs fact)) :full))
             (sign 1) (kept '()))
        (dolist (factor (factors-of x))
          (let ((f (car factor)))
            (cond ((and (realp f) (plusp f)))
                  ((and (realp f) (minusp f)) (setf sign (- sign)))
                  ((holds run `(> ,f 0)))
                  ((holds run `(< ,f 0)) (setf sign (- sign)))
                  (t (push f kept)))))
        (if (or (null kept) (rest kept))
            fact
            (let ((operator (if (= sign 1)
                                (first fact)
                                (ecase (first fact) (> '<) (< '>) (>= '<=) (<= '>=))))
                  (kept (first kept)))
              (if (square-root-argument kept)
                  ;; a real square root has the sign of its radicand (zero with it); a
                  ;; negative radicand is no real time at all: the fact is about it
                  (core-fact run (list operator (square-root-argument kept) 0))
                  (list operator kept 0)))))))

(defun square-root-argument (x)
  "Y when X is sqrt(Y) or Y^(1/2), else NIL."
  (and (consp x)
       (cond ((and (eq (first x) 'sqrt) (= (length x) 2)) (second x))
             ((and (eq (first x) 'expt) (eql (third x) 1/2)) (second x)))))

(defun simplest-missing-fact (run facts)
  "Of FACTS (the relations undecided for several candidates), the one whose core form
(see CORE-FACT) is smallest: a sign condition on the parameters alone (the push above
or below a threshold) before a comparison of two times that it would settle."
  (let ((best nil) (best-size nil))
    (dolist (fact facts best)
      (let* ((core (core-fact run fact))
             (size (if (and (consp core) (member (first core) '(< > <= >=))
                            (free-of-p 'tau core)
                            (notany #'keywordp (alexandria:flatten core)))
                       (count-atoms core)
                       most-positive-fixnum)))
        (when (or (null best) (< size best-size))
          (setf best fact best-size size))))))

(defun count-atoms (x)
  "The number of atoms in the tree X."
  (if (atom x) 1 (+ (count-atoms (car x)) (count-atoms (cdr x)))))

(defun closed-form-time-p (time)
  "True when TIME is an expression (not a (:NO-CLOSED-FORM ...) description)."
  (not (and (consp time) (keywordp (first time)))))

(defun numeric-time (run time)
  "TIME as a number under the run's parameter values, or NIL."
  (let ((values (run-values run)))
    (when (run-numbers-known-p run)
      (if (closed-form-time-p time)
          (numeric-or-nil (run-bridge run) time values)
          (numeric-travel-time (run-bridge run) (getf (rest time) :speed-squared)
                               (getf (rest time) :from-arc-length)
                               (getf (rest time) :to-arc-length) values)))))

(defun compare-times (run a b)
  "Whether the time A comes no later than B: :TRUE, :FALSE or (values :UNKNOWN FACT).
Closed forms are compared under the assumptions; where that fails and the run has
parameter values, the numbers decide (and the fact is noted as assumed from them).
Where the values decide first (AMES.ALGEBRA:VALUES-FIRST-P), the closed forms get only a
cheap proof before the numbers, and the full one only when the numbers are too close."
  (let* ((closed (and (closed-form-time-p a) (closed-form-time-p b)))
         (fact (if closed `(<= ,a ,b) (list :no-later a b)))
         (cheap (and closed (ames.algebra:values-first-p) (run-numbers-known-p run)))
         (verdict (cond ((not closed) :unknown)
                        (cheap (ames.algebra:decide-first-cheaply (run-bridge run) fact))
                        (t (decide run fact)))))
    (if (not (eq verdict :unknown))
        verdict
        (let ((na (numeric-time run a)) (nb (numeric-time run b)))
          (cond ((and na nb (> (abs (- na nb)) (* 1d-9 (max 1d0 (abs na)))))
                 (push (list :fact (if (<= na nb) fact (list :not fact)) :from :values)
                       (run-assumed run))
                 (if (<= na nb) :true :false))
                ((and cheap (not (eq (setf verdict (decide run fact)) :unknown)))
                 verdict)
                (t (values :unknown fact)))))))

(defun same-time-p (run a b)
  "True when the times A and B are proven equal."
  (and (closed-form-time-p a) (closed-form-time-p b)
       (or (equal a b) (holds run `(= ,a ,b))
           (ames.maxima:equivalent-p (run-bridge run) a b))))

(defun ambiguity (run fact candidates &optional unknown)
  "Signal AMBIGUOUS-TRANSITION for the missing FACT (in core form) between CANDIDATES."
  (let ((fact (core-fact run fact)))
    (error 'ambiguous-transition
           :datum fact :missing-fact fact
           :candidates (append (mapcar (lambda (c) (list (candidate-event c) (candidate-time c)))
                                       candidates)
                               (mapcar (lambda (u) (list (second u) :undecided (first u))) unknown))
           :detail "transition: which event ends the state")))

(defun nearest-on-path (run candidates)
  "Of CANDIDATES, all on one curved motion, those at the nearest arc length."
  (let* ((group (candidate-group (first candidates)))
         (first (find-if (lambda (c)
                           (every (lambda (o)
                                    (or (eq o c)
                                        (not (eq (nearer-p run group (candidate-at-arc o)
                                                           (candidate-at-arc c))
                                                 :true))))
                                  candidates))
                         candidates)))
    (unless first
      (ambiguity run `(< ,(candidate-at-arc (first candidates)) ,(candidate-at-arc (second candidates)))
                 candidates))
    (dolist (o candidates)
      (unless (or (eq o first) (eq (nearer-p run group (candidate-at-arc first) (candidate-at-arc o)) :true)
                  (holds run `(= ,(candidate-at-arc first) ,(candidate-at-arc o))))
        (ambiguity run `(< ,(candidate-at-arc first) ,(candidate-at-arc o)) candidates)))
    (remove-if-not (lambda (o) (or (eq o first) (holds run `(= ,(candidate-at-arc first)
                                                                 ,(candidate-at-arc o)))))
                   candidates)))

(defun same-path-p (a b)
  "True when the candidates A and B are both on one curved motion (already ordered by
arc length)."
  (and (candidate-group a) (eq (candidate-group a) (candidate-group b))))

(defun preceded-p (run not-before candidates)
  "True when one of CANDIDATES is proven to fire strictly before the time NOT-BEFORE."
  (and not-before (closed-form-time-p not-before)
       (some (lambda (c)
               (and (closed-form-time-p (candidate-time c))
                    (eq (compare-times run not-before (candidate-time c)) :false)))
             candidates)))

(defun earliest-candidates (run candidates unknown)
  "The CANDIDATES that fire first, all at one time, proven earliest (NIL when there is
none: the state lasts forever). UNKNOWN lists conditions whose firing is undecided, as
(FACT EVENT [NOT-BEFORE]); one that a candidate proven to fire strictly before its
NOT-BEFORE precedes cannot end the state and is left out. Signals AMBIGUOUS-TRANSITION
(restart STOP-SIMULATION) when an undecided condition remains or the order is not
decided."
  (setf unknown (remove-if (lambda (u) (preceded-p run (third u) candidates)) unknown))
  (when unknown
    (ambiguity run (simplest-missing-fact run (mapcar #'first unknown)) candidates unknown))
  (when candidates
    ;; within one curved motion, by arc length; then across groups, by time
    (let* ((path-groups (remove-duplicates (remove nil (mapcar #'candidate-group candidates))))
           (pool (append (remove-if #'candidate-group candidates)
                         (loop for group in path-groups
                               append (nearest-on-path
                                       run (remove group candidates :key #'candidate-group
                                                                    :test-not #'eq)))))
           (first nil))
      (dolist (c pool)
        (when (every (lambda (o)
                       (or (eq o c) (same-path-p o c)
                           (eq (compare-times run (candidate-time c) (candidate-time o)) :true)))
                     pool)
          (setf first c)
          (return)))
      (unless first
        (loop for c in pool
              do (loop for o in pool
                       unless (or (eq o c) (same-path-p o c))
                         do (multiple-value-bind (verdict fact)
                                (compare-times run (candidate-time c) (candidate-time o))
                              (when (eq verdict :unknown)
                                (ambiguity run fact pool)))))
        (ambiguity run (list :order (mapcar #'candidate-event pool)) pool))
      (remove-if-not (lambda (o)
                       (or (eq o first)
                           (same-path-p o first)
                           (same-time-p run (candidate-time o) (candidate-time first))))
                     pool))))
