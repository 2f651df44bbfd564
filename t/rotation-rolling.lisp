;;;; t/rotation-rolling.lisp -- the rotation core (issue 23) on the rolling-disc family: a disc
;;;; rolling down a rough incline, the same disc slipping where mu < tan(a)/3, a hoop and a
;;;; disc racing down identical inclines, a disc launched sliding on a rough floor.
;;;;
;;;; Every expected result is the textbook's (each scenario file's header), over the
;;;; scenario's own parameters, compared by Maxima-checked equivalence under its
;;;; assumptions; then again with the scenario's (:value N) defaults, where the numbers the
;;;; run prints must be the formulas' values. The helpers are those of
;;;; t/simulator-scenarios.lisp and t/friction.lisp.

(in-package #:ames.tests)

(def-suite rotation-rolling :in all-tests
  :description "Rotating bodies (src/kb/rotation.lisp, src/simulator/rotation.lisp): a
disc rolling and slipping on an incline, a hoop and a disc racing, a disc launched
sliding that starts to roll.")

(in-suite rotation-rolling)

(defun rotation-entry (alist body)
  "BODY's (a name) entry in a state's rotation ALIST ((BODY VALUE) ...), or NIL."
  (second (find body alist :key #'first :test #'same-name-p*)))

(defun named-scenario (file name)
  "The scenario named NAME of scenarios/FILE.lisp."
  (find name (ames:read-scenario-file (find file (scenario-files) :key #'pathname-name :test #'string=))
        :key (lambda (s) (symbol-name (ames:scenario-name s))) :test #'string-equal))

(defun with-mu-assumption (scenario relation)
  "SCENARIO with mu's assumptions replaced by RELATION (mu positive) and no default value."
  (ames:parse-scenario
   (mapcar (lambda (clause)
             (if (and (consp clause) (same-name-p* (first clause) "PARAMETERS"))
                 (cons (first clause)
                       (mapcar (lambda (spec)
                                 (if (and (consp spec) (same-name-p* (first spec) "MU"))
                                     (list (first spec) :positive relation)
                                     spec))
                               (rest clause)))
                 clause))
           (ames:scenario-form scenario))))

(defun check-rolling-state (bridge scenario state body fraction)
  "Check STATE of SCENARIO: BODY rolls without slipping down the incline of angle a, with
acceleration FRACTION g sin a along the slope, static friction (1 - FRACTION) m g sin a up
it, normal force m g cos a, angular acceleration -FRACTION g sin a / r, and reaches the
foot, the half slope L = h / (2 sin a) down, after sqrt(2 L / (FRACTION g sin a))."
  (flet ((x (form) (in-scenario-terms scenario form)))
    (call-with-scenario-facts
     bridge scenario
     (lambda ()
       (is-same-vector bridge "acceleration" (per-body (ames::state-accelerations state) body)
                       (list (x `(* ,fraction g (sin a) (cos a))) (x `(- (* ,fraction g (expt (sin a) 2))))))
       (check-friction bridge state body "INCLINE" :static (x `(* ,(- 1 fraction) m g (sin a))))
       (is-same bridge "N" (normal-force-between state body "INCLINE") (x '(* m g (cos a))))
       (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) body)
                (x `(- (/ (* ,fraction g (sin a)) r))))
       (is-same bridge "time to the foot" (ames::state-duration state)
                (x `(sqrt (/ (* 2 (/ h (* 2 (sin a)))) (* ,fraction g (sin a))))))
       ;; rolling: the rim's speed is the centre's, at the foot too
       (is-same bridge "omega r = -v at the foot"
                (x `(* r ,(rotation-entry (ames.simulator:state-final-angular-velocities state) body)))
                (x `(- (sqrt (* 2 ,fraction g (sin a) (/ h (* 2 (sin a)))))))))))
  (is (equal '(:leaves :contact) (sort (mapcar #'first (or (ames::state-simultaneous-events state)
                                                          (list (ames::state-end-event state))))
                                       #'string>))
      "the foot: ~S" (ames::state-end-event state)))

(test disc-rolls-down-a-rough-incline
  "With mu > tan(a)/3 the disc rolls: a = (2/3) g sin a, friction m g sin a / 3, N = m g
cos a, alpha = -(2/3) g sin a / r, at the foot after sqrt(3 L / (g sin a)); its energy
(with (1/2) I omega^2) is conserved; the queries give its speed and spin there."
  (with-fixture simulator-bridge ()
    (let ((scenario (named-scenario "disc-rolling-down-incline" "disc-rolling-down-incline")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (let ((state (first states)))
          (check-rolling-state bridge scenario state "DISC" 2/3)
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (let ((energy (ames.simulator::state-total-energy state)))
               (is (ames.simulator::reported-kinetic-energy state 'disc nil))
               (is-same bridge "energy conserved" energy (subst 0 'tau energy))
               (is (not (ames.maxima:equivalent-p
                         bridge (ames.simulator::reported-kinetic-energy state 'disc nil)
                         (in-scenario-terms scenario '(* 1/2 m (expt (* 2/3 g (sin a) tau) 2))))))
               (is-same bridge "kinetic energy with rotation" (ames.simulator::reported-kinetic-energy state 'disc nil)
                        (in-scenario-terms scenario '(* 3/4 m (expt (* 2/3 g (sin a) tau) 2)))))
             (let ((answers (ames::history-answers history)))
               (is-same bridge "speed at the foot" (second (assoc "SPEED-AT-FOOT" answers :test #'same-name-p*))
                        (in-scenario-terms scenario '(sqrt (/ (* 2 g h) 3))))
               (is-same bridge "spin at the foot" (second (assoc "SPIN-AT-FOOT" answers :test #'same-name-p*))
                        (in-scenario-terms scenario '(- (/ (sqrt (/ (* 2 g h) 3)) r))))))))))))

(test disc-rolls-with-values
  "The rolling disc with the scenario's values: the printed duration is the formula's
value, sqrt(3 L / (g sin a)) with L = h / (2 sin a)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (named-scenario "disc-rolling-down-incline" "disc-rolling-down-incline"))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (declare (ignore history))
        (flet ((value (name) (float (cdr (find name values :key (lambda (e) (symbol-name (car e)))
                                                           :test #'string-equal))
                                    1d0)))
          (let ((expected (sqrt (/ (* 3 (/ (value "H") (* 2 (sin (value "A")))))
                                   (* (value "G") (sin (value "A"))))))
                (printed (getf (ames.simulator:state-numbers (first states)) :duration)))
            (is (realp printed))
            (is (< (abs (- printed expected)) 1d-9) "duration ~A, expected ~A" printed expected)))))))

(test disc-slips-where-friction-is-too-weak
  "With mu < tan(a)/3 the disc slips: kinetic friction mu m g cos a, acceleration g (sin a -
mu cos a) down the slope, alpha = -2 mu g cos a / r; on an unbounded slope it never rolls.
On the triangle of the race, the same assumption selects the same motion (how that state
ends, at the corner's arc or past the slope's end, is not decided symbolically, as for a
sliding block: the run stops there, its state known)."
  (with-fixture simulator-bridge ()
    (dolist (scenario (list (named-scenario "disc-rolling-down-incline" "disc-slipping-down-incline")
                            (with-mu-assumption (named-scenario "hoop-and-disc-race" "disc-in-the-race")
                                                '(< mu (/ (tan a) 3)))))
      (multiple-value-bind (history states) (run-of (unbranched scenario) bridge)
        (declare (ignore history))
        (let ((state (first states)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "acceleration" (per-body (ames::state-accelerations state) "DISC")
                               (list (x '(* g (- (sin a) (* mu (cos a))) (cos a)))
                                     (x '(- (* g (- (sin a) (* mu (cos a))) (sin a))))))
               (check-friction bridge state "DISC" "INCLINE" :sliding (x '(* mu m g (cos a))))
               (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) "DISC")
                        (x '(- (/ (* 2 mu g (cos a)) r))))))
            (let* ((end (ames::state-end-event state))
                   (rolls (and (consp end) (same-name-p* (first end) "STOPS-SLIDING"))))
              (is (null rolls) "it starts rolling: ~S" end))))))))

(test hoop-and-disc-race
  "The hoop rolls at (1/2) g sin a (friction m g sin a / 2), the disc at (2/3) g sin a:
both times to the foot in closed form, the disc's the shorter."
  (with-fixture simulator-bridge ()
    (let* ((disc (named-scenario "hoop-and-disc-race" "disc-in-the-race"))
           (hoop (named-scenario "hoop-and-disc-race" "hoop-in-the-race"))
           (disc-state (first (nth-value 1 (run-of disc bridge))))
           (hoop-state (first (nth-value 1 (run-of hoop bridge)))))
      (check-rolling-state bridge disc disc-state "DISC" 2/3)
      (check-rolling-state bridge hoop hoop-state "HOOP" 1/2)
      (call-with-scenario-facts
       bridge disc
       (lambda ()
         (is (eq :true (ames.algebra:decide bridge `(< ,(ames::state-duration disc-state)
                                                       ,(in-scenario-terms disc (ames::state-duration hoop-state))))))
         (is-same bridge "ratio of the times"
                  `(/ ,(ames::state-duration disc-state) ,(in-scenario-terms disc (ames::state-duration hoop-state)))
                  '(/ (sqrt 3) 2)))))))

(test disc-launched-sliding-starts-to-roll
  "A disc launched at v0 without spin slides (friction mu m g back, alpha = -2 mu g / r)
until t = v0 / (3 mu g) ((:stops-sliding disc floor)), at (2/3) v0 and omega = -2 v0 /
(3 r), having slid 5 v0^2 / (18 mu g); then it rolls at (2/3) v0 forever (static friction
0). Its angular momentum about the contact line's point, the origin, is conserved: -m r v0."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "disc-launched-sliding")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (destructuring-bind (&optional sliding rolling) states
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (check-friction bridge sliding "DISC" "FLOOR" :sliding (x '(* mu m g)))
               (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations sliding) "DISC")
                        (x '(- (/ (* 2 mu g) r))))
               (is (equal "STOPS-SLIDING" (symbol-name (first (ames::state-end-event sliding)))))
               (is-same bridge "rolls from" (ames::state-duration sliding) (x '(/ v0 (* 3 mu g))))
               (is-same-vector bridge "velocity then" (per-body (ames::state-final-velocities sliding) "DISC")
                               (list (x '(* 2/3 v0)) 0))
               (is-same bridge "omega then"
                        (rotation-entry (ames.simulator:state-final-angular-velocities sliding) "DISC")
                        (x '(- (/ (* 2 v0) (* 3 r)))))
               (is-same bridge "slid" (first (per-body (ames::state-final-positions sliding) "DISC"))
                        (x '(/ (* 5 (expt v0 2)) (* 18 mu g))))
               (dolist (state states)
                 (is-same bridge "angular momentum about the origin"
                          (third (find "ANGULAR-MOMENTUM" (ames.simulator::reported-section state :momentum)
                                       :key #'first :test #'same-name-p*))
                          (x '(- (* m r v0)))))
               (check-friction bridge rolling "DISC" "FLOOR" :static 0)
               (is (eq :forever (ames::state-duration rolling)))
               (is-same bridge "omega r = -v rolling"
                        (x `(* r ,(rotation-entry (ames.simulator:state-angular-velocities rolling) "DISC")))
                        (x '(- (* 2/3 v0))))
               (let ((answers (ames::history-answers history)))
                 (is-same bridge "query: rolls at" (second (assoc "ROLLS-AT" answers :test #'same-name-p*))
                          (x '(/ v0 (* 3 mu g))))
                 (is-same bridge "query: speed" (second (assoc "ROLLING-SPEED" answers :test #'same-name-p*))
                          (x '(* 2/3 v0))))))))))))

(test disc-launched-sliding-with-values
  "With the scenario's values (v0 = 3, mu = 1/5, g = 981/100, r = 3/10) the numbers beside
the formulas: it rolls from v0 / (3 mu g), at 2 v0 / 3."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "disc-launched-sliding"))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (declare (ignore history))
        (let ((numbers (ames.simulator:state-numbers (first states))))
          (is (< (abs (- (getf numbers :duration) (/ 3d0 (* 3 1/5 981/100)))) 1d-9))
          (is (< (abs (- (first (second (assoc "DISC" (getf numbers :final-velocities)
                                               :test #'same-name-p*)))
                         2d0))
                 1d-9)))))))

(defparameter *disc-on-pulled-cart*
  '(scenario disc-on-pulled-cart "A disc on a cart pulled by a force rolls on it."
    (parameters (m :positive) (mc :positive) (r :positive) (g :positive) (w :positive)
                (f :positive) (mu :positive (> mu (/ f (* (+ m (* 3 mc)) g)))))
    (gravity g)
    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
    (body cart :mass mc :shape (polygon (0 0) (w 0) (w 1) (0 1)) :position (0 0) :velocity (0 0))
    (body disc :mass m :inertia :uniform :shape (circle r) :position ((/ w 2) (+ 1 r)) :velocity (0 0))
    (force pull :on cart :value (f 0))
    (friction disc cart :static mu)
    (simulate :states 1))
  "A uniform disc at rest on a cart that a force f pulls over a frictionless floor: with
enough friction it rolls on the cart.")

(test disc-rolls-on-a-pulled-cart
  "Rolling on a moving body: the contact points' relative velocity is zero, so the cart
accelerates at A = 3 f / (3 mc + m), the disc at A / 3 and alpha = 2 A / (3 r) (it rolls
backwards on the cart), pushed forward by friction m A / 3 (the textbook result), the
cart held back by its reaction."
  (with-fixture simulator-bridge ()
    (let ((scenario (ames:parse-scenario *disc-on-pulled-cart*)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (declare (ignore history))
        (let ((state (first states))
              (big-a (in-scenario-terms scenario '(/ (* 3 f) (+ (* 3 mc) m)))))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "cart" (per-body (ames::state-accelerations state) "CART")
                               (list big-a 0))
               (is-same-vector bridge "disc" (per-body (ames::state-accelerations state) "DISC")
                               (list `(/ ,big-a 3) 0))
               (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) "DISC")
                        `(/ (* 2 ,big-a) (* 3 ,(x 'r))))
               ;; the cart is the contact's observer: the disc's friction on it, backward
               ;; along the contact's tangent (+x)
               (check-friction bridge state "CART" "DISC" :static `(- (* ,(x 'm) (/ ,big-a 3))))))))))))

(defparameter *disc-on-a-spring*
  '(scenario disc-on-a-spring "A disc on a rough floor tied at its centre to a wall by a spring."
    (parameters (m :positive) (r :positive) (g :positive) (k :positive) (d :positive)
                (l :positive (> l (+ d r))) (mu :positive (> mu (/ (* k d) (* 3 m g)))))
    (gravity g)
    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
    (body wall :fixed t :shape (half-plane (0 -1) (0 1)))
    (body disc :mass m :inertia :uniform :shape (circle r) :position ((+ l d) r) :velocity (0 0))
    (spring s :from (wall (0 r)) :to (disc (0 0)) :stiffness k :rest-length l)
    (friction disc floor :static mu)
    (simulate :states 1))
  "A uniform disc pulled d past a spring's rest length, released on a rough floor where
friction can hold it rolling (mu > k d / (3 m g)).")

(test disc-rolls-to-and-fro-on-a-spring
  "A rolling disc on a spring (a linear motion, the angle solved with the position): it
oscillates at w = sqrt(2 k / (3 m)), the spring's k over the mass m + I / r^2, forever
(static friction, at most k d / 3, never reaches mu m g), x = l + d cos(w t), turning at
alpha = -a / r; the energy, with (1/2) I omega^2, is conserved."
  (with-fixture simulator-bridge ()
    (let ((scenario (ames:parse-scenario *disc-on-a-spring*)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (let ((state (first states)))
          (is (eq :forever (ames::state-duration state)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((w (x '(sqrt (/ (* 2 k) (* 3 m))))))
                 (is-same bridge "x" (first (per-body (ames::state-positions state) "DISC"))
                          (x `(+ l (* d (cos (* ,w tau))))))
                 (is-same bridge "omega r = -v"
                          (x `(* r ,(rotation-entry (ames.simulator:state-angular-velocities state) "DISC")))
                          (x `(* d ,w (sin (* ,w tau)))))
                 (is-same bridge "alpha r = -a"
                          (x `(* r ,(rotation-entry (ames.simulator:state-angular-accelerations state) "DISC")))
                          (x `(- ,(first (per-body (ames::state-accelerations state) "DISC")))))
                 (let ((energy (ames.simulator::state-total-energy state)))
                   (is-same bridge "energy conserved" energy (subst 0 'tau energy))))))))))))
