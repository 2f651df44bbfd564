;;;; src/base/special-functions.lisp -- numeric values of the hyperbolic, elliptic and Jacobi functions of the algebra.
;;;;
;;;; The conventions are Maxima's (and Abramowitz and Stegun's): every elliptic function
;;;; takes the PARAMETER m (not the modulus k = sqrt(m)).
;;;;   (elliptic-f phi m) = integral from 0 to phi of dt / sqrt(1 - m sin^2 t)
;;;;   (elliptic-e phi m) = integral from 0 to phi of sqrt(1 - m sin^2 t) dt
;;;;   (elliptic-k m)     = (elliptic-f pi/2 m)
;;;;   (jacobi-am u m)    = the phi with (elliptic-f phi m) = u; sn = sin am, cn = cos am,
;;;;   dn = sqrt(1 - m sn^2) (for m <= 1).
;;;; The values are double-floats computed with Carlson's symmetric integrals R_F and R_D
;;;; (duplication) and the arithmetic-geometric mean (descending Landen), to about 1e-14.
;;;; Where a function is not real (K(m) for m >= 1, an amplitude beyond the first well
;;;; for m > 1) or not implemented cheaply (Jacobi's functions for m < 0), the value is
;;;; NIL: callers then leave the question to Maxima's float().

(in-package #:ames.base)

(defun carlson-rf (x y z)
  "Carlson's R_F(X, Y, Z) = 1/2 integral_0^inf dt / sqrt((t+X)(t+Y)(t+Z)), for X, Y, Z
>= 0 with at most one zero (double-floats)."
  (loop
    (let* ((mean (/ (+ x y z) 3))
           (dx (- 1 (/ x mean))) (dy (- 1 (/ y mean))) (dz (- 1 (/ z mean))))
      (when (< (max (abs dx) (abs dy) (abs dz)) 1d-4)
        ;; the series of R_F in the deviations, to fifth order (error below 1e-19)
        (let ((e2 (- (* dx dy) (* dz dz))) (e3 (* dx dy dz)))
          (return (/ (+ 1 (/ e2 -10) (/ e3 14) (/ (* e2 e2) 24) (* -3/44 e2 e3))
                     (sqrt mean)))))
      (let ((lambda (+ (* (sqrt x) (sqrt y)) (* (sqrt x) (sqrt z)) (* (sqrt y) (sqrt z)))))
        (setf x (/ (+ x lambda) 4) y (/ (+ y lambda) 4) z (/ (+ z lambda) 4))))))

(defun carlson-rd (x y z)
  "Carlson's R_D(X, Y, Z) = 3/2 integral_0^inf dt / ((t+Z) sqrt((t+X)(t+Y)(t+Z))), for
X, Y >= 0 (not both zero) and Z > 0 (double-floats)."
  (let ((sum 0d0) (factor 1d0))
    (loop
      (let* ((mean (/ (+ x y (* 3 z)) 5))
             (dx (- 1 (/ x mean))) (dy (- 1 (/ y mean))) (dz (- 1 (/ z mean))))
        (when (< (max (abs dx) (abs dy) (abs dz)) 1d-4)
          (let* ((ea (* dx dy)) (eb (* dz dz)) (ec (- ea eb)) (ed (- ea (* 6 eb)))
                 (ee (+ ed ec ec)))
            (return (+ (* 3 sum)
                       (/ (* factor
                             (+ 1 (* ed (+ -3/14 (* 9/88 ed) (* -9/52 dz ee)))
                                (* dz (+ (* 1/6 ee) (* dz (+ (* -9/22 ec) (* dz 3/26 ea)))))))
                          (* mean (sqrt mean)))))))
        (let ((lambda (+ (* (sqrt x) (sqrt y)) (* (sqrt x) (sqrt z)) (* (sqrt y) (sqrt z)))))
          (incf sum (/ factor (* (sqrt z) (+ z lambda))))
          (setf factor (/ factor 4)
                x (/ (+ x lambda) 4) y (/ (+ y lambda) 4) z (/ (+ z lambda) 4)))))))

(defun complete-elliptic-k (m)
  "K(M) for M < 1, else NIL (infinite at 1, complex beyond)."
  (and (< m 1) (carlson-rf 0d0 (- 1 m) 1d0)))

(defun complete-elliptic-e (m)
  "E(M) for M <= 1, else NIL."
  (cond ((= m 1) 1d0)
        ((< m 1) (- (carlson-rf 0d0 (- 1 m) 1d0)
                    (* (/ m 3) (carlson-rd 0d0 (- 1 m) 1d0))))
        (t nil)))

(defun reduced-amplitude (phi)
  "PHI = N pi + R with R in [-pi/2, pi/2]: the values N (an integer) and R."
  (let ((n (round phi pi)))
    (values n (- phi (* n pi)))))

(defun incomplete-elliptic (phi m kind)
  "F(PHI | M) (KIND :F) or E(PHI | M) (KIND :E) as a double-float, or NIL where it is
not real: for M > 1 beyond the first well |sin PHI| <= 1/sqrt(M) around 0, for M = 1
(KIND :F) at or beyond |PHI| = pi/2."
  (multiple-value-bind (n r) (reduced-amplitude phi)
    (let* ((s (sin r)) (c (cos r)) (delta (- 1 (* m s s))))
      (when (and (or (zerop n) (< m 1))
                 (>= delta 0)
                 (not (and (eq kind :f) (zerop delta))))
        (let ((c2 (* c c)))
          ;; R_F(0, 0, 1) diverges: F(pi/2 | 1) is infinite, E(pi/2 | 1) = 1
          (when (and (zerop c2) (zerop delta))
            (return-from incomplete-elliptic (and (eq kind :e) (float-sign s 1d0))))
          (let ((principal
                  (if (zerop s)
                      0d0
                      (ecase kind
                        (:f (* s (carlson-rf c2 delta 1d0)))
                        (:e (- (* s (carlson-rf c2 delta 1d0))
                               (* (/ m 3) s s s (carlson-rd c2 delta 1d0))))))))
            (if (zerop n)
                principal
                (+ principal (* 2 n (ecase kind
                                      (:f (complete-elliptic-k m))
                                      (:e (complete-elliptic-e m))))))))))))

(defun jacobi-amplitude (u m)
  "am(U | M) for 0 <= M <= 1 (the arithmetic-geometric mean, Abramowitz and Stegun
16.4), else NIL."
  (cond ((or (< m 0) (> m 1)) nil)
        ((zerop m) u)
        ((= m 1) (atan (sinh u)))
        (t (let ((a 1d0) (b (sqrt (- 1 m))) (cs '()) (as '()))
             (loop repeat 40
                   do (let ((c (/ (- a b) 2)))
                        (psetf a (/ (+ a b) 2) b (sqrt (* a b)))
                        (push c cs) (push a as))
                   until (< (abs (first cs)) 1d-17))
             ;; phi_N = 2^N a_N u, then phi_(n-1) = (phi_n + asin(c_n sin(phi_n) / a_n)) / 2
             (let ((phi (* (expt 2 (length cs)) (first as) u)))
               (loop for c in cs for an in as
                     do (setf phi (/ (+ phi (asin (max -1d0 (min 1d0 (/ (* c (sin phi)) an))))) 2)))
               phi)))))

(defun jacobi-values (u m)
  "sn, cn and dn of (U | M) as three values, or NIL: for M > 1 through the reciprocal
parameter (sn(u|m) = sn(u sqrt m | 1/m)/sqrt m, cn(u|m) = dn(u sqrt m | 1/m), dn(u|m) =
cn(u sqrt m | 1/m)); NIL for M < 0."
  (if (> m 1)
      (let ((root (sqrt m)))
        (multiple-value-bind (sn cn dn) (jacobi-values (* u root) (/ m))
          (and sn (values (/ sn root) dn cn))))
      (let ((am (jacobi-amplitude u m)))
        (and am (let ((sn (sin am)))
                  (values sn (cos am) (sqrt (max 0d0 (- 1 (* m sn sn))))))))))

(defparameter +lanczos-coefficients+
  '(0.99999999999980993d0 676.5203681218851d0 -1259.1392167224028d0 771.32342877765313d0
    -176.61502916214059d0 12.507343278686905d0 -0.13857109526572012d0
    9.9843695780195716d-6 1.5056327351493116d-7)
  "Lanczos's coefficients for g = 7, n = 9 (about 15 significant digits).")

(defun gamma-value (x)
  "Euler's gamma function at the double X, or NIL at a pole (0, -1, -2, ...); by the
reflection formula below 1/2, else Lanczos's approximation."
  (cond ((and (<= x 0) (= x (fround x))) nil)
        ((< x 1/2) (let ((other (gamma-value (- 1 x))))
                     (and other (/ pi (* (sin (* pi x)) other)))))
        (t (let* ((x (- x 1))
                  (sum (first +lanczos-coefficients+))
                  (t7 (+ x 7.5d0)))
             (loop for c in (rest +lanczos-coefficients+) for i from 1
                   do (incf sum (/ c (+ x i))))
             (* (sqrt (* 2 pi)) (expt t7 (+ x 0.5d0)) (exp (- t7)) sum)))))

(defun special-function-value (operator arguments)
  "The value of the hyperbolic, elliptic or Jacobi OPERATOR of the algebra at the real
ARGUMENTS, as a double-float, or NIL where it is not real or not computed here (see the
file header). May signal ARITHMETIC-ERROR on overflow."
  (destructuring-bind (x &optional y) (mapcar (lambda (a) (float a 1d0)) arguments)
    (ecase operator
      (sinh (sinh x))
      (cosh (cosh x))
      (tanh (tanh x))
      (asinh (if (> (abs x) 1d100)
                 (* (signum x) (+ (log 2d0) (log (abs x))))
                 (asinh x)))
      (acosh (cond ((< x 1) nil)
                   ((> x 1d100) (+ (log 2d0) (log x)))
                   (t (acosh x))))
      (atanh (and (< (abs x) 1) (atanh x)))
      (elliptic-k (complete-elliptic-k x))
      (gamma-function (gamma-value x))
      (elliptic-f (incomplete-elliptic x y :f))
      (elliptic-e (incomplete-elliptic x y :e))
      (jacobi-am (if (> y 1)
                     ;; |am| stays below asin(1/sqrt m) < pi/2: am = asin(sn)
                     (let ((sn (jacobi-values x y))) (and sn (asin sn)))
                     (jacobi-amplitude x y)))
      ((jacobi-sn jacobi-cn jacobi-dn)
       (multiple-value-bind (sn cn dn) (jacobi-values x y)
         (and sn (ecase operator (jacobi-sn sn) (jacobi-cn cn) (jacobi-dn dn))))))))
