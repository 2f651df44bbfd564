;;;; src/simulator/one-sided-series.lisp -- local series of a quantity whose derivatives
;;;; cannot be evaluated at the start of the state, though it is smooth just after it.
;;;;
;;;; SERIES-COEFFICIENTS (model.lisp) differentiates a quantity along the state's ODEs and
;;;; evaluates each derivative at the start. A force law that is not smooth where the state
;;;; starts defeats it: quadratic drag -C |v| v has |v| = sqrt(vx^2 + vy^2), whose
;;;; derivative v.a / |v| is 0/0 for a body at rest (a block stopped against a wall by a
;;;; plastic impact, its wall's normal force zero at the start). The motion itself is
;;;; smooth for tau > 0, and its one-sided series exists: |v| = |a0| tau + ...
;;;;
;;;; Here the state terms' series are built by Picard's iteration: term_(j+1) is the j-th
;;;; coefficient of its rate with the terms' polynomials of degree j put in, over j + 1;
;;;; each expansion is Maxima's taylor() about tau = 0 for tau > 0
;;;; (AMES.MAXIMA:ONE-SIDED-TAYLOR-COEFFICIENTS). The quantity's series is then the
;;;; expansion of the quantity with the terms' polynomials put in. Where a series has a
;;;; pole or a fractional power there is no such series, and NIL says so.

(in-package #:ames.simulator)

(defun one-sided-coefficients (run expression degree)
  "The coefficients (c0 ... c_DEGREE) of EXPRESSION's series in TAU about 0+, or NIL."
  (ames.maxima:one-sided-taylor-coefficients (run-bridge run) expression 'tau degree))

(defun polynomial-in-tau (coefficients)
  "The polynomial c0 + c1 tau + ... of COEFFICIENTS."
  (cons '+ (loop for c in coefficients for k from 0
                 collect (if (zerop k) c `(* ,c (expt tau ,k))))))

(defun state-term-polynomials (run solved degree)
  "An alist state term -> its series in TAU to DEGREE (a polynomial) at the start of the
SOLVED state, by Picard's iteration along its rates; NIL when a rate has no one-sided
series."
  (let ((series (mapcar (lambda (entry) (list (car entry) (cdr entry)))
                        (solved-model-initial solved))))
    (dotimes (j degree)
      (let ((substitution (mapcar (lambda (entry) (cons (first entry) (polynomial-in-tau (rest entry))))
                                  series)))
        (setf series
              (loop for entry in series
                    for rate = (cdr (assoc (first entry) (solved-model-rates solved) :test #'equal))
                    for coefficients = (and rate (one-sided-coefficients
                                                  run (substitute-expressions substitution rate) j))
                    unless coefficients do (return-from state-term-polynomials nil)
                    collect (append entry (list (tidy run `(/ ,(nth j coefficients) ,(1+ j)))))))))
    (mapcar (lambda (entry) (cons (first entry) (polynomial-in-tau (rest entry)))) series)))

(defun one-sided-series (run solved expression count)
  "The first COUNT coefficients of EXPRESSION's series in TAU at the start of the SOLVED
state, for TAU > 0, with the state terms' own series put in (see the file header); NIL
when it has none."
  (let ((polynomials (state-term-polynomials run solved (1- count))))
    (and polynomials
         (one-sided-coefficients run (substitute-expressions polynomials expression) (1- count)))))
