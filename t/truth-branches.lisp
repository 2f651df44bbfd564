;;;; t/truth-branches.lisp -- a run that branches where the assumptions leave the outcome open, each branch to its end.
;;;;
;;;; The ball thrown toward a low wall (scenarios/ball-toward-low-wall.lisp): whether it
;;;; clears the wall is a fact about the parameters, so the run forks; every branch must
;;;; then finish, which needs the truth layer to chain the branch's fact through square
;;;; roots (w > 0 and w < h - g d^2/(2 v0^2) give v0 sqrt(2 h/g) > d), the boundary branch
;;;; to keep the dropped parameter's assumptions, and non-selected branches to run
;;;; without the values that contradict their facts. Results are Maxima-checked under
;;;; each branch's facts.

(in-package #:ames.tests)

(in-suite truth-scenarios)

(defun branch-side (scenario branch over into)
  "Which way BRANCH's fact goes: :BOUNDARY for an equation, else :OVER or :INTO as it
holds at the parameter values OVER or INTO (alists by name), or NIL."
  (let ((relation (getf branch :assume)))
    (flet ((holds-at (values)
             (let ((difference (expression-value `(- ,(relation-lhs relation) ,(relation-rhs relation))
                                                 (in-scenario-terms scenario values))))
               (ecase (first relation)
                 ((> >=) (> difference 0)) ((< <=) (< difference 0)) (= nil)))))
      (cond ((eq (first relation) '=) :boundary)
            ((and (holds-at over) (not (holds-at into))) :over)
            ((and (holds-at into) (not (holds-at over))) :into)))))

(test ball-toward-a-low-wall-branches-and-every-branch-finishes
  "Over the wall (w below the ball's height at the wall): it lands at t = sqrt(2 h/g) at
x = v0 sqrt(2 h/g), beyond the wall, and slides on forever. Into the wall: a second fork
on whether it lands first (2 h v0^2 against g d^2), each sub-branch to its end; when it
does not land first it hits the wall at t = d/v0. At the boundary it hits the wall's top
at t = d/v0. With the defaults (--numeric) the branch over the wall is selected."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "ball-toward-low-wall"))
           (history (ames:simulate scenario :bridge bridge))
           (fork (first (ames::history-states history)))
           (branches (and fork (ames::state-branches fork)))
           (over '((m . 1) (g . 10) (h . 2) (d . 1) (v0 . 3) (w . 1)))
           (into '((m . 1) (g . 10) (h . 2) (d . 1) (v0 . 3) (w . 19/10))))
      (flet ((x (form) (in-scenario-terms scenario form))
             (side (branch) (branch-side scenario branch over into)))
        (is (eq :branched (ames::history-outcome history)))
        (is (finished-p history))
        (is (set-equal-p '(:over :into :boundary) (mapcar #'side branches)))
        (dolist (branch branches)
          (let ((first-state (first (getf branch :states))))
            (is (not (null first-state)))
            (when first-state
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (ames.maxima:with-assumptions
                     (bridge (if (getf branch :substitution) '() (list (getf branch :assume))))
                   (ecase (side branch)
                     (:over
                      (is (eq :complete (getf branch :outcome)))
                      (end-event-is first-state :collision "BALL" "FLOOR")
                      (is-same bridge "landing time" (ames::state-duration first-state)
                               (x '(sqrt (/ (* 2 h) g))))
                      (is-same bridge "landing place"
                               (first (per-body (ames::state-final-positions first-state) "BALL"))
                               (x '(* v0 (sqrt (/ (* 2 h) g))))))
                     (:into
                      (let ((inner (ames::state-branches first-state)))
                        (is (= 3 (length inner)))
                        (is (every (lambda (b) (eq :complete (getf b :outcome))) inner))
                        (let ((lands-later (find-if (lambda (b)
                                                      (let ((r (getf b :assume)))
                                                        (and (eq '> (first r))
                                                             (eql 0 (relation-rhs r))
                                                             (mentions-name-p "H" (relation-lhs r))
                                                             (> (expression-value (relation-lhs r) (in-scenario-terms scenario into)) 0))))
                                                    inner)))
                          (is (not (null lands-later)))
                          (when lands-later
                            (let ((hit (first (getf lands-later :states))))
                              (end-event-is hit :collision "BALL" "WALL")
                              (ames.maxima:with-assumptions (bridge (list (getf lands-later :assume)))
                                (is-same bridge "time to the wall" (ames::state-duration hit)
                                         (x '(/ d v0)))))))))
                     (:boundary
                      (is (eq :complete (getf branch :outcome)) "~S" (getf branch :failure))
                      (end-event-is first-state :collision "BALL" "WALL")
                      (is-same bridge "time to the wall's top" (ames::state-duration first-state)
                               (x '(/ d v0))))))))))))
      ;; the defaults select the branch over the wall
      (let* ((values (ames::run-parameter-values scenario :numeric t))
             (selected (ames:simulate scenario :bridge bridge :parameter-values values))
             (chosen (find-if (lambda (b) (getf b :selected))
                              (ames::state-branches (first (ames::history-states selected))))))
        (is (not (null chosen)))
        (when chosen
          (is (eq :over (branch-side scenario chosen over into))))))))

(defparameter *particle-in-a-bowl*
  '(scenario particle-in-a-bowl
    "A particle released at rest inside a fixed circular bowl, at angle theta0 from the bottom."
    (parameters (m :positive) (g :positive) (r :positive) (theta0 :positive (< theta0 (/ pi 2))))
    (gravity g)
    (body bowl :fixed t :shape (arc :center (0 r) :radius r :from pi :to (* 2 pi) :solid :outside))
    (body particle :mass m :position ((* r (sin theta0)) (- r (* r (cos theta0))))
                   :velocity (0 0) :shape point)
    (simulate :states 3))
  "A body that turns back on a curve: the energy integral vanishes at the mirror point
-theta0, a root of sin(s/r) = cos theta0 that solve() does not list.")

(test a-body-turning-back-on-a-curve-swings-between-its-turning-points
  "The particle in a bowl swings to -theta0 and back: it is not taken to the bowl's rim
with an imaginary speed, nor does it branch on the start's arc length. Its first state
is periodic forever, between the turning points s = r (pi/2 -+ theta0), with the
pendulum's period 4 sqrt(r/g) K(sin^2(theta0/2)) (Maxima-checked)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *particle-in-a-bowl*))
           (history (ames:simulate scenario :bridge bridge))
           (state (first (ames::history-states history)))
           (periodic (and state (ames.simulator:state-periodic state))))
      (is (eq :complete (ames::history-outcome history)))
      (is (eq :forever (and state (ames::state-duration state))))
      (is (not (null periodic)))
      (when periodic
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             ;; K's parameter sin^2(theta0/2) is (1 - cos theta0)/2
             (is-same bridge "period" (getf periodic :period)
                      (x '(* 4 (sqrt (/ r g)) (elliptic-k (/ (- 1 (cos theta0)) 2)))))
             (is-same bridge "first turning point" (first (getf periodic :between))
                      (x '(* r (- (/ pi 2) theta0))))
             (is-same bridge "second turning point" (second (getf periodic :between))
                      (x '(* r (+ (/ pi 2) theta0)))))))))))

(defparameter *particle-kicked-in-a-bowl*
  '(scenario particle-kicked-in-a-bowl
    "A particle at the bottom of a fixed circular bowl, given speed v0 along it."
    (parameters (m :positive) (g :positive) (r :positive) (v0 :positive (< v0 (sqrt (* 5 g r)))))
    (gravity g)
    (body bowl :fixed t :shape (arc :center (0 r) :radius r :from pi :to (* 2 pi) :solid :outside))
    (body particle :mass m :position (0 0) :velocity (v0 0) :shape point)
    (simulate :states 1))
  "Whether the particle reaches the bowl's rim is v0^2 against 2 g r (below sqrt(5 g r)
the normal force could not vanish on the bowl's far half, were it a whole circle).")

(test whether-a-body-reaches-the-end-of-a-curve-is-a-fact-not-a-guess
  "The particle kicked along the bottom of a bowl reaches the rim only if v0^2 >= 2 g r
(its speed squared there, v0^2 - 2 g r, must not be negative): the run branches on it.
Fast enough, it reaches the rim at s = 0 with speed sqrt(v0^2 - 2 g r); too slow, it
turns back, (:turns particle), at the height v0^2/(2 g) where its speed vanishes."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *particle-kicked-in-a-bowl*))
           (history (ames:simulate scenario :bridge bridge))
           (fork (first (ames::history-states history)))
           (branches (and fork (ames::state-branches fork))))
      (flet ((holds-at (branch v0)
               (let* ((relation (getf branch :assume))
                      (d (expression-value `(- ,(relation-lhs relation) ,(relation-rhs relation))
                                           (in-scenario-terms scenario `((m . 1) (g . 10) (r . 1) (v0 . ,v0))))))
                 (ecase (first relation) ((> >=) (> d 0)) ((< <=) (< d 0)) (= (zerop d))))))
        (is (= 3 (length branches)))
        (let ((fast (find-if (lambda (b) (and (not (eq '= (first (getf b :assume)))) (holds-at b 10)))
                             branches))
              (slow (find-if (lambda (b) (and (not (eq '= (first (getf b :assume)))) (holds-at b 1)))
                             branches)))
          (is (and fast slow (not (eq fast slow))))
          (when fast
            (let ((state (first (getf fast :states))))
              (end-event-is state :leaves "PARTICLE" "BOWL")
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (ames.maxima:with-assumptions (bridge (list (getf fast :assume)))
                   (is-same bridge "speed at the rim"
                            (second (per-body (ames::state-final-velocities state) "PARTICLE"))
                            (in-scenario-terms scenario '(sqrt (- (expt v0 2) (* 2 g r))))))))))
          (when slow
            (let ((state (first (getf slow :states))))
              (end-event-is state :turns "PARTICLE")
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (ames.maxima:with-assumptions (bridge (list (getf slow :assume)))
                   (is-same bridge "height of the turning point"
                            (second (per-body (ames::state-final-positions state) "PARTICLE"))
                            (in-scenario-terms scenario '(/ (expt v0 2) (* 2 g))))
                   (is-same-vector bridge "velocity at the turning point"
                                   (per-body (ames::state-final-velocities state) "PARTICLE")
                                   '(0 0))))))))))))
