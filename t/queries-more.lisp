;;;; t/queries-more.lisp -- the questions of "Queries, more questions" (issue 26) on runs with and
;;;; without branches (one answer per branch, with its facts), and the driven bodies of
;;;; the language page (a box on a conveyor belt). Answers are checked by Maxima
;;;; equivalence against formulas written here from the physics; helpers are in
;;;; t/queries-answers.lisp.

(in-package #:ames.tests)

(in-suite queries)

(test bouncing-ball-rest-time-distance-and-more
  "The ball dropped from h bouncing with e = 1/2: it comes to rest for good at the Zeno
sum sqrt(2h/g) (1 + 2 e/(1 - e)) = 3 sqrt(2h/g); it travels h (1 + e^2)/(1 - e^2) = 5h/3
in all, h/2 in its first bounce; it lands with vertical velocity -sqrt(2 g h); state 1
ends at 2 sqrt(2h/g) (asked both as (time (end 1)) and (value (time) :at (end 1))); it
first falls to h/2 at sqrt(h/g) and never reaches 2h."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "bouncing-ball"
                        "(query rest (time (:rest ball)))"
                        "(query dist (distance ball))"
                        "(query first-bounce (distance ball :during (start 1)))"
                        "(query vy (value (y (velocity ball)) :at (:collision ball floor)))"
                        "(query vx (value (x (velocity ball)) :at (end 0)))"
                        "(query end-1 (time (end 1)))"
                        "(query clock (value (time) :at (end 1)))"
                        "(query half (time (reaches (y ball) (/ h 2))))"
                        "(query twice (time (reaches (y ball) (* 2 h))))")))
           (history (ames:simulate scenario :bridge bridge)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "rest" (answer-value history "REST")
                    (x '(* (sqrt (/ (* 2 h) g)) (+ 1 (/ (* 2 1/2) (- 1 1/2))))))
           (is-same bridge "distance" (answer-value history "DIST")
                    (x '(/ (* h (+ 1 (expt 1/2 2))) (- 1 (expt 1/2 2)))))
           (is-same bridge "first bounce" (answer-value history "FIRST-BOUNCE") (x '(* 2 (/ h 4))))
           (is-same bridge "landing velocity" (answer-value history "VY") (x '(- (sqrt (* 2 g h)))))
           (is-same bridge "horizontal velocity" (answer-value history "VX") 0)
           (is-same bridge "end of state 1" (answer-value history "END-1") (x '(* 2 (sqrt (/ (* 2 h) g)))))
           (is-same bridge "clock at the end of state 1" (answer-value history "CLOCK")
                    (x '(* 2 (sqrt (/ (* 2 h) g)))))
           (is-same bridge "half height" (answer-value history "HALF") (x '(sqrt (/ h g))))
           (is (eq :never (first (answer-value history "TWICE"))))))))))

(defun boundary-substitution (bridge scenario facts &optional (names '("W" "H")))
  "For each equation among FACTS (a boundary branch's), the binding of the first of the
parameters NAMES it holds (linearly) that solves it: the values that put the branch
on its boundary, so that answers are compared there."
  (loop for fact in facts
        when (eq (first fact) '=)
          append (let ((unknown (find-if (lambda (name) (mentions-name-p name fact)) names)))
                   (and unknown
                        (let* ((symbol (in-scenario-terms scenario (intern unknown :ames.tests)))
                               (solutions (ames.maxima:solve-equations bridge (list fact) (list symbol))))
                          (is (= 1 (length solutions)) "~S solved for ~A: ~S" fact unknown solutions)
                          (first solutions))))))

(test every-query-kind-answers-per-branch
  "The ball thrown toward a low wall branches on whether it clears the wall and whether
it lands before reaching it. On every path each answer carries its path's facts, and
(on a boundary path, compared on the boundary): it lands at sqrt(2h/g) (the wall's
impulse is horizontal), asked as an event's time and as (value (time) :at EVENT); it falls
to the wall's height at sqrt(2(h - w)/g); its horizontal velocity on landing is 0 after a
(plastic) hit on the wall, else v0; its energy before landing is m g h after the hit, else
m g h + m v0^2/2; it rests for good from the later of its landing and its reaching the
wall (d/v0), and never when it clears the wall (it slides on); its curved path's length
is not answered, saying why; its lowest point in the state that ends on the floor is 0; a
proof and a parameter selection are answered too."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "ball-toward-low-wall"
                        "(query lands (time (:collision ball floor)))"
                        "(query clock (value (time) :at (:collision ball floor)))"
                        "(query wall-height (time (reaches (y ball) w)))"
                        "(query vx (value (x (velocity ball)) :at (:collision ball floor)))"
                        "(query energy (value (energy) :at (:collision ball floor)))"
                        "(query rest (time (:rest ball)))"
                        "(query path (distance ball))"
                        "(query falls (prove (<= (y ball) h)))"
                        "(query clears (parameter v0 :such-that (not (:collision ball wall))))"
                        "(query lowest (minimum (y ball) :during (:collision ball floor)))")))
           (history (ames:simulate scenario :bridge bridge))
           (paths (ames.simulator::history-paths history)))
      (is (> (length paths) 1))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (loop for (facts nil . states) in paths
              for k from 0
              for hit = (position-if (lambda (s) (ames.simulator::event-state (list s) '(:collision ball wall))) states)
              for landed = (position-if (lambda (s) (ames.simulator::event-state (list s) '(:collision ball floor))) states)
              for hit-first = (and hit (or (null landed) (< hit landed)))
              do (ames.maxima:with-assumptions
                     (bridge (append (ames:scenario-assumption-relations scenario)
                                     (remove '= facts :key #'first)))
                   (let ((boundary (boundary-substitution bridge scenario facts)))
                     (flet ((entry (name) (nth k (answers-named history name)))
                            (same (what actual expected)
                              (flet ((there (e) (ames.base:substitute-expressions boundary e)))
                                (is-same bridge (format nil "~A on path ~D" what k)
                                         (and actual (not (keywordp actual)) (there actual))
                                         (there (x expected))))))
                       (dolist (name '("LANDS" "CLOCK" "WALL-HEIGHT" "VX" "ENERGY" "REST" "PATH" "FALLS" "LOWEST"))
                         (is (equal facts (getf (cddr (entry name)) :assume)) "~A on path ~D" name k))
                       (when landed
                         (same "landing" (second (entry "LANDS")) '(sqrt (/ (* 2 h) g)))
                         (same "clock" (second (entry "CLOCK")) '(sqrt (/ (* 2 h) g)))
                         (same "vx" (second (entry "VX")) (if hit-first 0 'v0))
                         (same "lowest" (second (entry "LOWEST")) 0)
                         (same "energy" (second (entry "ENERGY"))
                               (if hit-first '(* m g h) '(+ (* m g h) (* 1/2 m (expt v0 2))))))
                       (cond ((and hit landed) (same "rest" (second (entry "REST"))
                                                     (if hit-first '(sqrt (/ (* 2 h) g)) '(/ d v0))))
                             (t (is (eq :unanswered (second (entry "REST"))) "rest ~S" (entry "REST"))))
                       (same "wall height" (second (entry "WALL-HEIGHT")) '(sqrt (/ (* 2 (- h w)) g)))
                       (is (eq :unanswered (second (entry "PATH"))))
                       (is (stringp (getf (cddr (entry "PATH")) :reason)))
                       (is (member (first (second (entry "FALLS"))) '(:true :unknown)) "~S" (entry "FALLS")))))))
      (is (= 1 (length (answers-named history "CLEARS")))))))

(defparameter *belt-text*
  "(scenario box-on-conveyor-belt
     \"A box set down at rest on a conveyor belt moving at constant speed v.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
                 (v :positive (:value 2)) (mu :positive (:value 1/2)))
     (gravity g)
     (body belt :driven t :velocity (v 0) :shape (half-plane (1 0) (0 0)))
     (body box :mass m :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
     (friction box belt :static mu)
     (simulate :states 3)
     (query catches-up (time (end 0)))
     (query slip (value (- (x belt) (x box)) :at (end 0)))
     (query speed (value (x (velocity box)) :at (start 1)))
     (query energy (value (energy) :at (end 0))))"
  "A box on a conveyor belt (a driven half-plane).")

(test box-on-a-conveyor-belt
  "A box set down at rest on a belt driven at v: kinetic friction mu m g accelerates it at
mu g until it moves with the belt, at v/(mu g), having slipped v^2/(2 mu g) behind the belt;
then it sticks and moves at v forever. The belt keeps its velocity; its drive balances the
friction and the box's weight, (mu m g, m g); the system's energy is the box's m v^2/2 (the
belt has no mass). A driven body with a :mass, or :fixed too, is refused."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text *belt-text*))
           (history (ames:simulate scenario :bridge bridge))
           (states (ames::history-states history)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "catches up" (answer-value history "CATCHES-UP") (x '(/ v (* mu g))))
           (is-same bridge "slip" (answer-value history "SLIP") (x '(/ (expt v 2) (* 2 mu g))))
           (is-same bridge "speed with the belt" (answer-value history "SPEED") (x 'v))
           (is-same bridge "energy" (answer-value history "ENERGY") (x '(* 1/2 m (expt v 2))))
           (is-same-vector bridge "the box's acceleration while it slips"
                           (per-body (ames::state-accelerations (first states)) "BOX") (x '((* mu g) 0)))
           (is-same-vector bridge "the belt's acceleration" (per-body (ames::state-accelerations (first states)) "BELT")
                           '(0 0))
           (let ((drive (find :drive (ames::state-forces-of (first states)) :key #'first)))
             (is-same-vector bridge "the drive's reaction" (third drive) (x '((* mu m g) (* m g)))))
           (is (eq :forever (ames::state-duration (second states))))
           (is-same-vector bridge "sticking" (per-body (ames::state-velocities (second states)) "BOX") (x '(v 0)))))))
    ;; a box thrown on faster than the belt (u > v) is slowed to the belt's speed instead,
    ;; after (u - v)/(mu g), having slipped (u - v)^2/(2 mu g) ahead
    (let* ((text (cl-ppcre:regex-replace
                  ":velocity \\(0 0\\) :shape \\(polygon"
                  (cl-ppcre:regex-replace "\\(mu :positive \\(:value 1/2\\)\\)" *belt-text*
                                          "(mu :positive (:value 1/2)) (u (> u v) (:value 3))")
                  ":velocity (u 0) :shape (polygon"))
           (scenario (scenario-from-text text))
           (history (ames:simulate scenario :bridge bridge)))
      (is (search "(u 0)" text))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (is-same bridge "slowed" (answer-value history "CATCHES-UP")
                  (in-scenario-terms scenario '(/ (- u v) (* mu g))))
         (is-same bridge "ahead" (answer-value history "SLIP")
                  (in-scenario-terms scenario '(- (/ (expt (- u v) 2) (* 2 mu g)))))
         (is-same bridge "with the belt" (answer-value history "SPEED") (in-scenario-terms scenario 'v)))))
    (signals ames:scenario-error
      (scenario-from-text (cl-ppcre:regex-replace "belt :driven t" *belt-text* "belt :driven t :mass 1")))
    (signals ames:scenario-error
      (scenario-from-text (cl-ppcre:regex-replace "belt :driven t" *belt-text* "belt :driven t :fixed t")))))

(test distance-and-state-times-per-branch
  "A block launched up a rough incline at v0 stops after v0/(g (sin a + mu cos a)), having
slid v0^2/(2 g (sin a + mu cos a)) (on every branch of the fork at its stop, asked as
(time (end 0)), (value (time) :at (end 0)) and (distance block :during (start 0))). Where it
sticks (mu cos a - sin a >= 0), that is all it travels and it rests for good from then;
where it slides back, it moves forever: neither is answered."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "block-launched-up-rough-incline"
                        "(query up (distance block :during (start 0)))"
                        "(query total (distance block))"
                        "(query stop (time (end 0)))"
                        "(query clock (value (time) :at (end 0)))"
                        "(query rest (time (:rest block)))")))
           (history (ames:simulate scenario :bridge bridge))
           (paths (ames.simulator::history-paths history)))
      (is (= 3 (length paths)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (loop for (facts) in paths
              for k from 0
              for sticks = (member (first (first facts)) '(> =))
              do (ames.maxima:with-assumptions
                     (bridge (append (ames:scenario-assumption-relations scenario) (remove '= facts :key #'first)))
                   (let ((boundary (boundary-substitution bridge scenario facts '("MU"))))
                   (flet ((entry (name) (nth k (answers-named history name)))
                          (is-same (bridge what actual expected)
                            (flet ((there (e) (ames.base:substitute-expressions boundary e)))
                              (is-same bridge what (and actual (not (keywordp actual)) (there actual))
                                       (there expected)))))
                     (dolist (name '("UP" "TOTAL" "STOP" "CLOCK" "REST"))
                       (is (equal facts (getf (cddr (entry name)) :assume))))
                     (let ((run-up (x '(/ (expt v0 2) (* 2 g (+ (sin a) (* mu (cos a)))))))
                           (stop (x '(/ v0 (* g (+ (sin a) (* mu (cos a))))))))
                       (is-same bridge "run up" (second (entry "UP")) run-up)
                       (is-same bridge "stop" (second (entry "STOP")) stop)
                       (is-same bridge "clock" (second (entry "CLOCK")) stop)
                       (cond (sticks
                              (is-same bridge "total" (second (entry "TOTAL")) run-up)
                              (is-same bridge "rest" (second (entry "REST")) stop))
                             (t (is (eq :unanswered (second (entry "TOTAL"))))
                                (is (eq :unanswered (second (entry "REST")))))))))))))))
