;;;; src/maxima-bridge/truth.lisp -- what a physicist knows, for DECIDE: signed factors, angles, monotonicity, squares.
;;;;
;;;; Maxima's is() and sign() miss facts any physicist reads off at once: cos(pi/2 - a) > 0
;;;; when 0 < a < pi/2; (h - r)(l1 - l2) > 0 when h > r and l1 > l2 (sign() does not use
;;;; orderings inside sums); sqrt(X)/sqrt(g) <= sqrt(Y)/sqrt(g) when X <= Y (monotonicity);
;;;; two times compared through their squares. DECIDE-BY-REASONING tries, in order:
;;;;   1. quarter turns: sin, cos and tan of an angle shifted by a multiple of pi/2 (or
;;;;      negated) rewritten as functions of the plain angle (cos(pi/2 - a) = sin(a));
;;;;   2. signed parts: the sign of the difference of the sides, found from the signs of
;;;;      its factors and terms (EXPRESSION-SIGNS), each asked of Maxima, or of DECIDE again;
;;;;   3. common factors of the two sides, of known sign, divided out;
;;;;   4. monotonicity: f(u) against f(v) for the same increasing (decreasing) f on the
;;;;      ranges of u and v is u against v (reversed);
;;;;   5. squares: two sides of one sign, one with a radical, compared through their squares;
;;;;   6. angles: sin, cos and tan of compound angles whose ranges give them a sign stand
;;;;      for fresh variables of that sign (in [-1, 1] for sin and cos).
;;;; Every step is an equivalence or a sound relaxation, so a :TRUE or :FALSE it finds is
;;;; proven; a step that cannot apply answers :UNKNOWN. Steps ask DECIDE about smaller or
;;;; rewritten relations; DECIDE stops a question that is already under way, and
;;;; questions nested too deep (see *DECIDING*), so the reasoning always ends.
;;;;
;;;; Signs are lists of :POSITIVE :ZERO :NEGATIVE (the values an expression may take);
;;;; NIL means nothing is known, and also that the expression may be undefined or not
;;;; real somewhere (a square root of something that may be negative, a division by
;;;; something that may be zero): no conclusion is drawn from such a part.

(in-package #:ames.maxima)

(defstruct (prover (:constructor make-prover (bridge ranges)))
  "What the reasoning about one relation needs: the BRIDGE and the exact RANGES of the
subjects under the facts in force (see SUBJECT-RANGES)."
  bridge ranges)

(defun prover-for (bridge)
  "A PROVER for BRIDGE under the facts in force."
  (make-prover bridge (subject-ranges (flatten-facts (current-assumptions bridge)))))

;;; Linear forms of angles, and quarter turns

(defun linear-terms (expression)
  "EXPRESSION as an alist (TERM . COEFFICIENT) of rational coefficients, EXPRESSION being
the sum of COEFFICIENT * TERM: TERM is 1 for the constant part, PI, or any other
subexpression taken whole (a variable, a product of variables, a function)."
  (labels ((merge-terms (alists)
             (let ((result '()))
               (dolist (alist alists)
                 (dolist (entry alist)
                   (let ((old (assoc (car entry) result :test #'equal)))
                     (if old
                         (incf (cdr old) (cdr entry))
                         (push (cons (car entry) (cdr entry)) result)))))
               (remove 0 (nreverse result) :key #'cdr)))
           (scaled (alist c) (mapcar (lambda (e) (cons (car e) (* c (cdr e)))) alist))
           (terms (x)
             (cond ((rationalp x) (if (zerop x) '() (list (cons 1 x))))
                   ((eq x 'pi) (list (cons 'pi 1)))
                   ((not (compound-expression-p x)) (list (cons x 1)))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (merge-terms (mapcar #'terms arguments)))
                          (- (if (rest arguments)
                                 (merge-terms (cons (terms (first arguments))
                                                    (mapcar (lambda (a) (scaled (terms a) -1))
                                                            (rest arguments))))
                                 (scaled (terms (first arguments)) -1)))
                          (* (let ((others (remove-if #'rationalp arguments)))
                               (cond ((null others) (terms (reduce #'* arguments)))
                                     ((rest others) (list (cons x 1)))
                                     (t (scaled (terms (first others))
                                                (reduce #'* (remove-if-not #'rationalp arguments)))))))
                          (/ (if (and (= (length arguments) 2) (rationalp (second arguments))
                                      (/= 0 (second arguments)))
                                 (scaled (terms (first arguments)) (/ (second arguments)))
                                 (list (cons x 1))))
                          (t (list (cons x 1)))))))))
    (terms expression)))

(defun linear-expression (alist)
  "The expression of the linear form ALIST (see LINEAR-TERMS)."
  (let ((terms (loop for (term . c) in alist
                     collect (cond ((eql term 1) c)
                                   ((eql c 1) term)
                                   ((eql c -1) (list '- term))
                                   (t (list '* c term))))))
    (cond ((null terms) 0)
          ((rest terms) (cons '+ terms))
          (t (first terms)))))

(defun reduced-circular-function (function argument)
  "FUNCTION (SIN COS TAN) of ARGUMENT with quarter turns shifted out and a negated angle
turned around (cos(pi/2 - a) = sin(a), sin(-a) = -sin(a)); NIL when nothing changes."
  (let* ((terms (linear-terms argument))
         (turns (* 2 (or (cdr (assoc 'pi terms)) 0)))
         (rest (remove 'pi terms :key #'car)))
    (when (integerp turns)
      (let* ((flip (and rest (every (lambda (entry) (minusp (cdr entry))) rest)))
             (angle (linear-expression (if flip
                                           (mapcar (lambda (e) (cons (car e) (- (cdr e)))) rest)
                                           rest)))
             (k (mod turns 4)))
        (when (and (or (/= 0 k) flip)
                   (not (and (eq function 'tan) (oddp k) (null rest))))
          ;; f(s x + k pi/2) with x the plain angle and s = -1 when FLIP
          (flet ((signed (sign expression) (if (minusp sign) (list '- expression) expression)))
            (let ((s (if flip -1 1)))
              (ecase function
                (cos (ecase k           ; cos(y + k pi/2), y = s x
                       (0 (list 'cos angle))
                       (1 (signed (- s) (list 'sin angle)))
                       (2 (list '- (list 'cos angle)))
                       (3 (signed s (list 'sin angle)))))
                (sin (ecase k           ; sin(y + k pi/2)
                       (0 (signed s (list 'sin angle)))
                       (1 (list 'cos angle))
                       (2 (signed (- s) (list 'sin angle)))
                       (3 (list '- (list 'cos angle)))))
                (tan (if (evenp k)
                         (signed s (list 'tan angle))
                         (signed (- s) (list '/ 1 (list 'tan angle)))))))))))))

(defun reduce-quarter-turns (expression)
  "EXPRESSION (a relation or an arithmetic expression) with every sin, cos and tan of an
angle shifted by quarter turns or negated written with the plain angle."
  (cond ((atom expression) expression)
        ((quantity-term-p expression) expression)
        (t (let ((rebuilt (cons (expression-operator expression)
                                (mapcar #'reduce-quarter-turns (expression-arguments expression)))))
             (or (and (member (expression-operator rebuilt) '(sin cos tan))
                      (reduced-circular-function (expression-operator rebuilt) (second rebuilt)))
                 rebuilt)))))

;;; Signs of expressions, from the signs of their parts

(defun number-signs (x)
  (list (cond ((plusp x) :positive) ((minusp x) :negative) (t :zero))))

(defun negated-signs (signs)
  (mapcar (lambda (s) (case s (:positive :negative) (:negative :positive) (t s))) signs))

(defun only-signs-p (signs &rest allowed)
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

(defun square-root-radicand (x)
  "The radicand A when X is (SQRT A) or (EXPT A 1/2), else NIL."
  (and (compound-expression-p x)
       (case (expression-operator x)
         (sqrt (second x))
         (expt (and (eql (third x) 1/2) (second x))))))

(defun quotient-signs (prover x)
  "The signs of the product or quotient X from those of its factors. A square root of a
negative radicand is i times a positive number, so two of them make a real product:
sqrt(A) sqrt(B) = -sqrt(A B) for A, B < 0 (Maxima writes some times that way); an odd
number of them leaves the reals (NIL)."
  (multiple-value-bind (coefficient factors) (product-parts x)
    (let ((signs (list (first (number-signs coefficient))))
          (turns 0))                    ; the power of i: +1 per imaginary factor above, -1 below
      (dolist (factor factors)
        (destructuring-bind (part . power) factor
          (let ((part-signs (expression-signs prover part)))
            (cond ((and part-signs (not (and (= power -1) (member :zero part-signs))))
                   (setf signs (sign-product signs part-signs)))
                  ((and (null part-signs) (square-root-radicand part)
                        (only-signs-p (expression-signs prover (square-root-radicand part)) :negative))
                   (incf turns power))
                  (t (return-from quotient-signs nil))))))
      (cond ((oddp turns) nil)
            ((= 2 (mod turns 4)) (negated-signs signs))
            (t signs)))))

(defun admissible-value (bridge expression)
  "The value of EXPRESSION at one point that surely satisfies the facts in force (a
double float), or NIL when none is found."
  (let ((value nil))
    (call-with-admissible-points bridge expression
                                 (lambda (point)
                                   (let ((ball (expression-ball expression point)))
                                     (when ball (setf value (ball-center ball))))))
    value))

(defun placed-trigonometric-signs (prover kernel)
  "The signs of KERNEL, (SIN X), (COS X) or (TAN X), found by placing X between two
consecutive zeros (or a zero and a pole) of the function: the piece is guessed from X's
value at an admissible point, and both bounds are asked of DECIDE (0 < b - a < pi with
b > a for sin(b - a)). NIL when that fails."
  (let* ((bridge (prover-bridge prover))
         (function (expression-operator kernel))
         (angle (second kernel))
         (value (admissible-value bridge angle)))
    (when value
      (multiple-value-bind (width offset) (if (eq function 'tan)
                                              (values 1/2 0)
                                              (values 1 (if (eq function 'sin) 0 -1/2)))
        ;; the piece [offset + k width, offset + (k + 1) width], in multiples of pi
        (let* ((k (floor (- (/ value pi) offset) width))
               (low (+ offset (* k width))) (high (+ offset (* (1+ k) width))))
          (flet ((bound (operator multiple)
                   (eq :true (decide bridge (list operator angle (list '* multiple 'pi))))))
            ;; sin, cos and tan are positive on the even pieces, negative on the odd ones
            (when (and (bound '> low) (bound '< high))
              (if (evenp k) '(:positive) '(:negative)))))))))

(defun trigonometric-signs (prover kernel)
  "The signs of KERNEL, (SIN X), (COS X) or (TAN X), that the range of X gives, or else
that placing X between two zeros gives (see PLACED-TRIGONOMETRIC-SIGNS); NIL when
neither does."
  (let* ((range (expression-range (second kernel) (prover-ranges prover)))
         (sign (and range (range-trigonometric-sign (expression-operator kernel) range))))
    (cond (sign (ecase sign
                  (:positive '(:positive)) (:negative '(:negative))
                  (:nonnegative '(:positive :zero)) (:nonpositive '(:negative :zero))))
          ((subject-p (second kernel)) nil)
          (t (placed-trigonometric-signs prover kernel)))))

(defun facts-signs (bridge x)
  "The signs of X that is() shows from the facts in force (X >= 0, X < 0 ...), in one
round trip: is() uses a fact about a compound X that sign() ignores."
  (let ((form (to-mx bridge x))
        (signs (list :positive :zero :negative)))
    (loop for (head . excluded) in `((,+mgreaterp+ :negative :zero) (,+mlessp+ :positive :zero)
                                     (,+mgeqp+ :negative) (,+mleqp+ :positive))
          for answer in (request-list bridge
                                      (loop for (head) in `((,+mgreaterp+) (,+mlessp+) (,+mgeqp+) (,+mleqp+))
                                            collect (mcall "$IS" (mform head form 0)))
                                      :datum x)
          when (eq (maxima-truth answer) :true)
            do (setf signs (set-difference signs excluded)))
    signs))

(defvar *imaginary-radicands* '()
  "The radicands, proven negative, of the square roots in the relation being decided by
DECIDE-WITH-IMAGINARY-RADICANDS: Maxima is not asked about an expression holding one.")

(defun mentions-imaginary-root-p (x)
  "True when X has a square root of one of *IMAGINARY-RADICANDS*."
  (and *imaginary-radicands* (consp x) (not (quantity-term-p x))
       (or (member (square-root-radicand x) *imaginary-radicands* :test #'equal)
           (some #'mentions-imaginary-root-p (expression-arguments x)))))

(defun leaf-signs (prover x)
  "The signs of X found as a whole: by exact arithmetic when X is a constant, from
Maxima's sign() of its forms and is() of its sign facts, then from DECIDE about X > 0
and X < 0 when X is a short compound expression. NIL when Maxima finds X outside the
reals."
  (let ((bridge (prover-bridge prover)))
    (cond
      ((mentions-imaginary-root-p x) nil)
      ((null (expression-variables x))
        (let ((ball (expression-ball x '())))
          (case (and ball (ball-sign ball))
            (:positive '(:positive))
            (:negative '(:negative))
            (t (handler-case (form-signs bridge (to-mx bridge x) :datum x)
                 (maxima-error () nil))))))
      (t
        (let ((signs (handler-case (form-signs bridge (to-mx bridge x) :datum x)
                       (maxima-error () nil))))
          (when (and signs (rest signs) (not (subject-p x)))
            (setf signs (intersection signs (handler-case (facts-signs bridge x)
                                              (maxima-error () signs)))))
          (when (and signs (rest signs) (not (subject-p x))
                     (<= (expression-size x) *largest-decided-part*))
            (flet ((rule-out (sign relation)
                     (ecase (decide bridge relation)
                       (:true (setf signs (list sign)))
                       (:false (setf signs (remove sign signs)))
                       (:unknown))))
              (rule-out :positive (list '> x 0))
              (when (rest signs)
                (rule-out :negative (list '< x 0)))))
          signs)))))

(defun expression-signs (prover x &key top)
  "The signs the arithmetic expression X may take at every admissible point, from the
signs of its parts: products and quotients of signed factors, sums of terms of one sign,
powers, square roots, exp, log, abs, atan, and sin, cos, tan of angles whose range gives
them a sign; what the parts do not settle is asked of X as a whole (LEAF-SIGNS), except
for X itself when TOP is true. NIL when nothing is known or X may be undefined."
  (labels ((signs (y) (expression-signs prover y))
           (whole () (if top nil (leaf-signs prover x))))
    (cond ((realp x) (number-signs x))
          ((constant-symbol-p x) '(:positive))
          ((subject-p x) (whole))
          ((not (compound-expression-p x)) nil)
          (t
           (let ((arguments (expression-arguments x)))
             (case (expression-operator x)
               (+ (or (sum-signs (mapcar #'signs arguments)) (whole)))
               (- (if (rest arguments)
                      (or (sum-signs (cons (signs (first arguments))
                                           (mapcar (lambda (a) (negated-signs (signs a)))
                                                   (rest arguments))))
                          (whole))
                      (let ((inner (signs (first arguments))))
                        (and inner (negated-signs inner)))))
               ((* /) (or (quotient-signs prover x) (whole)))
               (expt (let ((exponent (second arguments)))
                       (or (if (rationalp exponent)
                               (power-signs (signs (first arguments)) exponent)
                               (and (only-signs-p (signs (first arguments)) :positive)
                                    (signs exponent)
                                    '(:positive)))
                           (whole))))
               (sqrt (let ((inner (signs (first arguments))))
                       (and (only-signs-p inner :positive :zero) inner)))
               (abs (let ((inner (signs (first arguments))))
                      (cond ((null inner) (whole))
                            ((member :zero inner) (if (rest inner) '(:positive :zero) '(:zero)))
                            (t '(:positive)))))
               (exp (if (signs (first arguments)) '(:positive) (whole)))
               (log (if (only-signs-p (signs (first arguments)) :positive)
                        (signs (list '- (first arguments) 1))
                        nil))
               (atan (if (rest arguments)
                         (let ((y (signs (first arguments))))
                           (cond ((only-signs-p y :positive) '(:positive))
                                 ((only-signs-p y :negative) '(:negative))
                                 (t (whole))))
                         (or (signs (first arguments)) (whole))))
               ((sin cos tan) (or (trigonometric-signs prover x) (whole)))
               (t (whole))))))))

;;; The steps

(defun decide-by-quarter-turns (prover relation)
  "Step 1: RELATION with quarter turns shifted out of its angles, decided afresh."
  (let ((reduced (reduce-quarter-turns relation)))
    (if (equal reduced relation)
        :unknown
        (decide (prover-bridge prover) reduced))))

(defun relation-difference (relation)
  "LHS - RHS of RELATION (LHS itself when RHS is 0)."
  (if (eql (relation-rhs relation) 0)
      (relation-lhs relation)
      (list '- (relation-lhs relation) (relation-rhs relation))))

(defun full-simplification (bridge expression)
  "Maxima's :FULL simplification of EXPRESSION, or NIL when it leaves the algebra."
  (handler-case (simplify bridge expression :strategy :full)
    (untranslatable-result () nil)
    (maxima-error () nil)))

(defun decide-by-signed-parts (prover relation)
  "Step 2: the sign of LHS - RHS from the signs of its parts, as written and as Maxima
simplifies it (factored, often)."
  (let* ((operator (expression-operator relation))
         (difference (relation-difference relation))
         (verdict (relation-verdict operator (expression-signs prover difference :top t))))
    (if (not (eq verdict :unknown))
        verdict
        (let ((simplified (and (<= (expression-size relation) *largest-simplified-relation*)
                               (full-simplification (prover-bridge prover) difference))))
          (if (or (null simplified) (equal simplified difference))
              :unknown
              (relation-verdict operator (expression-signs prover simplified :top t)))))))

(defun product-parts (x)
  "X as (values COEFFICIENT FACTORS): a rational and a list of (FACTOR . POWER), POWER
1 for a factor of the numerator and -1 for one of the denominator."
  (let ((coefficient 1) (factors '()))
    (labels ((walk (y power)
               (cond ((rationalp y) (setf coefficient (* coefficient (if (= power 1) y (/ y)))))
                     ((and (compound-expression-p y) (eq (expression-operator y) '*))
                      (dolist (factor (expression-arguments y)) (walk factor power)))
                     ((and (compound-expression-p y) (eq (expression-operator y) '/)
                           (rest (expression-arguments y)))
                      (walk (first (expression-arguments y)) power)
                      (dolist (factor (rest (expression-arguments y))) (walk factor (- power))))
                     ((and (compound-expression-p y) (eq (expression-operator y) '-)
                           (null (rest (expression-arguments y))))
                      (setf coefficient (- coefficient))
                      (walk (second y) power))
                     (t (push (cons y power) factors)))))
      (if (and (rationalp x) (zerop x))
          (values 0 '())
          (progn (walk x 1) (values coefficient (nreverse factors)))))))

(defun product-expression (coefficient factors)
  "The expression COEFFICIENT * the product of FACTORS ((FACTOR . POWER) ...)."
  (let ((numerator (loop for (f . p) in factors when (= p 1) collect f))
        (denominator (loop for (f . p) in factors when (= p -1) collect f)))
    (unless (eql coefficient 1) (push coefficient numerator))
    (let ((top (cond ((null numerator) 1) ((rest numerator) (cons '* numerator)) (t (first numerator)))))
      (if denominator
          (list '/ top (if (rest denominator) (cons '* denominator) (first denominator)))
          top))))

(defun decide-by-common-factors (prover relation)
  "Step 3: factors common to both sides, of a known strict sign, divided out (reversing
the relation for a negative one): 2 sqrt(X) / sqrt(g) <= 2 sqrt(Y) / sqrt(g) becomes
sqrt(X) <= sqrt(Y)."
  (multiple-value-bind (left-coefficient left) (product-parts (relation-lhs relation))
    (multiple-value-bind (right-coefficient right) (product-parts (relation-rhs relation))
      (let ((operator (expression-operator relation)) (removed nil))
        (when (and (/= 0 left-coefficient) (/= 0 right-coefficient) left right)
          (dolist (factor (copy-list left))
            (when (member factor right :test #'equal)
              (let ((signs (expression-signs prover (car factor))))
                (when (or (equal signs '(:positive)) (equal signs '(:negative)))
                  (setf left (remove factor left :test #'equal :count 1)
                        right (remove factor right :test #'equal :count 1)
                        removed t)
                  (when (equal signs '(:negative))
                    (setf operator (flipped-operator operator))))))))
        (if removed
            (decide (prover-bridge prover)
                    (list operator (product-expression left-coefficient left)
                          (product-expression right-coefficient right)))
            :unknown)))))

(defun range-hull (a b)
  "The smallest range holding the ranges A and B (NIL ends stay unbounded)."
  (flet ((pick (x y side)
           (cond ((or (null x) (null y)) nil)
                 (t (let ((sign (pn-sign (pn- x y))))
                      (cond ((null sign) (return-from range-hull nil))
                            ((eq side :lower) (if (<= sign 0) x y))
                            (t (if (>= sign 0) x y))))))))
    (make-range (pick (range-lower a) (range-lower b) :lower)
                (pick (range-upper a) (range-upper b) :upper)
                (and (range-lower-open a) (range-lower-open b))
                (and (range-upper-open a) (range-upper-open b)))))

(defun monotone-direction (prover function u v)
  "Whether the one-argument FUNCTION is :INCREASING or :DECREASING (strictly) on a
domain holding the values of U and V, where both are defined; NIL when not shown."
  (flet ((signs (x) (expression-signs prover x)))
    (case function
      (sqrt (and (only-signs-p (signs u) :positive :zero) (only-signs-p (signs v) :positive :zero)
                 :increasing))
      ((exp atan) (and (signs u) (signs v) :increasing))
      (log (and (only-signs-p (signs u) :positive) (only-signs-p (signs v) :positive) :increasing))
      ((sin cos tan)
       (let ((ranges (prover-ranges prover)))
         (let ((ru (expression-range u ranges)) (rv (expression-range v ranges)))
           (and ru rv (let ((hull (range-hull ru rv)))
                        (and hull (range-monotonicity function hull)))))))
      (t nil))))

(defun decide-by-monotonicity (prover relation)
  "Step 4: f(u) against f(v), f the same function (or the same power), compared through
u and v where f is strictly monotone; sin u against cos v is sin u against sin(pi/2 - v)."
  (let ((lhs (relation-lhs relation)) (rhs (relation-rhs relation))
        (operator (expression-operator relation)))
    (flet ((by (direction u v)
             (case direction
               (:increasing (decide (prover-bridge prover) (list operator u v)))
               (:decreasing (decide (prover-bridge prover) (list (flipped-operator operator) u v)))
               (t :unknown))))
      (when (and (compound-expression-p lhs) (compound-expression-p rhs)
                 (equal (list (expression-operator lhs) (expression-operator rhs)) '(sin cos)))
        ;; cos v = sin(pi/2 - v)
        (setf rhs (list 'sin (list '- (list '/ 'pi 2) (second rhs)))))
      (when (and (compound-expression-p lhs) (compound-expression-p rhs)
                 (equal (list (expression-operator lhs) (expression-operator rhs)) '(cos sin)))
        (setf lhs (list 'sin (list '- (list '/ 'pi 2) (second lhs)))))
      (cond ((not (and (compound-expression-p lhs) (compound-expression-p rhs)
                       (eq (expression-operator lhs) (expression-operator rhs))))
             :unknown)
            ((and (eq (expression-operator lhs) 'expt)
                  (equal (third lhs) (third rhs)) (integerp (third lhs)) (/= 0 (third lhs)))
             (let* ((n (third lhs)) (u (second lhs)) (v (second rhs))
                    (su (expression-signs prover u)) (sv (expression-signs prover v)))
               (by (cond ((and (oddp n) (plusp n) su sv) :increasing)
                         ((and (only-signs-p su :positive :zero) (only-signs-p sv :positive :zero))
                          (if (plusp n)
                              :increasing
                              (and (only-signs-p su :positive) (only-signs-p sv :positive)
                                   :decreasing)))
                         ((and (evenp n) (plusp n)
                               (only-signs-p su :negative :zero) (only-signs-p sv :negative :zero))
                          :decreasing))
                   u v)))
            ((and (= 1 (length (expression-arguments lhs))) (= 1 (length (expression-arguments rhs))))
             (by (monotone-direction prover (expression-operator lhs) (second lhs) (second rhs))
                 (second lhs) (second rhs)))
            (t :unknown)))))

(defun radical-expression-p (x)
  "True when X has a square root or a power with an exponent that is not an integer."
  (and (consp x) (not (quantity-term-p x))
       (or (eq (expression-operator x) 'sqrt)
           (and (eq (expression-operator x) 'expt) (not (integerp (third x))))
           (some #'radical-expression-p (expression-arguments x)))))

(defun two-sided (relation)
  "RELATION with a difference against 0 written as a comparison of its two parts:
(>= (- P Q) 0) becomes (>= P Q), (< (+ P (- Q)) 0) becomes (< P Q); else RELATION."
  (let ((lhs (relation-lhs relation)) (rhs (relation-rhs relation)))
    (if (and (eql rhs 0) (compound-expression-p lhs))
        (let ((arguments (expression-arguments lhs)))
          (case (expression-operator lhs)
            (- (if (= (length arguments) 2)
                   (list (expression-operator relation) (first arguments) (second arguments))
                   relation))
            (+ (let ((negated (find-if (lambda (a) (and (compound-expression-p a)
                                                        (eq (expression-operator a) '-)
                                                        (null (rest (expression-arguments a)))))
                                       arguments)))
                 (if (and negated (= (length arguments) 2))
                     (list (expression-operator relation)
                           (first (remove negated arguments :count 1))
                           (second negated))
                     relation)))
            (t relation)))
        relation)))

(defun decide-by-squares (prover relation)
  "Step 5: sides of one sign, one of them with a radical, compared through their squares
(x -> x^2 is increasing on [0, oo) and decreasing on (-oo, 0]): two times
sqrt(A)/sqrt(g) and sqrt(B)/sqrt(g) are ordered as A/g and B/g. A difference of two
parts against 0 is taken as the comparison of the parts."
  (let* ((relation (two-sided relation))
         (lhs (relation-lhs relation)) (rhs (relation-rhs relation))
         (bridge (prover-bridge prover)))
    (if (not (and (or (radical-expression-p lhs) (radical-expression-p rhs))
                  (not (eql lhs 0)) (not (eql rhs 0))
                  (<= (expression-size relation) *largest-squared-relation*)))
        :unknown
        (let* ((left (expression-signs prover lhs))
               (right (and left (expression-signs prover rhs)))
               (operator (cond ((null right) nil)
                               ((and (only-signs-p left :positive :zero)
                                     (only-signs-p right :positive :zero))
                                (expression-operator relation))
                               ((and (only-signs-p left :negative :zero)
                                     (only-signs-p right :negative :zero))
                                (flipped-operator (expression-operator relation))))))
          (if (null operator)
              :unknown
              (let ((left-square (full-simplification bridge (list 'expt lhs 2)))
                    (right-square (full-simplification bridge (list 'expt rhs 2))))
                (if (and left-square right-square
                         ;; squares that grew are no simpler to compare
                         (<= (+ (expression-size left-square) (expression-size right-square))
                             (expression-size relation)))
                    (decide bridge (list operator left-square right-square))
                    :unknown)))))))

(defun angle-kernels (expression)
  "The subexpressions (SIN X), (COS X), (TAN X) of EXPRESSION whose X is not a plain
variable, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (mapc #'walk (expression-arguments x))
                 (when (and (member (expression-operator x) '(sin cos tan))
                            (not (subject-p (second x))))
                   (pushnew x found :test #'equal)))))
      (walk expression))
    (nreverse found)))

(defun kernel-variable (bridge kernel)
  "The fresh variable standing for KERNEL in DECIDE-BY-ANGLE-SUBSTITUTION: uninterned,
the same each time for a KERNEL of BRIDGE (so that requests come again from the cache),
and named apart from the algebra's variables ($AMESX...)."
  (let ((table (bridge-excess-names bridge))
        (key (list :kernel kernel)))
    (or (gethash key table)
        (let ((variable (make-symbol (format nil "~A-VALUE" (expression-operator kernel)))))
          (maxima-name (bridge-names bridge) variable "$AMESX")
          (setf (gethash (copy-tree key) table) variable)))))

(defun decide-by-angle-substitution (prover relation)
  "Step 6: every sin, cos and tan of a compound angle whose range gives it a sign is
replaced by a fresh variable with that sign (and in [-1, 1] for sin and cos); the
relation is decided under those facts. Sound: at every admissible point the kernels'
values satisfy them."
  (let ((bindings '()) (facts '()) (bridge (prover-bridge prover)))
    (dolist (kernel (angle-kernels relation))
      (let ((signs (trigonometric-signs prover kernel)))
        (when signs
          (let ((variable (kernel-variable bridge kernel)))
            (push (cons kernel variable) bindings)
            (push (cond ((equal signs '(:positive)) (list '> variable 0))
                        ((equal signs '(:negative)) (list '< variable 0))
                        ((member :positive signs) (list '>= variable 0))
                        (t (list '<= variable 0)))
                  facts)
            (unless (eq (expression-operator kernel) 'tan)
              (push (list '<= variable 1) facts)
              (push (list '>= variable -1) facts))))))
    (if (null bindings)
        :unknown
        (let ((rewritten (substitute-subexpressions bindings relation)))
          (handler-case (call-with-assumptions bridge facts (lambda () (decide bridge rewritten)))
            (inconsistent-assumptions () :unknown)
            (maxima-error () :unknown))))))

(defun substitute-subexpressions (bindings expression)
  "EXPRESSION with every subexpression EQUAL to the CAR of an entry of BINDINGS replaced
by its CDR."
  (let ((entry (assoc expression bindings :test #'equal)))
    (cond (entry (cdr entry))
          ((and (consp expression) (not (quantity-term-p expression)))
           (cons (car expression)
                 (mapcar (lambda (x) (substitute-subexpressions bindings x)) (cdr expression))))
          (t expression))))

(defun product-root-radicands (expression)
  "The radicands of the square roots that stand, two or more together, as factors of
one product or quotient somewhere in EXPRESSION, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (member (expression-operator x) '(* /))
                   (let ((radicands (loop for (factor) in (nth-value 1 (product-parts x))
                                          for radicand = (square-root-radicand factor)
                                          when radicand collect radicand)))
                     (when (rest radicands)
                       (dolist (radicand radicands) (pushnew radicand found :test #'equal)))))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    (nreverse found)))

(defun imaginary-radicands (bridge relation)
  "The radicands of RELATION's products of square roots (see PRODUCT-ROOT-RADICANDS)
that are proven negative: there sqrt(A) sqrt(B) = -sqrt(A B), which is() and sign(),
taking every square root for a real one, get wrong. A radicand sign() finds
nonnegative is not asked further."
  (loop for radicand in (product-root-radicands relation)
        for signs = (handler-case (form-signs bridge (to-mx bridge radicand) :datum relation)
                      (maxima-error () nil))
        when (and (not (only-signs-p signs :positive :zero))
                  (member :negative signs)
                  (eq :true (decide bridge (list '< radicand 0))))
          collect radicand))

(defun decide-with-imaginary-radicands (bridge relation)
  "RELATION decided without asking Maxima about its square roots of negative radicands
(see IMAGINARY-RADICANDS): from the signs of its parts (two imaginary factors make a
negative real one), then through squares."
  (let* ((*imaginary-radicands* (imaginary-radicands bridge relation))
         (prover (prover-for bridge))
         (verdict (relation-verdict (expression-operator relation)
                                    (expression-signs prover (relation-difference relation) :top t))))
    (if (eq verdict :unknown)
        (handler-case (decide-by-squares prover relation)
          ((or maxima-timeout maxima-error) () :unknown))
        verdict)))

(defparameter *largest-simplified-relation* 400
  "DECIDE-BY-SIGNED-PARTS has Maxima simplify (and factor) the difference of the sides
of a relation of at most this many atoms and operators.")

(defparameter *largest-squared-relation* 160
  "DECIDE-BY-SQUARES leaves alone a relation with more atoms and operators than this:
the comparisons a physicist makes through squares are short, and squaring the long
relations of a simulation (sums of products of square roots) costs much and proves
little.")

(defparameter *largest-decided-part* 60
  "LEAF-SIGNS asks DECIDE about a part of at most this many atoms and operators; a
longer one gets Maxima's sign() only.")

(defparameter *deepest-reasoning* 3
  "How many DECIDE-BY-REASONING calls may be under way at once.")

(defvar *reasoning-depth* 0
  "How many DECIDE-BY-REASONING calls are under way.")

(defparameter *reasoning-steps*
  '(decide-by-quarter-turns decide-by-signed-parts decide-by-common-factors
    decide-by-monotonicity decide-by-squares decide-by-angle-substitution)
  "The steps of DECIDE-BY-REASONING, in the order they are tried.")

(defun decide-by-reasoning (bridge relation)
  "RELATION (= /= < > <= >=) decided as a physicist would (see this file's header):
:TRUE or :FALSE when a step proves it, else :UNKNOWN."
  (cond ((>= *reasoning-depth* *deepest-reasoning*)
         (push :depth *cut-short*)
         :unknown)
        (t (let ((prover (prover-for bridge))
                 (*reasoning-depth* (1+ *reasoning-depth*)))
             (dolist (step *reasoning-steps* :unknown)
               (let ((verdict (handler-case (funcall step prover relation)
                                ;; a step whose rewriting Maxima cannot finish proves
                                ;; nothing (and the relation may do better elsewhere)
                                ((or maxima-timeout maxima-error) ()
                                  (push :depth *cut-short*)
                                  :unknown))))
                 (unless (eq verdict :unknown)
                   (return verdict))))))))
