;;;; src/algebra/constant-zero.lisp -- relations between constants that differ by nothing
;;;; but round-off: Maxima's sign() decides them by a float evaluation, and is wrong.
;;;;
;;;; sign(1032 sin((pi + 2 acos(407/1032))/2) - 407) is "neg" in Debian's Maxima (its
;;;; bigfloat value at the default precision is -7.8e-16), and is(equal(a, b)) is false for
;;;; (3 pi - 3 asin c)/4 and (3 pi + 6 acos c)/8, which are equal: the energy integral at a
;;;; turning point found on the far branch of the arcsine (a body moving toward -s on a
;;;; circle) was taken for negative there, and the turning point for unreachable. A
;;;; relation between constants with a trigonometric or inverse trigonometric function
;;;; whose sides agree to round-off is decided here, exactly: its difference proven zero
;;;; (EXACTLY-ZERO-P) or :UNKNOWN, never
;;;; by the float.

(in-package #:ames.algebra)

(defparameter *round-off-difference* 1d-9
  "A difference of constants below this, relative to the sides' size, is round-off as far
as a float can tell: DECIDE-CONSTANT-NEAR-ZERO decides its relation exactly or not at all.")

(defparameter *float-decided-operators* '(sin cos tan asin acos atan)
  "The operators over constants whose sign Maxima decides by a float evaluation.")

(defun mentions-float-decided-p (expression)
  "True when EXPRESSION has an operator of *FLOAT-DECIDED-OPERATORS*."
  (and (consp expression)
       (or (member (expression-operator expression) *float-decided-operators*)
           (some #'mentions-float-decided-p (expression-arguments expression)))))

(defun inverses-as-asin (expression)
  "EXPRESSION with each acos(u) written pi/2 - asin(u) (an identity on [-1, 1]) and each
atan(u) asin(u / sqrt(1 + u^2)) (an identity for every real u): one inverse function
left, which trigexpand() undoes."
  (if (atom expression)
      expression
      (let ((x (cons (first expression) (mapcar #'inverses-as-asin (rest expression)))))
        (cond ((/= (length x) 2) x)
              ((eq (first x) 'acos) `(- (/ pi 2) (asin ,(second x))))
              ((eq (first x) 'atan) `(asin (/ ,(second x) (sqrt (+ 1 (expt ,(second x) 2))))))
              (t x)))))

(defun zero-difference-verdict (operator)
  "The truth of LHS OPERATOR RHS when LHS - RHS is zero."
  (if (member operator '(= <= >=)) :true :false))

(defun decide-constant-near-zero (bridge relation)
  "RELATION (= /= < > <= >=) between constants with a trigonometric or inverse
trigonometric function, whose sides agree to round-off: :TRUE or :FALSE when the
difference of its sides is proven exactly zero, else :UNKNOWN. :NOT-APPLICABLE for any
other relation (variables in it, no such function, sides that differ beyond round-off,
or no real value), which the other strategies decide."
  (let ((operator (expression-operator relation)))
    (unless (and (member operator '(= /= < > <= >=))
                 (mentions-float-decided-p relation)
                 (null (expression-variables relation)))
      (return-from decide-constant-near-zero :not-applicable))
    (let* ((lhs (relation-lhs relation)) (rhs (relation-rhs relation))
           (values (handler-case (list (numeric-value bridge lhs '()) (numeric-value bridge rhs '()))
                     (numeric-evaluation-failed () nil))))
      (when (or (null values)
                (> (abs (- (first values) (second values)))
                   (* *round-off-difference* (max 1d0 (abs (first values)) (abs (second values))))))
        (return-from decide-constant-near-zero :not-applicable))
      (if (exactly-zero-p bridge `(- ,lhs ,rhs))
          (zero-difference-verdict operator)
          :unknown))))

(defun cosine-arguments (expression)
  "The arguments K of the cos(K) in EXPRESSION, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (consp x)
                 (when (and (eq (first x) 'cos) (= (length x) 2))
                   (pushnew (second x) found :test #'equal))
                 (mapc #'walk (rest x)))))
      (walk expression))
    found))

(defun exactly-zero-p (bridge difference)
  "True when the constant DIFFERENCE is proven zero (REDUCES-TO-ZERO-P) as it is, or with
acos and atan written with asin (INVERSES-AS-ASIN), or with the sines and cosines of
rational multiples of pi brought to the first octant (FIRST-OCTANT-TRIGONOMETRY). NIL
when not proven."
  (or (reduces-to-zero-p bridge difference)
      (let ((rewritten (inverses-as-asin difference)))
        (and (not (equal rewritten difference))
             (reduces-to-zero-p bridge rewritten)))
      (let ((octant (first-octant-trigonometry difference)))
        (and (not (equal octant difference))
             (or (reduces-to-zero-p bridge octant)
                 (let ((rewritten (inverses-as-asin octant)))
                   (and (not (equal rewritten octant))
                        (reduces-to-zero-p bridge rewritten))))))))

(defun reduces-to-zero-p (bridge difference)
  "True when the constant DIFFERENCE, expanded and trigexpand()ed, then ratsimp()ed with
each cos(K)^2 written 1 - sin(K)^2 (sin and cos of one angle are no independent atoms),
then radcan()ed, is 0."
  (handler-case
      (let ((expanded (simplify bridge difference :strategy :expanded-trigexpand)))
        (or (eql expanded 0)
            (let ((reduced (ratsimp-with-sines bridge expanded (cosine-arguments expanded)
                                               :datum difference)))
              (or (eql reduced 0)
                  (eql (simplify bridge reduced :strategy :radcan) 0)))))
    (maxima-condition () nil)))

;;; Constant factors near zero in a relation with variables

(defun near-zero-constants (expression)
  "The constant subexpressions of EXPRESSION (no variables) with a trigonometric or
inverse trigonometric function whose double value is 0 to round-off (relative to their
terms' sizes when a sum), outermost only, each once."
  (let ((found '()))
    (labels ((size (x)
               (let ((v (ignore-errors (expression-value x))))
                 (and (realp v) (abs v))))
             (walk (x)
               (when (consp x)
                 (if (and (mentions-float-decided-p x) (null (expression-variables x)))
                     (let ((value (size x))
                           (scale (if (eq (expression-operator x) '+)
                                      (reduce #'+ (mapcar (lambda (term) (or (size term) 0))
                                                          (expression-arguments x)))
                                      1d0)))
                       (if (and value (<= value (* *round-off-difference* (max 1d0 scale))))
                           (pushnew x found :test #'equal)
                           (mapc #'walk (expression-arguments x))))
                     (mapc #'walk (expression-arguments x))))))
      (walk expression))
    (nreverse found)))

(defun decide-near-zero-constants (bridge relation)
  "RELATION (= /= < > <= >=) with variables, in which a constant subexpression with a
trigonometric function is 0 to round-off (NEAR-ZERO-CONSTANTS): Maxima's sign() would
take its float's sign (cos(2 atan 3 - atan(4/3)) r^2 <= 0 was false). Each such constant
proven exactly zero (EXACTLY-ZERO-P) is replaced by 0 and the relation decided afresh;
:UNKNOWN when one is not proven zero (its sign is beyond a float's reach).
:NOT-APPLICABLE when RELATION has no such constant, or no variables (DECIDE-CONSTANT-
NEAR-ZERO's case)."
  (if (or (null (expression-variables relation))
          (not (mentions-float-decided-p relation)))
      :not-applicable
      (let ((constants (near-zero-constants relation)))
        (cond ((null constants) :not-applicable)
              ((every (lambda (c) (exactly-zero-p bridge c)) constants)
               (decide bridge (substitute-subexpressions (mapcar (lambda (c) (cons c 0)) constants)
                                                         relation)))
              (t :unknown)))))
(defun octant-sine-or-cosine (function q)
  "FUNCTION (SIN or COS) of the angle Q pi (Q rational) written as a sign and the sine or
cosine of an angle R pi with R in [0, 1/4] (sin(pi - x) = sin x, cos(pi - x) = -cos x,
sin(pi/2 - x) = cos x, and the period 2 pi): an expression."
  (let ((r (mod q 2)) (sign 1))
    (ecase function
      (sin (when (>= r 1) (setf r (- r 1) sign (- sign)))
           (when (> r 1/2) (setf r (- 1 r))))
      (cos (when (> r 1) (setf r (- 2 r)))
           (when (> r 1/2) (setf r (- 1 r) sign (- sign)))))
    (let ((other (if (eq function 'sin) 'cos 'sin)))
      (when (> r 1/4) (setf r (- 1/2 r) function other))
      (let ((value (if (zerop r) (if (eq function 'sin) 0 1) `(,function (* ,r pi)))))
        (if (= sign 1) value `(- ,value))))))

(defun first-octant-trigonometry (expression)
  "EXPRESSION with each sin, cos and tan of a rational multiple of pi written with the
sine or cosine of an angle in [0, pi/4] (OCTANT-SINE-OR-COSINE): Maxima leaves
cos(43 pi/60) as it is, so that cos(43 pi/60) + cos(17 pi/60) is not seen to be 0 (a
ladder's end exactly on the floor, at an angle of 51 degrees)."
  (if (atom expression)
      expression
      (let* ((x (cons (first expression) (mapcar #'first-octant-trigonometry (rest expression))))
             (angle (and (= (length x) 2) (member (first x) '(sin cos tan))
                         (pi-linear-value (second x)))))
        (cond ((not (and angle (zerop (car angle)))) x)
              ((eq (first x) 'tan) `(/ ,(octant-sine-or-cosine 'sin (cdr angle))
                                      ,(octant-sine-or-cosine 'cos (cdr angle))))
              (t (octant-sine-or-cosine (first x) (cdr angle)))))))
