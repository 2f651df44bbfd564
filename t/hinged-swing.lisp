;;;; t/hinged-swing.lisp -- turning points of a rotation (issue 23): a body on a hinge turns
;;;; back where its angular velocity changes sign (src/kb/turning.lisp), and a swing
;;;; between two turning points is periodic (src/simulator/turns.lisp); value queries at
;;;; (reaches QUANTITY VALUE) along the angle (src/simulator/reaches-at.lisp).
;;;;
;;;; The expected results are the textbook's physical pendulum: a uniform rod (m, l) on a
;;;; hinge at one end is a simple pendulum of length 2 l / 3, omega^2 = (3 g / l)(sin theta0
;;;; - sin theta). Closed forms are compared by Maxima-checked equivalence under the
;;;; scenario's assumptions; times and periods with the scenario's values against an
;;;; independent quadrature of that energy integral (ames.algebra:NUMERIC-TRAVEL-TIME) and
;;;; against the textbook's 4 sqrt(2 l / (3 g)) K(k^2). Helpers: t/simulator-scenarios.lisp,
;;;; t/friction.lisp, t/rotation-rolling.lisp.

(in-package #:ames.tests)

(def-suite hinged-swing :in all-tests
  :description "A body on a hinge turning back: (:turns B) and its periodic swing; value
queries at (reaches ...) along its angle.")

(in-suite hinged-swing)

(defun numeric-under (bridge expression values)
  "EXPRESSION's number under VALUES (an alist of the scenario's parameters)."
  (ames.maxima:numeric-value bridge expression values))

(defun near-p (a b &optional (tolerance 1d-8))
  "True when the reals A and B agree to TOLERANCE relative."
  (and (realp a) (realp b) (<= (abs (- a b)) (* tolerance (max 1d0 (abs b))))))

(test rod-released-horizontal-swings-periodically
  "A rod hinged at one end, released horizontal: one state along its angle that lasts
forever, periodic between the two horizontals (0 and -pi) with the period
4 sqrt(2 l / (3 g)) K(1/2), twice the quadrature of dtheta / sqrt(-(3 g / l) sin theta)
from 0 to -pi; at the bottom omega = -sqrt(3 g / l) and the hinge holds (5/2) m g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "rod-hinged-released-horizontal"))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (is (= 1 (length states)))
        (let* ((state (first states))
               (periodic (ames::state-periodic state)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (is (eq :forever (ames::state-duration state)))
            (is (not (null periodic)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "first turning point" (first (getf periodic :between)) 0)
               (is-same bridge "second turning point" (second (getf periodic :between)) (x '(- pi)))
               (is-same bridge "omega at the bottom"
                        (second (assoc "OMEGA-AT-BOTTOM" (ames::history-answers history) :test #'same-name-p*))
                        (x '(- (sqrt (/ (* 3 g) l)))))
               (is-same bridge "the hinge's pull at the bottom"
                        (second (assoc "HINGE-AT-BOTTOM" (ames::history-answers history) :test #'same-name-p*))
                        (x '(* 5/2 m g)))))
            (let ((period (numeric-under bridge (getf periodic :period) values))
                  (textbook (numeric-under bridge (x '(* 4 (sqrt (/ (* 2 l) (* 3 g))) (elliptic-k 1/2))) values))
                  (quadrature (* 2 (ames.algebra:numeric-travel-time
                                    bridge (x '(- (/ (* 3 g (sin tau)) l))) 'tau 0 (x '(- pi)) values))))
              (is (near-p period textbook) "period ~A, textbook ~A" period textbook)
              (is (near-p period quadrature) "period ~A, quadrature ~A" period quadrature))))))))

(defun pushed-rod (omega)
  "The scenario text of a uniform rod hanging at rest from a hinge at its top end, set
turning counter-clockwise at OMEGA (a string, an expression of g and l), its centre
then moving at OMEGA l / 2."
  (format nil "(scenario rod-hanging-pushed
     \"A uniform rod hanging from a hinge at its top end, set turning.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1)))
     (gravity g)
     (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position (0 (- (/ l 2))) :velocity ((/ (* ~A l) 2) 0)
               :angle (- (/ pi 2)) :angular-velocity ~A)
     (hinge pin :body rod :at ((- (/ l 2)) 0))
     (query highest (value (angle rod) :at (:turns rod)))
     (query half-way (value (angular-velocity rod) :at (reaches (angle rod) (- (asin 5/6)))))
     (simulate :states 3))" omega omega))

(defparameter *pushed-rod* (pushed-rod "(sqrt (/ g l))")
  "A rod hanging at rest on its hinge, set turning counter-clockwise at sqrt(g / l): it
rises to sin theta = -2/3 (omega^2 = (g / l)(-2 - 3 sin theta)), turns there and swings
for good between that angle and its mirror image -pi + asin(2/3).")

(test hinged-rod-turns-back
  "The rod set turning: (:turns rod) at theta = -asin(2/3) with omega = 0, after the
quadrature's time (the textbook's sqrt(2 l / (3 g)) K(1/6), a quarter period); then a
state at rest there that swings forever between -asin(2/3) and asin(2/3) - pi with the
period 4 sqrt(2 l / (3 g)) K(1/6). The angular velocity where sin theta = -5/6 is
sqrt(g / (2 l)) on the way up."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *pushed-rod*)))
           (values (ames.scenario:run-parameter-values scenario :numeric t)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (is (= 2 (length states)))
        (when (= 2 (length states))
          (destructuring-bind (up swing) states
            (flet ((x (form) (in-scenario-terms scenario form)))
              (is (equal '("TURNS" "ROD") (names-of (ames::state-end-event up))))
              (is (eq :forever (ames::state-duration swing)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "the angle where it turns"
                          (rotation-entry (ames.simulator:state-final-angles up) "ROD") (x '(- (asin 2/3))))
                 (is-same bridge "at rest there"
                          (rotation-entry (ames.simulator:state-final-angular-velocities up) "ROD") 0)
                 (is-same bridge "the swing's far turning point"
                          (second (getf (ames::state-periodic swing) :between)) (x '(- (asin 2/3) pi)))
                 (is-same bridge "query: the angle at the turn"
                          (second (assoc "HIGHEST" (ames::history-answers history) :test #'same-name-p*))
                          (x '(- (asin 2/3))))
                 (is-same bridge "query: omega half way up"
                          (second (assoc "HALF-WAY" (ames::history-answers history) :test #'same-name-p*))
                          (x '(sqrt (/ g (* 2 l)))))))
              (let ((duration (numeric-under bridge (ames::state-duration up) values))
                    (quadrature (ames.algebra:numeric-travel-time
                                 bridge (x '(- (/ (* g (+ 2 (* 3 (sin tau)))) l))) 'tau
                                 (x '(- (/ pi 2))) (x '(- (asin 2/3))) values))
                    (period (numeric-under bridge (getf (ames::state-periodic swing) :period) values))
                    (textbook (numeric-under bridge (x '(* 4 (sqrt (/ (* 2 l) (* 3 g))) (elliptic-k 1/6))) values)))
                (is (near-p duration quadrature) "time to the turn ~A, quadrature ~A" duration quadrature)
                (is (near-p period textbook) "period ~A, textbook ~A" period textbook)))))))))

(test hinged-rod-sent-to-its-top-creeps-there-forever
  "A hanging rod set turning at sqrt(6 g / l) has just the energy to reach the top:
omega^2 = (3 g / l)(1 - sin theta) has a double zero at pi/2, which it approaches in no
finite time. No turning point ends the state: it lasts forever, with no period."
  (with-fixture simulator-bridge ()
    (let ((scenario (first (ames:read-scenarios-from-string (pushed-rod "(sqrt (/ (* 6 g) l))")))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (= 1 (length states)))
        (let ((state (first states)))
          (is (eq :forever (ames::state-duration state)))
          (is (null (ames::state-periodic state)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "omega^2 over the angle"
                      (expt-2 (rotation-entry (ames.simulator:state-angular-velocities state) "ROD"))
                      (substitute-expressions
                       (list (cons (in-scenario-terms scenario 'tau) 'ames.simulator::arc-length))
                       (in-scenario-terms scenario '(* (/ (* 3 g) l) (- 1 (sin tau)))))))))
        (is (eq :complete (ames::history-outcome history)))))))
