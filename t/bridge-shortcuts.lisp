;;;; t/bridge-shortcuts.lisp -- tests of the bridge's shortcuts: each must give the answer the long way gives.
;;;;
;;;; Numeric witnesses (an inequality seen to hold and to fail at admissible points is
;;;; undecided), balls that enclose exact values, the lazy sign() requests, the cached
;;;; order substitution, the shared simplification candidates and the ode2 that is not
;;;; asked. Each shortcut is compared with what Maxima says without it.

(in-package #:ames.tests)

(def-suite bridge-shortcuts :in all-tests
  :description "The Maxima bridge's shortcuts give the answers of the long way.")

(in-suite bridge-shortcuts)

(defun round-trips (bridge)
  "How many round trips BRIDGE has made to Maxima."
  (getf (ames.maxima:bridge-statistics bridge) :maxima-calls))

(defun ball-holds-p (ball value)
  "True when the real VALUE lies in BALL."
  (<= (abs (- value (ames.algebra::ball-center ball))) (ames.algebra::ball-radius ball)))

(test balls-enclose-values-and-refuse-what-is-undefined
  (flet ((ball (expression &rest point) (ames.algebra::expression-ball expression point)))
    (is (ball-holds-p (ball '(+ 1 (sqrt 2))) (+ 1 (sqrt 2d0))))
    (is (ball-holds-p (ball '(* (sin x) (cos x)) '(x . 0.7d0)) (* (sin 0.7d0) (cos 0.7d0))))
    (is (ball-holds-p (ball '(/ 1 (- x 1/3)) '(x . 0.5d0)) 6d0))
    (is (ball-holds-p (ball '(atan y x) '(y . 1d0) '(x . -1d0)) (* 3/4 pi)))
    (is (ball-holds-p (ball '(expt x 3/2) '(x . 4d0)) 8d0))
    ;; a box of points: every value in it is enclosed
    (let ((box (ball '(* x (- 1 x)) (cons 'x (ames.algebra::make-ball 0.5d0 0.25d0)))))
      (dolist (x '(0.25d0 0.4d0 0.5d0 0.75d0))
        (is (ball-holds-p box (* x (- 1 x))))))
    ;; undefined or not real somewhere: no ball
    (is (null (ball '(sqrt x) '(x . -1d0))))
    (is (null (ball '(/ 1 x) '(x . 0d0))))
    (is (null (ball '(log x) '(x . 0d0))))
    (is (null (ball '(asin x) '(x . 2d0))))
    (is (null (ball '(tan x) (cons 'x (/ pi 2)))))
    ;; a box across the negative x axis, where atan2 jumps: no ball (at a point on it,
    ;; y exactly 0, the angle is pi, as Maxima's atan2(0, -1))
    (is (null (ball '(atan y x) (cons 'y (ames.algebra::make-ball 0d0 1d-3)) '(x . -1d0))))
    (is (ball-holds-p (ball '(atan y x) '(y . 0d0) '(x . -1d0)) pi))
    (is (null (ball '(exp x) '(x . 1d6))))
    (is (null (ball '(/ 1 x) (cons 'x (ames.algebra::make-ball 0.1d0 0.2d0)))))))

(test an-inequality-seen-both-ways-is-undecided-at-once
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 0) (< x 1) (> k 0)))
       (is (ames.algebra:sign-varies-p b '(- x 1/2)))
       (is (not (ames.algebra:sign-varies-p b '(* x (- 1 x)))))
       (is (not (ames.algebra:sign-varies-p b 'k)))
       ;; only is() is asked: the strategies, which would all fail, are left out
       (let ((before (round-trips b)))
         (is (eq :unknown (ames.algebra:decide b '(> (* k (- x 1/2)) 0))))
         (is (= 1 (- (round-trips b) before))))
       ;; true everywhere, or with no witness found: the long way still decides
       (is (eq :true (ames.algebra:decide b '(> (* k x (- 1 x)) 0))))
       (is (eq :false (ames.algebra:decide b '(< (* k x (- 1 x)) 0))))))))

(test witnesses-never-contradict-a-decided-relation
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0) (> h 0) (> a 0) (< a (/ pi 2))
                                        (> bb 0) (< bb h) (> l2 0) (> l1 l2)))
       (dolist (relation '((> (+ (expt (sin a) 2) (expt (cos a) 2)) 1/2)
                           (> (* bb (- h bb)) 0)
                           (< (- bb h) 0)
                           (> (* m g (cos a)) 0)
                           (>= (expt (- (sin a) (cos a)) 2) 0)
                           (> (+ (* m g (expt (- l1 l2) 2)) (* h (- l1 l2))) 0)
                           (< (/ (- (* m g (sin a))) (+ m h)) 0)))
         (is (eq :true (ames.algebra:decide b relation)) "~S is not decided true" relation)
         (is (not (ames.algebra::witnessed-both-ways-p b relation))
             "~S has witnesses both ways although it holds" relation))))))

(test an-equation-whose-sides-cross-is-undecided-at-once
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> a 0) (< a (/ pi 2)) (> bb 0)))
       (let ((before (round-trips b)))
         (is (eq :unknown (ames.algebra:decide b '(= (* bb (cos a)) (* bb (sin a))))))
         (is (= 1 (- (round-trips b) before))))
       (is (eq :true (ames.algebra:decide b '(= (+ (expt (sin a) 2) (expt (cos a) 2)) 1))))
       (is (eq :false (ames.algebra:decide b '(= (* bb (sin a)) 0)))))))
  (call-with-bridge
    (lambda (b)
      ;; 1/x takes both signs but never 0: the segment between the witnesses crosses the
      ;; pole, so there is no shortcut, and the long way says never equal
      (ames.maxima:with-assumptions (b '((/= x 0)))
        (is (eq :false (ames.algebra:decide b '(= (/ 1 x) 0))))))))

(test a-segment-is-checked-piece-by-piece
  (let ((from '((x . 0.1d0) (y . 0.9d0)))
        (to '((x . 0.9d0) (y . 0.95d0))))
    (is (ames.algebra::continuous-and-admissible-between-p '(- x 1/2) '((< x y) (> x 0)) from to))
    ;; a fact that fails in between, a pole in between
    (is (not (ames.algebra::continuous-and-admissible-between-p '(- x 1/2) '((> (- x 1/2) 0) (> x 0))
                                                               from to)))
    (is (not (ames.algebra::continuous-and-admissible-between-p '(/ 1 (- x 1/2)) '((> x 0)) from to)))))

(test lazy-signs-agree-with-all-signs-at-once
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0) (> a 0) (< a (/ pi 2)) (> l1 l2)))
       (dolist (expression '((+ (expt x 2) 1) (- (expt x 2)) (- x y) (* m g (sin a))
                             (- (expt (sin a) 2) 1) (- l1 l2) (* (- l2 l1) m) 0
                             (+ (* 2 m l1) (- (* 2 m l2)))))
         (let ((form (ames.maxima::to-mx b expression)))
           (is (null (set-exclusive-or (ames.maxima::form-signs b form)
                                       (first (ames.maxima::forms-signs b (list form)))))
               "the signs of ~S differ" expression)))))))

(test the-order-substitution-names-its-excess-once
  (call-with-bridge
   (lambda (b)
     (let ((excess (ames.algebra::order-excess-name b 'l1)))
       (is (null (symbol-package excess)))
       (is (eq excess (ames.algebra::order-excess-name b 'l1)))
       (is (not (eq excess (ames.algebra::order-excess-name b 'l2)))))
     (ames.maxima:with-assumptions (b '((> mb 0) (> g 0) (> f 0) (> l2 0) (> l1 l2) (> l3 0)))
       ;; the rewritten relation is asked again with the same names: only the scope's own
       ;; two round trips are made the second time
       (let* ((relation '(> (+ (* mb g (expt (- l1 l2) 2)) (* f l3 (- l1 l2))) 0))
              (first-time (let ((before (round-trips b)))
                            (is (eq :true (ames.algebra::decide-by-order-substitution b relation)))
                            (- (round-trips b) before)))
              (second-time (let ((before (round-trips b)))
                             (is (eq :true (ames.algebra::decide-by-order-substitution b relation)))
                             (- (round-trips b) before))))
         (is (< second-time first-time))
         (is (<= second-time 2)))))))

(test the-simplest-form-is-the-smallest-candidate
  (call-with-bridge
   (lambda (b)
     (dolist (expression '((+ (expt (sin a) 2) (expt (cos a) 2) x)
                           (/ (- (expt x 2) 1) (- x 1))
                           (* (sqrt (- 9 (* 4 (expt (cos th) 2)))) r)
                           (- (* 2 (sin u) (cos u)) (sin (* 2 u)))
                           (+ (/ l3 2) (* (/ 1 2) (- l1 l2)))))
       (let* ((form (ames.maxima::to-mx b expression))
              (ratsimped (ames.maxima::mcall "$RATSIMP" form))
              (candidates (mapcar (lambda (f) (ames.maxima::from-mx b f))
                                  (ames.maxima::request-list
                                   b (list ratsimped
                                           (ames.maxima::mcall "$TRIGSIMP" form)
                                           (ames.maxima::mcall "$RATSIMP" (ames.maxima::mcall "$TRIGSIMP" form))
                                           (ames.maxima::mcall "$FACTOR" ratsimped)
                                           (ames.maxima::mcall "$RADCAN" form)))))
              (smallest (reduce (lambda (best c)
                                  (if (< (ames.maxima::expression-size c)
                                         (ames.maxima::expression-size best))
                                      c best))
                                candidates)))
         (is (equal smallest (ames.maxima:simplify b expression :strategy :full))
             "~S: ~S is not the smallest candidate ~S" expression
             (ames.maxima:simplify b expression :strategy :full) smallest))))))

(test ode2-is-left-out-only-where-it-answers-implicitly
  (let ((s (ames.maxima::wire "$AMESVA")))
    (is (ames.maxima::nonlinear-in-p s (list (list ames.maxima::+cos+) s)))
    (is (not (ames.maxima::nonlinear-in-p s (list (list ames.maxima::+mplus+) 1 s))))
    (is (not (ames.maxima::nonlinear-in-p s (list (list ames.maxima::+sin+) (ames.maxima::wire "$AMESVB"))))))
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> g 0) (> r 0)))
       (let ((solution (ames.maxima:solve-autonomous-ode b '(- (* g (cos (/ s r)))) 's
                                                         :initial-position 's0 :initial-velocity 0)))
         (is (eq :energy-integral (ames.maxima:ode-solution-kind solution)))
         (is (ames.maxima:equivalent-p b (ames.maxima:ode-solution-speed-squared solution)
                                       '(* 2 g r (- (sin (/ s0 r)) (sin (/ s r))))))
         ;; and ode2 itself says so: an implicit answer (a list of two equations)
         (let ((x (ames.maxima::to-mx b 's)) (tm (ames.maxima::to-mx b 'tau)))
           (is (not (ames.maxima::mform-p
                     (ames.maxima::maxima-request
                      b (ames.maxima::mcall "$ODE2"
                                            (ames.maxima::mform ames.maxima::+mequal+
                                                                (ames.maxima::mform ames.maxima::+derivative+ x tm 2)
                                                                (ames.maxima::to-mx b '(- (* g (cos (/ s r))))))
                                            x tm))
                     ames.maxima::+mequal+)))))))))

(test holds-p-is-decide-s-true-and-refutes-without-maxima
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 0) (< x 1) (> k 0) (> a 0) (< a (/ pi 2))))
       (dolist (relation '((> (* k x (- 1 x)) 0) (< (* k x (- 1 x)) 0) (> (- x 1/2) 0)
                           (= (* k (- x 1/2)) 0) (= (+ (expt (sin a) 2) (expt (cos a) 2)) 1)
                           (>= (* k (sin a)) 0) (<= (- (cos a) 1) 0) (< (tan a) 0)
                           (and (> k 0) (< x 1)) (or (> x 1/2) (< x 1/3))))
         (is (eq (eq :true (ames.algebra:decide b relation))
                 (ames.algebra:holds-p b relation))
             "holds-p and decide disagree on ~S" relation))
       ;; a relation that fails somewhere is refused without a round trip
       (let ((before (round-trips b)))
         (is (not (ames.algebra:holds-p b '(> (* k (- x 1/3)) 0))))
         (is (not (ames.algebra:holds-p b '(= (* k x) (* k (expt x 2))))))
         (is (= before (round-trips b))))))))

(test refuted-p-sees-a-counterexample-under-extra-facts
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> v 0) (> g 0)))
       ;; v tau - g tau^2 / 2 rises first: positive at some tau > 0
       (is (ames.algebra:refuted-p b '(< (- (* v tau) (* 1/2 g (expt tau 2))) 0)
                                  :assuming '((> tau 0))))
       ;; -v tau - g tau^2 stays negative for tau > 0: no counterexample, and none is made up
       (is (not (ames.algebra:refuted-p b '(< (- (- (* v tau)) (* g (expt tau 2))) 0)
                                       :assuming '((> tau 0)))))
       (is (not (ames.algebra:refuted-p b '(> (* g v) 0))))
       (is (ames.algebra:refuted-p b '(> (- v g) 0)))))))

(test earliest-root-leaves-out-undecided-candidates-only-when-asked
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> v 0)))
       ;; c tau^2 - v tau: the sign of c decides whether a root follows the start
       (multiple-value-bind (root candidates)
           (ames.algebra:earliest-root b '(- (* c (expt tau 2)) (* v tau)) 'tau)
         (is (eq :unknown root))
         (is (consp candidates)))
       (multiple-value-bind (root candidates)
           (ames.algebra:earliest-root b '(- (* c (expt tau 2)) (* v tau)) 'tau :candidates nil)
         (is (eq :unknown root))
         (is (null candidates)))
       ;; a decided answer is the same either way
       (is (equal (multiple-value-list (ames.algebra:earliest-root b '(- (expt tau 2) (* v tau)) 'tau))
                  (multiple-value-list (ames.algebra:earliest-root b '(- (expt tau 2) (* v tau)) 'tau
                                                                  :candidates nil))))))))

(test ames-trigsimp-is-trigsimp
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> a 0) (< a (/ pi 2))))
       ;; the fast way (no tan, no square of sin or cos) and the slow way alike
       (dolist (expression '((+ (* -1/2 bb (cos a)) (- (* bb (sin a))))
                             (/ (* (cos a) (sin a) m g) (+ (* (expt (sin a) 2) m) w))
                             (+ (* 1/2 bb (sin a)) (/ (* 1/2 bb (cos a)) (tan a)))
                             (- (+ (expt (sin a) 2) (expt (cos a) 2)) 1)
                             (/ (+ (sin u) (cos u)) (- (sin u) (cos u)))
                             (* (sqrt (+ (expt (sin a) 2) 1)) (cos a))
                             (sin (+ (* 2 (expt (cos u) 2)) (expt (sin u) 2)))))
         (let ((form (ames.maxima::to-mx b expression)))
           (is (equal (ames.maxima::maxima-request b (ames.maxima::mcall "$TRIGSIMP" form))
                      (ames.maxima::maxima-request b (ames.maxima::mcall "$AMES_TRIGSIMP" form)))
               "ames_trigsimp differs from trigsimp on ~S" expression)))))))
