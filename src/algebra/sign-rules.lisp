;;;; src/algebra/sign-rules.lisp -- AMES's one sign system: sets of signs and the rules of signs.
;;;;
;;;; The sign of a quantity over every admissible point is a SIGN SET, a list of the signs
;;;; :POSITIVE, :ZERO and :NEGATIVE it may take: (:POSITIVE) is strictly positive,
;;;; (:POSITIVE :ZERO) nonnegative, all three unknown. The rules of signs combine them
;;;; (a sum of terms of one sign, a product, a power); SIGNS.LISP adds what a physicist
;;;; reads off angles and facts, and Maxima's sign(); the broad phase of the simulator
;;;; uses the rules alone over the parameters' declared signs (RULES-OF-SIGNS), and
;;;; geometry the sign of a constant (CONSTANT-SIGN, the signum of a number, which
;;;; NUMBER-SIGNS turns into a set).
;;;; Inside SIGNS.LISP the empty set NIL stands for "nothing known" (see its header).

(in-package #:ames.algebra)

(defparameter +all-signs+ '(:positive :negative :zero)
  "The sign set of a quantity of which nothing is known.")

(defun number-signs (x)
  "The sign set of the real number X."
  (list (cond ((plusp x) :positive) ((minusp x) :negative) (t :zero))))

(defun negated-signs (signs)
  "The sign set of -X when X has the sign set SIGNS."
  (mapcar (lambda (s) (case s (:positive :negative) (:negative :positive) (t s))) signs))

(defun only-signs-p (signs &rest allowed)
  "True when the sign set SIGNS is not empty and holds only signs among ALLOWED."
  (and signs (subsetp signs allowed)))

(defun sum-signs (term-signs)
  "The signs of a sum whose terms have TERM-SIGNS; NIL unless the terms agree in sign."
  (flet ((agree (sign)
           (when (every (lambda (s) (only-signs-p s sign :zero)) term-signs)
             (cond ((some (lambda (s) (equal s (list sign))) term-signs) (list sign))
                   ((every (lambda (s) (equal s '(:zero))) term-signs) '(:zero))
                   (t (list sign :zero))))))
    (and (notany #'null term-signs)
         (or (agree :positive) (agree :negative)))))

(defun power-signs (base-signs exponent)
  "The signs of a power whose base has BASE-SIGNS, for a rational EXPONENT."
  (cond ((null base-signs) nil)
        ((integerp exponent)
         (cond ((and (<= exponent 0) (member :zero base-signs)) nil)
               ((zerop exponent) '(:positive))
               ((evenp exponent)
                (remove-duplicates (mapcar (lambda (s) (if (eq s :zero) :zero :positive)) base-signs)))
               (t base-signs)))
        ((only-signs-p base-signs :positive) '(:positive))
        ((and (plusp exponent) (only-signs-p base-signs :positive :zero)) base-signs)
        (t nil)))

(defun sign-product (a b)
  "The signs a product may have when its factors may have the signs A and B."
  (remove-duplicates
   (loop for x in a
         append (loop for y in b
                      collect (cond ((or (eq x :zero) (eq y :zero)) :zero)
                                    ((eq x y) :positive)
                                    (t :negative))))))

;;; Relations to zero

(defparameter +relation-signs+
  '((< :negative) (<= :negative :zero) (= :zero) (>= :positive :zero) (> :positive)
    (/= :positive :negative))
  "Each relation operator with the sign set of E it admits in (OP E 0).")

(defun relation-signs (operator)
  "The sign set of E admitted by (OPERATOR E 0). Signals a TYPE-ERROR unless OPERATOR
is one of < <= = >= > /=."
  (rest (or (assoc operator +relation-signs+)
            (error 'type-error :datum operator :expected-type '(member < <= = >= > /=)))))

(defun signs-relation (signs)
  "The order relation (< <= = >= >) whose (OP E 0) admits exactly the sign set SIGNS;
:ALL when SIGNS holds every sign; else NIL."
  (if (subsetp +all-signs+ signs)
      :all
      (loop for (operator . admitted) in +relation-signs+
            when (and (not (eq operator '/=)) (subsetp admitted signs) (subsetp signs admitted))
              return operator)))

(defun relation-verdict (operator signs)
  "The truth of (OPERATOR d 0) when d may have only the sign set SIGNS: :TRUE when every
sign of SIGNS is admitted, :FALSE when none is, else :UNKNOWN (also for SIGNS NIL,
nothing known)."
  (let ((admitted (relation-signs operator)))
    (cond ((null signs) :unknown)
          ((subsetp signs admitted) :true)
          ((null (intersection signs admitted)) :false)
          (t :unknown))))

;;; The sign of a constant

(defparameter *float-decision-margin* 1d-9
  "A constant expression whose floating value exceeds this in magnitude has that sign.")

(defun constant-sign (x &optional (margin *float-decision-margin*))
  "The sign (-1, 0 or 1) of the expression X when arithmetic alone settles it: always
when its value is an exact rational, else when its double-float value lies farther than
MARGIN from zero; NIL otherwise (and whenever X has a variable)."
  (multiple-value-bind (value exact) (expression-value x)
    (cond ((null value) nil)
          ((and exact (rationalp value)) (signum value))
          ((> (abs value) margin) (round (signum value)))
          (t nil))))

;;; The rules of signs alone, over the signs of the variables

(defun known-signs (signs)
  "SIGNS, or all three signs where SIGNS is NIL (nothing known)."
  (or signs +all-signs+))

(defun rules-of-signs (variable-signs expression)
  "The sign set of the arithmetic EXPRESSION at every admissible point by the rules of
signs alone (never by Maxima), the sign set of each variable being (funcall
VARIABLE-SIGNS variable). A float, an unknown operator or a divisor that may vanish
gives all three signs; x^0 is positive."
  (labels ((walk (x)
             (cond ((realp x) (if (rationalp x) (number-signs x) +all-signs+))
                   ((symbolp x) (known-signs (funcall variable-signs x)))
                   ((not (consp x)) +all-signs+)
                   (t (operation (first x) (mapcar #'walk (rest x)) (rest x)))))
           (sum (signs) (if signs (known-signs (sum-signs signs)) (list :zero)))
           (product (signs) (reduce #'sign-product signs :initial-value (list :positive)))
           (operation (operator signs arguments)
             (case operator
               (+ (sum signs))
               (- (if (rest signs)
                      (sum (list (first signs) (negated-signs (sum (rest signs)))))
                      (negated-signs (first signs))))
               (* (product signs))
               ;; a divisor must be known not to vanish
               (/ (if (every (lambda (s) (member s '((:positive) (:negative)) :test #'equal))
                             (rest signs))
                      (product signs)
                      +all-signs+))
               (sqrt (if (only-signs-p (first signs) :positive :zero) (first signs) +all-signs+))
               (expt (let ((power (second arguments)))
                       (cond ((not (integerp power)) +all-signs+)
                             ((zerop power) (list :positive))
                             (t (known-signs (power-signs (first signs) power))))))
               (t +all-signs+))))
    (walk expression)))
