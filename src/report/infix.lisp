;;;; src/report/infix.lisp -- expressions as a physicist writes them in plain text: mp mw g cos a / (mw + mp sin^2 a).
;;;;
;;;; Factors are juxtaposed with a space, a function of a name takes no parentheses (cos a,
;;;; sin^2 a), a rational coefficient is parenthesised ((1/2) a_x tau^2), and a quotient is
;;;; spaced when its numerator is a product. Parentheses appear only where precedence needs
;;;; them. Names are printed by a NAME-FUNCTION (lower-case symbol names by default), so
;;;; that no package prefix ever reaches a report.

(in-package #:ames.report)

(defun default-name (name)
  "A variable or quantity term as plain text: its symbol name in lower case; a quantity
term (HEAD ARG ...) as head(arg, ...)."
  (if (symbolp name)
      (string-downcase (symbol-name name))
      (format nil "~(~A~)(~{~(~A~)~^, ~})" (symbol-name (first name))
              (mapcar (lambda (a) (if (symbolp a) (symbol-name a) a)) (rest name)))))

(defun number-text (number &optional (digits 4))
  "NUMBER for people: an integer or ratio exactly (3, 1/2), a float to DIGITS
significant digits without trailing zeros (0.9071, 29.43, 1.5e-7)."
  (cond ((integerp number) (format nil "~D" number))
        ((rationalp number) (format nil "~D/~D" (numerator number) (denominator number)))
        ((not (realp number)) (princ-to-string number))
        ((zerop number) "0")
        (t (let* ((magnitude (abs number))
                  (exponent (floor (log magnitude 10))))
             (if (or (< exponent -4) (>= exponent 9))
                 (let ((mantissa (/ number (expt 10d0 exponent))))
                   (format nil "~Ae~D" (trimmed-decimal mantissa (1- digits)) exponent))
                 (trimmed-decimal number (max 0 (- digits 1 exponent))))))))

(defun trimmed-decimal (number places)
  "NUMBER with PLACES decimals, trailing zeros (and a bare point) removed."
  (let ((text (format nil "~,vF" places number)))
    (when (find #\. text)
      (setf text (string-right-trim "0" text))
      (setf text (string-right-trim "." text)))
    (cond ((string= text "-0") "0")
          ((and (> (length text) 1) (char= (char text 0) #\.)) (concatenate 'string "0" text))
          ((and (> (length text) 2) (string= (subseq text 0 2) "-.")) (concatenate 'string "-0" (subseq text 1)))
          (t text))))

(defun top-level-space-p (text)
  "True when TEXT has a space outside parentheses."
  (let ((depth 0))
    (loop for c across text
          do (case c (#\( (incf depth)) (#\) (decf depth)) (#\Space (when (zerop depth) (return t)))))))

(defun name-atom-p (x)
  "True for what a function may take without parentheses: a name or a non-negative integer."
  (or (and (symbolp x) x) (quantity-term-p x) (and (integerp x) (>= x 0))))

(defun parenthesized (text)
  "TEXT between parentheses."
  (format nil "(~A)" text))

(defun negative-term-p (x)
  "True for a negative number or a negation (- A): a term a sum writes with \" - \"."
  (or (and (realp x) (minusp x))
      (and (consp x) (eq (first x) '-) (null (cddr x)))))

(defun text-atom (x name-function)
  "The atom or quantity term X as text: a number as NUMBER-TEXT writes it, pi, or a name
by NAME-FUNCTION."
  (cond ((realp x) (number-text x))
        ((constant-symbol-p x) "pi")
        (t (funcall name-function x))))

(defun text-sum (x name-function)
  "The sum X, (+ TERM ...), as text: each negative term after the first written as
\" - \" and its magnitude."
  (with-output-to-string (out)
    (loop for (term . more) on (rest x)
          for first = t then nil
          do (cond ((and first (negative-term-p term))
                    (write-string (text-render term :sum name-function) out))
                   ((negative-term-p term)
                    (format out " - ~A" (text-render (if (realp term) (- term) (second term))
                                                     :factor name-function)))
                   (first (write-string (text-render term :sum name-function) out))
                   (t (format out " + ~A" (text-render term :sum name-function)))))))

(defun text-function (operator arguments name-function)
  "The elementary function OPERATOR of ARGUMENTS as text: atan2(y, x), cos a of a name,
f(x) otherwise."
  (let ((name (string-downcase (symbol-name operator))))
    (cond ((and (eq operator 'atan) (rest arguments))
           (format nil "atan2(~A, ~A)" (text-render (first arguments) :sum name-function)
                   (text-render (second arguments) :sum name-function)))
          ((and (member operator '(sin cos tan)) (name-atom-p (first arguments)))
           (format nil "~A ~A" name (text-atom (first arguments) name-function)))
          (t (format nil "~A(~A)" name (text-render (first arguments) :sum name-function))))))

(defun text-power (base exponent name-function)
  "BASE to the power EXPONENT as text: sin^2 a for a trigonometric function to a positive
integer power, the base parenthesised unless a name or a function."
  (let ((exponent-text (if (and (integerp exponent) (plusp exponent))
                           (number-text exponent)
                           (parenthesized (text-render exponent :sum name-function)))))
    (cond ((and (consp base) (member (first base) '(sin cos tan))
                (name-atom-p (second base)) (integerp exponent) (plusp exponent))
           (format nil "~(~A~)^~A ~A" (first base) exponent-text
                   (text-atom (second base) name-function)))
          ((and (consp base) (member (first base) '(sin cos tan))
                (integerp exponent) (plusp exponent))
           (format nil "~(~A~)^~A(~A)" (first base) exponent-text
                   (text-render (second base) :sum name-function)))
          ((or (name-atom-p base)
               (and (consp base) (member (first base) '(sqrt exp log asin acos atan))))
           (format nil "~A^~A" (text-render base :power name-function) exponent-text))
          (t (format nil "~A^~A" (parenthesized (text-render base :sum name-function))
                     exponent-text)))))

(defun text-quotient (x name-function)
  "The quotient X, (/ NUMERATOR DENOMINATOR ...) or (/ A) for 1/A, as text, spaced when
either side has a space at its top level."
  (let* ((numerator (text-render (second x) :factor name-function))
         (denominator (text-render (if (cdddr x) (cons '* (cddr x)) (third x))
                                   :denominator name-function)))
    (if (rest (rest x))
        (if (or (top-level-space-p numerator)
                (top-level-space-p denominator))
            (format nil "~A / ~A" numerator denominator)
            (format nil "~A/~A" numerator denominator))
        (format nil "1/~A" numerator))))

(defun text-other-form (x name-function)
  "The form X that no operator of TEXT-FORM's knows as text: name(arguments) for another
function of the algebra, else X printed in lower case."
  (if (and (symbolp (first x)) (not (keywordp (first x)))
           (alexandria:proper-list-p x))
      ;; another function of the algebra: name(arguments)
      (format nil "~(~A~)(~{~A~^, ~})"
              (substitute #\_ #\- (symbol-name (first x)))
              (mapcar (lambda (a) (text-render a :sum name-function)) (rest x)))
      (let ((*print-case* :downcase)) (prin1-to-string x))))

(defun text-operation (x name-function)
  "The compound form X (not a quantity term) as text, without the parentheses its
context may need."
  (flet ((render (x context) (text-render x context name-function)))
    (case (first x)
      (+ (text-sum x name-function))
      (- (if (rest (rest x))
             (text-sum (list* '+ (second x) (mapcar (lambda (a) (list '- a)) (cddr x)))
                       name-function)
             (format nil "-~A" (render (second x) :factor))))
      (* (format nil "~{~A~^ ~}"
                 (mapcar (lambda (factor)
                           (if (and (rationalp factor) (not (integerp factor)))
                               (parenthesized (text-atom factor name-function))
                               (render factor :factor)))
                         (rest x))))
      (/ (text-quotient x name-function))
      (expt (text-power (second x) (third x) name-function))
      ((sin cos tan asin acos atan sqrt exp log abs)
       (text-function (first x) (rest x) name-function))
      ((= /= < > <= >=)
       (format nil "~A ~A ~A" (render (second x) :sum)
               (case (first x) (/= "/=") (t (string-downcase (symbol-name (first x)))))
               (render (third x) :sum)))
      ((and or) (format nil (if (eq (first x) 'and) "~{~A~^ and ~}" "~{~A~^ or ~}")
                        (mapcar (lambda (a) (render a :sum)) (rest x))))
      (not (format nil "not ~A" (parenthesized (render (second x) :sum))))
      ;; the complete and incomplete elliptic integrals with the
      ;; parameter m, as Abramowitz and Stegun write them
      (elliptic-k (format nil "K(~A)" (render (second x) :sum)))
      ((elliptic-f elliptic-e)
       (format nil "~:[E~;F~](~A | ~A)" (eq (first x) 'elliptic-f)
               (render (second x) :sum) (render (third x) :sum)))
      (t (text-other-form x name-function)))))

(defun text-render (x context name-function)
  "X (prefix algebra) as text in CONTEXT: :sum (anything goes), :factor (a factor of a
product or a numerator), :denominator, :power (a base); parenthesised when the context
needs it. Names are written by NAME-FUNCTION."
  (let ((text
          (cond ((atom x) (text-atom x name-function))
                ((quantity-term-p x) (text-atom x name-function))
                (t (text-operation x name-function)))))
    (if (text-needs-parentheses-p x context) (parenthesized text) text)))

(defun text-needs-parentheses-p (x context)
  "True when X, written as text, needs parentheses in CONTEXT (see TEXT-RENDER)."
  (let ((kind (cond ((realp x) (cond ((minusp x) :negative)
                                     ((not (integerp x)) :ratio)
                                     (t :atom)))
                    ((atom x) :atom)
                    ((quantity-term-p x) :atom)
                    ((eq (first x) '+) :sum)
                    ((eq (first x) '-) (if (cddr x) :sum :negative))
                    ((eq (first x) '*) :product)
                    ((eq (first x) '/) :quotient)
                    ((member (first x) '(= /= < > <= >= and or not)) :sum)
                    (t :atom))))
    (ecase context
      (:sum nil)
      (:factor (member kind '(:sum :negative)))
      (:denominator (member kind '(:sum :negative :product :quotient :ratio)))
      (:power (not (eq kind :atom))))))

(defun text-form (expression &key (name-function #'default-name))
  "EXPRESSION (prefix algebra: arithmetic or a relation) as one line of plain text as a
physicist writes it (see the file header)."
  (text-render expression :sum name-function))

(defun infix (expression)
  "EXPRESSION (prefix algebra) as one line of plain text, as TEXT-FORM writes it with
lower-case names: mp mw g cos a / (mw + mp sin^2 a). No presentation step: the form is
printed as it is structured."
  (text-form expression))
