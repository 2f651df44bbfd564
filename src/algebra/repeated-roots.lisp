;;;; src/algebra/repeated-roots.lisp -- a polynomial's repeated factors taken once: the
;;;; earliest-root search's second try, and the readable facts of an undecided one.
;;;;
;;;; A gap that a point closes along a tangent of a circle is a square, (s - r)^2 q(s): its
;;;; root is a double one, which solve() writes in radicals that Maxima's factor() divides
;;;; by zero on, and whose sign facts (the discriminant of a quartic) nobody can read. The
;;;; same roots, none repeated, come from its square-free part (the bridge's
;;;; SQUARE-FREE-POLYNOMIAL), of lower degree: a square of a quadratic is the quadratic.

(in-package #:ames.algebra)

(defun polynomial-root-by-degree (search form offset-variable coefficients)
  "The earliest root of the polynomial FORM with COEFFICIENTS, by its degree."
  (case (1- (length coefficients))
    (0 (constant-earliest-root search (first coefficients)))
    (1 (linear-earliest-root search coefficients))
    (2 (quadratic-earliest-root search coefficients form offset-variable))
    (t (solved-earliest-root search form offset-variable coefficients))))

(defun polynomial-earliest-root (search form offset-variable coefficients)
  "The earliest root of the polynomial FORM with COEFFICIENTS. One of degree 3 or more
that the search leaves undecided, or on which Maxima fails (solve()'s radicals of a
double root, which factor() divides by zero on), is searched again with each factor it
repeats taken once (SQUARE-FREE-POLYNOMIAL: the same roots, a touching gap's double
root a simple one, the degree lower): that answer when it is decided or the first
failed, else the first."
  (flet ((first-answer ()
           (handler-case (multiple-value-list
                          (polynomial-root-by-degree search form offset-variable coefficients))
             (maxima-error (condition) condition))))
    (let ((answer (first-answer)))
      (when (or (and (listp answer) (not (eq (first answer) :unknown)))
                (< (length coefficients) 4)
                (every #'numeric-root-form-p coefficients))
        (return-from polynomial-earliest-root
          (if (listp answer) (values-list answer) (error answer))))
      (multiple-value-bind (reduced reduced-coefficients)
          (call-or-nil (lambda ()
                         (square-free-polynomial (search-bridge search) form offset-variable
                                                 :datum (search-expression search))))
        (let ((second (and reduced (< (length reduced-coefficients) (length coefficients))
                           (handler-case (multiple-value-list
                                          (polynomial-root-by-degree search reduced offset-variable
                                                                     reduced-coefficients))
                             (maxima-error () nil)))))
          (cond ((and second (not (eq (first second) :unknown))) (values-list second))
                ((listp answer) (values-list answer))
                (second (values-list second))
                (t (error answer))))))))

(defun square-free-part (bridge expression variable)
  "EXPRESSION, a polynomial of degree 3 or more in VARIABLE (prefix), with each factor it
repeats taken once (the same real roots in VARIABLE at every value of the parameters),
as a prefix polynomial of lower degree; NIL when it is no such polynomial or has no
repeated factor the bridge finds (or Maxima fails on the attempt)."
  (call-or-nil (lambda () (square-free-part-of bridge expression variable))))

(defun square-free-part-of (bridge expression variable)
  "SQUARE-FREE-PART's work, its Maxima conditions not caught."
  (multiple-value-bind (form offset-variable after-form coefficients)
      (offset-polynomial bridge expression variable 0 :datum expression)
    (declare (ignore after-form))
    (when (and (listp coefficients) (> (length coefficients) 3))
      (multiple-value-bind (reduced reduced-coefficients)
          (square-free-polynomial bridge form offset-variable :datum expression)
        (when (and reduced (< (length reduced-coefficients) (length coefficients)))
          (handler-case (root-form-expression bridge reduced)
            (untranslatable-result () nil)))))))
