;;;; src/algebra/integrals.lisp -- travel times in closed form: the integral of ds / sqrt(E(s)) for the energy integral E.
;;;;
;;;; A one-degree-of-freedom conservative motion has the energy integral w^2 = E(s); the
;;;; time from s0 to s1 (no turning point between) is the integral of ds / sqrt(E). The
;;;; closed forms are found by pattern, in this order, each from an antiderivative G:
;;;;   E polynomial of degree <= 2 in s   (uniform acceleration: E linear; harmonic and
;;;;                                       repulsive motion: asin, asinh, acosh, log);
;;;;   E = A + B cos(k s) + C sin(k s)     (a particle on a circle under a constant force:
;;;;                                       the incomplete elliptic integral F, through
;;;;                                       1 + cos y = 2 - 2 sin^2(y/2));
;;;;   E = A + B / s                       (two bodies under mutual gravitation);
;;;;   anything else: Maxima's integrate(), when it answers without asking.
;;;; Each pattern picks its formula by the signs the current assumptions decide. Every
;;;; answer is then checked: symbolically (G' = 1/sqrt(E) on the path, by Maxima) when the
;;;; pattern's conditions were all decided, and always numerically against the quadrature
;;;; of quadrature.lisp at random admissible points (required when no symbolic proof).
;;;; The elliptic pattern is in elliptic.lisp.

(in-package #:ames.algebra)

(defstruct (travel (:constructor make-travel (bridge energy position from to direction)))
  "A travel-time question: BRIDGE, the squared speed ENERGY in the name POSITION, the
ends FROM and TO, and the DIRECTION of motion (1 when TO > FROM, else -1)."
  bridge energy position from to direction)

(defun travel-time (bridge speed-squared position from to &key direction)
  "The time to move monotonically from POSITION = FROM to POSITION = TO when the squared
speed is SPEED-SQUARED, an expression in POSITION (the energy integral w^2 = E(s)): the
integral of ds / sqrt(E) between FROM and TO, positive. The caller guarantees E > 0
strictly between FROM and TO (no turning point there); E may vanish at either end (a
start from rest, an arrival at a turning point). Returns
  (values TIME :CLOSED-FORM VERIFICATION)  TIME in prefix algebra; VERIFICATION is
      :SYMBOLIC when the formula's conditions were decided under the current assumptions
      and Maxima proved its derivative, :NUMERIC when it was checked only against
      quadrature, at 5 or more random points satisfying the facts in force (within 1e-7
      relative; no point disagreed);
  (values NIL :NO-CLOSED-FORM)  no verified closed form.
DIRECTION, 1 when TO > FROM and -1 when TO < FROM, is part of the caller's guarantee
when given; otherwise it is decided from the assumptions, or else (then only a numeric
verification can accept the answer) taken from random admissible points.
The patterns are listed in the file header. Maxima's questions and failures on the way
only mean :NO-CLOSED-FORM.
Signals INVALID-BRIDGE-ARGUMENT (POSITION no name, FROM or TO depending on it, a
DIRECTION other than 1, -1 or NIL), UNTRANSLATABLE-EXPRESSION."
  (check-travel-arguments position (list speed-squared from to) (list from to))
  (unless (member direction '(nil 1 -1))
    (error 'invalid-bridge-argument :datum direction :detail "the direction must be 1, -1 or NIL"))
  (when (zero-expression-p bridge (list '- to from))
    (return-from travel-time (values 0 :closed-form :symbolic)))
  (multiple-value-bind (direction decided) (choose-direction bridge from to direction)
    (when direction
      (let ((travel (make-travel bridge speed-squared position from to direction)))
        (dolist (strategy '(polynomial-antiderivative sinusoidal-antiderivative
                            central-antiderivative integrated-antiderivative))
          (multiple-value-bind (antiderivative proven end-value)
              (call-or-nil (lambda () (funcall strategy travel)))
            (when antiderivative
              (let ((time (call-or-nil (lambda () (time-between travel antiderivative end-value)))))
                (when time
                  (let ((verification (verify-travel-time travel antiderivative time
                                                          (and proven decided))))
                    (when verification
                      (return-from travel-time (values time :closed-form verification)))))))))))
    (values nil :no-closed-form)))

(defun choose-direction (bridge from to given)
  "The direction of travel (1 or -1) and whether it is known (GIVEN by the caller or
decided); else the sign of TO - FROM at random admissible points, not known; else NIL."
  (if given
      (values given t)
      (case (decided-sign bridge (list '- to from))
        (:positive (values 1 t))
        (:negative (values -1 t))
        (t (case (witnessed-sign bridge (list '- to from))
             (:positive (values 1 nil))
             (:negative (values -1 nil))
             (t nil))))))

(defun check-travel-arguments (position expressions ends)
  "Signal unless POSITION is a name, EXPRESSIONS are in the algebra and ENDS free of POSITION."
  (unless (subject-p position)
    (error 'invalid-bridge-argument :datum position
                                    :detail "the position must be a variable or a quantity term"))
  (dolist (expression expressions) (check-translatable expression :arithmetic))
  (dolist (end ends)
    (unless (free-of-p position end)
      (error 'invalid-bridge-argument :datum end
                                      :detail (format nil "an end of the travel depends on ~S" position)))))

(defun time-between (travel antiderivative &optional end-value)
  "DIRECTION (G(TO) - G(FROM)) for the antiderivative G, simplified; NIL when it still
depends on the position. END-VALUE, when given, is called on each end and may return
G's value there in a better form (exact where the formula meets a turning point)."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel)))
    (flet ((at (end)
             (or (and end-value (funcall end-value end))
                 (substitute-expressions (list (cons s end)) antiderivative))))
      (let ((time (simplified bridge `(* ,(travel-direction travel)
                                         (- ,(at (travel-to travel)) ,(at (travel-from travel)))))))
        (and (free-of-p s time) time)))))

;;; Verification

(defun verify-travel-time (travel antiderivative time proven)
  "How TIME was verified (:SYMBOLIC or :NUMERIC), or NIL when it was not: symbolically
when PROVEN (the pattern's conditions were decided) and Maxima shows ANTIDERIVATIVE' =
1/sqrt(E) for the position between the ends, unless the numeric check disagrees
somewhere; otherwise numerically, at *VERIFICATION-POINTS* admissible points or more."
  (multiple-value-bind (agreed disagreed) (compare-with-quadrature travel time)
    (cond ((plusp disagreed) nil)
          ((and proven (call-or-nil (lambda () (derivative-checked-p travel antiderivative))))
           :symbolic)
          ((>= agreed *verification-points*) :numeric)
          (t nil))))

(defun derivative-checked-p (travel antiderivative)
  "True when Maxima shows that ANTIDERIVATIVE' = 1/sqrt(E) for every position strictly
between the ends (assumed while it checks)."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (from (travel-from travel)) (to (travel-to travel))
         (facts (if (plusp (travel-direction travel))
                    `((> ,s ,from) (< ,s ,to))
                    `((< ,s ,from) (> ,s ,to)))))
    (with-assumptions (bridge facts)
      (equivalent-p bridge (maxima-derivative bridge antiderivative s)
                    `(/ 1 (sqrt ,(travel-energy travel)))))))

(defun compare-with-quadrature (travel time)
  "The numbers of admissible points where TIME agrees and disagrees with the quadrature
of ds / sqrt(E) (points where the quadrature fails are skipped)."
  (let* ((s (travel-position travel))
         (energy (travel-energy travel))
         (from (travel-from travel)) (to (travel-to travel))
         (profile (make-energy-profile (travel-bridge travel) energy s from to))
         (subjects (remove s (remove-duplicates (mapcan #'expression-variables
                                                        (list energy from to time))
                                                :test #'equal)
                           :test #'equal)))
    (compare-at-admissible-points
     (travel-bridge travel) time
     (lambda (point)
       (let ((start (expression-value from point))
             (end (expression-value to point)))
         (and start end
              (travel-time-integral profile (float start 1d0) (float end 1d0) point))))
     subjects)))

;;; The patterns. Each returns an antiderivative G of 1/sqrt(E) valid on the whole path,
;;; and whether its conditions were all decided (so that a derivative check proves it);
;;; or NIL when it does not apply.

(defun polynomial-antiderivative (travel)
  "E = c0 + c1 s + c2 s^2: s / sqrt(c0); 2 sqrt(E) / c1; for c2 < 0
-asin((2 c2 s + c1) / sqrt(D)) / sqrt(-c2) with D = c1^2 - 4 c2 c0 (> 0 since E > 0
on the path); for c2 > 0 asinh((2 c2 s + c1) / sqrt(-D)) / sqrt(c2) when D < 0, else
+-acosh(+-(2 c2 s + c1) / sqrt(D)) / sqrt(c2) (D > 0) or +-log(2 sqrt(c2 E) +- (2 c2 s
+ c1)) / sqrt(c2), the sign that of 2 c2 s + c1 on the path."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (energy (travel-energy travel))
         (coefficients (polynomial-coefficients-in bridge energy s)))
    (case (length coefficients)
      (1 (values `(/ ,s (sqrt ,(first coefficients))) t))
      (2 (when (member (decided-sign bridge (second coefficients)) '(:positive :negative))
           (values `(/ (* 2 (sqrt ,energy)) ,(second coefficients)) t)))
      (3 (destructuring-bind (c0 c1 a) coefficients
           (let ((slope `(+ (* 2 ,a ,s) ,c1))
                 (discriminant (simplified bridge `(- (expt ,c1 2) (* 4 ,a ,c0)))))
             (case (decided-sign bridge a)
               (:negative
                (values `(- (/ (asin (/ ,slope (sqrt ,discriminant))) (sqrt (- ,a)))) t
                        ;; at a turning point the sine is +-1 exactly
                        (lambda (end)
                          (when (at-rest-p travel end)
                            (case (decided-sign bridge (substitute-expressions (list (cons s end)) slope))
                              (:positive `(- (/ pi (* 2 (sqrt (- ,a))))))
                              (:negative `(/ pi (* 2 (sqrt (- ,a))))))))))
               (:positive
                (if (eq (decided-sign bridge discriminant) :negative)
                    (values `(/ (asinh (/ ,slope (sqrt (- ,discriminant)))) (sqrt ,a)) t)
                    (let ((side (path-sign travel slope))
                          (positive (eq (decided-sign bridge discriminant) :positive)))
                      (flet ((end-value (end)
                               ;; acosh(1) = 0 at a turning point
                               (and positive (at-rest-p travel end) 0)))
                       (case side
                        (:positive
                         (values (if positive
                                     `(/ (acosh (/ ,slope (sqrt ,discriminant))) (sqrt ,a))
                                     `(/ (log (+ (* 2 (sqrt ,a) (sqrt ,energy)) ,slope)) (sqrt ,a)))
                                 t #'end-value))
                        (:negative
                         (values (if positive
                                     `(- (/ (acosh (- (/ ,slope (sqrt ,discriminant)))) (sqrt ,a)))
                                     `(- (/ (log (- (* 2 (sqrt ,a) (sqrt ,energy)) ,slope)) (sqrt ,a))))
                                 t #'end-value))))))))))))))

(defun at-rest-p (travel end)
  "True when the squared speed simplifies to 0 at END (a start from rest, a turning point)."
  (let ((bridge (travel-bridge travel)))
    (zero-expression-p bridge (substituted bridge (travel-energy travel) (travel-position travel) end))))

(defun path-sign (travel expression)
  "The sign (:POSITIVE or :NEGATIVE) that EXPRESSION, linear in the position, has at both
ends of the path (hence on all of it), or NIL when that is not decided."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (at-from (decided-sign bridge (substitute-expressions (list (cons s (travel-from travel))) expression)))
         (at-to (decided-sign bridge (substitute-expressions (list (cons s (travel-to travel))) expression))))
    (and (eq at-from at-to) (member at-from '(:positive :negative)) at-from)))

(defun central-antiderivative (travel)
  "E = A + B/s on a path with s > 0, an antiderivative of sqrt(s) / sqrt(A s + B): for
A < 0 < B (a bound fall) (B/a^(3/2)) asin(sqrt(a s/B)) - sqrt(s (B - a s))/a with a =
-A; for A, B > 0 sqrt(s (A s + B))/A - (B/A^(3/2)) asinh(sqrt(A s/B)); for B < 0 < A
(b/A^(3/2)) acosh(sqrt(A s/b)) + sqrt(s (A s - b))/A with b = -B; for A = 0 < B
2 s^(3/2) / (3 sqrt(B))."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (coefficients (polynomial-coefficients-in bridge (simplified bridge `(* ,s ,(travel-energy travel)) :ratsimp) s)))
    (when (and (<= 1 (length coefficients) 2)
               (not (free-of-p s (travel-energy travel)))
               (eq (path-sign travel s) :positive))
      (destructuring-bind (b &optional (a 0)) coefficients
        (let ((a-sign (decided-sign bridge a)) (b-sign (decided-sign bridge b)))
          (cond ((and (eq a-sign :negative) (eq b-sign :positive))
                 (values `(- (* (/ ,b (expt (- ,a) 3/2)) (asin (sqrt (/ (* (- ,a) ,s) ,b))))
                             (/ (sqrt (* ,s (+ ,b (* ,a ,s)))) (- ,a)))
                         t
                         ;; at rest (the top of the fall) the sine is 1 exactly
                         (lambda (end)
                           (and (at-rest-p travel end)
                                `(* (/ ,b (expt (- ,a) 3/2)) (/ pi 2))))))
                ((and (eq a-sign :positive) (eq b-sign :positive))
                 (values `(- (/ (sqrt (* ,s (+ (* ,a ,s) ,b))) ,a)
                             (* (/ ,b (expt ,a 3/2)) (asinh (sqrt (/ (* ,a ,s) ,b)))))
                         t))
                ((and (eq a-sign :positive) (eq b-sign :negative))
                 (values `(+ (* (/ (- ,b) (expt ,a 3/2)) (acosh (sqrt (/ (* ,a ,s) (- ,b)))))
                             (/ (sqrt (* ,s (+ (* ,a ,s) ,b))) ,a))
                         t
                         (lambda (end) (and (at-rest-p travel end) 0))))
                ((and (eq a-sign :zero) (eq b-sign :positive))
                 (values `(/ (* 2 ,s (sqrt ,s)) (* 3 (sqrt ,b))) t))))))))

(defparameter *integration-timeout* 5
  "Seconds Maxima's integrate() may take in INTEGRATED-ANTIDERIVATIVE (at most the
bridge's own timeout).")

(defun integrated-antiderivative (travel)
  "Maxima's antiderivative of 1/sqrt(E), when integrate() gives one in the algebra
without asking a question. Never proven: only the numeric check can accept it (an
antiderivative may jump between the ends)."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (integrand `(/ 1 (sqrt ,(travel-energy travel))))
         (saved (bridge-timeout bridge)))
    (setf (bridge-timeout bridge) (min saved *integration-timeout*))
    (unwind-protect
         (let ((antiderivative (maxima-antiderivative bridge integrand s)))
           (when antiderivative (values antiderivative nil)))
      (setf (bridge-timeout bridge) saved))))
