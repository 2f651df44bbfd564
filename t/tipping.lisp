;;;; t/tipping.lisp -- a block tipping about one of its edges (src/simulator/rotation-path.lisp,
;;;; src/kb/corners.lisp): the motion of a body pinned at a corner along its angle.
;;;;
;;;; A block of width w and height k tipping about its edge (a corner pinned by static
;;;; friction) has one degree of freedom, its angle theta: its centre is at P + R(theta) rho,
;;;; rho the centre's arm from the edge, and theta'' = A(theta) = -m g (R(theta) rho)_x /
;;;; I_edge with I_edge = m (w^2 + k^2) / 3 (the textbook's inertia about an edge of the
;;;; block, parallel axes). The solved model gives the centre's accelerations over the angle
;;;; and omega in rational canonical form, where the slope X'(theta) = C0 / A cancels only
;;;; with sin^2 + cos^2 = 1: the integrator must still find the centre along the angle.
;;;; Expected results are the textbook's, compared by Maxima equivalence.

(in-package #:ames.tests)

(def-suite tipping :in all-tests
  :description "A block tipping about an edge: its centre along the angle (rotation paths).")

(in-suite tipping)

(defun tipping-run (bridge)
  "A RUN with BRIDGE alone: what the rotation-path algebra needs."
  (make-instance 'ames.simulator::run :bridge bridge))

(defun rotated-arm (rho theta)
  "The arm RHO (X Y) turned counter-clockwise by THETA, as two expressions."
  (destructuring-bind (x y) rho
    (list `(- (* ,x (cos ,theta)) (* ,y (sin ,theta)))
          `(+ (* ,x (sin ,theta)) (* ,y (cos ,theta))))))

(defun tipping-accelerations (run rho theta omega)
  "(values A AX AY) for a uniform w x k block of mass m pinned at the corner whose arm to
the centre is RHO, at the angle THETA turning at OMEGA (names): the textbook's angular
acceleration under gravity g about the edge, -m g r_x / I_edge, and the centre's
acceleration A k x r - OMEGA^2 r, each in Maxima's rational canonical form with sin^2
written 1 - cos^2, as the solver gives them (the quotient of the centre's omega-free part
by A then cancels only with sin^2 + cos^2 = 1)."
  (destructuring-bind (rx ry) (rotated-arm rho theta)
    (let ((driving `(/ (* -1 m g ,rx) (/ (* m (+ (expt w 2) (expt k 2))) 3))))
      (flet ((solver-form (expression)
               ;; rational form with sin^2 written 1 - cos^2, as the solver leaves it
               (ames.simulator::tidy
                run (subst `(- 1 (expt (cos ,theta) 2)) `(expt (sin ,theta) 2)
                           (ames.simulator::tidy run expression) :test #'equal))))
        (values (solver-form driving)
                (solver-form `(- (* -1 ,driving ,ry) (* (expt ,omega 2) ,rx)))
                (solver-form `(- (* ,driving ,rx) (* (expt ,omega 2) ,ry))))))))

(test centre-of-a-block-tipping-about-its-edge
  "A block tipping about its downhill edge P = (p, q) from the angle -a (on an incline of
angle a): along the angle its centre is P + R(theta) rho, rho = (-w/2, k/2), its slope
d/dtheta of that, whatever the order in which the solver wrote the accelerations."
  (with-fixture simulator-bridge ()
    (let* ((run (tipping-run bridge))
           (theta 'ames.simulator::arc-length)
           (omega '(ames.kb:angvel block))
           (rho '((- (/ w 2)) (/ k 2))))
      (ames.maxima:with-assumptions (bridge '((> m 0) (> g 0) (> w 0) (> k 0) (> a 0) (< a (/ pi 2))))
        (multiple-value-bind (driving ax ay) (tipping-accelerations run rho theta omega)
          (is-same bridge "the angular acceleration at the start: -m g ((k/2) sin a - (w/2) cos a) / I_edge"
                   (substitute-expressions (list (cons theta '(- a))) driving)
                   '(/ (* -1 m g (- (* (/ k 2) (sin a)) (* (/ w 2) (cos a)))) (/ (* m (+ (expt w 2) (expt k 2))) 3)))
          (destructuring-bind (rx ry) (rotated-arm rho theta)
            (loop for (acceleration start expected slope)
                    in (list (list ax (list 'p (substitute-expressions (list (cons theta '(- a))) rx))
                                   `(+ p ,rx) `(- ,ry))
                             (list ay (list 'q (substitute-expressions (list (cons theta '(- a))) ry))
                                   `(+ q ,ry) rx))
                  do (multiple-value-bind (x x-slope)
                         (ames.simulator::centre-along-angle run theta acceleration omega driving '(- a)
                                                             `(+ ,@start))
                       (is (not (null x)) "no centre found along the angle for ~S" acceleration)
                       (when x
                         (is-same bridge "the centre along the angle" x expected)
                         (is-same bridge "its slope along the angle" x-slope slope))))))))))

(test omega-squared-part-that-vanishes-by-trigonometry
  "The omega^2 part of a pinned body's angular acceleration can be 0 only by sin^2 + cos^2
= 1: proven zero then, and a part that is not zero is not."
  (with-fixture simulator-bridge ()
    (let ((run (tipping-run bridge)))
      (is (ames.simulator::identically-zero-p
           run '(* (/ (* w k) (+ (expt w 2) (expt k 2))) (- (+ (expt (sin x) 2) (expt (cos x) 2)) 1))))
      (is (not (ames.simulator::identically-zero-p run '(- (expt (sin x) 2) (expt (cos x) 2))))))))

;;; Roots along the angle found with numbers (src/simulator/numeric-angle-roots.lisp)

(defun swinging-group (direction)
  "A :ROTATION-PATH group from the angle 0 in DIRECTION whose energy integral
E = 2 g (cos theta - 1) / l + g / l turns negative at theta = +-pi/3 (a pendulum's)."
  (let ((group (ames.simulator::make-group '(bob)))
        (s 'ames.simulator::arc-length))
    (setf (ames.simulator::group-kind group) :rotation-path
          (ames.simulator::group-variable group) s
          (ames.simulator::group-s0 group) 0
          (ames.simulator::group-direction group) direction
          (ames.simulator::group-speed-squared group) `(+ (/ (* 2 g (- (cos ,s) 1)) l) (/ g l)))
    group))

(test numeric-roots-along-the-angle
  "Under values, where a condition of the angle first crosses zero ahead, before the
turning point at pi/3: cos theta - cos(pi/4) at pi/4 (either way), none for cos theta -
cos(pi/2) (beyond the turning point), none without values; the order of two angles by
the numbers."
  (with-fixture simulator-bridge ()
    (let ((run (make-instance 'ames.simulator::run :bridge bridge :values '((g . 981/100) (l . 2))))
          (s 'ames.simulator::arc-length))
      (dolist (direction '(1 -1))
        (let* ((group (swinging-group direction))
               (root (ames.simulator::numeric-angle-root run group `(- (cos ,s) (cos (/ pi 4))))))
          (is (rationalp root))
          (is (and root (< (abs (- root (* direction (/ pi 4)))) 1d-9)) "root ~A, expected ~A" root (* direction (/ pi 4)))
          (is (null (ames.simulator::numeric-angle-root run group `(cos ,s))) "beyond the turning point")
          (is (ames.simulator::numeric-reached-p run group (* direction 1)))
          (is (not (ames.simulator::numeric-reached-p run group (* direction 11/10))))
          (is (eq (if (= direction 1) :true :false)
                  (ames.simulator::numeric-angle-order run group 1/2 '(/ pi 4))))))
      (let ((without (make-instance 'ames.simulator::run :bridge bridge :values '()
                                    :scenario (ames:parse-scenario
                                               '(scenario s "x" (parameters (g :positive)) (gravity g)
                                                 (body b :mass 1 :shape (circle 1) :position (0 0) :velocity (0 0)))))))
        (is (null (ames.simulator::numeric-angle-root without (swinging-group 1) `(- (cos ,s) 1/2))))))))
