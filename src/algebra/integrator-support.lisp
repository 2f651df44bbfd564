;;;; src/algebra/integrator-support.lisp -- what the integrators share: their conditions, sign decisions, pattern extraction and numeric verification.
;;;;
;;;; The integrators (travel times, linear ODEs, trigonometric roots) recognise an
;;;; expression's shape by asking Maxima through the bridge's calculus (polynomial
;;;; coefficients, derivatives; the constants A, B, C of A + B cos(k s) + C sin(k s)),
;;;; choose a closed form by the signs the current assumptions decide, and check every
;;;; answer before it leaves the algebra: symbolically when Maxima can, else at random
;;;; admissible points (points satisfying the facts in force, as witnesses.lisp draws
;;;; them) against an independent numeric computation.

(in-package #:ames.algebra)

(define-condition linear-ode-failed (solve-failed)
  ()
  (:documentation "SOLVE-LINEAR-ODES found no verified closed form: the inverse Laplace
transform failed or answered outside the algebra, or the answer did not satisfy the
equations or the initial values when substituted back. DATUM is the list of equations.")
  (:report (lambda (condition stream)
             (format-report stream "No verified closed form for the linear ODEs: ~A~@[~%  equations: ~S~]"
                            (ames-error-detail condition)
                            (ames-error-datum condition)))))

;;; Auxiliary variables (the bridge's own names, never a user's)

(defvar *laplace-variable* (make-symbol "LAPLACE-S")
  "The variable of Laplace transforms in SOLVE-LINEAR-ODES.")

(defvar *half-angle-variable* (make-symbol "HALF-ANGLE-T")
  "The variable t = tan(x/2) of EARLIEST-TRIGONOMETRIC-ROOT.")

(defvar *sample-variable* (make-symbol "SAMPLE-S")
  "The variable standing for a position or a time inside a derivative check.")

(defun simplified (bridge expression &optional (strategy :full))
  "EXPRESSION simplified by Maxima (STRATEGY, :FULL by default: the smallest of several
forms)."
  (simplify bridge expression :strategy strategy))

(defun substituted (bridge expression variable value &optional (strategy :full))
  "EXPRESSION with VARIABLE replaced by VALUE, simplified."
  (simplified bridge (substitute-expressions (list (cons variable value)) expression) strategy))

(defun decided-sign (bridge expression)
  "The sign of EXPRESSION that the current assumptions decide: :POSITIVE, :NEGATIVE or
:ZERO, or NIL when none is decided."
  (cond ((realp expression) (cond ((plusp expression) :positive)
                                  ((minusp expression) :negative)
                                  (t :zero)))
        ((eq (decide bridge (list '> expression 0)) :true) :positive)
        ((eq (decide bridge (list '< expression 0)) :true) :negative)
        ((eq (decide bridge (list '= expression 0)) :true) :zero)
        (t nil)))

(defun zero-expression-p (bridge expression)
  "True when EXPRESSION is 0 (by simplification, under the current assumptions)."
  (or (eql expression 0) (equivalent-p bridge expression 0)))

;;; Shapes

(defun trigonometric-arguments (expression variable)
  "The arguments of the sines and cosines in EXPRESSION that depend on VARIABLE, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (and (member (first x) '(sin cos tan)) (not (free-of-p variable (second x))))
                   (pushnew (second x) found :test #'equal))
                 (mapc #'walk (rest x)))))
      (walk expression))
    (nreverse found)))

(defun sinusoid-coefficients (bridge expression variable)
  "When EXPRESSION is A + B cos(k v) + C sin(k v) in the VARIABLE v, with A, B, C, k
free of v (k from the first argument of a sine or cosine, which must be linear in v),
the list (A B C k), each simplified; else NIL. The decomposition is checked: EXPRESSION
minus A + B cos(k v) + C sin(k v) simplifies to 0."
  (let ((arguments (trigonometric-arguments expression variable)))
    (when arguments
      (let ((slope (polynomial-coefficients-in bridge (first arguments) variable)))
        (when (= (length slope) 2)
          (let* ((k (second slope))
                 (at-zero (substituted bridge expression variable 0))
                 (at-half (substituted bridge expression variable `(/ pi (* 2 ,k))))
                 (at-pi (substituted bridge expression variable `(/ pi ,k)))
                 (a (simplified bridge `(/ (+ ,at-zero ,at-pi) 2)))
                 (b (simplified bridge `(/ (- ,at-zero ,at-pi) 2)))
                 (c (simplified bridge `(- ,at-half ,a))))
            (when (trigonometric-identity-p
                   bridge expression
                   `(+ ,a (* ,b (cos (* ,k ,variable))) (* ,c (sin (* ,k ,variable)))))
              (list a b c k))))))))

(defun trigonometric-identity-p (bridge x y)
  "True when the expressions X and Y are equal: EQUIVALENT-P, or X - Y with the
arguments of its sines and cosines expanded into sums (sin((pi + 2 w t)/2) into
sin(pi/2 + w t), which Maxima's trigexpand then takes apart) simplifies to 0."
  (or (equivalent-p bridge x y)
      (zero-after-trigexpand-p bridge x y)))

;;; Numeric verification

(defparameter *verification-points* 5
  "How many admissible points a numerically verified result must agree at (none may
disagree).")

(defparameter *verification-tolerance* 1d-7
  "The relative difference allowed between a closed form's value and the independent
numeric value at a verification point.")

(defun agree-p (x y)
  "True when the reals X and Y agree within *VERIFICATION-TOLERANCE*, relatively (or
absolutely, near 0)."
  (<= (abs (- x y)) (* *verification-tolerance* (max 1d-12 (abs x) (abs y)))))

(defun compare-at-admissible-points (bridge candidate reference subjects)
  "Compare the closed form CANDIDATE with REFERENCE at random points that satisfy the
facts in force: the number of points where they agree and the number where they
disagree, as two values. A point is an alist subject -> double-float over SUBJECTS (and
the subjects of the facts); REFERENCE, called on a point, returns the independent value
there, or NIL where it has none (the point lies outside the case its caller handles: it
is skipped). CANDIDATE without a real value where REFERENCE has one disagrees. Stops at
the first disagreement, or after twice *VERIFICATION-POINTS* agreements."
  (let ((agreed 0) (disagreed 0)
        (*witness-admissible-points* 40))
    (call-with-admissible-points
     bridge (list '> (if subjects (list* '+ subjects) 0) 0)
     (lambda (point)
       (let ((expected (funcall reference point)))
         (when expected
           (let ((value (expression-value candidate point)))
             (if (and value (agree-p (float value 1d0) expected))
                 (incf agreed)
                 (incf disagreed)))))
       (or (plusp disagreed) (>= agreed (* 2 *verification-points*)))))
    (values agreed disagreed)))

(defun numerically-verified-p (bridge candidate reference subjects)
  "True when CANDIDATE agrees with REFERENCE at *VERIFICATION-POINTS* or more admissible
points and disagrees at none (see COMPARE-AT-ADMISSIBLE-POINTS)."
  (multiple-value-bind (agreed disagreed)
      (compare-at-admissible-points bridge candidate reference subjects)
    (and (zerop disagreed) (>= agreed *verification-points*))))
