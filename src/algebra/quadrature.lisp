;;;; src/algebra/quadrature.lisp -- numeric travel times: adaptive Gauss-Legendre quadrature of ds / sqrt(E(s)).
;;;;
;;;; The time to travel from s0 to s1 when the squared speed is E(s) is the integral of
;;;; ds / sqrt(E(s)). E vanishes where the motion starts from rest or ends at a turning
;;;; point; there the integrand has an inverse square-root singularity. Writing
;;;; s = s0 + (s1 - s0) sin^2(pi u / 2) makes ds vanish like u (and like 1 - u) at both
;;;; ends, as sqrt(E) does at a simple zero, so the integrand in u is smooth on [0, 1] and
;;;; Gauss-Legendre converges fast. Close to a zero of E, E(s) itself is mostly rounding
;;;; (cos(theta0) - cos(s/r)), so there E comes from its Taylor polynomial at the end,
;;;; whose coefficients Maxima computes once. The rest is Lisp double-float arithmetic
;;;; through AMES.BASE:EXPRESSION-VALUE. Also the reference for verifying closed forms
;;;; (see integrals.lisp).

(in-package #:ames.algebra)

(defparameter *gauss-legendre-16*
  (let ((x '(0.0950125098376374401853193d0 0.2816035507792589132304605d0
             0.4580167776572273863424194d0 0.6178762444026437484466718d0
             0.7554044083550030338951012d0 0.8656312023878317438804679d0
             0.9445750230732325760779884d0 0.9894009349916499325961542d0))
        (w '(0.1894506104550684962853967d0 0.1826034150449235888667637d0
             0.1691565193950025381893121d0 0.1495959888165767320815017d0
             0.1246289712555338720524763d0 0.0951585116824927848099251d0
             0.0622535239386478928628438d0 0.0271524594117540948517806d0)))
    (coerce (loop for xi in x for wi in w
                  append (list (cons (/ (- 1 xi) 2) (/ wi 2)) (cons (/ (+ 1 xi) 2) (/ wi 2))))
            'vector))
  "Sixteen-point Gauss-Legendre nodes and weights on [0, 1], as (node . weight).")

(defun gauss-legendre (function a b)
  "The 16-point Gauss-Legendre estimate of the integral of FUNCTION over [A, B], or NIL
when FUNCTION gives NIL at a node."
  (let ((width (- b a)) (sum 0d0))
    (loop for (node . weight) across *gauss-legendre-16*
          for value = (funcall function (+ a (* width node)))
          do (if value (incf sum (* weight value)) (return-from gauss-legendre nil)))
    (* sum width)))

(defun adaptive-integral (function a b &key (tolerance 1d-11) (depth 30))
  "The integral of FUNCTION (of a double-float, giving a double-float or NIL) over
[A, B], halving each piece whose two halves do not agree with it within its share of
TOLERANCE (relative to the whole estimate; at least a thousandth of it). NIL when
FUNCTION gives NIL somewhere, or when a piece still disagrees after DEPTH halvings (a
divergent integral)."
  (let ((whole (gauss-legendre function a b)))
    (when whole
      (let ((scale (max (abs whole) least-positive-normalized-double-float))
            (total 0d0)
            (pending (list (list a b whole 0))))
        (loop while pending
              do (destructuring-bind (left right estimate level) (pop pending)
                   (let* ((middle (/ (+ left right) 2))
                          (first-half (gauss-legendre function left middle))
                          (second-half (gauss-legendre function middle right)))
                     (unless (and first-half second-half)
                       (return-from adaptive-integral nil))
                     (let ((refined (+ first-half second-half)))
                       ;; a piece may err by its share of the tolerance, and a tiny piece
                       ;; (where rounding makes the integrand noisy: E near a zero at an
                       ;; end) by a thousandth of it
                       (cond ((<= (abs (- refined estimate))
                                  (* tolerance scale (max (/ (- right left) (- b a)) 1d-3)))
                              (incf total refined))
                             ((>= level depth) (return-from adaptive-integral nil))
                             (t (push (list left middle first-half (1+ level)) pending)
                                (push (list middle right second-half (1+ level)) pending)))))))
        total))))

(defun real-value (bridge expression values)
  "The double-float value of EXPRESSION under the alist VALUES, computed in Lisp, or by
Maxima's float() when Lisp gives none; NIL when it has no real value."
  (let ((value (expression-value expression values)))
    (cond (value (float value 1d0))
          (t (handler-case (numeric-value bridge expression values)
               (numeric-evaluation-failed () nil)
               (maxima-error () nil)
               (untranslatable-result () nil))))))

(defstruct (energy-profile (:constructor %make-energy-profile))
  "The squared speed EXPRESSION in the name POSITION, with its Taylor coefficients
(c0 c1 ... c4) in powers of (s - end) at FROM and at TO (expressions of the parameters;
NIL where Maxima could not differentiate). c0 is exactly 0 where the expression
simplifies to 0 at that end (a start from rest, a turning point)."
  expression position from-series to-series)

(defparameter *series-reach* 1d-3
  "Within this fraction of the path from an end, the squared speed is evaluated from its
Taylor polynomial at that end (rounding makes E(s) = cos(theta0) - cos(s/r) worthless
close to a zero; the polynomial of degree 4 errs by about the fourth power of the reach).")

(defun end-series (bridge expression position end &optional values)
  "The Taylor coefficients (c0 c1 c2 c3 c4) of EXPRESSION in POSITION at END (one round
trip), c0 exactly 0 when it simplifies to 0 (not tried when c0 is clearly not 0 under
the alist VALUES, when given); NIL when Maxima cannot give them."
  (call-or-nil
   (lambda ()
     (let* ((coefficients (taylor-coefficients bridge expression position end 4)))
       (let ((c0 (and values (expression-value (first coefficients) values)))
             (c1 (and values (expression-value (second coefficients) values))))
         (if (and (not (and c0 c1 (> (abs c0) (* 1d-9 (+ (abs c0) (abs c1))))))
                  (zero-expression-p bridge (first coefficients)))
             (cons 0 (rest coefficients))
             coefficients))))))

(defun make-energy-profile (bridge expression position from to &optional values)
  "The ENERGY-PROFILE of the squared speed EXPRESSION between FROM and TO (asks Maxima
for the derivatives; VALUES, when given, spare the zero test of an end where E is
clearly not 0 under them)."
  (%make-energy-profile :expression expression :position position
                        :from-series (end-series bridge expression position from values)
                        :to-series (end-series bridge expression position to values)))

(defun series-values (series values)
  "The coefficients of SERIES as double-floats under VALUES, or NIL."
  (loop for coefficient in series
        for value = (expression-value coefficient values)
        unless value return nil
        collect (float value 1d0)))

(defun rounded-zero-end (series span)
  "SERIES (double-float Taylor coefficients at an end of a travel of length SPAN) with a
constant term c0 that is a rounding residue of 0 put to 0: negative and under 1e-12 of
c1 SPAN (a turning point whose exact zero Maxima could not prove, written with 40-digit
radicals, evaluates to -1e-14): left as it is, E would be negative at the quadrature's
nodes nearest the end."
  (if (and series (rest series) (minusp (first series))
           (<= (abs (first series)) (* 1d-12 (abs (second series)) (abs span))))
      (cons 0d0 (rest series))
      series))

(defun polynomial-value (coefficients x)
  "c0 + c1 X + c2 X^2 + ... (Horner)."
  (reduce (lambda (c sum) (+ c (* x sum))) coefficients :from-end t :initial-value 0d0))

(defun travel-time-integral (profile start end values)
  "The integral of ds / sqrt(E) from the double-float START to END (in either order; the
result is positive), E the squared speed of the ENERGY-PROFILE PROFILE, under the alist
VALUES (double-floats); NIL when E is not positive at a node or the quadrature does not
converge. With s = START + (END - START) sin^2(pi u/2), s - START and END - s are
computed without cancellation, and near either end E comes from its Taylor polynomial."
  (let* ((span (- end start))
         (factor (* (abs span) (/ pi 2)))
         (reach (* *series-reach* (abs span)))
         (from-series (rounded-zero-end (series-values (energy-profile-from-series profile) values) span))
         (to-series (rounded-zero-end (series-values (energy-profile-to-series profile) values) span))
         (expression (energy-profile-expression profile))
         (bindings (acons (energy-profile-position profile) 0d0 values)))
    (flet ((integrand (u)
             (let* ((after-start (* span (expt (sin (* pi u 1/2)) 2)))
                    (before-end (* span (expt (cos (* pi u 1/2)) 2)))
                    (e (cond ((and from-series (<= (abs after-start) reach))
                              (polynomial-value from-series after-start))
                             ((and to-series (<= (abs before-end) reach))
                              (polynomial-value to-series (- before-end)))
                             (t (setf (cdr (first bindings)) (+ start after-start))
                                (expression-value expression bindings)))))
               (and e (plusp e) (/ (* factor (sin (* pi u))) (sqrt (float e 1d0)))))))
      (if (zerop span) 0d0 (adaptive-integral #'integrand 0d0 1d0)))))

(defun numeric-travel-time (bridge speed-squared position from to values)
  "The time, a positive double-float, to move monotonically from POSITION = FROM to
POSITION = TO when the squared speed is SPEED-SQUARED, an expression in POSITION: the
integral of ds / sqrt(SPEED-SQUARED) between FROM and TO, to about 1e-10 relative.
VALUES is an alist (name . real) giving every other name its value. SPEED-SQUARED may
vanish at FROM or TO (a start from rest, a turning point at the end): the substitution
s = FROM + (TO - FROM) sin^2(pi u/2) takes away those square-root singularities, and
near each end the squared speed is taken from its Taylor polynomial there (Maxima
differentiates it once; a zero at an end is recognised exactly), so that rounding near
a zero does no harm. 0 when FROM = TO.
Signals INVALID-BRIDGE-ARGUMENT for a POSITION that is no name or malformed VALUES,
UNTRANSLATABLE-EXPRESSION for an expression outside the algebra, and
NUMERIC-EVALUATION-FAILED when FROM or TO has no real value, or when SPEED-SQUARED is
not positive (or not real) somewhere strictly between them, or the quadrature does not
converge (a double zero of SPEED-SQUARED at an end: the time is infinite)."
  (unless (subject-p position)
    (error 'invalid-bridge-argument :datum position
                                    :detail "the position must be a variable or a quantity term"))
  (unless (and (alexandria:proper-list-p values)
               (every (lambda (b) (and (consp b) (subject-p (car b)) (realp (cdr b)))) values))
    (error 'invalid-bridge-argument :datum values
                                    :detail "values must be an alist (name . real number)"))
  (dolist (expression (list speed-squared from to))
    (check-translatable expression :arithmetic))
  (let* ((values (mapcar (lambda (b) (cons (car b) (float (cdr b) 1d0))) values))
         (start (real-value bridge from values))
         (end (real-value bridge to values)))
    (unless (and start end)
      (error 'numeric-evaluation-failed :datum (list from to)
                                        :detail "an end of the travel has no real value"))
    (or (travel-time-integral (make-energy-profile bridge speed-squared position from to values)
                              start end values)
        (error 'numeric-evaluation-failed
               :datum speed-squared
               :detail (format nil "the squared speed is not positive between ~,6G and ~,6G, ~
                                    or its integral does not converge" start end)))))
