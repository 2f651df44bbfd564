;;;; t/witness-refusals.lisp -- honest refusals the witness's random families found (issue 21),
;;;; answered since: a gap of one sign under drag never meets (src/simulator/termination.lisp,
;;;; sinusoid-floors.lisp's POSITIVE-AFTER-P), the one-sided series of a quantity with no
;;;; derivative at the start (quadratic drag at rest: src/simulator/one-sided-series.lisp),
;;;; and the choice of contacts and modes at a rough impact in a corner
;;;; (src/simulator/choice.lisp). Results are the textbook's, by Maxima equivalence; the
;;;; witness's agreement on the files kept under witness/disagreements/ is checked when
;;;; /usr/bin/python3 has Siconos.

(in-package #:ames.tests)

(def-suite witness-refusals :in all-tests
  :description "Refusals of the witness's families answered: drag and walls, rough impacts in a corner.")

(in-suite witness-refusals)

(defun answer-of-text (text)
  "AMES's s-expression answer (as data) for the first scenario of TEXT."
  (ames::ames-answer (witness-scenario text)))

(defun answer-state (answer index)
  "The state plist numbered INDEX of ANSWER."
  (find index (getf answer :states) :key (lambda (state) (getf state :index))))

(defun answer-entry (state key body)
  "The value of the body named BODY under KEY (:POSITIONS, :VELOCITIES ...) of STATE."
  (second (find body (getf state key) :key (lambda (entry) (symbol-name (first entry)))
                     :test #'string-equal)))

(defparameter *drag-toward-a-wall*
  "(scenario drag-to-wall \"A block coasts under drag toward a wall.\"
     (gravity 41/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body wall :fixed t :shape (polygon (~A 0) (~A 0) (~A 2) (~A 2)))
     (body block :mass 5/2 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
     (drag oil :on block :~A) (simulate :states 3))"
  "A block m = 5/2 at v = 3 toward a wall whose face is at X (format arguments X X+1 X+1 X
and the drag clause's tail).")

(defun drag-toward-a-wall (face drag)
  (format nil *drag-toward-a-wall* face (1+ face) (1+ face) face drag))

(test linear-drag-never-reaches-a-wall-at-its-reach
  "Under linear drag -b v the block coasts x = (m v / b) (1 - exp(-b tau / m)), never
farther than m v / b = 15: a wall whose face is exactly there (the block's front starts at
1, the face at 16) is never reached, and the state lasts forever (it once ended at a
'collision' the numeric root search took from round-off at tau = 184)."
  (with-fixture simulator-bridge ()
    (let* ((answer (answer-of-text (drag-toward-a-wall 16 "linear 1/2")))
           (state (answer-state answer 0)))
      (is (eq :none (getf state :end-event)) "~S" (getf state :end-event))
      (is-same bridge "position" (first (answer-entry state :positions "block"))
               `(* 15 (- 1 (exp (- (/ ames.base:tau 5))))))
      (is (= 1 (length (getf answer :states)))))))

(test quadratic-drag-block-stopped-at-a-wall-stays
  "Under quadratic drag -c |v| v the block reaches the wall (its reach has no bound: x =
(m / c) log(1 + c v tau / m)) and stops there plastically; at rest against the wall with
no force pressing it, it stays forever (the wall's normal force is zero at the start and
its series had 0/0 derivatives of |v| at v = 0). The impact comes at
tau = m (exp(c d / m) - 1) / (c v) = 125 (exp(9/25) - 1) / 27, d = 5 the distance to
the wall."
  (with-fixture simulator-bridge ()
    (let* ((answer (answer-of-text (drag-toward-a-wall 6 "quadratic 9/50")))
           (state (answer-state answer 1)))
      (is (not (null state)) "~S" answer)
      (when state
        (is (eq :none (getf state :end-event)))
        ;; the root of a log is found numerically (a rational to double precision)
        (is (< (abs (- (ames.base:expression-value (getf state :start) '())
                       (* 125/27 (- (exp (float 9/25 1d0)) 1))))
               1d-9)
            "start ~S" (getf state :start))
        (is-same-vector bridge "velocity" (answer-entry state :velocities "block") '(0 0))
        (is-same-vector bridge "position" (answer-entry state :positions "block") '(5 0))))))

(defparameter *disc-into-the-corner*
  "(scenario disc-into-corner \"A disc rolls down a rough incline into the corner.\"
     (gravity 10) (restitution 0)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body incline :fixed t :shape (polygon (0 0) (4 0) (0 3)))
     (body disc :mass 1 :inertia :uniform :shape (circle 1/4) :position (197/60 17/20)
           :velocity (0 0) :angular-velocity 0)
     (friction disc incline :static 1/2) (simulate :states 2))"
  "A uniform disc (I = m r^2 / 2, r = 1/4) rolling from rest down a 3-4-5 incline (sin a =
3/5; mu = 1/2 above tan a / 3 = 1/4: it rolls) through d = 1 until it touches the smooth
floor in the corner.")

(test disc-rolling-into-the-corner-leaves-the-slope
  "Rolling, v^2 = 2 g d sin a / (1 + I / (m r^2)) = 8: it lands at v (4/5, -3/5), spinning
at -v / r. The smooth floor's impulse is vertical through the centre, Jn = m (3/5) v; after
it the disc moves along the floor at v (4/5, 0), away from the slope (the incline's impulse
and its friction are inactive: they would pull), its spin unchanged; the energy lost is
Jn^2 / (2 m) = 36/25. Once refused: no consistent set of contacts and modes."
  (with-fixture simulator-bridge ()
    (let* ((scenario (witness-scenario *disc-into-the-corner*))
           (impact (first-impact scenario bridge))
           (v '(* 2 (sqrt 2))))
      (is (not (null impact)))
      (when impact
        (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "DISC")
                        `((* 4/5 ,v) 0))
        (is-same bridge "angular velocity after"
                 (impact-entry impact :angular-velocities-after "DISC") `(- (* 4 ,v)))
        (is-same bridge "energy lost" (getf impact :energy-lost) 36/25)
        (is (null (find :friction-impulse (getf impact :impulses) :key #'first))
            "a friction impulse: ~S" (getf impact :impulses))))))

(defparameter *refusals-now-witnessed*
  '("refused-drag-slide-wall-start.lisp" "refused-drag-slide-log-gap-4242-4.lisp"
    "refused-disc-incline-corner-4242-2.lisp" "refused-disc-incline-inactive-mode-4242-3.lisp")
  "Refusals of the random families kept under witness/disagreements/, each answered since
\(the file says how) and agreeing with the witness.")

(test refusals-now-agree-with-the-witness
  "Each refusal of *REFUSALS-NOW-WITNESSED* now agrees with Siconos."
  (with-siconos
    (dolist (name *refusals-now-witnessed*)
      (let* ((path (asdf:system-relative-pathname "ames" (format nil "witness/disagreements/~A" name)))
             (result (check-text (uiop:read-file-string path) :numeric t)))
        (is (eq :agree (getf result :verdict))
            "~A gives ~(~A~): ~A" name (getf result :verdict) (getf result :reason))))))

(defparameter *spring-in-oil*
  "(scenario spring-in-oil \"A block on a spring in a viscous medium.\" (gravity 15/2)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body post :fixed t :position (-1 0) :shape point)
     (body block :mass ~A :position (~A 0) :velocity (~A 0) :shape point)
     (spring s :from (post (1 0)) :to (block (0 0)) :stiffness ~A :rest-length ~A)
     (drag oil :on block :linear ~A) (simulate :states 2))"
  "A block (format arguments: mass, start, velocity, stiffness, rest length, drag) on a
spring from the origin in oil: its x is the spring's length.")

(defun spring-in-oil-never-closes (bridge m x0 v0 k l0 b expected)
  "Check that the spring in oil (*SPRING-IN-OIL*) never shrinks to zero length: one state,
forever, the block's x equivalent to EXPECTED (a function of tau)."
  (let* ((answer (answer-of-text (format nil *spring-in-oil* m x0 v0 k l0 b)))
         (state (answer-state answer 0)))
    (is (eq :none (getf state :end-event)) "~S" (getf state :end-event))
    (is (= 1 (length (getf answer :states))))
    (is-same bridge "position" (first (answer-entry state :positions "block")) expected)))

(test underdamped-spring-in-oil-never-closes
  "m x'' = -k (x - l0) - b x', m = 9/4, k = 51/4, b = 47/20 (underdamped), from x0 = 19/20
at v0 = 2: x = l0 + exp(-g tau) (A cos(w tau) + B sin(w tau)), g = b / 2m = 47/90,
w = sqrt(k/m - g^2) = sqrt(43691)/90, A = 1/5, B = (v0 + g A)/w. Its envelope dips below 0
(l0 = 3/4 < sqrt(A^2 + B^2)), but its first minimum, the lowest, is above: once refused
(the envelope's fact, a false constant, offered as the missing one)."
  (with-fixture simulator-bridge ()
    (spring-in-oil-never-closes
     bridge "9/4" "19/20" "2" "51/4" "3/4" "47/20"
     (let ((g 47/90) (w '(/ (sqrt 43691) 90)))
       `(+ 3/4 (* (exp (- (* ,g ames.base:tau)))
                  (+ (* 1/5 (cos (* ,w ames.base:tau)))
                     (* (/ (+ 2 (* ,g 1/5)) ,w) (sin (* ,w ames.base:tau))))))))))

(test overdamped-spring-in-oil-never-closes
  "m = 1/2, k = 27/4, b = 39/10 (overdamped: g = 39/10 > sqrt(k/m)), from x0 = 39/20 at
v0 = -2: x = l0 + exp(-g tau) (A cosh(q tau) + B sinh(q tau)), q = sqrt(g^2 - k/m) =
3 sqrt(19)/10, A = 9/20, B = (v0 + g A)/q; its one minimum is above 0. Once refused
\(sinh could not be differentiated, then the root of two exponentials was undecided)."
  (with-fixture simulator-bridge ()
    (spring-in-oil-never-closes
     bridge "1/2" "39/20" "-2" "27/4" "3/2" "39/10"
     (let ((g 39/10) (q '(/ (* 3 (sqrt 19)) 10)))
       `(+ 3/2 (* (exp (- (* ,g ames.base:tau)))
                  (+ (* 9/20 (cosh (* ,q ames.base:tau)))
                     (* (/ (+ -2 (* ,g 9/20)) ,q) (sinh (* ,q ames.base:tau))))))))))

(test one-sided-taylor-series
  "The one-sided series about 0+ (the bridge's ONE-SIDED-TAYLOR-COEFFICIENTS, which the
local series of |v| v at rest falls back on): sqrt(9 x^2 + x^3) = 3 x sqrt(1 + x/9) =
3 x + x^2/6 - x^3/216 + ... for x > 0; 1/x (a pole) and sqrt(x) (a half power) have none."
  (with-fixture simulator-bridge ()
    (let ((x 'ames.base:tau))
      (is (equal '(0 3 1/6 -1/216)
                 (ames.maxima:one-sided-taylor-coefficients bridge `(sqrt (+ (* 9 (expt ,x 2)) (expt ,x 3))) x 3)))
      (is (null (ames.maxima:one-sided-taylor-coefficients bridge `(/ 1 ,x) x 2)))
      (is (null (ames.maxima:one-sided-taylor-coefficients bridge `(sqrt ,x) x 2))))))
