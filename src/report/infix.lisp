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

(defun text-form (expression &key (name-function #'default-name))
  "EXPRESSION (prefix algebra: arithmetic or a relation) as one line of plain text as a
physicist writes it (see the file header)."
  (labels ((parens (text) (format nil "(~A)" text))
           (negative-p (x) (or (and (realp x) (minusp x))
                               (and (consp x) (eq (first x) '-) (null (cddr x)))))
           (atom-text (x)
             (cond ((realp x) (number-text x))
                   ((constant-symbol-p x) "pi")
                   (t (funcall name-function x))))
           (sum-text (x)
             (with-output-to-string (out)
               (loop for (term . more) on (rest x)
                     for first = t then nil
                     do (cond ((and first (negative-p term)) (write-string (render term :sum) out))
                              ((negative-p term)
                               (format out " - ~A" (render (if (realp term) (- term) (second term)) :factor)))
                              (first (write-string (render term :sum) out))
                              (t (format out " + ~A" (render term :sum)))))))
           (function-text (operator arguments)
             (let ((name (string-downcase (symbol-name operator))))
               (cond ((and (eq operator 'atan) (rest arguments))
                      (format nil "atan2(~A, ~A)" (render (first arguments) :sum) (render (second arguments) :sum)))
                     ((and (member operator '(sin cos tan)) (name-atom-p (first arguments)))
                      (format nil "~A ~A" name (atom-text (first arguments))))
                     (t (format nil "~A(~A)" name (render (first arguments) :sum))))))
           (power-text (base exponent)
             (let ((exponent-text (if (and (integerp exponent) (plusp exponent))
                                      (number-text exponent)
                                      (parens (render exponent :sum)))))
               (cond ((and (consp base) (member (first base) '(sin cos tan))
                           (name-atom-p (second base)) (integerp exponent) (plusp exponent))
                      (format nil "~(~A~)^~A ~A" (first base) exponent-text (atom-text (second base))))
                     ((and (consp base) (member (first base) '(sin cos tan))
                           (integerp exponent) (plusp exponent))
                      (format nil "~(~A~)^~A(~A)" (first base) exponent-text (render (second base) :sum)))
                     ((or (name-atom-p base) (and (consp base) (member (first base) '(sqrt exp log asin acos atan))))
                      (format nil "~A^~A" (render base :power) exponent-text))
                     (t (format nil "~A^~A" (parens (render base :sum)) exponent-text)))))
           (render (x context)
             ;; CONTEXT: :sum (anything goes), :factor (a factor of a product or a
             ;; numerator), :denominator, :power (a base)
             (let ((text
                     (cond ((atom x) (atom-text x))
                           ((quantity-term-p x) (atom-text x))
                           (t (case (first x)
                                (+ (sum-text x))
                                (- (if (rest (rest x))
                                       (sum-text (list* '+ (second x) (mapcar (lambda (a) (list '- a)) (cddr x))))
                                       (format nil "-~A" (render (second x) :factor))))
                                (* (format nil "~{~A~^ ~}"
                                           (mapcar (lambda (factor)
                                                     (if (and (rationalp factor) (not (integerp factor)))
                                                         (parens (atom-text factor))
                                                         (render factor :factor)))
                                                   (rest x))))
                                (/ (let* ((numerator (render (second x) :factor))
                                          (denominator (render (if (cdddr x) (cons '* (cddr x)) (third x))
                                                               :denominator)))
                                     (if (rest (rest x))
                                         (if (or (top-level-space-p numerator)
                                                 (top-level-space-p denominator))
                                             (format nil "~A / ~A" numerator denominator)
                                             (format nil "~A/~A" numerator denominator))
                                         (format nil "1/~A" numerator))))
                                (expt (power-text (second x) (third x)))
                                ((sin cos tan asin acos atan sqrt exp log abs) (function-text (first x) (rest x)))
                                ((= /= < > <= >=)
                                 (format nil "~A ~A ~A" (render (second x) :sum)
                                         (case (first x) (/= "/=") (t (string-downcase (symbol-name (first x)))))
                                         (render (third x) :sum)))
                                ((and or) (format nil (if (eq (first x) 'and) "~{~A~^ and ~}" "~{~A~^ or ~}")
                                                  (mapcar (lambda (a) (render a :sum)) (rest x))))
                                (not (format nil "not ~A" (parens (render (second x) :sum))))
                                ;; the complete and incomplete elliptic integrals with the
                                ;; parameter m, as Abramowitz and Stegun write them
                                (elliptic-k (format nil "K(~A)" (render (second x) :sum)))
                                ((elliptic-f elliptic-e)
                                 (format nil "~:[E~;F~](~A | ~A)" (eq (first x) 'elliptic-f)
                                         (render (second x) :sum) (render (third x) :sum)))
                                (t (if (and (symbolp (first x)) (not (keywordp (first x)))
                                            (alexandria:proper-list-p x))
                                       ;; another function of the algebra: name(arguments)
                                       (format nil "~(~A~)(~{~A~^, ~})"
                                               (substitute #\_ #\- (symbol-name (first x)))
                                               (mapcar (lambda (a) (render a :sum)) (rest x)))
                                       (let ((*print-case* :downcase)) (prin1-to-string x)))))))))
               (if (needs-parentheses-p x context) (parens text) text)))
           (needs-parentheses-p (x context)
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
                 (:power (not (eq kind :atom)))))))
    (render expression :sum)))

(defun infix (expression)
  "EXPRESSION (prefix algebra) as one line of plain text, as TEXT-FORM writes it with
lower-case names: mp mw g cos a / (mw + mp sin^2 a). No presentation step: the form is
printed as it is structured."
  (text-form expression))
