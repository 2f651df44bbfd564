;;;; t/rest-in-contact.lisp -- issue 20's class 10 (issue 21's witness case SEED=101 #718): bodies
;;;; that come to rest in contact stay there.
;;;;
;;;; After a plastic collision two bodies may rest against each other in equilibrium: every
;;;; velocity and every acceleration is zero. The state's ODEs then keep them there for
;;;; ever (simulator/equilibrium.lisp); AMES used to integrate such a state numerically from
;;;; its start rounded to doubles (sin(pi) = 1.2e-16) and end it with a turning point after
;;;; 1e-21 s, or said it could not go on without numbers. Fresh scenarios, the expected
;;;; results over their own parameters compared by Maxima-checked equivalence (helpers in
;;;; t/simulator-scenarios.lisp and t/springs-ropes-gravitation.lisp), and the self-check
;;;; passing under the default values.

(in-package #:ames.tests)

(def-suite rest-in-contact :in all-tests
  :description "Issue 20 class 10: bodies at rest in contact in equilibrium stay there.")

(in-suite rest-in-contact)

(defparameter *discs-meet-under-gravitation*
  "(scenario discs-meet-and-rest
     \"Two discs released at rest fall together under their gravitation and stick.\"
     (parameters (m1 :positive (:value 5)) (m2 :positive (:value 2)) (big-g :positive (:value 2))
                 (a :positive (:value 3/2)) (b :positive (:value 1/2))
                 (d :positive (> d (+ a b)) (:value 6)))
     (gravitation big-g) (restitution 0)
     (body first :mass m1 :position (0 0) :velocity (0 0) :shape (circle a))
     (body second :mass m2 :position (0 d) :velocity (0 0) :shape (circle b))
     (simulate :states 3))"
  "Two discs of different sizes and masses on the y axis, falling together under their
mutual gravitation; the collision is plastic.")

(defparameter *discs-stick-on-a-floor*
  "(scenario discs-stick-on-floor
     \"Two discs with opposite momenta slide together on a smooth floor and stick.\"
     (parameters (m1 :positive (:value 2)) (m2 :positive (:value 3)) (g :positive (:value 981/100))
                 (r :positive (:value 1/2)) (v :positive (:value 3))
                 (l :positive (> l (* 2 r)) (:value 4)))
     (gravity g) (restitution 0)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body left :mass m1 :position (0 r) :velocity (v 0) :shape (circle r))
     (body right :mass m2 :position (l r) :velocity ((- (/ (* m1 v) m2)) 0) :shape (circle r))
     (simulate :states 3))"
  "Two discs on a smooth floor, their momenta m1 v and -m1 v opposite; plastic collision.")

(defun resting-state-checks (history)
  "Check that HISTORY ends complete with two states, the second at rest for ever (its
bodies' motion constant, every acceleration zero, its initial velocities zero), and
return that state."
  (let ((states (ames::history-states history)))
    (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
    (is (= 2 (length states)) "~D states" (length states))
    (let ((rest (second states)))
      (when rest
        (is (eq :forever (ames::state-duration rest)))
        (is (eq :none (ames::state-end-event rest)))
        (is (equal '(:constant) (remove-duplicates (mapcar #'second (getf (ames::state-analysis rest)
                                                                          :integrators)))))
        (dolist (entry (ames::state-accelerations rest))
          (is (equal '(0 0) (second entry)) "acceleration of ~A: ~S" (first entry) (second entry)))
        (dolist (entry (ames:state-initial-velocities rest))
          (is (equal '(0 0) (second entry)) "velocity of ~A: ~S" (first entry) (second entry))))
      rest)))

(defun discs-pressed-force (state)
  "The normal force between the bodies FIRST and SECOND in STATE, either way round."
  (or (normal-force-between state "FIRST" "SECOND") (normal-force-between state "SECOND" "FIRST")))

(test discs-meeting-under-gravitation-rest-in-contact
  "The discs meet after the gravitation time, collide plastically (both at rest: their
momenta are opposite) and stay pressed together: the first (mass m1, radius a, at the
origin) has moved m2 (d - a - b)/(m1 + m2) toward the second, the centre of mass stays at
m2 d/(m1 + m2), the contact presses with G m1 m2/(a + b)^2, and the energy is
-G m1 m2/(a + b) for ever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text *discs-meet-under-gravitation*))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (rest (resting-state-checks history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (when rest
          (is (equal '(:collision "FIRST" "SECOND")
                     (event-names (ames::state-end-event (first (ames::history-states history))))))
          (is (= 1 (length (contact-pairs rest))))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "where the first rests" (per-body (ames::state-positions rest) "FIRST")
                             (x '(0 (/ (* m2 (- d a b)) (+ m1 m2)))))
             (is-same-vector bridge "where the second rests" (per-body (ames::state-positions rest) "SECOND")
                             (x '(0 (/ (+ (* m1 (+ a b)) (* m2 d)) (+ m1 m2)))))
             (is-same bridge "pressed together" (discs-pressed-force rest)
                      (x '(/ (* big-g m1 m2) (expt (+ a b) 2))))
             (is-same bridge "the energy" (total-energy rest) (x '(- (/ (* big-g m1 m2) (+ a b)))))
             (is-same bridge "the momentum" (total-momentum rest :y) 0))))))
    (let* ((numeric (ames:run-scenario (scenario-from-text *discs-meet-under-gravitation*)
                                       :bridge bridge :numeric t))
           (check (ames.check:self-check-result numeric)))
      (resting-state-checks numeric)
      (is (null (getf check :failures)) "self-check failures ~S" (getf check :failures))
      (is (equal '(0 1) (getf check :checked)) "checked ~S" (getf check :checked)))))

(test discs-with-opposite-momenta-stick-at-rest-on-a-floor
  "On a smooth floor the discs (momenta m1 v and -m1 v) meet after m2 (l - 2 r)/((m1 +
m2) v) and the plastic collision stops both: they rest for ever touching, the left at x =
m2 (l - 2 r)/(m1 + m2), the right 2 r further, the floor bearing m1 g and m2 g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text *discs-stick-on-a-floor*))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (rest (resting-state-checks history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (when rest
          (is (equal '(:collision "LEFT" "RIGHT")
                     (event-names (ames::state-end-event (first (ames::history-states history))))))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "time to meet" (ames::state-duration (first (ames::history-states history)))
                      (x '(/ (* m2 (- l (* 2 r))) (* (+ m1 m2) v))))
             (is-same-vector bridge "where the left rests" (per-body (ames::state-positions rest) "LEFT")
                             (x '((/ (* m2 (- l (* 2 r))) (+ m1 m2)) r)))
             (is-same-vector bridge "where the right rests" (per-body (ames::state-positions rest) "RIGHT")
                             (x '((+ (/ (* m2 (- l (* 2 r))) (+ m1 m2)) (* 2 r)) r)))
             (is-same bridge "the floor bears the left" (normal-force-between rest "LEFT" "FLOOR")
                      (x '(* m1 g)))
             (is-same bridge "the floor bears the right" (normal-force-between rest "RIGHT" "FLOOR")
                      (x '(* m2 g)))
             (is-same bridge "the energy" (total-energy rest) (x '(* (+ m1 m2) g r))))))))
    (let* ((numeric (ames:run-scenario (scenario-from-text *discs-stick-on-a-floor*)
                                       :bridge bridge :numeric t))
           (check (ames.check:self-check-result numeric)))
      (resting-state-checks numeric)
      (is (null (getf check :failures)) "self-check failures ~S" (getf check :failures))
      (is (equal '(0 1) (getf check :checked)) "checked ~S" (getf check :checked)))))

(test particle-at-rest-on-a-dome-top-stays
  "A particle at rest exactly on the top of a fixed circle (radius r) under gravity g is
in equilibrium (an unstable one): the motion the equations give keeps it there for ever,
the dome bearing m g (AMES used to stop, unable to choose a direction from a tangential
acceleration of 0)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text "
(scenario dome-top \"A particle at rest on the top of a dome.\"
  (parameters (m :positive) (g :positive) (r :positive))
  (gravity g)
  (body dome :fixed t :position (0 0) :shape (circle r))
  (body particle :mass m :position (0 r) :velocity (0 0) :shape point)
  (simulate :states 2))"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
      (when state
        (is (eq :forever (ames::state-duration state)))
        (is (equal '(0 0) (per-body (ames::state-accelerations state) "PARTICLE")))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same-vector bridge "it stays on the top" (per-body (ames::state-positions state) "PARTICLE")
                           (in-scenario-terms scenario '(0 r)))
           (is-same bridge "the dome bears it" (normal-force-between state "PARTICLE" "DOME")
                    (in-scenario-terms scenario '(* m g)))))))))
