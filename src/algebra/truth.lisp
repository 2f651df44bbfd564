;;;; src/algebra/truth.lisp -- what a physicist knows, for DECIDE: signed factors, angles, monotonicity, squares.
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
;;;;      for fresh variables of that sign (in [-1, 1] for sin and cos);
;;;;   7. inverse angles: sin, cos and tan of angles made of asin, acos, atan expanded into
;;;;      algebra (inverse-angles.lisp);
;;;;   8. polar angles: atan2(y, x) with y of known sign written pi/2 - atan(x/y) or
;;;;      -pi/2 - atan(x/y) (inverse-angles.lisp);
;;;;   9. half angles: sin, cos and tan of a plain angle written in t = tan(x/2)
;;;;      (half-angles.lisp);
;;;;  (4b, after monotonicity) an inverse tangent against an angle of multiples of pi and
;;;;      inverse tangents, compared through tan (atan-orders.lisp);
;;;;  (0, first) a relation linear in sin and cos of 2 atan(u) multiplied by 1 + u^2, an
;;;;      equivalent algebraic relation decided in its place (atan-orders.lisp).
;;;; Every step is an equivalence or a sound relaxation, so a :TRUE or :FALSE it finds is
;;;; proven; a step that cannot apply answers :UNKNOWN. Steps ask DECIDE about smaller or
;;;; rewritten relations; DECIDE stops a question that is already under way, and
;;;; questions nested too deep (see *DECIDING*), so the reasoning always ends.
;;;;
;;;; The signs of expressions from the signs of their parts are in signs.lisp.

(in-package #:ames.algebra)

(defparameter *largest-simplified-relation* 400
  "DECIDE-BY-SIGNED-PARTS has Maxima simplify (and factor) the difference of the sides
of a relation of at most this many atoms and operators.")

(defparameter *largest-squared-relation* 160
  "DECIDE-BY-SQUARES leaves alone a relation with more atoms and operators than this:
the comparisons a physicist makes through squares are short, and squaring the long
relations of a simulation (sums of products of square roots) costs much and proves
little.")

(defparameter *deepest-reasoning* 3
  "How many DECIDE-BY-REASONING calls may be under way at once.")

(defvar *reasoning-depth* 0
  "How many DECIDE-BY-REASONING calls are under way.")

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
variable, each once. Not those of a rational X (an angle found with numbers): their
values are known to sign() as they are, and a variable in their place only adds work."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (mapc #'walk (expression-arguments x))
                 (when (and (member (expression-operator x) '(sin cos tan))
                            (not (subject-p (second x)))
                            (not (rationalp (second x))))
                   (pushnew x found :test #'equal)))))
      (walk expression))
    (nreverse found)))

(defun kernel-variable (bridge kernel)
  "The fresh variable standing for KERNEL in DECIDE-BY-ANGLE-SUBSTITUTION: uninterned,
the same each time for a KERNEL of BRIDGE (so that requests come again from the cache),
and named apart from the algebra's variables ($AMESX...)."
  (keyed-auxiliary-variable bridge (list :kernel kernel)
                            (format nil "~A-VALUE" (expression-operator kernel))))

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

(defparameter *reasoning-steps*
  '(decide-by-half-angle-tangent decide-by-quarter-turns decide-by-signed-parts decide-by-common-factors
    decide-by-monotonicity decide-by-atan-order decide-by-squares decide-by-angle-substitution
    decide-by-inverse-angle-expansion decide-by-polar-angles decide-by-principal-angles
    decide-by-half-angles decide-by-one-angle-cells)
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
