;;;; t/wound-ropes.lisp -- hinges and ropes wound on turning discs (issue 23): an Atwood machine
;;;; over a massive pulley, a yo-yo, the force of the hinge of a swinging rod, a drum whose rope
;;;; runs over a pulley, and the refusals of a wound rope that would swing and of an impact
;;;; with a hinge.
;;;;
;;;; Expected results are the textbook's, written in the scenario files' headers:
;;;;   Atwood machine over a disc pulley of inertia I, radius R, mass M, hinged at its centre:
;;;;     a = (m1 - m2) g / (m1 + m2 + I/R^2), the pulley's angular acceleration a/R,
;;;;     T1 = m1 (g - a), T2 = m2 (g + a), the hinge holds M g + T1 + T2,
;;;;     m1 reaches the floor after sqrt(2 h / a);
;;;;   yo-yo of inertia I, mass m, its string wound on its axle of radius r:
;;;;     a = g / (1 + I/(m r^2)) down, tension m g / (1 + m r^2 / I), angular acceleration a/r;
;;;;   a uniform rod hinged at one end, released horizontal: alpha = -3 g cos(theta)/(2 l), the
;;;;     hinge holds m g/4 at release and (5/2) m g at the bottom (omega^2 = 3 g/l there).
;;;; Compared by Maxima-checked equivalence over the parameters (helpers in
;;;; t/simulator-scenarios.lisp and t/springs-ropes-gravitation.lisp), and under the
;;;; scenarios' parameter values with a numeric run.

(in-package #:ames.tests)

(def-suite wound-ropes :in all-tests
  :description "Hinges and ropes wound on turning discs: the massive-pulley Atwood machine, the yo-yo.")

(in-suite wound-ropes)

(defun scenario-named-with-states (name states)
  "The scenario of scenarios/NAME.lisp with its (simulate ...) clause asking for STATES
states only (the first states' tests need not run the rest)."
  (let* ((file (find name (scenario-files) :key #'pathname-name :test #'string=))
         (form (first (ames:read-scenario-forms (uiop:read-file-string file)))))
    (ames:parse-scenario
     (mapcar (lambda (clause)
               (if (and (consp clause) (symbolp (first clause))
                        (string= (symbol-name (first clause)) "SIMULATE"))
                   (list (first clause) :states states)
                   clause))
             form))))

(defun angular-acceleration-in (state body)
  "The angular acceleration STATE reports for the body named BODY."
  (per-body (ames.simulator::state-angular-accelerations state) body))

(defun same-under-values-p (bridge actual expected values)
  "True when the expressions ACTUAL and EXPECTED have the same value (to 1e-9, relative)
under the parameter VALUES (an alist)."
  (let ((a (ames.maxima:numeric-value bridge actual values))
        (e (ames.maxima:numeric-value bridge expected values)))
    (and (realp a) (realp e) (<= (abs (- a e)) (* 1d-9 (max 1 (abs e)))))))

(defun massive-atwood-expectations (x)
  "The massive-pulley Atwood machine's textbook results, a plist over the scenario's
parameters (X maps this file's symbols to them)."
  (let* ((a (funcall x '(/ (* (- m1 m2) g) (+ m1 m2 (/ i (expt big-r 2))))))
         (t1 (funcall x `(* m1 (- g ,a))))
         (t2 (funcall x `(* m2 (+ g ,a)))))
    (list :a a :alpha (funcall x `(/ ,a big-r)) :t1 t1 :t2 t2
          :hinge (funcall x `(+ (* big-m g) ,t1 ,t2))
          :time (funcall x `(sqrt (/ (* 2 h) ,a))))))

(defun check-massive-atwood (bridge state expected &optional values)
  "Check STATE, the massive-pulley Atwood machine's first state, against the plist
EXPECTED: symbolically (Maxima-checked equivalence) or, with VALUES, numerically."
  (flet ((same (what actual wanted)
           (if values
               (is (same-under-values-p bridge actual wanted values) "~A: got ~S, expected ~S"
                   what actual wanted)
               (is-same bridge what actual wanted))))
    (let ((heavy (per-body (ames::state-accelerations state) "HEAVY"))
          (light (per-body (ames::state-accelerations state) "LIGHT"))
          (hinge (force-entry state :hinge "AXLE")))
      (same "heavy falls" (second heavy) `(- ,(getf expected :a)))
      (same "heavy does not move sideways" (first heavy) 0)
      (same "light rises" (second light) (getf expected :a))
      (same "the pulley turns counter-clockwise" (angular-acceleration-in state "PULLEY")
            (getf expected :alpha))
      (same "tension on the heavy side" (third (force-entry state :tension "LEFT")) (getf expected :t1))
      (same "tension on the light side" (third (force-entry state :tension "RIGHT")) (getf expected :t2))
      (is (not (null hinge)) "the hinge's force is reported")
      (when hinge
        (same "the hinge pulls up with the weight and both tensions" (second (fourth hinge))
              (getf expected :hinge))
        (same "and not sideways" (first (fourth hinge)) 0))
      (same "heavy reaches the floor" (ames::state-duration state) (getf expected :time)))))

(test massive-pulley-atwood-machine
  "An Atwood machine over a hinged disc pulley: a = (m1 - m2) g/(m1 + m2 + I/R^2), each
rope its own tension, the hinge holding the pulley's weight and both tensions; the
query (y (hinge-force axle)) reads the same; the heavier mass lands after sqrt(2 h/a)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named-with-states "atwood-massive-pulley" 1))
           (history (simulate-stopping-when-ambiguous scenario bridge)))
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (not (null state)))
          (when state
            (is (equal '(:collision "HEAVY" "FLOOR") (event-names (ames::state-end-event state))))
            (let ((expected (massive-atwood-expectations #'x)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (check-massive-atwood bridge state expected)
                 (is-conserved bridge "energy, the pulley's turning included" (total-energy state) 'tau 0)
                 (is-same bridge "the query reads the hinge's force"
                          (second (find "HINGE-HOLDS" (ames:history-answers history)
                                        :key #'first :test #'same-name-p*))
                          (getf expected :hinge)))))))))))

(test massive-pulley-atwood-machine-with-values
  "The same machine run under its parameters' values: the numbers the formulas give."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named-with-states "atwood-massive-pulley" 1))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (not (null state)))
        (when state
          (is (equal '(:collision "HEAVY" "FLOOR") (event-names (ames::state-end-event state))))
          (check-massive-atwood bridge state (massive-atwood-expectations #'x)
                                (ames:scenario-parameter-values scenario)))))))

(defun yoyo-expectations (x)
  "The falling yo-yo's textbook results, a plist over the scenario's parameters."
  (let ((a (funcall x '(/ g (+ 1 (/ i (* m (expt r 2))))))))
    (list :a a :alpha (funcall x `(/ ,a r))
          :tension (funcall x '(/ (* m g) (+ 1 (/ (* m (expt r 2)) i)))))))

(defun check-yoyo (bridge state expected &optional values)
  "Check STATE, the yo-yo's fall, against the plist EXPECTED (symbolically, or
numerically under VALUES)."
  (flet ((same (what actual wanted)
           (if values
               (is (same-under-values-p bridge actual wanted values) "~A: got ~S, expected ~S"
                   what actual wanted)
               (is-same bridge what actual wanted))))
    (let ((acceleration (per-body (ames::state-accelerations state) "YOYO")))
      (same "the yo-yo falls" (second acceleration) `(- ,(getf expected :a)))
      (same "straight down" (first acceleration) 0)
      (same "turning counter-clockwise" (angular-acceleration-in state "YOYO") (getf expected :alpha))
      (same "the string's tension" (third (force-entry state :tension "STRING")) (getf expected :tension)))))

(test yoyo-falls-as-its-string-unwinds
  "A yo-yo falls at g/(1 + I/(m r^2)), its string's tension m g/(1 + m r^2/I), symbolically
and under its parameters' values; its energy (the turning included) is conserved."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "yoyo-falling" bridge)
      (let ((state (first (ames::history-states history))))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (not (null state)))
          (when state
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (check-yoyo bridge state (yoyo-expectations #'x))
               (is-conserved bridge "energy" (total-energy state) 'tau 0)))
            (let* ((numeric (ames:run-scenario scenario :bridge bridge :numeric t))
                   (numeric-state (first (ames::history-states numeric))))
              (is (not (null numeric-state)))
              (when numeric-state
                (check-yoyo bridge numeric-state (yoyo-expectations #'x)
                            (ames:scenario-parameter-values scenario))))))))))

;;; A rod on a hinge: the hinge's force (the swing itself has no closed form in time here)

(defparameter *hinged-rod*
  "(scenario hinged-rod \"A uniform rod hinged at one end, released horizontal above a floor.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
                 (d :positive (< d l) (:value 1/2)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 (- d)) (0 (- d))))
     (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position ((/ l 2) 0) :velocity (0 0))
     (hinge pin :body rod :at ((- (/ l 2)) 0))
     (simulate :states 1))"
  "The rod of scenarios/awaiting-rotation/rod-hinged-released-horizontal.lisp above a floor
at depth d < l: one state along its angle (the energy integral), ended by its free end
striking the floor (the swing's turning point, and a time limit, have no closed form yet).")

(defun at-rotation (expression angle angular-velocity)
  "EXPRESSION with every rotating body's angle term put to ANGLE and its angular velocity
term to ANGULAR-VELOCITY; in a state along one body's angle (a rotation path, whose
coordinate is the angle: the simulator's ARC-LENGTH symbol), that coordinate to ANGLE (the
angular velocity there is already the energy integral's, a function of the angle)."
  (cond ((eq expression 'ames.simulator::arc-length) angle)
        ((and (consp expression) (eq (first expression) 'ames.kb:angle)) angle)
        ((and (consp expression) (eq (first expression) 'ames.kb:angvel)) angular-velocity)
        ((consp expression) (mapcar (lambda (x) (at-rotation x angle angular-velocity)) expression))
        (t expression)))

(test hinge-holds-a-swinging-rod
  "A uniform rod (m, l) hinged at one end and released horizontal: its angular acceleration
is -3 g cos(theta)/(2 l); the hinge holds m g/4 at release and, at the bottom, where energy
gives omega^2 = 3 g/l, (5/2) m g straight up (the weight plus m omega^2 l/2): the
formulas of the state along its angle, evaluated at those angles."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *hinged-rod*)))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (not (null state)))
        (when state
          (let ((alpha (angular-acceleration-in state "ROD"))
                (hinge (fourth (force-entry state :hinge "PIN"))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "angular acceleration at release" (at-rotation alpha 0 0)
                        (x '(- (/ (* 3 g) (* 2 l)))))
               (is-same bridge "angular acceleration at 60 degrees down" (at-rotation alpha '(- (/ pi 3)) 0)
                        (x '(- (/ (* 3 g) (* 4 l)))))
               (is-same bridge "none at the bottom" (at-rotation alpha '(- (/ pi 2)) 0) 0)
               (is-same-vector bridge "the hinge at release" (at-rotation hinge 0 0) (x '(0 (/ (* m g) 4))))
               (is-same-vector bridge "the hinge at the bottom"
                               (at-rotation hinge '(- (/ pi 2)) (x '(- (sqrt (/ (* 3 g) l)))))
                               (x '(0 (* 5/2 m g))))))))))))

;;; A drum whose rope runs over a pulley; a wound rope that would swing

(defparameter *drum-over-pulley*
  "(scenario drum-over-pulley \"A hinged drum, its rope wound on top and led over a pulley to a hanging mass.\"
     (parameters (m :positive (:value 1)) (big-m :positive (:value 2)) (big-r :positive (:value 1/5))
                 (i :positive (:value 1/25)) (g :positive (:value 981/100))
                 (d :positive (> d big-r) (:value 1)) (h :positive (:value 1)))
     (gravity g)
     (body drum :mass big-m :inertia i :shape (circle big-r) :position (0 0) :velocity (0 0))
     (hinge axle :body drum :at (0 0))
     (body support :fixed t :shape point :position (d big-r))
     (pulley wheel :on support :at (0 0))
     (body weight :mass m :shape point :position (d (- big-r h)) :velocity (0 0))
     (rope cord :length (+ d h) :through ((drum (0 big-r) :wound) wheel (weight (0 0))))
     (simulate :states 1 :until 1/4))"
  "A rope wound first (on top of a hinged drum), horizontal to a pulley, then down.")

(test drum-pays-out-over-a-pulley
  "A drum (inertia I, radius R) whose rope leaves its top, runs over a pulley and holds a
mass m: a = g/(1 + I/(m R^2)) down, the drum turning clockwise at a/R, the tension
m g/(1 + m R^2/I), and the hinge pushing back against the rope: (-T, M g)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *drum-over-pulley*)))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (state (first (ames::history-states history))))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (not (null state)))
        (when state
          (let ((a (x '(/ g (+ 1 (/ i (* m (expt big-r 2)))))))
                (tension (x '(/ (* m g) (+ 1 (/ (* m (expt big-r 2)) i))))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "the mass falls" (per-body (ames::state-accelerations state) "WEIGHT")
                               `(0 (- ,a)))
               (is-same bridge "the drum turns clockwise" (angular-acceleration-in state "DRUM")
                        `(- (/ ,a ,(x 'big-r))))
               (is-same bridge "tension" (third (force-entry state :tension "CORD")) tension)
               (is-same-vector bridge "the hinge" (fourth (force-entry state :hinge "AXLE"))
                               `((- ,tension) ,(x '(* big-m g))))))))))))

(test a-wound-rope-that-would-swing-is-refused
  "A yo-yo hung from a point off to its side: its string's piece would swing round the disc
(the tangent point wandering), which is not modelled: the run stops with an
UNMODELLED-SITUATION rather than a wrong answer."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string
                             "(scenario slanted-yoyo \"A yo-yo on a slanted string.\"
                                (parameters (m :positive) (g :positive) (r :positive) (i :positive)
                                            (top :positive (> top r)))
                                (gravity g)
                                (body ceiling :fixed t :shape (half-plane (0 top) (1 top)))
                                (body yoyo :mass m :inertia i :shape (circle r) :position (0 0) :velocity (0 0))
                                (rope string :length (sqrt (- (+ (expt (+ r (/ top 2)) 2) (expt top 2)) (expt r 2)))
                                      :through ((ceiling ((+ r (/ top 2)) top)) (yoyo (r 0) :wound)))
                                (simulate :states 1))")))
           (condition (handler-case (progn (simulate-stopping-when-ambiguous scenario bridge) nil)
                        (ames-error (c) c))))
      (is (typep condition 'ames.kb:unmodelled-situation) "~A" condition))))
