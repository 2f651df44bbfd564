;;;; t/springs-ropes-gravitation.lisp -- forces that depend on where the bodies are (thesis 3.3.2,
;;;; "Springs", "Ropes", "Universal Gravitation", "Momentum and Energy"): a bumper spring, two
;;;; masses on a spring, an Atwood machine, a block pulled over a table's edge, two spheres
;;;; falling together; energy and momentum conserved where they must be; the clauses'
;;;; validation and the pieces the simulator adds for them.
;;;;
;;;; Expected results are the scenario files' headers, written over each scenario's own
;;;; parameters and compared by Maxima-checked equivalence (helpers in
;;;; t/simulator-scenarios.lisp).

(in-package #:ames.tests)

(def-suite forces :in all-tests
  :description "Springs, ropes over pulleys, universal gravitation, energy and momentum.")

(in-suite forces)

;;; Helpers

(defun run-scenario-file (name bridge &key parameter-values)
  "The scenario of scenarios/NAME.lisp and its history (stopped at an ambiguity)."
  (let ((scenario (scenario-named name)))
    (values scenario (simulate-stopping-when-ambiguous scenario bridge
                                                       :parameter-values parameter-values))))

(defun reported-section (state section)
  "The entries of the knowledge base's report SECTION (:ENERGY, :MOMENTUM) in STATE."
  (getf (ames.simulator:state-reported-sections state) section))

(defun total-energy (state)
  "The sum of every energy STATE reports (kinetic and potential), an expression over the
state's variable."
  (cons '+ (mapcar #'third (reported-section state :energy))))

(defun total-momentum (state axis)
  "The sum of the AXIS components of every momentum STATE reports."
  (cons '+ (mapcar (lambda (entry) (funcall (if (eq axis :x) #'first #'second) (third entry)))
                   (reported-section state :momentum))))

(defun at-variable (expression variable value)
  "EXPRESSION with the symbol VARIABLE replaced by VALUE."
  (ames.base:substitute-expressions (list (cons variable value)) expression))

(defun force-entry (state kind &rest names)
  "The entry (KIND NAME... VALUE) of STATE's forces whose names are NAMES, or NIL."
  (find-if (lambda (entry)
             (and (eq (first entry) kind)
                  (every #'same-name-p* names (subseq (rest entry) 0 (length names)))))
           (ames::state-forces-of state)))

(defun is-conserved (bridge what expression variable start)
  "Check that EXPRESSION, a function of VARIABLE, equals its value at START throughout."
  (is-same bridge what expression (at-variable expression variable start)))

;;; A bumper spring

(test block-bounces-off-a-bumper
  "The block meets the bumper after d / v0, stays in contact pi sqrt(m/k), compressing it by
v0 sqrt(m/k) half-way, leaves it with its velocity reversed and slides away forever; the
energy m v0^2/2 is shared between the block and the spring meanwhile."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "block-hits-bumper" bridge)
      (let ((states (ames::history-states history)))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
          (is (= 3 (length states)))
          (destructuring-bind (&optional approach pressed away) states
            (when away
              (is (equal '(:contact "BLOCK" "BUMPER") (event-names (ames::state-end-event approach))))
              (is (equal '(:leaves "BLOCK" "BUMPER") (event-names (ames::state-end-event pressed))))
              (is (eq :forever (ames::state-duration away)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "time to the bumper" (ames::state-duration approach) (x '(/ d v0)))
                 (is-same bridge "contact time" (ames::state-duration pressed) (x '(* pi (sqrt (/ m k)))))
                 (is-same-vector bridge "leaves with the velocity reversed"
                                 (per-body (ames::state-final-velocities pressed) "BLOCK") (x '(v0 0)))
                 (let* ((half (x '(* 1/2 pi (sqrt (/ m k)))))
                        (front (first (per-body (ames::state-positions pressed) "BLOCK"))))
                   (is-same bridge "maximum compression"
                            (at-variable `(- ,(x 'l0) ,front) 'tau half) (x '(* v0 (sqrt (/ m k)))))
                   (is-same bridge "the spring's push then"
                            (at-variable (first (fourth (force-entry pressed :spring "BUMPER" "BLOCK")))
                                         'tau half)
                            (x '(* k v0 (sqrt (/ m k))))))
                 (is-conserved bridge "energy while pressed" (total-energy pressed) 'tau 0)
                 (is-same bridge "the energy" (at-variable (total-energy pressed) 'tau 0)
                          (x '(* 1/2 m (expt v0 2)))))))))))))

;;; Two masses joined by a spring

(test two-masses-oscillate-on-a-spring
  "Pushed, the second particle drags the first: the centre of mass moves uniformly and the
stretch oscillates at sqrt(k (m1 + m2)/(m1 m2)); momentum and energy are conserved."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "two-masses-on-a-spring" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (when state
            (is (eq :forever (ames::state-duration state)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((w (x '(sqrt (/ (* k (+ m1 m2)) (* m1 m2))))))
                 (is-same-vector bridge "first"
                                 (per-body (ames::state-positions state) "FIRST")
                                 (x `((/ (* m2 v0 (- tau (/ (sin (* ,w tau)) ,w))) (+ m1 m2)) 0)))
                 (is-same-vector bridge "second"
                                 (per-body (ames::state-positions state) "SECOND")
                                 (x `((+ l0 (/ (+ (* m2 v0 tau) (/ (* m1 v0 (sin (* ,w tau))) ,w)) (+ m1 m2))) 0))))
               (is-same bridge "momentum" (total-momentum state :x) (x '(* m2 v0)))
               (is-same bridge "energy" (total-energy state) (x '(* 1/2 m2 (expt v0 2))))))))))))

;;; An Atwood machine

(test atwood-machine-falls-slackens-and-jerks
  "Taut: accelerations g (m1 - m2)/(m1 + m2), tension 2 g m1 m2/(m1 + m2), the heavier
mass lands after sqrt(2 h (m1 + m2)/(g (m1 - m2))); it stops, the rope goes slack and the
lighter mass rises freely, the rope tightening again after 2 v / g and jerking both to
m2 v / (m1 + m2); energy conserved while taut."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "atwood-machine" bridge)
      (let ((states (ames::history-states history)))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (= 3 (length states)) "~D states" (length states))
          (destructuring-bind (&optional taut slack jerked) states
            (when jerked
              (is (equal '(:collision "HEAVY" "FLOOR") (event-names (ames::state-end-event taut))))
              (is (equal '(:tightens "ROPE") (event-names (ames::state-end-event slack))))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (let ((a (x '(/ (* g (- m1 m2)) (+ m1 m2))))
                       (v (x '(sqrt (/ (* 2 g h (- m1 m2)) (+ m1 m2))))))
                   (is-same-vector bridge "heavy accelerates down"
                                   (per-body (ames::state-accelerations taut) "HEAVY") `(0 (- ,a)))
                   (is-same-vector bridge "light accelerates up"
                                   (per-body (ames::state-accelerations taut) "LIGHT") `(0 ,a))
                   (is-same bridge "tension" (third (force-entry taut :tension "ROPE"))
                            (x '(/ (* 2 g m1 m2) (+ m1 m2))))
                   (is-same bridge "time to the floor" (ames::state-duration taut)
                            (x '(sqrt (/ (* 2 h (+ m1 m2)) (* g (- m1 m2))))))
                   (is-conserved bridge "energy while taut" (total-energy taut) 'tau 0)
                   (is-same bridge "slack rope" (third (force-entry slack :tension "ROPE")) 0)
                   (is-same-vector bridge "the lighter mass keeps rising"
                                   (per-body (ames:state-initial-velocities slack) "LIGHT") `(0 ,v))
                   (is-same bridge "free flight until the rope tightens" (ames::state-duration slack)
                            (x `(/ (* 2 ,v) g)))
                   (is-same-vector bridge "the jerk lifts the heavier mass"
                                   (per-body (ames:state-initial-velocities jerked) "HEAVY")
                                   (x `(0 (/ (* m2 ,v) (+ m1 m2)))))
                   (is-same-vector bridge "and slows the lighter one"
                                   (per-body (ames:state-initial-velocities jerked) "LIGHT")
                                   (x `(0 (- (/ (* m2 ,v) (+ m1 m2))))))))))))))))

;;; A block pulled over a table's edge

(test block-pulled-over-the-table-edge
  "Both accelerate at g m2/(m1 + m2), the tension is g m1 m2/(m1 + m2), and the block
reaches the pulley's block after sqrt(2 d (m1 + m2)/(g m2))."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "block-pulled-over-table-edge" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (when state
            (is (equal '(:collision "BLOCK" "STOP") (event-names (ames::state-end-event state))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((a (x '(/ (* g m2) (+ m1 m2)))))
                 (is-same-vector bridge "the block" (per-body (ames::state-accelerations state) "BLOCK")
                                 `(,a 0))
                 (is-same-vector bridge "the weight" (per-body (ames::state-accelerations state) "WEIGHT")
                                 `(0 (- ,a)))
                 (is-same bridge "tension" (third (force-entry state :tension "CORD"))
                          (x '(/ (* g m1 m2) (+ m1 m2))))
                 (is-same bridge "time to the pulley" (ames::state-duration state)
                          (x '(sqrt (/ (* 2 d (+ m1 m2)) (* g m2)))))
                 (is-conserved bridge "energy" (total-energy state) 'tau 0))))))))))

;;; A particle on an incline tied over a pulley to a hanging mass

(test incline-pulled-up-by-a-hanging-mass
  "Along the 3-4-5 slope the particle accelerates up at g e/(m1 + m2), m2 = 3 m1/5 + e, the
tension is 8 g m1 m2/(5 (m1 + m2)), and it reaches the top corner after
sqrt(5 (m1 + m2)/(g e))."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "incline-and-hanging-mass" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (when state
            (is (equal '(:leaves "PARTICLE" "INCLINE" :endpoint) (event-names (ames::state-end-event state))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let* ((m2 '(+ (* 3/5 m1) e))
                      (a (x `(/ (* g e) (+ m1 ,m2)))))
                 (is-same-vector bridge "up the slope" (per-body (ames::state-accelerations state) "PARTICLE")
                                 `((* 4/5 ,a) (* 3/5 ,a)))
                 (is-same-vector bridge "the weight" (per-body (ames::state-accelerations state) "WEIGHT")
                                 `(0 (- ,a)))
                 (is-same bridge "tension" (third (force-entry state :tension "LINE"))
                          (x `(/ (* 8 g m1 ,m2) (* 5 (+ m1 ,m2)))))
                 (is-same bridge "time to the top" (ames::state-duration state)
                          (x `(sqrt (/ (* 5 (+ m1 ,m2)) (* g e)))))
                 (is-conserved bridge "energy" (total-energy state) 'tau 0))))))))))

;;; Two spheres under their mutual gravitation

(test spheres-fall-together
  "From rest at distance d they meet when their distance is a + b, after
sqrt(d^3/(2 G (m1 + m2))) (sqrt(s (1 - s)) + acos(sqrt(s))), s = (a + b)/d, along the line
of centres (a motion of one degree of freedom); momentum stays zero and the energy
-G m1 m2 / d."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "spheres-under-gravitation" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (when state
            (is (equal '(:collision "FIRST" "SECOND") (event-names (ames::state-end-event state))))
            (is (equal '(:line) (remove-duplicates (mapcar #'second (getf (ames::state-analysis state)
                                                                          :integrators)))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               ;; with s = (a + b)/d: sqrt(s (1 - s)) = sqrt(a + b) sqrt(d - a - b) / d and
               ;; acos(sqrt(s)) = pi/2 - asin(sqrt(s)), forms Maxima's simplifier keeps apart
               (is-same bridge "time to contact" (ames::state-duration state)
                        (x '(* (/ (* d (sqrt d)) (sqrt (* 2 big-g (+ m1 m2))))
                               (+ (/ (* (sqrt (+ a b)) (sqrt (- d a b))) d)
                                  (- (/ pi 2) (asin (/ (sqrt (+ a b)) (sqrt d))))))))
               (is-same bridge "momentum" (total-momentum state :x) 0)
               (is-same bridge "energy" (total-energy state) (x '(- (/ (* big-g m1 m2) d))))
               (let ((first (per-body (ames::state-final-positions state) "FIRST"))
                     (second (per-body (ames::state-final-positions state) "SECOND")))
                 (is-same bridge "they touch" `(- ,(first second) ,(first first)) (x '(+ a b)))
                 (is-same bridge "the centre of mass stays"
                          (x `(+ (* m1 ,(first first)) (* m2 ,(first second)))) (x '(* m2 d))))))))))))

;;; A spring pendulum released from rest off the vertical: the span turns from the start

(defparameter *spring-pendulum*
  '(scenario spring-pendulum "A mass on a spring released from rest off the vertical."
    (parameters (m :positive) (k :positive) (g :positive))
    (gravity g)
    (body support :fixed t :position (0 3) :shape point)
    (body bob :mass m :position (1 2) :velocity (0 0) :shape point)
    (spring coil :from (support (0 0)) :to (bob (0 0)) :stiffness k :rest-length 1)
    (simulate :states 2 :until 2))
  "A spring whose span must turn at once: no closed form; numbers under parameter values.")

(test spring-pendulum-turns-and-is-integrated-numerically
  "Released from rest off the vertical, the bob's pull across the spring makes the span's
fixed direction fail at once: it turns from the start (no closed form, so the run says so
without numbers), and with numbers it is integrated up to the time limit, conserving
m g y + m v^2/2 + k (l - 1)^2/2."
  (with-fixture simulator-bridge ()
    (let ((history (simulate-stopping-when-ambiguous (ames:parse-scenario *spring-pendulum*) bridge)))
      (is (eq :undecided (ames::history-outcome history)))
      (is (equal '(:numeric) (mapcar #'second (getf (ames::state-analysis (first (ames::history-states history)))
                                                    :integrators)))))
    (let* ((values '((m . 1) (k . 5) (g . 981/100)))
           (history (simulate-stopping-when-ambiguous (ames:parse-scenario *spring-pendulum*) bridge
                                                      :parameter-values values))
           (state (first (ames::history-states history)))
           (numeric (ames.simulator:state-numbers state)))
      (is (eq :time-limit (ames::history-outcome history)))
      (destructuring-bind (x y) (per-body (getf numeric :final-positions) "BOB")
        (destructuring-bind (vx vy) (per-body (getf numeric :final-velocities) "BOB")
          (let ((energy (+ (* 981/100 y) (* 1/2 (+ (* vx vx) (* vy vy)))
                           (* 5/2 (expt (- (sqrt (+ (* x x) (expt (- y 3) 2))) 1) 2))))
                (start (+ (* 981/100 2) (* 5/2 (expt (- (sqrt 2d0) 1) 2)))))
            (is (< (abs (- energy start)) 1d-6) "energy ~F, at the start ~F" energy start)))))))

;;; A bumper already compressed at the start

(defparameter *pressed-bumper*
  '(scenario pressed-bumper "A block at rest against a bumper (rest length 1) compressed by 1/2."
    (parameters (m :positive) (k :positive))
    (body wall :fixed t :shape (polygon (-1 0) (0 0) (0 2) (-1 2)))
    (body block :mass m :position (1/2 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
    (spring bumper :from (wall (0 1/2)) :toward (1 0) :stiffness k :rest-length 1)
    (simulate :states 2))
  "A bumper pressed at the start of the run.")

(test a-compressed-bumper-pushes-from-the-start
  "A block held against a bumper compressed by c = 1/2 is pressing it from the start:
released, it is pushed off after a quarter period, pi/2 sqrt(m/k), at c sqrt(k/m)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario *pressed-bumper*))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (when state
          (is (equal '(:leaves "BLOCK" "BUMPER") (event-names (ames::state-end-event state))))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "a quarter period" (ames::state-duration state) (x '(* 1/2 pi (sqrt (/ m k)))))
             (is-same-vector bridge "pushed off" (per-body (ames::state-final-velocities state) "BLOCK")
                             (x '((* 1/2 (sqrt (/ k m))) 0))))))))))

;;; The clauses

(defun clause-error (clauses)
  "The SCENARIO-ERROR a scenario of CLAUSES (after a body A, a fixed wall W and the
parameter K) signals, or NIL."
  (handler-case
      (progn (ames:parse-scenario `(scenario bad (parameters (k :positive))
                                     (body w :fixed t :shape (half-plane (0 1) (0 0)))
                                     (body a :mass 1 :position (1 0) :velocity (0 0) :shape point)
                                     ,@clauses))
             nil)
    (ames:scenario-error (condition) condition)))

(test spring-rope-and-gravitation-clauses-are-checked
  "Malformed spring, pulley, rope and gravitation clauses are scenario errors naming the
clause; a spring's rest length defaults to its length at the start."
  (flet ((fails (class clauses)
           (let ((condition (clause-error clauses)))
             (is (typep condition class) "~S gave ~S" clauses condition))))
    (fails 'ames:missing-property-error '((spring s :from (w (0 0)) :to (a (0 0)))))
    (fails 'ames:scenario-syntax-error '((spring s :from (w (0 0)) :to (a (0 0)) :toward (1 0) :stiffness k)))
    (fails 'ames:missing-property-error '((spring s :from (w (0 0)) :toward (1 0) :stiffness k)))
    (fails 'ames:scenario-syntax-error '((spring s :from (a (0 0)) :to (a (1 0)) :stiffness k)))
    (fails 'ames:scenario-expression-error '((spring s :from (w (0 0)) :toward (0 0) :stiffness k :rest-length 1)))
    (fails 'ames:scenario-expression-error '((spring s :from (w (0 0)) :to (a (0 0)) :stiffness -2)))
    (fails 'ames:undeclared-symbol-error '((spring s :from (nobody (0 0)) :to (a (0 0)) :stiffness k)))
    (fails 'ames:duplicate-name-error '((spring a :from (w (0 0)) :to (a (0 0)) :stiffness k)))
    (fails 'ames:undeclared-symbol-error '((rope r :length 2 :through ((w (0 0)) nowhere (a (0 0))))))
    (fails 'ames:scenario-syntax-error '((pulley p :on w :at (0 1))
                                         (rope r :length 2 :through ((w (0 0)) p p (a (0 0))))))
    (fails 'ames:scenario-syntax-error '((rope r :length 2 :through ((a (0 0))))))
    (fails 'ames:missing-property-error '((pulley p :on w)))
    (fails 'ames:duplicate-clause-error '((gravitation 1) (gravitation 2)))
    (fails 'ames:scenario-expression-error '((gravitation 0))))
  (let* ((scenario (ames:parse-scenario '(scenario ok (parameters (k :positive))
                                           (body w :fixed t :position (0 1) :shape (half-plane (0 1) (0 0)))
                                           (body a :mass 1 :position (3 4) :velocity (0 0) :shape point)
                                           (spring s :from (w (0 -1)) :to (a (0 0)) :stiffness k))))
         (spring (first (ames.scenario:scenario-springs scenario))))
    (is (= 5 (ames.base:expression-value (ames.scenario:scenario-spring-rest-length spring))))))

(test an-impact-event-gets-the-impulses-of-what-it-names
  "The event of an impact takes the impulses of the impact's entries that name only what
it names: a contact's (:impulse A B J), a rope's (:rope-impulse R J)."
  (let ((impact '(:impulses ((:impulse a b 3) (:impulse a c 4) (:rope-impulse r 5)) :energy-lost 7)))
    (is (equal '(:collision a b :impulse 3 :energy-lost 7)
               (ames.simulator::impact-event '(:collision a b) impact)))
    (is (equal '(:tightens r :impulse 5 :energy-lost 7)
               (ames.simulator::impact-event '(:tightens r) impact)))))

;;; A particle around a fixed sun: no closed form, numbers under parameter values

(test a-circular-orbit-is-integrated-numerically
  "A planet at distance 1 from a fixed sun (G M = 1) with speed 1 goes round a circle: no
closed form (the run says so without numbers); with numbers, at t = 3 it is at
(cos 3, sin 3)."
  (with-fixture simulator-bridge ()
    (let ((form '(scenario orbit "A particle around a fixed sun."
                  (parameters (big-m :positive) (big-g :positive) (m :positive) (v :positive))
                  (gravitation big-g)
                  (body sun :fixed t :mass big-m :position (0 0) :shape (circle 1/10))
                  (body planet :mass m :position (1 0) :velocity (0 v) :shape point)
                  (simulate :states 2 :until 3))))
      (is (eq :undecided (ames::history-outcome
                          (simulate-stopping-when-ambiguous (ames:parse-scenario form) bridge))))
      (let* ((history (simulate-stopping-when-ambiguous
                       (ames:parse-scenario form) bridge
                       :parameter-values '((big-m . 1) (big-g . 1) (m . 1/1000) (v . 1))))
             (state (first (ames::history-states history)))
             (at (per-body (getf (ames.simulator:state-numbers state) :final-positions) "PLANET")))
        (is (eq :time-limit (ames::history-outcome history)))
        (is (and at (< (abs (- (first at) (cos 3d0))) 1d-6) (< (abs (- (second at) (sin 3d0))) 1d-6))
            "the planet at ~S" at)))))

;;; A rope that would have to push is slack

(test a-rope-that-would-push-is-slack
  "A mass hanging on a rope at its full length, pushed up harder than its weight: taut, the
tension would be negative ((:slackens rope) at once), so the rope is slack from the start
and the mass rises at f/m - g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      '(scenario pushed-up "A hanging mass pushed up."
                        (parameters (m :positive) (g :positive) (f (> f (* m g))))
                        (gravity g)
                        (body ceiling :fixed t :position (0 2) :shape point)
                        (body bob :mass m :position (0 0) :velocity (0 0) :shape point)
                        (force push :on bob :value (0 f))
                        (rope cord :length 2 :through ((ceiling (0 0)) (bob (0 0))))
                        (simulate :states 1))))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (when state
          (is (equal '(:slack)
                     (loop for (key . option) in (getf (getf (ames::state-analysis state) :choices) :chosen)
                           when (mentions-name-p "CORD" key) collect option))
              "the rope's mode chosen: ~S" (getf (ames::state-analysis state) :choices))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "slack" (third (force-entry state :tension "CORD")) 0)
             (is-same-vector bridge "rising" (per-body (ames::state-accelerations state) "BOB")
                             (x '(0 (- (/ f m) g)))))))))))
