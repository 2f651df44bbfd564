;;;; t/trust-fresh-impacts.lisp -- issue 20, classes 4, 10 and 11, on impact problems written
;;;; fresh for these tests: a particle dropped onto the top of a free block with gravity a
;;;; parameter, a disc dropped onto a fixed block's top, balls bouncing to rest (the number
;;;; beside the summed series is its formula's), three blocks pushed into a wall given in
;;;; numbers (self-checked: every number of such a problem is known).
;;;;
;;;; Closed forms are checked by Maxima equivalence (helpers in t/simulator-scenarios.lisp and
;;;; t/self-check.lisp).

(in-package #:ames.tests)

(in-suite trust-fresh)

;;; Class 10: faces met with gravity a parameter

(defparameter *particle-onto-block*
  "(scenario particle-onto-block
     \"A particle dropped onto the top of a free block resting on the floor bounces.\"
     (parameters (m :positive (:value 1)) (bm :positive (:value 5)) (g :positive (:value 10))
                 (b :positive (:value 1)) (hh :positive (> hh b) (:value 3)))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body blk :mass bm :position (0 0) :velocity (0 0) :shape (polygon (0 0) (2 0) (2 b) (0 b)))
     (body p :mass m :position (1/2 hh) :velocity (1/4 0) :shape point)
     (restitution 1/2)
     (simulate :states 2))"
  "A particle moving slowly sideways dropped from height hh onto the top (height b) of a
free block on a frictionless floor, e = 1/2, g a parameter.")

(test a-particle-dropped-onto-a-free-block-bounces-off-its-top
  "The particle meets the block's top face after sqrt(2 (hh - b)/g) (not the floor inside
the block); the floor under the block takes the impulse with it, so the block stays at
rest and the particle leaves upward at e sqrt(2 g (hh - b)) with its sideways 1/4 kept;
the impulse of the top on it is (1 + e) m sqrt(2 g (hh - b))."
  (with-fixture simulator-bridge ()
    (let* ((history (numeric-history *particle-onto-block* bridge))
           (scenario (ames:history-scenario history))
           (path (ames.check::checked-path (ames:history-states history)))
           (fall (find-if (lambda (s) (consp (ames::state-end-event s)))
                          (remove '(:branch) path :key #'ames::state-end-event :test #'equal)))
           (after (second (member fall path))))
      (is (null (getf (self-check-of history) :failures)))
      (is (not (null after)) "no state after the impact")
      (when after
        (is (equal '(:collision "P" "BLK") (event-names (ames::state-end-event fall)))
            "~S" (ames::state-end-event fall))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (call-with-scenario-facts
           bridge scenario
           (lambda ()
             (is-same bridge "the fall" (ames::state-duration fall) (x '(sqrt (/ (* 2 (- hh b)) g))))
             (is-same bridge "the top's impulse" (getf (cdddr (ames::state-end-event fall)) :impulse)
                      (x '(* 3/2 m (sqrt (* 2 g (- hh b))))))
             (is-same-vector bridge "the particle just after"
                             (per-body (ames:state-initial-velocities after) "P")
                             (x '(1/4 (* 1/2 (sqrt (* 2 g (- hh b)))))))
             (is-same-vector bridge "the block just after"
                             (per-body (ames:state-initial-velocities after) "BLK") '(0 0)))))))))

(test a-disc-dropped-onto-a-fixed-block-rests-on-its-top
  "A disc (radius r) dropped from hh onto a fixed block's top (height b), g a parameter,
plastic: it lands after sqrt(2 (hh - r - b)/g) on the top face and rests there forever,
the top's normal force m g."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string
                             "(scenario disc-onto-block
                                \"A disc dropped onto a fixed block's top.\"
                                (parameters (m :positive) (g :positive) (r :positive (< r 1/2))
                                            (b :positive) (hh :positive (> hh (+ b r))))
                                (gravity g)
                                (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                (body blk :fixed t :shape (polygon (0 0) (2 0) (2 b) (0 b)))
                                (body d :mass m :position (1 hh) :velocity (0 0) :shape (circle r))
                                (simulate :states 2))")))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames:history-states history)))
      (is (eq :complete (ames:history-outcome history)) "outcome ~S" (ames:history-outcome history))
      (destructuring-bind (&optional fall rest) states
        (when rest
          (is (equal '(:collision "D" "BLK") (event-names (ames::state-end-event fall))))
          (is (eq :forever (ames::state-duration rest)))
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "the fall" (ames::state-duration fall) (x '(sqrt (/ (* 2 (- hh r b)) g))))
               (is-same bridge "the top's normal force" (normal-force-between rest "D" "BLK") (x '(* m g)))
               (is-same-vector bridge "at rest" (per-body (ames:state-velocities rest) "D") '(0 0))))))))))

;;; Class 4: the number beside a summed series is its formula's value

(test numbers-after-fresh-summed-series-are-their-formulas
  "A ball thrown straight up at v0 from a floor, e = 1/2: each flight half the one before,
at rest from (2 v0/g)/(1 - e) = 4 v0/g. A ball dropped from hh onto a fixed table top
(height b), e = 1/3: at rest on the table from sqrt(2 (hh - b)/g) (1 + e)/(1 - e) =
2 sqrt(2 (hh - b)/g). The printed numbers are those formulas' values (self-checked)."
  (with-fixture simulator-bridge ()
    (check-accumulated-start
     bridge (numeric-history "(scenario ball-thrown-up-bounces
                                \"A ball thrown up from a floor bounces with e = 1/2 until it rests.\"
                                (parameters (m :positive (:value 1)) (g :positive (:value 10))
                                            (v0 :positive (:value 3)))
                                (gravity g)
                                (restitution 1/2)
                                (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                (body ball :mass m :position (0 0) :velocity (0 v0) :shape point)
                                (simulate :states 6))" bridge)
     '(/ (* 4 v0) g))
    (check-accumulated-start
     bridge (numeric-history "(scenario ball-on-a-table-bounces
                                \"A ball dropped onto a table top bounces with e = 1/3 until it rests.\"
                                (parameters (m :positive (:value 1)) (g :positive (:value 98/10))
                                            (b :positive (:value 1)) (hh :positive (> hh b) (:value 3)))
                                (gravity g)
                                (restitution 1/3)
                                (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                (body table :fixed t :shape (polygon (-1 0) (1 0) (1 b) (-1 b)))
                                (body ball :mass m :position (0 hh) :velocity (0 0) :shape point)
                                (simulate :states 6))" bridge)
     '(* 2 (sqrt (/ (* 2 (- hh b)) g))))))

;;; Class 11: pushed blocks given in numbers, and their self-check

(test three-blocks-pushed-into-a-wall-given-in-numbers
  "Blocks of 1, 2 and 3 kg touching, 12 N on the first, the wall 1 m ahead of the third:
a = 2, they hit it after 1 s and stay (plastic) with the wall holding the push, 12 N,
and the second pressing the third with 3 x 12/6 = 6 N before the wall is reached. Given in
numbers, every number is known: the run is self-checked."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string
                             "(scenario three-blocks-into-a-wall
                                \"Three touching blocks pushed into a wall.\"
                                (gravity 98/10)
                                (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                (body wall :fixed t :shape (half-plane (4 1) (4 0)))
                                (body b1 :mass 1 :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
                                (body b2 :mass 2 :position (1 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
                                (body b3 :mass 3 :position (2 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
                                (force push :on b1 :value (12 0))
                                (simulate :states 3))")))
           (history (ames:run-scenario scenario :bridge bridge))
           (states (ames:history-states history))
           (check (self-check-of history)))
      (is (eq :complete (ames:history-outcome history)) "outcome ~S" (ames:history-outcome history))
      (is (not (null check)) "a problem in numbers is not self-checked")
      (is (null (getf check :failures)) "~S" (getf check :failures))
      (is (= 2 (length states)) "~D states" (length states))
      (destructuring-bind (&optional push rest) states
        (when rest
          (is (equal '(:collision "B3" "WALL") (event-names (ames::state-end-event push))))
          (is (same-expression-p bridge (ames::state-duration push) 1))
          (is (same-expression-p bridge (normal-force-between push "B2" "B3") 6))
          (is (same-expression-p bridge (normal-force-between rest "B3" "WALL") 12))
          (is (eq :forever (ames::state-duration rest))))))))

;;; Class 9: a rope piece of no length is an input error naming the rope (it was "Maxima
;;; failed: 0 to a negative exponent", exit 1)

(test a-rope-piece-of-no-length-is-an-error-naming-the-rope
  "A pendulum tied at a fixed point with a pulley put at that same point: the piece from
the tie to the pulley has no length, so no direction; the scenario is refused by a
condition naming the rope. Tied there without the pulley, it is accepted (it runs into
what it cannot model, not into that refusal)."
  (flet ((pendulum (pulley)
           (format nil "(scenario pendulum \"A particle on a cord from a fixed point.\"
                          (parameters (m :positive) (g :positive) (l :positive))
                          (gravity g)
                          (body pivot :fixed t :position (0 0) :shape point)
                          (body p :mass m :position (l 0) :velocity (0 0) :shape point)
                          ~:[~;(pulley hook :on pivot :at (0 0))~]
                          (rope cord :length l :through ((pivot (0 0)) ~:[~;hook ~](p (0 0))))
                          (simulate :states 1))" pulley pulley)))
    (with-fixture simulator-bridge ()
      (flet ((refusal (text)
               (handler-case (progn (ames:simulate (first (ames:read-scenarios-from-string text)) :bridge bridge)
                                    nil)
                 (ames:scenario-expression-error (condition) condition)
                 (ames.base:ames-error () nil))))
        (let ((condition (refusal (pendulum t))))
          (is (not (null condition)) "a rope piece of no length was accepted")
          (when condition
            (is (search "CORD" (princ-to-string condition)) "~A" condition)))
        (is (null (refusal (pendulum nil))) "the pendulum tied without the pulley was refused")))))
