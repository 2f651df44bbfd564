;;;; t/drag.lisp -- the (drag ...) clause: linear drag (terminal velocity, the damped
;;;; oscillator), quadratic drag along a line (tanh falling, tan rising until the ball stops),
;;;; quadratic drag in two dimensions (numbers), and the clause's validation.
;;;;
;;;; Expected results are the textbook's closed forms, compared by Maxima-checked
;;;; equivalence; the damped oscillator's motion is substituted into m x'' + c x' + k x = 0
;;;; and its initial conditions; the two-dimensional flight is compared with an independent
;;;; Runge-Kutta integration written here.

(in-package #:ames.tests)

(def-suite drag :in all-tests
  :description "Drag, linear and quadratic: closed forms along a line, the damped
oscillator's three cases, numbers in two dimensions.")

(in-suite drag)

(defun drag-history (name bridge)
  "The scenario scenarios/NAME.lisp and its history (stopped at an ambiguity)."
  (let ((scenario (scenario-named name)))
    (values scenario (simulate-stopping-when-ambiguous scenario bridge))))

(defun drag-form-history (text bridge)
  "The scenario written in TEXT and its history (stopped at an ambiguity)."
  (let ((scenario (first (ames:read-scenarios-from-string text))))
    (values scenario (simulate-stopping-when-ambiguous scenario bridge))))

(defun y-of (state what)
  "The ball's y position (WHAT :POS) or velocity (:VEL) over STATE."
  (second (per-body (if (eq what :pos) (ames::state-positions state) (ames::state-velocities state))
                    "BALL")))

(defun exp-tanh (x)
  "tanh X written with exponentials (the algebra has no tanh)."
  `(/ (- (exp (* 2 ,x)) 1) (+ (exp (* 2 ,x)) 1)))

;;; Linear drag

(test linear-drag-approaches-the-terminal-velocity
  "Dropped from rest: v = -(m g / c)(1 - exp(-c t / m)), so v + m g / c decays as
exp(-c t / m) to the terminal velocity -m g / c; y = h - (m g / c) t + (m^2 g / c^2)(1 -
exp(-c t / m)); the drag balances the weight in the limit."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (drag-history "drag-falling" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (eq :forever (ames::state-duration state)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "velocity" (y-of state :vel)
                      (x '(- (* (/ (* m g) c) (- 1 (exp (- (/ (* c tau) m))))))))
             (is-same bridge "approach to the terminal velocity -m g / c"
                      (x `(+ ,(y-of state :vel) (/ (* m g) c)))
                      (x '(* (/ (* m g) c) (exp (- (/ (* c tau) m))))))
             (is-same bridge "height" (y-of state :pos)
                      (x '(+ h (- (* (/ (* m g) c) tau))
                           (* (/ (* m m g) (* c c)) (- 1 (exp (- (/ (* c tau) m))))))))
             (is-same bridge "the drag is -c v"
                      (second (fourth (force-entry state :drag "AIR" "BALL")))
                      (x `(* -1 c ,(y-of state :vel)))))))))))

(defparameter *underdamped-spring*
  "(scenario underdamped-spring
     \"A block on a spring in oil, pulled out and released: c^2 < 4 m k.\"
     (parameters (m :positive) (c :positive) (k :positive (> k (/ (expt c 2) (* 4 m))))
                 (l0 :positive) (a :positive (< a l0)) (g :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body wall :fixed t :position (-1 0) :shape point)
     (body block :mass m :position ((+ l0 a) 0) :velocity (0 0) :shape point)
     (spring s :from (wall (1 0)) :to (block (0 0)) :stiffness k :rest-length l0)
     (drag oil :on block :linear c)
     (simulate :states 1))"
  "The damped oscillator with the under-damped case assumed, pulled out by less than its
rest length (else the spring might shrink to zero length).")

(test underdamped-spring-solves-its-equation
  "Under c^2 < 4 m k the stretch x = X - l0 satisfies m x'' + c x' + k x = 0 (the motion
substituted, simplified to 0), x(0) = a, x'(0) = 0, and is the textbook's
a exp(-c t / 2m) (cos w t + c sin(w t) / (2 m w)), w = sqrt(4 m k - c^2) / (2 m); the
state lasts forever and is not called periodic."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (drag-form-history *underdamped-spring* bridge)
      (let* ((state (first (ames::history-states history)))
             (x (first (per-body (ames::state-positions state) "BLOCK"))))
        (flet ((p (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (eq :forever (ames::state-duration state)))
          (is (null (getf (ames::state-notes state) :periodic)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (let* ((stretch `(- ,x ,(p 'l0)))
                    (d1 (ames.geometry:differentiate stretch 'tau))
                    (d2 (ames.geometry:differentiate d1 'tau)))
               (is-same bridge "m x'' + c x' + k x" (p `(+ (* m ,d2) (* c ,d1) (* k ,stretch))) 0)
               (is-same bridge "x(0)" (at-variable stretch 'tau 0) (p 'a))
               (is-same bridge "x'(0)" (at-variable d1 'tau 0) 0)
               (let ((w (p '(/ (sqrt (- (* 4 m k) (expt c 2))) (* 2 m)))))
                 (is-same bridge "the textbook's form" stretch
                          (p `(* a (exp (- (/ (* c tau) (* 2 m))))
                                 (+ (cos (* ,w tau)) (* (/ c (* 2 m ,w)) (sin (* ,w tau))))))))))))))))

(test damped-spring-branches-on-its-discriminant
  "Without an assumption on c^2 - 4 m k the run forks three ways (over-, under- and
critically damped); the critical branch is x = a (1 + c t / (2 m)) exp(-c t / (2 m))."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "damped-spring"))
           (history (ames:simulate scenario :bridge bridge))
           (paths (ames.simulator::history-paths history)))
      (is (= 3 (length paths)))
      (let ((critical (find-if (lambda (path) (some (lambda (f) (and (consp f) (eq (first f) '=))) (first path)))
                               paths)))
        (is (not (null critical)))
        (when critical
          ;; the boundary branch has k = c^2 / (4 m) substituted: the other parameters stay
          (let* ((state (car (last (cddr critical))))
                 (x (first (per-body (ames::state-positions state) "BLOCK"))))
            (flet ((p (form) (in-scenario-terms scenario form)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "critically damped" x
                          (p '(+ l0 (* a (+ 1 (/ (* c tau) (* 2 m))) (exp (- (/ (* c tau) (* 2 m)))))))))))))))))

;;; Quadratic drag along a line

(test quadratic-drag-falls-as-tanh
  "Dropped from rest: v = -sqrt(m g / k) tanh(t sqrt(g k / m)) and
y = h - (m / k) ln cosh(t sqrt(g k / m)); the state lasts forever."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (drag-history "quadratic-drag-falling" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (eq :forever (ames::state-duration state)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (let ((z (x '(* tau (sqrt (/ (* g k) m))))))
               (is-same bridge "velocity" (y-of state :vel)
                        (x `(- (* (sqrt (/ (* m g) k)) ,(exp-tanh z)))))
               (is-same bridge "height" (y-of state :pos)
                        (x `(- h (* (/ m k) (log (/ (+ (exp ,z) (exp (- ,z))) 2))))))))))))))

(test quadratic-drag-rises-stops-and-falls
  "Thrown up at v0: v = V tan(atan(v0 / V) - w t), V = sqrt(m g / k), w = sqrt(g k / m),
until it stops at t1 = atan(v0 / V) / w, (:turns ball), at h + (m / 2k) ln(1 + v0^2 / V^2);
then it falls from rest as tanh."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (drag-history "quadratic-drag-thrown-up" bridge)
      (destructuring-bind (&optional rising falling &rest others) (ames::history-states history)
        (declare (ignore others))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (not (null falling)))
          (when falling
            (is (equal '(:turns "BALL") (event-names (ames::state-end-event rising))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((big-v (x '(sqrt (/ (* m g) k)))) (w (x '(sqrt (/ (* g k) m)))))
                 (is-same bridge "rising velocity" (y-of rising :vel)
                          (x `(* ,big-v (tan (- (atan (/ v0 ,big-v)) (* ,w tau))))))
                 (is-same bridge "time to the top" (ames::state-duration rising)
                          (x `(/ (atan (/ v0 ,big-v)) ,w)))
                 (is-same bridge "height of the top" (second (per-body (ames::state-final-positions rising) "BALL"))
                          (x `(+ h (* (/ m (* 2 k)) (log (+ 1 (/ (expt v0 2) (expt ,big-v 2))))))))
                 (is-same bridge "at rest at the top" (second (per-body (ames::state-final-velocities rising) "BALL")) 0)
                 (is-same bridge "falling back" (y-of falling :vel)
                          (x `(- (* ,big-v ,(exp-tanh `(* ,w tau))))))
                 (is (eq :forever (ames::state-duration falling))))))))))))

;;; Quadratic drag in two dimensions: numbers

(defun rk4-flight-time (m g k vx vy)
  "When a ball launched from (0, 0) at (VX, VY) under gravity G and quadratic drag K
(mass M) comes back to y = 0: a fixed-step Runge-Kutta integration and a linear
interpolation of the last step."
  (let ((h 1d-4) (time 0d0) (state (vector 0d0 vx vy)))
    (flet ((rates (s)
             (let* ((u (svref s 1)) (v (svref s 2)) (speed (sqrt (+ (* u u) (* v v)))))
               (vector v (- (/ (* k speed u) m)) (- (+ g (/ (* k speed v) m))))))
           (ahead (s f a) (map 'vector (lambda (x d) (+ x (* a d))) s f)))
      (loop
        (let* ((k1 (rates state)) (k2 (rates (ahead state k1 (/ h 2))))
               (k3 (rates (ahead state k2 (/ h 2)))) (k4 (rates (ahead state k3 h)))
               (next (map 'vector (lambda (x a b c d) (+ x (* (/ h 6) (+ a (* 2 b) (* 2 c) d))))
                          state k1 k2 k3 k4)))
          (when (and (> time 0.1d0) (<= (svref next 0) 0))
            (return (+ time (* h (/ (svref state 0) (- (svref state 0) (svref next 0)))))))
          (setf state next time (+ time h)))))))

(test quadratic-drag-in-two-dimensions-has-numbers
  "Launched at an angle the flight has no closed form: without values the state says so;
under values it ends when the ball meets the ground, at the time an independent
Runge-Kutta integration finds, and the self-check passes; nothing ends it early (its
velocity never reverses)."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (drag-history "quadratic-drag-projectile" bridge)
      (declare (ignore scenario))
      (is (equal '(:no-closed-form :needs :parameter-values)
                 (ames::state-duration (first (ames::history-states history))))))
    (let* ((history (ames:run-scenario (scenario-named "quadratic-drag-projectile") :bridge bridge :numeric t))
           (state (first (ames::history-states history)))
           (check (ames.check:self-check-result history)))
      ;; it lands at about 7.6 m/s: an impact (it was taken for a contact reached at no speed)
      (is (equal '(:collision "BALL" "GROUND") (event-names (ames::state-end-event state))))
      (is (realp (ames::state-duration state)))
      (when (realp (ames::state-duration state))
        (is (< (abs (- (ames::state-duration state) (rk4-flight-time 1d0 9.81d0 0.05d0 10d0 10d0))) 1d-5)
            "flight time ~A" (ames::state-duration state)))
      (is (null (getf check :failures)) "self-check failures ~S" (getf check :failures))
      (is (getf check :checked)))))

;;; The clause

(defun drag-scenario-text (clause)
  "A scenario with one ball and the drag CLAUSE (a string)."
  (format nil "(scenario d \"\" (parameters (m :positive) (b :positive) (g :positive))
     (gravity g) (body ball :mass m :position (0 1) :velocity (0 0) :shape point) ~A)" clause))

(test drag-clause-is-validated
  "One of :linear and :quadratic, a positive coefficient, a declared body, a fresh name."
  (dolist (clause '("(drag air :on ball)" "(drag air :on ball :linear b :quadratic b)"
                    "(drag air :on ball :linear -1)" "(drag air :on nobody :linear b)"
                    "(drag ball :on ball :linear b)" "(drag air :on ball :viscous b)"))
    (signals ames:scenario-error
      (ames:parse-scenario (first (ames:read-scenario-forms (drag-scenario-text clause))))))
  (let ((scenario (ames:parse-scenario (first (ames:read-scenario-forms
                                               (drag-scenario-text "(drag air :on ball :quadratic b)"))))))
    (is (equal '(:drag "AIR" :on "BALL" :law :quadratic :coefficient "B")
               (mapcar (lambda (x) (if (and (symbolp x) (not (keywordp x))) (string x) x))
                       (first (ames.scenario:scenario-kb-clauses scenario)))))))

(defparameter *drag-onto-ground*
  "(scenario drag-onto-ground
     \"A ball dropped through a viscous medium onto the ground.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
                 (c :positive (:value 1/2)) (h :positive (:value 10)))
     (gravity g)
     (body ground :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
     (drag air :on ball :linear c)
     (simulate :states 3))"
  "Linear drag to the ground: the landing time is a Lambert W (no closed form from solve()).")

(test linear-drag-lands-at-a-number
  "Under values the ball lands where its closed-form height is zero (a number: the root has
no closed form), with the closed-form velocity then; the plastic impact stops it on the
ground, where it rests; the self-check passes."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *drag-onto-ground*)))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (states (ames::history-states history))
           (falling (first states))
           (values (ames:scenario-parameter-values scenario))
           (check (ames.check:self-check-result history)))
      (is (= 2 (length states)))
      (is (equal '(:collision "BALL" "GROUND") (event-names (ames::state-end-event falling))))
      (let ((time (ames::state-duration falling)))
        (is (realp time))
        (when (realp time)
          (flet ((at-landing (expression)
                   (ames.maxima:numeric-value bridge (at-variable expression 'tau (rational time)) values)))
            (is (< (abs (at-landing (y-of falling :pos))) 1d-9) "height at landing")
            (is (< (abs (- (at-landing (y-of falling :vel))
                           (second (per-body (ames::state-final-velocities falling) "BALL"))))
                   1d-9)
                "velocity at landing"))))
      (is (equal '(0 0) (per-body (ames::state-final-positions falling) "BALL")))
      (is (eq :forever (ames::state-duration (second states))))
      (is (null (getf check :failures)) "self-check failures ~S" (getf check :failures)))))

;;; Bounces under drag (make crosscheck found AMES summing them as a geometric series)

(test bounces-under-drag-are-no-geometric-series
  "A ball bouncing elastically (e = 1) under linear drag loses speed only to the drag, and
a smaller fraction of it the slower it goes (the flight's loss is of order b v / m g of
its speed): the ratio of successive impact speeds grows toward 1, so the impacts form no
geometric series and never accumulate. (AMES summed them from the first two cycles, as
under gravity alone, and put the ball at rest at t = 4.12; the witness has impacts at
1.058, 2.060, 2.767, 3.316 s.)"
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history)
        (drag-form-history "(scenario drag-bounces \"\" (gravity 17/2) (restitution 1)
                              (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                              (body ball :mass 1/2 :position (0 13/4) :velocity (0 0) :shape point)
                              (drag air :on ball :linear 3/5) (simulate :states 4))"
                           bridge)
      (declare (ignore scenario))
      (let* ((states (ames::history-states history))
             (speeds (loop for state in states
                           for impact = (ames.simulator:state-impact state)
                           when impact
                             collect (abs (expression-value
                                           (second (per-body (getf impact :velocities-before) "BALL")))))))
        (is (notany #'ames.simulator:state-accumulation states) "no accumulation under drag")
        (is (= 4 (length states)))
        (is (<= 3 (length speeds)) "impact speeds ~S" speeds)
        (when (<= 3 (length speeds))
          (destructuring-bind (v1 v2 v3 &rest more) speeds
            (declare (ignore more))
            (is (> v1 v2 v3) "the speeds fall: ~S" speeds)
            (is (> (/ v3 v2) (+ (/ v2 v1) 1/100)) "the ratio grows: ~S" speeds)
            ;; the second impact at t = 2.0603 (the witness: 2.06029179577)
            (is (< (abs (- (expression-value (ames::state-start (third states))) 2.06029179577d0)) 1d-8))))))))
