;;;; src/check/evaluate.lisp -- the self-check's own evaluator of the prefix algebra in doubles.
;;;;
;;;; COMPILE-NUMERIC turns an expression over named variables (symbols and quantity terms)
;;;; into a closure over a simple-vector of their values. It is written apart from the
;;;; simulator's numeric integrator and from Maxima on purpose: the check must not repeat
;;;; the computation it checks. A value that is not a finite real (the root of a negative,
;;;; a division by zero, an overflow) is an ARITHMETIC-ERROR, which callers turn into "no
;;;; value here".

(in-package #:ames.check)

(define-condition unevaluable (ames-error) ()
  (:documentation "An expression holds an operator or a name the self-check cannot give
a number to. DATUM is the offending form."))

(defun invalid ()
  "Signal that a value is not a finite real."
  (error 'floating-point-invalid-operation))

(defun finite (x)
  "X, a double, or an arithmetic error when it is not a finite real."
  (if (and (realp x) (< (abs x) most-positive-double-float)) x (invalid)))

(defun special-value (operator arguments)
  "The value of a special function of the algebra (ames.base's numeric library)."
  (or (special-function-value operator arguments) (invalid)))

(defun unary-function (operator)
  "The double function for the unary OPERATOR, or NIL."
  (case operator
    (sqrt (lambda (a) (if (minusp a) (invalid) (sqrt a))))
    (exp #'exp)
    (log (lambda (a) (if (plusp a) (log a) (invalid))))
    (sin #'sin) (cos #'cos) (tan #'tan) (abs #'abs)
    (asin (lambda (a) (if (<= -1 a 1) (asin a) (invalid))))
    (acos (lambda (a) (if (<= -1 a 1) (acos a) (invalid))))))

(defun accurate-constant (x)
  "The value of X as a double when X is a constant form (no names) holding numbers
beyond a double's 53 bits, from exact intervals (ACCURATE-VALUE): a root's
coefficients of 60 digits times radicals cancel far beyond a double's digits, and
evaluated in doubles gave a position of 8 for one of 0.296. NIL otherwise."
  (and (consp x) (not (quantity-term-p x))
       (big-number-p x)
       (null (expression-variables x))
       (accurate-value x)))

(defun compile-numeric (expression variables)
  "A function of a simple-vector of doubles (the values of VARIABLES, symbols or quantity
terms, in order) returning EXPRESSION's value as a double, or signalling ARITHMETIC-ERROR
where it has none. Signals UNEVALUABLE for a name not among VARIABLES or an operator
this evaluator does not know."
  (labels ((build (x)
             (let ((index (and (or (symbolp x) (consp x)) (position x variables :test #'equal))))
               (cond (index (lambda (v) (svref v index)))
                     ((realp x) (let ((d (coerce x 'double-float))) (lambda (v) (declare (ignore v)) d)))
                     ((eq x 'pi) (lambda (v) (declare (ignore v)) pi))
                     ((accurate-constant x)
                      (let ((d (accurate-constant x))) (lambda (v) (declare (ignore v)) d)))
                     ((or (atom x) (quantity-term-p x))
                      (error 'unevaluable :datum x :detail "The self-check has no value for this name."))
                     (t (operation (first x) (mapcar #'build (rest x)) x)))))
           (operation (operator args form)
             (let ((a (first args)) (b (second args)))
               (case operator
                 (+ (lambda (v) (let ((s 0d0)) (dolist (f args s) (incf s (funcall f v))))))
                 (* (lambda (v) (let ((s 1d0)) (dolist (f args s) (setf s (* s (funcall f v)))))))
                 (- (if (rest args)
                        (lambda (v) (let ((s (funcall a v))) (dolist (f (rest args) s) (decf s (funcall f v)))))
                        (lambda (v) (- (funcall a v)))))
                 (/ (if (rest args)
                        (lambda (v) (let ((s (funcall a v)))
                                      (dolist (f (rest args) (finite s))
                                        (let ((d (funcall f v))) (if (zerop d) (invalid) (setf s (/ s d)))))))
                        (lambda (v) (let ((d (funcall a v))) (if (zerop d) (invalid) (/ d))))))
                 (expt (let ((power (third form)))
                         (if (integerp power)
                             (lambda (v) (let ((x (funcall a v)))
                                           (if (and (zerop x) (minusp power)) (invalid) (finite (expt x power)))))
                             (lambda (v) (let ((x (funcall a v)) (p (funcall b v)))
                                           (cond ((plusp x) (finite (expt x p)))
                                                 ((and (zerop x) (plusp p)) 0d0)
                                                 (t (invalid))))))))
                 (atan (if b
                           (lambda (v) (atan (funcall a v) (funcall b v)))
                           (lambda (v) (atan (funcall a v)))))
                 (t (let ((unary (and (null b) (unary-function operator))))
                      (cond (unary (lambda (v) (funcall unary (funcall a v))))
                            ((member operator '(sinh cosh tanh asinh acosh atanh elliptic-k elliptic-f elliptic-e
                                                jacobi-sn jacobi-cn jacobi-dn jacobi-am gamma-function))
                             (lambda (v) (special-value operator (mapcar (lambda (f) (funcall f v)) args))))
                            (t (error 'unevaluable :datum form
                                                   :detail "The self-check cannot evaluate this operator.")))))))))
    (build expression)))

(defun value-under (expression bindings)
  "EXPRESSION's value as a double under BINDINGS (an alist name -> number), or NIL where
it has none. Signals UNEVALUABLE as COMPILE-NUMERIC does."
  (let ((function (compile-numeric expression (mapcar #'car bindings)))
        (vector (map 'simple-vector (lambda (entry) (coerce (cdr entry) 'double-float)) bindings)))
    (handler-case (funcall function vector)
      (arithmetic-error () nil))))

(defun round-off-form (expression)
  "An expression whose value bounds the magnitude the round-off of EXPRESSION's double
value is relative to: sums and differences add their terms' sizes, products multiply
them, a quotient divides by the denominator's size, a power of a non-negative constant
exponent raises the base's; a sine or cosine adds its argument's (an error in the
argument moves it by as much), an exponential multiplies by one plus it; any other
operand counts by its size."
  (flet ((size (x) (if (realp x) (abs x) `(abs ,x))))
    (if (atom expression)
        (size expression)
        (let ((arguments (rest expression)))
          (case (first expression)
            ((+ -) (cons '+ (mapcar #'round-off-form arguments)))
            (* (cons '* (mapcar #'round-off-form arguments)))
            (/ (if (rest arguments)
                   `(/ ,(round-off-form (first arguments)) ,@(mapcar #'size (rest arguments)))
                   `(/ 1 ,(size (first arguments)))))
            (sqrt `(sqrt ,(round-off-form (first arguments))))
            (expt (let ((power (second arguments)))
                    (if (and (realp power) (>= power 0))
                        `(expt ,(round-off-form (first arguments)) ,power)
                        (size expression))))
            ((sin cos) `(+ ,(size expression) ,(round-off-form (first arguments))))
            (exp `(* ,expression (+ 1 ,(round-off-form (first arguments)))))
            (t (size expression)))))))
