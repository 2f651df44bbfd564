;;;; src/algebra/sinusoid-quadratics.lisp -- the sign of a function of one angle that is a
;;;; quadratic in one sinusoid of it, at every angle, under the facts about the parameters.
;;;;
;;;; A block rocking on its edge presses on it with N(s) = alpha cos^2 s + beta cos s sin s +
;;;; gamma sin^2 s + delta cos s + epsilon sin s + zeta, the coefficients made of its mass,
;;;; size, g and the speed it was set turning at. The run asks where N reaches 0 along the
;;;; angle: a root of no closed form (quadratic in sin and cos), which the algebra cannot
;;;; place. A physicist writes N in the one sinusoid X = cos of the angle the centre makes
;;;; with the vertical through the edge, X = (delta cos s + epsilon sin s) / (scale): N = a
;;;; X^2 + X + c, and sees that this quadratic has no real root (4 a c > 1, a > 0): N > 0
;;;; at every angle, so it never reaches 0. Here, in general: with C = cos s and S = sin s,
;;;;   - when the linear part (delta, epsilon) is not 0: X = delta C + epsilon S and
;;;;     alpha C^2 + beta C S + gamma S^2 = a X^2 + lambda (C^2 + S^2) must hold as
;;;;     polynomials (alpha - gamma = a (delta^2 - epsilon^2), beta = 2 a delta epsilon, both
;;;;     checked by simplification), so f = a X^2 + X + c, c = zeta + lambda, X ranging over
;;;;     [-R, R], R = sqrt(delta^2 + epsilon^2). f > 0 at every angle when a > 0 and 4 a c - 1
;;;;     > 0 (no real root), or when f(-R) = a R^2 - R + c > 0 and the minimum over [-R, R]
;;;;     is at -R (a <= 0, or the vertex -1/(2 a) at or left of -R: 2 a R <= 1);
;;;;   - when it is 0: f = M + P cos 2s + Q sin 2s, M = zeta + (alpha + gamma)/2, P = (alpha -
;;;;     gamma)/2, Q = beta/2, and f > 0 at every angle when M > 0 and M^2 > P^2 + Q^2.
;;;; Each condition is asked of DECIDE under the facts in force. f < 0 likewise, on -f.
;;;; A static friction limit along the angle, mu N - F, is no quadratic in one sinusoid
;;;; (F's sinusoid is another). It is linear in mu: f = p P + Q, p a parameter. Where P
;;;; has a least value L > 0 at every angle (c - 1/(4 a) for a > 0 and the vertex within
;;;; [-R, R], else the value at -R; M - sqrt(P^2 + Q^2) without a linear part) and Q is no
;;;; larger than B = |M| + sqrt(P^2 + Q^2) + sqrt(delta^2 + epsilon^2) in size (each
;;;; harmonic at its amplitude), p > B / L proves f >= p L - B > 0 at every angle: a
;;;; declared "rough enough", mu greater than the largest friction over the least normal
;;;; force, taken one harmonic at a time (stronger than the motion needs).
;;;; Sound: each is a proof that f has that sign for every real angle, the more so over a
;;;; part of them (a rise from the flat position to a turning angle); where a condition is
;;;; not proven nothing is claimed.

(in-package #:ames.algebra)

(defun angle-only-in-sinusoids-p (function angle)
  "True when every occurrence of ANGLE in FUNCTION is as the whole argument of sin or cos."
  (labels ((clean (x)
             (cond ((equal x angle) nil)
                   ((atom x) t)
                   ((quantity-term-p x) t)
                   ((and (member (expression-operator x) '(sin cos)) (equal (second x) angle)
                         (null (cddr x)))
                    t)
                   (t (every #'clean (expression-arguments x))))))
    (clean function)))

(defun coefficients-up-to (bridge expression variable degree)
  "The coefficients (c0 ... c_DEGREE) of EXPRESSION as a polynomial in VARIABLE of degree
at most DEGREE (padded with 0), or NIL when it is no such polynomial."
  (let ((coefficients (polynomial-coefficients-in bridge expression variable)))
    (when (and coefficients (<= (length coefficients) (1+ degree)))
      (append coefficients (make-list (- (1+ degree) (length coefficients)) :initial-element 0)))))

(defun quadratic-sinusoid-coefficients (bridge function angle)
  "FUNCTION of ANGLE as alpha cos^2 + beta cos sin + gamma sin^2 + delta cos + epsilon sin
+ zeta: the list (ALPHA BETA GAMMA DELTA EPSILON ZETA), each free of ANGLE, or NIL when it
is not of that form."
  (when (angle-only-in-sinusoids-p function angle)
    (let* ((c (keyed-auxiliary-variable bridge (list :sinusoid-cos angle) "SINUSOID-C"))
           (s (keyed-auxiliary-variable bridge (list :sinusoid-sin angle) "SINUSOID-S"))
           (rewritten (substitute-subexpressions
                       (list (cons (list 'cos angle) c) (cons (list 'sin angle) s)) function)))
      (when (not (occurs-p angle rewritten))
        (destructuring-bind (&optional c0 c1 c2) (coefficients-up-to bridge rewritten c 2)
          (let ((in-s0 (and c0 (coefficients-up-to bridge c0 s 2)))
                (in-s1 (and c1 (coefficients-up-to bridge c1 s 1)))
                (in-s2 (and c2 (coefficients-up-to bridge c2 s 0))))
            (when (and in-s0 in-s1 in-s2)
              (destructuring-bind (zeta epsilon gamma) in-s0
                (destructuring-bind (delta beta) in-s1
                  (list (first in-s2) beta gamma delta epsilon zeta))))))))))

(defun one-sinusoid-form (bridge coefficients)
  "For COEFFICIENTS (ALPHA BETA GAMMA DELTA EPSILON ZETA) with a linear part: (A C R) with
f = A X^2 + X + C, X = DELTA cos + EPSILON sin in [-R, R], or NIL when the quadratic part
is not A X^2 + LAMBDA (cos^2 + sin^2)."
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    (let* ((difference `(- (expt ,delta 2) (expt ,epsilon 2)))
           (cross `(* 2 ,delta ,epsilon))
           (norm `(+ (expt ,delta 2) (expt ,epsilon 2)))
           (a (simplified bridge `(/ (+ (* (- ,alpha ,gamma) ,difference) (* ,beta ,cross))
                                     (expt ,norm 2)))))
      (when (and (zero-expression-p bridge `(- (- ,alpha ,gamma) (* ,a ,difference)))
                 (zero-expression-p bridge `(- ,beta (* ,a ,cross))))
        (list a (simplified bridge `(+ ,zeta (- ,alpha (* ,a (expt ,delta 2)))))
              (simplified bridge `(sqrt ,norm)))))))

(defun positive-quadratic-in-sinusoid-p (bridge coefficients)
  "True when the function with COEFFICIENTS (see SINUSOID-COEFFICIENTS) is proven positive
at every angle (see this file's header)."
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    (flet ((proven (relation) (holds-p bridge relation)))
      (if (and (zero-expression-p bridge delta) (zero-expression-p bridge epsilon))
          (let ((mean (simplified bridge `(+ ,zeta (/ (+ ,alpha ,gamma) 2)))))
            (and (proven `(> ,mean 0))
                 (proven `(> (- (expt ,mean 2) (/ (+ (expt (- ,alpha ,gamma) 2) (expt ,beta 2)) 4))
                             0))))
          (let ((form (one-sinusoid-form bridge coefficients)))
            (when form
              (destructuring-bind (a c r) form
                (or (and (proven `(> ,a 0)) (proven `(> (- (* 4 ,a ,c) 1) 0)))
                    (and (proven `(> (+ (* ,a (expt ,r 2)) (- ,r) ,c) 0))
                         (or (proven `(<= ,a 0)) (proven `(<= (* 2 ,a ,r) 1))))))))))))

;;; A function linear in a positive parameter: p P + Q, P bounded below, Q in size

(defun sinusoid-lower-bound (bridge coefficients)
  "An expression L, free of the angle, with the function of COEFFICIENTS >= L at every
angle (its least value over a quadratic in one sinusoid), or NIL when none is found."
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    (flet ((proven (relation) (holds-p bridge relation)))
      (if (and (zero-expression-p bridge delta) (zero-expression-p bridge epsilon))
          `(- (+ ,zeta (/ (+ ,alpha ,gamma) 2))
              (sqrt (/ (+ (expt (- ,alpha ,gamma) 2) (expt ,beta 2)) 4)))
          (let ((form (one-sinusoid-form bridge coefficients)))
            (when form
              (destructuring-bind (a c r) form
                (cond ((and (proven `(> ,a 0)) (proven `(>= (* 2 ,a ,r) 1)))
                       `(- ,c (/ 1 (* 4 ,a))))
                      ((or (proven `(<= ,a 0)) (proven `(<= (* 2 ,a ,r) 1)))
                       `(+ (* ,a (expt ,r 2)) (- ,r) ,c))))))))))

(defun sinusoid-size-bound (coefficients)
  "An expression B, free of the angle, with |f| <= B at every angle for the function of
COEFFICIENTS: |M| + sqrt(P^2 + Q^2) + sqrt(delta^2 + epsilon^2), f = M + P cos 2s + Q sin
2s + delta cos s + epsilon sin s."
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    `(+ (abs (+ ,zeta (/ (+ ,alpha ,gamma) 2)))
        (sqrt (/ (+ (expt (- ,alpha ,gamma) 2) (expt ,beta 2)) 4))
        (sqrt (+ (expt ,delta 2) (expt ,epsilon 2))))))

(defun expression-names (expression)
  "The symbols (parameters) of EXPRESSION, other than pi."
  (let ((names '()))
    (labels ((walk (x)
               (cond ((and (symbolp x) x (not (eq x 'pi))) (pushnew x names))
                     ((and (consp x) (not (quantity-term-p x))) (mapc #'walk (expression-arguments x))))))
      (walk expression))
    names))

(defun positive-through-a-parameter-p (bridge function angle)
  "True when FUNCTION = p P + Q for a parameter p, P and Q quadratic in sin and cos of
ANGLE, P >= L at every angle (SINUSOID-LOWER-BOUND), |Q| <= B (SINUSOID-SIZE-BOUND), and
L > 0 and p > B / L are proven: then p > 0 and FUNCTION >= p L - B > 0 at every angle (a static friction limit, mu N - F, under a declared \"rough enough\")."
  (dolist (p (remove angle (expression-names function)) nil)
    (let ((parts (coefficients-up-to bridge function p 1)))
      (when (and parts (not (zero-expression-p bridge (second parts))))
        (let ((inner (quadratic-sinusoid-coefficients bridge (second parts) angle))
              (rest (quadratic-sinusoid-coefficients bridge (first parts) angle)))
          (when (and inner rest)
            (let ((lower (sinusoid-lower-bound bridge inner)))
              ;; L > 0 and p > B / L (so p > 0, as B >= 0): p P + Q >= p L - B > 0
              (when (and lower (holds-p bridge `(> ,lower 0))
                         (holds-p bridge `(> ,p (/ ,(sinusoid-size-bound rest) ,lower))))
                (return t)))))))))

(defun sign-at-every-angle (bridge function angle)
  "The sign FUNCTION (of the name or term ANGLE, through its sin and cos only, quadratic in
them) is proven to have at every value of ANGLE under the facts in force: :POSITIVE,
:NEGATIVE, or NIL when neither is proven or FUNCTION is of no such form (see this file's
header). Sound: NIL claims nothing."
  (let ((coefficients (handler-case (quadratic-sinusoid-coefficients bridge function angle)
                        ((or maxima-error maxima-timeout) () nil))))
    (when coefficients
      (handler-case
          (cond ((positive-quadratic-in-sinusoid-p bridge coefficients) :positive)
                ((positive-quadratic-in-sinusoid-p
                  bridge (mapcar (lambda (x) (simplified bridge `(- ,x))) coefficients))
                 :negative)
                ((positive-through-a-parameter-p bridge function angle) :positive)
                ((positive-through-a-parameter-p bridge `(- ,function) angle) :negative))
        ((or maxima-error maxima-timeout) () nil)))))
