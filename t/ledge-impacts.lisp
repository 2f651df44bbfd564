;;;; t/ledge-impacts.lisp -- a corner touches a face only within the face (issue 23,
;;;; src/geometry/fixed-corners.lisp, src/kb/corners.lisp, src/simulator/guarded-meetings.lisp):
;;;; a rod landing across a ledge's edge is struck by the ledge's corner (a fixed corner on
;;;; the rotating body's face), its far end past the ledge's edge touches nothing, a rod
;;;; falling beside a ledge passes its top's line, and a rod pivoting on the ledge's edge
;;;; slides off it. The expected results are the textbook's, compared by Maxima equivalence
;;;; under the scenario's assumptions. Helpers: t/simulator-scenarios.lisp,
;;;; t/rotating-impacts.lisp (FIRST-IMPACT, IMPACT-ENTRY, IS-ENERGY-NOT-GAINED).

(in-package #:ames.tests)

(def-suite ledge-impacts :in all-tests
  :description "Corners within the faces' ends; a fixed corner striking a rotating body's
face: the rod across a ledge.")

(in-suite ledge-impacts)

(defun ledge-rod-expected (scenario)
  "The textbook's impact of the rod across the ledge (scenarios/rod-lands-across-a-ledge.lisp)
over SCENARIO's parameters: a plist :V (speed before) :J (the edge's impulse) :VY (the
centre's vertical velocity after) :OMEGA (after) :LOST (the kinetic energy lost)."
  (flet ((x (form) (in-scenario-terms scenario form)))
    (let* ((v (x '(sqrt (* 2 g h))))
           (a (x '(- (/ l 2) d)))
           (inertia (x '(/ (* m l l) 12)))
           (j `(/ (* ,(x 'm) ,v) (+ 1 (/ (* ,(x 'm) ,a ,a) ,inertia)))))
      (list :v v :j j
            :vy `(- (/ ,j ,(x 'm)) ,v)
            :omega `(- (/ (* ,j ,a) ,inertia))
            :lost `(- (* 1/2 ,(x 'm) ,v ,v)
                      (+ (* 1/2 ,(x 'm) (expt (- (/ ,j ,(x 'm)) ,v) 2))
                         (* 1/2 ,inertia (expt (/ (* ,j ,a) ,inertia) 2))))))))

(test rod-lands-across-a-ledge
  "A rod falling flat across a ledge's edge: only the edge pushes, J = m v / (1 + m a^2 / I)
with the arm a = l/2 - d; v' = J/m - v, omega' = -J a / I (clockwise); the energy lost
m g h l^2 / (l^2 + 12 a^2); one contact pushes (the ledge's corner), not the rod's far
end on the line of the ledge's top past its edge."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "rod-lands-across-a-ledge"))
           (impact (first-impact scenario bridge))
           (expected (ledge-rod-expected scenario)))
      (is (not (null impact)))
      (when impact
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same-vector bridge "velocity after" (impact-entry impact :velocities-after "ROD")
                           (list 0 (getf expected :vy)))
           (is-same bridge "angular velocity after"
                    (impact-entry impact :angular-velocities-after "ROD") (getf expected :omega))
           (let ((impulses (remove :impulse (getf impact :impulses) :key #'first :test-not #'eq)))
             (is (= 1 (length impulses)) "one impulse: ~S" impulses)
             (is-same bridge "the edge's impulse" (car (last (first impulses))) (getf expected :j)))
           (is-same bridge "energy lost" (getf impact :energy-lost) (getf expected :lost))
           ;; never gained: m g h l^2 / (l^2 + 3 (l - 2 d)^2), a ratio of positive terms
           (is-same bridge "energy lost, written positive" (getf impact :energy-lost)
                    (in-scenario-terms scenario '(/ (* m g h l l) (+ (* l l) (* 3 (expt (- l (* 2 d)) 2))))))
           ;; the pushing contact: the ledge's corner (a vertex of the ledge) on the rod's edge
           (is (equal '((:vertex 2)) (mapcar (lambda (c) (getf (cddr c) :feature))
                                             (getf impact :contacts)))
               "contacts ~S" (getf impact :contacts))))))))

(test rod-lands-across-a-ledge-with-values
  "The issue's figures: l = 2, d = 1/10, h = 1/5, g = 10, m = 1 give J = 200/343 (0.583),
v' = -486/343 (1.417 down), omega' = -540/343 (1.574 clockwise)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "rod-lands-across-a-ledge"))
           (values (ames.scenario:run-parameter-values scenario :numeric t))
           (impact (first-impact scenario bridge)))
      (is (not (null impact)))
      (when impact
        (flet ((at-values (expression) (ames.maxima:numeric-value bridge expression values)))
          (is (< (abs (- (at-values (second (impact-entry impact :velocities-after "ROD"))) -486/343)) 1d-9))
          (is (< (abs (- (at-values (impact-entry impact :angular-velocities-after "ROD")) -540/343)) 1d-9))
          (is (< (abs (- (at-values (car (last (first (getf impact :impulses))))) 200/343)) 1d-9)))))))

(defparameter *rod-beside-a-ledge*
  "(scenario rod-beside-a-ledge \"A rod falls flat beside a ledge onto the floor below it.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (h :positive (:value 1/5)))
     (gravity g)
     (body ledge :fixed t :shape (polygon (-3 0) (0 0) (0 1) (-3 1)))
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body rod :mass m :inertia :uniform :shape (segment (-1 0) (1 0))
               :position (3/2 (+ 1 h)) :velocity (0 0))
     (simulate :states 1))"
  "A rod (length 2) lying flat right of a ledge whose top is at y = 1 and ends at x = 0;
its ends (x = 1/2 and 5/2) reach the line of the ledge's top past its edge.")

(test rod-falls-past-a-ledges-line
  "A corner reaching a face's line beyond the face's end is no collision: the rod beside
the ledge falls through the line of the ledge's top and lands on the floor, after
sqrt(2 (h + 1) / g), at sqrt(2 g (h + 1))."
  (with-fixture simulator-bridge ()
    (let ((scenario (first (ames:read-scenarios-from-string *rod-beside-a-ledge*))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (declare (ignore history))
        (is (= 1 (length states)))
        (when states
          (let ((state (first states)))
            (is (equal "FLOOR" (symbol-name (third (ames::state-end-event state))))
                "the end event ~S" (ames::state-end-event state))
            (flet ((x (form) (in-scenario-terms scenario form)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "duration" (ames::state-duration state) (x '(sqrt (/ (* 2 (+ h 1)) g))))
                 (is-same-vector bridge "velocity at the floor"
                                 (per-body (ames::state-final-velocities state) "ROD")
                                 (x '(0 (- (sqrt (* 2 g (+ h 1))))))))))))))))

(test ledge-contacts-know-their-faces-ends
  "The geometry's contacts of a rod over a ledge: a fixed corner on the rod's face is a
:FACE-ON-VERTEX contact whose gap is the corner's height under the rod and whose place is
along the rod from its left end; a rod's end past the ledge's edge has its place outside
the ledge's top."
  (with-fixture simulator-bridge ()
    (let* ((ledge (ames.geometry:parse-shape '(polygon (-3 -1) (0 -1) (0 0) (-3 0)) :bridge bridge))
           (rod (ames.geometry:parse-shape '(segment (-1 0) (1 0)) :bridge bridge))
           (configuration (ames.geometry:make-configuration 'x 'y 0))
           (contacts (ames.geometry:rotating-body-contacts bridge rod configuration ledge))
           (edge (find-if (lambda (c) (and (eq (ames.geometry:rotating-contact-kind c) :face-on-vertex)
                                           (equal (ames.geometry:rotating-contact-other-feature c) '(:vertex 2))))
                          contacts))
           (far-end (find-if (lambda (c) (and (eq (ames.geometry:rotating-contact-kind c) :vertex-on-face)
                                              (equal (ames.geometry:rotating-contact-feature c) '(:vertex 1))
                                              (equal (ames.geometry:rotating-contact-other-feature c) '(:edge 2))))
                             contacts)))
      (is (= 12 (length contacts)) "two corners on four faces, four corners on one face: ~D"
          (length contacts))
      (is (not (null edge)))
      (is (not (null far-end)))
      (when (and edge far-end)
        (is-same bridge "the edge's gap" (ames.geometry:rotating-contact-gap edge) 'y)
        (is-same bridge "the edge's place" (ames.geometry:rotating-contact-place edge) '(- 1 x))
        (is-same-vector bridge "the edge's arm" (ames.geometry:rotating-contact-arm edge) '((- x) (- y)))
        (is-same-vector bridge "the edge pushes up" (ames.geometry:rotating-contact-normal edge) '(0 1))
        (let ((relations (ames.geometry:contact-extent-relations far-end)))
          (is (= 2 (length relations)))
          ;; the far end at x = 1.9 (the rod's centre at 0.9) is past the ledge's edge
          (is (eq :false (ames.algebra:decide
                          bridge (ames.base:substitute-expressions '((x . 9/10) (y . 0)) (first relations))))))))))

(test rod-slides-off-a-ledges-edge
  "After the impact the rod pivots and slides on the ledge's smooth edge (no closed form:
integrated under the scenario's values) until the edge reaches the rod's left end, where
the contact ends past its end: the rod's left end is then at the edge, (x, y) - (l/2)
(cos theta, sin theta) = (0, 0), and the smooth edge has done no work (K + U as just after
the impact)."
  (with-fixture simulator-bridge ()
    (let* ((form (let ((form (copy-tree (ames:scenario-form (scenario-named "rod-lands-across-a-ledge")))))
                   (setf (cdr (assoc 'ames-scenario::simulate (cdddr form))) '(:states 2))
                   form))
           (scenario (ames:parse-scenario form))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge :parameter-values values)
        (declare (ignore history))
        (is (= 2 (length states)))
        (when (= 2 (length states))
          (let* ((state (second states))
                 (event (ames::state-end-event state))
                 (number (lambda (x) (ames.maxima:numeric-value bridge x values)))
                 (position (mapcar number (per-body (ames::state-final-positions state) "ROD")))
                 (velocity (mapcar number (per-body (ames::state-final-velocities state) "ROD")))
                 (theta (funcall number (per-body (ames::state-final-angles state) "ROD")))
                 (omega (funcall number (per-body (ames::state-final-angular-velocities state) "ROD")))
                 (start (mapcar number (per-body (ames::state-initial-velocities state) "ROD")))
                 (omega0 (funcall number (impact-entry (ames::state-impact (first states)) :angular-velocities-after "ROD"))))
            (is (and (eq :leaves (first event)) (member :endpoint event)) "the end event ~S" event)
            ;; l = 2: the left end at the edge
            (is (< (abs (- (first position) (cos theta))) 1d-6) "x ~S theta ~S" (first position) theta)
            (is (< (abs (- (second position) (sin theta))) 1d-6) "y ~S theta ~S" (second position) theta)
            ;; energy: m = 1, g = 10, I = 1/3; just after the impact the centre is at y = 0
            (flet ((energy (v w y) (+ (* 1/2 (+ (expt (first v) 2) (expt (second v) 2)))
                                      (* 1/2 1/3 w w) (* 10 y))))
              (is (< (abs (- (energy velocity omega (second position)) (energy start omega0 0))) 1d-6)))
            ;; exactly at the values (l = 2), not within 1e-6: the corner put back on the face puts the left end
            ;; at the edge, (x, y) = (l/2)(cos theta, sin theta) for the integrated theta,
            ;; and the rod's point at the edge has no velocity across the rod,
            ;; (v + omega k x r) . n = 0 with r = -(l/2)(cos, sin) and n = (-sin, cos)
            (destructuring-bind (x y) (per-body (ames::state-final-positions state) "ROD")
              (destructuring-bind (vx vy) (per-body (ames::state-final-velocities state) "ROD")
                (let ((theta (per-body (ames::state-final-angles state) "ROD"))
                      (omega (per-body (ames::state-final-angular-velocities state) "ROD"))
                      ;; at the values: a numeric end is written as numbers (numeric-ends.lisp)
                      (l (cdr (assoc (in-scenario-terms scenario 'l) values))))
                  (is-same bridge "the rod's left end at the edge, x" x `(* (/ ,l 2) (cos ,theta)))
                  (is-same bridge "the rod's left end at the edge, y" y `(* (/ ,l 2) (sin ,theta)))
                  (is-same bridge "no velocity into the edge"
                           `(+ (* (- (sin ,theta)) (+ ,vx (* ,omega (/ ,l 2) (sin ,theta))))
                               (* (cos ,theta) (- ,vy (* ,omega (/ ,l 2) (cos ,theta)))))
                           0))))))))))
