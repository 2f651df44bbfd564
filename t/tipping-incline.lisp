;;;; t/tipping-incline.lisp -- the block tipping on a rough incline (issue 23), at its start.
;;;;
;;;; scenarios/awaiting-rotation/block-tipping-on-incline.lisp: a w x k block (k tan a > w)
;;;; standing on an incline of angle a, rough enough for its downhill edge to stick as it
;;;; starts to tip (declared: mu above the friction needed there over the normal force).
;;;; Its weight's line passes downhill of that edge, so its uphill corner lifts off at once
;;;; and it turns about the edge: one degree of freedom, its angle s from -a, with
;;;; omega^2 = 6 g (y(-a) - y(s)) / (w^2 + k^2) (energy: the centre's height above the edge
;;;; y(s) = (k/2) cos s - (w/2) sin s, I_edge = m (w^2 + k^2) / 3), and at the start the
;;;; textbook's angular acceleration -m g ((k/2) sin a - (w/2) cos a) / I_edge, half the
;;;; slope of omega^2 along s. The choice search settles this start without a fork, but
;;;; takes a minute or two on a loaded machine: the test is in LONG-CHECKS (`make fuzz`).

(in-package #:ames.tests)

(defun incline-block-file ()
  "The file of the block tipping on the incline."
  (merge-pathnames "scenarios/awaiting-rotation/block-tipping-on-incline.lisp"
                   (asdf:system-source-directory "ames")))

(test (tipping-block-on-an-incline-turns-about-its-downhill-edge :suite long-checks)
  "The block's first state, symbolically: one rotation path (pinned at its downhill edge,
the uphill corner lifted), omega^2 along the angle as the energy gives it, and the
textbook's angular acceleration at the start."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenario-file (incline-block-file))))
           (world (nth-value 1 (ames:check-scenario scenario bridge)))
           (s 'ames.simulator::arc-length))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (let* ((run (ames.simulator::make-run world bridge))
                  (trial (ames.simulator::settle-choices run))
                  (groups (ames.simulator::integrate-groups run (ames.simulator::trial-solved trial)))
                  (path (find :rotation-path groups :key #'ames.simulator::group-kind)))
             (is (= 1 (length groups)))
             (is (not (null path)) "no rotation path: ~S" (mapcar #'ames.simulator::group-kind groups))
             (when path
               (let* ((w (x 'w)) (k (x 'k)) (g (x 'g)) (a (x 'a))
                      ;; the centre's height above the edge at the angle ANGLE
                      (height (lambda (angle) `(- (* (/ ,k 2) (cos ,angle)) (* (/ ,w 2) (sin ,angle)))))
                      (expected `(/ (* 6 ,g (- ,(funcall height `(- ,a)) ,(funcall height s)))
                                    (+ (expt ,w 2) (expt ,k 2))))
                      (speed-squared (ames.simulator::group-speed-squared path)))
                 (is-same bridge "omega^2 along the angle (the energy about the edge)"
                          speed-squared expected)
                 (is-same bridge "the angular acceleration at the start"
                          (ames.maxima:simplify
                           bridge (substitute-expressions
                                   (list (cons s (x '(- a))))
                                   `(/ ,(ames.geometry:differentiate speed-squared s) 2)))
                          (x '(/ (* -1 m g (- (* (/ k 2) (sin a)) (* (/ w 2) (cos a))))
                                 (/ (* m (+ (expt w 2) (expt k 2))) 3)))))))))))))
