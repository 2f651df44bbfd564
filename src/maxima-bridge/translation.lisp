;;;; src/maxima-bridge/translation.lisp -- prefix algebra <-> Maxima's internal form, through mangled names.
;;;;
;;;; Going out, every variable and quantity term becomes a fresh Maxima symbol $AMESV<letters>
;;;; recorded in a NAME-TABLE (the letters sort in the order the names were made, see
;;;; LETTERS-FOR-INDEX), so that no user name (t, %pi, system, gamma ...) can ever meet
;;;; a Maxima name; PI becomes %pi and each operator its Maxima head. Anything outside the
;;;; grammar of AMES.BASE:CHECK-EXPRESSION is refused with UNTRANSLATABLE-EXPRESSION before a
;;;; single character is written. Coming back, Maxima's simplified form is turned into a
;;;; readable prefix expression ((/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2))))), and
;;;; anything outside the algebra (%i, integrals, unknown functions) is refused with
;;;; UNTRANSLATABLE-RESULT.

(in-package #:ames.maxima)

(defun wire (name)
  "The Maxima symbol NAME (a constant string of the bridge) in the wire package."
  (intern name '#:ames.maxima.wire))

(defmacro define-wire-symbols (&rest specs)
  "Define each (LISP-NAME \"MAXIMA-NAME\") as a constant wire symbol."
  `(progn ,@(loop for (lisp-name maxima-name) in specs
                  collect `(defparameter ,lisp-name (wire ,maxima-name)))))

(define-wire-symbols
  (+mplus+ "MPLUS") (+mtimes+ "MTIMES") (+mexpt+ "MEXPT") (+mquotient+ "MQUOTIENT")
  (+mminus+ "MMINUS") (+rat+ "RAT") (+mlist+ "MLIST")
  (+mequal+ "MEQUAL") (+mnotequal+ "MNOTEQUAL") (+mlessp+ "MLESSP") (+mgreaterp+ "MGREATERP")
  (+mleqp+ "MLEQP") (+mgeqp+ "MGEQP") (+mand+ "MAND") (+mor+ "MOR") (+mnot+ "MNOT")
  (+equal+ "$EQUAL") (+notequal+ "$NOTEQUAL")
  (+sin+ "%SIN") (+cos+ "%COS") (+tan+ "%TAN") (+asin+ "%ASIN") (+acos+ "%ACOS")
  (+atan+ "%ATAN") (+atan2+ "$ATAN2") (+atan2-noun+ "%ATAN2") (+sqrt+ "%SQRT") (+log+ "%LOG")
  (+abs+ "MABS") (+derivative+ "%DERIVATIVE")
  (+pi+ "$%PI") (+e+ "$%E") (+i+ "$%I") (+true+ "T") (+false+ "NIL")
  (+unknown+ "$UNKNOWN") (+inconsistent+ "$INCONSISTENT") (+initial-context+ "$INITIAL")
  (+all+ "$ALL") (+integrate-noun+ "%INTEGRATE"))

(defparameter *function-heads*
  `((sin . ,+sin+) (cos . ,+cos+) (tan . ,+tan+) (asin . ,+asin+) (acos . ,+acos+)
    (sqrt . ,+sqrt+) (log . ,+log+) (abs . ,+abs+))
  "One-argument functions of the algebra and their Maxima heads.")

(defparameter *special-function-heads*
  `((sinh . ,(wire "%SINH")) (cosh . ,(wire "%COSH")) (tanh . ,(wire "%TANH"))
    (asinh . ,(wire "%ASINH")) (acosh . ,(wire "%ACOSH")) (atanh . ,(wire "%ATANH"))
    (elliptic-f . ,(wire "%ELLIPTIC_F")) (elliptic-k . ,(wire "%ELLIPTIC_KC"))
    (elliptic-e . ,(wire "%ELLIPTIC_E"))
    (jacobi-sn . ,(wire "%JACOBI_SN")) (jacobi-cn . ,(wire "%JACOBI_CN"))
    (jacobi-dn . ,(wire "%JACOBI_DN")) (jacobi-am . ,(wire "%JACOBI_AM"))
    (gamma-function . ,(wire "%GAMMA")))
  "The hyperbolic, elliptic and Jacobi functions of the algebra and their Maxima heads
(elliptic_f(phi, m), elliptic_kc(m), elliptic_e(phi, m), jacobi_sn(u, m) ...: the same
argument order, parameter m as in AMES.BASE's special-functions.lisp).")

(defparameter *relation-heads*
  `((= . ,+mequal+) (/= . ,+mnotequal+) (< . ,+mlessp+) (> . ,+mgreaterp+)
    (<= . ,+mleqp+) (>= . ,+mgeqp+))
  "Relations of the algebra and their Maxima heads.")

(defparameter *logical-heads* `((and . ,+mand+) (or . ,+mor+) (not . ,+mnot+))
  "Connectives of the algebra and their Maxima heads.")

(defun operator-head (operator)
  "The Maxima head of OPERATOR, a function, relation or connective of the algebra with a
head of its own (not + - * / expt exp atan, which translate into other forms)."
  (or (cdr (assoc operator *function-heads*))
      (cdr (assoc operator *special-function-heads*))
      (cdr (assoc operator *relation-heads*))
      (cdr (assoc operator *logical-heads*))
      (error "No Maxima head for the operator ~S" operator)))

;;; Maxima forms: ((HEAD) ARG ...)

(defun mform (head &rest arguments)
  "The unsimplified Maxima form applying HEAD to ARGUMENTS."
  (list* (list head) arguments))

(defun mlist (items)
  "The Maxima list [ITEMS...]."
  (apply #'mform +mlist+ items))

(defun mform-p (form &optional head)
  "True when FORM is a Maxima operator form (with head HEAD, when given)."
  (and (consp form) (consp (car form)) (symbolp (caar form))
       (or (null head) (eq (caar form) head))))

(defun mform-head (form)
  "The head symbol of the Maxima form FORM."
  (caar form))

(defun mform-arguments (form)
  "The arguments of the Maxima form FORM."
  (cdr form))

(defun mlist-items (form)
  "The items of the Maxima list FORM; signals UNTRANSLATABLE-RESULT when it is no list."
  (unless (mform-p form +mlist+)
    (error 'untranslatable-result :datum form :maxima-form form
                                  :detail "a list was expected"))
  (mform-arguments form))

;;; The name table

(defclass name-table ()
  ((forward :initform (make-hash-table :test 'equal) :reader name-table-forward
            :documentation "User name (variable or quantity term) -> wire symbol.")
   (backward :initform (make-hash-table :test 'eq) :reader name-table-backward
             :documentation "Wire symbol -> user name.")
   (counts :initform (make-hash-table :test 'equal) :reader name-table-counts
           :documentation "Prefix -> how many names with that prefix have been made. Each
kind of name is counted apart, so that a variable's name, and with it Maxima's order of
terms, does not depend on how many assumption scopes or auxiliary names came before."))
  (:documentation "The one-to-one map between AMES's names and the fresh Maxima names
that stand for them. Kept by one bridge for its lifetime."))

(defun letters-for-index (index)
  "The letters of the INDEX-th name (from 0), chosen so that names sort as their indices
do, however many there are: 0 -> A ... 24 -> Y, then ZAA ... ZYZ, then ZZAAA ... ZZYZZ,
and so on (K letters Z, one letter A-Y, K letters A-Z). Maxima orders variables by
their names, and what is() proves about a chain of inequalities can depend on that
order, so a name must never sort before one made earlier: with plain base-26 letters
AA sorts before B, and 26 names would already change Maxima's answers."
  (let ((class 0) (size 25))
    (loop while (>= index size)
          do (decf index size)
             (incf class)
             (setf size (* size 26)))
    (let ((digits '()))
      (dotimes (i class)
        (multiple-value-bind (quotient remainder) (floor index 26)
          (push (code-char (+ (char-code #\A) remainder)) digits)
          (setf index quotient)))
      (concatenate 'string
                   (make-string class :initial-element #\Z)
                   (string (code-char (+ (char-code #\A) index)))
                   (coerce digits 'string)))))

(defun fresh-wire-name (prefix table)
  "A wire symbol PREFIX followed by fresh letters, counted in TABLE for each PREFIX."
  (let ((index (gethash prefix (name-table-counts table) 0)))
    (setf (gethash prefix (name-table-counts table)) (1+ index))
    (wire (concatenate 'string prefix (letters-for-index index)))))

(defun maxima-name (table name &optional (prefix "$AMESV"))
  "The Maxima symbol standing for the variable or quantity term NAME (made on first use,
from PREFIX: $AMESV for the names of the algebra, $AMESX for the bridge's own auxiliary
variables)."
  (or (gethash name (name-table-forward table))
      (let ((symbol (fresh-wire-name prefix table))
            (key (copy-tree name)))
        (setf (gethash key (name-table-forward table)) symbol
              (gethash symbol (name-table-backward table)) key)
        symbol)))

(defun user-name (table symbol)
  "The AMES name that the Maxima symbol SYMBOL stands for, or NIL."
  (gethash symbol (name-table-backward table)))

(defun fresh-context-name (table)
  "A fresh Maxima context name $AMESCTX<letters>."
  (fresh-wire-name "$AMESCTX" table))

;;; Out: prefix algebra -> Maxima

(defun check-translatable (expression kind)
  "Signal UNTRANSLATABLE-EXPRESSION unless EXPRESSION is in the algebra as KIND."
  (handler-case (check-expression expression :kind kind)
    (malformed-expression (c)
      (error 'untranslatable-expression
             :datum (ames-error-datum c) :detail (ames-error-detail c)
             :expression expression))))

(defun number-to-maxima (number)
  "The Maxima form of the real NUMBER: integers as they are, ratios as RAT forms, floats
as double-floats."
  (etypecase number
    (integer number)
    (ratio (mform +rat+ (numerator number) (denominator number)))
    (float (coerce number 'double-float))))

(defun to-maxima (table expression &key (kind :any) as-is)
  "The Maxima form of EXPRESSION (prefix algebra), its names mangled through TABLE.
KIND (:ARITHMETIC, :CONDITION or :ANY) says what EXPRESSION must be. AS-IS keeps
EXPRESSION's structure for tex() (negations as MMINUS, quotients as MQUOTIENT, negative
numbers as negations, the arguments in the order given), where the default writes what
Maxima's simplifier expects (a - b as a + (-1) b, a / b as a b^-1). Signals
UNTRANSLATABLE-EXPRESSION for anything outside the algebra."
  (check-translatable expression kind)
  (labels ((out (x)
             (cond ((and as-is (realp x) (minusp x)) (mform +mminus+ (out (- x))))
                   ((realp x) (number-to-maxima x))
                   ((constant-symbol-p x) +pi+)
                   ((or (variable-symbol-p x) (quantity-term-p x)) (maxima-name table x))
                   (t (operator-form (expression-operator x)
                                     (mapcar #'out (expression-arguments x))
                                     as-is)))))
    (out expression)))

(defun operator-form (operator arguments as-is)
  "The Maxima form of OPERATOR applied to the Maxima forms ARGUMENTS (see TO-MAXIMA for
AS-IS)."
  (flet ((negation (a) (if as-is (mform +mminus+ a) (mform +mtimes+ -1 a)))
         (product (factors) (if (rest factors) (apply #'mform +mtimes+ factors) (first factors))))
    (case operator
      (+ (if (rest arguments) (apply #'mform +mplus+ arguments) (first arguments)))
      (- (if (rest arguments)
             (apply #'mform +mplus+ (first arguments) (mapcar #'negation (rest arguments)))
             (negation (first arguments))))
      (* (product arguments))
      (/ (cond ((null (rest arguments))
                (if as-is (mform +mquotient+ 1 (first arguments)) (mform +mexpt+ (first arguments) -1)))
               (as-is (mform +mquotient+ (first arguments) (product (rest arguments))))
               (t (apply #'mform +mtimes+ (first arguments)
                         (mapcar (lambda (a) (mform +mexpt+ a -1)) (rest arguments))))))
      (expt (mform +mexpt+ (first arguments) (second arguments)))
      (exp (mform +mexpt+ +e+ (first arguments)))
      (atan (if (rest arguments)
                (mform +atan2+ (first arguments) (second arguments))
                (mform +atan+ (first arguments))))
      (t (apply #'mform (operator-head operator) arguments)))))

;;; Back: Maxima -> prefix algebra

(defun refuse-result (part form detail)
  "Signal UNTRANSLATABLE-RESULT for PART of Maxima's answer FORM."
  (error 'untranslatable-result :datum part :maxima-form form :detail detail))

(defun negative-number-p (x)
  (and (realp x) (minusp x)))

(defun from-maxima (table form)
  "The prefix-algebra expression for the Maxima form FORM, names mapped back through
TABLE. Signals UNTRANSLATABLE-RESULT for anything outside the algebra."
  (labels
      ((back (x)
         (cond ((integerp x) x)
               ((floatp x) (coerce x 'double-float))
               ((eq x +pi+) 'pi)
               ((eq x +e+) '(exp 1))
               ((eq x +i+) (refuse-result x form "a complex number (%i)"))
               ((symbolp x)
                (multiple-value-bind (name found) (user-name table x)
                  (if found name (refuse-result x form "a name AMES did not give"))))
               ((not (mform-p x)) (refuse-result x form "not a Maxima expression"))
               (t (back-operator (mform-head x) (mform-arguments x) x))))
       (back-operator (head arguments x)
         (cond ((eq head +rat+) (/ (first arguments) (second arguments)))
               ((eq head +mplus+) (sum-from-maxima arguments #'back))
               ((eq head +mtimes+) (product-from-maxima arguments #'back))
               ((eq head +mexpt+) (power-from-maxima (first arguments) (second arguments) #'back))
               ((eq head +mquotient+) (list '/ (back (first arguments)) (back (second arguments))))
               ((eq head +mminus+) (list '- (back (first arguments))))
               ((or (eq head +atan2+) (eq head +atan2-noun+))
                (list 'atan (back (first arguments)) (back (second arguments))))
               ((eq head +atan+) (list 'atan (back (first arguments))))
               ((rassoc head *function-heads*)
                (list (car (rassoc head *function-heads*)) (back (first arguments))))
               ((rassoc head *special-function-heads*)
                (let ((operator (car (rassoc head *special-function-heads*))))
                  (unless (= (length arguments)
                             (second (assoc operator +arithmetic-operators+)))
                    (refuse-result x form (format nil "~A with ~D arguments" head (length arguments))))
                  (list* operator (mapcar #'back arguments))))
               ((rassoc head *relation-heads*)
                (list (car (rassoc head *relation-heads*))
                      (back (first arguments)) (back (second arguments))))
               ((eq head +equal+) (list '= (back (first arguments)) (back (second arguments))))
               ((eq head +notequal+) (list '/= (back (first arguments)) (back (second arguments))))
               ((rassoc head *logical-heads*)
                (list* (car (rassoc head *logical-heads*)) (mapcar #'back arguments)))
               (t (refuse-result x form (format nil "the operator ~A" head))))))
    (back form)))

(defun negated-magnitude (x)
  "The magnitude of the Maxima form X when X is a negative number or a product with a
negative numeric coefficient, else NIL."
  (cond ((negative-number-p x) (- x))
        ((and (mform-p x +rat+) (minusp (second x)))
         (mform +rat+ (- (second x)) (third x)))
        ((and (mform-p x +mtimes+) (negative-number-p (second x)))
         (let ((magnitude (- (second x))) (rest (cddr x)))
           (if (eql magnitude 1)
               (if (rest rest) (apply #'mform +mtimes+ rest) (first rest))
               (apply #'mform +mtimes+ magnitude rest))))
        ((and (mform-p x +mtimes+) (mform-p (second x) +rat+) (minusp (second (second x))))
         (apply #'mform +mtimes+ (mform +rat+ (- (second (second x))) (third (second x)))
                (cddr x)))
        (t nil)))

(defun sum-from-maxima (terms back)
  "The prefix sum of the Maxima TERMS of an MPLUS, each read with BACK: the terms with
a negative coefficient written as subtracted (a + b - c - d)."
  (let ((positives '()) (negatives '()))
    (dolist (term terms)
      (let ((magnitude (negated-magnitude term)))
        (if magnitude
            (push (funcall back magnitude) negatives)
            (push (funcall back term) positives))))
    (setf positives (nreverse positives) negatives (nreverse negatives))
    (cond ((null negatives) (if (rest positives) (list* '+ positives) (first positives)))
          ((null positives)
           (list '- (if (rest negatives) (list* '+ negatives) (first negatives))))
          (t (list* '- (if (rest positives) (list* '+ positives) (first positives))
                    negatives)))))

(defun product-from-maxima (factors back)
  "The prefix product of the Maxima FACTORS of an MTIMES, each read with BACK: the
numeric coefficient first, factors with negative exponents and the coefficient's
denominator as a quotient's denominator, a negative coefficient as a negation."
  (let ((coefficient 1) (numerator '()) (denominator '()))
    (dolist (factor factors)
      (cond ((realp factor) (setf coefficient (* coefficient factor)))
            ((mform-p factor +rat+)
             (setf coefficient (* coefficient (/ (second factor) (third factor)))))
            ((and (mform-p factor +mexpt+) (negative-exponent (third factor)))
             (push (power-from-maxima (second factor) (negative-exponent (third factor)) back)
                   denominator))
            (t (push (funcall back factor) numerator))))
    (let* ((sign (if (minusp coefficient) -1 1))
           (magnitude (abs coefficient)))
      (when (and (rationalp magnitude) (/= 1 (denominator magnitude)))
        (push (denominator magnitude) denominator)
        (setf magnitude (numerator magnitude)))
      (setf numerator (nreverse numerator) denominator (nreverse denominator))
      (unless (eql magnitude 1) (push magnitude numerator))
      (let* ((top (cond ((null numerator) 1)
                        ((rest numerator) (list* '* numerator))
                        (t (first numerator))))
             (whole (if denominator
                        (list '/ top (if (rest denominator)
                                         (list* '* denominator)
                                         (first denominator)))
                        top)))
        (if (minusp sign) (list '- whole) whole)))))

(defun negative-exponent (exponent)
  "The positive magnitude when the Maxima EXPONENT is a negative number or rational, else NIL."
  (cond ((negative-number-p exponent) (- exponent))
        ((and (mform-p exponent +rat+) (minusp (second exponent)))
         (mform +rat+ (- (second exponent)) (third exponent)))
        (t nil)))

(defun power-from-maxima (base exponent back)
  "The prefix form of the Maxima power BASE^EXPONENT, its parts read with BACK: exp,
a quotient for a negative exponent, sqrt for the exponent 1/2."
  (let ((magnitude (negative-exponent exponent)))
    (cond ((eq base +e+) (list 'exp (funcall back exponent)))
          (magnitude (list '/ 1 (power-from-maxima base magnitude back)))
          ((eql exponent 1) (funcall back base))
          ((and (mform-p exponent +rat+) (eql (second exponent) 1) (eql (third exponent) 2))
           (list 'sqrt (funcall back base)))
          (t (list 'expt (funcall back base) (funcall back exponent))))))

(defun maxima-truth (form)
  "The truth value :TRUE, :FALSE or :UNKNOWN of Maxima's answer FORM to is(...)."
  (cond ((eq form +true+) :true)
        ((eq form +false+) :false)
        (t :unknown)))
