;;;; src/algebra/signs.lisp -- the signs of an expression from the signs of its parts, as a physicist finds them.
;;;;
;;;; EXPRESSION-SIGNS gives the signs an arithmetic expression may take at every admissible
;;;; point: products and quotients of signed factors, sums of terms of one sign, powers,
;;;; square roots (two square roots of negative radicands make a negative real product),
;;;; exp, log, abs, atan, and sin, cos, tan of angles whose exact range (angles.lisp), or a
;;;; placing of the angle between two zeros, gives them a sign. What the parts do not
;;;; settle is asked of the part as a whole: Maxima's sign() and is(), then DECIDE for a
;;;; short one. The quarter turns of angles are shifted out here too (cos(pi/2 - a) is
;;;; sin a). Used by the reasoning steps of truth.lisp.
;;;;
;;;; Signs are lists of :POSITIVE :ZERO :NEGATIVE (the values an expression may take);
;;;; NIL means nothing is known, and also that the expression may be undefined or not
;;;; real somewhere (a square root of something that may be negative, a division by
;;;; something that may be zero): no conclusion is drawn from such a part.

(in-package #:ames.algebra)

(defvar *compound-fact-signs* t
  "True when LEAF-SIGNS looks for a factor that is a multiple of what a fact in force
bounds (COMPOUND-FACT-MULTIPLE-SIGNS, in sturm.lisp).")

(defparameter *largest-decided-part* 60
  "LEAF-SIGNS asks DECIDE about a part of at most this many atoms and operators; a
longer one gets Maxima's sign() only.")

(defstruct (prover (:constructor make-prover (bridge ranges)))
  "What the reasoning about one relation needs: the BRIDGE and the exact RANGES of the
subjects under the facts in force (see SUBJECT-RANGES)."
  bridge ranges)

(defun prover-for (bridge)
  "A PROVER for BRIDGE under the facts in force."
  (make-prover bridge (subject-ranges (flatten-facts (current-assumptions bridge)))))

;;; Linear forms of angles, and quarter turns

(defun linear-terms (expression)
  "EXPRESSION as an alist (TERM . COEFFICIENT) of rational coefficients, EXPRESSION being
the sum of COEFFICIENT * TERM: TERM is 1 for the constant part, PI, or any other
subexpression taken whole (a variable, a product of variables, a function)."
  (labels ((merge-terms (alists)
             (let ((result '()))
               (dolist (alist alists)
                 (dolist (entry alist)
                   (let ((old (assoc (car entry) result :test #'equal)))
                     (if old
                         (incf (cdr old) (cdr entry))
                         (push (cons (car entry) (cdr entry)) result)))))
               (remove 0 (nreverse result) :key #'cdr)))
           (scaled (alist c) (mapcar (lambda (e) (cons (car e) (* c (cdr e)))) alist))
           (terms (x)
             (cond ((rationalp x) (if (zerop x) '() (list (cons 1 x))))
                   ((eq x 'pi) (list (cons 'pi 1)))
                   ((not (compound-expression-p x)) (list (cons x 1)))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (merge-terms (mapcar #'terms arguments)))
                          (- (if (rest arguments)
                                 (merge-terms (cons (terms (first arguments))
                                                    (mapcar (lambda (a) (scaled (terms a) -1))
                                                            (rest arguments))))
                                 (scaled (terms (first arguments)) -1)))
                          (* (let ((others (remove-if #'rationalp arguments)))
                               (cond ((null others) (terms (reduce #'* arguments)))
                                     ((rest others) (list (cons x 1)))
                                     (t (scaled (terms (first others))
                                                (reduce #'* (remove-if-not #'rationalp arguments)))))))
                          (/ (if (and (= (length arguments) 2) (rationalp (second arguments))
                                      (/= 0 (second arguments)))
                                 (scaled (terms (first arguments)) (/ (second arguments)))
                                 (list (cons x 1))))
                          (t (list (cons x 1)))))))))
    (terms expression)))

(defun linear-expression (alist)
  "The expression of the linear form ALIST (see LINEAR-TERMS)."
  (let ((terms (loop for (term . c) in alist
                     collect (cond ((eql term 1) c)
                                   ((eql c 1) term)
                                   ((eql c -1) (list '- term))
                                   (t (list '* c term))))))
    (cond ((null terms) 0)
          ((rest terms) (cons '+ terms))
          (t (first terms)))))

(defun reduced-circular-function (function argument)
  "FUNCTION (SIN COS TAN) of ARGUMENT with quarter turns shifted out and a negated angle
turned around (cos(pi/2 - a) = sin(a), sin(-a) = -sin(a)); NIL when nothing changes."
  (let* ((terms (linear-terms argument))
         (turns (* 2 (or (cdr (assoc 'pi terms)) 0)))
         (rest (remove 'pi terms :key #'car)))
    (when (integerp turns)
      (let* ((flip (and rest (every (lambda (entry) (minusp (cdr entry))) rest)))
             (angle (linear-expression (if flip
                                           (mapcar (lambda (e) (cons (car e) (- (cdr e)))) rest)
                                           rest)))
             (k (mod turns 4)))
        (when (and (or (/= 0 k) flip)
                   (not (and (eq function 'tan) (oddp k) (null rest))))
          ;; f(s x + k pi/2) with x the plain angle and s = -1 when FLIP
          (flet ((signed (sign expression) (if (minusp sign) (list '- expression) expression)))
            (let ((s (if flip -1 1)))
              (ecase function
                (cos (ecase k           ; cos(y + k pi/2), y = s x
                       (0 (list 'cos angle))
                       (1 (signed (- s) (list 'sin angle)))
                       (2 (list '- (list 'cos angle)))
                       (3 (signed s (list 'sin angle)))))
                (sin (ecase k           ; sin(y + k pi/2)
                       (0 (signed s (list 'sin angle)))
                       (1 (list 'cos angle))
                       (2 (signed (- s) (list 'sin angle)))
                       (3 (list '- (list 'cos angle)))))
                (tan (if (evenp k)
                         (signed s (list 'tan angle))
                         (signed (- s) (list '/ 1 (list 'tan angle)))))))))))))

(defun reduce-quarter-turns (expression)
  "EXPRESSION (a relation or an arithmetic expression) with every sin, cos and tan of an
angle shifted by quarter turns or negated written with the plain angle."
  (cond ((atom expression) expression)
        ((quantity-term-p expression) expression)
        (t (let ((rebuilt (cons (expression-operator expression)
                                (mapcar #'reduce-quarter-turns (expression-arguments expression)))))
             (or (and (member (expression-operator rebuilt) '(sin cos tan))
                      (reduced-circular-function (expression-operator rebuilt) (second rebuilt)))
                 rebuilt)))))

;;; Signs of expressions, from the signs of their parts

(defun square-root-radicand (x)
  "The radicand A when X is (SQRT A) or (EXPT A 1/2), else NIL."
  (and (compound-expression-p x)
       (case (expression-operator x)
         (sqrt (second x))
         (expt (and (eql (third x) 1/2) (second x))))))

(defun quotient-signs (prover x)
  "The signs of the product or quotient X from those of its factors. A square root of a
negative radicand is i times a positive number, so two of them make a real product:
sqrt(A) sqrt(B) = -sqrt(A B) for A, B < 0 (Maxima writes some times that way); an odd
number of them leaves the reals (NIL)."
  (multiple-value-bind (coefficient factors) (product-parts x)
    (let ((signs (list (first (number-signs coefficient))))
          (turns 0))                    ; the power of i: +1 per imaginary factor above, -1 below
      (dolist (factor factors)
        (destructuring-bind (part . power) factor
          (let ((part-signs (expression-signs prover part)))
            (cond ((and part-signs (not (and (= power -1) (member :zero part-signs))))
                   (setf signs (sign-product signs part-signs)))
                  ((and (null part-signs) (square-root-radicand part)
                        (only-signs-p (expression-signs prover (square-root-radicand part)) :negative))
                   (incf turns power))
                  (t (return-from quotient-signs nil))))))
      (cond ((oddp turns) nil)
            ((= 2 (mod turns 4)) (negated-signs signs))
            (t signs)))))

(defun admissible-value (bridge expression)
  "The value of EXPRESSION at one point that surely satisfies the facts in force (a
double float), or NIL when none is found."
  (let ((value nil))
    (call-with-admissible-points bridge expression
                                 (lambda (point)
                                   (let ((ball (expression-ball expression point)))
                                     (when ball (setf value (ball-center ball))))))
    value))

(defun placed-trigonometric-signs (prover kernel)
  "The signs of KERNEL, (SIN X), (COS X) or (TAN X), found by placing X between two
consecutive zeros (or a zero and a pole) of the function: the piece is guessed from X's
value at an admissible point, and both bounds are asked of DECIDE (0 < b - a < pi with
b > a for sin(b - a)). NIL when that fails."
  (let* ((bridge (prover-bridge prover))
         (function (expression-operator kernel))
         (angle (second kernel))
         (value (admissible-value bridge angle)))
    (when value
      (multiple-value-bind (width offset) (if (eq function 'tan)
                                              (values 1/2 0)
                                              (values 1 (if (eq function 'sin) 0 -1/2)))
        ;; the piece [offset + k width, offset + (k + 1) width], in multiples of pi
        (let* ((k (floor (- (/ value pi) offset) width))
               (low (+ offset (* k width))) (high (+ offset (* (1+ k) width))))
          (flet ((bound (operator multiple)
                   (eq :true (decide bridge (list operator angle (list '* multiple 'pi))))))
            ;; sin, cos and tan are positive on the even pieces, negative on the odd ones
            (when (and (bound '> low) (bound '< high))
              (if (evenp k) '(:positive) '(:negative)))))))))

(defun trigonometric-signs (prover kernel)
  "The signs of KERNEL, (SIN X), (COS X) or (TAN X), that the range of X gives, or else
that placing X between two zeros gives (see PLACED-TRIGONOMETRIC-SIGNS); NIL when
neither does."
  (let* ((range (expression-range (second kernel) (prover-ranges prover)))
         (sign (and range (range-trigonometric-sign (expression-operator kernel) range))))
    (cond (sign (ecase sign
                  (:positive '(:positive)) (:negative '(:negative))
                  (:nonnegative '(:positive :zero)) (:nonpositive '(:negative :zero))))
          ((subject-p (second kernel)) nil)
          (t (placed-trigonometric-signs prover kernel)))))

(defvar *imaginary-radicands* '()
  "The radicands, proven negative, of the square roots in the relation being decided by
DECIDE-WITH-IMAGINARY-RADICANDS: Maxima is not asked about an expression holding one.")

(defun mentions-imaginary-root-p (x)
  "True when X has a square root of one of *IMAGINARY-RADICANDS*."
  (and *imaginary-radicands* (consp x) (not (quantity-term-p x))
       (or (member (square-root-radicand x) *imaginary-radicands* :test #'equal)
           (some #'mentions-imaginary-root-p (expression-arguments x)))))

(defun leaf-signs (prover x)
  "The signs of X found as a whole: by exact arithmetic when X is a constant, from
Maxima's sign() of its forms and is() of its sign facts, then from DECIDE about X > 0
and X < 0 when X is a short compound expression, then as a multiple of what a fact in
force bounds (COMPOUND-FACT-MULTIPLE-SIGNS), then by counting the roots of a polynomial in
one bounded quantity (POLYNOMIAL-INTERVAL-SIGNS). NIL when Maxima finds X
outside the reals."
  (let ((bridge (prover-bridge prover)))
    (cond
      ((mentions-imaginary-root-p x) nil)
      ((null (expression-variables x))
        (let ((ball (expression-ball x '())))
          (case (and ball (ball-sign ball))
            (:positive '(:positive))
            (:negative '(:negative))
            (t (handler-case (maxima-signs bridge x)
                 (maxima-error () nil))))))
      (t
        (let ((signs (handler-case (maxima-signs bridge x
                                                 ;; asked with the sign() requests
                                                 :also (and (not (subject-p x))
                                                            (fact-sign-requests bridge x)))
                       (maxima-error () nil))))
          (when (and signs (rest signs) (not (subject-p x)))
            (setf signs (intersection signs (handler-case (maxima-fact-signs bridge x)
                                              (maxima-error () signs)))))
          (when (and signs (rest signs) (not (subject-p x))
                     (<= (expression-size x) *largest-decided-part*))
            (flet ((rule-out (sign relation)
                     (ecase (decide bridge relation)
                       (:true (setf signs (list sign)))
                       (:false (setf signs (remove sign signs)))
                       (:unknown))))
              (rule-out :positive (list '> x 0))
              (when (rest signs)
                (rule-out :negative (list '< x 0)))))
          (when (and signs (rest signs))
            ;; a multiple of what a fact in force (a branch's) bounds
            (let ((assumed (and *compound-fact-signs* (compound-fact-multiple-signs bridge x))))
              (when assumed
                (setf signs (or (intersection signs assumed) signs)))))
          (when (and signs (rest signs))
            ;; a polynomial in one bounded quantity: its roots counted (sturm.lisp)
            (let ((counted (polynomial-interval-signs prover x)))
              (when counted
                (setf signs (or (intersection signs counted) signs)))))
          signs)))))

(defun range-signs (prover x)
  "The signs X may take by its exact range (EXPRESSION-RANGE over the prover's subject
ranges: pi - atan u lies in (pi/2, 3 pi/2)), or NIL when the range has no sign."
  (let ((range (expression-range x (prover-ranges prover))))
    (when range
      (let ((low (and (range-lower range) (pn-sign (range-lower range))))
            (high (and (range-upper range) (pn-sign (range-upper range)))))
        (cond ((eql low 1) '(:positive))
              ((and (eql low 0) (range-lower-open range)) '(:positive))
              ((eql low 0) '(:positive :zero))
              ((eql high -1) '(:negative))
              ((and (eql high 0) (range-upper-open range)) '(:negative))
              ((eql high 0) '(:negative :zero)))))))

(defun expression-signs (prover x &key top)
  "The signs the arithmetic expression X may take at every admissible point, from the
signs of its parts: products and quotients of signed factors, sums of terms of one sign,
powers, square roots, exp, log, abs, atan, asin, acos, and sin, cos, tan of angles whose
range gives them a sign; what the parts do not settle is asked of X as a whole (LEAF-SIGNS), except
for X itself when TOP is true (then only POLYNOMIAL-INTERVAL-SIGNS is tried). NIL when
nothing is known or X may be undefined."
  (flet ((whole () (if top
                       ;; X itself is what is being decided: only counted roots are new
                       (polynomial-interval-signs prover x)
                       (leaf-signs prover x))))
    (cond ((realp x) (number-signs x))
          ((constant-symbol-p x) '(:positive))
          ((subject-p x) (whole))
          ((not (compound-expression-p x)) nil)
          (t
           (case (expression-operator x)
             ((+ - * / expt) (arithmetic-signs prover x #'whole))
             ((sqrt abs exp log atan asin acos sin cos tan)
              (elementary-function-signs prover x #'whole))
             (t (whole)))))))

(defun arithmetic-signs (prover x whole)
  "The signs of X, a sum, difference, product, quotient or power, from the signs of its
parts (see EXPRESSION-SIGNS); WHOLE, a function of no arguments, gives the signs of X
asked as a whole, where the parts do not settle them."
  (flet ((signs (y) (expression-signs prover y))
         (whole () (funcall whole)))
    (let ((arguments (expression-arguments x)))
      (ecase (expression-operator x)
        (+ (or (sum-signs (mapcar #'signs arguments)) (range-signs prover x) (whole)))
        (- (if (rest arguments)
               (or (sum-signs (cons (signs (first arguments))
                                    (mapcar (lambda (a) (negated-signs (signs a)))
                                            (rest arguments))))
                   (range-signs prover x)
                   (whole))
               (let ((inner (signs (first arguments))))
                 (and inner (negated-signs inner)))))
        ((* /) (or (quotient-signs prover x) (whole)))
        (expt (let ((exponent (second arguments)))
                (or (if (rationalp exponent)
                        (power-signs (signs (first arguments)) exponent)
                        (and (only-signs-p (signs (first arguments)) :positive)
                             (signs exponent)
                             '(:positive)))
                    (whole))))))))

(defun elementary-function-signs (prover x whole)
  "The signs of X, a square root, abs, exp, log, atan, asin, acos, sin, cos or tan, from
the signs of its argument (see EXPRESSION-SIGNS); WHOLE, a function of no arguments,
gives the signs of X asked as a whole, where the argument does not settle them."
  (flet ((signs (y) (expression-signs prover y))
         (whole () (funcall whole)))
    (let ((arguments (expression-arguments x)))
      (ecase (expression-operator x)
        (sqrt (let ((inner (signs (first arguments))))
                (and (only-signs-p inner :positive :zero) inner)))
        (abs (let ((inner (signs (first arguments))))
               (cond ((null inner) (whole))
                     ((member :zero inner) (if (rest inner) '(:positive :zero) '(:zero)))
                     (t '(:positive)))))
        (exp (if (signs (first arguments)) '(:positive) (whole)))
        (log (if (only-signs-p (signs (first arguments)) :positive)
                 (signs (list '- (first arguments) 1))
                 nil))
        (atan (if (rest arguments)
                  (let ((y (signs (first arguments))))
                    (cond ((only-signs-p y :positive) '(:positive))
                          ((only-signs-p y :negative) '(:negative))
                          (t (whole))))
                  (or (signs (first arguments)) (whole))))
        ;; asin is odd and increasing; acos x = pi/2 - asin x lies in [0, pi] and
        ;; is 0 only at x = 1
        (asin (or (signs (first arguments)) (whole)))
        (acos (let ((gap (signs (list '- 1 (first arguments)))))
                (cond ((only-signs-p gap :positive) '(:positive))
                      ((only-signs-p gap :positive :zero) '(:positive :zero))
                      (t (whole)))))
        ((sin cos tan) (or (trigonometric-signs prover x) (whole)))))))

;;; Products

(defun product-parts (x)
  "X as (values COEFFICIENT FACTORS): a rational and a list of (FACTOR . POWER), POWER
1 for a factor of the numerator and -1 for one of the denominator."
  (let ((coefficient 1) (factors '()))
    (labels ((walk (y power)
               (cond ((rationalp y) (setf coefficient (* coefficient (if (= power 1) y (/ y)))))
                     ((and (compound-expression-p y) (eq (expression-operator y) '*))
                      (dolist (factor (expression-arguments y)) (walk factor power)))
                     ((and (compound-expression-p y) (eq (expression-operator y) '/)
                           (rest (expression-arguments y)))
                      (walk (first (expression-arguments y)) power)
                      (dolist (factor (rest (expression-arguments y))) (walk factor (- power))))
                     ((and (compound-expression-p y) (eq (expression-operator y) '-)
                           (null (rest (expression-arguments y))))
                      (setf coefficient (- coefficient))
                      (walk (second y) power))
                     (t (push (cons y power) factors)))))
      (if (and (rationalp x) (zerop x))
          (values 0 '())
          (progn (walk x 1) (values coefficient (nreverse factors)))))))

(defun product-expression (coefficient factors)
  "The expression COEFFICIENT * the product of FACTORS ((FACTOR . POWER) ...)."
  (let ((numerator (loop for (f . p) in factors when (= p 1) collect f))
        (denominator (loop for (f . p) in factors when (= p -1) collect f)))
    (unless (eql coefficient 1) (push coefficient numerator))
    (let ((top (cond ((null numerator) 1) ((rest numerator) (cons '* numerator)) (t (first numerator)))))
      (if denominator
          (list '/ top (if (rest denominator) (cons '* denominator) (first denominator)))
          top))))
