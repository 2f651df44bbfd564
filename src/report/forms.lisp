;;;; src/report/forms.lisp -- the textbook arrangement of an expression: terms and factors in a
;;;; conventional order, signs pulled out of differences, radicals merged.
;;;;
;;;; Maxima chooses what is factored and simplified (see presentation.lisp); this file only
;;;; arranges what it gets, by rules that keep the value: + and * are reordered, a sum is
;;;; negated together with the sign of its odd power, cos^k x / sin^k x is written 1/tan^k x,
;;;; the square root of a base known to be negative is written with the base negated (sqrt(x)
;;;; sqrt(y) = -sqrt(-x) sqrt(-y) for x, y < 0), and square roots merge into one only where that
;;;; keeps the value (sqrt(x) sqrt(y) = sqrt(x y) needs x or y >= 0). The result is an
;;;; ordinary expression of the algebra, so Maxima can still check that it equals the solved
;;;; form (the tests do, on every scenario).
;;;;
;;;; A parsed expression is a SUM: a list of TERMs. A term is a coefficient (a number) times
;;;; powers ((BASE . EXPONENT) ...). A base is a variable, a quantity term, PI, a positive
;;;; number (under a fractional exponent only), (:SUM . TERMS) (a sum kept as a factor),
;;;; (:CALL OPERATOR SUM ...) (a function applied), or (:OPAQUE EXPRESSION). This file
;;;; parses and ranks them; form-display.lisp writes the arranged expression (ARRANGE).

(in-package #:ames.report)

(defstruct (term (:type list) (:constructor make-term (coefficient powers)))
  "COEFFICIENT times the product of (BASE . EXPONENT) in POWERS: a list, so that EQUAL
compares terms (and the bases made of them) by their contents."
  coefficient powers)

(defun single-term (sum)
  "The only term of SUM, or NIL when it has none or several."
  (and sum (null (rest sum)) (first sum)))

(defun sum-as-term (sum)
  "SUM as one term: itself when it has one term, 0 when none, else a (:SUM ...) base."
  (cond ((null sum) (make-term 0 '()))
        ((single-term sum))
        (t (make-term 1 (list (cons (cons :sum sum) 1))))))

(defun multiply-terms (a b)
  "The product of the terms A and B, equal bases merged."
  (let ((powers (copy-alist (term-powers a))))
    (dolist (power (term-powers b))
      (let ((same (assoc (car power) powers :test #'equal)))
        (if same
            (setf (cdr same) (+ (cdr same) (cdr power)))
            (setf powers (append powers (list (cons (car power) (cdr power))))))))
    (make-term (* (term-coefficient a) (term-coefficient b))
               (remove 0 powers :key #'cdr))))

(defun term-power (term exponent)
  "TERM to the integer EXPONENT."
  (make-term (expt (term-coefficient term) exponent)
             (if (zerop exponent)
                 '()
                 (mapcar (lambda (p) (cons (car p) (* (cdr p) exponent))) (term-powers term)))))

(defun negate-sum (sum)
  "SUM with every coefficient negated."
  (mapcar (lambda (term) (make-term (- (term-coefficient term)) (term-powers term))) sum))

(defun collect-like-terms (sum)
  "SUM with terms of equal powers added, zero terms dropped."
  (let ((result '()))
    (dolist (term sum)
      (let ((same (find (term-powers term) result :key #'term-powers :test #'equal)))
        (if same
            (setf (term-coefficient same) (+ (term-coefficient same) (term-coefficient term)))
            (push (make-term (term-coefficient term) (term-powers term)) result))))
    (remove-if (lambda (term) (and (rationalp (term-coefficient term))
                                   (zerop (term-coefficient term))))
               (nreverse result))))

(defun parse-form (expression)
  "EXPRESSION (arithmetic, prefix algebra) as a SUM (see the file header)."
  (labels ((atom-sum (base) (list (make-term 1 (list (cons base 1)))))
           (product (sums)
             (list (reduce #'multiply-terms (mapcar #'sum-as-term sums)
                           :initial-value (make-term 1 '()))))
           (power (base-sum exponent whole)
             (let ((term (single-term base-sum)))
               (cond ((not (realp exponent)) (atom-sum (list :opaque whole)))
                     ((null base-sum) (if (plusp exponent) '() (atom-sum (list :opaque whole))))
                     ((integerp exponent)
                      (if (and term (not (and (zerop (term-coefficient term)) (minusp exponent))))
                          (list (term-power term exponent))
                          (list (make-term 1 (list (cons (cons :sum base-sum) exponent))))))
                     ;; a fractional power is kept whole: (x^2)^(1/2) is |x|, not x
                     ((and term (null (term-powers term)) (rationalp (term-coefficient term))
                           (plusp (term-coefficient term)))
                      (list (make-term 1 (list (cons (term-coefficient term) exponent)))))
                     ;; a whole coefficient comes out: (8 h)^(1/2) = 8^(1/2) h^(1/2) (a
                     ;; fraction stays inside, sqrt(2 h/3): Maxima proves that form equal
                     ;; more often than sqrt(6 h)/3)
                     ((and term (term-powers term) (integerp (term-coefficient term))
                           (> (term-coefficient term) 1))
                      (list (multiply-terms (make-term 1 (list (cons (term-coefficient term) exponent)))
                                            (first (power (list (make-term 1 (term-powers term))) exponent whole)))))
                     ((and term (eql 1 (term-coefficient term)) (= 1 (length (term-powers term)))
                           (eql 1 (cdr (first (term-powers term)))))
                      (list (make-term 1 (list (cons (car (first (term-powers term))) exponent)))))
                     (t (list (make-term 1 (list (cons (cons :sum base-sum) exponent))))))))
           (walk (x)
             (cond ((realp x) (if (and (rationalp x) (zerop x)) '() (list (make-term x '()))))
                   ((or (variable-symbol-p x) (constant-symbol-p x) (quantity-term-p x))
                    (atom-sum x))
                   ((not (consp x)) (atom-sum (list :opaque x)))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (collect-like-terms (mapcan #'walk (copy-list arguments))))
                          (- (if (rest arguments)
                                 (collect-like-terms
                                  (append (walk (first arguments))
                                          (mapcan (lambda (a) (negate-sum (walk a))) (rest arguments))))
                                 (negate-sum (walk (first arguments)))))
                          (* (product (mapcar #'walk arguments)))
                          (/ (if (rest arguments)
                                 (product (cons (walk (first arguments))
                                                (mapcar (lambda (a) (power (walk a) -1 a)) (rest arguments))))
                                 (power (walk (first arguments)) -1 x)))
                          (expt (power (walk (first arguments)) (second arguments) x))
                          (sqrt (power (walk (first arguments)) 1/2 x))
                          ((sin cos tan asin acos atan exp log)
                           (atom-sum (list* :call (expression-operator x) (mapcar #'walk arguments))))
                          (t (atom-sum (list :opaque x)))))))))
    (walk expression)))

;;; Arranging: the context says how symbols rank and which sums are negative

(defstruct (arrangement (:constructor make-arrangement
                            (&key symbol-key negative-p (nonnegative-p (constantly nil)) variable)))
  "How to arrange: SYMBOL-KEY maps a variable or quantity term to its sort key (a list
of numbers and strings: masses first, then the other parameters as declared, the time
last); NEGATIVE-P (a function of an expression) says when a difference is known to be
negative, so that it is written the other way round, and NONNEGATIVE-P when an
expression is known to be >= 0, so that its square root merges with others; VARIABLE,
when given, orders a sum's terms by their power of it first (a polynomial in tau)."
  symbol-key negative-p nonnegative-p variable)

(defparameter *function-order* '(sin cos tan asin acos atan exp log sqrt)
  "The order of functions among the factors of a product: sin a cos a, then roots.")

(defun compare-keys (a b)
  "True when the sort key A comes before B (lists of reals and strings, lexicographic)."
  (loop for x in a for y in b
        do (cond ((and (realp x) (realp y))
                  (cond ((< x y) (return-from compare-keys t)) ((> x y) (return-from compare-keys nil))))
                 ((and (stringp x) (stringp y))
                  (cond ((string< x y) (return-from compare-keys t)) ((string> x y) (return-from compare-keys nil))))
                 (t (return-from compare-keys (realp x)))))
  (< (length a) (length b)))

(defun base-symbols (base)
  "The variables and quantity terms inside BASE."
  (cond ((or (variable-symbol-p base) (quantity-term-p base)) (list base))
        ((and (consp base) (eq (first base) :sum))
         (loop for term in (rest base) append (loop for p in (term-powers term) append (base-symbols (car p)))))
        ((and (consp base) (eq (first base) :call))
         (loop for sum in (cddr base) append (base-symbols (cons :sum sum))))
        ((and (consp base) (eq (first base) :opaque)) (expression-variables (second base)))
        (t '())))

(defun base-key (base arrangement)
  "The sort key of BASE among the factors of a product: numbers, pi, the symbols by
their keys (a sum after the plain symbols of its class), then functions, then roots."
  (cond ((realp base) (list 0))
        ((constant-symbol-p base) (list 1))
        ((or (variable-symbol-p base) (quantity-term-p base))
         (let ((key (funcall (arrangement-symbol-key arrangement) base)))
           (list* (first key) 0 (rest key))))
        ((eq (first base) :sum)
         (let ((keys (sort (mapcar (arrangement-symbol-key arrangement) (base-symbols base)) #'compare-keys)))
           (if keys
               (list* (first (first keys)) 1 (rest (first keys)))
               (list 1 1))))
        ((eq (first base) :call)
         (list* 8 (or (position (second base) *function-order*) 9)
                (if (cddr base) (base-key (cons :sum (third base)) arrangement) '())))
        (t (list 9))))

(defun term-degree (term variable)
  "The power of VARIABLE in TERM (0 when it has none)."
  (or (cdr (assoc variable (term-powers term))) 0))

(defun term-key (term arrangement)
  "The sort key of TERM in a sum: its power of the arrangement's variable, positive
terms first, fewer factors first, then its factors' keys."
  (let ((variable (arrangement-variable arrangement))
        (factors (remove-if #'realp (term-powers term) :key #'car)))
    (append (list (if variable (term-degree term variable) 0)
                  (if (minusp (term-coefficient term)) 1 0)
                  (reduce #'+ (mapcar (lambda (p) (abs (cdr p))) factors)))
            (loop for p in (sort (copy-list factors) #'compare-keys
                                 :key (lambda (p) (base-key (car p) arrangement)))
                  append (base-key (car p) arrangement)))))

(defun tangents-merged (powers)
  "POWERS with cos(x)^k sin(x)^-k written tan(x)^-k and sin(x)^k cos(x)^-k written tan(x)^k."
  (let ((result (copy-alist powers)))
    (dolist (power powers result)
      (let ((base (car power)))
        (when (and (consp base) (eq (first base) :call) (eq (second base) 'sin))
          (let ((cosine (assoc (list* :call 'cos (cddr base)) result :test #'equal))
                (sine (assoc base result :test #'equal)))
            (when (and cosine sine (integerp (cdr sine)) (eql (cdr sine) (- (cdr cosine))))
              (setf result (remove cosine (remove sine result)))
              (push (cons (list* :call 'tan (cddr base)) (cdr sine)) result))))))))
