;;;; t/witness-curved.lisp -- the witness's arcs, circles, gravitation and bumpers
;;;; (witness/siconos_arcs.py) checked on textbook cases, and AMES against it on the
;;;; scenarios of these families. Skipped, with a message, without Siconos (WITH-SICONOS,
;;;; t/witness.lisp).

(in-package #:ames.tests)

(def-suite witness-curved :in all-tests
  :description "The witness on arcs, under gravitation and with bumpers (issue 21).")

(in-suite witness-curved)

(defun scenario-file-text (name)
  (uiop:read-file-string (asdf:system-relative-pathname "ames" (format nil "scenarios/~A.lisp" name))))

(defun first-event-with (answer kind)
  (find-if (lambda (e) (some (lambda (pair) (eq kind (first pair))) (getf e :pairs)))
           (ames.witness:witness-events answer)))

(defun event-point (event body)
  (second (assoc body (getf event :positions) :test #'string=)))

(test witness-loop-lift-off
  "A particle launched at v0 along the bottom of a loop (radius r) with 2 g r < v0^2 < 5 g r
leaves it where the normal force vanishes: at height (g r + v0^2) / (3 g), sin a =
(v0^2 - 2 g r) / (3 g r) above the centre, on the side it was launched toward (textbook;
Lsodar's lift-off to 1e-6)."
  (with-siconos
    (let* ((answer (witness-run "(scenario l \"\" (gravity 10)
                                   (body loop :fixed t :shape (arc :center (0 1) :radius 1 :from 0 :to (* 2 pi) :solid :outside))
                                   (body ball :mass 1 :position (0 0) :velocity (6 0) :shape point)
                                   (simulate :states 1))" 0.6d0))
           (event (first-event-with answer :lift-off))
           (sin-a (/ (- 36 20) 30d0)))
      (is (eq :curved (getf answer :scheme)))
      (is (near (/ (+ 10 36) 30d0) (second (event-point event "ball")) 1d-6))
      (is (near (sqrt (- 1 (* sin-a sin-a))) (first (event-point event "ball")) 1d-6)))))

(test witness-bowl-turning-points
  "A particle released at rest in a bowl (radius r) at theta0 from the bottom turns on the
other side after half the pendulum's period P = 4 sqrt(r/g) K(sin^2(theta0/2)), at the
mirror point, and back after P (textbook)."
  (with-siconos
    (let* ((answer (witness-run (scenario-file-text "particle-in-a-bowl") 2.5d0))
           (period (* 4 (sqrt (/ 1 10d0))
                      (ames.base:expression-value (list (find-symbol "ELLIPTIC-K" '#:ames.base)
                                                        (expt (sin 0.25d0) 2)))))
           (turns (remove-if-not (lambda (e) (eq :turns (first (first (getf e :pairs)))))
                                 (ames.witness:witness-events answer))))
      (is (= 2 (length turns)))
      (is (near (/ period 2) (getf (first turns) :time) 1d-8))
      (is (near period (getf (second turns) :time) 1d-8))
      (is (near (- (sin 0.5d0)) (first (event-point (first turns) "particle")) 1d-8)))))

(test witness-probe-turns-and-falls-back
  "A probe launched straight up from a planet (G M, radius r) below the escape speed turns at
s = 2 G M r / (2 G M - r v0^2) and hits the planet again at speed v0, twice the time
later (energy and time symmetry)."
  (with-siconos
    (let* ((answer (witness-run (scenario-file-text "probe-escape-speed") 1.3d0))
           (turn (first-event-with answer :turns))
           (hit (first-event-with answer :collision)))
      (is (near (/ (* 2 1000 10) (- (* 2 1000) (* 10 25))) (second (event-point turn "probe")) 1d-9))
      (is (near (* 2 (getf turn :time)) (getf hit :time) 1d-9))
      (is (near -5 (second (second (assoc "probe" (getf hit :velocities) :test #'string=))) 1d-9)))))

(test witness-spheres-fall-together
  "Two spheres (m1, m2, radii a, b) released at rest at distance d touch after
sqrt(d^3 / (2 G (m1 + m2))) (sqrt(x (1 - x)) + acos(sqrt x)), x = (a + b) / d (the
radial Kepler problem)."
  (with-siconos
    (let* ((answer (witness-run (scenario-file-text "spheres-under-gravitation") 3.5d0))
           (hit (first-event-with answer :collision))
           (x (/ 3/4 3d0)))
      (is (near (* (sqrt (/ 27 (* 2 3d0))) (+ (sqrt (* x (- 1 x))) (acos (sqrt x))))
                (getf hit :time) 1d-9)))))

(test witness-bumper
  "A block (m, speed v) meets a bumper (k) after d / v, presses it for half a period
pi sqrt(m/k), and leaves it with velocity +v (Hooke's law, textbook)."
  (with-siconos
    (let* ((answer (witness-run (scenario-file-text "block-into-bumper-on-floor") 5d0))
           (contact (first-event-with answer :contact))
           (leaves (first-event-with answer :leaves)))
      (is (near 3 (getf contact :time) 1d-12))
      (is (near (+ 3 (* pi (sqrt 1/4))) (getf leaves :time) 1d-10))
      (is (near 1 (first (second (assoc "block" (getf leaves :velocities) :test #'string=))) 1d-9)))))

(test witness-curved-scenarios-agree
  "AMES agrees with the witness on a loop (fast enough to loop forever: compared at
samples along the path) and a bumper (its contact, its release, the block sliding away)."
  (with-siconos
    (loop for (name index) in '(("ball-round-vertical-loop" 3)
                                ("block-hits-bumper" 0))
          do (let* ((*package* (find-package '#:ames-scenario))
                    (scenario (nth index (ames.scenario:read-scenarios-from-string (scenario-file-text name))))
                    (result (ames::witness-check scenario :numeric t)))
               (is (eq :agree (getf result :verdict))
                   "~A: ~(~A~) ~@[(~A)~]" (ames.scenario:scenario-name scenario)
                   (getf result :verdict) (getf result :reason))))))

(test witness-periodic-comparison-catches-a-wrong-period
  "The bowl's periodic state with its period off by 1e-4 relative is a disagreement."
  (with-siconos
    (let* ((text (scenario-file-text "particle-in-a-bowl"))
           (result (check-text text :numeric t))
           (answer (copy-tree (getf result :answer)))
           (values (ames.scenario:run-parameter-values (witness-scenario text) :numeric t))
           (numeric (getf (first (getf answer :states)) :numeric)))
      (is (eq :agree (getf result :verdict)))
      (setf (getf numeric :period) (* (getf numeric :period) (+ 1 1d-4)))
      (setf (getf (first (getf answer :states)) :numeric) numeric)
      (is (eq :ames-wrong
              (ames.witness:comparison-verdict
               (ames.witness:compare-results answer (getf result :witness) values
                                             :t-end (ames::witness-horizon (getf result :answer) values))))))))
