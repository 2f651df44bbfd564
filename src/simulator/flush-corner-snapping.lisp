;;;; src/simulator/flush-corner-snapping.lisp -- at the end of a numerically integrated state,
;;;; a rotating body's face put exactly flush with a fixed face when a corner of each touches
;;;; the other's: its angle too.
;;;;
;;;; FLAT-CORNER-ANGLE (flat-corner-snapping.lisp) puts a body back flat on a face it
;;;; rests on by two of its own corners (or on two fixed corners by one of its faces): the
;;;; two gaps differ by a function of the angle alone. A body's corner P on a fixed face L
;;;; together with a fixed corner V (an end of L) on the body's face F (which P ends) is
;;;; the same resting, seen from both bodies (a block landed flat on a ledge while the
;;;; ledge's edge holds its bottom face), but the two gaps differ by a function of the
;;;; position too, so the integration's round-off (about 1e-12) in the angle cannot be
;;;; taken out as there. Both gaps vanish at once only where F lies along L: the angle
;;;; theta* where the contacts' normals are parallel, n1 x n2(theta) = A cos theta + B sin
;;;; theta = 0 (exact, as FLAT-ANGLE finds it), nearest the integrated angle and within
;;;; *CORNER-SNAP-TOLERANCE* of it. It is taken only when it is exact for these two
;;;; contacts: at theta* their gaps, affine in the position, are proportional (checked in
;;;; exact arithmetic: the same line of positions puts both on their faces), so the position
;;;; snapping (corner-snapping.lisp) then puts both exactly on. The angular velocity
;;;; follows as in flat-corner-snapping.lisp: while the first gap is held, the second
;;;; changes at omega S, S = d/dtheta (G2 - k G1) at theta* (k the ratio of the two gaps'
;;;; position coefficients); an omega whose S omega is within the tolerance of 0 is 0.

(in-package #:ames.simulator)

(defun contact-geometry-of-gap (run body gap)
  "The AMES.GEOMETRY:ROTATING-CONTACT of RUN's corner contact of BODY whose gap is GAP
(the very expression), or NIL."
  (loop for (nil observer nil . geometry) in (run-corner-contacts run)
        when (and (eq observer body) (eq (ames.geometry:rotating-contact-gap geometry) gap))
          return geometry))

(defun normals-cross (run body first second)
  "n1 x n2 of the rotating contacts FIRST and SECOND of BODY, over the symbol SNAP-ANGLE."
  (destructuring-bind ((ax ay) (bx by))
      (mapcar (lambda (geometry)
                (mapcar (lambda (x)
                          (substitute-expressions (list (cons `(ames.kb:angle ,body) 'snap-angle)) x))
                        (ames.geometry:rotating-contact-normal geometry)))
              (list first second))
    (tidy run `(- (* ,ax ,by) (* ,ay ,bx)))))

(defun proportional-gaps (run body first second angle)
  "The ratio k with SECOND = k FIRST at the exact ANGLE for every position of BODY (the
two gaps, affine in the position there, proportional), or NIL when they are not so."
  (let* ((x `(ames.kb:pos ,body :x)) (y `(ames.kb:pos ,body :y))
         (at (lambda (gap) (substitute-expressions (list (cons `(ames.kb:angle ,body) angle)) gap)))
         (p (affine-parts run (funcall at first) x y))
         (q (affine-parts run (funcall at second) x y)))
    (when (and p q)
      (destructuring-bind ((a1 b1 c1) (a2 b2 c2)) (list p q)
        (when (every (lambda (e) (eql 0 (tidy run e :full)))
                     (list `(- (* ,a1 ,b2) (* ,a2 ,b1)) `(- (* ,a1 ,c2) (* ,a2 ,c1))
                           `(- (* ,b1 ,c2) (* ,b2 ,c1))))
          (let ((n1 (snap-number run a1)) (n2 (snap-number run b1)))
            (cond ((and n1 (/= n1 0d0)) (tidy run `(/ ,a2 ,a1) :full))
                  ((and n2 (/= n2 0d0)) (tidy run `(/ ,b2 ,b1) :full)))))))))

(defun flush-slope (run body first second ratio angle position)
  "d/dtheta (SECOND - RATIO FIRST) at the exact ANGLE and POSITION of BODY, a double:
the rate, per unit of angular velocity, at which SECOND's gap opens while FIRST's is held."
  (let* ((x `(ames.kb:pos ,body :x)) (y `(ames.kb:pos ,body :y)) (theta `(ames.kb:angle ,body))
         (over (substitute-expressions (list (cons theta 'snap-angle) (cons x (first position))
                                             (cons y (second position)))
                                       `(- ,second (* ,ratio ,first)))))
    (snap-number run (substitute-expressions (list (cons 'snap-angle angle))
                                             (ames.geometry:differentiate over 'snap-angle)))))

(defun flush-corner-angle (run body theta position gaps)
  "The exact angle theta* that puts BODY's face flush with a fixed face, two of GAPS (the
near corner gaps at THETA and POSITION: CORNER-SNAP-CONDITIONS) being a corner of each
on the other's face (see the file header), within the tolerance of THETA; NIL when there
is none. Second value: the rate S of the second gap per unit angular velocity there."
  (loop for (first . others) on gaps
        do (dolist (second others)
             (let ((g1 (contact-geometry-of-gap run body first))
                   (g2 (contact-geometry-of-gap run body second)))
               (when (and g1 g2)
                 (multiple-value-bind (angle value) (flat-angle run (normals-cross run body g1 g2) theta)
                   (when (and angle value
                              (<= (abs (- value theta))
                                  (* *corner-snap-tolerance* (max 1d0 (abs (coerce theta 'double-float))))))
                     (let ((ratio (proportional-gaps run body first second angle)))
                       (when ratio
                         (let ((slope (flush-slope run body first second ratio angle position)))
                           (when (and slope (/= slope 0d0))
                             (return-from flush-corner-angle (values angle slope))))))))))))
  nil)
