;;;; src/simulator/polynomial-signs.lisp -- the sign of a polynomial in the parameters after its like terms cancel.
;;;;
;;;; The broad phase (broad-phase.lisp) compares bodies' coordinates with the bounds of a
;;;; contact's locus: (w1 + w2 + w3) - w1 - (w2 + w3/2) is w3/2, of the sign of w3, but the
;;;; rules of signs applied to the expression as written see a positive sum minus a
;;;; positive sum and say nothing. EXPANDED-SIGN first expands the expression into a sum
;;;; of monomials with exact rational coefficients (like terms cancelled), then applies the
;;;; rules of signs to the monomials: an exact rewriting followed by a sound rule, so it
;;;; answers only what is proven. An expression with anything but sums, differences,
;;;; products, integer powers and division by numbers, or one that expands to more than
;;;; *LARGEST-EXPANSION* monomials, is left :UNKNOWN. Never asks Maxima.

(in-package #:ames.simulator)

(defparameter *largest-expansion* 400
  "EXPANDED-MONOMIALS gives up on an expression with more monomials than this.")

(defun monomial-product (a b)
  "The product of the monomials A and B (sorted alists symbol -> positive exponent)."
  (let ((result (copy-alist a)))
    (dolist (factor b)
      (let ((entry (assoc (car factor) result)))
        (if entry
            (setf result (substitute (cons (car entry) (+ (cdr entry) (cdr factor))) entry result))
            (push factor result))))
    (sort result #'string< :key (lambda (factor) (symbol-name (car factor))))))

(defun polynomial-sum (a b)
  "The sum of the polynomials A and B (alists monomial -> nonzero rational), like terms
cancelled."
  (let ((table (make-hash-table :test #'equal)))
    (dolist (term (append a b))
      (incf (gethash (car term) table 0) (cdr term)))
    (let ((result '()))
      (maphash (lambda (monomial coefficient)
                 (unless (zerop coefficient) (push (cons monomial coefficient) result)))
               table)
      result)))

(defun polynomial-sums (polynomials)
  "The sum of POLYNOMIALS, exactly (REDUCE #'POLYNOMIAL-SUM POLYNOMIALS :INITIAL-VALUE
'()), the same terms in the same order, with one table instead of one a step (a sum of
N terms cost N^2 hashed terms). POLYNOMIAL-SUM's order: the terms of its first argument,
then the new ones of its second, reversed (a table iterates in the order of insertion)."
  (let ((table (make-hash-table :test #'equal))
        (result '()))
    (dolist (b polynomials result)
      (let ((new '()))
        (dolist (term b)
          (multiple-value-bind (coefficient found) (gethash (car term) table)
            (if found
                (setf (gethash (car term) table) (+ coefficient (cdr term)))
                (progn (setf (gethash (car term) table) (+ 0 (cdr term)))
                       (push (car term) new)))))
        (let ((order (append new (reverse (mapcar #'car result)))))
          (setf result '())
          ;; ORDER is the result's order; collected backwards, then put right
          (dolist (monomial order)
            (let ((coefficient (gethash monomial table)))
              (if (zerop coefficient)
                  (remhash monomial table)
                  (push (cons monomial coefficient) result))))
          (setf result (nreverse result)))))))

(defun polynomial-scaled (a k)
  "The polynomial A times the rational K."
  (if (zerop k) '() (mapcar (lambda (term) (cons (car term) (* k (cdr term)))) a)))

(defun polynomial-product (a b)
  "The product of the polynomials A and B."
  (when (> (* (length a) (length b)) *largest-expansion*)
    (throw 'too-large nil))
  (polynomial-sums (mapcar (lambda (x)
                             (mapcar (lambda (y) (cons (monomial-product (car x) (car y))
                                                       (* (cdr x) (cdr y))))
                                     b))
                           a)))

(defun expanded-monomials (expression)
  "EXPRESSION expanded into an alist monomial -> nonzero rational coefficient (a
monomial a sorted alist symbol -> exponent, NIL for the constant), or :UNKNOWN when it
is not a polynomial with rational coefficients in symbols or expands too far."
  (labels ((expand (x)
             (cond ((rationalp x) (if (zerop x) '() (list (cons '() x))))
                   ((and (symbolp x) (variable-symbol-p x)) (list (cons (list (cons x 1)) 1)))
                   ((not (consp x)) (throw 'too-large nil))
                   (t (let ((arguments (rest x)))
                        (case (first x)
                          (+ (polynomial-sums (mapcar #'expand arguments)))
                          (- (if (rest arguments)
                                 (polynomial-sum (expand (first arguments))
                                                 (polynomial-scaled
                                                  (polynomial-sums (mapcar #'expand (rest arguments)))
                                                  -1))
                                 (polynomial-scaled (expand (first arguments)) -1)))
                          (* (reduce #'polynomial-product (mapcar #'expand arguments)
                                     :initial-value (list (cons '() 1))))
                          (/ (if (and (rest arguments) (every #'rationalp (rest arguments))
                                      (notany #'zerop (rest arguments)))
                                 (polynomial-scaled (expand (first arguments))
                                                    (/ 1 (reduce #'* (rest arguments))))
                                 (throw 'too-large nil)))
                          (expt (let ((power (second arguments)))
                                  (if (and (integerp power) (<= 0 power 8))
                                      (let ((base (expand (first arguments)))
                                            (result (list (cons '() 1))))
                                        (dotimes (i power result)
                                          (setf result (polynomial-product result base))))
                                      (throw 'too-large nil))))
                          (t (throw 'too-large nil))))))))
    (let ((result (catch 'too-large (list :done (expand expression)))))
      (if (and result (<= (length (second result)) *largest-expansion*))
          (second result)
          :unknown))))

(defun expanded-sign (signs expression)
  "The sign of EXPRESSION for every admissible value of the parameters, whose signs
SIGNS gives (see SIGN-ALGEBRA), from its expanded monomials: a sign set (all three signs
when they are not known)."
  (let ((monomials (expanded-monomials expression)))
    (if (eq monomials :unknown)
        ames.algebra:+all-signs+
        (monomials-sign signs monomials))))

(defun monomials-sign (signs monomials)
  "The sign of the polynomial MONOMIALS (see EXPANDED-MONOMIALS) for every admissible
value of the parameters, whose signs SIGNS gives: a sign set."
  ;; the one sign system's rules (AMES.ALGEBRA sign sets) over the monomials
  (let ((signs-of-sum
                (ames.algebra:sum-signs
                 (mapcar (lambda (term)
                           (reduce #'ames.algebra:sign-product
                                   (mapcar (lambda (factor)
                                             (sign-algebra signs `(expt ,(car factor) ,(cdr factor))))
                                           (car term))
                                   :initial-value (ames.algebra:number-signs (cdr term))))
                         monomials))))
    (or signs-of-sum ames.algebra:+all-signs+)))

(defun polynomial-identity-verdict (expression)
  "Whether EXPRESSION is identically zero, read from its expansion with each quantity
term an indeterminate (see EXPANDED-MONOMIALS): :ZERO when it expands to the zero
polynomial, :NONZERO when to another (a polynomial with rational coefficients in
independent indeterminates is zero as a rational function only when it is the zero
polynomial: Maxima's ratsimp() answers the same), NIL when it is no such polynomial."
  (let* ((variables (expression-variables expression))
         (names (mapcar (lambda (x) (and (symbolp x) (symbol-name x))) variables))
         (placeholders
           (loop for term in variables
                 for index from 0
                 when (quantity-term-p term)
                   collect (cons term (make-symbol (format nil "QUANTITY ~D" index))))))
    ;; monomials are ordered by name: a placeholder's may not be a variable's
    (unless (some (lambda (entry) (member (symbol-name (cdr entry)) names :test #'equal))
                  placeholders)
      (let ((monomials (expanded-monomials (substitute-expressions placeholders expression))))
        (cond ((eq monomials :unknown) nil)
              ((null monomials) :zero)
              (t :nonzero))))))
