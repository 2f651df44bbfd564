;;;; t/textbook-rotation.lisp -- issue 23 on textbook rotation problems restated fresh in
;;;; AMES's language (scenarios/rolling-a-distance-down-an-incline.lisp,
;;;; sphere-rolls-or-slips-on-an-incline.lisp, balls-launched-with-spin.lisp,
;;;; rod-and-disc-pendulums.lisp, ladder-from-45-degrees.lisp): each textbook result (the
;;;; file headers) checked by Maxima equivalence over the scenario's own parameters, and its
;;;; printed number against the formula's value or an independent quadrature. Also the
;;;; defects these problems found: a value at the instant the run stops, a value at the start
;;;; of a state along a rotating body's angle, (angular-momentum B), atan(tan x) = x.
;;;; Helpers: t/simulator-scenarios.lisp, t/friction.lisp, t/rotation-rolling.lisp,
;;;; t/hinged-swing.lisp.

(in-package #:ames.tests)

(def-suite textbook-rotation :in all-tests
  :description "Fresh textbook rotation problems (issue 23): rolling a distance, rolling or
slipping, balls launched with spin, physical pendulums, a ladder from 45 degrees.")

(in-suite textbook-rotation)

(defun textbook-answer-entry (history name)
  "HISTORY's answer entry (NAME VALUE [:numeric N] ...) to the query NAME."
  (assoc name (ames::history-answers history) :test #'same-name-p*))

(defun answer-expression (history name)
  "HISTORY's closed-form answer to the query NAME (or :UNANSWERED)."
  (second (textbook-answer-entry history name)))

(defun answer-number (history name)
  "The number printed beside HISTORY's answer to the query NAME, or NIL."
  (getf (cddr (textbook-answer-entry history name)) :numeric))

(defun scenario-values (scenario)
  "SCENARIO's (:value N) defaults, as an alist for the numeric helpers."
  (ames.scenario:run-parameter-values scenario :numeric t))

(defun check-answers (bridge scenario history expected)
  "Check each (NAME FORM) of EXPECTED: HISTORY's answer NAME is FORM (over SCENARIO's
parameters, Maxima-checked under its assumptions); a vector FORM is a list of two
expressions, the first no operator."
  (call-with-scenario-facts
   bridge scenario
   (lambda ()
     (loop for (name form) in expected
           for actual = (answer-expression history name)
           for wanted = (in-scenario-terms scenario form)
           do (if (and (consp form) (not (symbolp (first form))) (= 2 (length form)))
                  (is-same-vector bridge name actual wanted)
                  (is-same bridge name actual wanted))))))

(defun check-numbers (bridge scenario history expected)
  "Check that the number printed beside each answer NAME of EXPECTED ((NAME FORM) ...) is
FORM's value under SCENARIO's defaults."
  (let ((values (scenario-values scenario)))
    (loop for (name form) in expected
          for printed = (answer-number history name)
          for wanted = (numeric-under bridge (in-scenario-terms scenario form) values)
          do (is (near-p printed wanted 1d-6) "~A: printed ~A, the formula gives ~A" name printed wanted))))

;;; Rolling a distance d down an incline: disc, hoop, sphere

(defparameter *rolling-results*
  '(("DISC-ROLLS-A-DISTANCE" "DISC" 1/2
     (("TIME-DOWN-D" (sqrt (/ (* 3 d) (* g (sin a)))))
      ("SPEED-DOWN-D" (sqrt (/ (* 4 g d (sin a)) 3)))
      ("KINETIC-DOWN-D" (* m g d (sin a)))))
    ("HOOP-ROLLS-A-DISTANCE" "HOOP" 1
     (("TIME-DOWN-D" (* 2 (sqrt (/ d (* g (sin a))))))
      ("SPIN-DOWN-D" (- (/ (sqrt (* g d (sin a))) r)))))
    ("SPHERE-ROLLS-A-DISTANCE" "BALL" 2/5
     (("SPEED-DOWN-D" (sqrt (/ (* 10 g d (sin a)) 7)))
      ("KINETIC-AT-1" (* 7/10 m (expt (* 5/7 g (sin a)) 2)))
      ("ANGULAR-MOMENTUM-AT-1" (- (* m g r (sin a)))))))
  "Each scenario of rolling-a-distance-down-an-incline, its body, k = I/(m r^2) and the
textbook answers to its queries.")

(test bodies-roll-a-distance-down-an-incline
  "A disc, a hoop and a sphere (I = k m r^2) rolling from rest: a = g sin a/(1 + k), static
friction k m g sin a/(1 + k), N = m g cos a, alpha = -g sin a/((1 + k) r); after a drop
h = d sin a: t = sqrt(2 d (1 + k)/(g sin a)), v = sqrt(2 g h/(1 + k)), K = m g h; the
sphere's angular momentum about a point of the slope -m g r t sin a; the numbers printed
are the formulas' values."
  (with-fixture simulator-bridge ()
    (loop for (name body k expected) in *rolling-results*
          for scenario = (named-scenario "rolling-a-distance-down-an-incline" name)
          do (let ((state (first (nth-value 1 (run-of scenario bridge)))))
               (flet ((x (form) (in-scenario-terms scenario form)))
                 (call-with-scenario-facts
                  bridge scenario
                  (lambda ()
                    (let ((a `(/ (* g (sin a)) ,(+ 1 k))))
                      (is-same-vector bridge name (per-body (ames::state-accelerations state) body)
                                      (list (x `(* ,a (cos a))) (x `(- (* ,a (sin a))))))
                      (check-friction bridge state body "SLOPE" :static (x `(* ,k m ,a)))
                      (is-same bridge "N" (normal-force-between state body "SLOPE") (x '(* m g (cos a))))
                      (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) body)
                               (x `(- (/ ,a r))))))))
               (let ((history (run-of scenario bridge)))
                 (check-answers bridge scenario history expected))
               (let ((history (run-of scenario bridge :parameter-values (scenario-values scenario))))
                 (check-numbers bridge scenario history expected))))))

;;; Rolling or slipping: the sphere's threshold mu = (2/7) tan a

(test sphere-rolls-or-slips-at-two-sevenths-of-tan-a
  "A solid sphere on a rough incline: with mu < tan(a)/(1 + m r^2/I) = (2/7) tan a it
slips (kinetic friction mu m g cos a, a = g (sin a - mu cos a), alpha = -(5/2) mu g cos a /
r); above it rolls (a = (5/7) g sin a, friction (2/7) m g sin a). Either way its angular
momentum about a point of the slope is -m g r t sin a. With mu open the run branches on
that very threshold."
  (with-fixture simulator-bridge ()
    (let ((open (named-scenario "sphere-rolls-or-slips-on-an-incline" "sphere-rolls-or-slips-on-an-incline")))
      (let ((fork (first (ames::history-states (ames:simulate open :bridge bridge)))))
        (is (ames::state-branches fork))
        (call-with-scenario-facts
         bridge open
         (lambda ()
           (is (some (lambda (branch)
                       (let ((fact (getf branch :assume)))
                         (and (consp fact) (member (first fact) '(< >))
                              (ames.maxima:with-assumptions (bridge (list fact))
                                (eq :true (ames.algebra:decide
                                           bridge (in-scenario-terms open '(< mu (* 2/7 (tan a))))))))))
                     (ames::state-branches fork))
               "no branch on mu < (2/7) tan a: ~S"
               (mapcar (lambda (b) (getf b :assume)) (ames::state-branches fork))))))
      (loop for (relation mode) in '(((< mu (* 2/7 (tan a))) :sliding) ((> mu (* 2/7 (tan a))) :static))
            for scenario = (with-mu-assumption open relation)
            do (let ((state (first (nth-value 1 (run-of scenario bridge)))))
                 (flet ((x (form) (in-scenario-terms scenario form)))
                   (call-with-scenario-facts
                    bridge scenario
                    (lambda ()
                      (let ((acceleration (if (eq mode :sliding)
                                              '(* g (- (sin a) (* mu (cos a))))
                                              '(* 5/7 g (sin a)))))
                        (is-same-vector bridge "acceleration" (per-body (ames::state-accelerations state) "BALL")
                                        (list (x `(* ,acceleration (cos a))) (x `(- (* ,acceleration (sin a)))))))
                      (check-friction bridge state "BALL" "SLOPE" mode
                                      (x (if (eq mode :sliding) '(* mu m g (cos a)) '(* 2/7 m g (sin a)))))
                      (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) "BALL")
                               (x (if (eq mode :sliding) '(- (/ (* 5/2 mu g (cos a)) r)) '(- (/ (* 5/7 g (sin a)) r)))))
                      (is-same bridge "angular momentum"
                               (third (find :angular-momentum (getf (ames::state-reported-sections state) :momentum)
                                             :key #'first))
                               (x '(- (* m g r (sin a) tau))))))))))))

;;; Balls launched with spin: the angular momentum about the contact point is kept

(defparameter *spin-results*
  '(("SPHERE-LAUNCHED-WITH-BACKSPIN" "BALL" (* 2/5 m r r) v0 w0 -1
     (("ROLLS-AT" (/ (* 2 (+ v0 (* r w0))) (* 7 mu g)))
      ("ROLLING-SPEED" (/ (- (* 5 v0) (* 2 r w0)) 7))
      ("SPIN-THEN" (- (/ (- (* 5 v0) (* 2 r w0)) (* 7 r))))
      ("ANGULAR-MOMENTUM-THEN" (- (* m r (- v0 (* 2/5 r w0)))))))
    ("DISC-LAUNCHED-WITH-TOPSPIN" "DISC" (* 1/2 m r r) v0 (- w0) 1
     (("ROLLS-AT" (/ (- (* r w0) v0) (* 3 mu g)))
      ("ROLLING-SPEED" (/ (+ (* 2 v0) (* r w0)) 3))))
    ("DISC-SPUN-IN-PLACE" "DISC" (* 1/2 m r r) 0 w0 -1
     (("ROLLS-AT" (/ (* r w0) (* 3 mu g)))
      ("ROLLING-SPEED" (/ (* r w0) 3))
      ("KINETIC-ENERGY-LOST" (* 1/6 m r r w0 w0)))))
  "Each scenario of balls-launched-with-spin: its body, inertia, launch speed and angular
velocity (counter-clockwise), the sign of the speed's change, and the textbook answers to its queries.")

(test balls-launched-with-spin-roll-at-the-kept-angular-momentum
  "A body of inertia I launched at v0 with angular velocity w on a rough floor slides
(kinetic friction mu m g) until it rolls at v = (m r^2 v0 - I r w)/(m r^2 + I), after
|v - v0|/(mu g): the sphere with backspin (5 v0 - 2 r w0)/7, the disc with topspin
(2 v0 + r w0)/3, the disc spun in place r w0/3 (backwards), two thirds of its energy lost.
Its angular momentum about the origin (a point of the floor) keeps its initial value
through both states; the numbers printed are the formulas' values."
  (with-fixture simulator-bridge ()
    (loop for (name body inertia v0 w change expected) in *spin-results*
          for scenario = (named-scenario "balls-launched-with-spin" name)
          do (multiple-value-bind (history states) (run-of scenario bridge)
               (is (= 2 (length states)) "~A: ~D states" name (length states))
               (is (equal (list :stops-sliding body "FLOOR") (event-names (ames::state-end-event (first states)))))
               (flet ((x (form) (in-scenario-terms scenario form)))
                 (call-with-scenario-facts
                  bridge scenario
                  (lambda ()
                    (let ((rolling (x `(/ (- (* m r r ,v0) (* ,inertia r ,w)) (+ (* m r r) ,inertia)))))
                      (is-same bridge "duration" (ames::state-duration (first states))
                               (x `(/ (* ,change (- ,rolling ,v0)) (* mu g))))
                      (is-same-vector bridge "rolling velocity" (per-body (ames::state-final-velocities (first states)) body)
                                      (list rolling 0)))
                    (dolist (state states)
                      (is-same bridge "angular momentum kept"
                               (third (find :angular-momentum (getf (ames::state-reported-sections state) :momentum)
                                             :key #'first))
                               (x `(+ (* ,inertia ,w) (- (* m r ,v0)))))))))
               (check-answers bridge scenario history expected)
               (check-numbers bridge scenario (run-of scenario bridge :parameter-values (scenario-values scenario))
                              expected)))))

;;; Physical pendulums: a rod from an angle, a disc hinged at its rim

(test rod-hinged-from-an-angle-and-disc-hinged-at-its-rim
  "The rod released b below the horizontal: omega = -sqrt(3 g (1 - sin b)/l) at the
bottom, the hinge m g (5 - 3 sin b)/2 there; at release alpha = -3 g cos b/(2 l), the
hinge (-3 m g sin b cos b/4, m g (1 + 3 sin^2 b)/4) (the start of a state along the angle);
period 4 sqrt(2 l/(3 g)) K((1 - sin b)/2), also twice the quadrature. The disc hinged at
its rim: period 4 sqrt(3 r/(2 g)) K(sin^2(b/2)) (2 pi sqrt(3 r/(2 g)) for small b), at the
bottom omega = -2 sqrt(g (1 - cos b)/(3 r)) (its far turning point comes as
-2 atan(tan b), decided past -b). The rod nudged at w0 from upright turns over and over:
omega^2 = w0^2 + 3 g/l horizontal, w0^2 + 6 g/l at the bottom, the hinge 4 m g + m l w0^2/2
there (reaches along an angle that never turns back, refused before)."
  (with-fixture simulator-bridge ()
    (let* ((rod (named-scenario "rod-and-disc-pendulums" "rod-hinged-released-at-an-angle"))
           (disc (named-scenario "rod-and-disc-pendulums" "disc-hinged-at-its-rim"))
           (rod-history (run-of rod bridge))
           (disc-history (run-of disc bridge)))
      (check-answers bridge rod rod-history
                     '(("OMEGA-AT-BOTTOM" (- (sqrt (/ (* 3 g (- 1 (sin b))) l))))
                       ("HINGE-AT-BOTTOM" (* m g (- 5 (* 3 (sin b))) 1/2))
                       ("ALPHA-AT-RELEASE" (- (/ (* 3 g (cos b)) (* 2 l))))
                       ("HINGE-AT-RELEASE" ((- (* 3/4 m g (sin b) (cos b))) (* 1/4 m g (+ 1 (* 3 (expt (sin b) 2))))))))
      (check-answers bridge disc disc-history
                     '(("OMEGA-AT-BOTTOM" (- (* 2 (sqrt (/ (* g (- 1 (cos b))) (* 3 r))))))))
      (let ((upright (named-scenario "rod-and-disc-pendulums" "rod-nudged-from-upright")))
        (check-answers bridge upright (run-of upright bridge)
                       '(("OMEGA-HORIZONTAL" (sqrt (+ (* w0 w0) (/ (* 3 g) l))))
                         ("OMEGA-BOTTOM" (sqrt (+ (* w0 w0) (/ (* 6 g) l))))
                         ("HINGE-BOTTOM" (+ (* 4 m g) (* 1/2 m l w0 w0))))))
      (flet ((period-of (history) (getf (ames::state-periodic (first (ames::history-states history))) :period)))
        (let* ((values (scenario-values rod))
               (period (numeric-under bridge (period-of rod-history) values))
               (textbook (numeric-under bridge (in-scenario-terms rod '(* 4 (sqrt (/ (* 2 l) (* 3 g)))
                                                                       (elliptic-k (/ (- 1 (sin b)) 2))))
                                        values))
               (quadrature (* 2 (ames.algebra:numeric-travel-time
                                 bridge (in-scenario-terms rod '(- (/ (* 3 g (+ (sin b) (sin tau))) l)))
                                 'tau (in-scenario-terms rod '(- b)) (in-scenario-terms rod '(- b pi)) values))))
          (is (near-p period textbook) "rod period ~A, textbook ~A" period textbook)
          (is (near-p period quadrature 1d-6) "rod period ~A, quadrature ~A" period quadrature))
        (let* ((values (scenario-values disc))
               (period (numeric-under bridge (period-of disc-history) values))
               (textbook (numeric-under bridge (in-scenario-terms disc '(* 4 (sqrt (/ (* 3 r) (* 2 g)))
                                                                         (elliptic-k (expt (sin (/ b 2)) 2))))
                                        values))
               (small (numeric-under bridge (in-scenario-terms disc '(* 2 pi (sqrt (/ (* 3 r) (* 2 g))))) values)))
          (is (near-p period textbook) "disc period ~A, textbook ~A" period textbook)
          (is (near-p period small 1d-3) "disc period ~A, small-angle ~A" period small))))))

;;; The ladder from 45 degrees

(test ladder-from-45-degrees-leaves-the-wall-at-two-thirds
  "The ladder released at a leaves the wall when its centre is at (1/3) l sin a (its top
at 2/3 of its height), turning at sqrt(g sin a/l), the floor pushing m g/4; with l = 4,
a = 45 degrees the time is the quadrature of ds/sqrt(3 g (sin a - sin s)/l)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (named-scenario "ladder-from-45-degrees" "ladder-from-45-degrees"))
           (values (scenario-values scenario))
           (expected '(("LEAVES-WALL-AT" (* 1/3 l (sin a)))
                       ("OMEGA-THEN" (sqrt (/ (* g (sin a)) l)))
                       ("FLOOR-PUSH-THEN" (* 1/4 m g)))))
      (check-answers bridge scenario (run-of scenario bridge) expected)
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (check-numbers bridge scenario history expected)
        (let ((printed (getf (ames.simulator:state-numbers (first states)) :duration))
              (quadrature (ames.algebra:numeric-travel-time
                           bridge (in-scenario-terms scenario '(/ (* 3 g (- (sin a) (sin tau))) l))
                           'tau (in-scenario-terms scenario '(- pi a))
                           (in-scenario-terms scenario '(- pi (asin (* 2/3 (sin a))))) values)))
          (is (near-p printed quadrature 1d-6) "duration ~A, quadrature ~A" printed quadrature))))))

;;; The defects these problems found

(defparameter *disc-until*
  "(scenario disc-rolls-until
     \"A disc rolling from rest down a long incline, the run stopped at time tf.\"
     (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
                 (tf :positive (:value 3/2)) (a (> a 0) (< a (/ pi 2)) (:value (deg 25)))
                 (mu :positive (> mu (/ (tan a) 3)) (:value 1/2)))
     (gravity g)
     (body slope :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
     (body disc :mass m :inertia :uniform :shape (circle r)
           :position ((* r (sin a)) (* r (cos a))) :velocity (0 0))
     (friction disc slope :static mu)
     (query spin-at-stop (value (angular-velocity disc) :at tf))
     (query momentum-at-stop (value (angular-momentum disc) :at tf))
     (query past-stop (value (angular-velocity disc) :at (* 2 tf)))
     (simulate :states 1 :until tf))"
  "A rolling disc whose run stops at its time limit tf, asked about tf and after it.")

(test values-at-the-instant-the-run-stops
  "A value asked at the time limit itself is the last state's at its end (it was refused
as 'the run does not reach t = tf'): omega = -(2/3) g tf sin a / r, the angular momentum
about a point of the slope -m g r tf sin a; a time past the limit is still refused."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *disc-until*)))
           (history (run-of scenario bridge)))
      (check-answers bridge scenario history
                     '(("SPIN-AT-STOP" (- (/ (* 2 g tf (sin a)) (* 3 r))))
                       ("MOMENTUM-AT-STOP" (- (* m g r tf (sin a))))))
      (is (eq :unanswered (answer-expression history "PAST-STOP"))))))

(test angular-momentum-is-asked-of-a-rotating-body-only
  "(angular-momentum B) names a rotating body; of a translating one (whose angular momentum
no component reports) the scenario is refused, naming the query."
  (signals ames:scenario-error
    (ames:read-scenarios-from-string
     "(scenario block-spin
        \"A block that does not rotate.\"
        (parameters (m :positive))
        (body block :mass m :shape point :position (0 0) :velocity (1 0))
        (query l (value (angular-momentum block) :at (start 0)))
        (simulate :states 1))")))

(test atan-of-a-tangent-is-its-angle-on-the-principal-branch
  "-2 atan(sin b/cos b) <= -b holds for 0 < b < pi/2 (atan(tan b) = b there); for
0 < b < pi it is not decided (atan(tan b) = b - pi past pi/2)."
  (with-fixture simulator-bridge ()
    (let ((relation '(<= (- (* 2 (atan (/ (sin b) (cos b))))) (- b))))
      (ames.maxima:with-assumptions (bridge '((> b 0) (< b (/ pi 2))))
        (is (eq :true (ames.algebra:decide bridge relation))))
      (ames.maxima:with-assumptions (bridge '((> b 0) (< b pi)))
        (is (not (eq :true (ames.algebra:decide bridge relation))))))))

;;; The spool pulled by a hanging weight (a rope wound on its axle)

(defun rolling-path-states (history)
  "The states of the path of HISTORY's tree whose last state has static friction (the
spool rolling), or NIL."
  (loop for (nil nil . states) in (ames.simulator::history-paths history)
        for last = (car (last states))
        when (and last (some (lambda (force) (and (eq (first force) :friction)
                                                  (eq :static (getf (cddddr force) :mode))))
                             (ames::state-forces-of last)))
          return states))

(test spool-rolls-pulled-by-a-hanging-weight
  "The spool rolling (the branch the values select), its string leaving the top (r) or the
bottom (-r) of its axle: a = M g R (R + r)/(I + m R^2 + M (R + r)^2), the weight falling at
a (1 + r/R), alpha = -a/R, T = M g (I + m R^2)/(I + m R^2 + M (R + r)^2), at the table's
edge after sqrt(2 l/a); the printed tension is its value. The boundary branches, whose
facts no parameter is solved for from, say so in their answers (they used to say the
values ruled them out, in a run without values too)."
  (with-fixture simulator-bridge ()
    (loop for (name side) in '(("SPOOL-PULLED-BY-A-HANGING-WEIGHT" 1) ("SPOOL-PULLED-FROM-UNDER-ITS-AXLE" -1))
          for scenario = (named-scenario "spool-pulled-by-a-hanging-weight" name)
          for values = (scenario-values scenario)
          for history = (ames:simulate scenario :bridge bridge :parameter-values values)
          for state = (car (last (rolling-path-states history)))
          do (is (not (null state)) "~A: no rolling branch" name)
             (when state
               (flet ((x (form) (in-scenario-terms scenario form)))
                 (let* ((arm `(+ big-r (* ,side r)))
                        (d `(+ i (* m big-r big-r) (* big-m (expt ,arm 2))))
                        (a `(/ (* big-m g big-r ,arm) ,d))
                        (tension `(/ (* big-m g (+ i (* m big-r big-r))) ,d)))
                   (call-with-scenario-facts
                    bridge scenario
                    (lambda ()
                      (is-same-vector bridge "spool" (per-body (ames::state-accelerations state) "SPOOL") (list (x a) 0))
                      (is-same-vector bridge "weight" (per-body (ames::state-accelerations state) "WEIGHT")
                                      (list 0 (x `(- (* ,a (/ ,arm big-r))))))
                      (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) "SPOOL")
                               (x `(- (/ ,a big-r))))
                      (is-same bridge "tension" (third (find :tension (ames::state-forces-of state) :key #'first))
                               (x tension))
                      (is-same bridge "to the edge" (ames::state-duration state) (x `(sqrt (/ (* 2 l) ,a))))))
                   (let ((printed (find-if (lambda (entry) (getf (cddr entry) :numeric))
                                           (remove "TENSION" (ames::history-answers history)
                                                   :key #'first :test-not #'same-name-p*))))
                     (is (near-p (getf (cddr printed) :numeric) (numeric-under bridge (x tension) values) 1d-6)))))))
    (let ((history (ames:simulate (named-scenario "spool-pulled-by-a-hanging-weight" "spool-pulled-by-a-hanging-weight")
                                  :bridge bridge)))
      (dolist (entry (ames::history-answers history))
        (when (eq :unanswered (second entry))
          (is (not (search "values" (getf (cddr entry) :reason))) "~S" entry))))))

;;; The instant of release where the motion has no closed form

(test rods-answered-at-the-instant-of-release
  "A rod released tilted b on a smooth floor: at release N = m g/(1 + 3 sin^2 b), alpha =
-6 g sin b/(l (1 + 3 sin^2 b)), the centre's acceleration -3 g sin^2 b/(1 + 3 sin^2 b),
though its motion has no closed form (these were refused); with values it lands flat at
sqrt(3 g l cos b/4). A free rod pushed at its end by f: alpha = 6 f/(m l), a = f/m at the
start; with values, at its end omega^2 = 12 f sin(theta)/(m l) (the energy integral)."
  (with-fixture simulator-bridge ()
    (let ((rod (named-scenario "rods-set-moving-by-a-push-or-a-fall" "rod-released-tilted-on-a-smooth-floor"))
          (free (named-scenario "rods-set-moving-by-a-push-or-a-fall" "free-rod-pushed-at-one-end")))
      (check-answers bridge rod (ames:simulate rod :bridge bridge)
                     '(("FLOOR-PUSH-AT-RELEASE" (/ (* m g) (+ 1 (* 3 (expt (sin b) 2)))))
                       ("ALPHA-AT-RELEASE" (- (/ (* 6 g (sin b)) (* l (+ 1 (* 3 (expt (sin b) 2)))))))
                       ("FALL-AT-RELEASE" (- (/ (* 3 g (expt (sin b) 2)) (+ 1 (* 3 (expt (sin b) 2))))))))
      (check-answers bridge free (ames:simulate free :bridge bridge)
                     '(("ALPHA-AT-START" (/ (* 6 f) (* m l)))
                       ("ACCELERATION-AT-START" (0 (/ f m)))))
      (let* ((values (scenario-values rod))
             (state (first (ames::history-states (ames:simulate rod :bridge bridge :parameter-values values))))
             (vy (numeric-under bridge (second (per-body (ames::state-final-velocities state) "ROD")) values)))
        (is (near-p vy (- (numeric-under bridge (in-scenario-terms rod '(sqrt (* 3/4 g l (cos b)))) values)) 1d-6)
            "landing at ~A" vy))
      (let* ((values (scenario-values free))
             (state (first (ames::history-states (ames:simulate free :bridge bridge :parameter-values values))))
             (theta (numeric-under bridge (rotation-entry (ames.simulator::state-final-angles state) "ROD") values))
             (omega (numeric-under bridge (rotation-entry (ames.simulator:state-final-angular-velocities state) "ROD")
                                   values)))
        (is (near-p (* omega omega)
                    (* (sin theta) (numeric-under bridge (in-scenario-terms free '(/ (* 12 f) (* m l))) values))
                    1d-6)
            "omega ~A at theta ~A" omega theta)))))

;;; A disc rolled up an incline: extrema over a state that never ends

(test disc-rolled-up-an-incline-rises-three-quarters-v0-squared-over-g
  "The disc rolling at v0 up the incline: one state with friction m g sin a/3 down the
slope and alpha = (2/3) g sin a/r; it stops after 3 v0/(2 g sin a), its centre's greatest
height r cos a + 3 v0^2/(4 g) (a maximum over a state that never ends, refused before),
its least speed 0; its greatest speed is refused (it grows without bound); its angular
momentum about the origin is 0 when it stops."
  (with-fixture simulator-bridge ()
    (let* ((scenario (named-scenario "disc-rolled-up-an-incline" "disc-rolled-up-an-incline")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (= 1 (length states)))
        (let ((state (first states)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (check-friction bridge state "DISC" "SLOPE" :static (in-scenario-terms scenario '(- (* 1/3 m g (sin a)))))
             (is-same bridge "alpha" (rotation-entry (ames.simulator:state-angular-accelerations state) "DISC")
                      (in-scenario-terms scenario '(/ (* 2 g (sin a)) (* 3 r)))))))
        (check-answers bridge scenario history
                       '(("STOPS-AT" (/ (* 3 v0) (* 2 g (sin a))))
                         ("HIGHEST" (+ (* r (cos a)) (/ (* 3 v0 v0) (* 4 g))))
                         ("SLOWEST" 0)
                         ("ANGULAR-MOMENTUM-THEN" 0)))
        (is (eq :unanswered (answer-expression history "FASTEST")))))))

;;; Rolling into a wall

(test rolling-bodies-bounce-off-a-wall-and-roll-back
  "A disc and a solid ball rolling at v0 into a smooth wall (e = 1): the wall's impulse 2 m
v0 reverses the velocity and leaves the spin; they slide and roll back at -v0 (m r^2 -
I)/(m r^2 + I), -v0/3 after 2 v0/(3 mu g) and -(3/7) v0 after 4 v0/(7 mu g); the numbers
printed are the formulas' values."
  (with-fixture simulator-bridge ()
    (loop for (name k) in '(("ROLLING-DISC-BOUNCES-OFF-A-WALL" 1/2) ("ROLLING-BALL-BOUNCES-OFF-A-WALL" 2/5))
          for scenario = (named-scenario "rolling-bodies-bounce-off-a-wall" name)
          for expected = `(("ROLLS-BACK-AT" (- (* v0 ,(/ (- 1 k) (+ 1 k)))))
                           ("SLIDES-FOR" (/ (* ,(/ (* 2 k) (+ 1 k)) v0) (* mu g))))
          do (multiple-value-bind (history states) (run-of scenario bridge)
               (is (= 3 (length states)))
               (is (equal '(:collision) (list (first (ames::state-end-event (first states))))))
               (call-with-scenario-facts
                bridge scenario
                (lambda ()
                  (is-same bridge "impulse" (getf (cdddr (ames::state-end-event (first states))) :impulse)
                           (in-scenario-terms scenario '(* 2 m v0)))))
               (check-answers bridge scenario history expected)
               (check-numbers bridge scenario (run-of scenario bridge :parameter-values (scenario-values scenario))
                              expected)))))
