;;;; t/witness.lisp -- the witness (src/witness/, witness/siconos_driver.py): Siconos checked
;;;; on textbook cases, the comparator on planted disagreements, and a fixed-seed sample of
;;;; random scenarios through AMES and the witness. Every test that needs Siconos is
;;;; skipped, with a message, when /usr/bin/python3 cannot import it.

(in-package #:ames.tests)

(def-suite witness :in all-tests
  :description "AMES against the independent witness (Siconos, issue 21).")

(in-suite witness)

(defmacro with-siconos (&body body)
  "Run BODY when the witness's Python has Siconos; otherwise skip, saying why."
  `(if (ames.witness:siconos-available-p)
       (progn ,@body)
       (skip "the witness needs ~A with Siconos (Debian's python3-siconos)" ames.witness:*python*)))

(defun witness-scenario (text)
  (let ((*package* (find-package '#:ames-scenario)))
    (first (ames.scenario:read-scenarios-from-string text))))

(defun witness-run (text horizon &optional settings)
  "The witness's answer for the scenario TEXT (its (:value N) defaults, SETTINGS over them)."
  (let* ((scenario (witness-scenario text))
         (values (ames.scenario:run-parameter-values scenario :settings settings :numeric t)))
    (values (ames.witness:run-witness (ames.witness:scenario-model scenario values horizon))
            values)))

(defun event-times (answer) (mapcar (lambda (e) (getf e :time)) (ames.witness:witness-events answer)))

(defun near (a b &optional (tolerance 1d-9)) (<= (abs (- a b)) (* tolerance (max 1 (abs a) (abs b)))))

(test witness-bouncing-ball
  "Siconos's impacts of a ball dropped from h with e = 1/2: at t1 = sqrt(2 h / g), then
t1 + 2 e t1 and t1 + 2 e t1 + 2 e^2 t1, the speed halved at each (textbook)."
  (with-siconos
    (let* ((answer (witness-run "(scenario b \"\" (parameters (g :positive (:value 981/100)) (h :positive (:value 1)))
                                   (gravity g) (restitution 1/2)
                                   (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                   (body ball :mass 1 :position (0 h) :velocity (0 0) :shape point)
                                   (simulate :states 3))" 1.2d0))
           (t1 (sqrt (/ 2 9.81d0)))
           (times (event-times answer)))
      (is (eq :ok (ames.witness:witness-status answer)))
      (is (near t1 (first times) 1d-12))
      (is (near (* 2 t1) (second times) 1d-11))
      (is (near (* 5/2 t1) (third times) 1d-11))
      (let ((first-event (first (ames.witness:witness-events answer))))
        (is (near (- (sqrt (* 2 9.81d0))) (second (second (first (getf first-event :velocities))))))
        (is (near (/ (sqrt (* 2 9.81d0)) 2) (second (second (first (getf first-event :after))))))))))

(test witness-ramp-leaving
  "A particle from rest halfway down the raised ramp's top face (angle a, length l, foot
h0 above the floor) leaves it at its end after sqrt(l / (g sin a cos a)) with speed
v = sqrt(g l tan a), and lands after (sqrt(v^2 sin^2 a + 2 g h0) - v sin a) / g more:
the face's extent is the driver's, the table's line does not hold the particle."
  (with-siconos
    (let* ((answer (witness-run (uiop:read-file-string
                                 (asdf:system-relative-pathname "ames" "scenarios/particle-off-raised-ramp.lisp"))
                                2d0))
           (g 9.81d0) (l 2d0) (h0 1d0) (a 0.5d0)
           (t1 (sqrt (/ l (* g (sin a) (cos a)))))
           (v (sqrt (* g l (tan a))))
           (t2 (/ (- (sqrt (+ (expt (* v (sin a)) 2) (* 2 g h0))) (* v (sin a))) g))
           (events (ames.witness:witness-events answer)))
      (is (eq :ok (ames.witness:witness-status answer)))
      (is (equal '(:leaves "particle" "ramp") (first (getf (first events) :pairs))))
      (is (near t1 (getf (first events) :time) 1d-10))
      (is (near l (first (second (first (getf (first events) :positions)))) 1d-10))
      (is (equal '(:collision "particle" "floor") (first (getf (second events) :pairs))))
      (is (near (+ t1 t2) (getf (second events) :time) 1d-10)))))

(test witness-two-blocks
  "Block A (ma, speed v) hits block B (mb, at rest) after d / v; after it A moves at
(ma - e mb) v / (ma + mb) and B at (1 + e) ma v / (ma + mb) (Newton's law)."
  (with-siconos
    (let* ((answer (witness-run (uiop:read-file-string
                                 (asdf:system-relative-pathname "ames" "scenarios/blocks-colliding.lisp"))
                                1d0))
           (event (first (ames.witness:witness-events answer)))
           (after (getf event :after)))
      (is (near 1/3 (getf event :time) 1d-10))
      (is (find '(:collision "block-b" "block-a") (getf event :pairs) :test #'equalp))
      (is (near (/ (- 1 (* 1/2 2)) 3) (first (second (assoc "block-a" after :test #'string=))) 1d-10))
      (is (near (/ (* 3/2 1 3) 3) (first (second (assoc "block-b" after :test #'string=))) 1d-10)))))

(test witness-rough-floor
  "A block sliding at v on a rough floor (mu) stops after v / (mu g), having gone
v^2 / (2 mu g) (textbook); Moreau-Jean time stepping (step 1e-4 s) finds both within
two steps."
  (with-siconos
    (let* ((answer (witness-run "(scenario f \"\" (gravity 981/100)
                                   (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                   (body block :mass 1 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
                                   (friction block floor :static 1/2) (simulate :states 2))" 1d0))
           (event (first (ames.witness:witness-events answer))))
      (is (eq :moreau-jean (getf answer :scheme)))
      (is (equal '(:stops-sliding "block" "floor") (first (getf event :pairs))))
      (is (< (abs (- (getf event :time) (/ 3 (* 1/2 9.81d0)))) 2d-4))
      (is (< (abs (- (first (second (first (getf event :positions)))) (/ 9 (* 2 1/2 9.81d0)))) 1d-4)))))

(test witness-atwood
  "The Atwood machine's heavier mass (m1 = 3, m2 = 1, h = 1) lands after
sqrt(2 h (m1 + m2) / (g (m1 - m2))); the rope, slack after the landing, tightens again
when the light mass comes back down, twice that time from the start (textbook)."
  (with-siconos
    (let* ((answer (witness-run (uiop:read-file-string
                                 (asdf:system-relative-pathname "ames" "scenarios/atwood-machine.lisp"))
                                1.5d0))
           (t1 (sqrt (/ (* 2 1 4) (* 9.81d0 2))))
           (events (ames.witness:witness-events answer)))
      (is (equal '(:collision "heavy" "floor") (first (getf (first events) :pairs))))
      (is (near t1 (getf (first events) :time) 1d-10))
      (is (equal '(:tightens "rope" "rope") (first (getf (second events) :pairs))))
      (is (near (* 2 t1) (getf (second events) :time) 1d-10)))))

(test witness-two-masses-on-a-spring
  "Two particles joined by a spring (k, rest length L0), the second pushed with v0: the
centre of mass moves at m2 v0 / M, the stretch is (v0 / w) sin(w t) with
w = sqrt(k M / (m1 m2)) (textbook); the witness's positions at its end agree to 1e-9."
  (with-siconos
    (let* ((answer (witness-run (uiop:read-file-string
                                 (asdf:system-relative-pathname "ames" "scenarios/two-masses-on-a-spring.lisp"))
                                2.5d0))
           (m1 1) (m2 2) (k 3) (v0 1) (l0 1) (m (+ m1 m2))
           (w (sqrt (/ (* k m) (* m1 m2) 1d0)))
           (end (ames.witness:witness-end answer))
           (time (getf end :time))
           (stretch (* (/ v0 w) (sin (* w time))))
           (centre (+ (/ (* m2 l0) m) (* (/ (* m2 v0) m) time)))
           (positions (getf end :positions)))
      (is (near 2.5d0 time 1d-9))
      (is (near (- centre (* (/ m2 m) (+ l0 stretch)))
                (first (second (assoc "first" positions :test #'string=))) 1d-9))
      (is (near (+ centre (* (/ m1 m) (+ l0 stretch)))
                (first (second (assoc "second" positions :test #'string=))) 1d-9)))))

(test witness-refuses-what-it-cannot-model
  "An outline and a bumper on a moving body are refused by the translator, never
approximated."
  (dolist (clause '("(body bump :fixed t :shape (outline (line (3 0) (5 0)) (arc :center (5 1) :radius 1 :from (- (/ pi 2)) :to (/ pi 2)) (line (5 2) (3 2)) (line (3 2) (3 0))))"
                    "(spring s :from (block (0 0)) :toward (1 0) :stiffness 3 :rest-length 1)"))
    (signals ames.witness:witness-unsupported
      (let ((scenario (witness-scenario
                       (format nil "(scenario f \"\" (gravity 10)
                                     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                     (body block :mass 1 :position (0 0) :velocity (1 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
                                     ~A (simulate :states 1))" clause))))
        (ames.witness:scenario-model scenario '() 1d0)))))

(defun check-text (text &rest keys)
  (apply #'ames::witness-check (witness-scenario text) keys))

(test witness-comparator-catches-planted-errors
  "AMES agrees with the witness on two blocks colliding; the same answer with a final
velocity off by 1e-5, or another event, is a disagreement."
  (with-siconos
    (let* ((text (uiop:read-file-string
                  (asdf:system-relative-pathname "ames" "scenarios/blocks-colliding.lisp")))
           (result (check-text text :numeric t))
           (answer (getf result :answer))
           (witness (getf result :witness))
           (values (ames.scenario:run-parameter-values (witness-scenario text) :numeric t)))
      (is (eq :agree (getf result :verdict)))
      (flet ((planted (edit)
               (let ((copy (copy-tree answer)))
                 (funcall edit (first (getf copy :states)))
                 (ames.witness:comparison-verdict
                  (ames.witness:compare-results copy witness values
                                                :t-end (ames::witness-horizon answer values))))))
        (is (eq :ames-wrong
                (planted (lambda (state)
                           (let ((entry (second (assoc "BLOCK-A" (getf (getf state :numeric) :final-velocities)
                                                       :test #'string= :key #'symbol-name))))
                             (incf (first entry) 1d-5))))))
        (is (eq :ames-wrong
                (planted (lambda (state) (setf (first (getf state :end-event)) :leaves)))))
        ;; a duration without a number (a travel-time integral the quadrature gave none) is
        ;; no disagreement: the state is unchecked, a verdict of its own
        (is (eq :unchecked
                (planted (lambda (state)
                           (setf (getf (getf state :numeric) :duration)
                                 '(:no-closed-form :from-arc-length 0 :to-arc-length 1
                                   :speed-squared 1))))))))))

(defparameter *known-disagreements*
  '()
  "Disagreements AMES has today, each kept as a scenario file under
witness/disagreements/ with the reason; a test checks that each still disagrees, so
that a fix shows up (then move the file to *WITNESSED-FIXES*).")

(defparameter *witnessed-fixes*
  '(("accumulated-bounce-numeric-start.lisp"
     "After a summed Zeno sequence of impacts, the :numeric :start of the state at rest was
the start of the last simulated impact's state plus its duration (0.903 s for the
bouncing ball), not the accumulation time 3 sqrt(2 h / g) = 1.3546 s that the closed
form :start gives. Fixed: a state's start number is its start formula's value.")
    ("refused-raised-ramp-quotient-by-zero.lisp"
     "A particle sliding off a raised ramp was refused ('Maxima failed: quotient by zero'):
a velocity component at the ramp's end was a zero written with nested radicals, on which
Maxima's factor() divides by zero. Fixed: a simplification candidate Maxima fails on is
left out.")
    ("refused-ramp-foot-impact.lisp"
     "A particle sliding off the foot of a ramp onto the floor with e > 0 was refused ('no
set of contacts and modes is consistent'). Fixed: a face a non-concave corner excuses is
no constraint of the impact.")
    ("ames-wrong-dome-lift-off-leftward.lisp"
     "A particle sliding off a dome toward -x lifted off (state 0 agreed), but AMES's next
state kept the contact, with an attractive normal force, down to the arc's end: the
normal force at the lift-off point (the far root, toward -x, in the bridge's half-angle
form) was zero, which Maxima's float sign() took for positive. Fixed: a relation between
constants agreeing to round-off is decided exactly or not at all (constant-zero.lisp).")
    ("ames-wrong-dome-leftward-landing.lisp"
     "A particle pushed toward -x off a dome landed on the floor with e = 0: AMES's impact
left its velocity unchanged and its next state fell through the floor (the state after
the lift-off wrongly kept the dome's contact; same cause and fix as above).")
    ("ames-wrong-drag-elastic-bounces.lisp"
     "An elastic ball (e = 1) bouncing under linear drag: AMES summed its impacts as a
geometric series from the first two cycles and put it at rest at t = 4.12 s; under drag a
flight does not scale with its speed and the impacts never accumulate (the witness
bounces on at 2.060 s). Fixed: a Zeno sequence is summed only over flights with constant
accelerations.")
    ("ames-wrong-loop-missed-turning-point.lisp"
     "A particle launched toward -x in a loop (r = 3/4) too slowly to reach the centre's
height was said to move forever; it turns at 0.4531 s: the energy integral at the
turning point found ahead (pi - asin, the far branch) is zero, which Maxima's float
sign() took for negative, so the turning point looked unreachable. Same fix.")
    ("witness-wrong-rough-incline-at-rest.lisp"
     "A particle at rest on a rough incline steeper than nothing but below its angle of
repose (tan a = 8/15 < mu = 13/20) stays at rest, as AMES says; the witness's LCP gave it
one Moreau-Jean step of tangential speed above its tolerance and called it a slide start.
Fixed in the witness: a slide start counts once it has lasted five steps.")
    ("witness-wrong-rough-incline-stop-at-rest.lisp"
     "A particle at rest on a rough incline (tan a = 5/12 < mu = 4/5): the witness's LCP
gave it a few steps of speed and a slide's end at 4e-4 s, which the comparator took for
an event AMES missed. Fixed in the witness: a slide ends once it has lasted five steps.")
    ("ames-wrong-spheres-spurious-turn.lisp"
     "Two spheres under gravitation, after a plastic collision, rest against each other:
AMES integrated the state numerically from its start rounded to doubles (sin(pi) =
1.2e-16) and ended it with a turning point after 8.7e-22 s; the witness has no event
(make crosscheck SEED=101 #718). Fixed: a group whose every rate is exactly zero at its
start stays there (simulator/equilibrium.lisp), and the self-check measures an event's
noise on its quantity's scale (an equilibrium's round-off is no event).")
    ("witness-wrong-step-corner.lisp"
     "A particle landing exactly in the corner of the floor and a step: the witness took
the floor's impact only (the step's face holds a body only within its extent, and the
particle, falling, was leaving it at its very end) and slid the particle through the step.
Fixed in the witness: a face whose end the body sits on, approaching it, holds it when
another face it hits stops the motion that would take it off (siconos_driver.py's
CORNER-HELD).")
    ("refused-drag-slide-quadratic.lisp"
     "A block sliding alone under quadratic drag was refused: the earliest root of a
'turns' function with abs(9 + 2 tau), positive for tau >= 0, undecided. Fixed: abs() of a
function of tau of proven sign, monotone, is written without it before the root search
(simulator/abs-signs.lisp).")
    ("refused-drag-projectile-reversing-push.lisp"
     "A ball under quadratic drag and a push, numerically integrated, was refused after
200,000 steps: its landing was taken for a contact reached at no speed (the numeric
state gave its candidates no rate), so no impact, and the next state fell through the
floor. Fixed: a numeric state's contact reached at a clear speed is an impact, its
position put exactly on the contact; the sliding state after it is decided by the
monotone abs() above.")
    ("ames-wrong-rod-on-ledge.lisp"
     "A rod landing flat across a ledge's edge was stopped dead by two equal impulses at its
ends, the far end past the edge taken for touching the ledge's top (a corner touched a
face by its gap alone), and the ledge's edge, a fixed corner under the rod's face, was not
modelled. Fixed: a corner touches only within the face's ends (src/kb/corners.lisp), a
fixed corner on a rotating body's face is a corner contact (src/geometry/fixed-corners.lisp;
the witness's siconos_ledges.py): J = 0.583 m at the edge, omega' = -1.574.")
    ("ames-wrong-drag-elastic-quadratic-bounces.lisp"
     "An elastic ball under quadratic drag: AMES summed its impacts as a geometric series
(its flight's accelerations, written over the velocity, were free of tau and taken for
constant). Fixed: a Zeno sequence needs accelerations free of every state quantity.")
    ("witness-wrong-wound-atwood-4242-985.lisp"
     "An Atwood machine over a ring pulley, ropes wound: the right mass lands at
9 sqrt(22)/44 = 0.9594 (a = 27/44 by hand, AMES's answer); the witness said 0.9795. Fixed
in the witness: a taut rope's gap is seen MARGIN closer, as a contact's, so that round-off
no longer lets it out of Moreau-Jean's index set for a step (the velocities chattered).")
    ("witness-failed-bowl-4242-885.lisp"
     "A particle swinging in a bowl: the witness failed (a model rebuilt with the particle
2.5e-12 behind the bowl, which Siconos refuses). Fixed in the witness: a body slightly
behind an active contact is put on it.")
    ("unchecked-duration-loop-4242-971.lisp"
     "A particle in a loop lifts off, lands and slides back to a turning point: the
comparator counted the duration without a number (a travel-time integral) as wrong.
Fixed: such a state is unchecked (a verdict of its own); a scenario without parameters
records the integral's number; and the comparator evaluates sines and inverse tangents
of 40-digit radicals to 160 digits, where the speed at the turning point is exactly 0.")
    ("witness-failed-drag-projectile-777-339.lisp"
     "A ball bouncing under quadratic drag (e = 1/2): the witness failed at the end of its
Zeno sequence (a rebound of 3.5e-8 m/s, then Siconos's processEvents). Fixed in the
witness: a body touching a fixed face with a normal speed under 1e-7 starts the next
model at rest on it, under state-dependent forces.")
    ("witness-wrong-hinged-swing-777-982.lisp"
     "A disc hinged at its rim, near a turning point: the comparator evaluated AMES's speed
at the first-order witness's position, which lags by 0.0047 rad, and the speed goes as the
square root of the energy left: 0.234 against the witness's 0.255; AMES's 0.2532 at the
right angle is exact (RK4). Fixed in the comparator: a swing's velocity is AMES's at its
own position at the sample's time (src/witness/compare-swing.lisp)."))
  "Disagreements the witness found and AMES has since fixed: each must now agree, with
its file under witness/disagreements/ kept as the regression case.")

(test witness-known-disagreements
  "Each known disagreement still disagrees (an expected failure, listed with its file)."
  (with-siconos
    (dolist (known *known-disagreements*)
      (let* ((path (asdf:system-relative-pathname "ames" (format nil "witness/disagreements/~A" (first known))))
             (result (check-text (uiop:read-file-string path) :numeric t)))
        (is (eq :ames-wrong (getf result :verdict))
            "~A now gives ~(~A~): fixed? Move it to *WITNESSED-FIXES*."
            (first known) (getf result :verdict))))))

(test witness-fixed-disagreements-agree
  "Each disagreement the witness once found, since fixed, agrees with Siconos."
  (with-siconos
    (dolist (fixed *witnessed-fixes*)
      (let* ((path (asdf:system-relative-pathname "ames" (format nil "witness/disagreements/~A" (first fixed))))
             (result (check-text (uiop:read-file-string path) :numeric t)))
        (is (eq :agree (getf result :verdict))
            "~A gives ~(~A~) again: ~A" (first fixed) (getf result :verdict) (second fixed))))))

(test witness-held-blocks-cut
  "Two blocks on a spring catch up with a third, twice, plastically (witness/disagreements/
witness-failed-spring-4242-444.lisp): the witness once failed. Its two impacts now agree;
past the second (the spring holds the blocks together, where Siconos's integrator stops)
the witness cuts its run and says why: unsupported, never a failure."
  (with-siconos
    (let* ((path (asdf:system-relative-pathname
                  "ames" "witness/disagreements/witness-failed-spring-4242-444.lisp"))
           (result (check-text (uiop:read-file-string path) :numeric t))
           (rows (ames.witness:comparison-rows (getf result :comparison))))
      (is (eq :unsupported (getf result :verdict)) "~S" (getf result :reason))
      (is (search "held against" (getf result :reason)))
      ;; both impacts were compared, and agreed
      (is (= 2 (count "end event" rows :key #'second :test #'string=)))
      (is (every #'sixth rows)))))

(defparameter *sample-families*
  (remove-if (lambda (family)
               (or (member family '(:incline-pulley :drag-fall :drag-projectile))
                   (assoc family ames.witness:*curved-families*)
                   (assoc family ames.witness:*rotation-families*)))
             (ames.witness:generator-families))
  "The families of the fixed-seed sample. Left out, with the reason: :INCLINE-PULLEY,
whose second state the witness cannot model (the rope turns once the particle leaves the
slope, or a body reaches the pulley, which AMES does not model either) and which is slow
(numeric integration; it is in `make crosscheck`); the families on arcs, with bumpers and
under gravitation (*CURVED-FAMILIES*: AMES takes 5-10 s on each, and their driver's Python
callbacks are slow; t/witness-curved.lisp covers them, `make crosscheck FAMILIES=...` runs
them); :DRAG-FALL and :DRAG-PROJECTILE (AMES takes 5 s on each: numbers by integration,
Lambert W landings); the rotating families (*ROTATION-FAMILIES*, unsupported by AMES
until it runs rotating bodies).")

(defparameter *sample-size* (* 4 (length *sample-families*))
  "How many random scenarios the fixed-seed sample runs (4 per family, in turn).")

(test witness-random-sample
  "A fixed-seed sample of random scenarios (4 per family of *SAMPLE-FAMILIES*, seed 1):
AMES is never wrong and never crashes against the witness."
  (with-siconos
    (let ((counts (ames::crosscheck :n *sample-size* :seed 1 :verbose nil
                                    :families *sample-families*
                                    :stream (make-broadcast-stream)
                                    :directory (uiop:ensure-directory-pathname
                                                (uiop:default-temporary-directory)))))
      (loop for (family . verdicts) in counts
            do (loop for (verdict . count) in verdicts
                     do (is (not (member verdict '(:ames-wrong :crash)))
                            "~A: ~D scenario~:P ~(~A~)" family count verdict)))
      ;; and the witness did witness: most of the sample agrees, it is not all refused
      (let ((agreeing (loop for (nil . verdicts) in counts sum (or (cdr (assoc :agree verdicts)) 0))))
        (is (>= agreeing (* 2/3 *sample-size*))
            "only ~D of ~D scenarios agree: ~S" agreeing *sample-size* counts)))))

(test witness-check-command
  "bin/ames check parses like run, and its status is 0 when AMES and the witness agree and
4 on a disagreement."
  (is (eq :check (getf (ames::parse-command-line '("check" "a.lisp" "--set" "g=10")) :command)))
  (with-siconos
    (flet ((status (file)
             (let ((*package* (find-package '#:ames-scenario)))
               (ames::check-files (list (asdf:system-relative-pathname "ames" file))
                                  :numeric t :stream (make-broadcast-stream)))))
      (is (eql 0 (status "scenarios/blocks-colliding.lisp")))
      ;; a disagreement the witness found, since fixed
      (is (eql 0 (status "witness/disagreements/accumulated-bounce-numeric-start.lisp")))
      ;; a file that cannot be read: its error is printed, the status is 1, nothing escapes
      (uiop:with-temporary-file (:pathname path :stream out :type "lisp")
        (write-string "(scenario broken \"d\" (body))" out)
        (finish-output out)
        (is (eql 1 (let ((*error-output* (make-broadcast-stream)))
                     (ames::check-files (list path) :numeric t :stream (make-broadcast-stream))))))))
  (is (equal '(0 4 4 1 1 1 1)
             (mapcar #'ames::verdict-status '(:agree :ames-wrong :crash :refused :unsupported :witness-failed
                                              :unchecked)))))

(test a-disagreement-file-reads-back-as-its-scenario
  "A disagreement written out (WRITE-DISAGREEMENT) is a scenario file whatever its
reason: a reason of several lines stays a comment, so the file reads back as the one
scenario it was written with."
  (let* ((text "(scenario written \"A written scenario.\" (gravity 10)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ball :mass 1 :position (0 1) :velocity (0 0) :shape point))")
         (directory (uiop:ensure-directory-pathname
                     (format nil "~Aames-disagreement-~D-~D" (uiop:temporary-directory)
                             (get-universal-time) (random 1000000 (make-random-state t))))))
    (unwind-protect
         (let* ((path (ames.witness::write-disagreement
                       directory "two-line-reason" text
                       (list :verdict :ames-wrong :reason (format nil "state 0: first line~%\"second\")) line")
                             :answer '(:states nil) :witness '(:status :ok))))
                (scenarios (ames.scenario:read-scenario-file path)))
           (is (= 1 (length scenarios)))
           (is (string-equal "WRITTEN" (symbol-name (ames.scenario:scenario-name (first scenarios))))))
      (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))))
