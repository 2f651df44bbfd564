;;;; t/rotation-corners.lisp -- rotating polygons and segments on fixed faces by their corners
;;;; (src/kb/corners.lisp, src/simulator/corners.lisp, src/simulator/rotation-path.lisp):
;;;; the ladder sliding on its wall and floor until it leaves the wall.
;;;;
;;;; The expected results are the textbook's (the scenario file's header), over the
;;;; scenario's own parameters, compared by Maxima-checked equivalence under its
;;;; assumptions; then with its (:value N) defaults, the printed duration against an
;;;; independent quadrature of the textbook's energy integral. Helpers: those of
;;;; t/simulator-scenarios.lisp, t/friction.lisp and t/rotation-rolling.lisp.

(in-package #:ames.tests)

(def-suite rotation-corners :in all-tests
  :description "Rotating polygons and segments touching fixed faces with their corners: the
ladder leaving its wall.")

(in-suite rotation-corners)

(defun expt-2 (x) "X squared, as an expression." `(expt ,x 2))

(test ladder-leaves-the-wall-at-two-thirds-of-its-height
  "A uniform ladder on a frictionless floor and wall, from rest at angle a to the floor:
one state along its angle (theta = pi - phi) with phi'^2 = 3 g (sin a - sin phi) / l, the
wall's push (3/4) m g (2 sin a - 3 sin phi) cos phi reaching zero at sin phi = (2/3) sin a:
(:lift-off ladder wall) with the top at (2/3) l sin a, the centre at l sin a / 3, turning
at sqrt(g sin a / l) clockwise."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "ladder-against-wall")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (is (= 1 (length states)))
        (let ((state (first states)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (is (equal '("LIFT-OFF" "LADDER" "WALL") (names-of (ames::state-end-event state))))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "angle at the end"
                        (rotation-entry (ames.simulator:state-final-angles state) "LADDER")
                        (x '(- pi (asin (* 2/3 (sin a))))))
               (is-same bridge "angular velocity at the end: omega^2 = g sin a / l"
                        (expt-2 (rotation-entry (ames.simulator:state-final-angular-velocities state) "LADDER"))
                        (x '(/ (* g (sin a)) l)))
               (is (eq :true (ames.algebra:decide
                              bridge `(> ,(rotation-entry (ames.simulator:state-final-angular-velocities state)
                                                          "LADDER")
                                         0)))
                   "theta = pi - phi grows as the ladder falls")
               (is-same-vector bridge "centre at the end" (per-body (ames::state-final-positions state) "LADDER")
                               (list (x '(* 1/6 l (sqrt (+ 5 (* 4 (expt (cos a) 2))))))
                                     (x '(* 1/3 l (sin a)))))
               ;; the wall's push over the state, at the start: (3/4) m g sin a cos a
               (let ((wall (normal-force-between state "LADDER" "WALL")))
                 (is (not (null wall)))
                 (is-same bridge "the wall's push at the start"
                          (substitute-expressions (list (cons 'ames.simulator::arc-length (x '(- pi a)))) wall)
                          (x '(* 3/4 m g (sin a) (cos a)))))
               (is-same bridge "query: the centre's height when it leaves the wall"
                        (second (assoc "LEAVES-WALL-AT" (ames::history-answers history) :test #'same-name-p*))
                        (x '(* 1/3 l (sin a))))))))))))

(test ladder-leaves-the-wall-with-values
  "With the scenario's values the printed duration is the travel time of the textbook's
phi'^2 = 3 g (sin a - sin phi) / l from phi = a down to asin((2/3) sin a)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "ladder-against-wall"))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (declare (ignore history))
        (let* ((point (mapcar (lambda (e) (cons (intern (symbol-name (car e)) '#:ames.tests) (cdr e))) values))
               (expected (ames.algebra:numeric-travel-time
                          bridge '(/ (* 3 g (- (sin a) (sin phi))) l) 'phi
                          'a '(asin (* 2/3 (sin a))) point))
               (printed (getf (ames.simulator:state-numbers (first states)) :duration)))
          (is (realp printed))
          (is (and (realp printed) (< (abs (- printed expected)) 1d-8))
              "duration ~A, expected ~A" printed expected))))))

(test ladder-stays-up-on-a-rough-floor
  "Against a smooth wall on a floor rough enough (mu > 1/(2 tan a)) the ladder stays at
rest forever: the floor's push m g, the wall's m g / (2 tan a), static friction at the foot
m g / (2 tan a) toward the wall."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "ladder-on-rough-floor")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (let ((state (first states)))
          (is (eq :forever (ames::state-duration state)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "the floor's push" (normal-force-between state "LADDER" "FLOOR") (x '(* m g)))
               (is-same bridge "the wall's push" (normal-force-between state "LADDER" "WALL")
                        (x '(/ (* m g) (* 2 (tan a)))))
               (check-friction bridge state "LADDER" "FLOOR" :static (x '(/ (* m g) (* 2 (tan a)))))
               (is-same-vector bridge "at rest" (per-body (ames::state-velocities state) "LADDER") (quote (0 0)))
               (is-same bridge "not turning"
                        (rotation-entry (ames.simulator:state-angular-velocities state) "LADDER") 0)))))))))
