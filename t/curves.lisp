;;;; t/curves.lisp -- motion on curves (issue 20): events in the direction of motion over
;;;; every turn of a circle, turning points and periodic swings, declared bounds carried
;;;; through squares, offset trigonometric gaps decided by their amplitude.
;;;;
;;;; Closed forms are checked by Maxima equivalence under the scenario's facts, or by
;;;; their values at several points where Maxima cannot rewrite a special function.

(in-package #:ames.tests)

(def-suite curves :in all-tests
  :description "Curved contacts: roots ahead on a circle, turning points, periods, bounds through squares.")

(in-suite curves)

(defun loop-scenario (name)
  "The scenario NAME (a string) of scenarios/ball-round-vertical-loop.lisp."
  (let ((file (find "ball-round-vertical-loop" (scenario-files) :key #'pathname-name :test #'string=)))
    (find name (ames:read-scenario-file file)
          :key (lambda (s) (string (ames:scenario-name s))) :test #'string-equal)))

(defun check-loop-lift-off (bridge scenario side)
  "SCENARIO's ball, launched from the loop's bottom too slowly to loop, leaves the loop
in its first state where N = 0: from energy (v^2 = v0^2 - 2 g y) and N = m v^2/r - m g
sin a = 0 with y = r (1 + sin a), at height y = (g r + v0^2)/(3 g) and horizontal
distance sqrt((5 g r - v0^2)(g r + v0^2))/(3 g) from the centre, on SIDE (1: +x, -1: -x),
the side it was launched toward."
  (let* ((history (ames:simulate scenario :bridge bridge))
         (state (first (ames::history-states history))))
    (is (null (ames::state-branches state)) "the declared bounds on v0 leave nothing to branch on")
    (end-event-is state :lift-off "BALL" "LOOP")
    (flet ((x (form) (in-scenario-terms scenario form)))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (let ((at (per-body (ames::state-final-positions state) "BALL"))
               (height (x '(/ (+ (* g r) (expt v0 2)) (* 3 g))))
               (distance (x `(* ,side (/ (sqrt (* (- (* 5 g r) (expt v0 2)) (+ (* g r) (expt v0 2))))
                                         (* 3 g))))))
           (if (and (same-expression-p bridge (second at) height)
                    (same-expression-p bridge (first at) distance))
               (pass)
               ;; Maxima may not rewrite sin(acos c - 3 pi/2): the values at admissible
               ;; points (g r < v0^2/2 < 5 g r / 2) decide then
               (loop for (g r v0) in '((10 1 6) (981/100 2 9) (1 1/2 3/2))
                     for bindings = (in-scenario-terms scenario `((m . 1) (g . ,g) (r . ,r) (v0 . ,v0)))
                     do (is (< (abs (- (expression-value (second at) bindings)
                                       (expression-value height bindings)))
                               1d-9)
                            "lift-off height ~S" (second at))
                        (is (< (abs (- (expression-value (first at) bindings)
                                       (expression-value distance bindings)))
                               1d-9)
                            "lift-off distance ~S" (first at))))))))))

(test a-ball-in-a-loop-leaves-it-launched-toward-minus-x
  "Launched toward -x (toward increasing arc length here), the ball leaves the loop on
the left at the height energy and N = 0 give: the root of N on the far turn of the
circle, which solve()'s principal root (behind the ball) missed."
  (with-fixture simulator-bridge ()
    (check-loop-lift-off bridge (loop-scenario "ball-in-loop-slow-leftward") -1)))

(test a-ball-in-a-loop-leaves-it-launched-toward-plus-x
  "The mirror image: launched toward +x, it leaves on the right at the same height."
  (with-fixture simulator-bridge ()
    (check-loop-lift-off bridge (loop-scenario "ball-in-loop-slow-rightward") 1)))

(test a-ball-fast-enough-loops-forever-either-way
  "Faster than sqrt(5 g r) the normal force stays positive all round: the ball loops
forever, launched either way (no lift-off at a root of N = 0 that is not real)."
  (with-fixture simulator-bridge ()
    (dolist (name '("ball-in-loop-fast-leftward" "ball-in-loop-fast-rightward"))
      (let* ((history (ames:simulate (loop-scenario name) :bridge bridge))
             (state (first (ames::history-states history))))
        (is (eq :complete (ames::history-outcome history)) "~A: ~S" name (ames::history-outcome history))
        (is (eq :forever (ames::state-duration state)) "~A loops forever" name)))))

;;; Turning points and periods

(defparameter *swing-in-an-offset-bowl*
  '(scenario swing-in-an-offset-bowl
    "A particle released at rest on the left wall of a bowl of radius R centred at (a, b + R)."
    (parameters (m :positive) (g :positive) (big-r :positive) (a :positive) (b :positive)
                (phi :positive (< phi (/ pi 2))))
    (gravity g)
    (body bowl :fixed t :shape (arc :center (a (+ b big-r)) :radius big-r :from pi :to (* 2 pi)
                                    :solid :outside))
    (body particle :mass m :position ((- a (* big-r (sin phi))) (- (+ b big-r) (* big-r (cos phi))))
                   :velocity (0 0) :shape point)
    (simulate :states 2))
  "Released on the left, the particle moves toward decreasing arc length.")

(test a-particle-released-on-the-left-of-a-bowl-swings-with-the-pendulum-period
  "A particle released at angle phi on the left of a bowl (moving the other way along the
arc than in scenarios/particle-in-a-bowl.lisp, the bowl away from the origin) swings
periodically between the angle phi on either side of the bottom, s = R (pi/2 +- phi),
with the period 4 sqrt(R/g) K(sin^2(phi/2)) = 4 sqrt(R/g) K((1 - cos phi)/2)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *swing-in-an-offset-bowl*))
           (history (ames:simulate scenario :bridge bridge))
           (state (first (ames::history-states history)))
           (periodic (ames.simulator:state-periodic state)))
      (is (eq :complete (ames::history-outcome history)))
      (is (eq :forever (ames::state-duration state)))
      (is (not (null periodic)))
      (when periodic
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "period" (getf periodic :period)
                      (x '(* 4 (sqrt (/ big-r g)) (elliptic-k (/ (- 1 (cos phi)) 2)))))
             (let ((between (getf periodic :between)))
               (is (= 2 (length between)))
               ;; each turning point, Maxima-checked or (asin(cos phi) = pi/2 - phi, which
               ;; Maxima does not rewrite) by its values
               (dolist (expected (list (x '(* big-r (+ (/ pi 2) phi))) (x '(* big-r (- (/ pi 2) phi)))))
                 (is (some (lambda (s)
                             (or (same-expression-p bridge s expected)
                                 (loop for (r phi) in '((1 1/2) (2 1) (1/2 3/2))
                                       for bindings = (in-scenario-terms scenario `((big-r . ,r) (phi . ,phi)))
                                       always (< (abs (- (expression-value s bindings)
                                                         (expression-value expected bindings)))
                                                 1d-9))))
                           between)
                     "turning point ~S not among ~S" expected between)))))
          ;; the special function's parameter, checked by values too
          (loop for (g r phi) in '((10 1 1/2) (981/100 2 1) (3 1/2 3/2))
                for bindings = (in-scenario-terms scenario `((m . 1) (g . ,g) (big-r . ,r) (a . 1) (b . 1) (phi . ,phi)))
                for got = (expression-value (getf periodic :period) bindings)
                for expected = (expression-value '(* 4 (sqrt (/ r g)) (elliptic-k (expt (sin (/ phi 2)) 2)))
                                                 `((r . ,r) (g . ,g) (phi . ,phi)))
                do (is (< (abs (- got expected)) (* 1d-9 expected)) "period ~A, expected ~A" got expected)))))))

(test the-bowl-scenario-gives-its-period-under-its-defaults
  "scenarios/particle-in-a-bowl.lisp under its defaults (g = 10, r = 1, theta0 = 1/2):
the period is 4 sqrt(1/10) K(sin^2(1/4)) = 2.01841..."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-in-a-bowl"))
           (history (ames:simulate scenario :bridge bridge))
           (state (first (ames::history-states history)))
           (period (getf (ames.simulator:state-periodic state) :period))
           (values (in-scenario-terms scenario '((m . 1) (g . 10) (r . 1) (theta0 . 1/2)))))
      (is (not (null period)))
      (when period
        (is (< (abs (- (expression-value period values)
                       (expression-value '(* 4 (sqrt 1/10) (elliptic-k (expt (sin 1/4) 2))))))
               1d-9))))))

;;; Declared bounds through squares, and offset sinusoids

(test declared-bounds-carry-through-squares
  "0 < v0 < sqrt(g r) excludes v0^2 - g r > 0; v0 > sqrt(2 g r) gives v0^2 - 2 g r > 0;
0 < mu < tan a (0 < a < pi/2) gives sin^2 a - mu^2 cos^2 a > 0. A relation the bounds
do not settle stays open."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> v0 0) (> g 0) (> r 0) (< v0 (sqrt (* g r)))))
      (is (eq :false (ames.algebra:decide bridge '(> (- (expt v0 2) (* g r)) 0))))
      (is (eq :true (ames.algebra:decide bridge '(< (expt v0 2) (* g r)))))
      (is (eq :unknown (ames.algebra:decide bridge '(> (- (expt v0 2) (/ (* g r) 2)) 0)))))
    (ames.maxima:with-assumptions (bridge '((> v0 0) (> g 0) (> r 0) (> v0 (sqrt (* 2 g r)))))
      (is (eq :true (ames.algebra:decide bridge '(> (- (expt v0 2) (* 2 g r)) 0)))))
    (ames.maxima:with-assumptions (bridge '((> mu 0) (> a 0) (< a (/ pi 2)) (< mu (tan a))))
      (is (eq :true (ames.algebra:decide bridge '(> (- (expt (sin a) 2) (* (expt mu 2) (expt (cos a) 2))) 0))))
      (is (eq :false (ames.algebra:decide bridge '(<= (- (expt (sin a) 2) (* (expt mu 2) (expt (cos a) 2))) 0)))))))

(test the-amplitude-of-a-loop-decides-lift-off
  "Between sqrt(2 g r) and sqrt(5 g r) the normal force's sinusoid m (v0^2 - 2 g r)/r +
3 m g cos x has a root: its offset is less than its amplitude, (v0^2 - 2 g r)^2 <=
9 g^2 r^2, which the declared bounds give through squares."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> m 0) (> g 0) (> r 0) (> v0 0) (> v0 (sqrt (* 2 g r)))
                                            (< v0 (sqrt (* 5 g r)))))
      (is (eq :true (ames.algebra:decide bridge '(<= (/ (* (expt m 2) (expt (- (expt v0 2) (* 2 g r)) 2))
                                                       (expt r 2))
                                                    (* 9 (expt m 2) (expt g 2)))))))))

(test an-offset-sinusoid-has-no-root-beyond-its-amplitude
  "A sin t + B cos t - C with C > A + B >= sqrt(A^2 + B^2) (A, B > 0) never vanishes."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> a 0) (> b 0) (> c (+ a b))))
      (is (eq :none (ames.algebra:earliest-trigonometric-root
                     bridge '(- (+ (* a (sin tau)) (* b (cos tau))) c) 'tau))))))

(test an-offset-cosine-vanishes-at-its-arc-cosine
  "h + k cos t with 0 < h < k first vanishes at t = acos(-h/k) (= pi - acos(h/k)),
between pi/2 and pi, and vanishes there."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> h 0) (> k h)))
      (multiple-value-bind (root status)
          (ames.algebra:earliest-trigonometric-root bridge '(+ h (* k (cos tau))) 'tau)
        (is (eq :found status))
        (is (same-expression-p bridge root '(acos (- (/ h k)))))
        (loop for (h k) in '((1 2) (1/3 1) (9/10 1))
              for angle = (expression-value root `((h . ,h) (k . ,k)))
              do (is (< (abs (+ h (* k (cos angle)))) 1d-12))
                 (is (< (/ pi 2) angle pi)))))))
