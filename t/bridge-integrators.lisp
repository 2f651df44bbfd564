;;;; t/bridge-integrators.lisp -- tests of the special functions of the algebra and the bridge's integrators.
;;;;
;;;; Travel times (integrals.lisp, quadrature.lisp), linear ODEs (linear-ode.lisp),
;;;; trigonometric roots (trig-roots.lisp). Closed forms are compared by meaning
;;;; (EQUIVALENT-P) or by value at several parameter values, never as printed text.

(in-package #:ames.tests)

(def-suite bridge-integrators :in bridge
  :description "Hyperbolic, elliptic and Jacobi functions; travel times; linear ODEs;
earliest roots of sinusoids.")

(in-suite bridge-integrators)

(defun close-to-p (x y &optional (tolerance 1d-9))
  "True when the reals X and Y agree within TOLERANCE, relatively (absolutely near 0)."
  (<= (abs (- x y)) (* tolerance (max 1 (abs x) (abs y)))))

(defun same-at-points-p (b x y points &optional (tolerance 1d-9))
  "True when the expressions X and Y have the same value (by Maxima's float) at every
alist of POINTS."
  (every (lambda (point)
           (close-to-p (ames.maxima:numeric-value b x point) (ames.maxima:numeric-value b y point)
                       tolerance))
         points))

;;; The special functions

(defparameter *special-function-samples*
  '((sinh 7/10) (cosh -3/2) (tanh 2) (asinh -5) (acosh 3) (atanh 1/3)
    (elliptic-f 1/2 3/10) (elliptic-f 2 1/2) (elliptic-f 4 1/2) (elliptic-f -7/2 -2)
    (elliptic-f 1/2 5/2) (elliptic-f 3/10 1) (elliptic-k 3/10) (elliptic-k -4)
    (elliptic-e 1/2 3/10) (elliptic-e 5 9/10)
    (jacobi-sn 1/2 3/10) (jacobi-cn 7/2 9/10) (jacobi-dn 2 1/2) (jacobi-am 1/2 99/100)
    (jacobi-sn 3/2 5/2) (jacobi-cn 3/2 5/2) (jacobi-am 3/2 5/2)
    (jacobi-am 1 1) (jacobi-sn 4 0))
  "One application of each new operator (several for the elliptic and Jacobi ones,
across their parameter ranges), at rational arguments. Not E(phi | m) for m > 1:
Maxima 5.46's float() makes it complex even where it is real (elliptic_e(1/4, 3)).")

(test special-functions-cross-the-bridge-and-back
  (call-with-bridge
   (lambda (b)
     (dolist (operator '(sinh cosh tanh asinh acosh atanh elliptic-k))
       (is (equal (list operator 'x) (ames.maxima:simplify b (list operator 'x)))))
     (dolist (operator '(elliptic-f elliptic-e jacobi-sn jacobi-cn jacobi-dn jacobi-am))
       (is (equal (list operator 'x 'm) (ames.maxima:simplify b (list operator 'x 'm))))
       (is (ames.maxima:equivalent-p b (list operator '(+ x 1) 'm) (list operator '(+ 1 x) 'm))))
     ;; Maxima's own simplifications come back in the algebra
     (is (ames.maxima:equivalent-p b '(jacobi-sn u 0) '(sin u)))
     (is (ames.maxima:equivalent-p b '(elliptic-f phi 0) 'phi))
     (is (ames.maxima:equivalent-p b '(elliptic-k 0) '(/ pi 2)))
     ;; a wrong number of arguments never reaches Maxima
     (signals ames.maxima:untranslatable-expression (ames.maxima:simplify b '(elliptic-f x)))
     (signals ames.maxima:untranslatable-expression (ames.maxima:simplify b '(sinh x y))))))

(defun maxima-float (b expression)
  "Maxima's own float() of the constant EXPRESSION (not NUMERIC-VALUE, which evaluates
elliptic and Jacobi functions in Lisp)."
  (ames.maxima::maxima-request b (ames.maxima::mcall "$FLOAT" (ames.maxima::to-mx b expression))))

(test special-functions-lisp-values-match-maxima-float
  (call-with-bridge
   (lambda (b)
     (dolist (sample *special-function-samples*)
       (let ((lisp (expression-value sample))
             (maxima (maxima-float b sample)))
         (is (and lisp (realp maxima) (close-to-p lisp maxima 1d-12))
             "~S: Lisp ~S, Maxima ~S" sample lisp maxima)))
     ;; where Maxima 5.46's float() is wrong, Lisp agrees with what Maxima gets right:
     ;; am(u|m) beyond K(m) is not asin(sn) (Maxima's answer) but has sin = sn, cos = cn
     (let ((am (expression-value '(jacobi-am 13/2 99/100))))
       (is (> am (/ pi 2)))
       (is (close-to-p (sin am) (maxima-float b '(jacobi-sn 13/2 99/100)) 1d-12))
       ;; (Maxima's cn is good to about 1e-12 here; its elliptic_f(am) gives 13/2 back)
       (is (close-to-p (cos am) (maxima-float b '(jacobi-cn 13/2 99/100)) 1d-10))
       (is (close-to-p 13/2 (maxima-float b `(elliptic-f ,am 99/100)) 1d-14))
       (is (close-to-p am (ames.maxima:numeric-value b '(jacobi-am u 99/100) '((u . 13/2))) 1d-15)))
     ;; dn(u|m) for m > 1 is cn(u sqrt(m) | 1/m), real (Maxima adds an imaginary residue)
     (is (close-to-p (expression-value '(jacobi-dn 3/2 5/2))
                     (maxima-float b '(jacobi-cn (* 3/2 (sqrt 5/2)) 2/5)) 1d-12))
     (is (realp (ames.maxima:numeric-value b '(jacobi-dn 3/2 5/2) '()))))))

(test special-function-identities-in-lisp
  (flet ((value (expression) (expression-value expression)))
    (is (close-to-p (value '(elliptic-k 0)) (/ pi 2) 1d-14))
    (is (close-to-p (value '(elliptic-e 1.2d0 0)) 1.2d0 1d-14))
    (is (close-to-p (value '(jacobi-cn 0.8d0 1)) (/ (cosh 0.8d0)) 1d-14))
    (dolist (m '(0.1d0 0.5d0 0.95d0))
      ;; am inverts F; F is quasi-periodic
      (is (close-to-p (value `(jacobi-am (elliptic-f 1.1d0 ,m) ,m)) 1.1d0 1d-12))
      (is (close-to-p (value `(elliptic-f (+ 1.1d0 pi) ,m))
                      (+ (value `(elliptic-f 1.1d0 ,m)) (* 2 (value `(elliptic-k ,m)))) 1d-12))
      ;; sn^2 + cn^2 = 1, dn^2 + m sn^2 = 1
      (is (close-to-p (+ (expt (value `(jacobi-sn 2.3 ,m)) 2) (expt (value `(jacobi-cn 2.3 ,m)) 2)) 1 1d-13))
      (is (close-to-p (+ (expt (value `(jacobi-dn 2.3 ,m)) 2) (* m (expt (value `(jacobi-sn 2.3 ,m)) 2))) 1 1d-13)))
    ;; where the value is not real, there is none
    (dolist (expression '((elliptic-k 1) (elliptic-k 2) (acosh 1/2) (atanh 1) (atanh -2)
                          (elliptic-f 2 3) (elliptic-f (/ pi 2) 1) (jacobi-sn 1 -1)))
      (is (null (value expression)) "~S has a value" expression))))

(test special-functions-in-decisions
  (call-with-bridge
   (lambda (b)
     ;; the numeric witnesses skip what they cannot evaluate instead of failing
     (is (member (ames.algebra:decide b '(> (sinh x) 0)) '(:true :unknown)))
     (ames.maxima:with-assumptions (b '((> x 0) (< x (acosh 3))))
       (is (member (ames.algebra:decide b '(> (+ (elliptic-k 1/2) (sinh x)) 0)) '(:true :unknown)))))))

;;; Travel times

(defun travel (b facts speed-squared from to &rest keys)
  "TRAVEL-TIME's values for SPEED-SQUARED in S, under FACTS."
  (ames.maxima:with-assumptions (b facts)
    (apply #'ames.algebra:travel-time b speed-squared 's from to keys)))

(test travel-time-polynomial-energies
  (call-with-bridge
   (lambda (b)
     ;; uniform acceleration from rest, either way, and with an initial speed
     (dolist (case '(((* 2 a s) 0 l) ((* 2 a s) l 0) ((* 2 a (- l s)) 0 l)))
       (multiple-value-bind (time status verification)
           (apply #'travel b '((> a 0) (> l 0)) case)
         (is (eq :closed-form status))
         (is (eq :symbolic verification))
         (is (ames.maxima:equivalent-p b time '(sqrt (/ (* 2 l) a))))))
     (is (ames.maxima:equivalent-p
          b (travel b '((> a 0) (> l 0) (> v0 0)) '(+ (expt v0 2) (* 2 a s)) 0 'l)
          '(/ (- (sqrt (+ (expt v0 2) (* 2 a l))) v0) a)))
     ;; harmonic motion: a quarter and a half period from rest at the amplitude
     (let ((facts '((> w 0) (> a 0))) (energy '(* (expt w 2) (- (expt a 2) (expt s 2)))))
       (is (ames.maxima:equivalent-p b (travel b facts energy 'a 0) '(/ pi (* 2 w))))
       (is (ames.maxima:equivalent-p b (travel b facts energy 'a '(- a)) '(/ pi w))))
     ;; harmonic motion from the centre with speed v0: asin form
     (let ((time (travel b '((> w 0) (> v0 0) (> d 0) (< d (/ v0 w)))
                         '(- (expt v0 2) (* (expt w 2) (expt s 2))) 0 'd)))
       (is (ames.maxima:equivalent-p b time '(/ (asin (/ (* w d) v0)) w))))
     ;; repulsive: asinh and acosh forms
     (is (ames.maxima:equivalent-p
          b (travel b '((> w 0) (> a 0) (> v0 0)) '(+ (expt v0 2) (* (expt w 2) (expt s 2))) 0 'a)
          '(/ (asinh (/ (* a w) v0)) w)))
     (is (ames.maxima:equivalent-p
          b (travel b '((> w 0) (> a 0) (> l a)) '(* (expt w 2) (- (expt s 2) (expt a 2))) 'a 'l)
          '(/ (acosh (/ l a)) w))))))

(test travel-time-on-a-sphere-is-the-thesis-time
  ;; a particle starting at rest at theta0 from the top of a sphere of radius r leaves it
  ;; where cos(theta) = 2/3 cos(theta0); s = r theta, w^2 = 2 g r (cos theta0 - cos theta)
  (call-with-bridge
   (lambda (b)
     (let ((energy '(* 2 g r (- (cos theta0) (cos (/ s r)))))
           (from '(* r theta0))
           (to '(* r (acos (* 2/3 (cos theta0))))))
       (multiple-value-bind (time status verification)
           (travel b '((> g 0) (> r 0) (> theta0 0) (< theta0 (/ pi 2))) energy from to)
         (is (eq :closed-form status))
         (is (eq :numeric verification))
         (is (member 'elliptic-k (flatten time)))
         (let ((values '((g . 981/100) (r . 1) (theta0 . 1/10))))
           (is (close-to-p 0.9071d0 (ames.maxima:numeric-value b time values) 1d-4))
           (is (close-to-p (ames.maxima:numeric-value b time values)
                           (ames.algebra:numeric-travel-time b energy 's from to values) 1d-9)))
         (dolist (values '(((g . 2) (r . 3) (theta0 . 1)) ((g . 50) (r . 1/10) (theta0 . 1/100))))
           (is (close-to-p (ames.maxima:numeric-value b time values)
                           (ames.algebra:numeric-travel-time b energy 's from to values) 1d-8))))))))

(test travel-time-of-a-pendulum-swing
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> g 0) (> l 0) (> theta0 0) (< theta0 (/ pi 2))))
           (energy '(* 2 (/ g l) (- (cos s) (cos theta0))))
           (quarter '(* (sqrt (/ l g)) (elliptic-k (expt (sin (/ theta0 2)) 2))))
           (points '(((g . 981/100) (l . 2) (theta0 . 7/10)) ((g . 1) (l . 1) (theta0 . 3/2))
                     ((g . 3) (l . 1/5) (theta0 . 1/50)))))
       ;; a quarter period from rest at theta0 down to the bottom: K(sin^2(theta0/2)) sqrt(l/g)
       (is (same-at-points-p b (travel b facts energy 'theta0 0) quarter points))
       ;; the same swing one turn further round (the well centred on 2 pi), and back up
       (is (same-at-points-p b (travel b facts energy '(+ (* 2 pi) theta0) '(* 2 pi)) quarter points))
       (is (same-at-points-p b (travel b facts energy 0 '(- theta0)) quarter points))))))

(test travel-time-of-a-revolution-and-a-fall
  (call-with-bridge
   (lambda (b)
     ;; going over the top: half a revolution takes 2 K(4 g / (l w0^2)) / w0
     (is (same-at-points-p b (travel b '((> g 0) (> l 0) (> w0 0) (> (* l (expt w0 2)) (* 4 g)))
                                  '(+ (expt w0 2) (* 2 (/ g l) (- (cos s) 1))) 0 'pi)
                        '(/ (* 2 (elliptic-k (/ (* 4 g) (* l (expt w0 2))))) w0)
                        '(((g . 981/100) (l . 2) (w0 . 5)) ((g . 1) (l . 1) (w0 . 21/10)))))
     ;; two bodies falling together from rest at distance s0, to s0/2
     (multiple-value-bind (time status)
         (travel b '((> c 0) (> s0 0)) '(* c (- (/ 1 s) (/ 1 s0))) 's0 '(/ s0 2))
       (is (eq :closed-form status))
       (is (ames.maxima:equivalent-p b time '(* (+ 1/2 (/ pi 4)) (sqrt (/ (expt s0 3) c)))))))))

(test travel-time-without-closed-form
  (call-with-bridge
   (lambda (b)
     (is (equal '(nil :no-closed-form) (multiple-value-list (travel b '() '(+ 1 (expt s 4)) 0 1))))
     (signals ames.maxima:invalid-bridge-argument (travel b '() '(* 2 s) 0 '(+ s 1)))
     (signals ames.maxima:invalid-bridge-argument (travel b '() '(* 2 s) 0 1 :direction 2))
     (signals ames.maxima:invalid-bridge-argument
       (ames.algebra:travel-time b '(* 2 s) '(+ s 1) 0 1)))))

(test numeric-travel-times
  (call-with-bridge
   (lambda (b)
     (is (close-to-p (sqrt 3d0) (ames.algebra:numeric-travel-time b '(* 2 a s) 's 0 'l '((a . 2) (l . 3))) 1d-12))
     ;; rest at both ends: half a period
     (is (close-to-p (/ pi 3) (ames.algebra:numeric-travel-time
                               b '(* 9 (- 4 (expt s 2))) 's 2 -2 '()) 1d-12))
     (is (zerop (ames.algebra:numeric-travel-time b '(* 2 s) 's 1 1 '())))
     (signals ames.maxima:numeric-evaluation-failed
       (ames.algebra:numeric-travel-time b '(- 1 (expt s 2)) 's 0 2 '()))
     (signals ames.maxima:numeric-evaluation-failed
       (ames.algebra:numeric-travel-time b '(* 2 s) 's 0 'l '()))
     (signals ames.maxima:invalid-bridge-argument
       (ames.algebra:numeric-travel-time b '(* 2 s) 's 0 1 '((a . "one")))))))

;;; Linear ODEs with constant coefficients

(defparameter *spring-facts* '((> k 0) (> m 0) (> v0 0) (> g 0) (> l0 0)))

(defun linear-solution (b accelerations positions velocities initial-positions initial-velocities)
  "SOLVE-LINEAR-ODES's values under *SPRING-FACTS*."
  (ames.maxima:with-assumptions (b *spring-facts*)
    (ames.algebra:solve-linear-odes b accelerations positions velocities
                                   initial-positions initial-velocities)))

(test linear-ode-bumper
  ;; a block meets a bumper spring at x = 0 with speed v0: x = (v0/omega) sin(omega tau)
  (call-with-bridge
   (lambda (b)
     (multiple-value-bind (positions velocities verification)
         (linear-solution b '((- (* (/ k m) x))) '(x) '(v) '(0) '(v0))
       (is (eq :symbolic verification))
       (is (ames.maxima:equivalent-p b (cdr (assoc 'x positions))
                                     '(* (/ v0 (sqrt (/ k m))) (sin (* (sqrt (/ k m)) tau)))))
       (is (ames.maxima:equivalent-p b (cdr (assoc 'v velocities))
                                     '(* v0 (cos (* (sqrt (/ k m)) tau)))))))))

(test linear-ode-spring-with-rest-length-and-gravity
  (call-with-bridge
   (lambda (b)
     ;; horizontal: released at rest from x0, oscillates about l0
     (let ((x (cdr (first (linear-solution b '((- (* (/ k m) (- x l0)))) '(x) '(v) '(x0) '(0))))))
       (is (ames.maxima:equivalent-p b x '(+ l0 (* (- x0 l0) (cos (* (sqrt (/ k m)) tau)))))))
     ;; vertical: released at rest at the rest length, it oscillates about l0 - m g / k
     (let ((x (cdr (first (linear-solution b '((- (- (* (/ k m) (- x l0))) g)) '(x) '(v) '(l0) '(0))))))
       (is (ames.maxima:equivalent-p
            b x '(- l0 (* (/ (* m g) k) (- 1 (cos (* (sqrt (/ k m)) tau)))))))))))

(test linear-ode-two-masses-and-a-spring
  ;; equal masses joined by a spring of rest length l0; the first is pushed with v0:
  ;; the centre of mass moves uniformly, the stretch oscillates at sqrt(2k/m)
  (call-with-bridge
   (lambda (b)
     (multiple-value-bind (positions velocities)
         (linear-solution b '((* (/ k m) (- x2 x1 l0)) (- (* (/ k m) (- x2 x1 l0))))
                          '(x1 x2) '(v1 v2) '(0 l0) '(v0 0))
       (let ((x1 (cdr (assoc 'x1 positions))) (x2 (cdr (assoc 'x2 positions)))
             (omega '(sqrt (/ (* 2 k) m))))
         (is (ames.maxima:equivalent-p b `(/ (+ ,x1 ,x2) 2) '(+ (/ l0 2) (/ (* v0 tau) 2))))
         (is (ames.maxima:equivalent-p b `(- ,x2 ,x1 l0) `(- (* (/ v0 ,omega) (sin (* ,omega tau))))))
         (is (ames.maxima:equivalent-p b (cdr (assoc 'v1 velocities))
                                       (ames.maxima:simplify b `(+ (/ v0 2) (* (/ v0 2) (cos (* ,omega tau))))))))))))

(test linear-ode-free-fall-and-damping
  (call-with-bridge
   (lambda (b)
     (let ((x (cdr (first (linear-solution b '((- g)) '(x) '(v) '(l0) '(v0))))))
       (is (ames.maxima:equivalent-p b x '(- (+ l0 (* v0 tau)) (/ (* g (expt tau 2)) 2)))))
     ;; a damper: the discriminant's sign is not decided, so Maxima's question comes back
     (signals ames.maxima:maxima-question
       (linear-solution b '((- (- (* (/ k m) x)) (* c v))) '(x) '(v) '(0) '(v0)))
     ;; strongly damped under an assumption that decides it: still verified
     (ames.maxima:with-assumptions (b '((> c 0) (> (* c c m) (* 4 k))))
       (multiple-value-bind (positions velocities verification)
           (linear-solution b '((- (- (* (/ k m) x)) (* c v))) '(x) '(v) '(0) '(v0))
         (declare (ignore velocities))
         (is (member verification '(:symbolic :numeric)))
         (is (not (free-of-p 'tau (cdr (first positions))))))))))

(test linear-ode-refuses-what-is-not-linear
  (call-with-bridge
   (lambda (b)
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((- (* (/ k m) (sin x)))) '(x) '(v) '(0) '(v0)))
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((* x v)) '(x) '(v) '(0) '(v0)))
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((- (* k tau))) '(x) '(v) '(0) '(v0)))
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((- x) (- y)) '(x y) '(v) '(0 0) '(0 0)))
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((- x)) '(x) '(x) '(0) '(0)))
     (signals ames.maxima:invalid-bridge-argument
       (linear-solution b '((- x)) '(x) '(v) '(v) '(0))))))

;;; Earliest roots of sinusoids

(defun trigonometric-root (b expression &rest keys)
  "EARLIEST-TRIGONOMETRIC-ROOT's values for EXPRESSION in TAU, with k, m, v0, w, l, a > 0."
  (ames.maxima:with-assumptions (b '((> k 0) (> m 0) (> v0 0) (> w 0) (> l 0) (> a 0)))
    (apply #'ames.algebra:earliest-trigonometric-root b expression 'tau keys)))

(defmacro is-root (b expected expression &rest keys)
  "Check that the earliest root of EXPRESSION is found, and equal to EXPECTED."
  `(multiple-value-bind (root status) (trigonometric-root ,b ,expression ,@keys)
     (is (eq :found status) "~S: ~S" ,expression root)
     (when (eq status :found)
       (is (ames.maxima:equivalent-p ,b root ,expected) "~S: ~S, not ~S" ,expression root ,expected))))

(test trigonometric-roots-of-springs
  (call-with-bridge
   (lambda (b)
     ;; a bumper's compression returns to 0 after half a period
     (is-root b '(/ pi w) '(* (/ v0 w) (sin (* w tau))))
     ;; ... and is 0 at the start, when the start counts
     (is-root b 0 '(* (/ v0 w) (sin (* w tau))) :strictly nil)
     ;; from a later start
     (is-root b '(/ pi w) '(* (/ v0 w) (sin (* w tau))) :after '(/ pi (* 2 w)))
     (is-root b '(/ (* 2 pi) w) '(* (/ v0 w) (sin (* w tau))) :after '(/ pi w))
     ;; L - L cos(w tau) reaches L/2 at pi/(3w)
     (is-root b '(/ pi (* 3 w)) '(- (- l (* l (cos (* w tau)))) (/ l 2)))
     ;; a phase: cos + sin = sqrt 2 cos(x - pi/4) vanishes first at 3 pi/4
     (is-root b '(/ (* 3 pi) (* 4 w)) '(+ (cos (* w tau)) (sin (* w tau))))
     (is-root b '(/ pi (* 4 w)) '(- (cos (* w tau)) (sin (* w tau))))
     (is-root b '(/ pi w) '(+ 1 (cos (* w tau)) (sin (* w tau))))
     ;; a negative frequency
     (is-root b '(/ pi w) '(* v0 (sin (* (- w) tau)))))))

(test trigonometric-roots-not-reached-or-undecided
  (call-with-bridge
   (lambda (b)
     ;; L - L cos never reaches 3L
     (is (eq :none (trigonometric-root b '(- (- l (* l (cos (* w tau)))) (* 3 l)))))
     ;; reaching a: only if a <= 2L, which the facts leave open
     (multiple-value-bind (status fact) (trigonometric-root b '(- (- l (* l (cos (* w tau)))) a))
       (is (eq :unknown status))
       (is (and (consp fact) (eq '<= (first fact))))
       ;; with a < 2L (from which it follows) the root is found
       (ames.maxima:with-assumptions (b '((< a (* 2 l))))
         (multiple-value-bind (root status) (trigonometric-root b '(- (- l (* l (cos (* w tau)))) a))
           (is (eq :found status))
           (is (same-at-points-p b root '(/ (acos (/ (- l a) l)) w)
                              '(((a . 1) (l . 3) (w . 2)) ((a . 59/10) (l . 3) (w . 1/2))))))))
     ;; two frequencies
     (is (eq :unknown (trigonometric-root b '(+ (cos (* w tau)) (cos (* 2 w tau))))))
     ;; a polynomial goes to EARLIEST-ROOT
     (is-root b '(/ l v0) '(- (* v0 tau) l)))))

;;; Positions over time on a circle

(test position-over-time-of-a-pendulum-and-the-sphere
  (call-with-bridge
   (lambda (b)
     ;; a pendulum released at theta0 is back at theta0 after a full period 4 K sqrt(l/g),
     ;; passes the bottom after a quarter, and is at -theta0 after half
     (ames.maxima:with-assumptions (b '((> g 0) (> l 0) (> theta0 0) (< theta0 (/ pi 2))))
       (multiple-value-bind (theta w status)
           (ames.algebra:position-over-time b '(* 2 (/ g l) (- (cos s) (cos theta0))) 's 'theta0)
         (declare (ignore w))
         (is (eq :numeric status))
         (let ((quarter '(* (sqrt (/ l g)) (elliptic-k (expt (sin (/ theta0 2)) 2))))
               (values '((g . 981/100) (l . 2) (theta0 . 7/10))))
           (flet ((at (time) (ames.maxima:numeric-value
                              b (substitute-expressions (list (cons 'tau time)) theta) values)))
             (is (close-to-p 0.7d0 (at 0) 1d-12))
             (is (close-to-p 0d0 (at quarter) 1d-9))
             (is (close-to-p -0.7d0 (at `(* 2 ,quarter)) 1d-9))
             (is (close-to-p 0.7d0 (at `(* 4 ,quarter)) 1d-9))))))
     ;; the sphere: at the travel time it is where it leaves the sphere
     (ames.maxima:with-assumptions (b '((> g 0) (> r 0) (> theta0 0) (< theta0 (/ pi 2))))
       (let ((energy '(* 2 g r (- (cos theta0) (cos (/ s r)))))
             (values '((g . 981/100) (r . 1) (theta0 . 1/10))))
         (multiple-value-bind (s w) (ames.algebra:position-over-time b energy 's '(* r theta0))
           (let ((time (ames.algebra:travel-time b energy 's '(* r theta0) '(* r (acos (* 2/3 (cos theta0)))))))
             (is (close-to-p (ames.maxima:numeric-value b '(acos (* 2/3 (cos theta0))) values)
                             (ames.maxima:numeric-value b (substitute-expressions (list (cons 'tau time)) s) values)
                             1d-9))
             ;; and its speed there is the energy integral's
             (is (close-to-p (ames.maxima:numeric-value b (substitute-expressions (list (cons 'tau time)) w) values)
                             (sqrt (* 2 9.81d0 (- (cos 0.1d0) (* 2/3 (cos 0.1d0)))))
                             1d-9)))))))))

(test position-over-time-going-round
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> g 0) (> l 0) (> w0 0) (> (* l (expt w0 2)) (* 4 g))))
       (let ((energy '(+ (expt w0 2) (* 2 (/ g l) (- (cos s) 1)))))
         (multiple-value-bind (theta w status) (ames.algebra:position-over-time b energy 's 0 :direction -1)
           (is (eq :numeric status))
           ;; going backwards, it is at -pi after the half-revolution time
           (let ((half (ames.algebra:travel-time b energy 's 0 '(- pi)))
                 (values '((g . 981/100) (l . 2) (w0 . 5))))
             (is (close-to-p (- pi) (ames.maxima:numeric-value
                                     b (substitute-expressions (list (cons 'tau half)) theta) values)
                             1d-9))
             (is (close-to-p -5d0 (ames.maxima:numeric-value
                                   b (substitute-expressions '((tau . 0)) w) values) 1d-12))))
         ;; not at rest: the direction is needed
         (signals ames.maxima:invalid-bridge-argument
           (ames.algebra:position-over-time b energy 's 0))
         ;; another shape
         (is (equal '(nil :no-closed-form)
                    (multiple-value-list (ames.algebra:position-over-time b '(+ 1 (expt s 4)) 's 0 :direction 1)))))))))
