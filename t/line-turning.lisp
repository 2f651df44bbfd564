;;;; t/line-turning.lisp -- turning points of one-degree-of-freedom motion along a straight
;;;; line (issue 20, class 2): a probe launched away from a planet below the escape speed
;;;; turns where its energy integral vanishes and falls back; at or above it, it escapes.
;;;;
;;;; Along the line of centres, s the distance, s'^2 = v0^2 - 2 G M (1/r - 1/s): the probe
;;;; turns at s = 2 G M r / (2 G M - r v0^2) (checked by Maxima equivalence); two free
;;;; bodies flying apart with zero total momentum at relative speed u from distance d turn
;;;; at 2 G (m1 + m2) d / (2 G (m1 + m2) - d u^2). The self-check's event search sees the
;;;; knowledge base's turning event: the old claim "it rises forever" is caught.

(in-package #:ames.tests)

(def-suite line-turning :in all-tests
  :description "Turning points along a straight line: a probe below and above the escape speed.")

(in-suite line-turning)

(defparameter *probe-launched-sideways*
  "(scenario probe-launched-sideways
     \"A probe launched along +x from a planet declared after it, too slowly to escape.\"
     (parameters (m :positive (:value 1)) (big-m :positive (:value 1000)) (big-g :positive (:value 1))
                 (r :positive (:value 10))
                 (v0 :positive (< v0 (sqrt (/ (* 2 big-g big-m) r))) (:value 5)))
     (gravitation big-g)
     (body probe :mass m :position (r 0) :velocity (v0 0) :shape point)
     (body planet :mass big-m :fixed t :position (0 0) :shape (circle r))
     (simulate :states 1))"
  "A fresh probe below the escape speed, the planet second, the launch along +x.")

(defparameter *bodies-flying-apart*
  "(scenario bodies-flying-apart
     \"Two free bodies flying apart with zero total momentum, too slowly to escape.\"
     (parameters (m1 :positive (:value 2)) (m2 :positive (:value 1)) (big-g :positive (:value 1))
                 (d :positive (:value 3))
                 (w :positive (< w (sqrt (/ (* 2 big-g) (* d (+ m1 m2))))) (:value 1/4)))
     (gravitation big-g)
     (body first :mass m1 :position (0 0) :velocity ((- (* m2 w)) 0) :shape point)
     (body second :mass m2 :position (d 0) :velocity ((* m1 w) 0) :shape point)
     (simulate :states 1))"
  "Relative speed u = (m1 + m2) w from distance d.")

(defparameter *probe-at-escape-speed*
  "(scenario probe-at-escape-speed
     \"A probe launched at exactly the escape speed.\"
     (parameters (m :positive (:value 1)) (big-m :positive (:value 1000)) (big-g :positive (:value 1))
                 (r :positive (:value 10)))
     (gravitation big-g)
     (body planet :mass big-m :fixed t :position (0 0) :shape (circle r))
     (body probe :mass m :position (0 r) :velocity (0 (sqrt (/ (* 2 big-g big-m) r))) :shape point)
     (simulate :states 2))"
  "Exactly at the escape speed the energy integral 2 G M / s never vanishes.")

(defun scenario-file-forms (name)
  "The scenarios of scenarios/NAME.lisp."
  (ames:read-scenario-file (find name (scenario-files) :key #'pathname-name :test #'string=)))

(defun history-of-text (text bridge)
  "The (scenario SIMULATE) history of the scenario written in TEXT, and the scenario."
  (let ((scenario (first (ames:read-scenarios-from-string text))))
    (values (ames:simulate scenario :bridge bridge) scenario)))

(test a-probe-below-escape-speed-turns-where-its-energy-integral-vanishes
  "Launched along +x at v0 < sqrt(2 G M / r), the probe stops at x = 2 G M r / (2 G M -
r v0^2): the state ends with (:turns probe), at rest there."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (history scenario) (history-of-text *probe-launched-sideways* bridge)
      (let ((state (first (ames::history-states history))))
        (is (null (ames::state-branches state)) "the declared bound leaves nothing to branch on")
        (end-event-is state :turns "PROBE")
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "turning point" (per-body (ames::state-final-positions state) "PROBE")
                             (list (x '(/ (* 2 big-g big-m r) (- (* 2 big-g big-m) (* r (expt v0 2))))) 0))
             (is-same-vector bridge "velocity at the turn" (per-body (ames::state-final-velocities state) "PROBE")
                             '(0 0)))))))))

(test two-bodies-flying-apart-turn-at-the-reduced-problems-distance
  "Two free bodies flying apart (zero total momentum, relative speed u = (m1 + m2) w)
stop where their distance is 2 G (m1 + m2) d / (2 G (m1 + m2) - d u^2); the event names
the second body."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (history scenario) (history-of-text *bodies-flying-apart* bridge)
      (let ((state (first (ames::history-states history))))
        (end-event-is state :turns "SECOND")
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (let ((x1 (first (per-body (ames::state-final-positions state) "FIRST")))
                   (x2 (first (per-body (ames::state-final-positions state) "SECOND")))
                   (u (x '(* (+ m1 m2) w))))
               (is-same bridge "distance at the turn" `(- ,x2 ,x1)
                        (x `(/ (* 2 big-g (+ m1 m2) d) (- (* 2 big-g (+ m1 m2)) (* d (expt ,u 2))))))
               ;; the centre of mass stays at m2 d / (m1 + m2)
               (is-same bridge "centre of mass" (x `(/ (+ (* m1 ,x1) (* m2 ,x2)) (+ m1 m2)))
                        (x '(/ (* m2 d) (+ m1 m2))))))))))))

(test a-probe-below-escape-speed-falls-back-and-collides
  "The file's probe below the escape speed, along the branch its values select: it turns,
then falls back and collides with the planet at s = r with the speed v0 it left with."
  (with-fixture simulator-bridge ()
    (let* ((scenario (find "PROBE-BELOW-ESCAPE-SPEED" (scenario-file-forms "probe-escape-speed")
                           :key (lambda (s) (string (ames:scenario-name s))) :test #'string=))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (states (remove-if #'ames::state-branches (ames.check::checked-path (ames::history-states history)))))
      (is (null (ames.check:self-check-failed-p history)))
      (is (<= 2 (length states)))
      (when (<= 2 (length states))
        (end-event-is (first states) :turns "PROBE")
        (end-event-is (second states) :collision "PROBE" "PLANET")
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "landing point" (per-body (ames::state-final-positions (second states)) "PROBE")
                             (list 0 (x 'r))))))))))

(test a-probe-at-or-above-escape-speed-escapes-forever
  "At the escape speed exactly, and above it (the file's second scenario), the energy
integral stays positive: nothing more changes, the state lasts forever."
  (with-fixture simulator-bridge ()
    (let ((exact (history-of-text *probe-at-escape-speed* bridge))
          (above (ames:simulate (find "PROBE-ABOVE-ESCAPE-SPEED" (scenario-file-forms "probe-escape-speed")
                                      :key (lambda (s) (string (ames:scenario-name s))) :test #'string=)
                                :bridge bridge)))
      (dolist (history (list exact above))
        (let ((state (first (ames::history-states history))))
          (is (eq :complete (ames::history-outcome history)))
          (is (null (ames::state-branches state)))
          (is (eq :forever (ames::state-duration state))))))))

(test the-self-check-catches-a-probe-claimed-to-rise-forever
  "The knowledge base owns the turning event, so the self-check's event search sees it:
the probe's state claimed to last forever (the old wrong answer), or to end later than
the turn, fails naming the turn."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *probe-launched-sideways*)))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (state (first (ames:history-states history))))
      (is (eq :checked (getf (state-check state history) :status)))
      (let ((duration (ames:state-duration state)) (end (ames::state-end-event state)))
        (setf (ames::state-duration state) :forever
              (ames::state-end-event state) :none)
        ;; within 1 time unit: the turn is at 0.598, the return to the planet at 1.196
        (let ((verdict (ames.check:check-state state (ames:history-parameter-values history) :horizon 1)))
          (is (eq :failed (getf verdict :status)) "~S" verdict)
          (is (some (lambda (claim) (and (search "before the end" claim) (search "turns" claim)))
                    (failed-claims verdict))
              "~S" (failed-claims verdict)))
        (setf (ames::state-duration state) `(* 11/10 ,duration)
              (ames::state-end-event state) end)
        (let ((verdict (state-check state history)))
          (is (eq :failed (getf verdict :status)) "~S" verdict))
        (setf (ames::state-duration state) duration)))))

;;; Springs: one oscillation, periodic forever

(defparameter *mass-on-a-spring*
  "(scenario mass-on-a-spring
     \"A block on a frictionless floor, tied by a spring to a point of the floor, pulled out and released.\"
     (parameters (m :positive (:value 2)) (k :positive (:value 8)) (g :positive (:value 10))
                 (l0 :positive (:value 1)) (a :positive (< a l0) (:value 1/2)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body block :mass m :position ((+ l0 a) 0) :velocity (0 0) :shape point)
     (spring coupling :from (floor (0 0)) :to (block (0 0)) :stiffness k :rest-length l0)
     (simulate :states 2))"
  "Released at stretch a < l0: x = l0 + a cos(sqrt(k/m) tau), between l0 - a and l0 + a
(with a > l0 the spring would shrink to zero length and open on the other side).")

(defparameter *two-masses-without-drift*
  "(scenario two-masses-without-drift
     \"Two particles joined by a spring, pushed apart with zero total momentum.\"
     (parameters (m1 :positive (:value 1)) (m2 :positive (:value 2)) (k :positive (:value 3))
                 (g :positive (:value 10)) (l0 :positive (:value 1))
                 (w :positive (< w (* l0 (sqrt (/ k (* m1 m2 (+ m1 m2)))))) (:value 1/2)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body first :mass m1 :position (0 0) :velocity ((- (* m2 w)) 0) :shape point)
     (body second :mass m2 :position (l0 0) :velocity ((* m1 w) 0) :shape point)
     (spring coupling :from (first (0 0)) :to (second (0 0)) :stiffness k :rest-length l0)
     (simulate :states 2))"
  "The centre of mass stays put: the stretch oscillates with the reduced mass, with an
amplitude (m1 + m2) w sqrt(m1 m2 / (k (m1 + m2))) below l0 (above it the spring would
shrink to zero length).")

(defun periodic-note (history)
  "The :PERIODIC note of HISTORY's first state, checking that it lasts forever."
  (let ((state (first (ames::history-states history))))
    (is (eq :complete (ames::history-outcome history)))
    (is (eq :forever (ames::state-duration state)))
    (ames.simulator:state-periodic state)))

(test a-mass-on-a-spring-oscillates-with-period-two-pi-root-m-over-k
  "The block swings forever between x = l0 - a and l0 + a with the period 2 pi sqrt(m/k)."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (history scenario) (history-of-text *mass-on-a-spring* bridge)
      (let ((periodic (periodic-note history)))
        (is (not (null periodic)))
        (when periodic
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "period" (getf periodic :period) (x '(* 2 pi (sqrt (/ m k)))))
               (is-same-vector bridge "turning points" (getf periodic :between)
                               (x '((- l0 a) (+ l0 a))))))))))))

(test two-free-masses-on-a-spring-oscillate-with-the-reduced-mass
  "Two masses pushed apart with zero total momentum oscillate with the period
2 pi sqrt(mu/k), mu = m1 m2/(m1 + m2); two-masses-on-a-spring.lisp, whose centre of mass
drifts, is no periodic state."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (history scenario) (history-of-text *two-masses-without-drift* bridge)
      (let ((periodic (periodic-note history)))
        (is (not (null periodic)))
        (when periodic
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "period" (getf periodic :period)
                        (x '(* 2 pi (sqrt (/ (* m1 m2) (* k (+ m1 m2)))))))))))))
    (let* ((scenario (first (scenario-file-forms "two-masses-on-a-spring")))
           (history (ames:simulate scenario :bridge bridge)))
      (is (null (periodic-note history))))))

;;; A ceiling above the probe: it turns below it, or hits it

(defparameter *probe-under-a-ceiling*
  "(scenario probe-under-a-ceiling
     \"A probe launched straight up below the escape speed toward a ceiling at height h.\"
     (parameters (m :positive (:value 1)) (big-m :positive (:value 1000)) (big-g :positive (:value 1))
                 (r :positive (:value 10)) (h :positive (> h r) (:value 20))
                 (v0 :positive (< v0 (sqrt (/ (* 2 big-g big-m) r))) (:value 5)))
     (gravitation big-g)
     (body planet :mass big-m :fixed t :position (0 0) :shape (circle r))
     (body ceiling :fixed t :shape (half-plane (0 h) (1 h)))
     (body probe :mass m :position (0 r) :velocity (0 v0) :shape point)
     (simulate :states 1))"
  "The probe reaches the ceiling only when its energy integral is positive there: h below
the turning height 2 G M r/(2 G M - r v0^2) = 11.43.")

(test a-probe-turns-below-a-ceiling-beyond-its-reach
  "Along the branch the values select: with h = 20 the probe turns (the ceiling is beyond
its reach); with h = 11 it hits the ceiling."
  (with-fixture simulator-bridge ()
    (dolist (case '((20 :turns "PROBE") (11 :collision "PROBE" "CEILING")))
      (destructuring-bind (h kind &rest bodies) case
        (let* ((scenario (first (ames:read-scenarios-from-string *probe-under-a-ceiling*)))
               (history (ames:run-scenario scenario :bridge bridge :numeric t
                                                    :settings (list (cons "H" h))))
               (states (remove-if #'ames::state-branches
                                  (ames.check::checked-path (ames::history-states history)))))
          (is (= 1 (length states)) "h = ~A: ~D states" h (length states))
          (when states
            (apply #'end-event-is (first states) kind bodies))
          (is (null (ames.check:self-check-failed-p history))))))))
