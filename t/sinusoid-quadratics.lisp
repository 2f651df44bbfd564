;;;; t/sinusoid-quadratics.lisp -- the sign of a quadratic in one sinusoid at every angle
;;;; (src/algebra/sinusoid-quadratics.lisp): the symbolic rocking block's normal force.
;;;;
;;;; The block (width w, height k, mass m, I_edge = m D^2/3, D^2 = w^2 + k^2) set turning
;;;; about its right bottom edge at w0 presses on that edge with (textbook: N = m g - m
;;;; (d cos p omega^2 + d sin p alpha), d = D/2, p the angle of the centre from the vertical
;;;; through the edge, omega^2 from the energy, alpha = (3 g / (2 D)) sin p)
;;;;   N = (m g / 4) ((3 c - b)^2 + 1 - b^2),  c = cos p = (k cos s - w sin s) / D,
;;;;   b = k / D + D w0^2 / (3 g) (the value of c at the turning point),
;;;; positive at every angle when b < 1, which is the declared bound on w0 (the centre does
;;;; not go over the edge). The run writes N in sin s and cos s; DECIDE proves its sign.

(in-package #:ames.tests)

(def-suite sinusoid-quadratics :in all-tests
  :description "The sign of a quadratic in one sinusoid of an angle at every angle, under
the facts about the parameters (the rocking block's normal force).")

(in-suite sinusoid-quadratics)

(defparameter *rocking-normal-force*
  '(/ (* m (+ (* 10 g (expt w 2)) (* g (expt k 2)) (* 6 g w k (sin s))
            (* 9 g (expt k 2) (expt (cos s) 2)) (* 2 w (expt k 2) (expt w0 2) (sin s))
            (* 2 (expt w 3) (expt w0 2) (sin s)) (* -6 g (expt k 2) (cos s))
            (* -18 g w k (sin s) (cos s)) (* -9 g (expt w 2) (expt (cos s) 2))
            (* -2 (expt w 2) k (expt w0 2) (cos s)) (* -2 (expt k 3) (expt w0 2) (cos s))))
      (* 4 (+ (expt w 2) (expt k 2))))
  "The normal force on the symbolic rocking block's edge along its angle s, as the run
writes it (scenarios/block-rocking-symbolic.lisp, the state on the edge).")

(defun textbook-rocking-normal-force ()
  "(m g / 4) ((3 c - b)^2 + 1 - b^2) (this file's header)."
  (let* ((d '(sqrt (+ (expt w 2) (expt k 2))))
         (c `(/ (- (* k (cos s)) (* w (sin s))) ,d))
         (b `(+ (/ k ,d) (/ (* ,d (expt w0 2)) (* 3 g)))))
    `(* 1/4 m g (+ (expt (- (* 3 ,c) ,b) 2) 1 (- (expt ,b 2))))))

(test rocking-normal-force-is-the-textbooks
  "The run's normal force is the textbook's (m g / 4) ((3 c - b)^2 + 1 - b^2)."
  (call-with-bridge
   (lambda (b)
     (is (ames.maxima:equivalent-p b *rocking-normal-force* (textbook-rocking-normal-force))))))

(defun sign-everywhere (bridge facts function &optional (angle 's))
  (ames.maxima:with-assumptions (bridge facts)
    (ames.algebra:sign-at-every-angle bridge function angle)))

(test rocking-normal-force-is-positive-at-every-angle
  "Under the declared bound on w0 the normal force is proven positive at every angle (so
on the whole rise); without it (w0 large enough to lift the block off its edge) it is
not, and its negative is not proven negative either."
  (call-with-bridge
   (lambda (b)
     (let ((facts (cons '(> m 0) *rocking-bound-facts*)))
       (is (eq :positive (sign-everywhere b facts *rocking-normal-force*)))
       (is (eq :negative (sign-everywhere b facts `(- ,*rocking-normal-force*)))))
     (let ((loose '((> m 0) (> g 0) (> w 0) (> k 0) (> w0 0))))
       (is (null (sign-everywhere b loose *rocking-normal-force*)))))))

(defun sinusoid-value (coefficients angle)
  "alpha cos^2 + beta cos sin + gamma sin^2 + delta cos + epsilon sin + zeta at ANGLE."
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    (let ((c (cos angle)) (s (sin angle)))
      (+ (* alpha c c) (* beta c s) (* gamma s s) (* delta c) (* epsilon s) zeta))))

(defun sinusoid-expression (coefficients)
  (destructuring-bind (alpha beta gamma delta epsilon zeta) coefficients
    `(+ (* ,alpha (expt (cos s) 2)) (* ,beta (cos s) (sin s)) (* ,gamma (expt (sin s) 2))
        (* ,delta (cos s)) (* ,epsilon (sin s)) ,zeta)))

(defun sinusoid-sign-at-points (coefficients)
  "The strict sign of the function with COEFFICIENTS at 720 angles over a turn, or 0 when
it has both signs or a zero among them (or very near one)."
  (let ((values (loop for i below 720
                      collect (sinusoid-value coefficients (* 2d0 pi (/ i 720))))))
    (cond ((every (lambda (v) (> v 1d-9)) values) 1)
          ((every (lambda (v) (< v -1d-9)) values) -1)
          (t 0))))

(test sinusoid-signs-hold-at-points
  "Every sign proven holds at 720 angles; relations that fail somewhere (a sinusoid
through 0, a quadratic with a real root within reach, a non-strict minimum) stay
unproven; quadratics in one sinusoid with and without a linear part are proven."
  (call-with-bridge
   (lambda (b)
     ;; proven: 2 + cos s; 1 + sin^2 s; cos s + sin s - 3 < 0
     (is (eq :positive (sign-everywhere b '() (sinusoid-expression '(0 0 0 1 0 2)))))
     (is (eq :positive (sign-everywhere b '() (sinusoid-expression '(0 0 1 0 0 1)))))
     (is (eq :negative (sign-everywhere b '() (sinusoid-expression '(-1 0 -1 1 1 -2)))))
     ;; X^2 + X + 3 with X = 3 cos + 4 sin (no real root)
     (is (eq :positive (sign-everywhere b '() (sinusoid-expression '(10 24 17 3 4 2)))))
     ;; not: 1 + cos s (0 at pi), cos s - 1/2, cos^2 - sin^2, (3 cos + 4 sin)^2 - 1
     (is (null (sign-everywhere b '() (sinusoid-expression '(0 0 0 1 0 1)))))
     (is (null (sign-everywhere b '() (sinusoid-expression '(0 0 0 1 0 -1/2)))))
     (is (null (sign-everywhere b '() (sinusoid-expression '(1 0 -1 0 0 0)))))
     (is (null (sign-everywhere b '() (sinusoid-expression '(9 24 16 0 0 -1)))))
     ;; random quadratics in one sinusoid: the verdict agrees with the points
     (let ((*random-state* (sb-ext:seed-random-state 23)) (proven 0))
       (dotimes (i 60)
         (let* ((delta (- (random 7) 3)) (epsilon (- (random 7) 3))
                (a (/ (- (random 9) 4) 4)) (lam (/ (- (random 9) 4) 2)) (c (/ (- (random 13) 6) 2))
                ;; a (delta C + epsilon S)^2 + lam (C^2 + S^2) + delta C + epsilon S + c - lam
                (coefficients (list (+ (* a delta delta) lam) (* 2 a delta epsilon)
                                    (+ (* a epsilon epsilon) lam) delta epsilon (- c lam)))
                (verdict (sign-everywhere b '() (sinusoid-expression coefficients)))
                (points (sinusoid-sign-at-points coefficients)))
           (when verdict (incf proven))
           (is (member verdict (case points (1 '(nil :positive)) (-1 '(nil :negative)) (t '(nil))))
               "~A: ~A, but ~A at points" coefficients verdict points)))
       (is (> proven 5))))))

;;; The friction limit mu N -+ F at every angle, under a declared "rough enough"

(defparameter *rocking-friction*
  '(/ (* m (+ (* (- (* (- (* 9 g (expt k 2)) (* 9 g (expt w 2))) (cos s))
                    (+ (* 6 g (expt k 2)) (* 2 (expt w 2) k (expt w0 2)) (* 2 (expt k 3) (expt w0 2))))
                 (sin s))
              (* 18 g w k (expt (cos s) 2))
              (- (* (+ (* 6 g w k) (* 2 w (expt k 2) (expt w0 2)) (* 2 (expt w 3) (expt w0 2))) (cos s)))
              (* -9 g w k)))
      (* 4 (+ (expt w 2) (expt k 2))))
  "The static friction on the symbolic rocking block's edge along its angle s, as the run
writes it.")

(defparameter *rocking-turning-cosine*
  '(/ (+ (* 3 g k) (* (+ (expt w 2) (expt k 2)) (expt w0 2))) (* 3 g (sqrt (+ (expt w 2) (expt k 2)))))
  "b = k/D + D w0^2/(3 g): the cosine of the centre's angle from the vertical through the
edge at the turning point.")

(test rocking-friction-is-the-textbooks
  "The run's friction is the textbook's m a_x = (3 m g / 4) sin p (2 b - 3 c) (this file's
header; p = atan(w/k) + s, the sign of the x axis)."
  (call-with-bridge
   (lambda (b)
     (let* ((d '(sqrt (+ (expt w 2) (expt k 2))))
            (c `(/ (- (* k (cos s)) (* w (sin s))) ,d))
            (sp `(/ (+ (* w (cos s)) (* k (sin s))) ,d)))
       (is (ames.maxima:equivalent-p
            b *rocking-friction*
            `(* -3/4 m g ,sp (- (* 2 ,*rocking-turning-cosine*) (* 3 ,c)))))))))

(test rocking-friction-limit-holds-at-every-angle-when-rough-enough
  "With mu > (9/2 + 6 b) / (1 - b^2) (N >= (m g / 4)(1 - b^2) and |F| <= (m g / 4)(9/2 + 6 b)
at every angle), mu N - F and mu N + F are proven positive at every angle; with mu > 0
alone, or a bound a tenth of it, they are not."
  (call-with-bridge
   (lambda (b)
     (let* ((beta *rocking-turning-cosine*)
            (rough `(> mu (/ (+ 9/2 (* 6 ,beta)) (- 1 (expt ,beta 2)))))
            (facts (list* '(> m 0) '(> mu 0) rough *rocking-bound-facts*)))
       (dolist (sign '(1 -1))
         (let ((limit `(- (* mu ,*rocking-normal-force*) (* ,sign ,*rocking-friction*))))
           (is (eq :positive (sign-everywhere b facts limit)))))
       ;; mu N - F, which a slippery floor makes negative at the start for a fast block
       (let ((limit `(- (* mu ,*rocking-normal-force*) ,*rocking-friction*)))
         (is (null (sign-everywhere b (list* '(> m 0) '(> mu 0) *rocking-bound-facts*) limit)))
         (is (null (sign-everywhere b (list* '(> m 0) '(> mu 0)
                                             `(> mu (/ (+ 9/20 (* 6/10 ,beta)) (- 1 (expt ,beta 2))))
                                             *rocking-bound-facts*)
                                    limit))))))))

(test parameter-bounds-hold-at-points
  "p P + Q with P a quadratic in one sinusoid and Q any quadratic in sin and cos, under a
fact p > p0: every :POSITIVE holds at 720 angles for p just above p0 and well above it."
  (call-with-bridge
   (lambda (b)
     (let ((*random-state* (sb-ext:seed-random-state 29)) (proven 0))
       (dotimes (i 25)
         (let* ((delta (- (random 5) 2)) (epsilon (- (random 5) 2))
                (a (/ (random 5) 4)) (c (/ (random 9) 2))
                (inner (list (* a delta delta) (* 2 a delta epsilon) (* a epsilon epsilon)
                             delta epsilon c))
                (outer (loop repeat 6 collect (/ (- (random 9) 4) 2)))
                (p0 (/ (random 17) 2))
                (function `(+ (* p ,(sinusoid-expression inner)) ,(sinusoid-expression outer)))
                (verdict (sign-everywhere b `((> p ,p0)) function)))
           (when (eq verdict :positive)
             (incf proven)
             (dolist (p (list (+ p0 1/1000) (+ p0 5)))
               (is (= 1 (sinusoid-sign-at-points
                         (mapcar (lambda (x y) (+ (* p x) y)) inner outer)))
                   "~A under p > ~A: not positive at p = ~A" function p0 p)))))
       (is (> proven 2))))))
