;;;; src/algebra/intervals.lisp -- interval arithmetic over the prefix algebra: bounds on an
;;;; expression's values when its names range over intervals, and the truth of a relation
;;;; between numbers (no names at all) that such bounds settle.
;;;;
;;;; Every operation (+, -, *, /, integer powers, square roots, sin and cos over an
;;;; interval, with the extrema inside it) gives an interval of doubles widened by a
;;;; relative *INTERVAL-WIDENING*, which covers the rounding of double precision: the
;;;; true values lie inside. A form with no interval here (an unknown function, a
;;;; division by an interval holding 0) gives NIL: no bound, nothing decided. A relation
;;;; between numbers whose difference's interval excludes 0 is decided (DECIDE's first
;;;; strategy for such relations: angles and times built of nested sin, cos, atan and
;;;; roots of numbers, which Maxima's sign() does not settle).

(in-package #:ames.algebra)

(defparameter *interval-widening* 1d-12
  "The relative widening of every interval result, covering double-precision rounding.")

(defun widened (low high)
  "The interval (LOW . HIGH) widened by *INTERVAL-WIDENING* (relative, and absolute near 0)."
  (let ((slack (* *interval-widening* (max 1d-300 (abs low) (abs high)))))
    (cons (- low slack) (+ high slack))))

(defun interval-product (a b)
  "The product of the intervals A and B."
  (let ((products (list (* (car a) (car b)) (* (car a) (cdr b)) (* (cdr a) (car b)) (* (cdr a) (cdr b)))))
    (widened (reduce #'min products) (reduce #'max products))))

(defun interval-power (a n)
  "The interval A to the non-negative integer power N."
  (let ((p1 (expt (car a) n)) (p2 (expt (cdr a) n)))
    (if (and (evenp n) (<= (car a) 0d0 (cdr a)))
        (widened 0d0 (max p1 p2))
        (widened (min p1 p2) (max p1 p2)))))

(defun interval-trigonometric (head a)
  "sin or cos (HEAD) over the interval A: the values at its ends, and -1 or 1 where an
extremum of the function lies within it."
  (let* ((low (car a)) (high (cdr a))
         (f (if (eq head 'sin) #'sin #'cos))
         (values (list (funcall f low) (funcall f high)))
         ;; extrema of sin at pi/2 + k pi, of cos at k pi
         (offset (if (eq head 'sin) (/ pi 2) 0d0)))
    (if (> (- high low) (* 2 pi))
        (cons -1d0 1d0)
        (progn
          (loop for k from (ceiling (/ (- low offset) pi)) to (floor (/ (- high offset) pi))
                do (push (if (evenp k) 1d0 -1d0) values))
          (widened (max -1d0 (reduce #'min values)) (min 1d0 (reduce #'max values)))))))

(defun interval-value (expression bindings)
  "The interval (LOW . HIGH) of doubles holding every value of EXPRESSION (the prefix
algebra) when each name or term bound in the alist BINDINGS (to an interval) ranges over
its interval; NIL when some part has no interval here (an unbound name, a division by an
interval holding 0, a root of one reaching below 0, an unknown function)."
  (labels ((value (x)
             (cond ((realp x) (let ((d (coerce x 'double-float))) (widened d d)))
                   ((eq x 'pi) (widened pi pi))
                   ((or (symbolp x) (quantity-term-p x))
                    (cdr (assoc x bindings :test #'equal)))
                   ((not (consp x)) nil)
                   (t (let ((parts (mapcar #'value (rest x))))
                        (when (every #'identity parts)
                          (operation (first x) parts (rest x)))))))
           (operation (head parts operands)
             (case head
               (+ (widened (reduce #'+ parts :key #'car) (reduce #'+ parts :key #'cdr)))
               (- (if (rest parts)
                      (widened (- (car (first parts)) (reduce #'+ (rest parts) :key #'cdr))
                               (- (cdr (first parts)) (reduce #'+ (rest parts) :key #'car)))
                      (widened (- (cdr (first parts))) (- (car (first parts))))))
               (* (reduce #'interval-product parts))
               (/ (let ((divisor (second parts)))
                    (when (or (> (car divisor) 0d0) (< (cdr divisor) 0d0))
                      (interval-product (first parts)
                                        (widened (min (/ (car divisor)) (/ (cdr divisor)))
                                                 (max (/ (car divisor)) (/ (cdr divisor))))))))
               (expt (let ((n (second operands)))
                       (cond ((and (integerp n) (>= n 0)) (interval-power (first parts) n))
                             ((and (integerp n) (< n 0))
                              (operation '/ (list (widened 1d0 1d0) (interval-power (first parts) (- n)))
                                         nil))
                             ((eql n 1/2) (operation 'sqrt (list (first parts)) nil)))))
               (sqrt (let ((a (first parts)))
                       (when (>= (car a) 0d0)
                         (widened (sqrt (car a)) (sqrt (cdr a))))))
               ((sin cos) (interval-trigonometric head (first parts)))
               (atan (let ((a (first parts)))
                       (when (null (rest parts))
                         (widened (atan (car a)) (atan (cdr a))))))
               (t nil))))
    (handler-case (value expression)
      (arithmetic-error () nil))))

(defun positive-over-interval-p (function variable from to bindings &key (pieces 64) (depth 16))
  "True when FUNCTION of VARIABLE is proven positive for every VARIABLE between the
doubles FROM and TO (either order) by interval arithmetic (see the file header), the
parameters taking their values from BINDINGS (an alist name -> real)."
  (let ((fixed (mapcar (lambda (entry)
                         (let ((d (coerce (cdr entry) 'double-float))) (cons (car entry) (widened d d))))
                       bindings))
        (low (min from to)) (high (max from to)))
    (labels ((positive-on (a b level)
               (let ((range (interval-value function (acons variable (widened a b) fixed))))
                 (cond ((and range (> (car range) 0d0)) t)
                       ((>= level depth) nil)
                       (t (let ((middle (/ (+ a b) 2)))
                            (and (positive-on a middle (1+ level))
                                 (positive-on middle b (1+ level)))))))))
      (let ((step (/ (- high low) pieces)))
        (loop for i below pieces
              always (positive-on (+ low (* i step)) (if (= i (1- pieces)) high (+ low (* (1+ i) step))) 0))))))


(defun constant-relation-by-intervals (relation)
  "The truth of RELATION, (OP LHS RHS) with OP among < <= > >= = /= over numbers and PI
alone, when the interval of LHS - RHS excludes 0 (in doubles, else over exact rationals:
EXACT-CONSTANT-SIGN, for terms that cancel beyond a double's digits): :TRUE or :FALSE;
NIL otherwise (a name in it, an interval holding 0, a form without an interval, and two
rational sides, which Maxima compares exactly as it always did)."
  (when (and (consp relation) (member (first relation) '(< <= > >= = /=))
             (= (length relation) 3)
             (not (and (rationalp (second relation)) (rationalp (third relation))))
             (null (expression-variables relation)))
    (let* ((difference `(- ,(second relation) ,(third relation)))
           (d (interval-value difference '())))
      (let ((sign (or (and d (cond ((> (car d) 0d0) :positive) ((< (cdr d) 0d0) :negative)))
                      ;; terms cancelling beyond a double's digits: over exact rationals
                      (find (exact-constant-sign difference) '(:positive :negative)))))
        (when sign
          (if (ecase (first relation)
                ((> >=) (eq sign :positive))
                ((< <=) (eq sign :negative))
                (= nil)
                (/= t))
              :true
              :false))))))
