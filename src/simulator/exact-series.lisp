;;;; src/simulator/exact-series.lisp -- local series at a start whose numbers are all exact
;;;; rationals, by power-series arithmetic instead of repeated symbolic differentiation.
;;;;
;;;; SERIES-COEFFICIENTS (model.lisp) differentiates an expression along the state's ODEs
;;;; by the chain rule, symbolically, and evaluates each derivative at the start. The
;;;; unsimplified derivatives grow by a factor at each step: a block flush with a ledge's
;;;; edge, its rates rational functions of the sine and cosine of its angle, needed a
;;;; fourth coefficient of a normal force whose first three vanish, and its derivative grew
;;;; from 1,500 to 1,800,000 conses in three steps. Where the start is all exact numbers
;;;; (every parameter in the expression and the rates a number, every state term's start
;;;; value a rational, every angle's sine and cosine exact: angle 0), the same Taylor
;;;; coefficients come from truncated power series over the rationals: the state's series
;;;; by Picard's iteration, X = X0 + integral of RATES(X) (each round exact to one more
;;;; order), then the expression evaluated on them with the series' +, -, *, /, integer
;;;; powers, square roots (of a rational square), sine and cosine (at 0). Anything else (a
;;;; symbol, a float, a division by a series starting at 0, an operator not listed) gives
;;;; NIL, and the symbolic route is taken as before. The coefficients are the same
;;;; rationals Maxima would give: exact arithmetic, no round-off.

(in-package #:ames.simulator)

(define-condition not-exact-series (error) ()
  (:documentation "An expression this file's exact power series cannot evaluate."))

(defun series-give-up ()
  "Leave the exact series for the symbolic route."
  (error 'not-exact-series))

(defun constant-series (c n)
  "The series of the rational C to order N."
  (let ((s (make-array (1+ n) :initial-element 0)))
    (setf (aref s 0) c)
    s))

(defun series+ (a b)
  (map 'vector #'+ a b))

(defun series- (a b)
  (map 'vector #'- a b))

(defun series* (a b)
  "The product of the series A and B, truncated to their order."
  (let* ((n (1- (length a))) (c (make-array (1+ n) :initial-element 0)))
    (dotimes (k (1+ n) c)
      (setf (aref c k) (loop for i from 0 to k sum (* (aref a i) (aref b (- k i))))))))

(defun series/ (a b)
  "The quotient of the series A and B (B starting at a non-zero number)."
  (let* ((n (1- (length a))) (c (make-array (1+ n) :initial-element 0)) (b0 (aref b 0)))
    (when (zerop b0) (series-give-up))
    (dotimes (k (1+ n) c)
      (setf (aref c k) (/ (- (aref a k) (loop for i from 1 to k sum (* (aref b i) (aref c (- k i)))))
                          b0)))))

(defun series-expt (a power)
  "The series A to the integer POWER."
  (let ((n (1- (length a))))
    (cond ((minusp power) (series/ (constant-series 1 n) (series-expt a (- power))))
          (t (let ((result (constant-series 1 n)))
               (dotimes (i power result) (setf result (series* result a))))))))

(defun exact-rational-sqrt (x)
  "The rational square root of the rational X >= 0, or NIL when it is not one."
  (when (and (rationalp x) (>= x 0))
    (let ((p (isqrt (numerator x))) (q (isqrt (denominator x))))
      (and (= (* p p) (numerator x)) (= (* q q) (denominator x)) (/ p q)))))

(defun series-sqrt (a)
  "The square root of the series A (A0 a positive rational square)."
  (let* ((n (1- (length a))) (c (make-array (1+ n) :initial-element 0))
         (c0 (exact-rational-sqrt (aref a 0))))
    (unless (and c0 (plusp c0)) (series-give-up))
    (setf (aref c 0) c0)
    (loop for k from 1 to n
          do (setf (aref c k) (/ (- (aref a k) (loop for i from 1 below k sum (* (aref c i) (aref c (- k i)))))
                                 (* 2 c0))))
    c))

(defun series-sine-cosine (a)
  "The sine and cosine of the series A (A0 = 0): two series, by s' = c a', c' = -s a'."
  (unless (eql 0 (aref a 0)) (series-give-up))
  (let* ((n (1- (length a)))
         (s (make-array (1+ n) :initial-element 0)) (c (make-array (1+ n) :initial-element 0)))
    (setf (aref c 0) 1)
    (loop for k from 1 to n
          do (setf (aref s k) (/ (loop for j from 1 to k sum (* j (aref a j) (aref c (- k j)))) k)
                   (aref c k) (- (/ (loop for j from 1 to k sum (* j (aref a j) (aref s (- k j)))) k))))
    (values s c)))

(defun evaluate-series (expression bindings n)
  "The series of EXPRESSION to order N, its state terms' series from BINDINGS (a hash
table, EQUAL), TAU the series of the time. Signals NOT-EXACT-SERIES."
  (labels ((walk (x)
             (cond ((rationalp x) (constant-series x n))
                   ((eq x 'tau) (let ((s (constant-series 0 n))) (when (plusp n) (setf (aref s 1) 1)) s))
                   ((quantity-term-p x) (or (gethash x bindings) (series-give-up)))
                   ((atom x) (series-give-up))
                   (t (let ((args (rest x)))
                        (case (first x)
                          (+ (reduce #'series+ (mapcar #'walk args) :initial-value (constant-series 0 n)))
                          (- (if (rest args)
                                 (reduce #'series- (mapcar #'walk (rest args)) :initial-value (walk (first args)))
                                 (series- (constant-series 0 n) (walk (first args)))))
                          (* (reduce #'series* (mapcar #'walk args) :initial-value (constant-series 1 n)))
                          (/ (if (rest args)
                                 (reduce #'series/ (mapcar #'walk (rest args)) :initial-value (walk (first args)))
                                 (series/ (constant-series 1 n) (walk (first args)))))
                          (expt (let ((power (second args)))
                                  (cond ((integerp power) (series-expt (walk (first args)) power))
                                        ((eql power 1/2) (series-sqrt (walk (first args))))
                                        ((eql power -1/2) (series/ (constant-series 1 n)
                                                                   (series-sqrt (walk (first args)))))
                                        (t (series-give-up)))))
                          (sqrt (series-sqrt (walk (first args))))
                          (sin (nth-value 0 (series-sine-cosine (walk (first args)))))
                          (cos (nth-value 1 (series-sine-cosine (walk (first args)))))
                          (t (series-give-up))))))))
    (walk expression)))

(defun exact-state-series (solved)
  "The series to order *SERIES-ORDER* of SOLVED's state terms at the start (Picard's
iteration, see the file header), memoized: a hash table term -> series, or NIL when the
start is not all exact."
  (multiple-value-bind (memo found) (gethash '(:exact-state-series) (solved-model-series solved))
    (if found
        memo
        (setf (gethash '(:exact-state-series) (solved-model-series solved))
              (handler-case (picard-series solved *series-order*)
                (not-exact-series () nil))))))

(defun picard-series (solved n)
  "EXACT-STATE-SERIES's work; signals NOT-EXACT-SERIES."
  (let ((rates (solved-model-rates solved))
        (table (make-hash-table :test #'equal)))
    (loop for (term . value) in (solved-model-initial solved)
          do (unless (rationalp value) (series-give-up))
             (setf (gethash term table) (constant-series value n)))
    (unless rates (series-give-up))
    (dotimes (round n table)
      (let ((next (make-hash-table :test #'equal)))
        (loop for (term . rate) in rates
              for r = (evaluate-series rate table n)
              for x = (constant-series (aref (gethash term table) 0) n)
              do (loop for k from 0 below n do (setf (aref x (1+ k)) (/ (aref r k) (1+ k))))
                 (setf (gethash term next) x))
        (setf table next)))))

(defun exact-series-coefficients (solved expression count)
  "The first COUNT Taylor coefficients of EXPRESSION at the start of SOLVED's state by
exact power series (see the file header), or NIL where they do not apply."
  (let ((n (1- count)))
    (when (and (plusp count) (<= n *series-order*))
      (let ((states (exact-state-series solved)))
        (when states
          (handler-case (coerce (subseq (evaluate-series expression states *series-order*) 0 count) 'list)
            (not-exact-series () nil)))))))
