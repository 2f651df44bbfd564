;;;; src/simulator/corner-snapping.lisp -- at the end of a numerically integrated state, the
;;;; corners of rotating bodies that touch a face put exactly on it.
;;;;
;;;; A numeric state (numeric.lisp) ends with double-precision positions and angles: a
;;;; corner that slid along a face all through the state (its gap held at zero only by the
;;;; gap's second derivative), or that reached a face or a face's end at the event that ends
;;;; the state, is off its locus by the integration's error or the event's bisection (about
;;;; 1e-12). The next state decides in exact arithmetic whether it touches: a gap of 1e-13
;;;; is no contact, and the state after it meets the face again 1e-12 s later, or finds no
;;;; consistent contact set. So, as SNAP-ONTO-CONTACTS does for a body's face, each
;;;; rotating body's corner contacts (corners.lisp) are put exactly on their loci at the
;;;; state's end: with the body's angle theta as the integration left it (a rational), a
;;;; corner's gap and its place along the face are affine in the body's position (x, y);
;;;; every gap within *CORNER-SNAP-TOLERANCE* of 0 at a place within the face (to that
;;;; tolerance), and every place within it of a face's end, is a condition G(x, y) = 0, and
;;;; the position is moved the least that satisfies the first two independent ones (one:
;;;; along G's gradient; two: the 2 x 2 system; in the plane any further one is implied
;;;; where the geometry agrees, as a corner at a face's end is on both faces), in exact
;;;; arithmetic. The tolerance is checked: a body that would move further than it (or
;;;; whose conditions are not affine) stays where the integration put it. A body resting by two
;;;; corners on one face needs its angle moved too (the two gaps differ by a function of
;;;; theta alone): the second corner is not snapped (not done yet).

(in-package #:ames.simulator)

(defparameter *corner-snap-tolerance* 1d-8
  "How far (in the scenario's units of length, relative to the larger of 1 and the body's
distance from the origin) a numeric state's end may leave a rotating body's corner from a
face, or from a face's end, and still be put exactly on it.")

(defun snap-number (run x)
  "The double X is under the run's parameter values (when it has them), or NIL."
  (let ((v (ignore-errors (expression-value x (and (run-numbers-known-p run) (numeric-bindings run))))))
    (and (realp v) (coerce v 'double-float))))

(defun corner-snap-conditions (run body theta position &optional leaving)
  "The near conditions G(x, y) of the rotating BODY at angle THETA and POSITION (X Y)
(see the file header): a list of (G . VALUE), G over (pos BODY :x) and (pos BODY :y),
VALUE its double at POSITION; second value the tolerance; third, the gaps among them as
the geometry writes them (over the position and (angle BODY))."
  (let* ((bindings (list (cons `(ames.kb:pos ,body :x) (first position))
                         (cons `(ames.kb:pos ,body :y) (second position))))
         (tolerance (* *corner-snap-tolerance*
                       (max 1d0 (abs (or (snap-number run (first position)) 1d0))
                            (abs (or (snap-number run (second position)) 1d0)))))
         (conditions '()) (gaps '()))
    (flet ((at-angle (x) (substitute-expressions (list (cons `(ames.kb:angle ,body) theta)) x))
           (value (x) (snap-number run (substitute-expressions bindings x))))
      (loop for (name observer nil . geometry) in (run-corner-contacts run)
            when (and (eq observer body) (not (member name leaving)))
              do (let* ((gap (at-angle (ames.geometry:rotating-contact-gap geometry)))
                        (margins (mapcar (lambda (r) (at-angle (extent-margin r)))
                                         (ames.geometry:contact-extent-relations geometry)))
                        (g (value gap))
                        (m (mapcar #'value margins)))
                   (when (and g (<= (abs g) tolerance) (every (lambda (v) (and v (>= v (- tolerance)))) m))
                     (push (cons gap g) conditions)
                     (push (ames.geometry:rotating-contact-gap geometry) gaps)
                     (loop for margin in margins for v in m
                           when (<= (abs v) tolerance)
                             do (push (cons margin v) conditions)))))
      (values (nreverse conditions) tolerance (nreverse gaps)))))

(defun affine-parts (run expression x y)
  "(A B C) with EXPRESSION = A X + B Y + C (X and Y terms), A B C free of X and Y; NIL
when it is not so."
  (let* ((over (substitute-expressions (list (cons x 'snap-x) (cons y 'snap-y)) expression))
         (a (tidy run (ames.geometry:differentiate over 'snap-x)))
         (b (tidy run (ames.geometry:differentiate over 'snap-y))))
    (when (every (lambda (c) (and (free-of-p 'snap-x c) (free-of-p 'snap-y c))) (list a b))
      (list a b (tidy run `(- ,over (* ,a snap-x) (* ,b snap-y)))))))

(defun snapped-position (run body conditions position)
  "POSITION (X Y) moved the least that makes the first independent CONDITIONS (G . VALUE)
exactly 0 (see the file header), in exact arithmetic; NIL when they are not affine in the
position."
  (least-change-solution run (mapcar #'car conditions)
                         `(ames.kb:pos ,body :x) `(ames.kb:pos ,body :y) position))

(defun least-change-solution (run expressions x y point)
  "POINT (X0 Y0), values of the terms X and Y, moved the least that makes the first two
independent of EXPRESSIONS (affine in X and Y) exactly 0: along the first one's gradient
when no other is independent of it, else the 2 x 2 system of the first two independent
ones (in the plane any further one is implied where the geometry agrees). In exact
arithmetic; NIL when some expression is not affine in X and Y."
  (let ((chosen '()))
    (dolist (expression expressions)
      (let ((parts (affine-parts run expression x y)))
        (unless parts (return-from least-change-solution nil))
        (let ((n (mapcar (lambda (e) (snap-number run e)) (subseq parts 0 2))))
          (unless (every #'realp n) (return-from least-change-solution nil))
          (flet ((independent-p (other)
                   (let ((m (second other)))
                     (> (abs (- (* (first n) (second m)) (* (second n) (first m))))
                        (* 1d-9 (sqrt (* (+ (expt (first n) 2) (expt (second n) 2))
                                         (+ (expt (first m) 2) (expt (second m) 2)))))))))
            (cond ((null chosen) (push (list parts n) chosen))
                  ((and (null (rest chosen)) (independent-p (first chosen)))
                   (push (list parts n) chosen)))))))
    (when (and chosen (every (lambda (c) (some (lambda (v) (/= v 0d0)) (second c))) chosen))
      (destructuring-bind (px py) point
        (if (null (rest chosen))
            (destructuring-bind (a b c) (first (first chosen))
              ;; along the gradient (A B): P - G(P) (A B) / (A^2 + B^2)
              (let ((scale `(/ (+ (* ,a ,px) (* ,b ,py) ,c) (+ (expt ,a 2) (expt ,b 2)))))
                (list (tidy run `(- ,px (* ,scale ,a)) :full) (tidy run `(- ,py (* ,scale ,b)) :full))))
            (destructuring-bind ((a1 b1 c1) (a2 b2 c2)) (mapcar #'first (reverse chosen))
              ;; A1 x + B1 y = -C1, A2 x + B2 y = -C2
              (let ((det `(- (* ,a1 ,b2) (* ,a2 ,b1))))
                (list (tidy run `(/ (- (* ,b1 ,c2) (* ,b2 ,c1)) ,det) :full)
                      (tidy run `(/ (- (* ,a2 ,c1) (* ,a1 ,c2)) ,det) :full)))))))))

(defun distance-moved (run from to)
  "The distance between the points FROM and TO (X Y) under the run's numbers, or NIL."
  (let ((d (mapcar (lambda (a b) (let ((x (snap-number run a)) (y (snap-number run b))) (and x y (- x y))))
                   from to)))
    (and (every #'realp d) (sqrt (+ (expt (first d) 2) (expt (second d) 2))))))

(defun leaving-contacts (fired)
  "The contact entities that FIRED candidates end by a force, not by the geometry: a
corner whose normal force turns attractive lifts off (its relation speaks of no position
or angle). Such a corner leaves its face at the state's end: it is not put back on it
(its gap is 0 and so is its normal force, and the next state could not decide whether it
still touches)."
  (loop for candidate in fired
        for condition = (candidate-condition candidate)
        when (and condition (eq (ames.engine:termination-condition-kind condition) :deactivation)
                  (notany #'state-quantity-p
                          (expression-variables (ames.engine:termination-condition-relation condition))))
          collect (let ((key (ames.engine:termination-condition-instance condition)))
                    (and (consp key) (second key)))))

(defun snap-corners-onto-faces (run positions angles &optional fired)
  "POSITIONS (an alist body -> (X Y)) with each rotating body whose corners are within
*CORNER-SNAP-TOLERANCE* of a face or a face's end, at its angle in ANGLES (an alist body
-> (THETA)), moved exactly onto them (see the file header), when it moves no further than
that tolerance; the others as they are. The contacts the FIRED candidates lift off
(LEAVING-CONTACTS) are not snapped."
  (mapcar (lambda (entry)
            (destructuring-bind (body position) entry
              (let ((theta (second (assoc body angles))))
                (or (and theta (not (body-fixed-p run body))
                         (multiple-value-bind (conditions tolerance)
                             (corner-snap-conditions run body theta position (leaving-contacts fired))
                           (let ((snapped (and conditions (snapped-position run body conditions position))))
                             (and snapped
                                  (let ((moved (distance-moved run snapped position)))
                                    (and moved (<= moved tolerance) (list body snapped)))))))
                    entry))))
          positions))

(defun snap-corner-velocities (run velocities positions angles omegas &optional fired)
  "VELOCITIES (an alist body -> (VX VY)) with each rotating body's velocity changed the
least that makes the rate of every gap of a corner touching a face (at its exact
POSITIONS, ANGLES and angular velocities OMEGAS, alists body -> value) exactly 0 where
that rate is within *CORNER-SNAP-TOLERANCE* (relative to the larger of 1 and the body's
speed) of 0: a corner that slides along its face stays on it in the next state, in exact
arithmetic. A rate further from 0 (a corner striking its face) is left as it is."
  (mapcar (lambda (entry)
            (destructuring-bind (body velocity) entry
              (let ((theta (second (assoc body angles)))
                    (omega (second (assoc body omegas)))
                    (position (second (assoc body positions))))
                (or (and theta omega position (not (body-fixed-p run body))
                         (let* ((gaps (nth-value 2 (corner-snap-conditions run body theta position
                                                                             (leaving-contacts fired))))
                                (tolerance (* *corner-snap-tolerance*
                                              (max 1d0 (or (ignore-errors (sqrt (+ (expt (snap-number run (first velocity)) 2)
                                                                                    (expt (snap-number run (second velocity)) 2))))
                                                           1d0))))
                                (vx `(ames.kb:vel ,body :x)) (vy `(ames.kb:vel ,body :y))
                                (rates (loop for gap in gaps
                                             for rate = (gap-rate run body gap position theta omega vx vy)
                                             for value = (snap-number run (substitute-expressions
                                                                           (list (cons vx (first velocity))
                                                                                 (cons vy (second velocity)))
                                                                           rate))
                                             when (and value (<= (abs value) tolerance))
                                               collect rate))
                                (snapped (and rates (least-change-solution run rates vx vy velocity))))
                           (and snapped
                                (let ((moved (distance-moved run snapped velocity)))
                                  (and moved (<= moved tolerance) (list body snapped))))))
                    entry))))
          velocities))

(defun gap-rate (run body gap position theta omega vx vy)
  "The rate of the corner's GAP (over BODY's position and angle terms) at POSITION, THETA
and the angular velocity OMEGA, over the velocity terms VX and VY."
  (let* ((x `(ames.kb:pos ,body :x)) (y `(ames.kb:pos ,body :y)) (angle `(ames.kb:angle ,body))
         (over (substitute-expressions (list (cons x 'snap-x) (cons y 'snap-y) (cons angle 'snap-angle)) gap))
         (at (lambda (e) (substitute-expressions (list (cons 'snap-x (first position)) (cons 'snap-y (second position))
                                                       (cons 'snap-angle theta))
                                                 e))))
    (tidy run `(+ (* ,(funcall at (ames.geometry:differentiate over 'snap-x)) ,vx)
                  (* ,(funcall at (ames.geometry:differentiate over 'snap-y)) ,vy)
                  (* ,(funcall at (ames.geometry:differentiate over 'snap-angle)) ,omega)))))
