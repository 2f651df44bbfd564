;;;; t/simulator-core.lisp -- the qualitative-state core on textbook scenarios it once got wrong:
;;;; contacts at a convex corner (alternatives, chosen by consistency), curved contacts beside
;;;; other bodies, and states whose start follows a curved one.
;;;;
;;;; Each scenario is a file under scenarios/; every expected result is the textbook's, over
;;;; the scenario's own parameters, compared by Maxima-checked equivalence.

(in-package #:ames.tests)

(in-suite simulator)

(defun arc-length-at (expression s)
  "EXPRESSION, a function of the simulator's arc-length variable, at arc length S."
  (substitute-expressions (list (cons 'ames.simulator::arc-length s)) expression))

(defun tried-assignments (state)
  "The assignments the choice search tried at the start of STATE, each a plist
(:ASSIGNMENT :VERDICT :DEGENERATE :WHY)."
  (getf (getf (ames.simulator:state-analysis state) :choices) :tried))

(test wedge-apex-particle-slides-down-the-slope
  "Released at the apex of the wedge (thesis figure 2-10), the particle slides down the
slope: the slope and the back face meet in a convex corner, so at most one of them holds;
pressing on the slope alone is the one non-degenerate consistent choice (the back face
alone would push with N = 0, and falling free only grazes it). The normal force is the
thesis's mp mw g cos a / (mw + mp sin^2 a), and the particle reaches the ground after
sqrt(2 h (mw + mp sin^2 a) / (g sin^2 a (mp + mw)))."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-at-wedge-apex"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (not (null state)))
        (when state
          (is (set-equal-p '(("PARTICLE" "WEDGE") ("WEDGE" "GROUND")) (contact-pairs state)))
          (let ((tried (tried-assignments state)))
            (is (= 3 (length tried)) "the corner's three options: ~S" tried)
            (is (= 3 (count :consistent tried :key (lambda (trial) (getf trial :verdict))))
                "all three are consistent: ~S" tried)
            (is (= 2 (count-if (lambda (trial) (plusp (getf trial :degenerate))) tried))
                "two are degenerate: ~S" tried))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "N" (normal-force-between state "PARTICLE" "WEDGE")
                      (x '(/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2))))))
             (is-same bridge "wedge's acceleration"
                      (first (per-body (ames::state-accelerations state) "WEDGE"))
                      (x '(- (/ (* mp g (sin a) (cos a)) (+ mw (* mp (expt (sin a) 2)))))))
             (is-same bridge "time to the ground" (ames::state-duration state)
                      (x '(sqrt (/ (* 2 h (+ mw (* mp (expt (sin a) 2))))
                                   (* g (expt (sin a) 2) (+ mp mw))))))
             ;; the horizontal momentum stays zero: mp x_p + mw x_w = 0 with x_p - x_w = h / tan a
             (is-same-vector bridge "lands at the foot of the slope"
                             (per-body (ames::state-final-positions state) "PARTICLE")
                             (x '((/ (* mw h) (* (tan a) (+ mp mw))) 0))))))))))

(test incline-top-corner-particle-slides-down
  "Released at the top corner of a fixed incline whose back face is vertical, the
particle slides down the slope with acceleration g sin a along it and N = m g cos a,
and reaches the floor at the incline's foot after sqrt(2 h / g) / sin a."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-at-incline-top"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (not (null state)))
        (when state
          (is (equal '(("PARTICLE" "INCLINE")) (contact-pairs state)))
          (let ((events (mapcar #'event-names (or (ames.simulator:state-simultaneous-events state)
                                                  (list (ames::state-end-event state))))))
            (is (member '(:collision "PARTICLE" "FLOOR") events :test #'equal) "events ~S" events))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "N" (normal-force-between state "PARTICLE" "INCLINE") (x '(* m g (cos a))))
             (is-same-vector bridge "acceleration down the slope"
                             (per-body (ames::state-accelerations state) "PARTICLE")
                             (x '((* g (sin a) (cos a)) (- (* g (expt (sin a) 2))))))
             (is-same bridge "time to the foot" (ames::state-duration state)
                      (x '(/ (sqrt (/ (* 2 h) g)) (sin a)))))))))))

(test table-top-left-corner-particle-slides-across-and-off
  "Starting at the table's top-left corner moving right, the particle slides along the
top (the left face, approached at the corner, is never hit: the particle stays outside
the top face), leaves the far edge after w / v0, flies, and lands on the floor after
sqrt(2 h / g) at w + v0 sqrt(2 h / g)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-across-table"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (= 3 (length states)))
        (destructuring-bind (&optional top flight ground) states
          (declare (ignore ground))
          (when (and top flight)
            (is (equal '(("PARTICLE" "TABLE")) (contact-pairs top)))
            (is (equal '(:leaves "PARTICLE" "TABLE" :endpoint) (event-names (ames::state-end-event top))))
            (is (null (contact-pairs flight)))
            (is (equal '(:collision "PARTICLE" "FLOOR") (event-names (ames::state-end-event flight))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "N on the top" (normal-force-between top "PARTICLE" "TABLE") (x '(* m g)))
               (is-same bridge "time across" (ames::state-duration top) (x '(/ w v0)))
               (is-same bridge "flight starts then" (ames::state-start flight) (x '(/ w v0)))
               (is-same bridge "flight time" (ames::state-duration flight) (x '(sqrt (/ (* 2 h) g))))
               (is-same-vector bridge "landing point"
                               (per-body (ames::state-final-positions flight) "PARTICLE")
                               (x '((+ w (* v0 (sqrt (/ (* 2 h) g)))) 0)))))))))))

(test quarter-circle-track-onto-the-floor
  "From rest at the top of a concave quarter-circle track, the particle reaches the
bottom with speed sqrt(2 g R), pressed by N = 3 m g there, meets the floor tangentially
(a contact, no impact) and slides on along it with that speed and N = m g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-down-quarter-circle"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (destructuring-bind (&optional curve floor) states
          (when (and curve floor)
            (is (equal '(("PARTICLE" "TRACK")) (contact-pairs curve)))
            (is (equal '(("PARTICLE" "FLOOR")) (contact-pairs floor)))
            (let ((events (mapcar #'event-names (ames.simulator:state-simultaneous-events curve))))
              (is (member '(:contact "PARTICLE" "FLOOR") events :test #'equal) "events ~S" events)
              (is (member '(:leaves "PARTICLE" "TRACK" :endpoint) events :test #'equal) "events ~S" events))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((end (ames.simulator:state-end-arc-length curve)))
                 (is (not (null end)))
                 (when end
                   (is-same bridge "N at the bottom"
                            (arc-length-at (normal-force-between curve "PARTICLE" "TRACK") end)
                            (x '(* 3 m g)))))
               (is-same bridge "time down the quarter circle: sqrt(r/g) K(1/2)"
                        (ames::state-duration curve) (x '(* (sqrt (/ r g)) (elliptic-k 1/2))))
               (is-same-vector bridge "velocity at the bottom"
                               (per-body (ames::state-final-velocities curve) "PARTICLE")
                               (x '((sqrt (* 2 g r)) 0)))
               (is-same bridge "N on the floor" (normal-force-between floor "PARTICLE" "FLOOR")
                        (x '(* m g)))
               (is-same-vector bridge "sliding on"
                               (per-body (ames::state-positions floor) "PARTICLE")
                               (x '((* (sqrt (* 2 g r)) tau) 0)))))))))))

(test sphere-lift-off-then-flight-clear-of-the-sphere
  "The thesis's sphere (section 2.6.3): from rest at theta0 from the top the particle
lifts off where cos theta = (2/3) cos theta0, with v^2 = (2/3) g r cos theta0, then flies
freely and never meets the sphere again."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-on-sphere"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (destructuring-bind (&optional slide flight) states
          (when (and slide flight)
            (is (equal '(:lift-off "PARTICLE" "SPHERE") (event-names (ames::state-end-event slide))))
            (is (eq :forever (ames::state-duration flight)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "lift-off point"
                               (per-body (ames::state-final-positions slide) "PARTICLE")
                               (x '((* r (sqrt (- 1 (* 4/9 (expt (cos theta0) 2)))))
                                    (* 2/3 r (cos theta0)))))
               (let ((v (per-body (ames::state-final-velocities slide) "PARTICLE")))
                 (is-same bridge "speed squared at lift-off"
                          `(+ (expt ,(first v) 2) (expt ,(second v) 2))
                          (x '(* 2/3 g r (cos theta0)))))))))))))

(test sphere-on-floor-slide-lift-off-flight-landing
  "The thesis's third example run to its end (section 2.6.3): the particle slides on the
sphere that stands on the floor, lifts off where cos theta = (2/3) cos theta0, flies
clear of the sphere, lands on the floor with v^2 = 2 g r (1 + cos theta0) (energy from
the height r (1 + cos theta0)), keeps the horizontal velocity sqrt(8 g r cos^3 theta0 / 27)
of lift-off (a plastic impact), and slides on the floor forever with N = m g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-on-sphere-on-floor"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (eq :complete (ames::history-outcome history)))
        (is (= 3 (length states)))
        (destructuring-bind (&optional slide flight floor) states
          (when (and slide flight floor)
            (is (equal '(:lift-off "PARTICLE" "SPHERE") (event-names (ames::state-end-event slide))))
            (is (eq :collision (first (ames::state-end-event flight))))
            (is (eq :forever (ames::state-duration floor)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "lift-off point (the sphere's centre at (0, r))"
                               (per-body (ames::state-final-positions slide) "PARTICLE")
                               (x '((* r (sqrt (- 1 (* 4/9 (expt (cos theta0) 2)))))
                                    (+ r (* 2/3 r (cos theta0))))))
               (let ((v (per-body (ames::state-final-velocities flight) "PARTICLE")))
                 (is-same bridge "speed squared just before landing"
                          `(+ (expt ,(first v) 2) (expt ,(second v) 2))
                          (x '(* 2 g r (+ 1 (cos theta0))))))
               (is-same-vector bridge "velocity after the plastic landing"
                               (per-body (ames::state-initial-velocities floor) "PARTICLE")
                               (x '((sqrt (* 8/27 g r (expt (cos theta0) 3))) 0)))
               (is-same bridge "N on the floor" (normal-force-between floor "PARTICLE" "FLOOR")
                        (x '(* m g)))))))))))
