;;;; src/base/algebra.lisp -- AMES's prefix algebra: its grammar, accessors and walkers.
;;;;
;;;; An expression is one of
;;;;   a real number (integers and ratios are exact; a float is taken as given),
;;;;   the symbol PI (the exact constant, never its Lisp value),
;;;;   a variable: any other non-keyword symbol that is not an operator (TAU is the
;;;;     state-local time),
;;;;   a quantity term: (HEAD ATOM ...) where HEAD is a symbol outside COMMON-LISP and each
;;;;     ATOM a symbol, keyword or integer, e.g. (acc particle :x); a term is an
;;;;     opaque unknown, like a variable,
;;;;   an arithmetic form (OP EXPR ...) with OP in +ARITHMETIC-OPERATORS+,
;;;;   a relation (REL EXPR EXPR) with REL in +RELATION-OPERATORS+, or
;;;;   a logical form (AND ...), (OR ...), (NOT X) over relations.
;;;; Nothing here evaluates an expression; symbols are data.

(in-package #:ames.base)

(defparameter +arithmetic-operators+
  '((+ 1 nil) (- 1 nil) (* 1 nil) (/ 1 nil) (expt 2 2)
    (sqrt 1 1) (exp 1 1) (log 1 1)
    (sin 1 1) (cos 1 1) (tan 1 1) (asin 1 1) (acos 1 1) (atan 1 2)
    (abs 1 1)
    ;; hyperbolic functions, and their inverses
    (sinh 1 1) (cosh 1 1) (tanh 1 1) (asinh 1 1) (acosh 1 1) (atanh 1 1)
    ;; elliptic integrals (amplitude, parameter m) and Jacobi's functions (u, m), see
    ;; special-functions.lisp
    (elliptic-f 2 2) (elliptic-k 1 1) (elliptic-e 2 2)
    (jacobi-sn 2 2) (jacobi-cn 2 2) (jacobi-dn 2 2) (jacobi-am 2 2)
    ;; Euler's gamma function: Maxima writes K(1/2) and kin exactly with it
    (gamma-function 1 1))
  "Each arithmetic operator with its least and greatest number of arguments (NIL:
no limit).")

(defparameter +relation-operators+ '(= /= < > <= >=)
  "The binary relations of the algebra.")

(defparameter +logical-operators+ '(and or not)
  "The connectives that combine relations into conditions.")

(defconstant tau 'tau
  "The state-local time variable: every qualitative state starts at TAU = 0.")

(defvar *arithmetic-operator-table* (cons nil nil)
  "(SOURCE . TABLE): an EQ hash table of the operators of the list SOURCE, the
+ARITHMETIC-OPERATORS+ it was made from (made again when that list is another).")

(defun arithmetic-operator-p (symbol)
  "True when SYMBOL names an arithmetic operator of the algebra."
  (and (symbolp symbol)
       (let ((cache *arithmetic-operator-table*))
         (unless (eq (car cache) +arithmetic-operators+)
           (let ((table (make-hash-table :test #'eq)))
             (dolist (entry +arithmetic-operators+) (setf (gethash (first entry) table) t))
             (setf cache (cons +arithmetic-operators+ table)
                   *arithmetic-operator-table* cache)))
         (values (gethash symbol (cdr cache))))))

(defun relation-operator-p (symbol)
  "True when SYMBOL names a relation of the algebra."
  (and (symbolp symbol) (member symbol +relation-operators+) t))

(defun logical-operator-p (symbol)
  "True when SYMBOL names a logical connective of the algebra."
  (and (symbolp symbol) (member symbol +logical-operators+) t))

(defun operator-p (symbol)
  "True when SYMBOL is any operator, relation or connective of the algebra."
  (or (arithmetic-operator-p symbol) (relation-operator-p symbol)
      (logical-operator-p symbol)))

(defun constant-symbol-p (x)
  "True for the symbols that denote exact constants (only PI)."
  (eq x 'pi))

(defun variable-symbol-p (x)
  "True when X is a symbol that the algebra reads as a variable."
  (and (symbolp x) x (not (eq x t)) (not (keywordp x))
       (not (constant-symbol-p x)) (not (operator-p x))))

(defun quantity-term-p (x)
  "True when X is a quantity term such as (acc particle :x): an opaque unknown."
  (and (consp x)
       (symbolp (car x)) (car x) (not (keywordp (car x))) (not (operator-p (car x)))
       (not (eq (symbol-package (car x)) (find-package '#:common-lisp)))
       (alexandria:proper-list-p (cdr x))
       (cdr x)
       (every (lambda (a) (or (integerp a) (and (symbolp a) a))) (cdr x))))

(defun compound-expression-p (x)
  "True when X is an operator form (not a term)."
  (and (consp x) (operator-p (car x))))

(defun expression-operator (expression)
  "The operator of a compound EXPRESSION."
  (car expression))

(defun expression-arguments (expression)
  "The argument list of a compound EXPRESSION."
  (cdr expression))

(defun make-expression (operator &rest arguments)
  "A compound expression applying OPERATOR to ARGUMENTS."
  (cons operator arguments))

(defun relation-lhs (relation)
  "The left-hand side of a binary RELATION."
  (second relation))

(defun relation-rhs (relation)
  "The right-hand side of a binary RELATION."
  (third relation))

(defun make-relation (operator lhs rhs)
  "The relation (OPERATOR LHS RHS)."
  (list operator lhs rhs))

(defun finite-real-p (x)
  "True when X is a rational or a finite float (neither an infinity nor a NaN)."
  (or (rationalp x)
      ;; not by comparison: with SBCL's float traps on, comparing a NaN signals
      (and (floatp x) (not (sb-ext:float-nan-p x)) (not (sb-ext:float-infinity-p x)))))

(defun arity-description (operator least most)
  "A sentence saying how many arguments OPERATOR takes: at least LEAST and at most MOST
(NIL: no limit), e.g. \"SIN takes 1 argument\", \"ATAN takes 1 or 2 arguments\"."
  (cond ((eql least most) (format nil "~A takes ~D argument~:P" operator least))
        ((null most) (format nil "~A takes at least ~D argument~:P" operator least))
        (t (format nil "~A takes ~D ~:[to~;or~] ~D arguments"
                   operator least (= most (1+ least)) most))))

(defun check-expression (expression &key (kind :any) (allow-terms t) (allow-floats t))
  "Signal MALFORMED-EXPRESSION unless EXPRESSION belongs to the algebra; return it.
KIND is :ARITHMETIC (a quantity), :CONDITION (a relation or logical form) or :ANY.
With ALLOW-TERMS false, quantity terms are rejected; with ALLOW-FLOATS false, floats."
  (labels ((fail (datum detail)
             (error 'malformed-expression :datum datum :detail detail
                                          :expression expression))
           (check-arithmetic (x)
             (cond ((realp x)
                    (when (and (floatp x) (not allow-floats))
                      (fail x "a float is not allowed here"))
                    (unless (finite-real-p x)
                      (fail x "not a finite real number")))
                   ((numberp x) (fail x "not a real number"))
                   ((constant-symbol-p x))
                   ((variable-symbol-p x))
                   ((symbolp x) (fail x "not a variable, a constant or a number"))
                   ((not (consp x)) (fail x "not a number, a symbol or a list"))
                   ((not (alexandria:proper-list-p x)) (fail x "not a proper list"))
                   ((arithmetic-operator-p (car x))
                    (destructuring-bind (least most) (rest (assoc (car x) +arithmetic-operators+))
                      (let ((n (length (cdr x))))
                        (when (or (< n least) (and most (> n most)))
                          (fail x (arity-description (car x) least most))))
                      (mapc #'check-arithmetic (cdr x))))
                   ((or (relation-operator-p (car x)) (logical-operator-p (car x)))
                    (fail x "a condition where a quantity is expected"))
                   ((quantity-term-p x)
                    (unless allow-terms (fail x "unknown operator")))
                   (t (fail x (format nil "unknown operator ~S" (car x))))))
           (check-condition (x)
             (cond ((not (and (consp x) (alexandria:proper-list-p x)))
                    (fail x "a condition (relation) is expected"))
                   ((relation-operator-p (car x))
                    (unless (= (length x) 3) (fail x "a relation takes two arguments"))
                    (mapc #'check-arithmetic (cdr x)))
                   ((eq (car x) 'not)
                    (unless (= (length x) 2) (fail x "NOT takes one argument"))
                    (check-condition (second x)))
                   ((logical-operator-p (car x)) (mapc #'check-condition (cdr x)))
                   (t (fail x "a condition (relation) is expected")))))
    (ecase kind
      (:arithmetic (check-arithmetic expression))
      (:condition (check-condition expression))
      (:any (if (and (consp expression)
                     (or (relation-operator-p (car expression))
                         (logical-operator-p (car expression))))
                (check-condition expression)
                (check-arithmetic expression))))
    expression))

(defun valid-expression-p (expression &rest keys)
  "True when EXPRESSION passes CHECK-EXPRESSION with KEYS."
  (handler-case (progn (apply #'check-expression expression keys) t)
    (malformed-expression () nil)))

(defun expression-variables (expression)
  "The variables and quantity terms of EXPRESSION, each once, in order of appearance."
  (let ((found '()))
    (labels ((walk (x)
               (cond ((variable-symbol-p x) (pushnew x found :test #'equal))
                     ((quantity-term-p x) (pushnew x found :test #'equal))
                     ((consp x) (mapc #'walk (cdr x))))))
      (walk expression))
    (nreverse found)))

(defun free-of-p (unknown expression)
  "True when the variable or quantity term UNKNOWN does not occur in EXPRESSION."
  (labels ((occurs (x)
             (cond ((equal x unknown) t)
                   ((and (consp x) (not (quantity-term-p x))) (some #'occurs (cdr x)))
                   (t nil))))
    (not (occurs expression))))

(defun substitute-expressions (bindings expression)
  "EXPRESSION with each variable or term that is the CAR of an entry of the alist
BINDINGS replaced by that entry's CDR. Purely syntactic: nothing is simplified."
  (labels ((walk (x)
             (let ((entry (and (or (variable-symbol-p x) (quantity-term-p x))
                               (assoc x bindings :test #'equal))))
               (cond (entry (cdr entry))
                     ((and (consp x) (not (quantity-term-p x)))
                      (cons (car x) (mapcar #'walk (cdr x))))
                     (t x)))))
    (walk expression)))
