;;;; src/interface/set-values.lisp -- the numbers --set accepts beyond plain decimals (issue 26):
;;;; pi in products and quotients, and degrees.
;;;;
;;;;   --set a=pi/4   --set a=3*pi/4   --set a=-pi   --set a=30deg   --set a=2.5deg
;;;;
;;;; A value is a product/quotient of factors, each a number PARSE-DECIMAL reads or pi
;;;; (a number written before pi multiplies it: 2pi), with an optional leading sign and an
;;;; optional trailing "deg" (degrees: times pi/180). Its value is exact when pi is not in
;;;; it, else the double-float nearest. Never calls the Lisp reader.

(in-package #:ames)

(defun parse-set-factor (text)
  "The value of one factor TEXT (a number, pi, or a number followed by pi) and whether it
holds pi, or NIL."
  (let ((lower (string-downcase text)))
    (cond ((string= lower "pi") (values pi t))
          ((and (> (length lower) 2) (string= "pi" (subseq lower (- (length lower) 2))))
           (let ((n (parse-decimal (subseq lower 0 (- (length lower) 2)))))
             (and n (values (* n pi) t))))
          (t (parse-decimal text)))))

(defun parse-set-value (text)
  "The number --set's VALUE TEXT writes (see the file header), or NIL."
  (let* ((trimmed (string-trim " " text))
         (degrees (and (> (length trimmed) 3)
                       (string-equal "deg" (subseq trimmed (- (length trimmed) 3)))))
         (body (if degrees (subseq trimmed 0 (- (length trimmed) 3)) trimmed))
         (negative (and (plusp (length body)) (char= (char body 0) #\-)))
         (body (if negative (subseq body 1) body))
         (tokens (cl-ppcre:split "([*/])" body :with-registers-p t))
         (value 1) (irrational nil))
    (when (or (null tokens) (evenp (length tokens))) (return-from parse-set-value nil))
    (loop for (operator factor) on (cons "*" tokens) by #'cddr
          do (multiple-value-bind (x holds-pi) (parse-set-factor factor)
               (unless x (return-from parse-set-value nil))
               (when holds-pi (setf irrational t))
               (if (string= operator "*")
                   (setf value (* value x))
                   (if (zerop x) (return-from parse-set-value nil) (setf value (/ value x))))))
    (when degrees (setf value (/ (* value pi) 180) irrational t))
    (when negative (setf value (- value)))
    (if irrational (coerce value 'double-float) value)))
