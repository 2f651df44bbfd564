;;;; src/maxima-bridge/root-forms.lisp -- the requests of the earliest-root search: an expression's polynomial in the offset after a start, Vieta's forms of its roots, solve() and realroots().
;;;;
;;;; The search itself (which root is proven earliest, from which signs) is the algebra
;;;; layer's (src/algebra/roots.lisp). It holds the forms these operations return as
;;;; opaque values, ROOT FORMS (Maxima forms of the offset of a root after the start, or
;;;; of the coefficients of the polynomial), and only passes them back to the operations
;;;; below: it never builds or reads one. Keeping the root forms in Maxima's terms between
;;;; requests (rather than translating each to prefix and back) keeps the requests as
;;;; Maxima simplifies them best, and cached.

(in-package #:ames.maxima)

(defun offset-polynomial (bridge shifted variable after &key datum)
  "SHIFTED (prefix, the expression with VARIABLE standing for the offset after the start
AFTER) as a polynomial in VARIABLE. Returns
  (values FORM OFFSET-VARIABLE AFTER-FORM COEFFICIENTS)
where FORM, OFFSET-VARIABLE and AFTER-FORM are the root forms of SHIFTED, VARIABLE and
AFTER, and COEFFICIENTS the root forms (c0 c1 ... cd) of its coefficients, or
:NOT-POLYNOMIAL. One request (ames_polynomial_coefficients), with DATUM for errors."
  (let* ((offset-variable (to-mx bridge variable))
         (form (to-mx bridge shifted))
         (after-form (to-mx bridge after))
         (coefficients (maxima-request bridge (mcall "$AMES_POLYNOMIAL_COEFFICIENTS"
                                                     form offset-variable)
                                       :datum datum)))
    (values form offset-variable after-form
            (if (eq coefficients +false+) :not-polynomial (mlist-items coefficients)))))

(defun square-free-polynomial (bridge form offset-variable &key datum)
  "The root form FORM, a polynomial in OFFSET-VARIABLE of degree 3 or more, with each
factor it repeats taken once ((s - r)^2 q(s) as (s - r) q(s): the same roots, none
repeated, so that a touching gap's double root is found as a simple one):
  (values REDUCED COEFFICIENTS) when that lowers its degree, else NIL. Two requests
(ames_square_free_part, ames_polynomial_coefficients), with DATUM for errors."
  (let* ((reduced (maxima-request bridge (mcall "$AMES_SQUARE_FREE_PART" form offset-variable)
                                  :datum datum))
         (coefficients (maxima-request bridge (mcall "$AMES_POLYNOMIAL_COEFFICIENTS"
                                                     reduced offset-variable)
                                       :datum datum)))
    (and (not (eq coefficients +false+))
         (values reduced (mlist-items coefficients)))))

(defun numeric-root-form-p (form)
  "True when the root form FORM is a plain number (integer, float or rational)."
  (or (realp form) (mform-p form +rat+)))

(defun complex-root-form-p (form)
  "True when the root form FORM contains the imaginary unit (a complex root is no time)."
  (contains-symbol-p +i+ form))

(defun root-form-signs (bridge form &key datum)
  "The signs (:POSITIVE :NEGATIVE :ZERO) the real root form FORM may have under the
facts in force (FORM-SIGNS: sign() of FORM in several simplified forms)."
  (form-signs bridge form :datum datum))

(defun root-form-imaginary-part (bridge form &key datum)
  "The imaginary part of the root form FORM, a root form (0 when FORM is real). One
request (imagpart), with DATUM for errors."
  (maxima-request bridge (mcall "$IMAGPART" form) :datum datum))

(defun root-form-expression (bridge form)
  "The root form FORM in prefix algebra, translated as it is (no request). Signals
UNTRANSLATABLE-RESULT when it leaves the algebra."
  (from-mx bridge form))

(defun root-at-offset (bridge after-form offset expression)
  "The root AFTER + OFFSET (root forms) in prefix algebra, in its simplest form (see
SIMPLEST-FORM; EXPRESSION is the datum of errors)."
  (simplest-form bridge (mform +mplus+ after-form offset) expression))

(defun linear-root-offset (c0 c1)
  "The root form of the one root -c0/c1 of c0 + c1 s = 0 (root forms C0, C1)."
  (mform +mtimes+ -1 (mquotient c0 c1)))

(defun vieta-forms (c0 c1 c2)
  "For c0 + c1 s + c2 s^2 = 0 (root forms), the root forms of the product P = c0/c2 and
sum S = -c1/c2 of its roots, of S/2, and of the reduced discriminant S^2/4 - P:
  (values P S S/2 DISCRIMINANT). The roots are S/2 -+ sqrt(DISCRIMINANT)."
  (let* ((product (mquotient c0 c2))
         (sum (mform +mtimes+ -1 (mquotient c1 c2)))
         (half-sum (mform +mtimes+ (mform +rat+ 1 2) sum)))
    (values product sum half-sum (mdifference (mform +mexpt+ half-sum 2) product))))

(defun root-form-sum (a b)
  "The root form A + B (the larger of Vieta's roots, S/2 + sqrt(D))."
  (mform +mplus+ a b))

(defun root-form-difference (a b)
  "The root form A - B (the smaller of Vieta's roots; a comparison of two roots)."
  (mdifference a b))

(defun rational-radicand (bridge radicand &key datum)
  "The root form RADICAND in rational form, and its numerator:
  (values RATIONAL NUMERATOR). Two requests (ratsimp, num)."
  (let ((rational (maxima-request bridge (mcall "$RATSIMP" radicand) :datum datum)))
    (values rational (maxima-request bridge (mcall "$NUM" rational) :datum datum))))

(defun real-square-root-form (bridge rational numerator negative-p &key datum)
  "The square root of the root form RATIONAL (with its NUMERATOR, from RATIONAL-RADICAND),
written so that Maxima's simplifier does not turn it into the imaginary unit over a
factor whose sign it does not know (it splits sqrt(N/D) into sqrt(N)/sqrt(D) when it
knows N < 0): when NEGATIVE-P (the numerator proven negative), numerator and
denominator are both negated and expanded first."
  (mform +mexpt+
         (if negative-p
             (mquotient (maxima-request bridge (mcall "$EXPAND" (mform +mtimes+ -1 numerator))
                                        :datum datum)
                        (maxima-request bridge (mcall "$EXPAND" (mform +mtimes+ -1
                                                                       (mcall "$DENOM" rational)))
                                        :datum datum))
             rational)
         (mform +rat+ 1 2)))

(defun radicand-denominator (bridge rational &key datum)
  "The denominator of the root form RATIONAL (from RATIONAL-RADICAND). One request (denom)."
  (maxima-request bridge (mcall "$DENOM" rational) :datum datum))

(defun cleared-square-root-form (bridge numerator denominator denominator-negative-p &key datum)
  "The square root of NUMERATOR/DENOMINATOR (root forms, their quotient proven
non-negative) written sqrt(N D) / |D|, N D expanded into one sum: the radicand is no
product that Maxima's simplifier could split into square roots of factors it takes for
negative (sqrt(N/D) = sqrt(N D)/|D| whenever N/D >= 0). DENOMINATOR-NEGATIVE-P says
which of D and -D is |D|; it must be proven (for a constant, exactly: Maxima's sign() of
one is a float's). One request (expand)."
  (mquotient (mform +mexpt+
                    (maxima-request bridge (mcall "$EXPAND" (mform +mtimes+ numerator denominator))
                                    :datum datum)
                    (mform +rat+ 1 2))
             (if denominator-negative-p (mform +mtimes+ -1 denominator) denominator)))

(defun solved-root-offsets (bridge form offset-variable &key datum)
  "The roots solve() finds of FORM = 0 in OFFSET-VARIABLE (root forms):
  (values EXPLICIT COUNT), EXPLICIT the root forms of the solutions given explicitly
(OFFSET-VARIABLE = value), COUNT the number of solutions solve() gave (more than the
explicit ones when some are implicit)."
  (let* ((answer (maxima-request bridge (mcall "$SOLVE" (mlist (list (mform +mequal+ form 0)))
                                               (mlist (list offset-variable)))
                                 :datum datum))
         (items (if (mform-p answer +mlist+) (mlist-items answer) '())))
    (values (loop for item in items
                  when (and (mform-p item +mequal+) (eq (second item) offset-variable))
                    collect (third item))
            (length items))))

(defun real-root-offsets (bridge form offset-variable &key datum)
  "The real roots of the polynomial root form FORM (numeric coefficients) in
OFFSET-VARIABLE, isolated by Sturm sequences (realroots()), in prefix algebra (each a
number when Maxima gave one)."
  (let ((answer (maxima-request bridge (mcall "$REALROOTS" form) :datum datum)))
    (loop for item in (mlist-items answer)
          when (and (mform-p item +mequal+) (eq (second item) offset-variable))
            collect (from-mx bridge (third item)))))
