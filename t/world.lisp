;;;; t/world.lisp -- the world built once: the checks' shapes and contact pairs are the run's, and where contacts touch.

(in-package #:ames.tests)

(def-suite world :in all-tests
  :description "The world a scenario's checks build (src/scenario/world.lisp) is the one the
run uses; a state's contacts carry where the bodies touch and the normal there.")

(in-suite world)

(defun first-state-run (scenario bridge function)
  "Call FUNCTION with the RUN of SCENARIO's first state, made in the WORLD its checks
built, and that WORLD, under the scenario's assumptions."
  (let ((world (nth-value 1 (ames:check-scenario scenario bridge))))
    (call-with-scenario-facts
     bridge scenario
     (lambda ()
       (let ((run (ames.simulator::make-run world bridge)))
         ;; the contacts that hold, chosen by consistency as the state's analysis does
         (ames.simulator::settle-choices run)
         (funcall function run world))))))

(test the-run-uses-the-world-the-checks-built
  "CHECK-SCENARIO returns the scenario and its world: a shape for every body in order and
a contact pair for every two bodies not both fixed; the run's contacts of two bodies'
shapes are the very contacts of those pairs, in order (the geometry is not built again)."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "particle-on-wedge")))
      (first-state-run
       scenario bridge
       (lambda (run world)
         (let ((bodies (ames:scenario-bodies scenario)))
           (is (eq scenario (ames:world-scenario world)))
           (is (equal (mapcar #'ames:scenario-body-name bodies)
                      (mapcar #'car (ames:world-shapes world))))
           (is (= (loop for (body . later) on bodies
                        sum (count-if-not (lambda (other) (and (ames:scenario-body-fixed-p body)
                                                                (ames:scenario-body-fixed-p other)))
                                          later))
                  (length (ames:world-pairs world))))
           (let ((contacts (ames:world-simple-contacts world)))
             (is (plusp (length contacts)))
             (is (every #'eq contacts
                        (mapcar #'cdr (subseq (ames.simulator::run-contacts run)
                                              0 (length contacts))))))))))))

(defun touching-between (run body-1 body-2)
  "The plist (:POINT P :NORMAL N) of RUN's active contact between the bodies named BODY-1
and BODY-2 at the start of its state, and the contact's (OBSERVER OBSTACLE) names."
  (let ((contact (contact-between run body-1 body-2)))
    (values (and contact (ames.simulator::contact-touching run contact))
            (and contact (ames.simulator::contact-bodies run contact)))))

(test a-particle-touches-the-slope-where-it-is
  "A particle halfway down a wedge's slope touches it at its own position; the normal is
the slope's unit outward normal (sin a, cos a). The wedge's base touches the ground along
an edge (its middle is drawn), with the normal (0, 1) pointing up into the wedge."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "particle-on-wedge")))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (first-state-run
         scenario bridge
         (lambda (run world)
           (declare (ignore world))
           (multiple-value-bind (touch bodies) (touching-between run "PARTICLE" "WEDGE")
             (is (same-name-p* (first bodies) "PARTICLE"))
             (is-same-vector bridge "the particle's touching point" (getf touch :point)
                             (x '((/ h (* 2 (tan a))) (/ h 2))))
             (is-same-vector bridge "the slope's normal" (getf touch :normal)
                             (x '((sin a) (cos a)))))
           (let ((touch (touching-between run "WEDGE" "GROUND")))
             (is-same-vector bridge "the middle of the wedge's base" (getf touch :point)
                             (x '((/ h (* 2 (tan a))) 0)))
             (is-same-vector bridge "the ground's normal" (getf touch :normal) '(0 1)))))))))

(test a-disc-touches-the-slope-on-its-rim
  "A disc of radius r whose centre is r from a fixed 30 degree slope along its normal
touches the slope at the centre minus r times the normal: the point of the slope at
height h/2. The normal is the slope's, (1/2, sqrt(3)/2), from the slope into the disc."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "disc-at-30-degrees")))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (first-state-run
         scenario bridge
         (lambda (run world)
           (declare (ignore world))
           (multiple-value-bind (touch bodies) (touching-between run "DISC" "INCLINE")
             (is (same-name-p* (first bodies) "DISC") "the moving disc observes the fixed incline")
             (is-same-vector bridge "the disc's touching point" (getf touch :point)
                             (x '((- (* (sqrt 3) k) (/ (* (sqrt 3) h) 2)) (/ h 2))))
             (is-same-vector bridge "the slope's normal" (getf touch :normal)
                             '(1/2 (/ (sqrt 3) 2))))))))))
