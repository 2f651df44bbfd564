;;;; t/rope-pendulum.lisp -- a particle on a taut rope swings several times
;;;; (scenarios/pendulum-on-a-rope.lisp): each numerically integrated swing's end is put
;;;; exactly on the rope's circle, moving along it (src/simulator/circle-snapping.lisp), and the
;;;; self-check's floor near zero allows a numeric state's own error (src/check/claims.lisp).
;;;;
;;;; Expected (textbook, the simple pendulum): each swing ends (:turns BOB) at the mirror
;;;; point (-+l sin theta0, -l cos theta0) after half the period, 2 sqrt(l/g)
;;;; K(sin^2(theta0/2)). Before, the first swing's end was a rational point off the circle
;;;; by 1e-12, the next state forked on the sign of the rope's slack and the branch the
;;;; values select dropped the bob into a free fall (a quartic in huge rationals that Maxima
;;;; did not finish); the self-check failed the end velocity (2e-11 against -4e-11).

(in-package #:ames.tests)

(def-suite rope-pendulum :in all-tests
  :description "A pendulum on a rope swings several times: ends put exactly on the circle,
at rest, the self-check passing.")

(in-suite rope-pendulum)

(test simplest-rational-within-a-tolerance
  "The continued fraction's first convergent within epsilon: near, and short."
  (dolist (x '(0.4142135623730951d0 -0.2553419212210362d0 1d-3 0.1d0 0d0))
    (let ((r (ames.simulator::simplest-rational-within x 1d-12)))
      (is (<= (abs (- (rational x) r)) 1d-12))
      (is (< (denominator r) 10000000) "~A: ~A" x r))))

(test rational-unit-vectors-are-on-the-circle
  "The rational point toward a direction is exactly a unit vector, within 1e-11 of the
direction, in every quadrant."
  (dolist (angle '(0.5d0 2.0d0 -1.2d0 3.1d0 -2.9d0 1.5707963267948966d0))
    (let ((unit (ames.simulator::rational-unit-toward (* 3 (cos angle)) (* 3 (sin angle)))))
      (is (every #'rationalp unit))
      (is (= 1 (+ (expt (first unit) 2) (expt (second unit) 2))))
      (is (< (abs (- (first unit) (cos angle))) 1d-11))
      (is (< (abs (- (second unit) (sin angle))) 1d-11)))))

(test a-pendulum-on-a-rope-swings-several-times
  "Four swings at theta0 = 1/2 (g = 10, l = 1): each ends (:turns BOB) exactly on the
circle x^2 + y^2 = l^2 (Maxima), moving along it (no radial velocity, exactly) at rest to
round-off, alternately at -+l sin theta0 at the height
-l cos theta0, after half the period; the self-check passes."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (scenario-file-forms "pendulum-on-a-rope")))
           (history (ames:run-scenario scenario :numeric t :bridge bridge))
           (states (remove-if #'ames::state-fork-p (ames.check::checked-path (ames:history-states history))))
           (half-period (* 2 (sqrt (/ 1d0 10)) (expression-value `(elliptic-k ,(expt (sin 0.25d0) 2)))))
           (package (symbol-package (ames:scenario-name scenario)))
           (l (find-symbol "L" package))
           (values (mapcar (lambda (entry) (cons (find-symbol (car entry) package) (cdr entry)))
                           '(("L" . 1) ("G" . 10) ("M" . 1) ("THETA0" . 1/2)))))
      (is (null (ames.check:self-check-failed-p history)))
      (is (= 4 (length states)) "~A states along the path" (length states))
      (loop for state in states
            for side = -1 then (- side)
            for end = (per-body (ames::state-final-positions state) "BOB")
            for velocity = (per-body (ames::state-final-velocities state) "BOB")
            do (is (equal '(:turns "BOB") (event-names (ames::state-end-event state))))
               (is (same-expression-p bridge `(+ (expt ,(first end) 2) (expt ,(second end) 2)) `(expt ,l 2))
                   "off the circle: ~S" end)
               ;; along the circle exactly (the rope's rate zero), at rest to round-off
               (is (same-expression-p bridge `(+ (* ,(first end) ,(first velocity)) (* ,(second end) ,(second velocity))) 0)
                   "a radial velocity: ~S at ~S" velocity end)
               (is (< (+ (abs (expression-value (first velocity) values)) (abs (expression-value (second velocity) values))) 1d-8)
                   "not at rest: ~S" velocity)
               (is (< (abs (- (expression-value (first end) values) (* side (sin 0.5d0)))) 1d-7))
               (is (< (abs (- (expression-value (second end) values) (- (cos 0.5d0)))) 1d-7))
               (let ((duration (expression-value (ames::state-duration state) values)))
                 (is (and (realp duration) (< (abs (- duration half-period)) (* 1d-7 half-period)))
                     "half period ~A, expected ~A" duration half-period))))))
