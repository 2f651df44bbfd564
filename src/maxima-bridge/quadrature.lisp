;;;; src/maxima-bridge/quadrature.lisp -- numeric travel times: adaptive Gauss-Legendre quadrature of ds / sqrt(E(s)).
;;;;
;;;; The time to travel from s0 to s1 when the squared speed is E(s) is the integral of
;;;; ds / sqrt(E(s)). E vanishes where the motion starts from rest or ends at a turning
;;;; point; there the integrand has an inverse square-root singularity. Writing
;;;; s = s0 + (s1 - s0) (1 - cos(pi u)) / 2 makes ds vanish like u (and like 1 - u) at both
;;;; ends, as sqrt(E) does at a simple zero, so the integrand in u is smooth on [0, 1] and
;;;; Gauss-Legendre converges fast. Everything is computed in Lisp double-floats through
;;;; AMES.BASE:EXPRESSION-VALUE; Maxima is asked only for an end that Lisp cannot
;;;; evaluate. Also the reference for verifying closed forms (see integrals.lisp).

(in-package #:ames.maxima)

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
[A, B], halving each piece whose two halves do not agree with it within TOLERANCE
(relative to the whole estimate). NIL when FUNCTION gives NIL somewhere, or when a piece
still disagrees after DEPTH halvings."
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
                       (cond ((<= (abs (- refined estimate)) (* tolerance scale (/ (- right left) (- b a))))
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

(defun travel-time-integral (speed-squared position start end values)
  "The integral of ds / sqrt(SPEED-SQUARED) from the double-float START to END (in
either order; the result is positive), SPEED-SQUARED an expression in POSITION and the
subjects bound by the alist VALUES (double-floats), or NIL when SPEED-SQUARED is not
positive at a node or the quadrature does not converge."
  (let* ((span (- end start))
         (factor (* (abs span) (/ pi 2)))
         (bindings (acons position 0d0 values)))
    (flet ((integrand (u)
             (let ((s (+ start (* span (/ (- 1 (cos (* pi u))) 2)))))
               (setf (cdr (first bindings)) s)
               (let ((e (expression-value speed-squared bindings)))
                 (and e (plusp e) (/ (* factor (sin (* pi u))) (sqrt (float e 1d0))))))))
      (if (zerop span) 0d0 (adaptive-integral #'integrand 0d0 1d0)))))

(defun numeric-travel-time (bridge speed-squared position from to values)
  "The time, a positive double-float, to move monotonically from POSITION = FROM to
POSITION = TO when the squared speed is SPEED-SQUARED, an expression in POSITION: the
integral of ds / sqrt(SPEED-SQUARED) between FROM and TO, to about 1e-10 relative.
VALUES is an alist (name . real) giving every other name its value. SPEED-SQUARED may
vanish at FROM or TO (a start from rest, a turning point at the end): the substitution
s = FROM + (TO - FROM) (1 - cos(pi u)) / 2 takes away those square-root singularities.
0 when FROM = TO.
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
    (or (travel-time-integral speed-squared position start end values)
        (error 'numeric-evaluation-failed
               :datum speed-squared
               :detail (format nil "the squared speed is not positive between ~,6G and ~,6G, ~
                                    or its integral does not converge" start end)))))
