;;;; src/geometry/expressions.lisp -- building prefix-algebra expressions with light simplification.
;;;;
;;;; Geometry computes with exact symbolic coordinates. These constructors (E+, E*, ...)
;;;; fold numbers, drop neutral elements and collect like terms, so that rational inputs
;;;; stay exact rationals and symbolic results stay readable. They never decide a sign:
;;;; everything that depends on a parameter's value is left for DECIDE (decide.lisp).
;;;; Also here: the exact value of a constant expression, and the derivative of an
;;;; expression with respect to a variable (for contact approach rates). The circular
;;;; functions and the clear sign of a constant are in angles.lisp.
;;;;
;;;; Bounds: exact arithmetic can grow without end ((expt 10 (expt 10 9)) in a coordinate,
;;;; a product of thirty constant sums that doubles at every factor). The constructors work
;;;; within the budget of the run in progress (src/base/limits.lisp): an exact power or
;;;; product whose result would need more bits than the limits allow, and a sum or an
;;;; expansion with more terms, signal BUDGET-EXCEEDED before they are built, and the
;;;; recursions check the run's deadline as they go.

(in-package #:ames.geometry)

;;; A total order on expressions, used to sort the factors of a product and the terms
;;; of a sum, so that equal expressions come out EQUAL.

(defun expression-rank (x)
  (cond ((numberp x) 0) ((symbolp x) 1) (t 2)))

(defun expression< (a b)
  "A total order on expressions: numbers, then symbols by name, then lists."
  (let ((ra (expression-rank a)) (rb (expression-rank b)))
    (cond ((/= ra rb) (< ra rb))
          ((numberp a) (< (realpart a) (realpart b)))
          ((symbolp a) (string< (symbol-name a) (symbol-name b)))
          (t (loop for xa on a for xb on b
                   do (cond ((expression< (car xa) (car xb)) (return t))
                            ((expression< (car xb) (car xa)) (return nil)))
                   finally (return (< (length a) (length b))))))))

;;; Products: a rational (or float) coefficient times factors BASE^EXPONENT. Division is
;;; multiplication by BASE^-1, equal bases combine their numeric exponents, and the
;;; square root of a rational is kept as M * (SQRT K) with K a square-free integer, so
;;; that expressions over rationals and their square roots cancel exactly.

(defun constant-expression-p (x)
  "True when X contains no variable and no quantity term."
  (null (expression-variables x)))

(defun power-bits (base power)
  "An upper bound on the size in bits of the rational BASE raised to the integer POWER."
  (1+ (* (abs power) (max (integer-length (1- (abs (numerator base))))
                          (integer-length (1- (denominator base)))))))

(defun exact-expt (base power)
  "BASE^POWER for a rational BASE and an integer POWER (BASE not 0 when POWER is
negative), after checking that the result fits the current limits: signals
BUDGET-EXCEEDED (quantity :INTEGER-BITS) when it would not."
  (check-number-size (power-bits base power) (list 'expt base power))
  (expt base power))

(defun power-parts (x)
  "X as (values BASE EXPONENT) when it is a power with a numeric exponent, else X and 1.
Nested powers flatten when the outer exponent is an integer."
  (if (and (consp x) (eq (car x) 'expt) (rationalp (third x)))
      (multiple-value-bind (base exponent) (power-parts (second x))
        (if (and (integerp (third x)) (not (eql exponent 1)))
            (values base (* exponent (third x)))
            (values (second x) (third x))))
      (values x 1)))

(defun product-factors (x)
  "X as (values COEFFICIENT FACTORS) with X = COEFFICIENT * product of FACTORS; the
factors are neither numbers nor products."
  (cond ((numberp x) (values x '()))
        ((and (consp x) (eq (car x) '*))
         (let ((coefficient 1) (factors '()))
           (dolist (f (cdr x))
             (multiple-value-bind (c fs) (product-factors f)
               (setf coefficient (check-rational-size (* coefficient c) x))
               (setf factors (append factors fs))))
           (values coefficient factors)))
        ((and (consp x) (eq (car x) '-) (= (length x) 2))
         (multiple-value-bind (c fs) (product-factors (second x))
           (values (- c) fs)))
        ((and (consp x) (eq (car x) '/) (= (length x) 3))
         (multiple-value-bind (c fs) (product-factors (second x))
           (multiple-value-bind (d gs) (product-factors (third x))
             (if (and (numberp d) (not (zerop d)))
                 (values (/ c d) (append fs (mapcar (lambda (g) (list 'expt g -1)) gs)))
                 (values c (append fs (list (list 'expt (third x) -1))))))))
        (t (values 1 (list x)))))

(defun combine-factors (coefficient factors)
  "COEFFICIENT and FACTORS with equal bases merged and exact parts folded into the
coefficient: (values COEFFICIENT FACTORS)."
  (let ((powers '()))
    (dolist (f factors)
      (multiple-value-bind (base exponent) (power-parts f)
        (let ((entry (assoc base powers :test #'equal)))
          (if entry
              (incf (cdr entry) exponent)
              (push (cons base exponent) powers)))))
    (let ((kept '()))
      (loop for (base . exponent) in (nreverse powers)
            do (cond ((zerop exponent))
                     ((and (rationalp base) (integerp exponent) (not (zerop base)))
                      (setf coefficient (check-rational-size
                                         (* coefficient (exact-expt base exponent)) base)))
                     ((and (consp base) (eq (car base) 'sqrt) (rationalp (second base))
                           (integerp exponent))
                      (multiple-value-bind (whole odd) (floor exponent 2)
                        (setf coefficient (check-rational-size
                                           (* coefficient (exact-expt (second base) whole))
                                           base))
                        (when (= odd 1) (push base kept))))
                     ((eql exponent 1) (push base kept))
                     (t (push (list 'expt base exponent) kept))))
      (values coefficient (nreverse kept)))))

(defun render-product (coefficient factors)
  "COEFFICIENT times FACTORS (non-numeric, sorted) as a prefix expression."
  (cond ((zerop coefficient) 0)
        ((null factors) coefficient)
        (t (let ((body (if (rest factors) (cons '* factors) (first factors))))
             (cond ((eql coefficient 1) body)
                   ((eql coefficient -1) (list '- body))
                   ((rest factors) (list* '* coefficient factors))
                   (t (list '* coefficient body)))))))

(defun build-product (coefficient factors)
  "The canonical product of COEFFICIENT and FACTORS; factors with negative exponents
go to a denominator: (/ NUMERATOR DENOMINATOR)."
  (multiple-value-bind (coefficient factors) (combine-factors coefficient factors)
    (let ((upper '()) (lower '()))
      (dolist (f factors)
        (multiple-value-bind (base exponent) (power-parts f)
          (if (and (realp exponent) (minusp exponent))
              (push (if (eql exponent -1) base (list 'expt base (- exponent))) lower)
              (push f upper))))
      (let ((upper (sort upper #'expression<)) (lower (sort lower #'expression<)))
        (if (or (null lower) (zerop coefficient))
            (render-product coefficient upper)
            (list '/ (render-product coefficient upper) (render-product 1 lower)))))))

(defun sum-expression-p (x)
  (and (consp x) (eq (car x) '+)))

(defun expansion-size (factors)
  "The number of terms that expanding the product of FACTORS over its sums gives at
most (counted up to a little past the current limits, then no further)."
  (let ((limit (limits-expression-size (current-limits))) (size 1))
    (dolist (f factors size)
      (when (sum-expression-p f)
        (setf size (* size (length (cdr f))))
        (when (> size limit) (return size))))))

(defun e* (&rest factors)
  "The product of FACTORS: numbers folded, powers of equal bases combined; a product
of constants is expanded over sums. Signals BUDGET-EXCEEDED when a number or the
expansion would be larger than the current limits allow."
  (check-budget factors)
  (multiple-value-bind (c fs) (product-factors (cons '* factors))
    (setf fs (mapcan (lambda (f)
                       (if (and (consp f) (eq (car f) 'expt) (integerp (third f))
                                (<= 2 (third f) 6) (sum-expression-p (second f))
                                (constant-expression-p (second f)))
                           (make-list (third f) :initial-element (second f))
                           (list f)))
                     fs))
    (let ((sum (find-if #'sum-expression-p fs)))
      (if (and sum (or (null (rest fs)) (every #'constant-expression-p fs)))
          (let ((rest (remove sum fs :count 1 :test #'eq)))
            (check-expression-size (expansion-size fs) (cons '* factors))
            (apply #'e+ (mapcar (lambda (term) (apply #'e* c term rest)) (cdr sum))))
          (build-product c fs)))))

(defun sum-terms (x)
  "X as a list of (COEFFICIENT . KEY) terms, KEY being 1 for the constant term."
  (cond ((numberp x) (list (cons x 1)))
        ((and (consp x) (eq (car x) '+)) (mapcan #'sum-terms (copy-list (cdr x))))
        ((and (consp x) (eq (car x) '-) (= (length x) 2))
         (mapcar (lambda (term) (cons (- (car term)) (cdr term))) (sum-terms (second x))))
        ((and (consp x) (eq (car x) '-))
         (append (sum-terms (second x))
                 (mapcan (lambda (y)
                           (mapcar (lambda (term) (cons (- (car term)) (cdr term)))
                                   (sum-terms y)))
                         (cddr x))))
        (t (multiple-value-bind (c fs) (product-factors x)
             (if (null fs)
                 (list (cons c 1))
                 (list (cons c (build-product 1 fs))))))))

(defun pythagorean-pairs (collected)
  "The alist COLLECTED (KEY . COEFFICIENT) of a sum with every pair c K cos(x)^2 +
c K sin(x)^2 replaced by c K."
  (flet ((square-of (f head)
           (and (consp f) (eq (car f) 'expt) (eql (third f) 2)
                (consp (second f)) (eq (car (second f)) head)
                (second (second f)))))
    (loop
      (let ((found nil))
        (loop named search
              for entry in collected
              do (multiple-value-bind (c factors) (product-factors (car entry))
                   (let ((cosine (find-if (lambda (f) (square-of f 'cos)) factors)))
                     (when cosine
                       (let* ((argument (square-of cosine 'cos))
                              (others (remove cosine factors :count 1 :test #'eq))
                              (partner-key (build-product 1 (cons (list 'expt (list 'sin argument) 2)
                                                                   others)))
                              (partner (assoc partner-key collected :test #'equal)))
                         (when (and partner (= (* c (cdr entry)) (cdr partner)))
                           (let ((key (build-product 1 others)))
                             (setf collected (remove partner (remove entry collected)))
                             (let ((existing (assoc key collected :test #'equal)))
                               (if existing
                                   (incf (cdr existing) (* c (cdr entry)))
                                   (push (cons key (* c (cdr entry))) collected))))
                           (setf found t)
                           (return-from search)))))))
        (unless found (return collected))))))

(defun e+ (&rest addends)
  "The sum of ADDENDS, with numbers folded and like terms collected. Signals
BUDGET-EXCEEDED when it has more terms than the current limits allow."
  (let* ((collected '())
         (terms (mapcan #'sum-terms addends))
         (count (length terms))
         ;; like terms are found by hashing when there are many (by EQUAL, as ASSOC did)
         (index (and (> count 16) (make-hash-table :test 'equal :size count))))
    (check-expression-size count (cons '+ addends))
    (dolist (term terms)
      (check-budget addends)
      (let ((entry (if index
                       (gethash (cdr term) index)
                       (assoc (cdr term) collected :test #'equal))))
        (if entry
            (setf (cdr entry) (check-rational-size (+ (cdr entry) (car term)) (cdr term)))
            (let ((entry (cons (cdr term) (car term))))
              (when index (setf (gethash (cdr term) index) entry))
              (push entry collected)))))
    (setf collected (pythagorean-pairs collected))
    (let* ((constant (let ((entry (assoc 1 collected :test #'eql))) (if entry (cdr entry) 0)))
           (terms (loop for (key . coefficient) in collected
                        unless (or (eql key 1) (zerop coefficient))
                          collect (multiple-value-bind (c fs) (product-factors key)
                                    (build-product (* c coefficient) fs))))
           (terms (sort terms #'expression<
                        :key (lambda (x) (if (and (consp x) (eq (car x) '-)) (second x) x))))
           (all (if (zerop constant) terms (append terms (list constant)))))
      (cond ((null all) 0)
            ((null (rest all)) (first all))
            (t (cons '+ all))))))

(defun e- (x &rest subtrahends)
  "Negation of X, or X minus SUBTRAHENDS."
  (if subtrahends
      (apply #'e+ x (mapcar (lambda (y) (e* -1 y)) subtrahends))
      (e* -1 x)))

(defun e/ (numerator denominator)
  "NUMERATOR divided by DENOMINATOR (a product with DENOMINATOR^-1). Signals
DIVISION-BY-ZERO for a literal zero denominator."
  (if (and (numberp denominator) (zerop denominator))
      (error 'division-by-zero :operation 'e/ :operands (list numerator denominator))
      (e* numerator (eexpt denominator -1))))

(defun eexpt (base power)
  "BASE raised to POWER. Signals BUDGET-EXCEEDED when an exact result would be larger
than the current limits allow."
  (cond ((eql power 0) 1)
        ((eql power 1) base)
        ((and (rationalp base) (integerp power) (not (and (zerop base) (minusp power))))
         (exact-expt base power))
        ((and (eql base 0) (realp power) (plusp power)) 0)
        ((eql base 1) 1)
        ((and (integerp power) (or (consp base) (symbolp base)))
         ;; an integer power distributes over the factors of a product
         (multiple-value-bind (c fs) (product-factors base)
           (if (and (zerop c) (minusp power))
               (list 'expt base power)
               (build-product (if (rationalp c) (exact-expt c power) (expt c power))
                              (mapcar (lambda (f) (list 'expt f power)) fs)))))
        (t (list 'expt base power))))

(defun esquare (x) "X squared." (eexpt x 2))

(defun square-free-split (n)
  "The positive integer N as (values M K) with N = M^2 K and K square-free (trial
division; a large cofactor is kept whole in K)."
  (let ((m 1) (k 1))
    (loop for p from 2
          while (and (<= (* p p) n) (< p 100000))
          do (check-budget n)
             (loop while (zerop (mod n (* p p)))
                   do (setf n (/ n (* p p)) m (* m p)))
             (when (zerop (mod n p))
               (setf n (/ n p) k (* k p))))
    (values m (* k n))))

(defun esqrt (x)
  "The square root of X: exact for rational squares, M * (SQRT K) with K square-free
for other non-negative rationals."
  (cond ((rational-root x 2))
        ((and (rationalp x) (plusp x))
         (multiple-value-bind (m k) (square-free-split (* (numerator x) (denominator x)))
           (e* (/ m (denominator x)) (list 'sqrt k))))
        ((and (consp x) (eq (car x) 'expt) (eql (third x) 2) (rationalp (second x)))
         (abs (second x)))
        (t (list 'sqrt x))))

(defun normalize-expression (expression)
  "EXPRESSION rebuilt bottom-up through the simplifying constructors: numbers folded,
like terms collected. Quantity terms and unknown forms are kept as they are. Signals
BUDGET-EXCEEDED when a number or a sum would grow larger than the current limits allow,
or the run's deadline passes."
  (check-budget expression)
  (cond ((atom expression) expression)
        ((quantity-term-p expression) expression)
        (t (let ((operator (car expression))
                 (arguments (mapcar #'normalize-expression (cdr expression))))
             (case operator
               (+ (apply #'e+ arguments))
               (- (apply #'e- arguments))
               (* (apply #'e* arguments))
               (/ (if (rest arguments)
                      (reduce #'e/ arguments)
                      (e/ 1 (first arguments))))
               (expt (eexpt (first arguments) (second arguments)))
               (sqrt (esqrt (first arguments)))
               (cos (ecos (first arguments)))
               (sin (esin (first arguments)))
               (tan (etan (first arguments)))
               (atan (if (rest arguments)
                         (eatan2 (first arguments) (second arguments))
                         (list 'atan (first arguments))))
               (t (cons operator arguments)))))))

;;; Evaluation of constant expressions (AMES.BASE:EXPRESSION-VALUE does the arithmetic).

(defun rational-value (expression)
  "The exact rational value of the constant EXPRESSION when it has one (built from
rationals with + - * /, integer powers and rational roots), else NIL."
  (multiple-value-bind (value exact) (expression-value expression)
    (and exact (rationalp value) value)))

;;; Derivatives (of relative trajectories and gap functions with respect to time).

(defun differentiate (expression variable)
  "The derivative of EXPRESSION (prefix algebra) with respect to the variable VARIABLE,
lightly simplified. Quantity terms and other variables are constants, and so is any
subexpression free of VARIABLE, whatever its operator (the length |l| of a parameter);
d|u| = u u' / |u|. Signals MALFORMED-EXPRESSION for an operator it does not know in a
subexpression that depends on VARIABLE."
  (labels ((d (x)
             (check-budget expression)
             (cond ((eq x variable) 1)
                   ((or (atom x) (quantity-term-p x) (free-of-p variable x)) 0)
                   (t (let ((args (cdr x)))
                        (case (car x)
                          (+ (apply #'e+ (mapcar #'d args)))
                          (- (apply #'e- (mapcar #'d args)))
                          (* (apply #'e+
                                    (loop for i from 0 below (length args)
                                          collect (apply #'e*
                                                         (loop for a in args for j from 0
                                                               collect (if (= i j) (d a) a))))))
                          (/ (if (rest args)
                                 (let ((u (first args)) (v (apply #'e* (rest args))))
                                   (e/ (e- (e* (d u) v) (e* u (d v))) (esquare v)))
                                 (e/ (e- (d (first args))) (esquare (first args)))))
                          (expt (destructuring-bind (u n) args
                                  (if (free-of-p variable n)
                                      (e* n (eexpt u (e- n 1)) (d u))
                                      (d (list 'exp (list '* n (list 'log u)))))))
                          (sqrt (e/ (d (first args)) (e* 2 (esqrt (first args)))))
                          ;; |u|' = u u' / |u| (0 where u is free of the variable)
                          (abs (if (free-of-p variable (first args))
                                   0
                                   (e/ (e* (first args) (d (first args))) x)))
                          (exp (e* x (d (first args))))
                          (log (e/ (d (first args)) (first args)))
                          (sin (e* (ecos (first args)) (d (first args))))
                          (cos (e- (e* (esin (first args)) (d (first args)))))
                          (tan (e/ (d (first args)) (esquare (ecos (first args)))))
                          (sinh (e* (list 'cosh (first args)) (d (first args))))
                          (cosh (e* (list 'sinh (first args)) (d (first args))))
                          (tanh (e/ (d (first args)) (esquare (list 'cosh (first args)))))
                          (asin (e/ (d (first args)) (esqrt (e- 1 (esquare (first args))))))
                          (acos (e- (e/ (d (first args)) (esqrt (e- 1 (esquare (first args)))))))
                          (atan (if (rest args)
                                    (destructuring-bind (y u) args
                                      (e/ (e- (e* u (d y)) (e* y (d u)))
                                          (e+ (esquare u) (esquare y))))
                                    (e/ (d (first args)) (e+ 1 (esquare (first args))))))
                          (t (error 'malformed-expression
                                    :datum x :expression expression
                                    :detail "cannot differentiate this operator"))))))))
    (d expression)))
