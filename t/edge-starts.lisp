;;;; t/edge-starts.lisp -- starts on an edge of the modes: a state that starts exactly at
;;;; rest at a turning point, and a body held at rest by more supports than the equations
;;;; fix (statically indeterminate).
;;;;
;;;; Expected results (textbook):
;;;; - A simple pendulum released at rest with its rope horizontal (theta0 = pi/2) swings to
;;;;   the mirror point at the same height, at rest, after half the period
;;;;   2 sqrt(l/g) K(sin^2(theta0/2)) = 2 sqrt(l/g) K(1/2), and back. Each turn is now put
;;;;   exactly at rest (src/simulator/turning-point-snapping.lisp), and the next swing
;;;;   starts from rest: the rope piece can only keep its direction at that instant, and
;;;;   that mode's exit, judged by the local series after the start, fires at once (the
;;;;   bob accelerates across the rope): the piece turns from the start
;;;;   (src/simulator/choice.lisp, FORCED-EXIT). Before, that start was refused ("no set of
;;;;   contacts and modes is consistent").
;;;; - A particle of mass m at rest on a rough incline (sin a = 3/5, mu_s = 1/2) tied by a
;;;;   rope up the slope: the tension T and static friction share m g sin a, with T >= 0
;;;;   and |F| <= mu_s m g cos a; T ranges over [m g (sin a - mu_s cos a), m g (sin a +
;;;;   mu_s cos a)] = [m g / 5, m g]. With the incline pulley of t/closing-at-pulley.lisp
;;;;   held at its pulley (m1 = 5/2, g = 10, sin a = 4/5, mu_s = 1/5), T + F = 20, |F| <= 3:
;;;;   T in [17, 23]. Refused as STATICALLY-INDETERMINATE naming the particle, with the
;;;;   range (src/simulator/indeterminate-forces.lisp).

(in-package #:ames.tests)

(def-suite edge-starts :in all-tests
  :description "A start exactly at rest at a turning point; statically indeterminate rest
refused as such, with the range of the shared forces.")

(in-suite edge-starts)

(defparameter *horizontal-rope-pendulum*
  "(scenario horizontal-rope-pendulum \"A particle on a taut horizontal rope released at rest.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (l :positive (:value 1)))
     (gravity g)
     (body ceiling :fixed t :position (0 0) :shape point)
     (body bob :mass m :position (l 0) :velocity (0 0) :shape point)
     (rope cord :length l :through ((ceiling (0 0)) (bob (0 0))))
     (simulate :states 3))"
  "The simple pendulum released at rest with its rope horizontal.")

(test a-rope-pendulum-turns-back-from-rest-exactly
  "Three swings from the horizontal (g = 10, l = 1): each ends (:turns BOB) exactly at
rest (velocity 0, not a round-off), on the circle x^2 + y^2 = l^2 (Maxima), at the
mirror point (-+1, 0) to 1e-7 (energy), after half the period 2 sqrt(l/g) K(1/2); the
swings after the first start at rest and run; the self-check passes."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-of-text *horizontal-rope-pendulum*))
           (history (ames:run-scenario scenario :numeric t :bridge bridge))
           (states (ames:history-states history))
           (half-period (* 2 (sqrt (/ 1d0 10)) (expression-value '(elliptic-k 1/2))))
           (values (mapcar (lambda (entry) (cons (in-scenario-terms scenario (car entry)) (cdr entry)))
                           '((l . 1) (g . 10) (m . 1))))
           (l (in-scenario-terms scenario 'l)))
      (is (null (ames.check:self-check-failed-p history)))
      (is (= 3 (length states)) "~A states" (length states))
      (loop for state in states
            for side = -1 then (- side)
            for end = (per-body (ames::state-final-positions state) "BOB")
            for velocity = (per-body (ames::state-final-velocities state) "BOB")
            do (is (equal '(:turns "BOB") (event-names (ames::state-end-event state))))
               (is (equal '(0 0) velocity) "not exactly at rest: ~S" velocity)
               (is (same-expression-p bridge `(+ (expt ,(first end) 2) (expt ,(second end) 2)) `(expt ,l 2))
                   "off the circle: ~S" end)
               (is (< (abs (- (expression-value (first end) values) side)) 1d-7))
               (is (< (abs (expression-value (second end) values)) 1d-7))
               (let ((duration (expression-value (ames::state-duration state) values)))
                 (is (and (realp duration) (< (abs (- duration half-period)) (* 1d-7 half-period)))
                     "half period ~A, expected ~A" duration half-period))))))

(test a-one-option-mode-whose-exit-fires-at-once-takes-its-transition
  "FORCED-EXIT: a mode point with one option (a stale mode's only successor) is no
choice, and its exit that surely fires at once is taken; a point with two options is
left to the search."
  (let* ((condition (ames.engine::make-termination-condition
                     :mode-transition '(span s) '(> x 0) '(:mode (span s) :from :fixed :to :turning)))
         (violations (list (list '(span s) :true nil '(:turns s) condition))))
    (flet ((point (options)
             (ames.engine::make-choice-point '(span s) :mode options :fixed '())))
      (is (equal '(:mode (span s) :from :fixed :to :turning)
                 (ames.simulator::forced-exit (list (point '(:fixed))) violations)))
      (is (null (ames.simulator::forced-exit (list (point '(:fixed :turning))) violations)))
      (is (equal '(:mode (span s) :from :fixed :to :turning)
                 (ames.simulator::forced-exit '() violations))))))

(defparameter *tied-on-rough-incline*
  "(scenario tied-on-rough-incline \"A particle at rest on a rough incline, tied up the slope.\"
     (parameters (m :positive) (g :positive))
     (gravity g)
     (body incline :fixed t :shape (polygon (0 0) (4 0) (4 3)))
     (body peg :fixed t :position (4 3) :shape point)
     (body particle :mass m :position (2 3/2) :velocity (0 0) :shape point)
     (friction particle incline :static 1/2 :kinetic 1/4)
     (rope tie :length 5/2 :through ((peg (0 0)) (particle (0 0))))
     (simulate :states 2))"
  "A particle at rest on a rough incline (sin a = 3/5, mu_s = 1/2), tied by a taut rope
to a peg up the slope.")

(defun indeterminate-refusal-of (scenario bridge)
  "The STATICALLY-INDETERMINATE condition SCENARIO's run signals, or NIL."
  (handler-case (progn (simulate-stopping-when-ambiguous scenario bridge) nil)
    (ames.simulator:statically-indeterminate (condition) condition)))

(defun share-range (refusal name)
  "The range (LOW HIGH) of the shared unknown whose head is named NAME in REFUSAL, from
its value over the free unknown and the free unknown's one lower and one upper bound."
  (let* ((free (ames.simulator:indeterminate-free refusal))
         (entry (find-if (lambda (entry) (same-name-p* (first (car entry)) name))
                         (ames.simulator:indeterminate-shares refusal)))
         (lower (ames.simulator:indeterminate-lower refusal))
         (upper (ames.simulator:indeterminate-upper refusal)))
    (when (and entry (= 1 (length lower)) (= 1 (length upper)))
      (flet ((at (bound) (ames.base::substitute-expressions (list (cons free bound)) (cdr entry))))
        (list (at (first lower)) (at (first upper)))))))

(defun is-same-range (bridge range low high)
  "Check that RANGE (two expressions, in either order) is LOW to HIGH (Maxima)."
  (is (and range
           (or (and (same-expression-p bridge (first range) low)
                    (same-expression-p bridge (second range) high))
               (and (same-expression-p bridge (first range) high)
                    (same-expression-p bridge (second range) low))))
      "range ~S, expected ~S to ~S" range low high))

(test a-tied-particle-on-a-rough-incline-is-statically-indeterminate
  "T + F share m g sin a = 3 m g / 5: refused as statically indeterminate, naming the
particle, the tension ranging over [m g / 5, m g] (Maxima), the friction force over
+-mu_s m g cos a = +-2 m g / 5."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-of-text *tied-on-rough-incline*))
           (refusal (indeterminate-refusal-of scenario bridge)))
      (is (not (null refusal)))
      (when refusal
        (is (equal '("PARTICLE") (mapcar #'string (ames.simulator:indeterminate-bodies refusal))))
        (is (search "statically indeterminate" (ames.base::ames-error-detail refusal)))
        (flet ((x (expression) (in-scenario-terms scenario expression)))
          (is-same-range bridge (share-range refusal "TENSION") (x '(/ (* m g) 5)) (x '(* m g)))
          (is-same-range bridge (share-range refusal "FRICTION-FORCE")
                         (x '(- (/ (* 2 m g) 5))) (x '(/ (* 2 m g) 5))))))))

(test an-incline-pulley-held-at-its-pulley-on-a-rough-incline-is-statically-indeterminate
  "The held state of t/closing-at-pulley.lisp's rough case (T + F = 20, |F| <= 3): the
particle slides to the strike at t = sqrt(14/17), then the held start is refused as
statically indeterminate, naming the particle, the tension ranging over [17, 23]."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-of-text
                      (incline-pulley-text "rough-held" :parameters "" :g "10" :m1 "5/2" :m2 "1"
                                           :extra "(friction particle incline :static 1/5 :kinetic 1/10)")))
           (refusal (indeterminate-refusal-of scenario bridge)))
      (is (not (null refusal)))
      (when refusal
        (is (equal '("PARTICLE") (mapcar #'string (ames.simulator:indeterminate-bodies refusal))))
        (is-same-range bridge (share-range refusal "TENSION") 17 23)
        (is-same-range bridge (share-range refusal "FRICTION-FORCE") -3 3)))))

;;; Local series by exact power series (src/simulator/exact-series.lisp)

(defun exact-series-of (rates initial expression)
  "The five Taylor coefficients of EXPRESSION at the start of a state with RATES and
INITIAL values (alists over state terms), by exact power series."
  (let ((solved (ames.simulator::%make-solved-model :rates rates :initial initial
                                                    :state (mapcar #'car initial))))
    (ames.simulator::exact-series-coefficients solved expression 5)))

(test exact-series-give-textbook-taylor-coefficients
  "The pendulum theta'' = -sin theta from theta = 0 at unit rate: theta = tau - tau^3/6
+ O(tau^5) (theta''' = -cos theta theta' = -1, theta'''' = 0), so sin theta = tau -
tau^3/3 + O(tau^5); the oscillator x'' = -x from (1, 0): cos tau = 1 - tau^2/2 +
tau^4/24; x' = 1/(1 + x) from 0: x = sqrt(1 + 2 tau) - 1 = tau - tau^2/2 + tau^3/2 -
5 tau^4/8 (binomial series). A symbolic parameter gives NIL (the symbolic route)."
  (let ((theta '(ames.kb:angle b)) (omega '(ames.kb:angvel b))
        (x '(ames.kb:pos b :x)) (v '(ames.kb:vel b :x)))
    (let ((pendulum (list (cons theta omega) (cons omega `(- (sin ,theta))))))
      (is (equal '(0 1 0 -1/6 0) (exact-series-of pendulum (list (cons theta 0) (cons omega 1)) theta)))
      (is (equal '(0 1 0 -1/3 0)
                 (exact-series-of pendulum (list (cons theta 0) (cons omega 1)) `(sin ,theta)))))
    (is (equal '(1 0 -1/2 0 1/24)
               (exact-series-of (list (cons x v) (cons v `(- ,x))) (list (cons x 1) (cons v 0)) x)))
    (is (equal '(0 1 -1/2 1/2 -5/8)
               (exact-series-of (list (cons x `(/ 1 (+ 1 ,x)))) (list (cons x 0)) x)))
    (is (null (exact-series-of (list (cons x v) (cons v '(- g))) (list (cons x 1) (cons v 0)) x)))))

;;; A corner at the end of a face (src/simulator/face-end-corners.lisp)

(defparameter *block-leaving-a-ledge*
  "(scenario block-leaving-a-ledge \"A block sliding flat off the far edge of a ledge.\" (gravity 10)
     (body floor :fixed t :shape (half-plane (1 -1/2) (0 -1/2)))
     (body ledge :fixed t :shape (polygon (-5 -1/2) (0 -1/2) (0 0) (-5 0)))
     (body block :mass 7/4 :inertia :uniform :shape (polygon (-7/8 -7/8) (7/8 -7/8) (7/8 7/8) (-7/8 7/8))
           :position (-3 7/8) :angle 0 :velocity (-1/4 0))
     (restitution 0) (simulate :states 1))"
  "A block (side 7/4) sliding flat at 1/4 on a frictionless ledge toward its far edge.")

(test a-block-sliding-off-a-ledges-edge-strikes-nothing
  "The block slides flat at 1/4 (normal forces m g / 2 = 35/4 at each corner) until its
trailing corner reaches the ledge's far edge at x = -5, after (3 + 7/8 - 5 + ...)/...:
9/8 at 1/4, t = 9/2; there its corner leaves the top and the ledge's corner comes onto
its bottom face, moving along it: no impact (main reported a collision giving the block
an upward velocity 3/32 and a spin 3/28). The end velocity is (-1/4, 0), no spin."
  (with-fixture simulator-bridge ()
    (let* ((history (simulate-stopping-when-ambiguous (scenario-of-text *block-leaving-a-ledge*) bridge))
           (state (first (ames:history-states history))))
      (is (not (null state)))
      (when state
        (is-same bridge "the slide's time" (ames::state-duration state) 9/2)
        (is (not (member :impulse (alexandria:ensure-list (ames::state-end-event state))))
            "an impact: ~S" (ames::state-end-event state))
        (is (equal '(-1/4 0) (per-body (ames::state-final-velocities state) "BLOCK")))
        (is (eql 0 (per-body (ames::state-final-angular-velocities state) "BLOCK")))))))

(test (a-corner-comes-onto-a-ledges-top-at-its-edge :suite long-checks)
  "Block-step seed 2031 #30 (the crosscheck's refusal): a block lands flat on a ledge
overhanging its edge, then slides back at 1/4; its overhanging corner reaches the line
of the ledge's side exactly at the ledge's top corner after (7/8 - (7 + 2 sqrt 5)/40) /
(1/4) = (28 - 2 sqrt 5)/10, moving along the ledge's top: it comes onto the top (a
touching, no impact), at (-7/8, 7/8) with velocity (-1/4, 0), then slides on flat (13 to
the far edge). Before, refused as a corner reaching a face's end at a speed. (About a
minute.)"
  (with-fixture simulator-bridge ()
    (let* ((text (let ((*package* (find-package '#:ames-scenario)))
                   (ames::crosscheck-scenario-text :block-step 2031 30)))
           (history (ames:run-scenario (first (ames:read-scenarios-from-string text))
                                       :numeric t :bridge bridge))
           (states (ames:history-states history)))
      (is (= 3 (length states)))
      (when (= 3 (length states))
        (destructuring-bind (fall slide flat) states
          (declare (ignore fall))
          (is (< (abs (- (expression-value (ames::state-duration slide))
                         (expression-value '(/ (- 28 (* 2 (sqrt 5))) 10))))
                 1d-9))
          (is (not (member :impulse (alexandria:ensure-list (ames::state-end-event slide)))))
          (is (equal '(-7/8 7/8) (per-body (ames::state-final-positions slide) "BLOCK")))
          (is (equal '(-1/4 0) (per-body (ames::state-final-velocities slide) "BLOCK")))
          (is-same bridge "the flat slide's time" (ames::state-duration flat) 13))))))
