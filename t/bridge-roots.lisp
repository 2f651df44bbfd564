;;;; t/bridge-roots.lisp -- tests of the bridge's earliest root, autonomous ODEs, numeric values and LaTeX.

(in-package #:ames.tests)

(in-suite bridge)

(defparameter *uniform-motion-gap* '(- (+ x0 (* v0 tm) (/ (* acc (expt tm 2)) 2)) l)
  "Where a body starting at X0 with velocity V0 and constant acceleration ACC is
relative to the point L, at time TM.")

(defparameter *uniform-motion-facts* '((> x0 0) (> v0 0) (> acc 0) (> l x0)))

(test earliest-root-with-symbolic-positive-parameters
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b *uniform-motion-facts*)
       (multiple-value-bind (root status) (ames.algebra:earliest-root b *uniform-motion-gap* 'tm)
         (is (eq :found status))
         (is (ames.maxima:equivalent-p
              b root '(/ (- (sqrt (+ (expt v0 2) (* 2 acc (- l x0)))) v0) acc)))
         ;; it is a root, and it lies after 0
         (is (ames.maxima:equivalent-p
              b (substitute-expressions (list (cons 'tm root)) *uniform-motion-gap*) 0))
         (is (eq :true (ames.algebra:decide b `(> ,root 0)))))))))

(test earliest-root-is-unknown-without-the-facts
  (call-with-bridge
   (lambda (b)
     (multiple-value-bind (status candidates) (ames.algebra:earliest-root b *uniform-motion-gap* 'tm)
       (is (eq :unknown status))
       (is (= 2 (length candidates)))
       (dolist (candidate candidates)
         (is (ames.maxima:equivalent-p
              b (substitute-expressions (list (cons 'tm candidate)) *uniform-motion-gap*) 0)))))))

(test earliest-root-when-the-point-is-behind
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> v0 0) (> acc 0) (> x0 l)))
       (is (eq :none (ames.algebra:earliest-root b *uniform-motion-gap* 'tm)))))))

(test earliest-root-with-numbers
  (call-with-bridge
   (lambda (b)
     (let ((gap (substitute-expressions '((x0 . 0) (v0 . 2) (acc . 2) (l . 3)) *uniform-motion-gap*)))
       ;; tm^2 + 2 tm - 3 = (tm - 1)(tm + 3)
       (is (equal '(1 :found) (multiple-value-list (ames.algebra:earliest-root b gap 'tm))))
       (is (eq :none (ames.algebra:earliest-root b gap 'tm :after 1)))
       (is (equal '(1 :found)
                  (multiple-value-list (ames.algebra:earliest-root b gap 'tm :after 1 :strictly nil))))
       (is (equal '(1 :found)
                  (multiple-value-list (ames.algebra:earliest-root b gap 'tm :after -2)))))
     (is (eq :none (ames.algebra:earliest-root b '(+ (expt tm 2) 1) 'tm)))
     (is (equal '(2 :found) (multiple-value-list (ames.algebra:earliest-root b '(- (* 3 tm) 6) 'tm))))
     (is (eq :none (ames.algebra:earliest-root b '(- (* 3 tm) 6) 'tm :after 3)))
     (let ((cubic '(* (- tm 1) (- tm 2) (- tm 3))))
       (is (equal '(1 :found) (multiple-value-list (ames.algebra:earliest-root b cubic 'tm))))
       (is (equal '(2 :found) (multiple-value-list (ames.algebra:earliest-root b cubic 'tm :after 1)))))
     ;; an irreducible cubic: isolated by Sturm sequences, given as a float
     (multiple-value-bind (root status) (ames.algebra:earliest-root b '(- (expt tm 3) tm 1) 'tm)
       (is (eq :found status))
       (is (typep root 'double-float))
       (is (< (abs (- (expt root 3) root 1)) 1d-6))))))

(test earliest-root-of-a-transcendental-expression-is-never-claimed
  (call-with-bridge
   (lambda (b)
     (multiple-value-bind (status candidates)
         (ames.algebra:earliest-root b '(- (sin tm) (/ 1 2)) 'tm)
       (is (eq :unknown status))
       (is (member '(/ pi 6) candidates :test (lambda (x y) (ames.maxima:equivalent-p b x y))))))))

(test earliest-root-rejects-bad-arguments
  (call-with-bridge
   (lambda (b)
     (signals ames.maxima:invalid-bridge-argument (ames.algebra:earliest-root b 'tm '(+ tm 1)))
     (signals ames.maxima:invalid-bridge-argument (ames.algebra:earliest-root b 'tm 'tm :after 'tm))
     (signals ames.maxima:untranslatable-expression (ames.algebra:earliest-root b '(< tm 1) 'tm)))))

;;; Autonomous ODEs

(test ode-with-constant-acceleration-has-a-closed-form
  (call-with-bridge
   (lambda (b)
     (let ((solution (ames.maxima:solve-autonomous-ode b 'c 's :initial-position 's0
                                                                :initial-velocity 'v0)))
       (is (eq :closed-form (ames.maxima:ode-solution-kind solution)))
       (is (ames.maxima:equivalent-p b (ames.maxima:ode-solution-position solution)
                                     '(+ s0 (* v0 tau) (/ (* c (expt tau 2)) 2))))
       (is (ames.maxima:equivalent-p b (ames.maxima:ode-solution-velocity solution)
                                     '(+ v0 (* c tau))))
       (is (ames.maxima:equivalent-p b (ames.maxima:ode-solution-speed-squared solution)
                                     '(+ (expt v0 2) (* 2 c (- s s0)))))))))

(test pendulum-ode-gives-the-energy-integral-only
  (call-with-bridge
   (lambda (b)
     (let ((solution (ames.maxima:solve-autonomous-ode b '(* (/ g r) (sin theta)) 'theta
                                                       :initial-position 'theta0
                                                       :initial-velocity 0)))
       (is (eq :energy-integral (ames.maxima:ode-solution-kind solution)))
       (is (null (ames.maxima:ode-solution-position solution)))
       (is (null (ames.maxima:ode-solution-velocity solution)))
       (is (ames.maxima:equivalent-p b (ames.maxima:ode-solution-speed-squared solution)
                                     '(/ (* 2 g (- (cos theta0) (cos theta))) r)))))))

(test harmonic-oscillator-ode-has-a-closed-form-with-cos-and-sin
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> k 0)))
       (let* ((solution (ames.maxima:solve-autonomous-ode b '(- (* k s)) 's :initial-position 's0
                                                                            :initial-velocity 'v0))
              (position (ames.maxima:ode-solution-position solution)))
         (is (eq :closed-form (ames.maxima:ode-solution-kind solution)))
         (is (member 'cos (flatten position)))
         (is (member 'sin (flatten position)))
         (is (ames.maxima:equivalent-p
              b position '(+ (* s0 (cos (* (sqrt k) tau))) (/ (* v0 (sin (* (sqrt k) tau))) (sqrt k)))))
         (is (ames.maxima:equivalent-p
              b (ames.maxima:ode-solution-velocity solution)
              '(- (* v0 (cos (* (sqrt k) tau))) (* s0 (sqrt k) (sin (* (sqrt k) tau)))))))))))

(test ode-rejects-what-is-not-an-autonomous-initial-value-problem
  (call-with-bridge
   (lambda (b)
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:solve-autonomous-ode b 'c 's :initial-position 's0))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:solve-autonomous-ode b '(* c tau) 's :initial-position 0 :initial-velocity 0))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:solve-autonomous-ode b 'c '(+ s 1) :initial-position 0 :initial-velocity 0)))))

;;; Numbers and LaTeX

(test numeric-values-under-parameter-values
  (call-with-bridge
   (lambda (b)
     (let ((value (ames.maxima:numeric-value b '(+ (sin x) (* 2 pi)) '((x . 1/2)))))
       (is (typep value 'double-float))
       (is (< (abs (- value (+ (sin 0.5d0) (* 2 pi)))) 1d-12)))
     (is (= 1.5d0 (ames.maxima:numeric-value b '(* (acc p :x) m) '(((acc p :x) . 3/4) (m . 2)))))
     (signals ames.maxima:numeric-evaluation-failed
       (ames.maxima:numeric-value b '(+ x y) '((x . 1))))
     (signals ames.maxima:numeric-evaluation-failed
       (ames.maxima:numeric-value b '(/ 1 x) '((x . 0))))
     (signals ames.maxima:numeric-evaluation-failed
       (ames.maxima:numeric-value b '(sqrt x) '((x . -1))))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:numeric-value b 'x '((x . "1")))))))

(test latex-through-maxima-tex
  (call-with-bridge
   (lambda (b)
     ;; the bridge writes no names of its own: the report's LaTeX names are the one set
     (let ((text (ames.maxima:latex b *wedge-normal-force* :name-function #'ames.report::latex-name)))
       (is (stringp text))
       (is (search "\\cos" text))
       (is (search "\\sin" text))
       (is (search "m_{p}" text))
       (is (search "\\over" text))
       (is (not (search "amesv" (string-downcase text)))))
     (let ((text (ames.maxima:latex b '(= (* m (acc particle :x)) theta0)
                                    :name-function #'ames.report::latex-name)))
       (is (search "\\theta" text))
       (is (search "\\mathrm{acc}_{particle,x}" text)))
     (signals ames.maxima:invalid-bridge-argument (ames.maxima:latex b 'x)))))

;;; Real square roots (radicals.lisp)

(defun complex-value (expression bindings)
  "The value of the arithmetic EXPRESSION at BINDINGS in complex arithmetic, with the
principal branch of every root (CL's SQRT and EXPT): a check of the arranged forms where
a radicand is negative, which EXPRESSION-VALUE (real only) does not evaluate."
  (labels ((value (x)
             (cond ((numberp x) x)
                   ((symbolp x) (or (cdr (assoc x bindings)) (error "unbound ~S" x)))
                   (t (let ((arguments (mapcar #'value (rest x))))
                        (ecase (first x)
                          (+ (apply #'+ arguments))
                          (- (apply #'- arguments))
                          (* (apply #'* arguments))
                          (/ (apply #'/ arguments))
                          (sqrt (sqrt (first arguments)))
                          (expt (expt (first arguments) (second arguments)))))))))
    (value expression)))

(defun radicands (expression)
  "The radicands of the square roots in EXPRESSION."
  (cond ((atom expression) '())
        ((ames.algebra::radical-exponent expression)
         (cons (second expression) (radicands (second expression))))
        (t (mapcan #'radicands (rest expression)))))

(test real-radicals-write-real-products-with-real-roots
  "With x < 0 < p and y < 0: sqrt(x) sqrt(y) p is -sqrt(-x) sqrt(-y) p, sqrt(x)/sqrt(y) is
sqrt(-x)/sqrt(-y), and a product that is not real (sqrt(x) p) or has no negative radicand
is left alone. The value is the same at points satisfying the facts (complex arithmetic,
principal roots), and every radicand left is proven >= 0 in the rewritten real forms."
  (let ((facts '((< x 0) (< y (- 1)) (> p 0)))
        (points (loop for (x y p) in '((-1/2 -3 2) (-2 -5/4 1/3) (-7 -2 5))
                      collect (list (cons 'x (float x 1d0)) (cons 'y (float y 1d0))
                                    (cons 'p (float p 1d0))))))
    (call-with-bridge
     (lambda (b)
       (ames.maxima:with-assumptions (b facts)
         (dolist (case '(((* p (sqrt x) (sqrt y)) :real)
                         ((/ (sqrt x) (sqrt (+ y 1))) :real)
                         ((+ 1 (/ (* 3 (expt x 3/2)) (sqrt y))) :real)
                         ((* p (sqrt x)) :unchanged)
                         ((* (sqrt p) (sqrt (+ p 1))) :unchanged)))
           (destructuring-bind (form kind) case
             (let ((rewritten (ames.algebra:real-radicals b form)))
               (is (every (lambda (point)
                            (< (abs (- (complex-value form point) (complex-value rewritten point)))
                               1d-9))
                          points)
                   "~S became ~S, of another value" form rewritten)
               (if (eq kind :unchanged)
                   (is (equal form rewritten) "~S became ~S" form rewritten)
                   (is (every (lambda (r) (ames.algebra:holds-p b `(>= ,r 0))) (radicands rewritten))
                       "~S became ~S, still with a negative radicand" form rewritten))))))
       ;; simplified, the first is Maxima's -p sqrt(x y)
       (ames.maxima:with-assumptions (b facts)
         (let ((simplified (ames.algebra:simplify-real b '(* p (sqrt x) (sqrt y)))))
           (is (every (lambda (point)
                        (< (abs (- (complex-value simplified point)
                                   (- (* (cdr (assoc 'p point))
                                         (sqrt (* (cdr (assoc 'x point)) (cdr (assoc 'y point))))))))
                           1d-9))
                      points)
               "simplified to ~S" simplified)))))))
