;;;; src/algebra/angles.lisp -- exact ranges of angles: where sin, cos and tan have a sign, and where they are monotone.
;;;;
;;;; Maxima does not use the range of an angle to find the sign of its sine (with
;;;; 0 < a < pi/2, is(cos(a) > 0) is unknown), nor of a shifted or scaled angle
;;;; (cos(pi/2 - a), sin(2 a), tan(a/2), sin(a + b)). A physicist reads those signs off
;;;; the ranges, and so does this file, exactly: the ends of ranges are numbers P + Q pi
;;;; with P and Q rational (PI-NUMBERs), compared with pi known to 40 digits, so that
;;;; an angle that reaches pi/2 exactly is told from one that stays below it. A bound
;;;; that is no such number (sqrt 2, atan 3) is widened outward to a rational one, which
;;;; keeps every conclusion sound. Ranges of compound angles come from the ranges of
;;;; their subjects by interval arithmetic (sums, differences, rational multiples).

(in-package #:ames.algebra)

;;; Numbers P + Q pi

(defparameter *pi-below* 31415926535897932384626433832795028841971/10000000000000000000000000000000000000000
  "A rational just below pi (40 digits).")

(defparameter *pi-above* 31415926535897932384626433832795028841972/10000000000000000000000000000000000000000
  "A rational just above pi.")

(defun pi-number (rational &optional (pi-part 0))
  "The exact number RATIONAL + PI-PART * pi, as a cons (RATIONAL . PI-PART)."
  (cons rational pi-part))

(defun pn+ (a b) (pi-number (+ (car a) (car b)) (+ (cdr a) (cdr b))))
(defun pn- (a b) (pi-number (- (car a) (car b)) (- (cdr a) (cdr b))))
(defun pn-scale (a c) "A times the rational C." (pi-number (* c (car a)) (* c (cdr a))))

(defun pn-sign (a)
  "The sign (-1, 0 or 1) of the PI-NUMBER A, exactly (pi is irrational, so A is 0 only
when both its parts are); NIL in the (unmet) case where 40 digits of pi do not tell."
  (destructuring-bind (p . q) a
    (if (zerop q)
        (signum p)
        (let ((low (+ p (* q (if (plusp q) *pi-below* *pi-above*))))
              (high (+ p (* q (if (plusp q) *pi-above* *pi-below*)))))
          (cond ((plusp low) 1) ((minusp high) -1) (t nil))))))

(defun pn-float (a)
  "The double-float value of the PI-NUMBER A."
  (+ (coerce (car a) 'double-float) (* (coerce (cdr a) 'double-float) pi)))

(defun pi-linear-value (expression)
  "EXPRESSION as a PI-NUMBER when it is built from numbers and PI by + - * / and stays
of the form P + Q pi (a float is taken as the rational it is); NIL otherwise."
  (labels ((value (x)
             (cond ((rationalp x) (pi-number x))
                   ((floatp x) (and (finite-real-p x) (pi-number (rational x))))
                   ((eq x 'pi) (pi-number 0 1))
                   ((not (and (consp x) (member (car x) '(+ - * /)))) nil)
                   (t (let ((arguments (mapcar #'value (cdr x))))
                        (when (every #'identity arguments)
                          (combine (car x) arguments))))))
           (times (a b)
             (cond ((zerop (cdr a)) (pn-scale b (car a)))
                   ((zerop (cdr b)) (pn-scale a (car b)))
                   (t nil)))
           (combine (operator arguments)
             (ecase operator
               (+ (reduce #'pn+ arguments))
               (- (if (rest arguments)
                      (reduce #'pn- arguments)
                      (pn-scale (first arguments) -1)))
               (* (let ((product (pi-number 1)))
                    (dolist (a arguments product)
                      (setf product (or (times product a) (return nil))))))
               (/ (let ((result (if (rest arguments) (first arguments) (pi-number 1))))
                    (dolist (divisor (if (rest arguments) (rest arguments) arguments) result)
                      (unless (and (zerop (cdr divisor)) (/= 0 (car divisor)))
                        (return nil))
                      (setf result (pn-scale result (/ (car divisor))))))))))
    (value expression)))

;;; Ranges

(defstruct (range (:constructor make-range (lower upper &optional lower-open upper-open)))
  "The numbers between LOWER and UPPER (PI-NUMBERs, NIL for no bound), each end
excluded when its -OPEN flag is true."
  lower upper lower-open upper-open)

(defun point-range (value) (make-range value value))

(defun range-negation (range)
  (make-range (and (range-upper range) (pn-scale (range-upper range) -1))
              (and (range-lower range) (pn-scale (range-lower range) -1))
              (range-upper-open range) (range-lower-open range)))

(defun range-sum (a b)
  (make-range (and (range-lower a) (range-lower b) (pn+ (range-lower a) (range-lower b)))
              (and (range-upper a) (range-upper b) (pn+ (range-upper a) (range-upper b)))
              (or (range-lower-open a) (range-lower-open b))
              (or (range-upper-open a) (range-upper-open b))))

(defun range-scaled (range c)
  "RANGE times the PI-NUMBER C, or NIL when the product leaves the numbers P + Q pi."
  (flet ((scale (end)
           (cond ((null end) nil)
                 ((zerop (cdr c)) (pn-scale end (car c)))
                 ((zerop (cdr end)) (pn-scale c (car end)))
                 (t (return-from range-scaled nil)))))
    (case (pn-sign c)
      (0 (point-range (pi-number 0)))
      (1 (make-range (scale (range-lower range)) (scale (range-upper range))
                     (range-lower-open range) (range-upper-open range)))
      (-1 (range-scaled (range-negation range) (pn-scale c -1)))
      (t nil))))

(defun widened-bound (value side)
  "A rational bound on SIDE (:LOWER or :UPPER) just outside the double-float VALUE."
  (let ((r (rational value))
        (margin (+ (* (abs (rational value)) 1/1000000000000) 1/10000000000000000000000000000000000000000)))
    (pi-number (if (eq side :lower) (- r margin) (+ r margin)))))

(defun exact-bound (expression side)
  "The bound EXPRESSION (a constant) gives on SIDE, as (values PI-NUMBER EXACT): exact
when it is P + Q pi, else widened outward from its floating value; NIL when it has none."
  (let ((exact (pi-linear-value expression)))
    (if exact
        (values exact t)
        (let ((value (constant-value expression)))
          (and value (values (widened-bound value side) nil))))))

(defun tighter-range (range side value open)
  "RANGE with its SIDE end replaced by VALUE (OPEN) when that is tighter."
  (let ((old (if (eq side :lower) (range-lower range) (range-upper range)))
        (old-open (if (eq side :lower) (range-lower-open range) (range-upper-open range))))
    (let ((better (or (null old)
                      (let ((sign (pn-sign (pn- value old))))
                        (case sign
                          (0 (and open (not old-open)))
                          (1 (eq side :lower))
                          (-1 (eq side :upper))
                          (t nil))))))
      (when better
        (if (eq side :lower)
            (setf (range-lower range) value (range-lower-open range) open)
            (setf (range-upper range) value (range-upper-open range) open)))
      range)))

(defun flipped-operator (operator)
  "The relation operator that says the same with its sides exchanged."
  (ecase operator (< '>) (> '<) (<= '>=) (>= '<=) (= '=) (/= '/=)))

(defun oriented-bounds (fact)
  "The ways the relation FACT bounds a subject, as a list of (SUBJECT OPERATOR BOUND)
with the subject on the left: (< 0 x) gives ((X > 0)), (> b a) gives ((B > A) (A < B))."
  (let ((operator (expression-operator fact)))
    (when (member operator '(< > <= >= =))
      (let ((lhs (relation-lhs fact)) (rhs (relation-rhs fact)))
        (append (when (subject-p lhs) (list (list lhs operator rhs)))
                (when (subject-p rhs) (list (list rhs (flipped-operator operator) lhs))))))))

(defun subject-ranges (facts)
  "An alist (SUBJECT . RANGE) of the exact ranges the flattened FACTS give each subject
(a variable or quantity term): from the bounds that are constants, then, twice over,
from bounds that are expressions of other subjects (b > a with a > 0 gives b > 0)."
  (let ((ranges '()))
    (flet ((range-of (subject)
             (cdr (or (assoc subject ranges :test #'equal)
                      (let ((new (cons subject (make-range nil nil))))
                        (push new ranges)
                        new)))))
      (dolist (fact facts)
        (loop for (subject operator bound) in (oriented-bounds fact)
              when (null (expression-variables bound))
                do (let ((range (range-of subject)))
                     (flet ((side (side open)
                              (multiple-value-bind (value exact) (exact-bound bound side)
                                (when value
                                  (tighter-range range side value (or open (not exact)))))))
                       (ecase operator
                         (> (side :lower t)) (>= (side :lower nil))
                         (< (side :upper t)) (<= (side :upper nil))
                         (= (side :lower nil) (side :upper nil)))))))
      (loop repeat 2
            do (dolist (fact facts)
                 (loop for (subject operator bound) in (oriented-bounds fact)
                       for bound-range = (and (expression-variables bound)
                                              (free-of-p subject bound)
                                              (expression-range bound ranges))
                       when bound-range
                         do (let ((range (range-of subject)))
                              (when (and (member operator '(> >= =)) (range-lower bound-range))
                                (tighter-range range :lower (range-lower bound-range)
                                               (or (eq operator '>) (range-lower-open bound-range))))
                              (when (and (member operator '(< <= =)) (range-upper bound-range))
                                (tighter-range range :upper (range-upper bound-range)
                                               (or (eq operator '<) (range-upper-open bound-range))))))))
      (nreverse ranges))))

(defun expression-range (expression ranges)
  "The range of the arithmetic EXPRESSION over the subjects' RANGES (an alist from
SUBJECT-RANGES; a subject not in it is unbounded), by interval arithmetic on sums,
differences and multiples by constants, atan, asin and acos taking their principal
values (atan of two arguments, the polar angle, in (-pi, pi]); NIL when EXPRESSION is of
another kind."
  (labels ((range (x)
             (let ((constant (pi-linear-value x)))
               (cond (constant (point-range constant))
                     ((subject-p x) (let ((entry (assoc x ranges :test #'equal)))
                                      (if entry (copy-range (cdr entry)) (make-range nil nil))))
                     ((not (consp x)) nil)
                     (t (let ((arguments (expression-arguments x)))
                          (case (expression-operator x)
                            (+ (reduce-ranges (mapcar #'range arguments)))
                            (- (let ((parts (mapcar #'range arguments)))
                                 (and (every #'identity parts)
                                      (if (rest parts)
                                          (reduce #'range-sum (mapcar #'range-negation (rest parts))
                                                  :initial-value (first parts))
                                          (range-negation (first parts))))))
                            (* (let* ((constants (mapcar #'pi-linear-value arguments))
                                      (others (loop for a in arguments for c in constants
                                                    unless c collect a)))
                                 (when (= (length others) 1)
                                   (let ((factor (pi-linear-value
                                                  (cons '* (remove-if-not #'pi-linear-value arguments))))
                                         (inner (range (first others))))
                                     (and factor inner (range-scaled inner factor))))))
                            (/ (let ((divisor (and (= (length arguments) 2)
                                                   (pi-linear-value (second arguments))))
                                     (inner (range (first arguments))))
                                 (and divisor inner (zerop (cdr divisor)) (/= 0 (car divisor))
                                      (range-scaled inner (pi-number (/ (car divisor)))))))
                            ;; the inverse functions' principal values, whatever the argument
                            (atan (if (= 1 (length arguments))
                                      (make-range (pi-number 0 -1/2) (pi-number 0 1/2) t t)
                                      ;; atan2(y, x): the polar angle, in (-pi, pi]
                                      (make-range (pi-number 0 -1) (pi-number 0 1) t nil)))
                            (asin (make-range (pi-number 0 -1/2) (pi-number 0 1/2)))
                            (acos (make-range (pi-number 0) (pi-number 0 1)))
                            (t nil)))))))
           (reduce-ranges (parts)
             (and (every #'identity parts) (reduce #'range-sum parts))))
    (range expression)))

;;; Signs and monotonicity of sin, cos and tan on a range

(defun range-within-p (range low high)
  "True when RANGE lies in the closed interval [LOW, HIGH] (PI-NUMBERs). Second value:
whether it also stays away from LOW (open there or above), third: from HIGH."
  (let ((lower (range-lower range)) (upper (range-upper range)))
    (when (and lower upper)
      (let ((from-low (pn-sign (pn- lower low)))
            (to-high (pn-sign (pn- high upper))))
        (when (and from-low to-high (>= from-low 0) (>= to-high 0))
          (values t
                  (or (plusp from-low) (range-lower-open range))
                  (or (plusp to-high) (range-upper-open range))))))))

(defun candidate-periods (range width offset)
  "Integers K such that [OFFSET + K WIDTH, OFFSET + (K+1) WIDTH] may hold RANGE
(PI-NUMBERs WIDTH and OFFSET), guessed from floating values."
  (let ((lower (range-lower range)))
    (when lower
      (let ((k (floor (/ (- (pn-float lower) (pn-float offset)) (pn-float width)))))
        (list k (1- k) (1+ k))))))

(defun range-piece (range width offset)
  "The K for which RANGE lies in [OFFSET + K WIDTH, OFFSET + (K+1) WIDTH], with whether
it stays away from each end, as (values K AWAY-FROM-LOW AWAY-FROM-HIGH); NIL when none."
  (dolist (k (candidate-periods range width offset) nil)
    (multiple-value-bind (within away-low away-high)
        (range-within-p range (pn+ offset (pn-scale width k)) (pn+ offset (pn-scale width (1+ k))))
      (when within (return (values k away-low away-high))))))

(defun range-trigonometric-sign (function range)
  "The sign FUNCTION (SIN, COS or TAN) surely has on RANGE: :POSITIVE, :NEGATIVE,
:NONNEGATIVE, :NONPOSITIVE, or NIL when RANGE crosses a zero (or, for tan, reaches a
pole, where it is undefined)."
  (let ((pi-1 (pi-number 0 1)) (half-pi (pi-number 0 1/2)))
    (ecase function
      ((sin cos)
       ;; sin is positive on (2k pi, (2k+1) pi); cos(x) = sin(x + pi/2)
       (multiple-value-bind (k away-low away-high)
           (range-piece range pi-1 (if (eq function 'sin) (pi-number 0) (pi-number 0 -1/2)))
         (when k
           (if (and away-low away-high)
               (if (evenp k) :positive :negative)
               (if (evenp k) :nonnegative :nonpositive)))))
      (tan
       ;; on [k pi/2, (k+1) pi/2]: k even, 0 at the low end and a pole at the high one
       (multiple-value-bind (k away-low away-high) (range-piece range half-pi (pi-number 0))
         (when k
           (if (evenp k)
               (and away-high (if away-low :positive :nonnegative))
               (and away-low (if away-high :negative :nonpositive)))))))))

(defun range-monotonicity (function range)
  "Whether FUNCTION (SIN, COS or TAN) is :INCREASING or :DECREASING (strictly) on the
whole of RANGE, or NIL when it is not monotone there (or RANGE is unbounded)."
  (let ((pi-1 (pi-number 0 1)))
    (ecase function
      ((sin cos)
       ;; sin increases on [-pi/2 + 2k pi, pi/2 + 2k pi]; cos increases on [-pi + 2k pi, 2k pi]
       (let ((k (range-piece range pi-1 (if (eq function 'sin) (pi-number 0 -1/2) (pi-number 0 -1)))))
         (when k (if (evenp k) :increasing :decreasing))))
      (tan
       (multiple-value-bind (k away-low away-high) (range-piece range pi-1 (pi-number 0 -1/2))
         (and k away-low away-high :increasing))))))

(defun sign-fact (sign expression)
  "The relation saying that EXPRESSION has SIGN (:POSITIVE :NEGATIVE :NONNEGATIVE
:NONPOSITIVE)."
  (list (ecase sign (:positive '>) (:negative '<) (:nonnegative '>=) (:nonpositive '<=))
        expression 0))

(defun range-avoids-p (range point)
  "True when RANGE holds no number POINT + 2 k pi (POINT a PI-NUMBER, k an integer)."
  (multiple-value-bind (k away-low away-high) (range-piece range (pi-number 0 2) point)
    (and k away-low away-high)))

(defun range-bound-facts (function subject range)
  "The facts that FUNCTION (SIN or COS) of SUBJECT stays strictly inside [-1, 1] on
RANGE, where RANGE avoids the points at which it reaches 1 or -1: 0 < a < pi/2 gives
cos a < 1 and sin a < 1 (Maxima knows only cos a <= 1)."
  (let ((top (if (eq function 'sin) (pi-number 0 1/2) (pi-number 0)))
        (bottom (if (eq function 'sin) (pi-number 0 -1/2) (pi-number 0 1)))
        (value (list function subject)))
    (append (when (range-avoids-p range top) (list (list '< value 1)))
            (when (range-avoids-p range bottom) (list (list '> value -1))))))

(defun angle-sign-facts (facts)
  "The sign facts of sin, cos and tan of each subject that the flattened FACTS bound on
both sides, and the strict bounds of sin and cos inside [-1, 1]: 0 < a < pi/2 gives
sin a > 0, cos a > 0, tan a > 0, sin a < 1 and cos a < 1 (and > -1)."
  (loop for (subject . range) in (subject-ranges facts)
        when (and (range-lower range) (range-upper range))
          append (append (loop for function in '(sin cos tan)
                               for sign = (range-trigonometric-sign function range)
                               when sign collect (sign-fact sign (list function subject)))
                         (range-bound-facts 'sin subject range)
                         (range-bound-facts 'cos subject range))))
