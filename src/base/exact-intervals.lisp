;;;; src/base/exact-intervals.lisp -- the sign of a constant built of rationals and roots,
;;;; proven by interval arithmetic over exact rationals.
;;;;
;;;; Maxima's sign() of a constant such as a + b sqrt(7) sqrt(1003) + c sqrt(R1) sqrt(R2)
;;;; evaluates it in floating point. After three bounces of a particle over terrain the
;;;; terms of such a constant are near 1e210 and cancel to 1e181: its double value is
;;;; noise, and sign() answered "pos" for a negative numerator and for a negative
;;;; denominator alike (the root search then took the square root of the radicand's wrong
;;;; form, and Maxima wrote it with %i). Double intervals (src/algebra/intervals.lisp)
;;;; only say that they cannot tell.
;;;;
;;;; Here every bound is an exact rational: sums, products, quotients and integer powers
;;;; are exact, and only a root is bounded, from below and from above, by integer roots
;;;; of the radicand scaled by a power of two (PRECISION bits below the root's leading
;;;; bit). The true value always lies inside. EXACT-CONSTANT-SIGN raises the precision
;;;; until the interval leaves out 0; a value that is exactly zero never does (it is then
;;;; :NEAR-ZERO, for the caller to prove or leave open), and a nonzero algebraic number
;;;; does once the precision exceeds its cancellation.

(in-package #:ames.base)

(defparameter *exact-sign-precisions* '(64 256 1024 4096)
  "The precisions (bits of each root's bounds) EXACT-CONSTANT-SIGN tries in turn.")

(defun root-bounds (r k precision)
  "(INTEGER-ROOT, evaluation.lisp, gives the integer part.) Rationals LOW <= R^(1/K) <= HIGH for the non-negative rational R, HIGH - LOW about
2^-PRECISION of the root's size: (values LOW HIGH)."
  (if (zerop r)
      (values 0 0)
      (let* ((magnitude (- (integer-length (numerator r)) (integer-length (denominator r))))
             (bits (max 0 (- precision (floor magnitude k))))
             (scaled (* r (expt 2 (* k bits))))
             (low (integer-root (floor scaled) k)))
        (values (/ low (expt 2 bits))
                (/ (if (= (expt low k) scaled) low (1+ low)) (expt 2 bits))))))

(defun interval-root (interval k precision)
  "The interval of the K-th root of INTERVAL (rational bounds); NIL when it reaches below 0."
  (destructuring-bind (low . high) interval
    (when (>= low 0)
      (cons (root-bounds low k precision) (nth-value 1 (root-bounds high k precision))))))

(defun exact-interval-product (a b)
  (let ((products (list (* (car a) (car b)) (* (car a) (cdr b))
                        (* (cdr a) (car b)) (* (cdr a) (cdr b)))))
    (cons (reduce #'min products) (reduce #'max products))))

(defun exact-interval-inverse (a)
  "1 / A, NIL when A holds 0."
  (when (or (plusp (car a)) (minusp (cdr a)))
    (cons (/ (cdr a)) (/ (car a)))))

(defun exact-interval-power (a n)
  "The interval A to the integer power N; NIL for a negative N when A holds 0."
  (cond ((minusp n) (let ((p (exact-interval-power a (- n)))) (and p (exact-interval-inverse p))))
        (t (let ((p1 (expt (car a) n)) (p2 (expt (cdr a) n)))
             (if (and (evenp n) (<= (car a) 0 (cdr a)))
                 (cons 0 (max p1 p2))
                 (cons (min p1 p2) (max p1 p2)))))))

(defun exact-interval (expression precision &optional bindings)
  "An interval (LOW . HIGH) of rationals holding the value of the constant EXPRESSION
(numbers, + - * /, powers p/q with |p| and q at most 64, sqrt: the prefix algebra's
radicals), each root bounded to PRECISION bits, the names and terms bound in the alist
BINDINGS taking their (real) values exactly. NIL when EXPRESSION has anything else (an unbound
name, a function, PI), a root of an interval reaching below 0 or a division by one
holding 0 at this precision."
  (labels ((value (x)
             (cond ((rationalp x) (cons x x))
                   ((floatp x) (let ((r (rational x))) (cons r r)))
                   ((and bindings (or (variable-symbol-p x) (quantity-term-p x)))
                    (let ((entry (assoc x bindings :test #'equal)))
                      (and entry (realp (cdr entry)) (finite-real-p (cdr entry))
                           (value (rational (cdr entry))))))
                   ((not (and (consp x) (alexandria:proper-list-p x) (rest x))) nil)
                   (t (let ((parts (mapcar #'value (rest x))))
                        (and (every #'identity parts) (operation (first x) parts (rest x)))))))
           (operation (head parts operands)
             (case head
               (+ (cons (reduce #'+ parts :key #'car) (reduce #'+ parts :key #'cdr)))
               (- (if (rest parts)
                      (cons (- (car (first parts)) (reduce #'+ (rest parts) :key #'cdr))
                            (- (cdr (first parts)) (reduce #'+ (rest parts) :key #'car)))
                      (cons (- (cdr (first parts))) (- (car (first parts))))))
               (* (reduce #'exact-interval-product parts))
               (/ (let ((divisors (mapcar #'exact-interval-inverse (rest parts))))
                    (and (every #'identity divisors)
                         (reduce #'exact-interval-product divisors :initial-value (first parts)))))
               (sqrt (and (null (rest parts)) (interval-root (first parts) 2 precision)))
               (expt (let ((n (second operands)))
                       (cond ((/= (length parts) 2) nil)
                             ;; a large power is left to doubles: its exact bounds grow
                             ((not (and (rationalp n) (<= (abs (numerator n)) 64))) nil)
                             ((integerp n) (exact-interval-power (first parts) n))
                             ((<= (denominator n) 64)
                              (let ((root (interval-root (first parts) (denominator n) precision)))
                                (and root (exact-interval-power root (numerator n))))))))
               (t nil))))
    (handler-case (value expression)
      (arithmetic-error () nil))))

(defun exact-constant-sign (expression &key (precisions *exact-sign-precisions*))
  "The sign of the constant EXPRESSION proven by exact interval arithmetic (see the file
header): :POSITIVE, :NEGATIVE, :ZERO (a value computed exactly, no root in the way), or
:NEAR-ZERO when its interval holds 0 at every one of PRECISIONS (exactly zero, or
closer to it than the last precision can tell: not decided). NIL when EXPRESSION is no
constant of numbers and radicals (see EXACT-INTERVAL)."
  (let ((evaluated nil))
    (dolist (precision precisions (and evaluated :near-zero))
      (let ((interval (exact-interval expression precision)))
        (when interval
          (setf evaluated t)
          (cond ((plusp (car interval)) (return :positive))
                ((minusp (cdr interval)) (return :negative))
                ((= 0 (car interval) (cdr interval)) (return :zero))))))))

;;; Accurate doubles of ill-conditioned constants

(defparameter *accurate-value-precisions* '(64 128 256 512 1024 2048 4096)
  "The precisions ACCURATE-VALUE tries in turn.")

(defun big-number-p (expression)
  "True when EXPRESSION holds a rational whose numerator or denominator has more than
53 bits (more than a double holds): where sums of such terms times radicals cancel, a
double evaluation is noise (see the file header)."
  (if (consp expression)
      (some #'big-number-p (rest expression))
      (and (rationalp expression)
           (or (> (integer-length (numerator expression)) 53)
               (> (integer-length (denominator expression)) 53)))))

(defun accurate-value (expression &optional bindings)
  "EXPRESSION's value (under BINDINGS, as EXPRESSION-VALUE takes them) as a double
correct to about its last bit, from exact intervals (EXACT-INTERVAL) narrowed until
their width is below 2^-55 of their size; the midpoint of the narrowest when none
is (a value too near 0 to tell better). NIL when EXPRESSION has no exact interval (a
function, PI) or its value is beyond a double."
  (let ((best nil))
    (dolist (precision *accurate-value-precisions*)
      (let ((interval (exact-interval expression precision bindings)))
        (when interval
          (setf best interval)
          (when (<= (- (cdr interval) (car interval))
                    (* (expt 2 -55) (max (abs (car interval)) (abs (cdr interval)))))
            (return)))))
    (and best
         (handler-case (float (/ (+ (car best) (cdr best)) 2) 1d0)
           (arithmetic-error () nil)))))
