;;;; t/rotating-impacts.lisp -- impacts of rotating bodies (issue 23; src/kb/rotating-impacts.lisp,
;;;; the hinge at an impact in src/kb/hinges.lisp): the angular impulse r x J, Newton's
;;;; restitution on the normal velocity of the contact points (omega x r included), the hinge's
;;;; impulsive reaction holding its pin, and the kinetic energy an impact dissipates (never
;;;; negative). The expected results are the textbook's, compared by Maxima equivalence under
;;;; the scenario's assumptions. Helpers: t/simulator-scenarios.lisp, t/friction.lisp.

(in-package #:ames.tests)

(def-suite rotating-impacts :in all-tests
  :description "Impacts of rotating bodies: angular impulse, restitution at the contact
points, a hinge holding its pin, energy never gained.")

(in-suite rotating-impacts)

(defun first-impact (scenario bridge)
  "The impact plist (src/simulator/impacts.lisp) ending SCENARIO's first state, or NIL."
  (multiple-value-bind (history states) (run-of scenario bridge)
    (declare (ignore history))
    (and states (ames::state-impact (first states)))))

(defun impact-entry (impact key body)
  "The entry of the body named BODY under KEY (:VELOCITIES-AFTER ...) of IMPACT."
  (per-body (getf impact key) body))

(defun is-energy-not-gained (bridge scenario lost)
  "Check that the kinetic energy LOST at an impact is >= 0 under SCENARIO's assumptions
and, to be sure it is no vacuous check, at the scenario's parameter values."
  (let ((values (ames.scenario:run-parameter-values scenario :numeric t)))
    (let ((signs (ames.maxima:maxima-signs bridge lost)))
      (is (and signs (not (member :negative signs))) "energy lost ~S is not shown >= 0: ~S" lost signs))
    (is (>= (ames.maxima:numeric-value bridge lost values) 0))))

(test rod-falling-tilted-strikes-a-smooth-floor
  "A uniform rod falling at 30 degrees strikes a smooth floor with its lower end:
J = 4 (1 + e) m |v| / 13, v' = (9 - 4 e) v / 13, omega' = -6 cos(30) J / (m l), no
horizontal velocity, the energy lost (1 - e^2) (4/13) m v^2 / 2."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "rod-falls-tilted-onto-floor"))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (let* ((v (x '(- (sqrt (/ (* g (- 4 l)) 2)))))
                 (j `(/ (* 4 (+ 1 ,(x 'e)) ,(x 'm) (- ,v)) 13)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "ROD")
                               `(0 (/ (* (- 9 (* 4 ,(x 'e))) ,v) 13)))
               (is-same bridge "angular velocity after"
                        (impact-entry impact :angular-velocities-after "ROD")
                        `(/ (* -6 (/ (sqrt 3) 2) ,j) (* ,(x 'm) ,(x 'l))))
               (is-same bridge "energy lost" (getf impact :energy-lost)
                        `(* 1/2 (- 1 (expt ,(x 'e) 2)) 4/13 ,(x 'm) (expt ,v 2)))
               (is-energy-not-gained bridge scenario (getf impact :energy-lost))))))))))

(test hinged-rod-strikes-the-floor
  "A rod hinged at one end swings onto the floor: the hinge holds the pin, so
omega' = -e omega, omega = -sqrt(3 g / (2 l)); the floor's impulse m (1 + e) sqrt(2 g l) / 3;
the energy lost (1 - e^2) m g l / 4; the pin is still just after."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "rod-hinged-strikes-floor"))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (let ((omega (x '(- (sqrt (/ (* 3 g) (* 2 l))))))
                (floor-impulse (find-if (lambda (entry) (eq (first entry) :impulse))
                                        (getf impact :impulses))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "angular velocity before"
                        (impact-entry impact :angular-velocities-before "ROD") omega)
               (is-same bridge "omega' = -e omega"
                        (impact-entry impact :angular-velocities-after "ROD")
                        `(* -1 ,(x 'e) ,omega))
               ;; the pin at (-l/2) (cos, sin)(-pi/6) from the centre: its velocity after is 0
               (let ((v (impact-entry impact :velocities-after "ROD"))
                     (w (impact-entry impact :angular-velocities-after "ROD"))
                     (arm (list (x '(- (* (/ l 2) (/ (sqrt 3) 2)))) (x '(/ l 4)))))
                 (is-same-vector bridge "the pin is still"
                                 (list `(- ,(first v) (* ,w ,(second arm))) `(+ ,(second v) (* ,w ,(first arm))))
                                 '(0 0)))
               (is-same bridge "the floor's impulse" (car (last floor-impulse))
                        (x '(/ (* m (+ 1 e) (sqrt (* 2 g l))) 3)))
               (is-same bridge "energy lost" (getf impact :energy-lost)
                        (x '(/ (* m g l (- 1 (expt e 2))) 4)))
               (is-energy-not-gained bridge scenario (getf impact :energy-lost))))))))))

(defparameter *spinning-disc*
  "(scenario spinning-disc-bounces \"A spinning disc thrown onto a smooth floor.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (< r 1) (:value 1/10))
                 (w0 :positive (:value 5)) (u :positive (:value 1)) (e :positive (< e 1) (:value 1/2)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body disc :mass m :inertia :uniform :shape (circle r) :position (0 1) :angular-velocity w0 :velocity (u 0))
     (restitution disc floor e)
     (simulate :states 1))"
  "A uniform disc spinning at W0, thrown horizontally at U onto a smooth floor.")

(test spinning-disc-keeps-its-spin-on-a-smooth-floor
  "A disc's impulse from a smooth floor passes through its centre: the spin w0 and the
horizontal velocity u are kept, the vertical one reversed and scaled by e."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *spinning-disc*)))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "spin kept" (impact-entry impact :angular-velocities-after "DISC") (x 'w0))
             (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "DISC")
                             (x '(u (* e (sqrt (* 2 g (- 1 r)))))))
             (is-energy-not-gained bridge scenario (getf impact :energy-lost)))))))))

(test ball-dropped-onto-a-hinged-wheel
  "A ball falling the height d onto the top of a wheel on an axle at its centre: the
impulse passes through the pin, so the wheel does not move (the hinge's impulse holds it)
and the ball rebounds with e times its speed, losing (1 - e^2) m g d."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string
                             "(scenario ball-on-wheel \"A ball falls onto a hinged wheel.\"
                                (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
                                            (r :positive (:value 1/5)) (d :positive (:value 2))
                                            (e :positive (< e 1) (:value 1/2)))
                                (gravity g)
                                (body wheel :mass m :inertia :uniform :shape (circle r) :position (0 0) :velocity (0 0))
                                (hinge axle :body wheel :at (0 0))
                                (body ball :mass m :shape point :position (0 (+ r d)) :velocity (0 0))
                                (restitution ball wheel e)
                                (simulate :states 1))")))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "the wheel stays" (impact-entry impact :velocities-after "WHEEL") '(0 0))
             (is-same bridge "nor turns" (impact-entry impact :angular-velocities-after "WHEEL") 0)
             (is-same-vector bridge "the ball rebounds" (impact-entry impact :velocities-after "BALL")
                             (x '(0 (* e (sqrt (* 2 g d))))))
             (is-same bridge "energy lost" (getf impact :energy-lost) (x '(* (- 1 (expt e 2)) m g d)))
             (is-energy-not-gained bridge scenario (getf impact :energy-lost)))))))))

(defun ball-with-topspin (mu)
  "The scenario text of a solid ball (I = 2/5 m r^2) thrown at 3 m/s with topspin (its rim
at 2 m/s, clockwise) that drops the height 1/5 onto a rough floor (friction MU, a string),
g = 10, e = 1/2: it lands at vy = -2, its contact point slipping forward at 1 m/s."
  (format nil "(scenario ball-with-topspin \"A ball with topspin lands on a rough floor.\"
     (parameters (m :positive (:value 1)) (r :positive (< r 1/2) (:value 1/10)))
     (gravity 10)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass m :inertia (* 2/5 m (expt r 2)) :shape (circle r)
           :position (0 (+ r 1/5)) :angular-velocity (- (/ 2 r)) :velocity (3 0))
     (restitution ball floor 1/2)
     (friction ball floor :static ~A)
     (simulate :states 2))" mu))

(defun ball-impact-check (mu vx omega jt)
  "Check the first impact of BALL-WITH-TOPSPIN at MU: the velocity after (VX 1), the
angular velocity OMEGA (an expression of r), the friction impulse JT along the tangent
(an expression of m), the energy lost >= 0."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string (ball-with-topspin mu))))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "BALL")
                             (list vx 1))
             (is-same bridge "angular velocity after"
                      (impact-entry impact :angular-velocities-after "BALL") (x omega))
             (is-same bridge "friction impulse"
                      (car (last (find :friction-impulse (getf impact :impulses) :key #'first)))
                      (x jt))
             (is-same bridge "normal impulse"
                      (car (last (find :impulse (getf impact :impulses) :key #'first)))
                      (x '(* 3 m)))
             (is-energy-not-gained bridge scenario (getf impact :energy-lost)))))))))

(test ball-with-topspin-sticks-on-a-rough-floor
  "mu = 1/2: the impulse needed to stop the slip, 2 m / 7, is within the cone mu Jn =
3 m / 2: the ball leaves rolling, with the angular momentum about the contact point kept:
vx' = (u - (2/5) r omega0) / (7/5) = 19/7, omega' = -vx' / r; the friction impulse
m (vx' - u) along -x is 2 m / 7 along the tangent (-1, 0)."
  (ball-impact-check "1/2" 19/7 '(- (/ 19 (* 7 r))) '(* 2/7 m)))

(test ball-with-topspin-slides-on-a-slippery-floor
  "mu = 1/20: the cone mu Jn = 3 m / 20 is less than the 2 m / 7 that would stop the slip:
the ball slides through the impact, vx' = 3 - mu Jn / m = 57/20, omega' = -2/r -
r mu Jn / I = -19 / (8 r), its contact point still slipping forward (19/40)."
  (ball-impact-check "1/20" 57/20 '(- (/ 19 (* 8 r))) '(* 3/20 m)))

(test yoyo-string-jerked-taut
  "A yo-yo falling freely the height s until its wound string jerks taut: v' = m r^2 v /
(I + m r^2), omega' = m r |v| / (I + m r^2), the jerk m I |v| / (I + m r^2), the energy
lost m g s I / (I + m r^2)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "yoyo-string-jerked-taut"))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (let ((speed (x '(sqrt (* 2 g s))))
                (k (x '(+ i (* m (expt r 2)))))
                (jerk (find-if (lambda (entry) (eq (first entry) :rope-impulse)) (getf impact :impulses))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "YOYO")
                               `(0 (- (/ (* ,(x '(* m (expt r 2))) ,speed) ,k))))
               (is-same bridge "angular velocity after" (impact-entry impact :angular-velocities-after "YOYO")
                        `(/ (* ,(x '(* m r)) ,speed) ,k))
               (is-same bridge "the jerk" (car (last jerk)) `(/ (* ,(x '(* m i)) ,speed) ,k))
               (is-same bridge "energy lost" (getf impact :energy-lost) `(/ ,(x '(* m g s i)) ,k))
               (is-energy-not-gained bridge scenario (getf impact :energy-lost))))))))))

(test massive-pulley-atwood-landing
  "The heavier mass of an Atwood machine over a massive pulley lands plastically: it stops,
its rope goes slack (no jerk: a rope's impulse, if reported, is 0), the lighter mass and the pulley keep their speeds, and the
energy lost is its (1/2) m1 v^2 = m1 (m1 - m2) g h R^2 / (I + (m1 + m2) R^2)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named-with-states "atwood-massive-pulley" 1))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "the heavy mass stops" (impact-entry impact :velocities-after "HEAVY") '(0 0))
             (is-same-vector bridge "the light mass keeps its velocity"
                             (impact-entry impact :velocities-after "LIGHT")
                             (impact-entry impact :velocities-before "LIGHT"))
             (is-same bridge "the pulley keeps its spin"
                      (impact-entry impact :angular-velocities-after "PULLEY")
                      (impact-entry impact :angular-velocities-before "PULLEY"))
             (dolist (entry (getf impact :impulses))
               (when (eq (first entry) :rope-impulse)
                 (is-same bridge "no jerk along a rope" (car (last entry)) 0)))
             (is-same bridge "energy lost" (getf impact :energy-lost)
                      (x '(/ (* m1 (- m1 m2) g h (expt big-r 2)) (+ i (* (+ m1 m2) (expt big-r 2))))))
             (is-energy-not-gained bridge scenario (getf impact :energy-lost)))))))))
