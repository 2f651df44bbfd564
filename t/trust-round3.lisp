;;;; t/trust-round3.lisp -- issue 20, round 3: every scenario self-checked, a spring through zero
;;;; length, a pendulum on a rope, and floors of oscillations.
;;;;
;;;; Written fresh for these tests (none of these scenarios is in scenarios/):
;;;;   - values for the parameters a scenario gives no default, chosen to satisfy every
;;;;     assumption (the self-check of scenarios/ runs every file with them);
;;;;   - a block on a spring pushed toward the spring's fixed end: below v0 = l0 sqrt(k/m) it
;;;;     oscillates, above it the spring shrinks to zero length and opens on the other side
;;;;     (its line of action is defined by its ends, Hooke's d/|d|), the block oscillating
;;;;     about -l0; exactly at it the spring touches zero length at rest and the block comes
;;;;     back (the direction it had); a spring of zero length at rest is refused by name;
;;;;   - an oscillation's least value decides whether a spring ever closes: a pushed pair
;;;;     branches on it, a damped spring released short of its anchor never closes;
;;;;   - a particle on a taut rope swings as a pendulum (period 4 sqrt(L/g) K(sin^2(theta0/2))
;;;;     for any amplitude), also past a right angle from where it starts.
;;;; Closed forms are checked by Maxima equivalence, numbers against their formulas.

(in-package #:ames.tests)

(def-suite trust-round3 :in all-tests
  :description "Issue 20, round 3: admissible values for the self-check of every scenario,
springs through zero length, oscillation floors, a pendulum on a rope.")

(in-suite trust-round3)

(defun round3-scenario (text)
  "The first scenario written in TEXT."
  (first (ames:read-scenarios-from-string text)))

(defun round3-history (text bridge)
  "The scenario written in TEXT and its symbolic history."
  (let ((scenario (round3-scenario text)))
    (values scenario (ames:simulate scenario :bridge bridge))))

;;; Values for the self-check

(test every-parameter-gets-a-value-that-satisfies-the-assumptions
  "ADMISSIBLE-PARAMETER-VALUES gives every parameter of every scenario of scenarios/ a
number (its default, else a chosen one) that passes the check a run's values get; for a
fresh scenario with coupled assumptions each chosen value satisfies them."
  (dolist (file (scenario-files))
    (dolist (scenario (ames:read-scenario-file file))
      (let ((values (ames:admissible-parameter-values scenario)))
        (is (= (length values) (length (ames:scenario-parameters scenario))))
        (is (every (lambda (entry) (realp (cdr entry))) values))
        (is (equal values (handler-case (ames.scenario:run-parameter-values scenario :settings values)
                            (ames:ames-error (e) (list :refused (princ-to-string e)))))
            "~A: the chosen values ~S are refused" (pathname-name file) values))))
  (let* ((scenario (round3-scenario
                    "(scenario coupled \"Coupled assumptions.\"
                       (parameters (h :positive) (b (> b 0) (< b h)) (a (> a 0) (< a (/ pi 2)))
                                   (mu :positive (> mu (tan a))) (muk :positive (<= muk mu))
                                   (m :positive (:value 7)))
                       (body p :mass m :position (0 0) :velocity (0 0) :shape point))"))
         (values (ames:admissible-parameter-values scenario)))
    (flet ((v (name) (cdr (find name values :key (lambda (e) (symbol-name (car e))) :test #'string=))))
      (is (= 7 (v "M")) "a default is kept")
      (is (< 0 (v "B") (v "H")))
      (is (< 0 (v "A") (/ pi 2)))
      (is (> (v "MU") (tan (v "A"))))
      (is (<= (v "MUK") (v "MU"))))
    (is (equal '("H" "B" "A" "MU" "MUK")
               (mapcar #'symbol-name (nth-value 1 (ames:admissible-parameter-values scenario)))))))

;;; A spring through zero length

(defparameter *through-the-anchor*
  "(scenario block-through-its-spring-anchor
     \"A block pushed toward its spring's anchor fast enough to pass it.\"
     (parameters (m :positive) (k :positive) (l0 :positive)
                 (v0 :positive (> v0 (* l0 (sqrt (/ k m))))) (g :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body anchor :fixed t :position (0 0) :shape point)
     (body block :mass m :position (l0 0) :velocity ((- v0) 0) :shape point)
     (spring s :from (anchor (0 0)) :to (block (0 0)) :stiffness k)
     (simulate :states 3))"
  "At rest length l0 from the anchor, pushed toward it at v0 > l0 w (w = sqrt(k/m)): the
spring shrinks to zero after asin(l0 w / v0) / w, at speed u = sqrt(v0^2 - l0^2 w^2); on
the far side its ends define its direction again, and the block oscillates about -l0:
x = -(l0 (1 - cos w tau) + (u/w) sin w tau), back at the anchor after
(pi + 2 atan(l0 w / u)) / w.")

(test a-block-passes-through-its-spring-anchor
  "The spring closes (:spring-closes S) at the textbook's time and speed, opens on the
other side with the block oscillating about -l0, and closes again after the time the
oscillation takes to come back; energy m v0^2 / 2 throughout."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (round3-history *through-the-anchor* bridge)
      (let ((states (ames:history-states history)))
        (is (= 3 (length states)))
        (destructuring-bind (&optional in out back) states
          (declare (ignore back))
          (when out
            (is (eq :spring-closes (first (ames::state-end-event in))))
            (is (eq :spring-closes (first (ames::state-end-event out))))
            (flet ((x (form) (in-scenario-terms scenario form)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (let ((w (x '(sqrt (/ k m))))
                       (u (x '(sqrt (- (expt v0 2) (/ (* k (expt l0 2)) m))))))
                   (is-same bridge "time to the anchor" (ames::state-duration in)
                            (x `(/ (asin (/ (* l0 ,w) v0)) ,w)))
                   (is-same-vector bridge "at the anchor" (per-body (ames::state-final-positions in) "BLOCK") '(0 0))
                   (is-same-vector bridge "speed there" (per-body (ames::state-final-velocities in) "BLOCK")
                                   `((- ,u) 0))
                   (is-same bridge "beyond the anchor" (first (per-body (ames::state-positions out) "BLOCK"))
                            (x `(- (+ (* l0 (- 1 (cos (* ,w tau)))) (* (/ ,u ,w) (sin (* ,w tau)))))))
                   (is-same bridge "time back to the anchor" (ames::state-duration out)
                            (x `(/ (+ pi (* 2 (atan (/ (* l0 ,w) ,u)))) ,w)))
                   (is-same bridge "energy" (total-energy out) (x '(* 1/2 m (expt v0 2))))))))))))))

(defparameter *launched-from-the-anchor*
  "(scenario block-launched-from-its-spring-anchor
     \"A block at its spring's anchor (spring of rest length l0) launched along the floor.\"
     (parameters (m :positive) (k :positive) (l0 :positive) (v0 :positive) (g :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body anchor :fixed t :position (0 0) :shape point)
     (body block :mass m :position (0 0) :velocity ((- v0) 0) :shape point)
     (spring s :from (anchor (0 0)) :to (block (0 0)) :stiffness k :rest-length l0)
     (simulate :states 2))"
  "The spring starts at zero length and opens along the block's velocity, pushing it
with k l0 at first: x = -(l0 (1 - cos w tau) + (v0/w) sin w tau), back at the anchor after
(pi + 2 atan(l0 w / v0)) / w, moving at v0 the other way.")

(test a-spring-of-zero-length-opens-along-the-relative-velocity
  "A span of zero length at the start takes the direction its ends separate along (no
0/0): the textbook's motion, and the spring closes again when the block comes back."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (round3-history *launched-from-the-anchor* bridge)
      (let ((out (first (ames:history-states history))))
        (is (not (null out)))
        (when out
          (is (eq :spring-closes (first (ames::state-end-event out))))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((w (x '(sqrt (/ k m)))))
                 (is-same bridge "x" (first (per-body (ames::state-positions out) "BLOCK"))
                          (x `(- (+ (* l0 (- 1 (cos (* ,w tau)))) (* (/ v0 ,w) (sin (* ,w tau)))))))
                 (is-same bridge "time back" (ames::state-duration out)
                          (x `(/ (+ pi (* 2 (atan (/ (* l0 ,w) v0)))) ,w)))
                 (is-same-vector bridge "velocity back" (per-body (ames::state-final-velocities out) "BLOCK")
                                 (x '(v0 0))))))))))))

(test a-spring-touching-zero-length-at-rest-turns-back
  "Released at 2 l0 from the anchor, the block reaches the anchor at rest (the spring's
length touches zero): it does not close, the block comes back the way it came (the
direction the spring had): one state, forever, between 0 and 2 l0, period 2 pi sqrt(m/k)."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history)
        (round3-history "(scenario touching \"Released at twice the rest length.\"
                           (parameters (m :positive) (k :positive) (l0 :positive) (g :positive))
                           (gravity g)
                           (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                           (body anchor :fixed t :position (0 0) :shape point)
                           (body block :mass m :position ((* 2 l0) 0) :velocity (0 0) :shape point)
                           (spring s :from (anchor (0 0)) :to (block (0 0)) :stiffness k :rest-length l0)
                           (simulate :states 2))"
                        bridge)
      (let ((state (first (ames:history-states history))))
        (is (eq :complete (ames:history-outcome history)))
        (is (eq :forever (ames::state-duration state)))
        (let ((periodic (ames.simulator:state-periodic state)))
          (is (not (null periodic)))
          (when periodic
            (flet ((x (form) (in-scenario-terms scenario form)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "period" (getf periodic :period) (x '(* 2 pi (sqrt (/ m k)))))
                 (is-same-vector bridge "turning points" (getf periodic :between) (x '(0 (* 2 l0)))))))))))))

(test a-spring-of-zero-length-at-rest-is-refused-by-name
  "Ends that coincide and do not move apart give a spring no direction (0/0): the run is
refused with an AMES-ERROR naming the spring, not a generic inconsistency."
  (with-fixture simulator-bridge ()
    (let ((scenario (round3-scenario
                     "(scenario undefined \"A block at rest at its spring's anchor.\"
                        (parameters (m :positive) (k :positive) (l0 :positive) (g :positive))
                        (gravity g)
                        (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                        (body anchor :fixed t :position (0 0) :shape point)
                        (body block :mass m :position (0 0) :velocity (0 0) :shape point)
                        (spring coil :from (anchor (0 0)) :to (block (0 0)) :stiffness k :rest-length l0)
                        (simulate :states 2))")))
      (let ((condition (handler-case (progn (ames:simulate scenario :bridge bridge) nil)
                         (ames:ames-error (e) e))))
        (is (typep condition 'ames:ames-error))
        (is (search "COIL" (string-upcase (princ-to-string condition)))
            "the refusal does not name the spring: ~A" condition)))))

;;; Floors of oscillations: whether a spring ever closes

(test a-pushed-spring-branches-on-whether-it-reaches-zero-length
  "Without a bound on v0 the run forks on m v0^2 - k l0^2 (the oscillation's least length
l0 - v0 sqrt(m/k) against 0), not on a root it cannot find; the branch below it lasts
forever, the one above closes the spring."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history)
        (round3-history (ppcre:regex-replace "\\(v0 :positive \\(> v0 \\(\\* l0 \\(sqrt \\(/ k m\\)\\)\\)\\)\\)"
                                             *through-the-anchor* "(v0 :positive)")
                        bridge)
      (let* ((fork (first (ames:history-states history)))
             (branches (ames::state-branches fork)))
        (is (= 3 (length branches)) "~D branches" (length branches))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is (some (lambda (branch)
                         (let ((fact (getf branch :assume)))
                           (and (consp fact) (member (first fact) '(< >))
                                (or (same-expression-p bridge (second fact) (x '(- (* m (expt v0 2)) (* k (expt l0 2)))))
                                    (same-expression-p bridge (second fact) (x '(- (* k (expt l0 2)) (* m (expt v0 2)))))))))
                       branches)
                 "the fork's facts: ~S" (mapcar (lambda (b) (getf b :assume)) branches)))))))))

(defparameter *damped-short*
  "(scenario damped-short-of-its-anchor
     \"A block on a spring in oil pulled out by a < l0 and released.\"
     (parameters (m :positive) (c :positive) (k :positive (> k (/ (expt c 2) (* 4 m))))
                 (l0 :positive) (a :positive (< a l0)) (g :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body wall :fixed t :position (0 0) :shape point)
     (body block :mass m :position ((+ l0 a) 0) :velocity (0 0) :shape point)
     (spring s :from (wall (0 0)) :to (block (0 0)) :stiffness k :rest-length l0)
     (drag oil :on block :linear c)
     (simulate :states 1))"
  "Under-damped, released from rest: its stretch a exp(-c tau / 2m) (cos w tau + (c / 2 m w)
sin w tau) has its extremes at w tau = n pi, a (-1)^n exp(-c n pi / 2 m w): never below
-a, so with a < l0 the spring never closes.")

(test a-damped-spring-released-short-of-its-anchor-never-closes
  "With a < l0 the run is complete and lasts forever (the damped oscillation's floor);
without it, it forks on l0^2 - a^2, the floor's own condition, instead of claiming
forever."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (round3-history *damped-short* bridge)
      (declare (ignore scenario))
      (is (eq :complete (ames:history-outcome history)))
      (is (eq :forever (ames::state-duration (first (ames:history-states history))))))
    (multiple-value-bind (scenario history)
        (round3-history (ppcre:regex-replace "\\(a :positive \\(< a l0\\)\\)" *damped-short* "(a :positive)") bridge)
      (let ((branches (ames::state-branches (first (ames:history-states history)))))
        (is (not (null branches)) "the run claims ~S without a bound on a"
            (ames::state-duration (first (ames:history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is (some (lambda (branch)
                         (let ((fact (getf branch :assume)))
                           (and (consp fact) (member (first fact) '(< >))
                                (or (same-expression-p bridge (second fact) (x '(- (expt l0 2) (expt a 2))))
                                    (same-expression-p bridge (second fact) (x '(- (expt a 2) (expt l0 2))))))))
                       branches)
                 "the fork's facts: ~S" (mapcar (lambda (b) (getf b :assume)) branches)))))))))

;;; A pendulum on a rope

(defun pendulum-on-a-rope (theta0)
  "A particle on a rope of length l = 1 hung from a fixed point, released at rest with the
rope taut at THETA0 from the vertical (g = 10), for one state."
  (format nil "(scenario pendulum-on-a-rope \"A particle on a taut rope released at an angle.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (l :positive (:value 1))
                 (theta0 :positive (< theta0 pi) (:value ~A)))
     (gravity g)
     (body ceiling :fixed t :position (0 0) :shape point)
     (body bob :mass m :position ((* l (sin theta0)) (- (* l (cos theta0)))) :velocity (0 0) :shape point)
     (rope cord :length l :through ((ceiling (0 0)) (bob (0 0))))
     (simulate :states 1))" theta0))

(test a-particle-on-a-taut-rope-swings-to-the-mirror-point-in-half-a-period
  "Released at theta0 (1/2, and 5/4 past the right angle from its start at which the
rope's piece used to be taken for closing up), the particle swings on the taut rope and
turns back, (:turns BOB), at the mirror point
(-l sin theta0, -l cos theta0) after half the pendulum's period,
2 sqrt(l/g) K(sin^2(theta0/2))."
  (with-fixture simulator-bridge ()
    (dolist (theta0 '(1/2 5/4))
      (let* ((scenario (round3-scenario (pendulum-on-a-rope theta0)))
             (history (let ((ames.check:*self-check* nil))
                        (ames:run-scenario scenario :numeric t :bridge bridge)))
             ;; along the branch the values select (the run may fork at its start)
             (state (find-if-not #'ames::state-fork-p (ames.check::checked-path (ames:history-states history)))))
        (is (not (null state)))
        (when state
          (is (equal '(:turns "BOB") (event-names (ames::state-end-event state)))
              "theta0 = ~A: the swing ends with ~S" theta0 (ames::state-end-event state))
          (let ((expected (* 2 (sqrt (/ 1d0 10)) (expression-value `(elliptic-k ,(expt (sin (/ theta0 2d0)) 2)))))
                (duration (expression-value (ames::state-duration state) '())))
            (is (and (realp duration) (< (abs (- duration expected)) (* 1d-7 expected)))
                "theta0 = ~A: half period ~A, expected ~A" theta0 duration expected))
          ;; the end is put exactly on the rope's circle: l times a rational point
          (let ((end (per-body (ames::state-final-positions state) "BOB"))
                (l (list (cons (find-symbol "L" (symbol-package (ames:scenario-name scenario))) 1))))
            (is (< (abs (- (expression-value (first end) l) (- (sin (float theta0 1d0))))) 1d-7))
            (is (< (abs (- (expression-value (second end) l) (- (cos (float theta0 1d0))))) 1d-7))))))))
