;;;; src/algebra/atan-orders.lisp -- a step of DECIDE's reasoning: an inverse tangent against
;;;; an angle, compared through tan, which is increasing on (-pi/2, pi/2).
;;;;
;;;; A turning angle found through the half-angle substitution comes as s* = 2 atan(T), T a
;;;; root of a quadratic; where it lies is asked as pi + 4 atan(T) < 0 (s* against -pi/2),
;;;; 2 atan(T) > atan(k/w) - pi, and so on. Maxima's is() and sign() see no relation
;;;; between atan(T) and a constant angle. A physicist isolates the inverse tangent and
;;;; takes the tangent of both sides: the relation is c atan(X) + R op 0, linear in
;;;; atan(X) with a rational c /= 0 (R free of it), so it says atan(X) op' phi, phi = -R/c
;;;; (op' reversed for c < 0). phi is made of rational multiples of pi and of inverse
;;;; tangents atan(Y) (each in (0, pi/2) or (-pi/2, 0) by the sign of Y), so it lies in a
;;;; span (lo pi, hi pi) found by interval arithmetic. Then:
;;;;   - a span at or below -pi/2 (at or above pi/2) puts atan(X) above (below) phi;
;;;;   - phi = q pi (a constant) or phi = +-atan(Y) + n pi/2 (tan phi = +-Y or -+1/Y) within
;;;;     (-pi/2, pi/2): atan(X) op' phi exactly when X op' tan(phi), decided afresh;
;;;;   - otherwise the span's ends bound phi: atan(X) >= hi pi (X >= tan(hi pi), hi a
;;;;     multiple of pi/12 or pi/8 inside (-1/2, 1/2)) puts atan(X) above phi, atan(X) <= lo
;;;;     pi below it (strict where the span's end is closed).
;;;; Sound: tan is strictly increasing on (-pi/2, pi/2), where atan takes its values, and
;;;; every rewriting is an equivalence or a bound proven on the way.

(in-package #:ames.algebra)

(defparameter *most-atan-kernels* 3
  "The most inverse tangents of one relation DECIDE-BY-ATAN-ORDER isolates in turn.")

(defparameter *exact-tangents*
  '((0 . 0) (1/12 . (- 2 (sqrt 3))) (1/8 . (- (sqrt 2) 1)) (1/6 . (/ 1 (sqrt 3)))
    (1/4 . 1) (1/3 . (sqrt 3)) (3/8 . (+ (sqrt 2) 1)) (5/12 . (+ 2 (sqrt 3))))
  "tan(q pi) for the rational q in [0, 1/2) whose tangent is written exactly.")

(defun exact-tangent (q)
  "tan(Q pi) as an exact expression for a rational Q in (-1/2, 1/2) of *EXACT-TANGENTS*
(or its negative), else NIL."
  (let ((entry (assoc (abs q) *exact-tangents*)))
    (cond ((null entry) nil)
          ((minusp q) (list '- (cdr entry)))
          (t (cdr entry)))))

(defun one-argument-atans (expression argument-test)
  "The one-argument (atan X) forms of EXPRESSION (outside quantity terms) whose X
satisfies ARGUMENT-TEST, innermost first, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (mapc #'walk (expression-arguments x))
                 (when (and (eq (expression-operator x) 'atan)
                            (= 1 (length (expression-arguments x)))
                            (funcall argument-test (first (expression-arguments x))))
                   (pushnew x found :test #'equal)))))
      (walk expression))
    (nreverse found)))

(defun atan-kernels (expression)
  "The one-argument (atan X) of EXPRESSION whose X has a variable, largest first."
  (sort (reverse (one-argument-atans expression (complement #'numeric-constant-p)))
        #'> :key #'expression-size))

(defun linear-in-kernel (expression kernel)
  "EXPRESSION as c KERNEL + R with c rational and R free of KERNEL: (values c R), or NIL
when it is not of that form (through +, -, products and quotients by rationals)."
  (labels ((parts (x)
             (cond ((equal x kernel) (values 1 0))
                   ((not (occurs-p kernel x)) (values 0 x))
                   ((not (consp x)) (throw 'not-linear nil))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (let ((c 0) (rest '()))
                               (dolist (a arguments)
                                 (multiple-value-bind (ca ra) (parts a)
                                   (incf c ca) (push ra rest)))
                               (values c (cons '+ (nreverse rest)))))
                          (- (if (null (rest arguments))
                                 (multiple-value-bind (c r) (parts (first arguments))
                                   (values (- c) (list '- r)))
                                 (parts (list '+ (first arguments)
                                              (list '- (cons '+ (rest arguments)))))))
                          (* (let ((numbers (remove-if-not #'rationalp arguments))
                                   (others (remove-if #'rationalp arguments)))
                               (unless (= 1 (length others)) (throw 'not-linear nil))
                               (let ((factor (reduce #'* numbers)))
                                 (multiple-value-bind (c r) (parts (first others))
                                   (values (* factor c) (list '* factor r))))))
                          (/ (let ((divisor (second arguments)))
                               (unless (and (rationalp divisor) (/= 0 divisor)
                                            (= 2 (length arguments)))
                                 (throw 'not-linear nil))
                               (multiple-value-bind (c r) (parts (first arguments))
                                 (values (/ c divisor) (list '/ r divisor)))))
                          (t (throw 'not-linear nil))))))))
    (catch 'not-linear
      (multiple-value-bind (c r) (parts expression)
        (and (/= c 0) (values c r))))))

(defun occurs-p (part expression)
  "True when PART (compared with EQUAL) is a subexpression of EXPRESSION."
  (or (equal part expression)
      (and (consp expression) (not (quantity-term-p expression))
           (some (lambda (x) (occurs-p part x)) (expression-arguments expression)))))

;;; The span of an angle made of multiples of pi and inverse tangents

(defun quarter-span (prover y sign)
  "The span of atan(Y), Y of the strict SIGN (+1, -1), in units of pi, narrowed to one
side of +-pi/4 where Y against +-1 is proven: (values LO HI LO-OPEN HI-OPEN)."
  (let ((bridge (prover-bridge prover)))
    (if (= sign 1)
        (cond ((holds-p bridge `(> ,y 1)) (values 1/4 1/2 t t))
              ((holds-p bridge `(>= ,y 1)) (values 1/4 1/2 nil t))
              ((holds-p bridge `(< ,y 1)) (values 0 1/4 t t))
              ((holds-p bridge `(<= ,y 1)) (values 0 1/4 t nil))
              (t (values 0 1/2 t t)))
        (multiple-value-bind (lo hi lo-open hi-open) (quarter-span prover `(- ,y) 1)
          (values (- hi) (- lo) hi-open lo-open)))))

(defun angle-span (prover angle &key refine)
  "The span of ANGLE in units of pi, (values LO HI LO-OPEN HI-OPEN), for ANGLE made of
rationals times pi, 0 and one-argument inverse tangents (through +, -, rational
products and quotients); NIL when ANGLE is not of that form. REFINE narrows each
inverse tangent's span to one side of +-pi/4 where the facts decide it (QUARTER-SPAN)."
  (labels ((span (x)
             (cond ((eql x 0) (values 0 0 nil nil))
                   ((eq x 'pi) (values 1 1 nil nil))
                   ((not (consp x)) (throw 'no-span nil))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (atan (unless (= 1 (length arguments)) (throw 'no-span nil))
                           (let ((signs (expression-signs prover (first arguments))))
                             (cond ((only-signs-p signs :positive)
                                    (if refine (quarter-span prover (first arguments) 1) (values 0 1/2 t t)))
                                   ((only-signs-p signs :negative)
                                    (if refine (quarter-span prover (first arguments) -1) (values -1/2 0 t t)))
                                   ((only-signs-p signs :positive :zero) (values 0 1/2 nil t))
                                   ((only-signs-p signs :negative :zero) (values -1/2 0 t nil))
                                   (t (values -1/2 1/2 t t)))))
                          (+ (let ((lo 0) (hi 0) (lo-open nil) (hi-open nil))
                               (dolist (a arguments (values lo hi lo-open hi-open))
                                 (multiple-value-bind (l h lo2 ho2) (span a)
                                   (incf lo l) (incf hi h)
                                   (setf lo-open (or lo-open lo2) hi-open (or hi-open ho2))))))
                          (- (if (null (rest arguments))
                                 (scaled -1 (first arguments))
                                 (span (list '+ (first arguments)
                                             (list '- (cons '+ (rest arguments)))))))
                          (* (let ((numbers (remove-if-not #'rationalp arguments))
                                   (others (remove-if #'rationalp arguments)))
                               (case (length others)
                                 (0 (if (zerop (reduce #'* numbers)) (values 0 0 nil nil) (throw 'no-span nil)))
                                 (1 (scaled (reduce #'* numbers) (first others)))
                                 (t (throw 'no-span nil)))))
                          (/ (let ((divisor (second arguments)))
                               (unless (and (= 2 (length arguments)) (rationalp divisor) (/= 0 divisor))
                                 (throw 'no-span nil))
                               (scaled (/ 1 divisor) (first arguments))))
                          (t (throw 'no-span nil)))))))
           (scaled (factor x)
             (multiple-value-bind (l h lo-open hi-open) (span x)
               (cond ((zerop factor) (values 0 0 nil nil))
                     ((plusp factor) (values (* factor l) (* factor h) lo-open hi-open))
                     (t (values (* factor h) (* factor l) hi-open lo-open))))))
    (catch 'no-span
      (span angle))))

(defun exact-angle-tangent (prover angle lo hi)
  "tan(ANGLE) written exactly, for ANGLE whose span (LO HI, in units of pi) lies within
the open (-1/2, 1/2): a constant q pi of *EXACT-TANGENTS*, or +-atan(Y) + n pi/2 (tan = +-Y for n
even, -+1/Y for n odd); NIL otherwise."
  (if (= lo hi)
      (exact-tangent lo)
      (let ((kernels (atan-kernels angle)))
        (when (= 1 (length kernels))
          (multiple-value-bind (c rest) (linear-in-kernel angle (first kernels))
            (multiple-value-bind (l h) (and c (angle-span prover rest))
              (when (and (member c '(1 -1)) l (= l h) (integerp (* 2 l)))
                (let ((tangent (if (= c 1) (second (first kernels)) `(- ,(second (first kernels))))))
                  (if (integerp l) tangent `(- (/ 1 ,tangent)))))))))))

(defun atan-above-verdict (prover x angle strict)
  "The truth of atan(X) > ANGLE (STRICT) or atan(X) >= ANGLE, ANGLE of a span (see
ANGLE-SPAN): :TRUE, :FALSE or :UNKNOWN, by the cases of this file's header; with the
inverse tangents' spans narrowed (QUARTER-SPAN) when their crude spans leave it open."
  (let ((verdict (atan-above-verdict-in-span prover x angle strict nil)))
    (if (eq verdict :unknown)
        (atan-above-verdict-in-span prover x angle strict t)
        verdict)))

(defun atan-above-verdict-in-span (prover x angle strict refine)
  "ATAN-ABOVE-VERDICT with the span of ANGLE (ANGLE-SPAN, REFINE)."
  (multiple-value-bind (lo hi lo-open hi-open) (angle-span prover angle :refine refine)
    (let ((bridge (prover-bridge prover))
          (operator (if strict '> '>=)))
      (cond ((null lo) :unknown)
            ((<= hi -1/2) :true)
            ((>= lo 1/2) :false)
            ((let ((tangent (and (or (> lo -1/2) (and (= lo -1/2) lo-open))
                                 (or (< hi 1/2) (and (= hi 1/2) hi-open))
                                 (exact-angle-tangent prover angle lo hi))))
               (and tangent
                    (let ((verdict (decide bridge (list operator x tangent))))
                      (and (not (eq verdict :unknown)) verdict)))))
            ((= lo hi) :unknown)
            (t (let ((above (and (> hi -1/2) (< hi 1/2) (exact-tangent hi)))
                     (below (and (> lo -1/2) (< lo 1/2) (exact-tangent lo))))
                 (cond ((and above (holds-p bridge (list '> x above))) :true)
                       ((and above (or hi-open (not strict)) (holds-p bridge (list '>= x above))) :true)
                       ((and below (holds-p bridge (list '< x below))) :false)
                       ((and below (or lo-open strict) (holds-p bridge (list '<= x below))) :false)
                       (t :unknown))))))))

(defun decide-by-atan-order (prover relation)
  "Reasoning step: RELATION (< <= > >=) linear in an inverse tangent atan(X) of a
variable expression, with the rest an angle of multiples of pi and inverse tangents,
decided through tan (see this file's header); :UNKNOWN when no such atan(X) decides it."
  (let ((operator (expression-operator relation))
        (difference (relation-difference relation)))
    (if (not (member operator '(< <= > >=)))
        :unknown
        (loop for kernel in (atan-kernels relation)
              repeat *most-atan-kernels*
              do (multiple-value-bind (c rest) (linear-in-kernel difference kernel)
                   (when c
                     ;; c atan(X) + R op 0: atan(X) op' -R/c
                     (let* ((op (if (plusp c) operator (flipped-operator operator)))
                            (angle (list '* (- (/ 1 c)) rest))
                            (x (second kernel))
                            (verdict (ecase op
                                       (> (atan-above-verdict prover x angle t))
                                       (>= (atan-above-verdict prover x angle nil))
                                       (< (negated-verdict (atan-above-verdict prover x angle nil)))
                                       (<= (negated-verdict (atan-above-verdict prover x angle t))))))
                       (unless (eq verdict :unknown)
                         (return verdict)))))
              finally (return :unknown)))))

(defun negated-verdict (verdict)
  "The verdict on the negation of a relation whose verdict is VERDICT."
  (ecase verdict (:true :false) (:false :true) (:unknown :unknown)))

;;; sin and cos of 2 atan(u) (or atan(u)) in a relation linear in them

(defun kernel-coefficient-parts (expression kernel)
  "EXPRESSION as c KERNEL + R with c and R free of KERNEL (through +, -, products with
one factor holding KERNEL, quotients by expressions free of it): (values c R), c
possibly 0; NIL when it is not of that form."
  (labels ((parts (x)
             (cond ((equal x kernel) (values 1 0))
                   ((not (occurs-p kernel x)) (values 0 x))
                   ((not (consp x)) (throw 'not-linear nil))
                   (t (let ((arguments (expression-arguments x)))
                        (case (expression-operator x)
                          (+ (let ((cs '()) (rs '()))
                               (dolist (a arguments)
                                 (multiple-value-bind (ca ra) (parts a)
                                   (push ca cs) (push ra rs)))
                               (values (cons '+ (nreverse cs)) (cons '+ (nreverse rs)))))
                          (- (if (null (rest arguments))
                                 (multiple-value-bind (c r) (parts (first arguments))
                                   (values (list '- c) (list '- r)))
                                 (parts (list '+ (first arguments)
                                              (list '- (cons '+ (rest arguments)))))))
                          (* (let ((holding (remove-if-not (lambda (a) (occurs-p kernel a)) arguments))
                                   (others (remove-if (lambda (a) (occurs-p kernel a)) arguments)))
                               (unless (= 1 (length holding)) (throw 'not-linear nil))
                               (multiple-value-bind (c r) (parts (first holding))
                                 (values (list* '* c others) (list* '* r others)))))
                          (/ (unless (and (= 2 (length arguments)) (not (occurs-p kernel (second arguments))))
                               (throw 'not-linear nil))
                           (multiple-value-bind (c r) (parts (first arguments))
                             (values (list '/ c (second arguments)) (list '/ r (second arguments)))))
                          (t (throw 'not-linear nil))))))))
    (catch 'not-linear
      (parts expression))))

(defun inverse-tangent-angles (expression)
  "The arguments u of the (sin A) and (cos A) of EXPRESSION whose A is atan(u) or
2 atan(u) (as (* 2 (atan u))), each once, with the multiple: a list of (N U)."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (member (expression-operator x) '(sin cos))
                   (let ((angle (second x)))
                     (cond ((and (consp angle) (eq (first angle) 'atan) (= 2 (length angle)))
                            (pushnew (list 1 (second angle)) found :test #'equal))
                           ((and (consp angle) (eq (first angle) '*) (= 3 (length angle))
                                 (eql 2 (second angle)) (consp (third angle))
                                 (eq (first (third angle)) 'atan) (= 2 (length (third angle))))
                            (pushnew (list 2 (second (third angle))) found :test #'equal)))))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    found))

(defun decide-by-half-angle-tangent (prover relation)
  "Reasoning step: RELATION (< <= > >=) whose difference is linear in sin A and cos A, A =
2 atan(u) (or atan(u)), with coefficients free of them, multiplied by 1 + u^2 (or
sqrt(1 + u^2)), positive: c0 + c1 cos A + c2 sin A becomes c0 (1 + u^2) + c1 (1 - u^2) +
2 c2 u (c0 sqrt(1 + u^2) + c1 + c2 u), compact and algebraic in u, decided in place. The
expansion of step 7 (inverse-angles.lisp) writes the same expanded, often far larger
than the relation. :UNKNOWN when no such angle makes the relation linear."
  (let ((operator (expression-operator relation))
        (difference (relation-difference relation)))
    (if (not (member operator '(< <= > >=)))
        :unknown
        (dolist (angle (inverse-tangent-angles relation) :unknown)
          (destructuring-bind (n u) angle
            (let* ((a (if (= n 1) `(atan ,u) `(* 2 (atan ,u))))
                   (cosine `(cos ,a)) (sine `(sin ,a)))
              (multiple-value-bind (c1 rest) (kernel-coefficient-parts difference cosine)
                (multiple-value-bind (c2 c0) (and c1 (kernel-coefficient-parts rest sine))
                  (when (and c2 (not (occurs-p cosine c1)) (not (occurs-p sine c1))
                             (not (occurs-p sine c2)) (not (occurs-p cosine c0)))
                    (let* ((square `(+ 1 (expt ,u 2)))
                           (rewritten
                             (if (= n 2)
                                 `(+ (* ,c0 ,square) (* ,c1 (- 1 (expt ,u 2))) (* 2 ,c2 ,u))
                                 `(+ (* ,c0 (sqrt ,square)) ,c1 (* ,c2 ,u))))
                           ;; an equivalent relation, decided in place (at the depth of
                           ;; this one: DECIDE's bounds on nesting would cut the proofs it
                           ;; needs, such as a radicand's sign by convexity)
                           (verdict (decide-relation (prover-bridge prover) (list operator rewritten 0))))
                      (unless (eq verdict :unknown)
                        (return verdict))))))))))))
