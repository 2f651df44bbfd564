;;;; t/rolling-events.lisp -- events that end rolling (issue 23): a rolling disc that starts to
;;;; slip where static friction reaches mu_s N, and a disc that rolls over a corner and
;;;; leaves it.
;;;;
;;;; Every expected result is the textbook's (each scenario's header), over the scenario's
;;;; own parameters, compared by Maxima-checked equivalence under its assumptions; then
;;;; with the (:value N) defaults, where the numbers printed must be the formulas' values.
;;;; The helpers are those of t/simulator-scenarios.lisp, t/friction.lisp and
;;;; t/rotation-rolling.lisp.

(in-package #:ames.tests)

(def-suite rolling-events :in all-tests
  :description "Events of rolling discs: a disc rolling on a spring starts to slip
(src/algebra/trig-roots.lisp: the root of A + C sin x as an asin); a disc rolling over a
corner leaves it (src/simulator/rolling-path.lisp).")

(in-suite rolling-events)

(defun with-simulate-states (scenario states)
  "SCENARIO (an object) with (simulate :states STATES :branch nil)."
  (ames:parse-scenario
   (mapcar (lambda (clause)
             (if (and (consp clause) (same-name-p* (first clause) "SIMULATE"))
                 (list (first clause) :states states :branch nil)
                 clause))
           (ames:scenario-form scenario))))

(defun parameter-number (values name)
  "The value of the parameter named NAME in the parameter VALUES, a double."
  (float (cdr (find name values :key (lambda (e) (symbol-name (car e))) :test #'string-equal)) 1d0))

(test disc-on-a-spring-starts-to-slip
  "A disc rolling on a spring, launched from the rest length at v0: x = l + (v0/w) sin(w
t), w = sqrt(2 k / (3 m)); static friction -k (x - l) / 3; it starts to slip
((:starts-sliding disc floor)) at t = asin(3 mu m g w / (k v0)) / w, the stretch 3 mu m g
/ k, moving at sqrt(v0^2 - 6 mu^2 m g^2 / k) and still rolling (omega r = -v); energy
with (1/2) I omega^2 conserved; then it slides: kinetic friction mu m g backwards, the
spin slowing at alpha = 2 mu g / r."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "disc-rolling-on-a-spring")))
      (multiple-value-bind (history states) (run-of (with-simulate-states scenario 2) bridge)
        (declare (ignore history))
        (is (<= 2 (length states)))
        (destructuring-bind (&optional rolling sliding &rest more) states
          (declare (ignore more))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (let ((w (x '(sqrt (/ (* 2 k) (* 3 m)))))
                     (speed (x '(sqrt (- (expt v0 2) (/ (* 6 (expt mu 2) m (expt g 2)) k))))))
                 (is-same bridge "x" (first (per-body (ames::state-positions rolling) "DISC"))
                          (x `(+ l (* (/ v0 ,w) (sin (* ,w tau))))))
                 (check-friction bridge rolling "DISC" "FLOOR" :static
                                 (x `(- (* (/ k 3) (/ v0 ,w) (sin (* ,w tau))))))
                 (is (same-name-p* (first (ames::state-end-event rolling)) "STARTS-SLIDING")
                     "end: ~S" (ames::state-end-event rolling))
                 (is-same bridge "slips at" (ames::state-duration rolling)
                          (x `(/ (asin (/ (* 3 mu m g ,w) (* k v0))) ,w)))
                 (is-same bridge "stretch then" (first (per-body (ames::state-final-positions rolling) "DISC"))
                          (x '(+ l (/ (* 3 mu m g) k))))
                 (is-same-vector bridge "velocity then" (per-body (ames::state-final-velocities rolling) "DISC")
                                 (list speed 0))
                 (is-same bridge "omega r = -v then"
                          (x `(* r ,(rotation-entry (ames.simulator:state-final-angular-velocities rolling) "DISC")))
                          `(- ,speed))
                 (let ((energy (ames.simulator::state-total-energy rolling)))
                   (is-same bridge "energy conserved" energy (subst 0 'tau energy)))
                 (when sliding
                   (check-friction bridge sliding "DISC" "FLOOR" :sliding (x '(- (* mu m g))))
                   (is-same bridge "alpha sliding"
                            (rotation-entry (ames.simulator:state-angular-accelerations sliding) "DISC")
                            (x '(/ (* 2 mu g) r)))))))))))))

(test disc-on-a-spring-slips-with-values
  "With the scenario's values the printed numbers are the formulas': the time of the slip
asin(3 mu m g w / (k v0)) / w and the speed then; the self-check passes (an atan of a
half-angle root lost its digits there and the next state's closed form was wrong)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "disc-rolling-on-a-spring"))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (declare (ignore history))
        (flet ((p (name) (parameter-number values name)))
          (let* ((w (sqrt (/ (* 2 (p "K")) (* 3 (p "M")))))
                 (expected (/ (asin (/ (* 3 (p "MU") (p "M") (p "G") w) (* (p "K") (p "V0")))) w))
                 (numbers (ames.simulator:state-numbers (first states))))
            (is (< (abs (- (getf numbers :duration) expected)) 1d-9)
                "duration ~A, expected ~A" (getf numbers :duration) expected)
            (is (< (abs (- (first (per-body (getf numbers :final-velocities) "DISC"))
                           (sqrt (- (expt (p "V0") 2)
                                    (/ (* 6 (expt (p "MU") 2) (p "M") (expt (p "G") 2)) (p "K"))))))
                   1d-9))))))))

(test spring-slip-self-check
  "The run under values, through the sliding state that follows the slip, passes its
self-check (numeric integration of the model from each state's start): both states
checked, no failure."
  (with-fixture simulator-bridge ()
    (let* ((scenario (with-simulate-states (scenario-named "disc-rolling-on-a-spring") 2))
           (history (ames:run-scenario scenario :numeric t :bridge bridge))
           (check (self-check-of history)))
      (is (equal '(0 1) (getf check :checked)) "~S" check)
      (is (null (getf check :failures)) "~S" (getf check :failures)))))

;;; A disc over a corner

(test disc-leaves-a-smooth-table-edge
  "A disc released at rest at th0 from the top of a smooth edge: nothing turns it (omega =
0 along the whole arc), N = m g (3 cos theta - 2 cos th0), it leaves the edge
((:lift-off disc table)) at cos theta = (2/3) cos th0 (its centre at 2 r cos(th0) / 3 above
the edge) at the speed sqrt(2 g r cos(th0) / 3); the energy m g r cos th0 is conserved.
(The arc length s is measured from the horizontal: cos theta = sin(s/r).)"
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "disc-over-a-table-edge")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (let ((state (first states))
              (s ames.simulator::+arc-length+))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is (same-name-p* (first (ames::state-end-event state)) "LIFT-OFF")
                   "end: ~S" (ames::state-end-event state))
               ;; the expected N written over TAU, then TAU read as the arc length
               (is-same bridge "N" (normal-force-between state "DISC" "TABLE")
                        (subst s 'tau (x '(* m g (- (* 3 (sin (/ tau r))) (* 2 (cos th0)))))))
               (is-same bridge "omega along the arc"
                        (rotation-entry (ames.simulator:state-angular-velocities state) "DISC") 0)
               (is-same bridge "centre height at lift-off"
                        (second (per-body (ames::state-final-positions state) "DISC"))
                        (x '(* 2/3 r (cos th0))))
               (is-same bridge "omega at lift-off"
                        (rotation-entry (ames.simulator:state-final-angular-velocities state) "DISC") 0)
               (is-same bridge "energy" (ames.simulator::state-total-energy state)
                        (x '(* m g r (cos th0))))
               (is-same bridge "speed at lift-off"
                        (second (assoc "SPEED-AT-LIFT-OFF" (ames::history-answers history)
                                       :test #'same-name-p*))
                        (x '(sqrt (* 2/3 g r (cos th0))))))))
          (is (eq :forever (ames::state-duration (second states)))))))))

(test disc-leaves-a-smooth-table-edge-with-values
  "Under the scenario's values the run passes its self-check, both states checked."
  (with-fixture simulator-bridge ()
    (let* ((history (ames:run-scenario (scenario-named "disc-over-a-table-edge") :numeric t :bridge bridge))
           (check (self-check-of history)))
      (is (equal '(0 1) (getf check :checked)) "~S" check)
      (is (null (getf check :failures)) "~S" (getf check :failures)))))

(test disc-rolls-over-a-rough-table-edge-until-it-slips
  "A disc released at rest at cos th0 = 4/5 on a rough edge (mu = 1) rolls about it: omega =
-v / r, v^2 = (4/3) g r (cos th0 - cos theta), N = m g (7 cos theta - 4 cos th0) / 3 (zero at
the textbook's cos theta = (4/7) cos th0 = 16/35), static friction m g sin(theta) / 3; it
starts to slip first, where sin theta = mu (7 cos theta - 4 cos th0), with cos theta >
16/35. (cos theta = sin(s/r), sin theta = cos(s/r) over the arc length s.)"
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "disc-over-a-rough-table-edge")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (let ((state (first states))
              (s ames.simulator::+arc-length+))
          (flet ((x (form) (subst s 'tau (in-scenario-terms scenario form))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               ;; cos theta = sin(tau/r), sin theta = cos(tau/r), tau read as the arc length
               (is-same bridge "N" (normal-force-between state "DISC" "TABLE")
                        (x '(/ (* m g (- (* 7 (sin (/ tau r))) (* 4 4/5))) 3)))
               (is-same bridge "N's root: cos theta = (4/7) cos th0"
                        (subst '(asin 16/35) (x '(/ tau r)) (normal-force-between state "DISC" "TABLE")
                               :test #'equal)
                        0)
               (check-friction bridge state "DISC" "TABLE" :static (x '(/ (* m g (cos (/ tau r))) 3)))
               (let ((omega (rotation-entry (ames.simulator:state-angular-velocities state) "DISC")))
                 ;; rolling clockwise over the edge: omega r = -v
                 (is-same bridge "omega r = -v, v^2 = (4/3) g r (cos th0 - cos theta)"
                          `(* ,omega ,(x 'r))
                          (x '(- (sqrt (* 4/3 g r (- 4/5 (sin (/ tau r)))))))))
               (is (same-name-p* (first (ames::state-end-event state)) "STARTS-SLIDING")
                   "end: ~S" (ames::state-end-event state))
               (let ((cos-theta (ames.maxima:simplify
                                 bridge `(/ ,(second (per-body (ames::state-final-positions state) "DISC"))
                                            ,(x 'r)))))
                 (is (eq :true (ames.algebra:decide
                                bridge `(= (+ (expt ,cos-theta 2) (expt (- (* 7 ,cos-theta) 16/5) 2)) 1)))
                     "sin theta = 7 cos theta - 16/5 at the slip: cos theta = ~S" cos-theta)
                 (is (eq :true (ames.algebra:decide bridge `(> (- (* 7 ,cos-theta) 16/5) 0))))
                 (is (eq :true (ames.algebra:decide bridge `(> ,cos-theta 16/35)))
                     "it slips before the rolling lift-off"))))))))))

(test disc-over-a-rough-table-edge-with-values
  "Under the scenario's values the rolling state passes its self-check."
  (with-fixture simulator-bridge ()
    (let* ((history (ames:run-scenario (scenario-named "disc-over-a-rough-table-edge") :numeric t
                                                                                       :bridge bridge))
           (check (self-check-of history)))
      (is (equal '(0) (getf check :checked)) "~S" check)
      (is (null (getf check :failures)) "~S" (getf check :failures)))))
