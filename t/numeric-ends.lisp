;;;; t/numeric-ends.lisp -- a state's end found with numbers is written as numbers
;;;; (src/simulator/numeric-ends.lisp): the rod tipping over on smooth ice, integrated
;;;; numerically at l = 1, lands flat with its end values, impulses and energy lost as
;;;; numbers (not the integration's rationals times l and m), equal to the integration's
;;;; values and to the textbook's landing speed, omega^2 = 3 g cos(b) / l.

(in-package #:ames.tests)

(def-suite numeric-ends :in all-tests
  :description "A state's end found with numbers, and the impact after it, written as numbers.")

(in-suite numeric-ends)

(defparameter *rod-tipping-on-ice*
  "(scenario rod-tips-over-on-ice \"A uniform rod standing tilted on a frictionless floor falls flat.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
                 (b (> b 0) (< b (/ pi 2)) (:value (deg 30))))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
           :position ((* (/ l 2) (sin b)) (* (/ l 2) (cos b))) :angle (- (/ pi 2) b) :velocity (0 0))
     (simulate :states 1))"
  "The rod of Kleppner and Kolenkow's problem: released from rest at b = 30 degrees from the
vertical on smooth ice, it has no closed form in time and is integrated under values.")

(defun integrated-end (state head)
  "The value of the term (HEAD ROD ...) (HEAD's name, e.g. \"ANGVEL\") at the end of
STATE's numeric integration: its last sample."
  (let* ((trajectory (first (ames::state-numeric-trajectory state)))
         (terms (getf trajectory :terms))
         (last-sample (car (last (getf trajectory :samples))))
         (at (position-if (lambda (term) (and (consp term) (string= (symbol-name (first term)) head)
                                              (or (null (cddr term)) (eq (third term) :y))))
                          terms)))
    (and at (nth at (cdr last-sample)))))

(test numeric-end-and-impact-are-numbers
  "After the numerically integrated fall, the rod's end position, velocity, angle and
angular velocity, and the impact's impulses, energy lost and velocities after, are numbers
(no parameter in them); the angular velocity and the centre's vertical velocity are the
integration's (to 1e-9), the centre's velocity is -(l/2) omega there (the lower end on the
floor), omega^2 is 3 g cos(b) / l (energy: the textbook's landing), and the impulses and
energy lost balance the momentum and kinetic energy exactly."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *rod-tipping-on-ice*)))
           (history (ames:run-scenario scenario :bridge bridge :numeric t))
           (state (first (ames::history-states history)))
           (impact (ames::state-impact state)))
      (is (not (null (ames::state-numeric-trajectory state))) "integrated numerically")
      (let ((position (per-body (ames::state-final-positions state) "ROD"))
            (velocity (per-body (ames::state-final-velocities state) "ROD"))
            (theta (per-body (ames::state-final-angles state) "ROD"))
            (omega (per-body (ames::state-final-angular-velocities state) "ROD")))
        (is (every #'rationalp position) "position ~S" position)
        (is (every #'rationalp velocity) "velocity ~S" velocity)
        (is (rationalp theta) "angle ~S" theta)
        (is (rationalp omega) "angular velocity ~S" omega)
        (when (and (every #'rationalp velocity) (rationalp omega))
          (is (< (abs (- omega (integrated-end state "ANGVEL"))) 1d-9))
          (is (< (abs (- (second velocity) (integrated-end state "VEL"))) 1d-9))
          ;; the lower end on the floor at theta = 0: v_y = -(l/2) |omega| at l = 1
          (is (= (second velocity) (* 1/2 omega)))
          (is (< (abs (- (* omega omega) (* 3 981/100 (cos (/ pi 6))))) 1d-6)
              "omega^2 = ~F, 3 g cos b / l = ~F" (* omega omega) (* 3 981/100 (cos (/ pi 6))))
          (is (not (null impact)) "an impact ends the fall")
          (when impact
            (let ((impulses (mapcar (lambda (entry) (car (last entry))) (getf impact :impulses)))
                  (after (per-body (getf impact :velocities-after) "ROD"))
                  (omega-after (per-body (getf impact :angular-velocities-after) "ROD"))
                  (lost (getf impact :energy-lost)))
              (is (and impulses (every #'rationalp impulses)) "impulses ~S" impulses)
              (is (rationalp lost) "energy lost ~S" lost)
              (is (and (every #'rationalp after) (rationalp omega-after)) "after ~S ~S" after omega-after)
              (when (and impulses (every #'rationalp impulses) (every #'rationalp after)
                         (rationalp omega-after) (rationalp lost))
                ;; m = 1, l = 1: impulse = m dv_y; energy lost = K before - K after
                (is (= (reduce #'+ impulses) (- (second after) (second velocity))))
                (flet ((kinetic (v w) (+ (* 1/2 (+ (expt (first v) 2) (expt (second v) 2))) (* 1/24 w w))))
                  (is (= lost (- (kinetic velocity omega) (kinetic after omega-after))))))))))
      (is (null (getf (ames.check:self-check-result history) :failures))))))

(test valued-expressions-only-under-values
  "VALUED-EXPRESSION puts a run's values in (l = 1: 225770929 l / 89441190 is the
rational), leaves a run without values and an expression of the motion as they are."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      '(scenario s "x" (parameters (l :positive) (m :positive)) (gravity 1)
                        (body c :mass m :shape (circle l) :position (0 0) :velocity (0 0)))))
           (l (ames:scenario-parameter-name (ames:find-scenario-parameter 'l scenario)))
           (m (ames:scenario-parameter-name (ames:find-scenario-parameter 'm scenario))))
      (flet ((run-with (values)
               (make-instance 'ames.simulator::run :bridge bridge :values values :scenario scenario)))
        (let ((with (run-with (list (cons l 1) (cons m 2)))) (without (run-with '()))
              (mixed `(* -225770929/89441190 ,l ,m))
              (motion `(* ,l (ames.kb:vel c :x))))
          (is (eql -225770929/44720595 (ames.simulator::valued-expression with mixed)))
          (is (equal mixed (ames.simulator::valued-expression without mixed)))
          (is (equal motion (ames.simulator::valued-expression with motion))))))))
