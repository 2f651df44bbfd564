;;;; t/base.lisp -- tests of the prefix algebra's grammar and walkers.

(in-package #:ames.tests)

(in-suite base)

(test algebra-accepts-the-wedge-equation
  (is (equal '(= (* mp (acc particle :x)) (- (* n (sin a))))
             (check-expression '(= (* mp (acc particle :x)) (- (* n (sin a))))))))

(test algebra-rejects-what-is-not-in-the-grammar
  (dolist (bad '("system(\"ls\")" (+ 1 "x") (foo (bar)) (sin) (expt 2) #c(1 2)
                 (+ 1 . 2) (< 1 2 3) :key (quote x)))
    (signals malformed-expression (check-expression bad)))
  (signals malformed-expression (check-expression '(+ a b) :kind :condition))
  (signals malformed-expression (check-expression '(< a b) :kind :arithmetic))
  (signals malformed-expression (check-expression '(acc p :x) :allow-terms nil)))

(test malformed-expression-is-an-ames-error-naming-the-datum
  (let ((condition (handler-case (check-expression '(+ a (frob "x")))
                     (ames-error (c) c))))
    (is (typep condition 'malformed-expression))
    (is (equal '(frob "x") (ames-error-datum condition)))
    (is (search "FROB" (princ-to-string condition)))))

(test arity-messages-count-arguments-correctly
  (flet ((message (expression)
           (handler-case (progn (check-expression expression) nil)
             (malformed-expression (c) (ames-error-detail c)))))
    (is (string= "SIN takes 1 argument" (message '(sin 1 2))))
    (is (string= "EXPT takes 2 arguments" (message '(expt 2))))
    (is (string= "ATAN takes 1 or 2 arguments" (message '(atan 1 2 3))))
    (is (string= "+ takes at least 1 argument" (message '(+))))))

(test reports-of-huge-data-are-cut-short
  ;; printing a condition must neither exhaust the stack on a very deep datum nor run
  ;; for ever on a circular one
  (let ((deep "bad"))
    (dotimes (i 10000) (setf deep (list '- deep)))
    (let* ((condition (handler-case (check-expression deep)
                        (malformed-expression (c) c)))
           (report (princ-to-string condition)))
      (is (typep condition 'malformed-expression))
      (is (search "at fault: \"bad\"" report))
      (is (search "in: (- (- (- " report))
      (is (search "#" report))
      (is (< (length report) 400)))
    (let ((report (princ-to-string (make-condition 'ames-error :detail "deep" :datum deep))))
      (is (search "at fault: (- (- " report))
      (is (< (length report) 400))))
  (let ((long (make-list 100000 :initial-element 'x))
        (circular (list '+ 1 2)))
    (setf (cdr (last circular)) circular)
    (let ((report (princ-to-string
                   (make-condition 'malformed-expression
                                   :detail "long" :datum long :expression circular))))
      (is (search "(X X X" report))
      (is (search "..." report))
      (is (< (length report) 400)))))

(test expression-walkers
  (is (equal '(a (acc p :x) b) (expression-variables '(+ a (* (acc p :x) b pi) a))))
  (is (free-of-p 'c '(+ a (sin b))))
  (is (not (free-of-p '(acc p :x) '(* 2 (acc p :x)))))
  (is (equal '(+ 2 (sin (* 3 y)))
             (substitute-expressions '((x . 2) (z . (* 3 y))) '(+ x (sin z))))))

;;; Numeric values of constant expressions (src/base/evaluation.lisp)

(defun value-and-exactness (expression &optional bindings)
  "EXPRESSION-VALUE's two values as a list."
  (multiple-value-list (expression-value expression bindings)))

(defun not-a-number (&optional (infinity sb-ext:double-float-positive-infinity))
  "A quiet NaN, made at run time (SBCL traps the invalid operation unless masked)."
  (sb-int:with-float-traps-masked (:invalid)
    (- infinity infinity)))

(test finite-reals
  (is (finite-real-p 3))
  (is (finite-real-p -1/3))
  (is (finite-real-p 1.5f0))
  (is (finite-real-p most-positive-double-float))
  (is (not (finite-real-p sb-ext:double-float-positive-infinity)))
  (is (not (finite-real-p sb-ext:single-float-negative-infinity)))
  (is (not (finite-real-p (not-a-number))))
  (let ((nan (not-a-number)))
    (signals malformed-expression (check-expression nan))
    (is (equal '(nil nil) (multiple-value-list (expression-value `(+ 1 ,nan))))))
  (is (not (finite-real-p #c(1 2))))
  (is (not (finite-real-p 'x))))

(test rational-roots
  (is (eql 3/2 (rational-root 9/4 2)))
  (is (eql 0 (rational-root 0 3)))
  (is (eql 1 (rational-root 1 7)))
  (is (eql 2/3 (rational-root 8/27 3)))
  (is (eql 12345678901234567890 (rational-root (expt 12345678901234567890 5) 5)))
  (is (null (rational-root 2 2)))
  (is (null (rational-root 8/9 2)))
  (is (null (rational-root -4 2)))
  (is (null (rational-root 0.25 2)))
  (for-all ((n (gen-integer :min 1 :max 100000)) (d (gen-integer :min 1 :max 1000))
            (degree (gen-integer :min 2 :max 9)))
    (is (eql (/ n d) (rational-root (expt (/ n d) degree) degree)))
    ;; between n^k and (n+1)^k there is no k-th power
    (is (null (rational-root (1+ (expt n degree)) degree)))))

(test expression-values-are-exact-for-rationals
  (is (equal '(3/2 t) (value-and-exactness '(+ 1 (/ 1 2)))))
  (is (equal '(-5 t) (value-and-exactness '(- 5))))
  (is (equal '(1/4 t) (value-and-exactness '(/ 4))))
  (is (equal '(1/24 t) (value-and-exactness '(/ 1 2 3 4))))
  (is (equal (list (expt 2 100) t) (value-and-exactness '(expt 2 100))))
  (is (equal '(1/8 t) (value-and-exactness '(expt 2 -3))))
  (is (equal '(1 t) (value-and-exactness '(expt 0 0))))
  (is (equal '(3/2 t) (value-and-exactness '(sqrt 9/4))))
  (is (equal '(4 t) (value-and-exactness '(expt 8 2/3))))
  (is (equal '(2/3 t) (value-and-exactness '(expt 27/8 -1/3))))
  (is (equal '(0.0d0 nil) (value-and-exactness '(- (sqrt 2) (sqrt 2))))
      "two equal approximations subtract to a float zero, not an exact one")
  (is (equal '(6 t) (value-and-exactness '(* x 2) '((x . 3)))))
  (is (equal '(3/2 t) (value-and-exactness '(* 2 (acc p :x)) '(((acc p :x) . 3/4)))))
  (for-all ((tree (let ((leaf (gen-integer :min -50 :max 50)))
                    (lambda ()
                      (labels ((grow (depth)
                                 (if (or (zerop depth) (zerop (random 3)))
                                     (/ (funcall leaf) (1+ (random 7)))
                                     (list* (elt '(+ - *) (random 3))
                                            (grow (1- depth))
                                            (loop repeat (random 3)
                                                  collect (grow (1- depth)))))))
                        (grow 5))))))
    (labels ((fold (x)
               (if (rationalp x)
                   x
                   (apply (ecase (car x) (+ #'+) (- #'-) (* #'*)) (mapcar #'fold (cdr x))))))
      (is (equal (list (fold tree) t) (value-and-exactness tree))))))

(test expression-values-are-double-floats-otherwise
  (flet ((approximately (expected expression &optional bindings)
           (destructuring-bind (value exact) (value-and-exactness expression bindings)
             (and (typep value 'double-float)
                  (< (abs (- value expected)) 1d-14)
                  (not exact)))))
    (is (approximately (/ pi 2) '(/ pi 2)))
    (is (approximately (sqrt 2d0) '(sqrt 2)))
    (is (approximately 3d0 '(* 1.5f0 2)))
    (is (approximately (sqrt 2d0) '(expt 2 1/2)))
    (is (approximately 1d0 '(+ (expt (sin y) 2) (expt (cos y) 2)) '((y . 0.7))))
    (is (approximately 0d0 '(sin 0)))
    (is (approximately (atan 1d0 -1d0) '(atan 1 -1)))
    (is (approximately (log 2d0) '(log 2)))
    (is (approximately 4d0 '(expt -2 2.0)))
    (is (approximately 0d0 '(expt 0.0 3/2)))
    (is (approximately 1d0 '(expt 0.0 0)))
    ;; a number, or a bound variable, is taken as given
    (is (equal '(0.5d0 t) (value-and-exactness 0.5f0)))
    (is (equal '(0.25d0 t) (value-and-exactness 'x '((x . 0.25f0)))))
    (is (equal '(7 t) (value-and-exactness 'x '((x . 7)))))))

(test expression-values-are-nil-where-there-is-no-finite-real
  (dolist (expression '(x (+ 1 y) (* 2 (acc p :x))
                        (sqrt -1) (/ 1 0) (/ 0) (/ 1 (- 2 2)) (/ 1 0.0) (expt 0 -1)
                        (expt 0.0 -2.5) (log 0) (log -1) (asin 2) (acos -1.5) (atan 0 0)
                        (expt -8 1/3) (expt -2 0.5) (exp 100000) (expt 10 (expt 10 10))
                        (* 1d300 1d300) (+ (expt 10 400) 1.0) (expt 2.0 (expt 2 2000))
                        (sin 1 2) (expt 2) (-) (+ 1 . 2) (< 1 2) (foo 1) (acc p)
                        "x" :key t #c(1 2) (sqrt (quote x))))
    (is (equal '(nil nil) (value-and-exactness expression '((z . 1))))
        "~S has no value, yet gave ~S" expression (value-and-exactness expression)))
  (is (equal '(nil nil) (value-and-exactness 'x '((x . "3")))))
  (is (equal '(nil nil) (value-and-exactness 'x `((x . ,sb-ext:double-float-positive-infinity)))))
  (is (equal '(nil nil) (value-and-exactness '(+ x 1) '((x . #c(0 1)))))))

(test expression-values-of-deep-expressions
  (flet ((negated (times)
           (let ((x 1)) (dotimes (i times x) (setf x (list '- x))))))
    (is (equal '(1 t) (value-and-exactness (negated 1000))))
    (is (equal '(nil nil) (value-and-exactness (negated 1001))))
    ;; no stack exhaustion: too deep is no value
    (is (equal '(nil nil) (value-and-exactness (negated 100000))))))

(test expression-values-never-signal
  ;; random trees of every operator over awkward numbers: a value is NIL or a finite real
  (for-all ((tree (lambda ()
                    (labels ((leaf ()
                               (elt (list 0 1 -1 2 1/3 -7/2 0.0 1.5 -2.5 1d300 -1d-300
                                          (expt 10 400) pi 'pi)
                                    (random 14)))
                             (grow (depth)
                               (if (or (zerop depth) (zerop (random 3)))
                                   (leaf)
                                   (let ((entry (elt +arithmetic-operators+
                                                     (random (length +arithmetic-operators+)))))
                                     (cons (first entry)
                                           (destructuring-bind (least most) (rest entry)
                                             (loop repeat (+ least (random (1+ (- (or most (+ least 2))
                                                                                  least))))
                                                   collect (grow (1- depth)))))))))
                      (grow 6)))))
    (multiple-value-bind (value exact) (expression-value tree)
      (is (or (null value) (rationalp value) (typep value 'double-float)))
      (is (or value (null exact)))
      (is (or (null value) (finite-real-p value))))))
