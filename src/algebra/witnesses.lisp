;;;; src/algebra/witnesses.lisp -- numeric witnesses: admissible points, and values as balls that enclose them.
;;;;
;;;; Used by DECIDE (deciding.lisp) to answer at once what no strategy can decide, by
;;;; HOLDS-P and REFUTED-P, and by the parameter values of a run (values.lisp).

(in-package #:ames.algebra)

;;; Numeric witnesses: quick proofs that a relation is not decided, or not true
;;;
;;; A relation that fails at an admissible point (one that satisfies every fact in force)
;;; has no sound proof; one that also holds at another admissible point is decided neither
;;; way, and so is an equation whose sides differ both ways at two admissible points
;;; joined by a segment of admissible points on which both sides are continuous (they are
;;; equal somewhere between, by the intermediate value theorem, and not everywhere). DECIDE
;;; then answers :UNKNOWN at once instead of trying every strategy (the costliest case:
;;; each strategy fails), and HOLDS-P answers NIL. Points are drawn at random (from a
;;; fixed seed) within the numeric bounds of each variable; values are computed in double
;;; floats as balls (center and radius) that enclose the exact value, rounding included,
;;; and a sign, of the relation or of a fact, counts only when the whole ball has it. A
;;; point where anything is undefined or not real (a square root or logarithm of a ball
;;; reaching zero or below, a division by a ball holding zero, a pole of tan, an
;;; overflow) is left out. Finding no witness proves nothing, and the strategies run as
;;; before: no answer changes, only its cost (given that every strategy is sound).

(defparameter *witness-admissible-points* 16
  "How many admissible points CALL-WITH-ADMISSIBLE-POINTS offers at most (drawn once per
set of facts: admissible-pools.lisp).")

(defstruct (ball (:constructor make-ball (center radius)))
  "A real number known to lie within RADIUS of CENTER (double floats)."
  center radius)

(defun rounded-ball (center radius)
  "The ball CENTER +/- RADIUS widened by the rounding of computing CENTER."
  (make-ball center (+ radius (* 8 double-float-epsilon (abs center)) least-positive-normalized-double-float)))

(defun ball-sign (ball)
  ":POSITIVE or :NEGATIVE when every number of BALL has that sign, else NIL."
  (cond ((> (- (ball-center ball) (ball-radius ball)) 0) :positive)
        ((< (+ (ball-center ball) (ball-radius ball)) 0) :negative)
        (t nil)))

(defun exact-zero-ball-p (ball)
  "True when BALL is exactly zero (radius zero): what the exact zeros give (the number 0,
sin 0, the angle of a point on the positive x axis, a product with an exact zero), with
no rounding."
  (and (zerop (ball-center ball)) (zerop (ball-radius ball))))

(defun ball+ (a b)
  (cond ((exact-zero-ball-p a) b)
        ((exact-zero-ball-p b) a)
        (t (rounded-ball (+ (ball-center a) (ball-center b)) (+ (ball-radius a) (ball-radius b))))))

(defun ball-negation (a)
  (make-ball (- (ball-center a)) (ball-radius a)))

(defun ball* (a b)
  (when (or (exact-zero-ball-p a) (exact-zero-ball-p b))
    (return-from ball* (make-ball 0d0 0d0)))
  (let ((x (ball-center a)) (rx (ball-radius a)) (y (ball-center b)) (ry (ball-radius b)))
    (rounded-ball (* x y) (+ (* (abs x) ry) (* (abs y) rx) (* rx ry)))))

(defun ball-reciprocal (a)
  "1/A, or NIL when A may hold zero."
  (let ((x (ball-center a)) (rx (ball-radius a)))
    (when (> (abs x) rx)
      (rounded-ball (/ 1 x) (/ rx (* (abs x) (- (abs x) rx)))))))

(defun ball-integer-power (a n)
  "A^N for an integer N (NIL when N <= 0 and A may hold zero: 0^0 is undefined too)."
  (cond ((and (zerop n) (<= (abs (ball-center a)) (ball-radius a))) nil)
        ((minusp n) (let ((power (ball-integer-power a (- n))))
                      (and power (ball-reciprocal power))))
        (t (let ((result (make-ball 1d0 0d0)))
             (dotimes (i n result) (setf result (ball* result a)))))))

(defun positive-ball-p (a)
  (> (- (ball-center a) (ball-radius a)) 0))

(defun ball-function (operator a)
  "OPERATOR (sqrt exp log sin cos tan asin acos atan abs) of the ball A, or NIL where it
is undefined or not real somewhere in A, and for the operators it does not know."
  (let ((x (ball-center a)) (rx (ball-radius a)))
    (case operator
      (abs (make-ball (abs x) rx))
      (sqrt (cond ((and (zerop x) (zerop rx)) (make-ball 0d0 0d0))
                  ((>= (- x rx) 0)
                   (rounded-ball (sqrt x) (- (sqrt x) (sqrt (max 0d0 (- x rx))))))))
      (exp (rounded-ball (exp x) (* (exp x) (- (exp rx) 1))))
      (log (when (positive-ball-p a)
             (rounded-ball (log x) (- (log x) (log (- x rx))))))
      (sin (if (exact-zero-ball-p a) (make-ball 0d0 0d0) (rounded-ball (sin x) (min rx 2d0))))
      (cos (rounded-ball (cos x) (min rx 2d0)))
      (tan (let ((c (cos x)))
             (when (> (abs c) (+ rx 1d-12))
               (rounded-ball (tan x) (/ rx (expt (- (abs c) rx) 2))))))
      ((asin acos) (when (< (+ (abs x) rx) 1)
                     (rounded-ball (if (eq operator 'asin) (asin x) (acos x))
                                   (/ rx (sqrt (- 1 (expt (+ (abs x) rx) 2)))))))
      (atan (rounded-ball (atan x) (min rx pi))))))

(defun ball-atan2 (y x)
  "The angle of (X, Y) in (-pi, pi], or NIL when the balls reach the origin or the
negative x axis, where it is not continuous; with Y exactly zero, exactly 0 for X
surely positive and pi for X surely negative (Maxima's atan2(0, x))."
  (let ((cy (ball-center y)) (ry (ball-radius y)) (cx (ball-center x)) (rx (ball-radius x)))
    (when (exact-zero-ball-p y)
      (return-from ball-atan2
        (cond ((> (- cx rx) 0) (make-ball 0d0 0d0))
              ((< (+ cx rx) 0) (rounded-ball pi 0d0)))))
    (let ((distance (- (sqrt (+ (* cx cx) (* cy cy))) rx ry)))
      (when (and (> distance 0) (or (> (- cx rx) 0) (> (abs cy) ry)))
        (rounded-ball (atan cy cx) (/ (+ rx ry) distance))))))

(defun expression-ball (expression point)
  "The ball enclosing the value of the arithmetic EXPRESSION at POINT (an alist subject ->
double float, or -> ball for a whole box of points), or NIL where it is undefined or not
real somewhere."
  (labels ((fail () (return-from expression-ball nil))
           (value (x)
             (cond ((eql x 0) (make-ball 0d0 0d0))
                   ((rationalp x) (let ((d (coerce x 'double-float)))
                                    (rounded-ball d 0d0)))
                   ((floatp x) (make-ball (coerce x 'double-float) 0d0))
                   ((constant-symbol-p x) (rounded-ball pi 0d0))
                   ((or (variable-symbol-p x) (quantity-term-p x))
                    (let ((entry (assoc x point :test #'equal)))
                      (cond ((null entry) (fail))
                            ((ball-p (cdr entry)) (cdr entry))
                            (t (make-ball (cdr entry) 0d0)))))
                   (t (let ((arguments (mapcar #'value (expression-arguments x))))
                        (or (case (expression-operator x)
                              (+ (reduce #'ball+ arguments))
                              (- (if (rest arguments)
                                     (reduce #'ball+ (mapcar #'ball-negation (rest arguments))
                                             :initial-value (first arguments))
                                     (ball-negation (first arguments))))
                              (* (reduce #'ball* arguments))
                              (/ (if (rest arguments)
                                     (reduce (lambda (a b) (let ((r (ball-reciprocal b)))
                                                             (if r (ball* a r) (fail))))
                                             (rest arguments) :initial-value (first arguments))
                                     (ball-reciprocal (first arguments))))
                              (expt (let ((exponent (third x)))
                                      (if (and (integerp exponent) (<= (abs exponent) 64))
                                          (ball-integer-power (first arguments) exponent)
                                          ;; a^b = exp(b log a), for a > 0 only
                                          (let ((logarithm (ball-function 'log (first arguments))))
                                            (and logarithm
                                                 (ball-function 'exp (ball* (second arguments) logarithm)))))))
                              (atan (if (rest arguments)
                                        (ball-atan2 (first arguments) (second arguments))
                                        (ball-function 'atan (first arguments))))
                              (t (ball-function (expression-operator x) (first arguments))))
                            (fail)))))))
    (handler-case (value expression)
      (arithmetic-error () nil))))

(defun condition-truth (condition point)
  "Whether the relation or logical CONDITION surely holds at POINT: :TRUE, :FALSE, or NIL
when that is not sure (= is never sure). An inequality whose sides' difference is
exactly zero there (EXACT-ZERO-BALL-P) is sure: X > 0 fails, X >= 0 holds."
  (case (expression-operator condition)
    (not (case (condition-truth (second condition) point) (:true :false) (:false :true)))
    (and (let ((truths (mapcar (lambda (c) (condition-truth c point)) (expression-arguments condition))))
           (cond ((member :false truths) :false) ((every (lambda (x) (eq x :true)) truths) :true))))
    (or (let ((truths (mapcar (lambda (c) (condition-truth c point)) (expression-arguments condition))))
          (cond ((member :true truths) :true) ((every (lambda (x) (eq x :false)) truths) :false))))
    (t (let* ((difference (expression-ball (list '- (relation-lhs condition) (relation-rhs condition)) point))
              (sign (and difference (if (exact-zero-ball-p difference)
                                        (and (member (expression-operator condition) '(> >= < <=))
                                             :zero)
                                        (ball-sign difference)))))
         (when sign
           (ecase (expression-operator condition)
             (> (if (eq sign :positive) :true :false))
             (>= (if (member sign '(:positive :zero)) :true :false))
             (< (if (eq sign :negative) :true :false))
             (<= (if (member sign '(:negative :zero)) :true :false))
             (/= :true)
             (= :false)))))))

(defun random-value (interval random-state)
  "A random double float within INTERVAL ((LOWER . UPPER) of BOUNDs, either NIL), away
from its ends; log-uniform in size over four decades where a side is open-ended."
  (let ((lower (and (car interval) (bound-value (car interval))))
        (upper (and (cdr interval) (bound-value (cdr interval))))
        (size (expt 10d0 (- (random 4d0 random-state) 2))))
    (cond ((and lower upper) (+ lower (* (- upper lower) (+ 0.02d0 (random 0.96d0 random-state)))))
          (lower (+ lower size))
          (upper (- upper size))
          ((zerop (random 2 random-state)) size)
          (t (- size)))))

(defun distinct-subjects (subjects)
  "SUBJECTS without repetitions, exactly as (REMOVE-DUPLICATES SUBJECTS :TEST #'EQUAL)
gives them (each kept at its last occurrence), in time linear in their number."
  (let ((left (make-hash-table :test #'equal)))
    (dolist (subject subjects) (incf (gethash subject left 0)))
    (loop for subject in subjects
          when (zerop (decf (gethash subject left)))
            collect subject)))

(defun call-with-admissible-points (bridge relation function &optional assuming)
  "Call FUNCTION on random points (alists subject -> double float, over the subjects of
RELATION and of the facts in force) that surely satisfy the facts in force and the
facts ASSUMING, until it returns true or the points run out (at most
*WITNESS-ADMISSIBLE-POINTS*, drawn once per set of facts: admissible-pools.lisp).
Returns the flattened facts."
  (let ((facts (flatten-facts (append (current-assumptions bridge) assuming))))
    (pooled-admissible-points facts relation function)
    facts))

(defun relation-witnesses (bridge relation)
  "Two points that surely satisfy the facts in force, RELATION (an inequality) surely
holding at the first and surely failing at the second, as (values HOLDS FAILS FACTS):
alists subject -> double float, and the facts (flattened). NIL when none are found."
  (let ((holds nil) (fails nil))
    (let ((facts (call-with-admissible-points
                  bridge relation
                  (lambda (point)
                    (case (condition-truth relation point)
                      (:true (unless holds (setf holds point)))
                      (:false (unless fails (setf fails point))))
                    (and holds fails)))))
      (and holds fails (values holds fails facts)))))

(defun relation-refuted-p (bridge relation &optional assuming)
  "True when the condition RELATION surely fails at a point that surely satisfies the
facts in force and the facts ASSUMING: then no sound strategy proves it under them."
  (let ((refuted nil))
    (call-with-admissible-points bridge relation
                                 (lambda (point)
                                   (setf refuted (eq (condition-truth relation point) :false)))
                                 assuming)
    refuted))

(defun witnessed-both-ways-p (bridge relation)
  "True when the inequality RELATION (< > <= >=) surely holds at one point that surely
satisfies the facts in force, and surely fails at another: then it is not decided."
  (and (relation-witnesses bridge relation) t))

(defparameter *segment-pieces* 256
  "How many pieces of a segment CONTINUOUS-AND-ADMISSIBLE-BETWEEN-P may evaluate at most.")

(defun segment-piece (from to start end)
  "The point whose subjects are balls enclosing the points FROM + s (TO - FROM) for s in
[START, END] (FROM and TO alists subject -> double float)."
  (mapcar (lambda (entry)
            (let* ((a (cdr entry))
                   (b (cdr (assoc (car entry) to :test #'equal)))
                   (middle (/ (+ start end) 2)))
              (cons (car entry) (rounded-ball (+ a (* (- b a) middle))
                                              (* (abs (- b a)) (/ (- end start) 2))))))
          from))

(defun continuous-and-admissible-between-p (expression facts from to)
  "True when, on the whole segment between the points FROM and TO, every fact of FACTS
surely holds and the arithmetic EXPRESSION is surely defined and real, hence
continuous: checked on pieces of the segment, as balls, halving a piece that is not
sure. With EXPRESSION positive at one end and negative at the other, it then vanishes
at an admissible point in between."
  (let ((pending (list (cons 0d0 1d0))) (budget *segment-pieces*))
    (loop while pending
          do (destructuring-bind (start . end) (pop pending)
               (when (minusp (decf budget)) (return-from continuous-and-admissible-between-p nil))
               (let ((piece (segment-piece from to start end)))
                 (unless (and (expression-ball expression piece)
                              (every (lambda (fact) (eq (condition-truth fact piece) :true)) facts))
                   (let ((middle (/ (+ start end) 2)))
                     (push (cons start middle) pending)
                     (push (cons middle end) pending))))))
    t))
