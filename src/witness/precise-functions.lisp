;;;; src/witness/precise-functions.lisp -- roots, pi, sin, cos, tan, atan, asin and acos of
;;;; rationals to +PRECISE-DIGITS+ digits, in rational arithmetic (PRECISE-VALUE, compare.lisp).
;;;;
;;;; AMES's exact closed forms can hold 40-digit radicals inside sines and inverse tangents
;;;; (an arc length where a particle turns in a loop); in double precision their terms, near
;;;; 1e25, cancel to rounding (1e9), and a speed that is exactly 0 at a turning point comes
;;;; out as the square root of a negative number. Computed here to 160 digits instead:
;;;; fixed-point series (each term rounded to 10^-(digits + 10)), arguments reduced first
;;;; (atan by the half-angle formula below 1/4, sin and cos modulo 2 pi), pi by Machin's
;;;; formula.

(in-package #:ames.witness)

(defconstant +precise-digits+ 160
  "The decimal digits kept by PRECISE-VALUE's roots: AMES's exact closed forms can be
nested radicals whose terms, near 1e75, cancel down to order 1.")

(defun integer-nth-root (n q)
  "The largest integer r >= 0 with r^q <= n (n >= 0), by Newton's method."
  (if (< n 2)
      n
      (let ((x (ash 1 (ceiling (integer-length n) q))))
        (loop (let ((y (floor (+ (* (1- q) x) (floor n (expt x (1- q)))) q)))
                (when (>= y x) (return x))
                (setf x y))))))

(defun precise-root (x q)
  "The Q-th root of the rational X >= 0 to +PRECISE-DIGITS+ digits, as a rational."
  (let ((scale (expt 10 +precise-digits+)))
    (/ (integer-nth-root (floor (* x (expt scale q))) q) scale)))

(defun precise-zero ()
  "The size under which a precise value is 0 to the digits kept (half of them: room for
operands up to 1e80)."
  (expt 10 (- (floor +precise-digits+ 2))))

(defun fixed-point (x)
  "The rational X rounded to +PRECISE-DIGITS+ + 10 decimals (the series' guard digits)."
  (let ((scale (expt 10 (+ +precise-digits+ 10))))
    (/ (round (* x scale)) scale)))

(defun atan-series (x)
  "atan X for a rational |X| <= 1/4: its Taylor series, to the digits kept."
  (let ((x2 (fixed-point (* x x))) (limit (expt 10 (- (+ +precise-digits+ 10)))))
    (loop for k from 0
          for power = x then (fixed-point (* power x2))
          for term = (/ power (1+ (* 2 k)))
          while (> (abs term) limit)
          sum (if (evenp k) term (- term)))))

(defvar *precise-pi* nil "Pi to the digits kept, once computed.")

(defun precise-pi ()
  "Pi to +PRECISE-DIGITS+ digits (Machin: 16 atan(1/5) - 4 atan(1/239))."
  (or *precise-pi*
      (setf *precise-pi* (fixed-point (- (* 16 (atan-series 1/5)) (* 4 (atan-series 1/239)))))))

(defun precise-atan (x)
  "atan X for a rational X, to the digits kept."
  (cond ((minusp x) (- (precise-atan (- x))))
        ((> x 1) (- (/ (precise-pi) 2) (precise-atan (/ x))))
        ((> x 1/4) (* 2 (precise-atan (fixed-point (/ x (+ 1 (precise-root (+ 1 (* x x)) 2)))))))
        (t (atan-series x))))

(defun sine-series (x &optional (first-power 1))
  "sin X (FIRST-POWER 1) or cos X (FIRST-POWER 0) for a rational |X| <= pi: the Taylor
series, to the digits kept."
  (let ((x2 (fixed-point (* x x))) (limit (expt 10 (- (+ +precise-digits+ 10)))))
    (loop for n from first-power by 2
          for k from 0
          for term = (if (= n 1) x 1) then (fixed-point (/ (* term x2) (* (1- n) n)))
          while (> (abs term) limit)
          sum (if (evenp k) term (- term)))))

(defun precise-function (name x)
  "The function NAME (SIN COS TAN ATAN ASIN ACOS, by symbol name) of the rational X to
+PRECISE-DIGITS+ digits, or NIL outside its real domain (or a tangent at a pole)."
  (let ((name (symbol-name name)))
    (flet ((reduced (x)
             (let ((two-pi (* 2 (precise-pi))))
               (- x (* two-pi (round x two-pi))))))
      (cond ((string= name "SIN") (sine-series (reduced x) 1))
            ((string= name "COS") (sine-series (reduced x) 0))
            ((string= name "TAN") (let ((c (sine-series (reduced x) 0)))
                                    (and (> (abs c) (precise-zero)) (/ (sine-series (reduced x) 1) c))))
            ((string= name "ATAN") (precise-atan x))
            ((or (string= name "ASIN") (string= name "ACOS"))
             (let ((asin (cond ((> (abs x) 1) (return-from precise-function nil))
                               ((= (abs x) 1) (* (signum x) (/ (precise-pi) 2)))
                               (t (precise-atan (fixed-point (/ x (precise-root (- 1 (* x x)) 2))))))))
               (if (string= name "ASIN") asin (- (/ (precise-pi) 2) asin))))))))
