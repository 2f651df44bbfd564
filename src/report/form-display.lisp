;;;; src/report/form-display.lisp -- the arranged expression written back in the algebra:
;;;; terms normalised, square roots made real and merged where that keeps the value, signs
;;;; absorbed, and ARRANGE, the entry point (the parsed SUMs and TERMs, and the ranking of
;;;; their bases, are forms.lisp's).

(in-package #:ames.report)

;;; Display: the arranged expression of the algebra

(defun sum-base-p (base)
  "True when BASE is a sum kept as a factor."
  (and (consp base) (eq (first base) :sum)))

(defun half-integer-p (exponent)
  "True when EXPONENT is an odd multiple of 1/2 (a power of a square root)."
  (and (rationalp exponent) (= 2 (denominator exponent))))

(defun radicals-made-real (powers arrangement)
  "POWERS with every square-root power of a base known to be negative written with the
base negated: sqrt(x)^m = i^m sqrt(-x)^m for x < 0. Returns (values POWERS SIGN): when
the phases i^m multiply to +1 or -1, the rewritten powers and that sign; otherwise (the
product is not real) POWERS unchanged and 1."
  (let ((phase 0) (rewritten '()))
    (dolist (power powers)
      (destructuring-bind (base . exponent) power
        (if (and (half-integer-p exponent) (not (realp base))
                 (funcall (arrangement-negative-p arrangement) (display-base base arrangement)))
            (progn (incf phase (* 2 exponent))
                   (push (cons (cons :sum (if (sum-base-p base)
                                              (negate-sum (rest base))
                                              (list (make-term -1 (list (cons base 1))))))
                               exponent)
                         rewritten))
            (push power rewritten))))
    (if (evenp phase)
        (values (nreverse rewritten) (if (zerop (mod phase 4)) 1 -1))
        (values powers 1))))

(defun normalised-term (term arrangement)
  "TERM with cos/sin merged into tan, each difference among its integer powers written
with its positive terms first, or the other way round when the arrangement knows it to
be negative (the sign going to the coefficient when the power is odd), and the square
roots of negative bases written as roots of their negations (see RADICALS-MADE-REAL)."
  (let ((coefficient (term-coefficient term)) (powers '()))
    (dolist (power (tangents-merged (term-powers term)))
      (destructuring-bind (base . exponent) power
        (if (and (sum-base-p base) (integerp exponent)
                 (or (every (lambda (x) (minusp (term-coefficient x))) (rest base))
                     (funcall (arrangement-negative-p arrangement)
                              (display-sum (rest base) arrangement))))
            (progn (push (cons (cons :sum (negate-sum (rest base))) exponent) powers)
                   (when (oddp exponent) (setf coefficient (- coefficient))))
            (push power powers))))
    (multiple-value-bind (real-powers sign) (radicals-made-real (nreverse powers) arrangement)
      (reduce #'multiply-terms (mapcar (lambda (p) (make-term 1 (list p))) real-powers)
              :initial-value (make-term (* sign coefficient) '())))))

(defun display-base (base arrangement)
  "The expression for BASE."
  (cond ((or (realp base) (symbolp base) (quantity-term-p base)) base)
        ((eq (first base) :sum) (display-sum (rest base) arrangement))
        ((eq (first base) :call)
         (list* (second base) (mapcar (lambda (sum) (display-sum sum arrangement)) (cddr base))))
        (t (second base))))

(defun display-power (base exponent arrangement)
  "BASE to EXPONENT as an expression (BASE alone for exponent 1)."
  (let ((shown (display-base base arrangement)))
    (if (eql exponent 1) shown (list 'expt shown exponent))))

(defun display-product (factors)
  "The product of the expressions FACTORS (1 when there is none)."
  (cond ((null factors) 1) ((null (rest factors)) (first factors)) (t (cons '* factors))))

(defun radicals-to-merge (radicals arrangement)
  "RADICALS, a list of (BASE . M) for BASE^(M/2) with M odd, split into (values MERGED
ALONE): MERGED go under one square root, ALONE stay roots of their own. sqrt(x) sqrt(y)
= sqrt(x y) only when x or y is >= 0, so every base not known to be >= 0 stays alone,
except one with M = 1 (M = -1 when every power is negative, the root then being a
divisor) among bases that are."
  (let* ((inverted (every (lambda (p) (minusp (cdr p))) radicals))
         (unit (if inverted -1 1))
         (merged '()) (alone '()) (open-slot t))
    (dolist (radical radicals)
      (destructuring-bind (base . twice) radical
        (cond ((or (and (realp base) (plusp base))
                   (funcall (arrangement-nonnegative-p arrangement) (display-base base arrangement)))
               (push radical merged))
              ((and open-slot (eql twice unit))
               (setf open-slot nil)
               (push radical merged))
              (t (push radical alone)))))
    (values (nreverse merged) (nreverse alone))))

(defun square-part (n)
  "For a positive integer N, (values Q R) with N = Q^2 R and R free of squares."
  (let ((q 1) (r 1) (k 2))
    (loop while (> n 1)
          do (if (> (* k k) n)
                 (progn (setf r (* r n) n 1))
                 (let ((m 0))
                   (loop while (zerop (mod n k)) do (setf n (/ n k)) (incf m))
                   (setf q (* q (expt k (floor m 2))))
                   (when (oddp m) (setf r (* r k)))
                   (incf k))))
    (values q r)))

(defun numeric-roots-simplified (term)
  "TERM with each power of a positive integer to a half-integer exponent written as a
coefficient times the square root of a square-free integer: sqrt(8) as 2 sqrt(2),
2^(3/2) as 2 sqrt(2), 18^(-1/2) as 1/(3 sqrt(2)). Keeps the value."
  (let ((coefficient (term-coefficient term)) (powers '()))
    (dolist (power (term-powers term))
      (destructuring-bind (base . exponent) power
        (if (and (integerp base) (plusp base) (half-integer-p exponent)
                 (< (integer-length base) 40))
            ;; b^e with b = n/d: (n d)^e d^(-2e), and n d = q^2 r
            (let* ((whole (truncate exponent)) (half (- exponent whole))
                   (product (* (numerator base) (denominator base))))
              (multiple-value-bind (q r) (square-part product)
                (setf coefficient (* coefficient (expt base whole) (expt q (* 2 half))
                                     (expt (denominator base) (* -2 half))))
                (unless (eql r 1) (push (cons r half) powers))))
            (push power powers))))
    (make-term coefficient (nreverse powers))))

(defun display-term (term arrangement)
  "TERM as an expression: numeric coefficient first, factors by their keys, the
square roots merged into one, a quotient when there are negative powers, a negation
for a negative coefficient."
  (let* ((term (numeric-roots-simplified term))
         (coefficient (term-coefficient term))
         (numerator '()) (denominator '()) (radicals '()))
    (dolist (power (term-powers term))
      (destructuring-bind (base . exponent) power
        (cond ((and (realp base) (integerp exponent))
               (setf coefficient (* coefficient (expt base exponent))))
              ((integerp exponent)
               (if (plusp exponent) (push power numerator) (push (cons base (- exponent)) denominator)))
              ((and (rationalp exponent) (= 2 (denominator exponent)))
               (push (cons base (* 2 exponent)) radicals))
              ((plusp exponent) (push power numerator))
              (t (push (cons base (- exponent)) denominator)))))
    (flet ((arranged (powers)
             (mapcar (lambda (p) (display-power (car p) (cdr p) arrangement))
                     (stable-sort (nreverse powers) #'compare-keys
                                  :key (lambda (p) (base-key (car p) arrangement))))))
      (multiple-value-bind (merged alone) (radicals-to-merge (reverse radicals) arrangement)
        (let* ((magnitude (abs coefficient))
               (top (if (rationalp magnitude) (numerator magnitude) magnitude))
               (bottom (if (rationalp magnitude) (denominator magnitude) 1))
               ;; one square root; in the denominator when it has only negative powers
               (inverted (and merged (every (lambda (p) (minusp (cdr p))) merged)))
               (root (and merged
                          (list 'sqrt (display-term (make-term 1 (mapcar (lambda (p)
                                                                           (cons (car p) (if inverted (- (cdr p)) (cdr p))))
                                                                         merged))
                                                    arrangement))))
               (upper (append (unless (eql top 1) (list top)) (arranged numerator)
                              (and root (not inverted) (list root))
                              (loop for (base . twice) in alone
                                    unless (eql twice -1)
                                      collect (if (eql twice 1)
                                                  (list 'sqrt (display-base base arrangement))
                                                  (display-power base (/ twice 2) arrangement)))))
               (lower (append (unless (eql bottom 1) (list bottom)) (arranged denominator)
                              (and root inverted (list root))
                              (loop for (base . twice) in alone
                                    when (eql twice -1)
                                      collect (list 'sqrt (display-base base arrangement)))))
               (whole (if lower
                          (list '/ (display-product upper) (display-product lower))
                          (display-product upper))))
          (if (minusp coefficient) (list '- whole) whole))))))

(defun sign-absorbed (term arrangement)
  "TERM, when its coefficient is negative and it has a sum among its odd powers whose
negation is not known to be negative, with that sum negated and the coefficient made
positive: -(b - a) c is written (a - b) c."
  (let ((power (and (minusp (term-coefficient term))
                    (find-if (lambda (p) (and (sum-base-p (car p)) (integerp (cdr p)) (oddp (cdr p))
                                              (not (funcall (arrangement-negative-p arrangement)
                                                            (display-sum (negate-sum (rest (car p)))
                                                                         arrangement)))))
                             (term-powers term)))))
    (if power
        (make-term (- (term-coefficient term))
                   (substitute (cons (cons :sum (negate-sum (rest (car power)))) (cdr power)) power
                               (term-powers term)))
        term)))

(defun display-sum (sum arrangement)
  "SUM as an expression, its terms in the arrangement's order. A single term with a
negative coefficient gives its sign to a difference among its factors."
  (let ((terms (stable-sort (mapcar (lambda (term) (normalised-term term arrangement))
                                    (collect-like-terms sum))
                            #'compare-keys :key (lambda (term) (term-key term arrangement)))))
    (when (and terms (null (rest terms)))
      (setf terms (list (sign-absorbed (first terms) arrangement))))
    (cond ((null terms) 0)
          ((null (rest terms)) (display-term (first terms) arrangement))
          (t (cons '+ (mapcar (lambda (term) (display-term term arrangement)) terms))))))

(defun arrange (expression arrangement)
  "EXPRESSION (arithmetic, prefix algebra) arranged as a textbook writes it (see the
file header): an expression of the algebra of the same value."
  (display-sum (parse-form expression) arrangement))

(defun form-size (expression)
  "The number of atoms and operators of EXPRESSION: what the presentation minimises."
  (if (atom expression) 1 (reduce #'+ (mapcar #'form-size expression))))
