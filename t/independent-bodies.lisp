;;;; t/independent-bodies.lisp -- bodies that do not interact cost no more together than
;;;; apart (issue 23): the hoop and the disc released side by side in one scenario
;;;; (scenarios/hoop-and-disc-race-side-by-side.lisp), four bodies, the meetings of those
;;;; that do not touch set aside up to the disc's arrival (the horizon phase,
;;;; src/simulator/horizon-phase.lisp); four pucks stopping at once on a rough floor, their
;;;; 81 combinations of friction modes settled puck by puck (choice-clusters.lisp).
;;;;
;;;; Expected results (textbook), L = h / (2 sin a) the half slope: the disc rolls at
;;;; (2/3) g sin a and reaches its foot after sqrt(3 L / (g sin a)), which ends the state;
;;;; the hoop rolls at (1/2) g sin a and has then come 3 L / 4 down (its centre at
;;;; h / 8 + r cos a, above its foot's r cos a); along its motion in closed form it reaches
;;;; its foot after sqrt(4 L / (g sin a)): the disc first, sqrt(3)/2 of the hoop's time.
;;;; Compared by Maxima-checked equivalence under the scenario's assumptions.

(in-package #:ames.tests)

(def-suite independent-bodies :in all-tests
  :description "Bodies that do not interact: the hoop and the disc racing side by side in one
scenario (the disc first, both times in closed form); four pucks stopping at once.")

(in-suite independent-bodies)

(defun along-slope (scenario fraction)
  "The acceleration vector FRACTION g sin a down the slope of angle a, in SCENARIO's terms."
  (in-scenario-terms scenario (list `(* ,fraction g (sin a) (cos a))
                                    `(- (* ,fraction g (expt (sin a) 2))))))

(test hoop-and-disc-race-side-by-side
  "One state, both rolling (the disc at (2/3) g sin a, the hoop at (1/2) g sin a, static
friction m g sin a / 3 and / 2), ends with the disc at its foot after sqrt(3 L / (g sin a))
while the hoop is still on its slope, 3 L / 4 down; the hoop's own motion reaches its foot
at sqrt(4 L / (g sin a)), later: the disc's time is sqrt(3)/2 of it."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "hoop-and-disc-race-side-by-side"))
           (states (nth-value 1 (run-of scenario bridge)))
           (state (first states)))
      (is (= 1 (length states)) "one state: ~S" states)
      (when state
        (let ((end (ames::state-end-event state)))
          (is (and (consp end) (same-name-p* (second end) "DISC")) "the disc's arrival ends it: ~S" end)))
      (when state
        (flet ((x (form) (in-scenario-terms scenario form)))
          (let ((disc-time (x '(sqrt (/ (* 3 (/ h (* 2 (sin a)))) (* g (sin a))))))
                (hoop-time (x '(sqrt (/ (* 4 (/ h (* 2 (sin a)))) (* g (sin a))))))
                (hoop-at (per-body (ames::state-positions state) "HOOP")))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "the disc's acceleration"
                               (per-body (ames::state-accelerations state) "DISC") (along-slope scenario 2/3))
               (is-same-vector bridge "the hoop's acceleration"
                               (per-body (ames::state-accelerations state) "HOOP") (along-slope scenario 1/2))
               (check-friction bridge state "DISC" "INCLINE-1" :static (x '(/ (* m g (sin a)) 3)))
               (check-friction bridge state "HOOP" "INCLINE-2" :static (x '(/ (* m g (sin a)) 2)))
               (is-same bridge "the disc at its foot after sqrt(3 L / (g sin a))"
                        (ames::state-duration state) disc-time)
               (is-same-vector bridge "the disc at its foot"
                               (per-body (ames::state-final-positions state) "DISC")
                               (x '((+ (/ h (tan a)) (* r (sin a))) (* r (cos a)))))
               (is-same-vector bridge "the hoop 3 L / 4 down its slope then"
                               (per-body (ames::state-final-positions state) "HOOP")
                               (x '((+ d (/ (* 7 h) (* 8 (tan a))) (* r (sin a))) (+ (/ h 8) (* r (cos a))))))
               (is-same-vector bridge "the hoop's motion reaches its foot after sqrt(4 L / (g sin a))"
                               (subst hoop-time 'ames.base:tau hoop-at)
                               (x '((+ d (/ h (tan a)) (* r (sin a))) (* r (cos a)))))
               (is (eq :true (ames.algebra:decide bridge `(< ,(ames::state-duration state) ,hoop-time)))
                   "the disc first")
               (is-same bridge "the disc's time sqrt(3)/2 of the hoop's"
                        `(/ ,(ames::state-duration state) ,hoop-time) '(/ (sqrt 3) 2))))))))))

(defparameter *four-pucks*
  '(scenario four-pucks "Four pucks launched alike along a rough floor, far apart."
    (parameters (m :positive) (g :positive) (v0 :positive) (mu :positive))
    (gravity g)
    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
    (body p1 :mass m :position (0 0) :velocity (v0 0) :shape point)
    (body p2 :mass m :position (10 0) :velocity (v0 0) :shape point)
    (body p3 :mass m :position (20 0) :velocity (v0 0) :shape point)
    (body p4 :mass (* 2 m) :position (30 0) :velocity (v0 0) :shape point)
    (friction p1 floor :static mu)
    (friction p2 floor :static mu)
    (friction p3 floor :static mu)
    (friction p4 floor :static mu)
    (simulate :states 2))
  "Four pucks that stop at the same instant: 3^4 = 81 combinations of friction modes
there, more than the choice search enumerates at once.")

(test four-pucks-stop-at-once-and-rest
  "Each puck slides at -mu g and stops after v0 / (mu g), v0^2 / (2 mu g) on (textbook),
all at once; then each rests, its static friction 0, for ever: the stop's 81 combinations
of modes are settled puck by puck (each puck's own three), the whole checked consistent."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *four-pucks*))
           (states (nth-value 1 (run-of scenario bridge))))
      (is (= 2 (length states)) "two states: ~S" states)
      (when (= 2 (length states))
        (destructuring-bind (sliding resting) states
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "they stop after v0 / (mu g)" (ames::state-duration sliding)
                        (x '(/ v0 (* mu g))))
               (loop for (puck start) in '(("P1" 0) ("P2" 10) ("P3" 20) ("P4" 30))
                     do (is-same-vector bridge "sliding at -mu g"
                                        (per-body (ames::state-accelerations sliding) puck)
                                        (x '((- (* mu g)) 0)))
                        (is-same-vector bridge "v0^2 / (2 mu g) on"
                                        (per-body (ames::state-final-positions sliding) puck)
                                        (x `((+ ,start (/ (expt v0 2) (* 2 mu g))) 0)))
                        (is-same-vector bridge "at rest"
                                        (per-body (ames::state-accelerations resting) puck) '(0 0))
                        (check-friction bridge resting puck "FLOOR" :static 0))
               (is (eq :forever (ames::state-duration resting))
                   "at rest for ever: ~S" (ames::state-duration resting))))))))))
