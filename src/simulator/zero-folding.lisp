;;;; src/simulator/zero-folding.lisp -- the zeros of a raw expression folded in Lisp before Maxima sees it.
;;;;
;;;; A state's local series (model.lisp, EXTEND-SERIES) differentiates its expression along
;;;; the state's rates once per order, unsimplified, and evaluates each derivative at the
;;;; start: most of its terms are products with a velocity that is 0 there (a body at
;;;; rest), and the sums grow with every order. Maxima's simplifier drops them at once,
;;;; but only after the whole expression has been sent and read (the tipping block's
;;;; series: 93 ratsimps, 69 s). WITHOUT-ZEROS drops them first, in Lisp, exactly as
;;;; Maxima's simplifier would: 0 times anything is 0, 0 over anything is 0, a zero term
;;;; of a sum goes, 0 to a positive number is 0, anything to the power 0 is 1. The value
;;;; is unchanged wherever the expression is defined.

(in-package #:ames.simulator)

(defun exact-zero-p (x)
  "True when X is the exact number 0 (a float zero is left to Maxima)."
  (eql x 0))

(defun without-zeros (expression)
  "EXPRESSION (prefix) with its zeros folded (see the file header)."
  (if (atom expression)
      expression
      (let ((operator (first expression))
            (args (mapcar #'without-zeros (rest expression))))
        (case operator
          (+ (let ((terms (remove-if #'exact-zero-p args)))
               (cond ((null terms) 0) ((null (rest terms)) (first terms)) (t (cons '+ terms)))))
          (- (cond ((null (rest args)) (if (exact-zero-p (first args)) 0 (list '- (first args))))
                   (t (let ((subtrahends (remove-if #'exact-zero-p (rest args))))
                        (cond ((and (exact-zero-p (first args)) (null subtrahends)) 0)
                              ((exact-zero-p (first args)) (list '- (if (rest subtrahends)
                                                                  (cons '+ subtrahends)
                                                                  (first subtrahends))))
                              ((null subtrahends) (first args))
                              (t (list* '- (first args) subtrahends)))))))
          (* (if (some #'exact-zero-p args) 0 (cons '* args)))
          (/ (if (exact-zero-p (first args)) 0 (cons '/ args)))
          (expt (cond ((and (exact-zero-p (first args)) (realp (second args)) (plusp (second args))) 0)
                      ((exact-zero-p (second args)) 1)
                      (t (cons 'expt args))))
          (t (cons operator args))))))
