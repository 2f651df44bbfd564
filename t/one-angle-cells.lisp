;;;; t/one-angle-cells.lisp -- relations in one angle decided under facts in that angle, and
;;;; a fork's boundary at an angle (src/algebra/one-angle-cells.lisp, branching.lisp).
;;;;
;;;; A particle on an incline of static friction 1/2 (scenarios/particle-on-incline-of-
;;;; friction-one-half.lisp) slides when tan a > 1/2. The run forks on 2 sin a - cos a; in
;;;; its sliding branch the questions it asks next are relations in a alone, such as
;;;; (sin a + 4 cos a) cos a - 4 < 0, which is sin a (cos a - 4 sin a) < 0: true where
;;;; tan a > 1/4. The verdicts are checked against the relations' values at angles of
;;;; the branch, and the boundary's angle against Maxima's tan.

(in-package #:ames.tests)

(def-suite one-angle-cells :in all-tests
  :description "Relations in one angle decided exactly under facts in that angle; a fork's
boundary found at an angle.")

(in-suite one-angle-cells)

(defparameter *steeper-than-one-half*
  '((> a 0) (< a (/ pi 2)) (> (- (* 2 (sin a)) (cos a)) 0))
  "The sliding branch's facts: 0 < a < pi/2 and tan a > 1/2.")

(defun relation-at-angle (relation angle)
  "RELATION (in sin, cos and tan of A) evaluated in floating point at A = ANGLE."
  (let* ((values (list (cons '(sin a) (sin angle)) (cons '(cos a) (cos angle))
                       (cons '(tan a) (tan angle))))
         (difference (labels ((walk (x)
                                (cond ((assoc x values :test #'equal) (cdr (assoc x values :test #'equal)))
                                      ((numberp x) x)
                                      (t (apply (ecase (first x) (+ #'+) (- #'-) (* #'*) (/ #'/) (expt #'expt))
                                                (mapcar #'walk (rest x)))))))
                       (walk `(- ,(second relation) ,(third relation))))))
    (ecase (first relation)
      (> (> difference 0)) (< (< difference 0)) (>= (>= difference 0)) (<= (<= difference 0)))))

(test relations-in-one-angle-under-the-branchs-fact
  "Under tan a > 1/2 (0 < a < pi/2): the sliding branch's two questions are true, sin a >
cos a / 3 and sin a > cos a / 2 are true, tan a < 1/3 is false, and sin a > 3 cos a / 4
(tan a > 3/4) is not decided. Each verdict agrees with the relation's value at angles of
the branch (atan(1/2) = 0.4636 < a < pi/2); the undecided one holds at one and fails at
another."
  (call-with-bridge
   (lambda (b)
     (let ((angles (list 0.47d0 0.6d0 0.9d0 1.2d0 1.5d0)))
       (loop for (relation expected) in
             '(((< (- (* (+ (sin a) (* 4 (cos a))) (cos a)) 4) 0) :true)
               ((> (+ (expt (sin a) 2) (* 4 (sin a) (cos a)) -1) 0) :true)
               ((> (- (sin a) (* 1/3 (cos a))) 0) :true)
               ((> (- (sin a) (* 1/2 (cos a))) 0) :true)
               ((< (tan a) 1/3) :false)
               ((> (- (sin a) (* 3/4 (cos a))) 0) :unknown))
             do (is (eq expected (decided b *steeper-than-one-half* relation))
                    "~S: expected ~S" relation expected)
                (let ((truths (mapcar (lambda (angle) (relation-at-angle relation angle)) angles)))
                  (ecase expected
                    (:true (is (every #'identity truths)))
                    (:false (is (notany #'identity truths)))
                    (:unknown (is (and (some #'identity truths) (notevery #'identity truths)))))))))))

(test relations-in-one-obtuse-angle
  "With pi/2 < a < pi (cos a < 0): sin a + cos a < 1 holds (it is sqrt 2 sin(a + pi/4),
below 1 there) and tan a > -1 is not decided (it holds only beyond 3 pi/4)."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> a (/ pi 2)) (< a pi))))
       (is (eq :true (decided b facts '(< (+ (sin a) (cos a)) 1))))
       (is (eq :unknown (decided b facts '(> (tan a) -1))))))))

(test a-boundary-angle-is-the-one-root-in-its-range
  "2 sin a - cos a = 0 in 0 < a < pi/2 at a = atan(1/2); sin a + 2 cos a = 2 at atan(4/3)
(a = 0 is outside the range); 3 sin a = 1 at the angle whose sine is 1/3; cos a = -1/2 in
0 < a < pi at 2 pi / 3. Each root is checked by Maxima (the relation's sides equal at
it). 4 sin a cos a = 1 has two roots in 0 < a < pi/2 (pi/12 and 5 pi/12): no single
boundary."
  (call-with-bridge
   (lambda (b)
     (flet ((root-of (facts difference)
              (ames.maxima:with-assumptions (b facts)
                (ames.algebra:one-angle-root b difference 'a)))
            (zero-at-p (difference value)
              (same-expression-p b (subst value 'a difference) 0)))
       (let ((acute '((> a 0) (< a (/ pi 2)))))
         (dolist (difference '((- (* 2 (sin a)) (cos a)) (+ (sin a) (* 2 (cos a)) -2)
                               (- (* 3 (sin a)) 1)))
           (let ((value (root-of acute difference)))
             (is (not (null value)) "no root of ~S" difference)
             (when value
               (is (zero-at-p difference value) "~S is not 0 at ~S" difference value)
               (is (< 0 (ames.algebra::constant-value value) (/ pi 2))))))
         (is (same-expression-p b (root-of acute '(- (* 2 (sin a)) (cos a))) '(atan 1/2)))
         (is (null (root-of acute '(- (* 4 (sin a) (cos a)) 1)))))
       (let ((value (root-of '((> a 0) (< a pi)) '(+ (cos a) 1/2))))
         (is (not (null value)))
         (when value
           (is (< (abs (- (ames.algebra::constant-value value) (* 2/3 pi))) 1d-12))))))))

(test incline-of-friction-one-half-forks-at-its-boundary-angle
  "The particle on the incline of static friction 1/2: three branches on 2 sin a - cos a.
Sliding, it reaches the foot at sqrt(4 h / (g sin a (4 sin a - cos a))) (the branch's
later questions decided, so the branch completes); below the boundary it stays; at the
boundary, a = atan(1/2), static friction m g / sqrt 5 just holds it against N = 2 m g /
sqrt 5."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "particle-on-incline-of-friction-one-half"))
           (history (ames:run-scenario scenario :bridge bridge))
           (fork (first (ames::history-states history)))
           (branches (ames::state-branches fork)))
      (flet ((x (form) (in-scenario-terms scenario form))
             (branch (operator) (find operator branches :key (lambda (br) (first (getf br :assume))))))
        (is (= 3 (length branches)))
        (dolist (branch branches)
          (is (eq :complete (getf branch :outcome)) "~S" (getf branch :assume)))
        (let ((slide (first (getf (branch '>) :states))))
          (when slide
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "time to the foot" (ames::state-duration slide)
                        (x '(sqrt (/ (* 4 h) (* g (sin a) (- (* 4 (sin a)) (cos a)))))))))))
        (let ((rest-state (first (getf (branch '=) :states))))
          (is (equal (list '= (x '(- (* 2 (sin a)) (cos a))) 0) (getf (branch '=) :assume)))
          (when rest-state
            (is (eq :forever (ames::state-duration rest-state)))
            (check-friction bridge rest-state "PARTICLE" "INCLINE" :static
                            (x '(/ (* m g) (sqrt 5))))
            (is-same bridge "N" (normal-force-between rest-state "PARTICLE" "INCLINE")
                     (x '(/ (* 2 m g) (sqrt 5))))))))))

(test a-boundary-no-parameter-is-solved-for-is-listed
  "4 sin a cos a - 1 = 0 has two roots in the incline's range (pi/12 and 5 pi/12): no
parameter is solved for from it, and the fork on 4 sin a cos a - 1 > 0 lists its
boundary anyway, unsimulated (with why), after the two strict sides; its branch is
:NOT-SIMULATED, or :FAILED when the run's values lie on it."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "particle-on-incline-of-friction-one-half")))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (let* ((run (ames.simulator::make-run
                      (nth-value 1 (ames.scenario::check-scenario scenario bridge)) bridge))
                (fact (in-scenario-terms scenario '(> (- (* 4 (sin a) (cos a)) 1) 0)))
                (alternatives (ames.simulator::fork-alternatives run fact)))
           (is (equal '(> < =) (mapcar (lambda (alt) (first (getf alt :assume))) alternatives)))
           (let ((boundary (third alternatives)))
             (is (getf boundary :unsolved))
             (is (null (getf boundary :scenario)))
             (is (eq :not-simulated
                     (getf (ames.simulator::unsolved-boundary-branch boundary nil) :outcome)))
             (is (eq :failed
                     (getf (ames.simulator::unsolved-boundary-branch boundary t) :outcome)))
             (is (stringp (getf (ames.simulator::unsolved-boundary-branch boundary nil) :failure))))))))))
