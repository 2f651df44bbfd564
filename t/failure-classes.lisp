;;;; t/failure-classes.lisp -- issue 20's failure classes 3, 9, 10 and 11 on fresh scenarios:
;;;; a bumper in a block's path on a floor, impacts at the foot of a ramp with restitution
;;;; (a corner of the ramp touching too), derivatives of expressions an operator the
;;;; differentiator does not know leaves constant.
;;;;
;;;; Every expected result is the textbook's, over the scenario's own parameters, compared by
;;;; Maxima-checked equivalence (helpers in t/simulator-scenarios.lisp and
;;;; t/springs-ropes-gravitation.lisp).

(in-package #:ames.tests)

(def-suite failure-classes :in all-tests
  :description "Issue 20, classes 3, 9, 10, 11: bumpers on floors, impacts at corners, errors where an answer exists.")

(in-suite failure-classes)

;; SCENARIO-FROM-TEXT is the one of queries-answers.lisp.

;;; Class 3: a bumper in the path of a block sliding on a floor

(defun check-bumper-bounce (bridge scenario history direction height)
  "Check HISTORY, a block (speed v, mass m) meeting a bumper (stiffness k) after d / v
along DIRECTION (+1 or -1 on x): three states, pressed for pi sqrt(m/k) with the floor's
normal force m g, compressed by v sqrt(m/k) half-way, leaving with its velocity reversed,
energy m v^2 / 2 + m g HEIGHT (HEIGHT the centre of mass's) conserved while pressed."
  (let ((states (ames::history-states history)))
    (flet ((x (form) (in-scenario-terms scenario form)))
      (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
      (is (= 3 (length states)) "~D states" (length states))
      (destructuring-bind (&optional approach pressed away) states
        (when away
          (is (equal '(:contact "BLOCK" "BUMPER") (event-names (ames::state-end-event approach))))
          (is (equal '(:leaves "BLOCK" "BUMPER") (event-names (ames::state-end-event pressed))))
          (is (eq :forever (ames::state-duration away)))
          (is (not (member "WALL" (alexandria:flatten (contact-pairs away)) :test #'equal)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "time to the bumper" (ames::state-duration approach) (x '(/ d v)))
             (is-same bridge "contact time" (ames::state-duration pressed) (x '(* pi (sqrt (/ m k)))))
             (is-same bridge "the floor's normal force" (normal-force-between pressed "BLOCK" "FLOOR")
                      (x '(* m g)))
             (is-same-vector bridge "leaves with the velocity reversed"
                             (per-body (ames::state-final-velocities pressed) "BLOCK")
                             (x `((* ,(- direction) v) 0)))
             (let* ((half (x '(* 1/2 pi (sqrt (/ m k)))))
                    (x0 (first (per-body (ames::state-positions pressed) "BLOCK")))
                    (start (at-variable x0 'tau 0)))
               (is-same bridge "maximum compression"
                        (at-variable `(* ,direction (- ,x0 ,start)) 'tau half)
                        (x '(* v (sqrt (/ m k))))))
             (is-conserved bridge "energy while pressed" (total-energy pressed) 'tau 0)
             (is-same bridge "the energy" (at-variable (total-energy pressed) 'tau 0)
                      (x `(+ (* 1/2 m (expt v 2)) (* m g ,height))))))
          (is-same-vector bridge "velocity away" (per-body (ames:state-initial-velocities away) "BLOCK")
                          (x `((* ,(- direction) v) 0))))))))

(test block-into-bumper-on-a-floor-comes-back
  "scenarios/block-into-bumper-on-floor.lisp: the block on the floor meets the bumper on a
half-plane wall, compresses it by v sqrt(m/k) and comes back at v; the wall is never hit."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "block-into-bumper-on-floor" bridge)
      (check-bumper-bounce bridge scenario history -1 0))))

(test block-into-bumper-on-a-right-hand-wall-comes-back
  "A centred block sliding to the right into a bumper on a wall at x = w (a half-plane
whose solid is x > w), the bumper at a quarter of the block's height: the same bounce,
mirrored."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text "
(scenario bumper-right
  \"A block slides right into a bumper on a wall.\"
  (parameters (m :positive) (k :positive) (g :positive) (v :positive) (d :positive)
              (l0 :positive (> l0 (* v (sqrt (/ m k)))))
              (w :positive (> w (+ l0 d 1))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (w 1) (w 0)))
  (body block :mass m :position ((- w l0 d 1/2) 1/2) :velocity (v 0)
        :shape (polygon (-1/2 -1/2) (1/2 -1/2) (1/2 1/2) (-1/2 1/2)))
  (spring bumper :from (wall (w 1/4)) :toward (-1 0) :stiffness k :rest-length l0)
  (simulate :states 4))"))
           (history (simulate-stopping-when-ambiguous scenario bridge)))
      (check-bumper-bounce bridge scenario history 1 1/2))))

;;; Class 11: a particle leaving the foot of a ramp, bouncing (the ramp's corner touches too)

(defun ramp-foot-scenario (e mirrored)
  "A particle released at the top of a fixed ramp of height h and angle a on the floor,
restitution E; MIRRORED puts the slope on the left (the particle leaves toward -x)."
  (scenario-from-text
   (format nil "
(scenario ramp-foot
  \"A particle slides down a ramp onto the floor and bounces.\"
  (parameters (m :positive) (g :positive) (h :positive) (a (> a 0) (< a (/ pi 2))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ramp :fixed t :shape ~A)
  (body particle :mass m :position (0 h) :velocity (0 0) :shape point)
  (restitution ~A)
  (simulate :states 3))"
           (if mirrored
               "(polygon (0 0) (0 h) ((- (/ h (tan a))) 0))"
               "(polygon (0 0) ((/ h (tan a)) 0) (0 h))")
           e)))

(defun check-ramp-foot-bounce (bridge e mirrored)
  "The particle reaches the foot with speed sqrt(2 g h) along the slope; the floor turns
its vertical part -sqrt(2 g h) sin a into E sqrt(2 g h) sin a, the horizontal part
sqrt(2 g h) cos a is kept, no impulse comes from the ramp; it then flies free and lands
again after 2 E sqrt(2 g h) sin a / g."
  (let* ((scenario (ramp-foot-scenario e mirrored))
         (history (simulate-stopping-when-ambiguous scenario bridge))
         (states (ames::history-states history))
         (sign (if mirrored -1 1)))
    (flet ((x (form) (in-scenario-terms scenario form)))
      (is (member (ames::history-outcome history) '(:complete :state-limit))
          "e = ~A: outcome ~S" e (ames::history-outcome history))
      (destructuring-bind (&optional slide flight &rest more) states
        (declare (ignore more))
        (is (not (null flight)) "e = ~A: ~D states" e (length states))
        (when flight
          (is (equal '(:collision "PARTICLE" "FLOOR") (event-names (ames::state-end-event slide))))
          (is (null (contact-pairs flight)) "e = ~A: contacts in flight ~S" e (contact-pairs flight))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "velocity just after the impact"
                             (per-body (ames:state-initial-velocities flight) "PARTICLE")
                             (x `((* ,sign (sqrt (* 2 g h)) (cos a)) (* ,e (sqrt (* 2 g h)) (sin a)))))
             (is-same bridge "impulse of the floor"
                      (getf (cdddr (ames::state-end-event slide)) :impulse)
                      (x `(* (+ 1 ,e) m (sqrt (* 2 g h)) (sin a))))
             (is-same bridge "time of flight" (ames::state-duration flight)
                      (x `(/ (* 2 ,e (sqrt (* 2 g h)) (sin a)) g))))))))))

(test particle-bounces-off-the-floor-at-a-ramp-foot
  "Restitution 1/2 at the foot of a ramp whose lower corner touches the particle too: the
corner's base face, which the particle leaves, is no constraint of the impact."
  (with-fixture simulator-bridge ()
    (check-ramp-foot-bounce bridge 1/2 nil)))

(test particle-bounces-elastically-off-a-mirrored-ramp-foot
  "The mirrored ramp (slope down toward -x), elastic impact with the floor."
  (with-fixture simulator-bridge ()
    (check-ramp-foot-bounce bridge 1 t)))

;;; Class 9: the differentiator and operators it does not know

(test derivative-of-constant-subexpressions-and-abs
  "Any subexpression free of the variable is a constant, whatever its operator (|l| of a
parameter); d|u|/dt = u u' / |u|."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> l 0)))
      (is-same bridge "d/dtau (|l| tau)" (ames.geometry::differentiate '(* (abs l) tau) 'tau) '(abs l))
      (is-same bridge "d/dtau (floor(l) + tau^2)"
               (ames.geometry::differentiate '(+ (floor l) (expt tau 2)) 'tau) '(* 2 tau))
      (is-same bridge "d/dtau |l - tau^2|"
               (ames.geometry::differentiate '(abs (- l (expt tau 2))) 'tau)
               '(/ (* -2 tau (- l (expt tau 2))) (abs (- l (expt tau 2))))))))

;;; Class 9: three touching discs (a numeric group ended at its start; steps that overflow)

(defun discs-in-a-row (masses)
  "Three discs of radius r in a row on a frictionless floor, touching, the first (speed v)
pushing the other two at rest; MASSES their three masses (forms); plastic impacts."
  (scenario-from-text
   (format nil "
(scenario discs
  \"A disc pushes two touching discs.\"
  (parameters (g :positive) (m1 :positive) (m2 :positive) (m3 :positive) (r :positive) (v :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body a :mass ~A :position (0 r) :velocity (v 0) :shape (circle r))
  (body b :mass ~A :position ((* 2 r) r) :velocity (0 0) :shape (circle r))
  (body c :mass ~A :position ((* 4 r) r) :velocity (0 0) :shape (circle r))
  (restitution 0)
  (simulate :states 2))" (first masses) (second masses) (third masses))))

(defun check-discs-move-together (bridge masses)
  "Plastic: the three discs move on together at m1 v / (m1 + m2 + m3) just after the
impact at the start (momentum conserved)."
  (let* ((scenario (discs-in-a-row masses))
         (history (simulate-stopping-when-ambiguous scenario bridge))
         (first-state (first (ames::history-states history)))
         (next (second (ames::history-states history))))
    (flet ((x (form) (in-scenario-terms scenario form)))
      (is (not (null next)) "two states expected, outcome ~S" (ames::history-outcome history))
      (when next
        (is (equal '(:collision "A" "B") (event-names (ames::state-end-event first-state))))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "impact at the start" (ames::state-duration first-state) 0)
           (let ((common (x `(/ (* ,(first masses) v) (+ ,@masses)))))
             (dolist (body '("A" "B" "C"))
               (is-same-vector bridge (format nil "~A just after" body)
                               (per-body (ames:state-initial-velocities next) body)
                               (list common 0))))))))))

(test three-touching-discs-plastic-equal-masses
  "Equal masses m: each disc moves on at v/3."
  (with-fixture simulator-bridge ()
    (check-discs-move-together bridge '(m1 m1 m1))))

(test three-touching-discs-plastic-three-masses
  "Masses m1, m2, m3: each disc moves on at m1 v / (m1 + m2 + m3)."
  (with-fixture simulator-bridge ()
    (check-discs-move-together bridge '(m1 m2 m3))))

(test integration-without-events-stops-before-overflowing
  "A uniform motion with no event: the integrator reports no event (NIL time) instead of
overflowing its growing steps."
  (let ((time (ames.simulator::integrate-until
               (lambda (y) (vector (svref y 1) 0d0)) (vector 0d0 1d0)
               (list (lambda (state time) (declare (ignore time)) (+ 1d0 (svref state 1)))))))
    (is (null time))))

;;; Class 11: a sign fact of the geometry decided by the run's values (a stairs-shaped
;;; polygon with a parameter height met by a disc: TYPE-ERROR on a NIL ball before)

(test geometry-sign-fact-decided-by-values
  "(:SIGN X) under parameter values: :POSITIVE, :NEGATIVE or :ZERO as X's value is, and
:NONE when no value settles it."
  (let ((s (intern "S" '#:ames-scenario)))
    (flet ((outcome (value expression)
             (ames.algebra:with-parameter-values ((list (cons s value)))
               (ames.geometry::value-outcome (list :sign expression) '(:positive :zero :negative)))))
      ;; 1 - 16 (s - 7/4)^2: positive for s in (3/2, 2), zero at s = 3/2, negative below
      (let ((x `(+ (* -16 (expt (+ ,s -7/4) 2)) 1)))
        (is (eq :positive (outcome 7/4 x)))
        (is (eq :negative (outcome 1/2 x)))
        (is (eq :zero (outcome 3/2 x))))
      (is (eq :none (ames.algebra:with-parameter-values ('())
                      (ames.geometry::value-outcome (list :sign s) '(:positive :negative))))))))

;;; Class 9: the sexp output names things as the user does

(defun foreign-symbols (tree)
  "The symbols of TREE, keywords aside, that are not accessible in the scenario package."
  (let ((found '()))
    (labels ((walk (x)
               (cond ((consp x) (walk (car x)) (walk (cdr x)))
                     ((and x (symbolp x) (not (keywordp x))
                           (not (eq x (find-symbol (symbol-name x) '#:ames-scenario))))
                      (pushnew x found)))))
      (walk tree))
    found))

(test sexp-output-names-the-arc-length-s
  "The particle sliding down a quarter circle: the sexp report writes the arc length s
(no internal symbol of AMES anywhere, the JSON round trip intact), and its formulas over s
are the textbook's: position (-r sin(s/r), r - r cos(s/r)), normal force 3 m g cos(s/r)."
  (with-fixture simulator-bridge ()
    (multiple-value-bind (scenario history) (run-scenario-file "particle-down-quarter-circle" bridge)
      (let* ((sexp (ames:history-sexp history))
             (state (first (getf sexp :states)))
             (r (intern "R" '#:ames-scenario)) (m (intern "M" '#:ames-scenario))
             (g (intern "G" '#:ames-scenario)) (s (intern "S" '#:ames-scenario)))
        (flet ((x (form) (sublis (list (cons 'r r) (cons 'm m) (cons 'g g) (cons 's s)) form)))
          (is (null (foreign-symbols sexp)) "internal symbols: ~S" (foreign-symbols sexp))
          (is (equal sexp (ames.report:json-to-sexp (ames.report:history-json history))))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same-vector bridge "position on the curve"
                             (second (per-body (getf state :positions) "PARTICLE"))
                             (x '((- (* r (sin (/ s r)))) (- r (* r (cos (/ s r)))))))
             (is-same bridge "normal force"
                      (car (last (find :normal (getf state :forces) :key #'first)))
                      (x '(* 3 m g (cos (/ s r))))))))))))

;;; Class 3 with friction: a block on a rough floor into a bumper (numbers)

(defun rough-bumper-scenario (speed)
  "A block (m = 1) on a rough floor (mu = 1/2, g = 10), its front 1 from a bumper's free
end (k = 20, rest length 1) on a wall, launched toward it at SPEED (a form)."
  (scenario-from-text
   (format nil "
(scenario rough-bumper
  \"A block slides on a rough floor into a bumper.\"
  (gravity 10)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 0) (0 1)))
  (body block :mass 1 :position (2 0) :velocity ((- ~A) 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (friction block floor :static 1/2)
  (spring bumper :from (wall (0 1/2)) :toward (1 0) :stiffness 20 :rest-length 1)
  (simulate :states 5))" speed)))

(defun check-rough-bumper (bridge speed rests)
  "The block reaches the bumper with v1^2 = SPEED^2 - 2 mu g; work and energy give the
compression c at its first stop: k c^2 / 2 + mu m g c = m v1^2 / 2. It stays there when
k c <= mu m g; else it slides back and stops at the mirror image of that point about the
equilibrium 1 - mu m g / k (half an oscillation). RESTS: the expected positions where it
stops, in order."
  (let* ((scenario (rough-bumper-scenario speed))
         (history (simulate-stopping-when-ambiguous scenario bridge))
         (states (ames::history-states history))
         (stops (loop for state in states
                      when (equal '(:stops-sliding "BLOCK" "FLOOR")
                                  (event-names (ames::state-end-event state)))
                        collect state)))
    (is (eq :complete (ames::history-outcome history)) "outcome ~S" (ames::history-outcome history))
    (is (= (length rests) (length stops)) "~D stops" (length stops))
    (loop for state in stops for rest in rests
          do (is-same-vector bridge "where it stops"
                             (per-body (ames::state-final-positions state) "BLOCK") (list rest 0))
             (is-same-vector bridge "at rest"
                             (per-body (ames::state-final-velocities state) "BLOCK") '(0 0)))
    (is (eq :forever (ames::state-duration (car (last states)))))))

(test block-on-a-rough-floor-sticks-against-the-bumper
  "v0 = 2 sqrt(3): v1^2 = 2, 10 c^2 + 5 c = 1, c = (sqrt(65) - 5)/20, k c < 5: it stays
compressed, its front at 1 - c."
  (with-fixture simulator-bridge ()
    (check-rough-bumper bridge '(* 2 (sqrt 3)) '((/ (- 25 (sqrt 65)) 20)))))

(test block-on-a-rough-floor-is-pushed-back-by-the-bumper-then-sticks
  "v0 = 4: v1^2 = 6, 10 c^2 + 5 c = 3, c = (sqrt(145) - 5)/20, k c > 5: pushed back, it
stops at 2 (3/4) - (1 - c) = (5 + sqrt(145))/20, where k (1 - x) < 5: it stays."
  (with-fixture simulator-bridge ()
    (check-rough-bumper bridge 4 '((/ (- 25 (sqrt 145)) 20) (/ (+ 5 (sqrt 145)) 20)))))

;;; Class 9: abs in relations decided by the cases of its argument's sign

(test abs-is-decided-by-the-sign-cases-of-its-argument
  "|u| >= u whatever u; a sum of lengths with |len - 2 r - top| is at least len; |a - b|
> 0 where a > b; |x| < -1 never; |x - 1| > 1/2 depends on x."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> r 0) (> top 0) (> len 0) (> a b)))
      (is (eq :true (ames.algebra:decide bridge '(>= (abs (- x y)) (- x y)))))
      (is (eq :true (ames.algebra:decide bridge '(>= (+ (* 2 r) top (abs (- len (* 2 r) top))) len))))
      (is (eq :true (ames.algebra:decide bridge '(> (abs (- a b)) 0))))
      (is (eq :false (ames.algebra:decide bridge '(< (abs x) -1))))
      (is (eq :unknown (ames.algebra:decide bridge '(> (abs (- x 1)) 1/2)))))))
