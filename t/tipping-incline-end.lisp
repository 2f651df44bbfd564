;;;; t/tipping-incline-end.lisp -- what ends the tipping of the block on the rough incline
;;;; (issue 23), under the file's values.
;;;;
;;;; The block of scenarios/awaiting-rotation/block-tipping-on-incline.lisp (w = 1/5, k = 1,
;;;; a = 30 deg, mu = 1, g = 9.81) turns about its downhill edge from rest at its angle
;;;; s = -a. The textbook's analysis of the rotation about a fixed edge: the centre at
;;;; r(s) = (-(w/2) cos s - (k/2) sin s, -(w/2) sin s + (k/2) cos s) from the edge,
;;;; I_edge = m (w^2 + k^2) / 3, the energy omega^2 = 3 g (w sin a + k cos a + w sin s -
;;;; k cos s) / (w^2 + k^2), alpha = (1/2) d(omega^2)/ds = 3 g (w cos s + k sin s) /
;;;; (2 (w^2 + k^2)) (at the start 3 g (w cos a - k sin a) / (2 (w^2 + k^2)) < 0: clockwise,
;;;; k tan a > w), and the edge's force R = m (alpha x r - omega^2 r) + m g (0, 1), whose
;;;; components along the slope's normal (sin a, cos a) and down the slope (cos a, -sin a)
;;;; are the normal force N and the friction F. The edge sticks while |F| <= mu N; the
;;;; block would land on its downhill face at s = -(a + pi/2). With these values the edge
;;;; reaches its friction limit first, F = -mu N (the friction up the slope at its limit)
;;;; at s = -1.12404 (N > 0 there: it has not lifted off): the state's end, found by AMES
;;;; along the angle with numbers (a root with no closed form) once the conditions that
;;;; cannot come first are set aside by the numbers (src/simulator/angle-horizon.lisp).
;;;; The run takes a minute or more on a loaded machine: the test is in LONG-CHECKS.

(in-package #:ames.tests)

(def-suite angle-horizon :in all-tests
  :description "Under values, where a condition along a rotation path may first fire, by
numbers (src/simulator/angle-horizon.lisp).")

(defun angle-horizon-first (relation reach)
  "NUMERIC-FIRST-ANGLE's (U SURE) for RELATION over the angle ARC-LENGTH itself, turning
forward from 0 with the value P = 1/2, up to REACH."
  (let ((run (make-instance 'ames.simulator::run :values '((p . 1/2))))
        (group (ames.simulator::make-group nil)))
    (setf (ames.simulator::group-s0 group) 0
          (ames.simulator::group-direction group) 1
          (ames.simulator::group-kind group) :rotation-path)
    (multiple-value-list
     (ames.simulator::numeric-first-angle run group relation #'identity reach))))

(test (a-gap-closing-beyond-its-face-is-passed :suite angle-horizon)
  "A guarded meeting: the gap cos s - p closes at s = pi/3 (p = 1/2); where its guard
sin s >= 4/5 holds there, that is where it surely fires; where the guard (sin s >= 9/10)
clearly fails, the closing is passed, and the next one (at 2 pi + pi/3) is beyond the
reach: the earliest angle is the reach itself, not sure; a guard too close to call at the
closing keeps the closing as the earliest angle, not sure."
  (let ((s 'ames.simulator::arc-length))
    (destructuring-bind (u sure) (angle-horizon-first `(and (= (- (cos ,s) p) 0) (>= (sin ,s) 4/5)) 6d0)
      (is (< (abs (- u (/ pi 3))) 1d-9))
      (is-true sure))
    (destructuring-bind (u sure) (angle-horizon-first `(and (= (- (cos ,s) p) 0) (>= (sin ,s) 9/10)) 6d0)
      (is (= u 6d0))
      (is-false sure))
    (destructuring-bind (u sure)
        (angle-horizon-first `(and (= (- (cos ,s) p) 0) (>= (sin ,s) (/ (sqrt 3) 2))) 6d0)
      (is (< (abs (- u (/ pi 3))) 1d-9))
      (is-false sure))))

(test (an-inequality-fires-at-its-first-crossing :suite angle-horizon)
  "A plain inequality fires surely where its violation function first crosses below zero
(cos s > p: at s = pi/3); one that never does within the reach (cos s > -2) has the reach
as its earliest angle; an OR, its earliest part, not sure."
  (let ((s 'ames.simulator::arc-length))
    (destructuring-bind (u sure) (angle-horizon-first `(< (cos ,s) p) 6d0)
      (is (< (abs (- u (/ pi 3))) 1d-9))
      (is-true sure))
    (destructuring-bind (u sure) (angle-horizon-first `(< (cos ,s) -2) 5d0)
      (is (= u 5d0))
      (is-false sure))
    (destructuring-bind (u sure) (angle-horizon-first `(or (< (cos ,s) p) (> (sin ,s) (/ (sqrt 2) 2))) 6d0)
      (is (< (abs (- u (/ pi 4))) 1d-9))
      (is-false sure))))

(defun incline-textbook-forces (s values)
  "The textbook's (values N F OMEGA^2 ALPHA) on the block turning about its downhill edge
at the angle S (see the file header), over VALUES (an alist of the scenario's parameter
names, as strings, to numbers)."
  (flet ((v (name) (float (cdr (assoc name values :test #'string-equal)) 1d0)))
    (let* ((m (v "M")) (g (v "G")) (w (v "W")) (k (v "K")) (a (v "A"))
           (omega2 (/ (* 3 g (+ (* w (sin a)) (* k (cos a)) (* w (sin s)) (* -1 k (cos s))))
                      (+ (* w w) (* k k))))
           (alpha (/ (* 3 g (+ (* w (cos s)) (* k (sin s)))) (* 2 (+ (* w w) (* k k)))))
           (rx (- (* -1/2 w (cos s)) (* 1/2 k (sin s))))
           (ry (+ (* -1/2 w (sin s)) (* 1/2 k (cos s))))
           (force-x (* m (- (* alpha (- ry)) (* omega2 rx))))
           (force-y (+ (* m (- (* alpha rx) (* omega2 ry))) (* m g))))
      (values (+ (* force-x (sin a)) (* force-y (cos a)))
              (- (* force-x (cos a)) (* force-y (sin a)))
              omega2 alpha))))

(test (tipping-block-on-an-incline-stops-sticking-before-it-lands :suite long-checks)
  "Under the file's values, the block's first state (turning about its downhill edge)
ends where its edge starts sliding, at the angle where the textbook's F = -mu N, before
the block lifts off its edge or lands on its face; self-checked."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenario-file (incline-block-file))))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (values (mapcar (lambda (entry) (cons (string (car entry)) (cdr entry)))
                           (ames.scenario:run-parameter-values scenario :numeric t)))
           (state (first (ames::history-states history))))
      (is (null (ames.check:self-check-failed-p history)))
      (is (not (null state)))
      (when state
        (end-event-is state :starts-sliding "BLOCK" "INCLINE")
        (let ((s (ames::state-end-arc-length state))
              (a (float (cdr (assoc "A" values :test #'string-equal)) 1d0))
              (mu (float (cdr (assoc "MU" values :test #'string-equal)) 1d0)))
          (is (realp s) "no end angle: ~S" s)
          (when (realp s)
            (multiple-value-bind (n f omega2) (incline-textbook-forces (float s 1d0) values)
              ;; the friction limit reached, up the slope
              (is (< (abs (+ f (* mu n))) (* 1d-6 (abs n))) "F + mu N = ~G at s = ~G" (+ f (* mu n)) s)
              (is (plusp n) "N = ~G: lifted off" n)
              (is (plusp omega2))
              ;; turned clockwise from -a, not as far as landing on the face
              (is (< (- (+ a (/ pi 2))) s (- a)) "s = ~G" s)
              ;; and no earlier angle where the edge slides or lifts (a fine scan)
              (is (loop for u from 1 below 1000
                        for x = (- (- a) (* u (/ (- (- a) s) 1000)))
                        always (multiple-value-bind (n f) (incline-textbook-forces x values)
                                 (and (plusp n) (< (abs f) (* mu n)))))))))))))
