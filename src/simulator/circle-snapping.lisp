;;;; src/simulator/circle-snapping.lisp -- at the end of a numerically integrated state, a
;;;; body held on a circle about a fixed point put exactly on it.
;;;;
;;;; A particle on a taut rope from a fixed point (a pendulum) is integrated numerically;
;;;; its end position, carried over as rationals (RATIONAL-OF), is off the circle of the
;;;; rope's length by the integration's error. The next state decides in exact arithmetic
;;;; whether the rope is taut (its slack and the rate of its length zero): a slack of 1e-12
;;;; makes it fork on the sign of that slack, and the branch the values select drops the
;;;; particle into a free fall whose meeting with the rope's length is a quartic in huge
;;;; rationals. The current modes' entry equations (AMES.ENGINE:HELD-ENTRY-EQUATIONS) say
;;;; what the state holds without naming the phenomenon; one that reads
;;;; c0 + c1 sqrt((x - a)^2 + (y - b)^2) = 0 over one free body's position (x, y) (a, b, c0,
;;;; c1 free of the motion, c1 a number) holds the body on the circle about (a, b) of radius
;;;; r = -c0/c1. The body is put on it at a rational point: with u the axis direction
;;;; nearest to the body's direction d from the centre and v = u turned a right angle,
;;;; t = (d.v)/(|d| + d.u) as the simplest rational within 1e-12 (|t| <= tan(pi/8)), the point
;;;; (a, b) + r ((1 - t^2) u + 2 t v) / (1 + t^2) is exactly on the circle, within the
;;;; tolerance of where the integration left it (else the body stays put). Its velocity
;;;; loses its exact radial part (the rope's rate then exactly zero), its part along the
;;;; circle written as a short rational (to 1e-9 of itself), or, where the event that
;;;; ended the state fixes it, the speed at which that event holds exactly: 0 at a turning
;;;; point (turning-point-snapping.lisp). The next state then starts at rest exactly; its
;;;; rope piece can only keep its direction at that instant, and that mode's exit, judged
;;;; by the local series after the start, fires at once: the piece turns from the start
;;;; (choice.lisp's FORCED-EXIT).

(in-package #:ames.simulator)

(defparameter *circle-snap-tolerance* 1d-8
  "How far (relative to the larger of 1 and the radius) a numeric state's end may leave a
body from the circle it is held on, and still be put exactly on it.")

(defun motion-terms (expression)
  "The quantity terms of EXPRESSION (pos, vel, ...), each once."
  (let ((found '()))
    (labels ((walk (x)
               (cond ((quantity-term-p x) (pushnew x found :test #'equal))
                     ((consp x) (mapc #'walk (rest x))))))
      (walk expression))
    found))

(defun square-root-kernels (expression terms)
  "The (sqrt R) of EXPRESSION whose R holds one of TERMS."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (and (eq (first x) 'sqrt)
                            (some (lambda (term) (not (free-of-p term (second x)))) terms))
                   (pushnew x found :test #'equal))
                 (mapc #'walk (rest x)))))
      (walk expression))
    found))

(defun held-circle (run equation positions)
  "(values BODY CENTER RADIUS) when EQUATION, an expression the state holds at zero, with
the fixed bodies' positions put in from POSITIONS, reads c0 + c1 sqrt((x - a)^2 +
(y - b)^2) over one free body's position (see the file header); NIL otherwise."
  (let* ((terms (motion-terms equation))
         (bodies (remove-duplicates (mapcar #'second terms))))
    (when (and terms (every (lambda (term) (eq (first term) 'ames.kb:pos)) terms))
      (let ((free (remove-if (lambda (body) (body-fixed-p run body)) bodies)))
        (when (= 1 (length free))
          (let* ((body (first free))
                 (x `(ames.kb:pos ,body :x)) (y `(ames.kb:pos ,body :y))
                 (fixed (loop for other in bodies
                              unless (eq other body)
                                append (let ((at (second (assoc other positions))))
                                         (list (cons `(ames.kb:pos ,other :x) (first at))
                                               (cons `(ames.kb:pos ,other :y) (second at))))))
                 (held (substitute-expressions fixed equation))
                 (kernels (square-root-kernels held (list x y))))
            (when (= 1 (length kernels))
              (circle-of-kernel run body held (first kernels) x y))))))))

(defun circle-of-kernel (run body held kernel x y)
  "HELD-CIRCLE's reading of HELD, linear in its one square root KERNEL over X and Y."
  (let* ((bridge (run-bridge run))
         (z (ames.maxima:keyed-auxiliary-variable bridge (list :circle-kernel) "CIRCLE-ROOT"))
         (linear (ames.maxima:call-or-nil
                  (lambda () (ames.maxima:polynomial-coefficients-in
                              bridge (ames.algebra:substitute-subexpressions (list (cons kernel z)) held) z))))
         (radicand (second kernel)))
    (when (and (= 2 (length linear)) (numberp (second linear)) (/= 0 (second linear))
               (null (motion-terms (first linear))))
      (let ((in-x (ames.maxima:call-or-nil
                   (lambda () (ames.maxima:polynomial-coefficients-in bridge radicand x))))
            (in-y (ames.maxima:call-or-nil
                   (lambda () (ames.maxima:polynomial-coefficients-in bridge radicand y)))))
        (when (and (= 3 (length in-x)) (= 3 (length in-y))
                   (eql 1 (third in-x)) (eql 1 (third in-y))
                   (free-of-p y (second in-x)) (free-of-p x (second in-y)))
          (let ((center (list (tidy run `(* -1/2 ,(second in-x))) (tidy run `(* -1/2 ,(second in-y)))))
                (radius (tidy run `(- (/ ,(first linear) ,(second linear))))))
            (when (and (null (motion-terms center)) (null (motion-terms radius))
                       (ames.maxima:equivalent-p
                        bridge radicand `(+ (expt (- ,x ,(first center)) 2) (expt (- ,y ,(second center)) 2))))
              (values body center radius))))))))

(defparameter *circle-point-precision* 1d-12
  "How near the rational half-angle tangent of a point put on a circle is to the double
it stands for: the simplest rational within it keeps the point's numbers short.")

(defun simplest-rational-within (x epsilon)
  "The first convergent p/q of the continued fraction of the double X with |X - p/q| <=
EPSILON (the exact rational of X at worst)."
  (let ((exact (rational x)) (p0 0) (q0 1) (p1 1) (q1 0) (rest (rational x)))
    (loop
      (let* ((a (floor rest))
             (p2 (+ (* a p1) p0)) (q2 (+ (* a q1) q0)))
        (setf p0 p1 q0 q1 p1 p2 q1 q2)
        (when (or (<= (abs (- exact (/ p1 q1))) epsilon) (= rest a))
          (return (/ p1 q1)))
        (setf rest (/ 1 (- rest a)))))))

(defun rational-unit-toward (dx dy)
  "A unit vector with rational components near the direction (DX DY) (doubles, not both
zero): the rational point of the file header, as a list (UX UY)."
  (let* ((axes '((1 0) (0 1) (-1 0) (0 -1)))
         (u (first (sort (copy-list axes) #'>
                         :key (lambda (a) (+ (* dx (first a)) (* dy (second a)))))))
         (v (list (- (second u)) (first u)))
         (along (+ (* dx (first u)) (* dy (second u))))
         (across (+ (* dx (first v)) (* dy (second v))))
         (tt (simplest-rational-within (/ across (+ (sqrt (+ (* dx dx) (* dy dy))) along))
                                       *circle-point-precision*))
         (scale (/ 1 (+ 1 (* tt tt)))))
    (list (* scale (+ (* (- 1 (* tt tt)) (first u)) (* 2 tt (first v))))
          (* scale (+ (* (- 1 (* tt tt)) (second u)) (* 2 tt (second v)))))))

(defun snapped-circle-point (run center radius at)
  "The point on the circle about CENTER of RADIUS (expressions) nearest a rational
direction from the numeric position AT, with its exact unit direction: (values POINT
UNIT), or NIL when AT is off the circle beyond the tolerance."
  (let ((a (snap-number run (first center))) (b (snap-number run (second center)))
        (r (snap-number run radius))
        (px (snap-number run (first at))) (py (snap-number run (second at))))
    (when (and a b r px py (plusp r))
      (let* ((dx (- px a)) (dy (- py b)) (distance (sqrt (+ (* dx dx) (* dy dy)))))
        (when (and (plusp distance)
                   (<= (abs (- distance r)) (* *circle-snap-tolerance* (max 1d0 r))))
          (let ((unit (rational-unit-toward dx dy)))
            (values (mapcar (lambda (c u) (tidy run `(+ ,c (* ,radius ,u)))) center unit)
                    unit)))))))

(defun held-circles (run positions)
  "The circles the current modes hold free bodies on at POSITIONS: a list of (BODY
CENTER RADIUS)."
  (loop for equation in (ames.engine:held-entry-equations (run-model run))
        for (body center radius) = (multiple-value-list (held-circle run equation positions))
        when body collect (list body center radius)))

(defun snap-onto-held-circles (run positions)
  "POSITIONS with each body held on a circle (HELD-CIRCLES) put exactly on it (see the
file header): only a position the integration left as rationals, and not exactly on
the circle already (an exact closed form stays as it is)."
  (dolist (circle (held-circles run positions) positions)
    (destructuring-bind (body center radius) circle
      (let* ((at (second (assoc body positions)))
             (point (and (every #'rationalp at)
                         (not (eql 0 (tidy run `(- (+ (expt (- ,(first at) ,(first center)) 2)
                                                      (expt (- ,(second at) ,(second center)) 2))
                                                   (expt ,radius 2)))))
                         (snapped-circle-point run center radius at))))
        (when point
          (setf positions (substitute (list body point) (assoc body positions) positions)))))))

(defun velocity-on-circle (run body center radius positions velocities &optional fired)
  "BODY's velocity among VELOCITIES moved onto the circle about CENTER of RADIUS it is
held on at POSITIONS (see SNAP-VELOCITIES-ONTO-HELD-CIRCLES), or NIL when its position
is not a rational point of it, or the correction is beyond the tolerance. Its speed
along the circle is the one at which a FIRED candidate's event holds exactly, where
there is one (turning-point-snapping.lisp)."
  (let* ((at (second (assoc body positions)))
         (v (second (assoc body velocities)))
         (vn (mapcar (lambda (c) (snap-number run c)) v))
         ;; exact where the position was put on the circle at a rational point
         (unit (mapcar (lambda (p c) (tidy run `(/ (- ,p ,c) ,radius))) at center)))
    (when (and (every #'rationalp v) (every #'realp vn) (every #'rationalp unit))
      (let* ((radial (+ (* (first v) (first unit)) (* (second v) (second unit))))
             (tangent (list (- (second unit)) (first unit)))
             (along (+ (* (first v) (first tangent)) (* (second v) (second tangent))))
             ;; the speed along the circle as a short rational, to 1e-9 of itself
             (short (cond ((event-speed-on-circle run body tangent positions velocities fired along))
                          ((zerop along) 0)
                          (t (simplest-rational-within (float along 1d0) (* 1d-9 (abs along))))))
             (speed (max 1d0 (abs (first vn)) (abs (second vn)))))
        (when (<= (abs radial) (* *circle-snap-tolerance* speed))
          (list (* short (first tangent)) (* short (second tangent))))))))

(defun snap-velocities-onto-held-circles (run velocities positions &optional fired)
  "VELOCITIES with each body held on a circle at POSITIONS (snapped) moving along it: its
radial part removed exactly, so that the next state finds the circle's rate exactly
zero. (At a turning point the part along the circle is the integration's round-off,
with the sign of the swing to come; it is kept, and the next state starts swinging that
way, unless the event that ended the state, FIRED, fixes it: exactly 0 at a turning
point, turning-point-snapping.lisp.) A body whose correction is beyond the tolerance
keeps its velocity."
  (dolist (circle (held-circles run positions) velocities)
    (destructuring-bind (body center radius) circle
      (let ((snapped (velocity-on-circle run body center radius positions velocities fired)))
        (when snapped
          (setf velocities (substitute (list body snapped) (assoc body velocities) velocities)))))))
