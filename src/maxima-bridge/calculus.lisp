;;;; src/maxima-bridge/calculus.lisp -- the calculus the integrators ask of Maxima: derivatives, coefficients, series, antiderivatives, inverse Laplace transforms, root counts.
;;;;
;;;; Each operation takes and returns AMES's prefix algebra, like those of operations.lisp;
;;;; the integrators of the algebra layer (src/algebra/) decide what to do with the answers.
;;;; CALL-OR-NIL is the one way to try a request whose failure only means "not this way".

(in-package #:ames.maxima)

(defun mquotient (a b)
  "The Maxima form of the quotient of the Maxima forms A and B (A B^-1)."
  (mform +mtimes+ a (mform +mexpt+ b -1)))

(defun call-or-nil (function)
  "FUNCTION's values, or NIL when Maxima asks a question, fails, times out, or answers
outside the algebra: for the attempts whose failure only means that another way must
be tried (never for an answer that is returned unchecked)."
  (handler-case (funcall function)
    (maxima-question () nil)
    (maxima-error () nil)
    (maxima-timeout () nil)
    (untranslatable-result () nil)
    (inconsistent-assumptions () nil)
    (solve-failed () nil)))

(defun auxiliary-variable (bridge symbol)
  "SYMBOL (an uninterned symbol held by the integrators) registered in BRIDGE's name
table as one of the bridge's own $AMESX names, so that it can never meet a user's name;
returns SYMBOL, which then translates like any variable."
  (maxima-name (bridge-names bridge) symbol "$AMESX")
  symbol)

(defun keyed-auxiliary-variable (bridge key name)
  "The auxiliary variable (see AUXILIARY-VARIABLE) BRIDGE keeps for KEY (compared with
EQUAL): made the first time as an uninterned symbol called NAME, the same one each time
after, so that requests written with it come again from the cache."
  (let ((table (bridge-excess-names bridge)))
    (or (gethash key table)
        (setf (gethash (copy-tree key) table)
              (auxiliary-variable bridge (make-symbol name))))))

(defun maxima-derivative (bridge expression variable)
  "The derivative of EXPRESSION with respect to the name VARIABLE, by Maxima, ratsimped.
Signals UNTRANSLATABLE-RESULT when Maxima leaves it unevaluated (a derivative of
jacobi_am, say)."
  (from-mx bridge (maxima-request bridge (mcall "$RATSIMP" (mcall "$DIFF" (to-mx bridge expression)
                                                                  (to-mx bridge variable)))
                                  :datum expression)))

(defun polynomial-coefficients-in (bridge expression variable)
  "The coefficients (c0 c1 ... cd) of EXPRESSION as a polynomial in VARIABLE (prefix,
free of VARIABLE, simplified), or NIL when it is not one. Unlike
POLYNOMIAL-COEFFICIENTS (for the reports), a quotient whose denominator is free of
VARIABLE counts as a polynomial."
  (let* ((form (to-mx bridge expression))
         (answers (request-list bridge (list (mcall "$AMES_POLYNOMIAL_COEFFICIENTS" form (to-mx bridge variable))
                                             (mcall "$DENOM" (mcall "$RATSIMP" form)))
                                :datum expression))
         (numerator (first answers))
         (denominator (second answers)))
    ;; ames_polynomial_coefficients gives the numerator's coefficients (its denominator
    ;; is then free of VARIABLE)
    (and (not (eq numerator +false+))
         (call-or-nil
          (lambda ()
            (mapcar (lambda (c)
                      (from-mx bridge (maxima-request bridge (mcall "$RATSIMP" (mquotient c denominator))
                                                      :datum expression)))
                    (mlist-items numerator)))))))

(defun zero-after-trigexpand-p (bridge x y)
  "True when X - Y, with the arguments of its sines and cosines expanded into sums
(sin((pi + 2 w t)/2) into sin(pi/2 + w t), which trigexpand then takes apart), ratsimps
to 0, with or without trigsimp, or (trigexpand twice) with radcan where radicals remain (a phase asin(q)
expands into cos(asin q) = sqrt(1 - q^2), which ratsimp keeps apart from the same root
written sqrt(l) w sqrt(6 g - l w^2))."
  (let* ((difference (mdifference (to-mx bridge x) (to-mx bridge y)))
         (expanded (mcall "$TRIGEXPAND" (mcall "$EXPAND" difference))))
    (flet ((zero-p (form) (eql 0 (maxima-request bridge form :datum (list '- x y)))))
      (or (zero-p (mcall "$RATSIMP" expanded))
          (zero-p (mcall "$RATSIMP" (mcall "$AMES_TRIGSIMP" expanded)))
          (and (radical-form-p difference)
               ;; trigexpand again: sin(pi + 2 atan z) comes out of the first as
               ;; -sin(2 atan z), a multiple angle the second takes apart
               (zero-p (mcall "$RATSIMP" (mcall "$RADCAN" (mcall "$TRIGEXPAND" expanded)))))))))

(defun taylor-coefficients (bridge expression variable at degree)
  "The Taylor coefficients (c0 c1 ... c_DEGREE) of EXPRESSION in VARIABLE at AT (c_k the
k-th derivative at AT over k!), ratsimped, in one round trip."
  (let ((form (to-mx bridge expression))
        (s (to-mx bridge variable))
        (point (to-mx bridge at)))
    (mapcar (lambda (c) (from-mx bridge c))
            (request-list bridge
                          (loop for k from 0 to degree
                                for factorial = 1 then (* factorial k)
                                collect (mcall "$RATSIMP"
                                               (mquotient (mcall "$SUBSTITUTE" point s
                                                                 (if (zerop k) form (mcall "$DIFF" form s k)))
                                                          factorial)))
                          :datum expression))))

(defun one-sided-taylor-coefficients (bridge expression variable degree)
  "The coefficients (c0 c1 ... c_DEGREE) of Maxima's truncated Taylor series of
EXPRESSION in VARIABLE about 0, VARIABLE > 0 (a one-sided expansion: the square root of
VARIABLE^2 is VARIABLE), simplified; NIL when the truncated series is no polynomial in
VARIABLE (a pole, a fractional power, an abs() left) or Maxima cannot expand it. For a
function that is smooth on VARIABLE > 0 but whose derivatives cannot be evaluated at 0
\(|v| v at v = 0)."
  (call-or-nil
   (lambda ()
     (let* ((s (to-mx bridge variable))
            (series (maxima-request bridge (mcall "$RATDISREP"
                                                  (mcall "$TAYLOR" (to-mx bridge expression) s 0 degree))
                                    :datum expression))
            (coefficients (polynomial-coefficients-in bridge (from-mx bridge series) variable)))
       (and coefficients
            (<= (length coefficients) (1+ degree))
            (append coefficients (make-list (- (1+ degree) (length coefficients))
                                            :initial-element 0)))))))

(defun maxima-antiderivative (bridge integrand variable)
  "Maxima's antiderivative of INTEGRAND in VARIABLE, or NIL when integrate() leaves an
integral in it. Signals what MAXIMA-REQUEST signals (a question, a timeout) and
UNTRANSLATABLE-RESULT."
  (let ((answer (maxima-request bridge (mcall "$INTEGRATE" (to-mx bridge integrand) (to-mx bridge variable))
                                :datum integrand)))
    (unless (contains-head-p +integrate-noun+ answer)
      (from-mx bridge answer))))

(defun inverse-laplace-transform (bridge transform variable time datum)
  "ilt(TRANSFORM, VARIABLE, TIME) in its simplest form, in prefix algebra. Signals
UNTRANSLATABLE-RESULT when the answer is outside the algebra."
  (let ((answer (maxima-request bridge (mcall "$ILT" (to-mx bridge transform)
                                              (to-mx bridge variable) (to-mx bridge time))
                                :datum datum)))
    (simplest-form bridge answer transform)))

(defun maxima-root-count (bridge polynomial low high &key datum)
  "Maxima's nroots: the number of real roots of the univariate POLYNOMIAL in (LOW, HIGH]."
  (maxima-request bridge (mcall "$NROOTS" (to-mx bridge polynomial) (to-mx bridge low) (to-mx bridge high))
                  :datum datum))
