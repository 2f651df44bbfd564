;;;; t/corner-strikes.lisp -- a corner reached at a speed at the end of a state integrated
;;;; numerically (issues 21 and 23): the impact resolved over every contact touching then,
;;;; the contacts that separate after it not held, and a body's face put flush with a fixed
;;;; face exactly when a corner of each touches the other's (flush-corner-snapping.lisp).
;;;;
;;;; The rocking block of scenarios/block-rocking-on-an-edge.lisp (w = 1, k = 2, m = 1) on
;;;; a frictionless floor has two degrees of freedom and is integrated numerically. It falls
;;;; back onto its face turning at omega and strikes the floor with its other bottom corner.
;;;; The plastic, frictionless impact at that corner (its vertical velocity just after 0)
;;;; keeps the angular momentum about the vertical line through it, and the horizontal
;;;; momentum: omega' = omega (I_c - m w^2/4) / (I_c + m w^2/4) = omega / 4 with I_c = m (w^2
;;;; + k^2)/12 = 5/12 (Housner 1963, for a frictionless floor), the centre rising at
;;;; v_y' = omega' w/2 just after, and the first corner (its pivot until then) leaving the
;;;; floor at omega' w: the next state holds the struck corner only. Helpers:
;;;; t/simulator-scenarios.lisp, t/friction.lisp, t/rocking-block.lisp.

(in-package #:ames.tests)

(def-suite corner-strikes :in all-tests
  :description "A corner reached at a speed at the end of a numerically integrated state:
its impact, the contacts it leaves, a face put flush with a face.")

(in-suite corner-strikes)

(defparameter *rocking-block-two-strikes*
  (cl-ppcre:regex-replace "\\(simulate :states 1\\)" *frictionless-rocking-block*
                          "(simulate :states 2)")
  "The rocking block of t/rocking-block.lisp set turning about its right edge on a
frictionless floor, for two states: back onto its face, then on its left edge.")

(defun normal-force-count (state)
  "How many normal forces act in STATE (each held corner gives one)."
  (count-if (lambda (entry) (and (consp entry) (eq :normal (first entry))))
            (ames::state-forces state)))

(test frictionless-rocking-block-strikes-at-a-quarter
  "The block falls back flat (angle exactly 0) at the speed it started with (energy kept,
to the integration's accuracy), strikes with its left corner: omega' = omega/4 exactly and
v_y' = omega' w/2 (Housner, frictionless floor); its right corner, which held it until
then, separates at omega' w > 0 and is not held in the next state, which turns the
block on its left corner alone and lasts."
  (with-fixture simulator-bridge ()
    (let ((scenario (first (ames:read-scenarios-from-string *rocking-block-two-strikes*)))
          (w0 (sqrt 1.1772d0)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (is (= 2 (length states)))
        (when (= 2 (length states))
          (destructuring-bind (back rock) states
            (flet ((final (state accessor)
                     (second (assoc 'block (funcall accessor state) :test #'same-name-p*))))
              (is (same-name-p* 'collision (first (ames::state-end-event back))))
              (is (eql 0 (final back #'ames::state-final-angles)))
              (is (< (abs (- (float (final back #'ames::state-final-angular-velocities) 1d0) w0)) 1d-6))
              (let* ((impact (ames::state-impact back))
                     (before (second (assoc 'block (getf impact :angular-velocities-before) :test #'same-name-p*)))
                     (after (second (assoc 'block (getf impact :angular-velocities-after) :test #'same-name-p*)))
                     (velocity (second (assoc 'block (getf impact :velocities-after) :test #'same-name-p*))))
                (is-same bridge "Housner's ratio on a frictionless floor" `(/ ,after ,before) 1/4)
                (is-same bridge "the centre rises at omega' w/2" (second velocity) `(* 1/2 ,after))
                (is (> (float after 1d0) 0d0))
                ;; one corner struck: one impulse
                (is (= 1 (length (getf impact :contacts)))))
              ;; the next state holds the struck corner only, and lasts
              (is (= 1 (normal-force-count rock)))
              (is (= 1 (normal-force-count back)))
              (is (> (float (ames::state-duration rock) 1d0) 1d-3))
              (is (same-name-p* 'collision (first (ames::state-end-event rock)))))))))))

;;; A block landed flat on a ledge while the ledge's edge holds its bottom face
;;; (witness/ block-step 23 #7): its left bottom corner on the ledge's top and the ledge's
;;; corner (0, 0) on its bottom face. The integration leaves the angle at 8e-12; the face is
;;; put flush with the ledge's top: angle 0 exactly, then the centre at height 1 exactly, so
;;; that both gaps are 0.

(defparameter *block-on-a-ledge*
  "(scenario block-on-a-ledge \"A block across a ledge's edge.\" (gravity 33/4)
     (body floor :fixed t :shape (half-plane (1 -1) (0 -1)))
     (body ledge :fixed t :shape (polygon (-9/2 -1) (0 -1) (0 0) (-9/2 0)))
     (body block :mass 7/4 :inertia :uniform :shape (polygon (-1 -1) (1 -1) (1 1) (-1 1))
                 :position (7/65 491/260) :angle (atan -5/12) :velocity (0 0))
     (restitution 0) (simulate :states 1))"
  "A 2 x 2 block above a ledge whose top is y = 0 and whose edge is at the origin.")

(test face-put-flush-on-a-ledge
  "An angle of 8e-12 with the block's left corner on the ledge's top and the ledge's corner
on its bottom face goes to 0 exactly, and the position to height 1 exactly; an angle of
1e-6 is left (beyond the tolerance: no round-off)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *block-on-a-ledge*)))
           (block (find-symbol "BLOCK" (symbol-package (ames:scenario-name scenario))))
           (run (ames.simulator::make-run (nth-value 1 (ames.scenario::check-scenario scenario bridge)) bridge))
           (theta 310/38068268021721)
           (position (list 67931299/116646774 (+ (sin (float theta 1d0)) (cos (float theta 1d0))))))
      (setf position (list (first position) (rational (second position))))
      (multiple-value-bind (angle slope) (ames.simulator::flat-corner-angle run block theta position '())
        (is (eql 0 angle))
        (is (and slope (> (abs slope) 0.1d0))))
      (let ((snapped (second (assoc block (ames.simulator::snap-corners-onto-faces
                                           run (list (list block position)) (list (list block 0)))))))
        (is (eql 1 (second snapped)))
        (is (eql (first position) (first snapped))))
      (is (null (ames.simulator::flat-corner-angle run block 1/1000000 (list (first position) 1) '()))))))
