;;;; src/geometry/angles.lisp -- the circular functions of the exact simplifier, and the clear sign of a constant expression.
;;;;
;;;; ECOS, ESIN, ETAN and EATAN2 build the circular functions for the constructors of
;;;; expressions.lisp: exact at multiples of PI/4 and PI/6 (with square roots of 2 and 3),
;;;; quarter turns taken out of the argument, cos and sin of a two-argument atan as ratios.
;;;; CONSTANT-SIGN settles the sign of a constant expression by arithmetic when it can.

(in-package #:ames.geometry)

(defun pi-multiple (x)
  "The rational R when X is structurally R*PI (or 0), else NIL."
  (cond ((eql x 0) 0)
        ((eq x 'pi) 1)
        ((and (consp x) (eq (car x) '*))
         (multiple-value-bind (c fs) (product-factors x)
           (and (rationalp c) (equal fs '(pi)) c)))
        ((and (consp x) (eq (car x) '-) (= (length x) 2))
         (let ((r (pi-multiple (second x)))) (and r (- r))))
        (t nil)))

(defun special-angle-value (x function)
  "The exact value of FUNCTION (COS or SIN) at X when X is a multiple of PI/4 or PI/6
(using square roots of 2 and 3), else NIL."
  (let ((r (pi-multiple x)))
    (when r
      (let ((r (mod r 2)))                ; the angle in [0, 2 pi) as a multiple of pi
        (flet ((cosine (r)
                 ;; r in [0, 2): reduce to the first quadrant with signs
                 (multiple-value-bind (quadrant within) (floor r 1/2)
                   (let* ((angle (if (oddp quadrant) (- 1/2 within) within))
                          (magnitude (case angle
                                       (0 1) (1/6 (e* 1/2 (esqrt 3))) (1/4 (e* 1/2 (esqrt 2)))
                                       (1/3 1/2) (1/2 0) (t nil))))
                     (and magnitude
                          (if (member quadrant '(1 2)) (e- magnitude) magnitude))))))
          (ecase function
            (cos (cosine r))
            (sin (cosine (mod (- r 1/2) 2)))))))))

(defun two-argument-atan-p (x)
  (and (consp x) (eq (car x) 'atan) (= (length x) 3)))

(defun split-quarter-turns (x)
  "X as (values REST K) with X = REST + K PI/2 for an integer K taken from X's terms."
  (let ((k 0) (rest '()))
    (dolist (term (if (and (consp x) (eq (car x) '+)) (cdr x) (list x)))
      (let ((r (pi-multiple term)))
        (if (and r (integerp (* 2 r)))
            (incf k (* 2 r))
            (push term rest))))
    (values (apply #'e+ (nreverse rest)) (mod k 4))))

(defun circular-function (function x)
  "FUNCTION (COS or SIN) of X: exact at multiples of PI/4 and PI/6; quarter turns in X
shifted out; at X = atan(y, u), cos = u / sqrt(u^2 + y^2) and sin = y / sqrt(u^2 + y^2)."
  (multiple-value-bind (rest k) (split-quarter-turns x)
    (cond ((special-angle-value x function))
          ((and (not (equal rest x)) (not (eql rest 0)))
           ;; cos(r + k pi/2), and sin(r + k pi/2) = cos(r + (k - 1) pi/2)
           (ecase (mod (if (eq function 'sin) (1- k) k) 4)
             (0 (ecos rest)) (1 (e- (esin rest))) (2 (e- (ecos rest))) (3 (esin rest))))
          ((two-argument-atan-p x)
           (destructuring-bind (y u) (rest x)
             (e/ (ecase function (cos u) (sin y))
                 (esqrt (e+ (esquare y) (esquare u))))))
          (t (list function x)))))

(defun ecos (x)
  "The cosine of X, simplified as CIRCULAR-FUNCTION says."
  (circular-function 'cos x))

(defun esin (x)
  "The sine of X, simplified as CIRCULAR-FUNCTION says."
  (circular-function 'sin x))

(defun etan (x)
  "The tangent of X."
  (let ((r (pi-multiple x)))
    (if (and r (integerp r)) 0 (list 'tan x))))

(defun special-atan2 (y x)
  "The angle of (X, Y) as a multiple of PI when X and Y are constants making a
multiple of PI/6 or PI/4, else NIL."
  (let ((sx (constant-sign x)) (sy (constant-sign y)))
    (when (and sx sy)
      (cond ((and (zerop sy) (zerop sx)) nil)
            ((zerop sy) (if (plusp sx) 0 1))
            ((zerop sx) (if (plusp sy) 1/2 -1/2))
            (t (let* ((ratio (e/ y x))
                      (slope (let ((r (rational-value ratio))) (and r (abs r))))
                      (slope-squared (rational-value (e* ratio ratio)))
                      (first-quadrant (cond ((eql slope 1) 1/4)
                                            ((eql slope-squared 3) 1/3)
                                            ((eql slope-squared 1/3) 1/6))))
                 (when first-quadrant
                   (cond ((and (plusp sx) (plusp sy)) first-quadrant)
                         ((plusp sy) (- 1 first-quadrant))
                         ((plusp sx) (- first-quadrant))
                         (t (- first-quadrant 1))))))))))

(defun eatan2 (y x)
  "The angle of the direction (X, Y), in (-PI, PI], as (ATAN Y X) unless exact."
  (let ((special (special-atan2 y x)))
    (cond (special (e* special 'pi))
          ((and (rationalp y) (rationalp x))
           ;; reduce (12, -16) to (3, -4)
           (let ((scale (/ (max (abs x) (abs y)))))
             (let* ((ny (* y scale)) (nx (* x scale))
                    (common (/ (lcm (denominator nx) (denominator ny))
                               (gcd (numerator nx) (numerator ny)))))
               (list 'atan (* ny common) (* nx common)))))
          (t (list 'atan y x)))))
