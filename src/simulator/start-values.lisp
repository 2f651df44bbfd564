;;;; src/simulator/start-values.lisp -- a query about the start of the run where the first
;;;; state's motion has no closed form.
;;;;
;;;; A force acting at a point of a free rod, a rod released on a smooth floor: the motion
;;;; has no closed form in time, and the state's accelerations and forces are expressions
;;;; over the bodies' unknown positions, velocities, angles and angular velocities. At the
;;;; instant of release, what a textbook asks (the initial angular acceleration, the floor's
;;;; initial push), those are the scenario's own initial values: a value query at the start
;;;; of the run's first state reads the state's expressions with them put in. (Later states
;;;; start where an earlier one ended, possibly after an impact: their start stays
;;;; unanswered unless in closed form.)

(in-package #:ames.simulator)

(defvar *known-terms* '()
  "Quantity terms whose values are known at the point a query asks about, ((TERM . VALUE)
...), put into the state's expressions by QUANTITY-IN: the run's initial values at its
start (see the file header), else none.")

(defun run-start-state-p (states state)
  "True when STATE, one of the path STATES, starts the run: it starts at time 0 and only
forks (no period of motion) come before it."
  (let ((before (ldiff states (member state states))))
    (and (eql 0 (state-start state)) (every #'fork-state-p before))))

(defun initial-terms (scenario)
  "The quantity terms of SCENARIO's moving bodies at the start of the run, ((TERM . VALUE)
...): position and velocity, and a rotating body's angle and angular velocity."
  (loop for body in (scenario-bodies scenario)
        for name = (scenario-body-name body)
        unless (scenario-body-fixed-p body)
          append (destructuring-bind (&optional x y) (scenario-body-position body)
                   (destructuring-bind (&optional vx vy) (scenario-body-velocity body)
                     (append (and x (list (cons `(ames.kb:pos ,name :x) x) (cons `(ames.kb:pos ,name :y) y)))
                             (and vx (list (cons `(ames.kb:vel ,name :x) vx) (cons `(ames.kb:vel ,name :y) vy)))
                             (and (scenario-body-rotating-p body)
                                  (list (cons `(ames.kb:angle ,name) (scenario-body-angle body))
                                        (cons `(ames.kb:angvel ,name) (scenario-body-angular-velocity body)))))))))

(defun known-terms-at (scenario states state at)
  "The quantity terms known at the point AT (:START, :END or a local time) of STATE among
the path STATES: the initial values at the run's start, else NIL."
  (and (eq at :start) (run-start-state-p states state) (initial-terms scenario)))
