;;;; t/trust-fresh.lisp -- issue 20 on textbook problems written fresh for these tests (a
;;;; block dropped onto a vertical bumper; a particle dropped onto one; a sign with sin and cos
;;;; of 2 atan u; a rough incline whose declared bound on mu leaves nothing to fork on).
;;;;
;;;; Classes 3 (a bumper in the path), 7 (facts the declared bounds exclude) and 8 (a gap A
;;;; sin + B cos + C of gravity and a vertical bumper). Closed forms are checked by Maxima
;;;; equivalence (helpers in t/simulator-scenarios.lisp, t/self-check.lisp).

(in-package #:ames.tests)

(def-suite trust-fresh :in all-tests
  :description "Issue 20 on fresh textbook problems: vertical bumpers, inverse angles, declared bounds.")

(in-suite trust-fresh)

;;; Class 3 and 8: a block dropped onto a vertical bumper (gravity and the spring together)

(defparameter *block-onto-bumper*
  "(scenario block-onto-bumper
     \"A small block dropped from height h above a vertical bumper on a floor.\"
     (parameters (m :positive (:value 1/2)) (g :positive (:value 98/10)) (k :positive (:value 500))
                 (h :positive (:value 1)) (l0 :positive (:value 1/5)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body p :mass m :position (0 (+ l0 h)) :velocity (0 0)
           :shape (polygon (-1/10 0) (1/10 0) (1/10 1/5) (-1/10 1/5)))
     (spring s :from (floor (0 0)) :toward (0 1) :stiffness k :rest-length l0)
     (simulate :states 3))"
  "Serway's block dropped onto a spring, the spring a bumper standing on the floor.")

(test a-block-dropped-onto-a-vertical-bumper-bounces-back-up
  "The block meets the bumper after sqrt(2 h/g) at sqrt(2 g h); pressed, its height is
l0 - (m g/k)(1 - cos w tau) - sqrt(2 g h)/w sin w tau (w = sqrt(k/m)), the greatest
compression (m g + sqrt(m^2 g^2 + 2 k m g h))/k (k c^2/2 = m g (h + c)); it leaves when the
gap A sin + B cos + C returns to 0, after (pi + 2 atan(sqrt(m g/(2 k h)))) sqrt(m/k), at
sqrt(2 g h) upward, with no fork (the sign of that velocity is decided) and never reaching
the floor; then it rises and falls back for 2 sqrt(2 h/g)."
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *block-onto-bumper* bridge))
           (scenario (ames:history-scenario history))
           (states (ames:history-states history)))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (is (= 3 (length states)) "~D states" (length states))
        (is (notany #'ames::state-branches states) "a fork on a fact that always holds")
        (is (null (getf (self-check-of history) :failures)))
        (destructuring-bind (&optional fall pressed rise) states
          (when rise
            (is (equal '(:contact "P" "S") (event-names (ames::state-end-event fall))))
            (is (equal '(:leaves "P" "S") (event-names (ames::state-end-event pressed))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "fall" (ames::state-duration fall) (x '(sqrt (/ (* 2 h) g))))
               (is-same bridge "pressed" (ames::state-duration pressed)
                        (x '(* (+ pi (* 2 (atan (sqrt (/ (* m g) (* 2 k h)))))) (sqrt (/ m k)))))
               (let ((y (second (per-body (ames::state-positions pressed) "P")))
                     (w (x '(sqrt (/ k m)))))
                 (is-same bridge "height while pressed" y
                          (x `(- l0 (* (/ (* m g) k) (- 1 (cos (* ,w tau))))
                                 (* (/ (sqrt (* 2 g h)) ,w) (sin (* ,w tau))))))
                 ;; the lowest point: where the velocity vanishes, tan(w tau) = -sqrt(2 g h) k/(w m g)
                 (let ((lowest (x `(/ (- pi (atan (/ (* (sqrt (* 2 g h)) k) (* ,w m g)))) ,w))))
                   (is-same bridge "greatest compression" (x `(- l0 ,(at-variable y 'tau lowest)))
                            (x '(/ (+ (* m g) (sqrt (+ (* m m g g) (* 2 k m g h)))) k)))))
               (is-same-vector bridge "leaves upward" (per-body (ames:state-initial-velocities rise) "P")
                               (x '(0 (sqrt (* 2 g h)))))
               (is-same bridge "back to the bumper" (ames::state-duration rise)
                        (x '(* 2 (sqrt (/ (* 2 h) g)))))))))))))

(test a-point-dropped-onto-a-bumper-is-refused-not-passed-through
  "A particle (a point) dropped onto a vertical bumper's free end (a point too): the
model has no contact between two points, so the run is refused, naming the particle;
it used to fall through the bumper to the floor, exit 0."
  (with-fixture simulator-bridge ()
    (let ((scenario (first (ames:read-scenarios-from-string
                            "(scenario point-onto-bumper
                               \"A particle dropped onto a vertical bumper.\"
                               (parameters (m :positive) (g :positive) (k :positive) (h :positive))
                               (gravity g)
                               (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                               (body p :mass m :position (0 (+ 1 h)) :velocity (0 0) :shape point)
                               (spring s :from (floor (0 0)) :toward (0 1) :stiffness k :rest-length 1)
                               (simulate :states 2))"))))
      (handler-case (progn (ames:simulate scenario :bridge bridge)
                           (fail "the run went on"))
        (ames::unsupported-situation (condition)
          (is (string-equal "P" (symbol-name (ames.base:ames-error-datum condition)))))))))

;;; Class 7 and 8: signs the algebra decides

(test sines-of-inverse-angles-are-decided-as-algebra
  "g sin(2 atan u) sqrt(m k) + k cos(2 atan u) sqrt(2 g h) with u = sqrt(m g/(2 k h)) is
(2 u g sqrt(m k) + k sqrt(2 g h) (1 - u^2))/(1 + u^2) = (m g sqrt(g/(2 h)) + k sqrt(2 g h))/(1 + u^2) > 0; cos(2 atan u) has
either sign; sin(asin c + acos c) = 1."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> m 0) (> g 0) (> k 0) (> h 0) (> c 0) (< c 1)))
      (let ((u '(sqrt (/ (* m g) (* 2 k h)))))
        (is (eq :true (ames.algebra:decide
                       bridge `(> (+ (* g (sin (* 2 (atan ,u))) (sqrt (* m k)))
                                     (* k (cos (* 2 (atan ,u))) (sqrt (* 2 g h))))
                                  0))))
        (is (eq :false (ames.algebra:decide
                        bridge `(< (+ (* g (sin (* 2 (atan ,u))) (sqrt (* m k)))
                                      (* k (cos (* 2 (atan ,u))) (sqrt (* 2 g h))))
                                   0))))
        (is (eq :unknown (ames.algebra:decide bridge `(> (cos (* 2 (atan ,u))) 0))))
        (is (eq :true (ames.algebra:decide bridge '(= (sin (+ (asin c) (acos c))) 1))))))))

(defun rough-incline-block (bound)
  "A particle released halfway up a rough incline (height h, angle a), friction mu with the
declared BOUND on mu (a relation form)."
  (first (ames:read-scenarios-from-string
          (format nil "(scenario rough-incline-particle
              \"A particle released on a rough incline.\"
              (parameters (m :positive) (g :positive) (h :positive)
                          (a (> a 0) (< a (/ pi 2))) (mu :positive ~S))
              (gravity g)
              (body incline :fixed t :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
              (body p :mass m :position ((/ h (* 2 (tan a))) (/ h 2)) :velocity (0 0) :shape point)
              (friction p incline :static mu)
              (simulate :states 1))" bound))))

(test declared-bounds-on-mu-leave-nothing-to-fork-on
  "Declared mu < tan a: no fork, the particle slides down the incline's half, h/(2 sin a),
at g (sin a - mu cos a), and reaches the foot after sqrt(h/(g sin a (sin a - mu cos a))).
Declared mu > tan a: no fork, it stays at rest forever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (rough-incline-block '(< mu (tan a))))
           (history (ames:simulate scenario :bridge bridge))
           (state (first (ames:history-states history))))
      (is (null (ames::state-branches state)) "forked under mu < tan a")
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (is-same bridge "time to the foot" (ames::state-duration state)
                  (in-scenario-terms scenario '(sqrt (/ h (* g (sin a) (- (sin a) (* mu (cos a))))))))
         (is-same bridge "speed squared at the foot"
                  (let ((v (per-body (ames::state-final-velocities state) "P")))
                    `(+ (expt ,(first v) 2) (expt ,(second v) 2)))
                  (in-scenario-terms scenario '(/ (* g h (- (sin a) (* mu (cos a)))) (sin a)))))))
    (let* ((scenario (rough-incline-block '(> mu (tan a))))
           (history (ames:simulate scenario :bridge bridge))
           (state (first (ames:history-states history))))
      (is (null (ames::state-branches state)) "forked under mu > tan a")
      (is (eq :forever (ames::state-duration state)))
      (is-same-vector bridge "at rest" (per-body (ames:state-velocities state) "P") '(0 0)))))

;;; Class 9: the numeric integrator evaluates abs (a spring's length |x| whose sign the
;;; assumptions leave open: a block on a spring on a rough floor, released from a stretch,
;;; failed its branch under values: "met an operator it cannot evaluate")

(test the-numeric-integrator-evaluates-abs
  "|x - 2| at x = 1/2 and 3; |sin y| at y = -1."
  (let ((f (ames.simulator::numeric-function '(abs (- x 2)) '(x)))
        (g (ames.simulator::numeric-function '(* 3 (abs (sin y))) '(y))))
    (is (= 3/2 (funcall f (vector 0.5d0))))
    (is (= 1 (funcall f (vector 3d0))))
    (is (< (abs (- (funcall g (vector -1d0)) (* 3 (sin 1d0)))) 1d-15))))

(defparameter *spring-on-a-rough-floor*
  "(scenario spring-on-rough-floor
     \"A block on a rough floor on a wall spring, released from a stretch aa.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (k :positive (:value 100))
                 (mu :positive (:value 1/10)) (aa :positive (> aa (/ (* mu m g) k)) (:value 1/5)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body wall :fixed t :shape (half-plane (0 0) (0 1)))
     (body blk :mass m :position ((+ 2 aa) 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
     (spring s :from (wall (0 1/2)) :to (blk (0 1/2)) :stiffness k :rest-length 2)
     (friction blk floor :static mu)
     (simulate :states 2))"
  "Serway's damped-by-friction oscillator: each half swing loses 2 mu m g/k of amplitude.")

(test a-block-on-a-spring-on-a-rough-floor-loses-two-mu-m-g-over-k-each-swing
  "Released at 2 + aa (k aa > mu m g), the block stops after pi sqrt(m/k) at
2 - aa + 2 mu m g/k; with the defaults (k (aa - 2 mu m g/k) = 18 > mu m g = 1) it slides
back and stops after another half period at 2 + aa - 4 mu m g/k = 54/25."
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *spring-on-a-rough-floor* bridge))
           (scenario (ames:history-scenario history))
           (path (ames.check::checked-path (ames:history-states history))))
      (is (null (getf (self-check-of history) :failures)))
      (let ((stops (remove-if-not (lambda (s) (equal '(:stops-sliding "BLK" "FLOOR")
                                                     (event-names (ames::state-end-event s))))
                                  path)))
        (is (= 2 (length stops)) "~D stops" (length stops))
        (when stops
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "first half swing" (ames::state-duration (first stops))
                      (in-scenario-terms scenario '(* pi (sqrt (/ m k)))))
             (is-same bridge "first stop" (first (per-body (ames::state-final-positions (first stops)) "BLK"))
                      (in-scenario-terms scenario '(+ (- 2 aa) (/ (* 2 mu m g) k)))))))
        (when (second stops)
          (is (< (abs (- (expression-value (first (per-body (ames::state-final-positions (second stops)) "BLK"))
                                           (in-scenario-terms scenario '((m . 1) (g . 10) (k . 100) (mu . 1/10) (aa . 1/5))))
                         54/25))
                 1d-9)))))))

;;; Class 1 and 2 on a loop: a ball too slow to loop leaves it, lands back on it, slides and turns

(defparameter *slow-loop*
  "(scenario slow-ball-in-a-loop
     \"A ball launched at sqrt(3 g r) inside a vertical loop leaves it and lands back on it.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1)))
     (gravity g)
     (body loop :fixed t :shape (arc :center (0 r) :radius r :from (- (/ pi 2)) :to (* 3/2 pi) :solid :outside))
     (body ball :mass m :position (0 0) :velocity ((sqrt (* 3 g r)) 0) :shape point)
     (simulate :states 3))"
  "Launched along the bottom at v0^2 = 3 g r: it leaves the loop where N = 0, at height
(v0^2 + g r)/(3 g) = 4 r/3, x = 2 sqrt(2) r/3, with speed sqrt(g r/3) (v^2 = g (y - r)).")

(test a-slow-ball-lands-back-on-its-loop-slides-and-turns
  "It leaves at (2 sqrt 2 r/3, 4 r/3) moving (-sqrt(g r/3)/3, 2 sqrt(2 g r/3)/3); the
parabola meets the circle again at (10 sqrt 2 r/27, 4 r/27) after 8 sqrt(2 r/(3 g))/3; the
plastic landing keeps the tangential part, v_t^2 = 20449 g r/19683, and the ball slides on
until it turns at height 4 r/27 + v_t^2/(2 g) = 26281 r/39366. (It used to end exit 1 on a
complex number, the finished states lost.)"
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *slow-loop* bridge))
           (scenario (ames:history-scenario history))
           (states (ames:history-states history)))
      (is (= 3 (length states)) "~D states" (length states))
      (is (null (getf (self-check-of history) :failures)) "~S" (getf (self-check-of history) :failures))
      (destructuring-bind (&optional leave flight slide) states
        (when slide
          (is (equal '(:lift-off "BALL" "LOOP") (event-names (ames::state-end-event leave))))
          (is (equal '(:collision "BALL" "LOOP") (event-names (ames::state-end-event flight))))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "where it leaves" (per-body (ames::state-final-positions leave) "BALL")
                               (x '((* 2/3 (sqrt 2) r) (* 4/3 r))))
               (is-same bridge "the flight" (ames::state-duration flight)
                        (x '(* 8/3 (sqrt (/ (* 2 r) (* 3 g))))))
               (is-same-vector bridge "where it lands" (per-body (ames::state-final-positions flight) "BALL")
                               (x '((* 10/27 (sqrt 2) r) (* 4/27 r))))))
            ;; the turning point's closed form holds nested arc tangents: compared by value
            (loop for (g r) in '((10 1) (981/100 2) (1 1/2))
                  for bindings = (in-scenario-terms scenario `((m . 1) (g . ,g) (r . ,r)))
                  do (is (< (abs (- (expression-value (second (per-body (ames::state-final-positions slide) "BALL"))
                                                      bindings)
                                    (* 26281/39366 r)))
                            1d-9)
                         "turning height at g = ~A, r = ~A" g r))))))))
