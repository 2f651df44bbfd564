;;;; src/algebra/one-angle-cells.lisp -- a relation in one angle decided exactly under the
;;;; facts in that angle: half angles, then the real line cut into cells (Sturm).
;;;;
;;;; A branch assumes 2 sin a - cos a > 0 (a block on an incline of friction 1/2 slides);
;;;; deeper in it the run asks whether (sin a + 4 cos a) cos a - 4 < 0. A physicist sees it:
;;;; the left side is sin a (cos a - 4 sin a), and tan a > 1/2 > 1/4. DECIDE's rewriting
;;;; step with half angles (half-angles.lisp) rewrites the relation but not the facts, and
;;;; sign() knows no fact about 2 sin a - cos a. Here both are rewritten: with t = tan(a/2)
;;;; every sine, cosine and tangent of a is rational in t, the range of a (inside (-pi, pi),
;;;; where t = tan(a/2) is an increasing bijection onto the reals) becomes an interval of t,
;;;; and the relation and every fact in force that is about a alone become signs of
;;;; polynomials with rational coefficients in t. The real roots of all of them are isolated
;;;; in disjoint rational intervals (Sturm sequences, exact rational arithmetic, in Lisp);
;;;; between them and at them every polynomial has a known sign. The relation is :TRUE when
;;;; it holds in every cell where the facts hold, :FALSE when it fails in every such cell,
;;;; :UNKNOWN otherwise (or when no cell is admissible, or the relation is undefined in one).
;;;; Sound: a fact left out (it mentions another parameter, or a coefficient is not
;;;; rational) and an end of the interval widened outward (an angle whose half's tangent
;;;; is not rational) only add cells, which can only lose a verdict.

(in-package #:ames.algebra)

(defparameter *largest-cell-degree* 40
  "The most total degree in t of the relation's and the facts' polynomials that the cells
are worked out for.")

;;; Polynomials in one variable: lists of rational coefficients, highest power first

(defun upoly-trim (p)
  "P without leading zero coefficients (NIL is the zero polynomial)."
  (member-if-not #'zerop p))

(defun upoly-degree (p) (1- (length p)))

(defun upoly-value (p x)
  "P at the rational X, exactly (Horner)."
  (let ((value 0))
    (dolist (c p value) (setf value (+ (* value x) c)))))

(defun upoly-derivative (p)
  (let ((n (upoly-degree p)))
    (upoly-trim (loop for c in (butlast p) for k downfrom n collect (* k c)))))

(defun upoly-remainder (p q)
  "The remainder of P divided by the non-zero Q."
  (let ((p (upoly-trim p)) (q (upoly-trim q)))
    (loop while (and p (>= (length p) (length q)))
          do (let ((factor (/ (first p) (first q))))
               (setf p (upoly-trim (rest (mapcar (lambda (a b) (- a (* factor b)))
                                                 p (append q (make-list (- (length p) (length q))
                                                                        :initial-element 0))))))))
    p))

(defun upoly-quotient (p q)
  "The quotient of P divided by the non-zero Q (the remainder dropped)."
  (let ((p (upoly-trim p)) (q (upoly-trim q)) (quotient '()))
    (loop while (and p (>= (length p) (length q)))
          do (let ((factor (/ (first p) (first q))))
               (push factor quotient)
               (setf p (rest (mapcar (lambda (a b) (- a (* factor b)))
                                     p (append q (make-list (- (length p) (length q))
                                                            :initial-element 0)))))))
    (upoly-trim (append (reverse quotient) (and (null quotient) '(0))))))

(defun upoly-gcd (p q)
  "The monic greatest common divisor of P and Q (not both zero)."
  (loop while (upoly-trim q)
        do (psetf p q q (upoly-remainder p q)))
  (let ((p (upoly-trim p)))
    (mapcar (lambda (c) (/ c (first p))) p)))

(defun upoly-product (p q)
  (let ((result (make-list (+ (length p) (length q) -1) :initial-element 0)))
    (loop for a in p for i from 0
          do (loop for b in q for j from 0 do (incf (nth (+ i j) result) (* a b))))
    result))

(defun upoly-squarefree (p)
  "P divided by its repeated factors: the same real roots, each simple."
  (let ((g (upoly-gcd p (upoly-derivative p))))
    (if (zerop (upoly-degree g)) p (upoly-quotient p g))))

(defun sturm-chain (p)
  (let ((chain (list (upoly-derivative p) p)))
    (loop for r = (upoly-trim (mapcar #'- (upoly-remainder (second chain) (first chain))))
          while r do (push r chain))
    (nreverse chain)))

(defun sign-changes (chain x)
  (let ((signs (remove 0 (mapcar (lambda (p) (signum (upoly-value p x))) chain))))
    (loop for (a b) on signs while b count (/= a b))))

(defun roots-between (chain low high)
  "The number of distinct real roots of CHAIN's polynomial in (LOW, HIGH], neither a root."
  (- (sign-changes chain low) (sign-changes chain high)))

(defun split-point (p low high)
  "A rational strictly between LOW and HIGH where P is not zero."
  (loop for k from 2
        for x = (+ low (/ (* (- high low) (floor k 2)) (1+ k)))
        unless (zerop (upoly-value p x)) return x))

(defun isolated-roots (p low high)
  "Disjoint intervals (A . B), A < B rationals where P is not zero, each holding exactly one
root of the squarefree P in (LOW, HIGH) (LOW and HIGH not roots), in increasing order, none
starting at LOW or ending at HIGH (so that a point between LOW and the first root, and one
between the last root and HIGH, are known)."
  (let ((chain (sturm-chain p)))
    (labels ((isolate (a b)
               (let ((count (roots-between chain a b)))
                 (cond ((zerop count) '())
                       ((= count 1) (list (cons a b)))
                       (t (let ((middle (split-point p a b)))
                            (append (isolate a middle) (isolate middle b)))))))
             (pulled-in (interval)
               (destructuring-bind (a . b) interval
                 (loop while (= a low)
                       do (let ((middle (split-point p a b)))
                            (if (zerop (roots-between chain a middle))
                                (setf a middle)
                                (setf b middle))))
                 (loop while (= b high)
                       do (let ((middle (split-point p a b)))
                            (if (zerop (roots-between chain middle b))
                                (setf b middle)
                                (setf a middle))))
                 (cons a b))))
      (mapcar #'pulled-in (isolate low high)))))

(defun root-bound (p)
  "A rational beyond the absolute value of every real root of P (Cauchy)."
  (1+ (reduce #'max (mapcar (lambda (c) (abs (/ c (first p)))) (rest p)) :initial-value 0)))

;;; The relation and the facts in t = tan(a/2)

(defun one-angle-subject (relation)
  "The subject X when every variable of RELATION is X, met only as the argument of sin,
cos or tan; NIL otherwise."
  (let ((subject nil))
    (labels ((walk (x)
               (cond ((subject-p x)
                      (return-from one-angle-subject nil))
                     ((atom x) t)
                     ((and (member (expression-operator x) '(sin cos tan))
                           (subject-p (second x)) (null (cddr x)))
                      (if (or (null subject) (equal subject (second x)))
                          (setf subject (second x))
                          (return-from one-angle-subject nil)))
                     (t (mapc #'walk (expression-arguments x))))))
      (if (and (consp relation) (not (quantity-term-p relation)))
          (mapc #'walk (expression-arguments relation))
          (return-from one-angle-subject nil))
      subject)))

(defun t-polynomial (polynomial variable)
  "The alist POLYNOMIAL (POLYNOMIAL-OF) in the one VARIABLE as a coefficient list, or NIL
when another atom occurs in it."
  (let ((degree 0))
    (dolist (term polynomial)
      (let ((monomial (car term)))
        (cond ((null monomial))
              ((and (null (rest monomial)) (equal (car (first monomial)) variable))
               (setf degree (max degree (cdr (first monomial)))))
              (t (return-from t-polynomial nil)))))
    (let ((coefficients (make-list (1+ degree) :initial-element 0)))
      (dolist (term polynomial)
        (let ((power (if (car term) (cdr (first (car term))) 0)))
          (incf (nth (- degree power) coefficients) (cdr term))))
      (or (upoly-trim coefficients) '(0)))))

(defun half-angle-quotient (bridge expression angle variable)
  "EXPRESSION (in sin, cos, tan of ANGLE) in t = VARIABLE, as (values NUMERATOR
DENOMINATOR), coefficient lists; NIL when they are not polynomials with rational
coefficients."
  (let ((rewritten (substitute-subexpressions (half-angle-bindings angle variable) expression)))
    (multiple-value-bind (numerator denominator) (quotient-parts bridge rewritten)
      (let ((n (and numerator (polynomial-of numerator)))
            (d (and denominator (polynomial-of denominator))))
        (when (or n (eql numerator 0))
          (let ((np (if (eql numerator 0) '(0) (t-polynomial n variable)))
                (dp (if (eql denominator 1) '(1) (and d (t-polynomial d variable)))))
            (and np dp (upoly-trim dp) (values np dp))))))))

(defun half-tangent-end (end side)
  "tan(END/2) for the range end END (a PI-NUMBER strictly inside (-pi, pi)), as a rational:
exact at 0 and +-pi/2, else a rational just outside it on SIDE."
  (cond ((and (zerop (car end)) (member (cdr end) '(0 1/2 -1/2)))
         (values (* 2 (cdr end)) t))
        (t (values (car (widened-bound (tan (/ (pn-float end) 2)) side)) nil))))

(defun half-tangent-interval (prover angle)
  "The interval of t = tan(ANGLE/2) over ANGLE's range, as a list (LOW HIGH LOW-CLOSED
HIGH-CLOSED), LOW or HIGH NIL for an unbounded side (the range reaching -pi or pi,
excluded); NIL when the range is not bounded inside [-pi, pi] with +-pi excluded."
  (let ((range (cdr (assoc angle (prover-ranges prover) :test #'equal))))
    (when (and range (range-lower range) (range-upper range))
      (let ((lower (range-lower range)) (upper (range-upper range)))
        (flet ((edge-p (end sign) (and (zerop (car end)) (= (cdr end) sign))))
          (when (and (or (plusp (pn-sign (pn+ lower (pi-number 0 1))))
                         (and (edge-p lower -1) (range-lower-open range)))
                     (or (minusp (pn-sign (pn- upper (pi-number 0 1))))
                         (and (edge-p upper 1) (range-upper-open range))))
            (multiple-value-bind (low low-exact)
                (if (edge-p lower -1) (values nil nil) (half-tangent-end lower :lower))
              (multiple-value-bind (high high-exact)
                  (if (edge-p upper 1) (values nil nil) (half-tangent-end upper :upper))
                (list low high
                      (and low (not (and low-exact (range-lower-open range))))
                      (and high (not (and high-exact (range-upper-open range)))))))))))))

(defun angle-facts (bridge angle)
  "The facts in force that are about ANGLE alone through its sine, cosine and tangent,
as relations (OPERATOR DIFFERENCE 0)."
  (loop for fact in (flatten-facts (current-assumptions bridge))
        when (and (consp fact) (member (expression-operator fact) '(< > <= >= = /=))
                  (equal (one-angle-subject fact) angle))
          collect (list (expression-operator fact) (relation-difference fact) 0)))

;;; Cells

(defun sign-holds-p (operator sign)
  "True when a difference of SIGN (-1, 0, 1) satisfies OPERATOR against 0."
  (ecase operator
    (> (plusp sign)) (>= (>= sign 0)) (< (minusp sign)) (<= (<= sign 0))
    (= (zerop sign)) (/= (/= sign 0))))

(defun cell-verdicts (signs goal facts)
  "At one cell where the polynomials' SIGNS (a function of a polynomial) are known:
:HOLDS, :FAILS, :UNDEFINED (the goal's denominator vanishes) or NIL (no fact-admissible
point). GOAL and each of FACTS are (OPERATOR NUMERATOR DENOMINATOR)."
  (flet ((sign-of (entry)
           (let ((d (funcall signs (third entry))))
             (and (/= d 0) (* d (funcall signs (second entry)))))))
    (when (every (lambda (fact)
                   (let ((s (sign-of fact))) (and s (sign-holds-p (first fact) s))))
                 facts)
      (let ((s (sign-of goal)))
        (cond ((null s) :undefined)
              ((sign-holds-p (first goal) s) :holds)
              (t :fails))))))

(defun angle-cells (polynomials low high low-closed high-closed)
  "The cells of the t-interval (LOW, HIGH) (NIL: unbounded), with its ends where closed,
that the real roots of POLYNOMIALS (coefficient lists) cut it into: a list of
(SIGNS . WHERE), SIGNS a function from one of POLYNOMIALS to its sign (-1, 0, 1) in that
cell, WHERE a rational point of a cell where none vanishes or at an end, or (A . B), the
isolating interval of a root of one or more of them."
  (let* ((product (upoly-squarefree
                   (reduce #'upoly-product (remove-if (lambda (p) (< (upoly-degree p) 1)) polynomials)
                           :initial-value '(1))))
         (bound (root-bound product))
         (cells '()))
    (flet ((at-point (x)
             (push (cons (lambda (p) (signum (upoly-value p x))) x) cells))
           (deflated (p x)
             (loop while (and (> (upoly-degree p) 0) (zerop (upoly-value p x)))
                   do (setf p (upoly-quotient p (list 1 (- x)))))
             p))
      (when (and low low-closed) (at-point low))
      (when (and high high-closed) (at-point high))
      (let* ((reach (max bound (if low (1+ (abs low)) 0) (if high (1+ (abs high)) 0)))
             (from (or low (- reach))) (to (or high reach))
             (interior (deflated (deflated product from) to))
             (intervals (if (zerop (upoly-degree interior)) '() (isolated-roots interior from to)))
             (gap-start from))
        (dolist (interval intervals)
          (destructuring-bind (a . b) interval
            (at-point (/ (+ gap-start a) 2))
            (push (cons (lambda (p)
                          (let ((g (upoly-gcd p interior)))
                            (if (and (plusp (upoly-degree g))
                                     (= 1 (roots-between (sturm-chain g) a b)))
                                0
                                (signum (upoly-value p a)))))
                        interval)
                  cells)
            (setf gap-start b)))
        (at-point (/ (+ gap-start to) 2))))
    cells))

(defun entry-polynomials (entries)
  "The numerators and denominators of ENTRIES ((OPERATOR NUMERATOR DENOMINATOR) ...)."
  (loop for entry in entries append (list (second entry) (third entry))))

(defun cell-outcomes (goal facts interval)
  "The verdicts (CELL-VERDICTS) of GOAL in every cell of INTERVAL (LOW HIGH LOW-CLOSED
HIGH-CLOSED) of t where FACTS hold."
  (loop for (signs . nil) in (apply #'angle-cells (entry-polynomials (cons goal facts)) interval)
        collect (cell-verdicts signs goal facts)))

(defun one-angle-entries (bridge relation angle)
  "RELATION and the facts in force about ANGLE alone in t = tan(ANGLE/2): (values GOAL
FACTS), each (OPERATOR NUMERATOR DENOMINATOR); GOAL NIL when RELATION is not rational in t
with rational coefficients. Facts that are not are left out."
  (let ((variable (keyed-auxiliary-variable bridge (list :half-angle angle)
                                            (format nil "~A-HALF-TAN" angle))))
    (flet ((entry (operator difference)
             (multiple-value-bind (n d) (half-angle-quotient bridge difference angle variable)
               (and n (list operator n d)))))
      (values (entry (expression-operator relation) (relation-difference relation))
              (loop for (operator difference) in (angle-facts bridge angle)
                    for entry = (entry operator difference)
                    when entry collect entry)))))

(defun decide-by-one-angle-cells (prover relation)
  "Step of DECIDE-BY-REASONING: RELATION about one angle alone decided under the facts
about that angle alone, exactly (see this file's header): :TRUE, :FALSE or :UNKNOWN."
  (let* ((angle (and (member (expression-operator relation) '(< > <= >= = /=))
                     (one-angle-subject relation)))
         (interval (and angle (half-tangent-interval prover angle))))
    (unless interval (return-from decide-by-one-angle-cells :unknown))
    (multiple-value-bind (goal facts) (one-angle-entries (prover-bridge prover) relation angle)
      (unless (and goal (<= (reduce #'+ (cons goal facts)
                                    :key (lambda (e) (+ (upoly-degree (second e))
                                                        (upoly-degree (third e)))))
                            *largest-cell-degree*))
        (return-from decide-by-one-angle-cells :unknown))
      (let ((outcomes (remove nil (cell-outcomes goal facts interval))))
        (cond ((or (null outcomes) (member :undefined outcomes)) :unknown)
              ((every (lambda (o) (eq o :holds)) outcomes) :true)
              ((every (lambda (o) (eq o :fails)) outcomes) :false)
              (t :unknown))))))

;;; The angle where a relation's sides meet: a fork's boundary

(defun coefficient-expression (coefficients variable)
  "The polynomial with COEFFICIENTS (highest power first) in VARIABLE, as an expression."
  (let ((degree (upoly-degree coefficients)))
    `(+ ,@(loop for c in coefficients for k downfrom degree
                unless (zerop c) collect `(* ,c (expt ,variable ,k))))))

(defun zero-cells (goal facts interval)
  "The WHEREs (see ANGLE-CELLS) of the cells of INTERVAL where FACTS hold, GOAL's numerator
vanishes and its denominator does not."
  (let ((equation (list '= (second goal) (third goal))))
    (loop for (signs . where) in (apply #'angle-cells (entry-polynomials (cons goal facts)) interval)
          when (eq (cell-verdicts signs equation facts) :holds)
            collect where)))

(defun root-in-interval (bridge numerator variable interval)
  "The exact real root of the polynomial NUMERATOR (coefficients) in VARIABLE that lies in
the isolating INTERVAL (A . B), from Maxima's solve(), or NIL when solve() gives no
single one there (the interval is narrowed first, so that floating values place it)."
  (let* ((squarefree (upoly-squarefree numerator))
         (chain (sturm-chain squarefree))
         (a (car interval)) (b (cdr interval)))
    (loop repeat 40
          do (let ((middle (split-point squarefree a b)))
               (if (zerop (roots-between chain a middle)) (setf a middle) (setf b middle))))
    (let ((inside (loop for solution in (handler-case
                                            (solve-equations bridge
                                                             (list (list '= (coefficient-expression
                                                                             squarefree variable)
                                                                         0))
                                                             (list variable))
                                          (solve-failed () nil))
                        for root = (cdr (first solution))
                        for value = (constant-value root)
                        when (and value (< a (rational value) b))
                          collect root)))
      (and inside (null (rest inside)) (first inside)))))

(defun one-angle-root (bridge difference angle)
  "The one value of ANGLE, in its range and where the facts in force about ANGLE alone
hold, at which DIFFERENCE (in sin, cos and tan of ANGLE alone) is zero, as an expression
(an atan): NIL when there is no such value, more than one, or it cannot be told or
written exactly. The range must lie in (-pi, pi) (see HALF-TANGENT-INTERVAL)."
  (let* ((relation (list '= difference 0))
         (interval (and (equal (one-angle-subject relation) angle)
                        (half-tangent-interval (prover-for bridge) angle))))
    (when interval
      (multiple-value-bind (goal facts) (one-angle-entries bridge relation angle)
        (let ((zeros (and goal (plusp (upoly-degree (second goal)))
                          (zero-cells goal facts interval)))
              (variable (keyed-auxiliary-variable bridge (list :half-angle angle)
                                                  (format nil "~A-HALF-TAN" angle))))
          (when (and zeros (null (rest zeros)))
            (let ((root (if (rationalp (first zeros))
                            (first zeros)
                            (root-in-interval bridge (second goal) variable (first zeros)))))
              (when root
                (let ((value (constant-value root)))
                  (if (and value (< -1 value 1))
                      ;; within (-pi/2, pi/2): tan of the angle is 2t/(1 - t^2)
                      (list 'atan (simplified bridge `(/ (* 2 ,root) (- 1 (expt ,root 2)))))
                      (list '* 2 (list 'atan root))))))))))))
