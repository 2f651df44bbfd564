;;;; src/algebra/fact-remainders.lisp -- part of DECIDE's last strategy (combined-bounds.lisp): one fact and a remainder of one sign.
;;;;
;;;; A relation f > 0 may follow from one fact s > 0 in force and the parameters' signs
;;;; together: f = c s + r, with c a positive number and r >= 0 proven (most often a sum
;;;; of terms each of one sign). The pushed block that tips while its front edge slides
;;;; forward (A < 0, A the friction limit of that edge sticking) cannot also have the
;;;; edge's friction limit in the other direction fail (B < 0): B = -A + 114 mu w k P + 20
;;;; mu m g w^2 + 80 mu m g k^2. The order substitution writes a variable as its bound
;;;; plus an excess, and the combined bounds need two facts linear in one variable; the
;;;; sum of one fact and a positive remainder is neither. GOAL-PROVEN-BY-ONE-FACT-P finds
;;;; it: both polynomials expanded in Lisp (POLYNOMIAL-OF: sines, roots and other
;;;; non-polynomial subterms taken as atoms, so the identity is exact), c taken from the ratio of the coefficients of a
;;;; monomial they share (positive ratios only, the few smallest distinct ones), and the
;;;; remainder f - c s asked of DECIDE (without the combined bounds, as their multipliers
;;;; are). Sound: f - c s = r is an identity of polynomials and c > 0, s > 0 (or >= 0),
;;;; r >= 0 (or > 0) are facts or proven; f > 0 then needs one of the two strict. A goal
;;;; with a denominator is asked of its numerator where the denominator's sign is proven.

(in-package #:ames.algebra)

(defparameter *most-remainder-multipliers* 3
  "The most multipliers c (ratios of shared coefficients) tried for one fact.")

;;; Polynomials as alists (MONOMIAL . COEFFICIENT), a MONOMIAL a list of (FACTOR . POWER)
;;; sorted by the printed FACTOR: a variable, or any other non-polynomial subterm (sin a)

(defun monomial-key (factors)
  "FACTORS ((FACTOR . POWER) ...) merged and sorted: a monomial."
  (let ((merged '()))
    (dolist (f factors)
      (let ((old (assoc (car f) merged :test #'equal)))
        (if old (incf (cdr old) (cdr f)) (push (cons (car f) (cdr f)) merged))))
    (sort (remove 0 merged :key #'cdr)
          #'string< :key (lambda (f) (let ((*print-pretty* nil)) (prin1-to-string (car f)))))))

(defun polynomial-sum (&rest polynomials)
  "The sum of POLYNOMIALS, without zero coefficients."
  (let ((sum '()))
    (dolist (p polynomials)
      (dolist (term p)
        (let ((old (assoc (car term) sum :test #'equal)))
          (if old (incf (cdr old) (cdr term)) (push (cons (car term) (cdr term)) sum)))))
    (remove 0 sum :key #'cdr)))

(defun polynomial-scaled (polynomial c)
  "POLYNOMIAL times the number C."
  (mapcar (lambda (term) (cons (car term) (* c (cdr term)))) polynomial))

(defparameter *largest-remainder-expansion* 400
  "POLYNOMIAL-OF gives up on a product of more pairs of terms than this.")

(defun polynomial-product (p q)
  "The product of the polynomials P and Q; throws TOO-LARGE past
*LARGEST-REMAINDER-EXPANSION* pairs of terms."
  (when (> (* (length p) (length q)) *largest-remainder-expansion*)
    (throw 'too-large nil))
  (apply #'polynomial-sum
         (loop for (m1 . c1) in p
               collect (loop for (m2 . c2) in q
                             collect (cons (monomial-key (append m1 m2)) (* c1 c2))))))

(defun polynomial-of (expression)
  "EXPRESSION (prefix) expanded as a polynomial over its variables and non-polynomial
subterms, with rational coefficients, as (values POLYNOMIAL T); NIL when a division by a
non-number or a float stands in the way, or the expansion grows too large (the zero
polynomial is (values NIL T)). Like the simulator's EXPANDED-MONOMIALS
(polynomial-signs.lisp, a layer up), with other subterms taken as atoms."
  (labels ((fail () (return-from polynomial-of nil))
           (walk (x)
             (cond ((rationalp x) (if (zerop x) '() (list (cons '() x))))
                   ((realp x) (fail))
                   ((atom x) (list (cons (list (cons x 1)) 1)))
                   (t (let ((args (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (apply #'polynomial-sum (mapcar #'walk args)))
                          (- (if (rest args)
                                 (apply #'polynomial-sum (walk (first args))
                                        (mapcar (lambda (a) (polynomial-scaled (walk a) -1)) (rest args)))
                                 (polynomial-scaled (walk (first args)) -1)))
                          (* (let ((product (list (cons '() 1))))
                               (dolist (a args product)
                                 (setf product (polynomial-product product (walk a))))))
                          (/ (if (and (= 2 (length args)) (rationalp (second args))
                                      (not (zerop (second args))))
                                 (polynomial-scaled (walk (first args)) (/ (second args)))
                                 (fail)))
                          (expt (let ((power (second args)))
                                  (if (and (integerp power) (<= 0 power 12))
                                      (let ((base (walk (first args))) (result (list (cons '() 1))))
                                        (dotimes (i power result)
                                          (setf result (polynomial-product result base))))
                                      (list (cons (list (cons x 1)) 1)))))
                          (t (list (cons (list (cons x 1)) 1)))))))))
    (catch 'too-large
      (values (walk expression) t))))

(defun polynomial-expression (polynomial)
  "POLYNOMIAL as a prefix expression."
  (flet ((monomial (m c)
           `(* ,c ,@(mapcar (lambda (f) (if (= 1 (cdr f)) (car f) `(expt ,(car f) ,(cdr f)))) m))))
    (if polynomial
        `(+ ,@(loop for (m . c) in polynomial collect (monomial m c)))
        0)))

(defun remainder-multipliers (goal fact)
  "The positive ratios of the coefficients of the monomials the polynomials GOAL and FACT
share, smallest first, at most *MOST-REMAINDER-MULTIPLIERS*."
  (let ((ratios '()))
    (loop for (monomial . c) in goal
          for f = (cdr (assoc monomial fact :test #'equal))
          when (and f (plusp (/ c f)))
            do (pushnew (/ c f) ratios))
    (let ((sorted (sort ratios #'<)))
      (subseq sorted 0 (min (length sorted) *most-remainder-multipliers*)))))

(defun quotient-parts (bridge expression)
  "(values NUMERATOR DENOMINATOR) of EXPRESSION put over one denominator by Maxima's
ratsimp (DENOMINATOR 1 for a polynomial)."
  (let ((form (simplified bridge expression :ratsimp)) (negated nil))
    (when (and (consp form) (eq (expression-operator form) '-) (null (cddr form)))
      (setf form (second form) negated t))
    (multiple-value-bind (numerator denominator)
        (if (and (consp form) (eq (expression-operator form) '/) (= 3 (length form)))
            (values (second form) (third form))
            (values form 1))
      (values (if negated `(- ,numerator) numerator) denominator))))

(defun numerator-polynomial (bridge expression)
  "The polynomial (POLYNOMIAL-OF) of the numerator of EXPRESSION times the sign of its
denominator, when that sign is proven: a polynomial of EXPRESSION's sign, or NIL."
  (or (polynomial-of expression)
      (multiple-value-bind (numerator denominator) (quotient-parts bridge expression)
        (cond ((eql denominator 1) (polynomial-of numerator))
              ((proven-nonnegative-p bridge denominator t) (polynomial-of numerator))
              ((proven-nonnegative-p bridge `(- ,denominator) t) (polynomial-of `(- ,numerator)))))))

(defun goal-proven-by-one-fact-p (bridge goal strict facts)
  "True when GOAL > 0 (STRICT) or GOAL >= 0 follows from one of FACTS (relations in force)
and a remainder of proven sign (see the file header)."
  (let ((goal-polynomial (numerator-polynomial bridge goal)))
    (dolist (fact (and goal-polynomial facts) nil)
      (multiple-value-bind (slack fact-strict) (slack-of fact)
        (let ((fact-polynomial (and slack (numerator-polynomial bridge slack))))
          (dolist (c (and fact-polynomial (remainder-multipliers goal-polynomial fact-polynomial)))
            (let ((rest (polynomial-sum goal-polynomial (polynomial-scaled fact-polynomial (- c)))))
              (if (null rest)
                  ;; GOAL = c FACT: as strict as the fact
                  (when (or (not strict) fact-strict)
                    (return-from goal-proven-by-one-fact-p t))
                  (let ((remainder (polynomial-expression rest)))
                    (when (and (not (multiplier-refuted-p bridge remainder))
                               (proven-nonnegative-p bridge remainder (and strict (not fact-strict))))
                      (return-from goal-proven-by-one-fact-p t)))))))))))
