;;;; t/algebra-signs.lisp -- tests of the one sign system (src/algebra/sign-rules.lisp) and the one translator's two styles.
;;;;
;;;; The rules of signs are checked against the values themselves: at random points that
;;;; respect the declared signs of the variables, every value an expression takes must have
;;;; a sign its sign set allows. The translator's AS-IS style (kept as written, for tex())
;;;; must give the same quantity as the default style (Maxima finds their difference zero).

(in-package #:ames.tests)

(def-suite algebra-signs :in all-tests
  :description "The algebra layer's sign system and the bridge's one translator.")

(in-suite algebra-signs)

(defparameter *declared-signs*
  '((m :positive) (k :positive) (n :negative) (x :positive :zero) (y :negative :zero) (z))
  "Variables and their declared sign sets, as the broad phase writes them (NIL: nothing
known).")

(defun declared-sign-set (variable)
  "The sign set of VARIABLE in *DECLARED-SIGNS*."
  (cdr (assoc variable *declared-signs*)))

(defun same-signs-p (a b)
  "True when the sign sets A and B hold the same signs."
  (null (set-exclusive-or a b)))

(defun random-admissible-point (random-state)
  "Bindings of the variables of *DECLARED-SIGNS* that respect their signs (zero now and
then where zero is allowed)."
  (loop for (variable . sign) in *declared-signs*
        for magnitude = (if (zerop (random 4 random-state)) 0 (1+ (random 7 random-state)))
        collect (cons variable
                      (cond ((same-signs-p sign '(:positive)) (max magnitude 1/2))
                            ((same-signs-p sign '(:negative)) (- (max magnitude 1/2)))
                            ((same-signs-p sign '(:positive :zero)) magnitude)
                            ((same-signs-p sign '(:negative :zero)) (- magnitude))
                            (t (if (zerop (random 2 random-state)) magnitude (- magnitude)))))))

(defun value-sign (value)
  "The sign keyword of the real VALUE."
  (cond ((plusp value) :positive) ((minusp value) :negative) (t :zero)))

(defparameter *signed-expressions*
  '((* m x) (- m) (+ m x) (- m y) (- y m) (/ x m) (/ m x) (* n n) (* n x) (* z z)
    (expt z 2) (expt n 3) (expt x 0) (sqrt x) (sqrt (* m k)) (+ (* m k) (expt z 2))
    (- (* n y) m) (/ (* x y) (* m n)) (+ z m) (* 0 z) (- 3 1/2) (sqrt (- m)))
  "Expressions of the variables of *DECLARED-SIGNS* whose sign sets are checked.")

(test rules-of-signs-hold-at-admissible-points
  (let ((random-state (sb-ext:seed-random-state 22)))
    (dolist (expression *signed-expressions*)
      (let ((signs (ames.algebra:rules-of-signs #'declared-sign-set expression)))
        (is (subsetp signs '(:positive :negative :zero)))
        (dotimes (i 40)
          (let ((value (expression-value expression (random-admissible-point random-state))))
            (when (realp value)
              (is (member (value-sign value) signs)
                  "~S has the value ~S at an admissible point, outside its signs ~S"
                  expression value signs))))))))

(test rules-of-signs-decide-what-the-rules-settle
  (flet ((signs-of (expression)
           (ames.algebra:rules-of-signs #'declared-sign-set expression)))
    (is (same-signs-p '(:positive) (signs-of '(+ m x))))
    (is (same-signs-p '(:negative) (signs-of '(- m))))
    (is (same-signs-p '(:positive :zero) (signs-of '(* m x))))
    (is (same-signs-p '(:negative :zero) (signs-of '(* n x))))
    (is (same-signs-p '(:positive) (signs-of '(* n n))))
    (is (same-signs-p '(:positive :zero) (signs-of '(expt z 2))))
    (is (same-signs-p '(:zero) (signs-of '(* 0 z))))
    ;; a divisor that may vanish, or a root of what may be negative, settles nothing
    (is (same-signs-p '(:positive :negative :zero) (signs-of '(/ m x))))
    (is (same-signs-p '(:positive :negative :zero) (signs-of '(sqrt (- m)))))
    (is (same-signs-p '(:positive :negative :zero) (signs-of '(+ z m))))))

(test constant-signs-by-arithmetic
  (is (eql 1 (ames.algebra:constant-sign '(- (sqrt 2) 1))))
  (is (eql -1 (ames.algebra:constant-sign '(- 1 pi))))
  (is (eql 0 (ames.algebra:constant-sign '(- 1/2 (/ 2 4)))))
  (is (null (ames.algebra:constant-sign '(- m 1))))
  ;; a float closer to zero than the margin has no sign by arithmetic
  (is (null (ames.algebra:constant-sign '(- (sin pi) 0))))
  (is (eql 1 (ames.algebra:constant-sign 1d-7 1d-9)))
  (is (null (ames.algebra:constant-sign 1d-7 1d-6))))

(test one-translator-in-two-styles
  (call-with-bridge
   (lambda (b)
     (dolist (expression '((- a (/ b c)) (/ (- a) (* b c)) (- -3 (* 2 a)) (/ 1 a) (- (expt a -2) b)))
       (let* ((table (ames.maxima::bridge-names b))
              (simplifying (ames.maxima::to-maxima table expression))
              (as-is (ames.maxima::to-maxima table expression :as-is t)))
         ;; the two styles write the same quantity: Maxima finds their difference zero
         (is (eql 0 (ames.maxima::maxima-request
                     b (ames.maxima::mcall "$RATSIMP" (ames.maxima::mdifference simplifying as-is))))
             "~S: the two translations differ" expression))))))

(test the-algebra-asks-maxima-only-through-the-bridges-exports
  "The algebra layer (issue 22: a narrow door) reaches the bridge only through its
exported operations: no symbol of AMES.MAXIMA is imported into AMES.ALGEBRA without being
external there, and no source of src/algebra/ writes ames.maxima:: (an internal)."
  (let ((internal '()))
    (do-symbols (symbol :ames.algebra)
      (when (and (eq (symbol-package symbol) (find-package :ames.maxima))
                 (not (eq :external (nth-value 1 (find-symbol (symbol-name symbol) :ames.maxima)))))
        (pushnew symbol internal)))
    (is (null internal) "the algebra uses the bridge's internals ~S" internal))
  (dolist (file (directory (asdf:system-relative-pathname "ames" "src/algebra/*.lisp")))
    (is (null (search "ames.maxima::" (string-downcase (uiop:read-file-string file))))
        "~A names an internal of the bridge" (file-namestring file))))
