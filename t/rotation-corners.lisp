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

(defparameter *block-beside-a-ledge*
  "(scenario block-beside-a-ledge \"A spinning block above and to the right of a ledge.\"
     (gravity 10)
     (body ledge :fixed t :shape (polygon (-3 -1) (0 -1) (0 0) (-3 0)))
     (body block :mass 1 :inertia :uniform
                 :shape (polygon (-1/2 -1/2) (1/2 -1/2) (1/2 1/2) (-1/2 1/2))
                 :position (2 3) :angle 0 :velocity (-1 0) :angular-velocity 5)
     (simulate :states 1))"
  "A square block, spinning, whose right and top faces have the ledge's edge (0, 0)
behind their lines at the start.")

(test a-fixed-corner-is-described-on-every-face-of-a-rotating-body
  "The ledge's edge (0, 0) is a :FACE-ON-VERTEX contact with each of the spinning block's
four faces, the two whose lines it is behind at the start (gap -5/2 and -7/2) too: the
block turns those faces round to it (witness/disagreements/ames-wrong-block-step-2027-650.lisp,
where the far face struck the edge and AMES flew through the ledge). The block's own
corners are still described only on the ledge's faces they are in front of."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *block-beside-a-ledge*)))
           (run (ames.simulator::make-run (nth-value 1 (ames.scenario::check-scenario scenario bridge)) bridge))
           (geometries (mapcar #'cdddr (ames.simulator::run-corner-contacts run)))
           (on-faces (remove-if-not (lambda (g)
                                      (and (eq :face-on-vertex (ames.geometry:rotating-contact-kind g))
                                           (equal '(0 0) (ames.geometry:rotating-contact-point g))))
                                    geometries))
           (start-gaps (mapcar (lambda (g)
                                 (ames.maxima:simplify
                                  bridge (ames.simulator::at-scenario-start
                                          (find-if (lambda (b) (string-equal "BLOCK" (symbol-name (ames.scenario:scenario-body-name b))))
                                                   (ames.scenario:scenario-bodies scenario))
                                          (ames.geometry:rotating-contact-gap g))
                                  :strategy :full))
                               on-faces)))
      (is (= 4 (length on-faces)) "~S" start-gaps)
      (is (= 2 (count-if (lambda (gap) (and (realp gap) (minusp gap))) start-gaps)) "~S" start-gaps)
      (is (null (set-difference '(-5/2 -7/2) start-gaps)) "~S" start-gaps)
      ;; a corner of the block on a face of the ledge: only where it is in front of it
      (is (every (lambda (g)
                   (let ((gap (ames.maxima:simplify
                               bridge (ames.simulator::at-scenario-start
                                       (find-if (lambda (b) (string-equal "BLOCK" (symbol-name (ames.scenario:scenario-body-name b))))
                                                (ames.scenario:scenario-bodies scenario))
                                       (ames.geometry:rotating-contact-gap g))
                               :strategy :full)))
                     (and (realp gap) (>= gap 0))))
                 (remove :face-on-vertex geometries :key #'ames.geometry:rotating-contact-kind))))))
