;;;; src/witness/complex-values.lisp -- the value of a closed form whose terms pass through
;;;; complex numbers: AMES may write a real quantity with an imaginary intermediate, such as
;;;; sqrt(-d) cosh(sqrt(-d) u) for cos(sqrt(d) u) (a spring's motion solved as if its
;;;; discriminant could have either sign). EXPRESSION-VALUE, a real evaluator, has no value
;;;; for it; the comparator then evaluates it in complex double precision and takes the
;;;; result when it is real to round-off.

(in-package #:ames.witness)

(defparameter +complex-functions+
  '(("SQRT" . sqrt) ("EXP" . exp) ("LOG" . log) ("SIN" . sin) ("COS" . cos) ("TAN" . tan)
    ("SINH" . sinh) ("COSH" . cosh) ("TANH" . tanh) ("ASIN" . asin) ("ACOS" . acos)
    ("ASINH" . asinh) ("ACOSH" . acosh) ("ATANH" . atanh) ("ABS" . abs))
  "The functions of one argument evaluated in complex arithmetic, by name.")

(defun complex-value (expression bindings)
  "EXPRESSION's value under BINDINGS in complex double-float arithmetic (+ - * / expt, the
functions of +COMPLEX-FUNCTIONS+, ATAN of one argument), or NIL when it has none."
  (labels ((value (x)
             (cond ((numberp x) (coerce x '(complex double-float)))
                   ((symbolp x)
                    (let ((entry (assoc x bindings)))
                      (cond (entry (value (cdr entry)))
                            ((string-equal (symbol-name x) "PI") (value pi))
                            (t (return-from complex-value nil)))))
                   ((not (and (consp x) (symbolp (first x)) (alexandria:proper-list-p x)))
                    (return-from complex-value nil))
                   (t (apply-operator (symbol-name (first x)) (mapcar #'value (rest x))))))
           (apply-operator (name arguments)
             (let ((function (cdr (assoc name +complex-functions+ :test #'string=))))
               (cond ((string= name "+") (apply #'+ arguments))
                     ((string= name "-") (apply #'- arguments))
                     ((string= name "*") (apply #'* arguments))
                     ((string= name "/") (if (some #'zerop (rest arguments))
                                             (return-from complex-value nil)
                                             (apply #'/ arguments)))
                     ((and (string= name "EXPT") (= 2 (length arguments)))
                      (if (and (zerop (first arguments)) (not (plusp (realpart (second arguments)))))
                          (return-from complex-value nil)
                          (expt (first arguments) (second arguments))))
                     ((and (string= name "ATAN") (= 1 (length arguments))) (atan (first arguments)))
                     ((and function (= 1 (length arguments))) (funcall function (first arguments)))
                     (t (return-from complex-value nil))))))
    (handler-case (value expression)
      (arithmetic-error () nil))))

(defun complex-real-value (expression bindings)
  "EXPRESSION's value under BINDINGS when, evaluated in complex arithmetic, it is real to
round-off (an imaginary part under 1e-9 of its size): the real part, as a double; else NIL."
  (let ((z (complex-value expression bindings)))
    (and z
         (<= (abs (imagpart z)) (* 1d-9 (max 1d0 (abs (realpart z)))))
         (realpart z))))
