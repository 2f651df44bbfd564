;;;; t/witness-refusals-roots.lisp -- more refusals of the witness's families answered (suite
;;;; witness-refusals, issue 21): a constant zero to round-off in the root search
;;;; (src/algebra/round-off.lisp: a particle bouncing off a step's top past its end, whose
;;;; crossing of the line of the step's bottom face at its landing on the floor was met again
;;;; and again), a numeric crossing that is round-off (src/simulator/numeric-roots.lisp), and
;;;; the friction impulse of a tilted rod striking a rough floor with no slip before the
;;;; impact (src/kb/rotating-impacts.lisp), textbook results by Maxima equivalence.

(in-package #:ames.tests)

(in-suite witness-refusals)

(defparameter *thrown-past-a-step*
  "(scenario step-235 \"A particle thrown toward a step on the floor.\" (gravity 29/4) (restitution 1/2)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body step :fixed t :shape (polygon (3/4 0) (9/4 0) (9/4 5/4) (3/4 5/4)))
     (body particle :mass 1 :position (0 4) :velocity (5/2 0) :shape point)
     (simulate :states 3))"
  "witness/disagreements/refused-step-meets-undecided.lisp: thrown at 5/2 from (0, 4),
g = 29/4, e = 1/2, toward a step from x = 3/4 to 9/4 with its top at 5/4.")

(test particle-bouncing-off-a-step-lands-on-the-floor
  "It lands on the step's top at t = sqrt(22/29) (x = 2.177 < 9/4), bounces up at
vy = e sqrt(2 g (4 - 5/4)) = sqrt(638)/8, passes the step's end above its top and lands
on the floor: 5/4 + vy tau - g tau^2 / 2 = 0 at tau = (sqrt(11) + sqrt(31))/sqrt(58),
where it also crosses the line of the step's bottom face (beyond the face's end: no
contact). Once refused: the search for a later crossing of that line met the same root
again (Maxima's sign() called the product of the roots, 0 written with radicals, 'neg')."
  (with-fixture simulator-bridge ()
    (let* ((answer (answer-of-text *thrown-past-a-step*))
           (state (answer-state answer 1)))
      (is (= 3 (length (getf answer :states))) "~S" (mapcar (lambda (s) (getf s :end-event)) (getf answer :states)))
      (when state
        (is (equal '("COLLISION" "PARTICLE" "FLOOR")
                   (mapcar #'symbol-name (subseq (getf state :end-event) 0 3)))
            "~S" (getf state :end-event))
        (is-same bridge "landing time" (getf state :duration)
                 '(/ (+ (sqrt 11) (sqrt 31)) (sqrt 58)))
        (is-same bridge "start" (getf state :start) '(sqrt 22/29))))))

(test a-constant-zero-to-round-off-has-no-float-sign
  "sqrt(2) sqrt(11) - sqrt(22) and (3 sqrt(2) sqrt(11) - 3 sqrt(22)) sqrt(29) sqrt(31) +
(33 sqrt(2) - 3 sqrt(11) sqrt(22)) sqrt(29) are 0 (their doubles are round-off, and
Maxima's sign() calls the second 'neg'): proven zero; sqrt(2) - 1414213562/10^9 (not 0,
3e-10 of its size, far above round-off) keeps Maxima's sign; a rational is never round-off."
  (with-fixture simulator-bridge ()
    (is (equal '(:zero) (ames.algebra::constant-zero-signs bridge '(- (* (sqrt 2) (sqrt 11)) (sqrt 22)))))
    (is (equal '(:zero) (ames.algebra::constant-zero-signs
                         bridge '(+ (* (- (* 3 (sqrt 2) (sqrt 11)) (* 3 (sqrt 22))) (sqrt 29) (sqrt 31))
                                    (* (- (* 33 (sqrt 2)) (* 3 (sqrt 11) (sqrt 22))) (sqrt 29))))))
    (is (null (ames.algebra::constant-zero-signs bridge '(- (sqrt 2) 1414213562/1000000000))))
    (is (null (ames.algebra::constant-zero-signs bridge '(- 1/3 1/3))))
    (is (null (ames.algebra::constant-zero-signs bridge '(- (sqrt 2) (sqrt 3)))))))

(test numeric-crossing-needs-a-sign-change-beyond-round-off
  "(15 - 15 (1 - exp(-tau/5))) - 15 exp(-tau/5) is 0 for every tau; its doubles are
round-off of either sign (-1.8e-15 at tau = 5.5). The numeric root search once took its
first negative double for a crossing (at 5.24); it now answers (:ROUND-OFF TAU), no
root. 1 - tau, sampled the same way, still crosses at 1, and 2 exp(-tau) - 1 at log 2."
  (let* ((zero '(- (- 15 (* 15 (- 1 (exp (- (/ ames.base:tau 5)))))) (* 15 (exp (- (/ ames.base:tau 5))))))
         (margin (lambda (expression)
                   (lambda (time)
                     (* ames.simulator::*crossing-round-off*
                        (ames.algebra:round-off-scale expression (list (cons 'ames.base:tau time)))))))
         (function (lambda (expression)
                     (let ((f (ames.simulator::numeric-function expression '(ames.base:tau))))
                       (lambda (time) (funcall f (vector time)))))))
    (let ((found (ames.simulator::first-numeric-crossing
                  (funcall function zero) (constantly nil) 0.5d0 50d0 (funcall margin zero))))
      (is (and (consp found) (eq :round-off (first found))) "~S" found))
    (let ((found (ames.simulator::first-numeric-crossing
                  (funcall function '(- 1 ames.base:tau)) (constantly nil) 0.3d0 50d0
                  (funcall margin '(- 1 ames.base:tau)))))
      (is (and (realp found) (< (abs (- found 1)) 1d-12)) "~S" found))
    (let* ((e '(- (* 2 (exp (- ames.base:tau))) 1))
           (found (ames.simulator::first-geometric-crossing (funcall function e) 50d0 (funcall margin e))))
      (is (and (realp found) (< (abs (- found (log 2d0))) 1d-12)) "~S" found))))

(defun rod-on-a-rough-floor (mu)
  "A uniform rod (m = 1, length 2, I = m/3) tilted at atan(3/4) (sin 3/5, cos 4/5) dropped
from rest so that its lower end falls 1/5 onto a rough floor (friction MU, a string),
g = 10, e = 0: it lands at v = 2 without spin, its end with no slip."
  (format nil "(scenario rod-rough \"A tilted rod falls onto a rough floor.\" (gravity 10)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body rod :mass 1 :inertia :uniform :shape (segment (-1 0) (1 0))
           :position (0 4/5) :angle (atan 3/4) :velocity (0 0))
     (restitution rod floor 0) (friction rod floor :static ~A) (simulate :states 1))" mu))

(defun rod-impact-check (mu jx jy)
  "The rod of ROD-ON-A-ROUGH-FLOOR at MU strikes the floor: the impulse (JX, JY) at its end
r = (-4/5, -3/5) (per unit m v, v = 2) gives v' = (JX, JY - 1) v, omega' = 3 (r x J) v
(I = 1/3); the friction impulse along the tangent (-1, 0) is -JX v, the normal JY v."
  (with-fixture simulator-bridge ()
    (let* ((scenario (witness-scenario (rod-on-a-rough-floor mu)))
           (impact (first-impact scenario bridge))
           (torque (- (* -4/5 jy) (* -3/5 jx))))
      (is (not (null impact)))
      (when impact
        (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "ROD")
                        (list (* 2 jx) (* 2 (- jy 1))))
        (is-same bridge "angular velocity after"
                 (impact-entry impact :angular-velocities-after "ROD") (* 3 torque 2))
        (is-same bridge "normal impulse"
                 (car (last (find :impulse (getf impact :impulses) :key #'first))) (* 2 jy))
        (is-same bridge "friction impulse"
                 (car (last (find :friction-impulse (getf impact :impulses) :key #'first))) (* -2 jx))))))

(test rod-striking-a-rough-floor-slides
  "Routh's rod: struck at its end with no slip before, it sticks when
mu >= 3 s c / (1 + 3 s^2) = 9/13. mu = 1/2 is below: the end slides outward through the
impact and friction takes mu Jn against that slip (Coulomb at the impulse level):
Jn = m v / (1 + 3 c^2 - 3 mu s c) = 5 m v / 11, Jt = mu Jn = 5 m v / 22 inward."
  (rod-impact-check "1/2" 5/22 5/11))

(test rod-striking-a-rough-floor-sticks
  "mu = 1 >= 9/13: the end sticks; Jn = m v (1 + 3 s^2) / 4 = 13 m v / 25 and the
friction Jx = 3 s c m v / 4 = 9 m v / 25 (within mu Jn)."
  (rod-impact-check "1" 9/25 13/25))

(test self-check-steps-no-finer-than-the-rates-round-off
  "y' = 1 computed as the small difference of terms of 1e9 (a rope's tension near its
pulley, from the expanded formula: terms of 1e9 for a result of 1e3) has a round-off of
1e-7 that changes at random with y: the step-doubling estimate of a step's error is then
about h 1e-8, and a tolerance of 1e-13 per step asks steps of 1e-5 and fewer (the incline
pulley crawled at 1,500 steps a second to the 120 s limit): 2,000 steps do not reach
tau = 1. With the rates' round-off scale (*RATE-SCALES*, here 1e9: ROUND-OFF-FORM gives
it from the terms) a step is not asked to do better than that round-off: tau = 1 is
reached within the 2,000 steps, at y = 1 within 1e-6, and the error allowed beyond the
tolerance is counted (*ERROR-SUM* > 0: the check reports such a state unchecked rather
than compare it to 1e-8). ROUND-OFF-FORM adds the sizes of a sum's terms."
  (let* ((rates (lambda (y time)
                  (declare (ignore time))
                  (vector (+ 1 (* 1d-7 (/ (- (mod (* 7919 (sxhash (svref y 0))) 1001) 500) 500))))))
         (ames.check::*step-limit* 2000))
    (signals ames.check::integration-failed
      (ames.check:integrate-rk4 rates (vector 0d0) 0d0 1d0))
    (let ((ames.check::*rate-scales* (lambda (y time) (declare (ignore y time)) (vector 1d9)))
          (ames.check::*error-sum* 0d0))
      (let ((y (ames.check:integrate-rk4 rates (vector 0d0) 0d0 1d0)))
        (is (< (abs (- (svref y 0) 1)) 1d-6) "~S" y)
        (is (plusp ames.check::*error-sum*)))))
  (is (= 2000000003d0 (funcall (ames.check:compile-numeric
                                (ames.check::round-off-form '(+ (- (+ 1000000000 y) 1000000000 y) 1))
                                '(y))
                               (vector 1d0)))))

(test step-and-spring-refusals-now-agree-with-the-witness
  "witness/disagreements/refused-step-meets-undecided.lisp (the particle bouncing past a
step's end) and refused-drag-spring-closes-constant-fact.lisp (a damped spring that never
closes) now agree with Siconos."
  (with-siconos
    (dolist (name '("refused-step-meets-undecided.lisp" "refused-drag-spring-closes-constant-fact.lisp"))
      (let* ((path (asdf:system-relative-pathname "ames" (format nil "witness/disagreements/~A" name)))
             (result (check-text (uiop:read-file-string path) :numeric t)))
        (is (eq :agree (getf result :verdict))
            "~A gives ~(~A~): ~A" name (getf result :verdict) (getf result :reason))))))
