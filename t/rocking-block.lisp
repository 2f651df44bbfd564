;;;; t/rocking-block.lisp -- turning points of a rotation held by corners (issue 23): a block
;;;; rocking on an edge turns back where its angular velocity changes sign (the watch of
;;;; src/kb/turning.lisp, a :WATCH section of the engine), and the next state rocks it back.
;;;;
;;;; The expected results are the textbook's (scenarios/block-rocking-on-an-edge.lisp): on
;;;; its edge the block (w = 1, k = 2, m = 1, I_edge = 5/3) turns until its kinetic energy
;;;; has lifted its centre, (1/2) I_edge w0^2 = m g ((k/2) cos s - (w/2) sin s - k/2); it
;;;; falls back to s = 0 with the speed it started with; the plastic impact on its other edge
;;;; keeps its angular momentum about that edge, omega' = omega (1 - (3/2) w^2 / (w^2 + k^2))
;;;; (Housner 1963), and it rises on that edge until (1/2) I_edge omega'^2 = m g ((k/2) cos s
;;;; + (w/2) sin s - k/2). Each is checked by Maxima equivalence. Helpers:
;;;; t/simulator-scenarios.lisp, t/friction.lisp.

(in-package #:ames.tests)

(def-suite rocking-block :in all-tests
  :description "A body held by a corner turning back ((:turns B), a watch on omega's sign
relative to the state's starting direction); the engine's :WATCH section.")

(in-suite rocking-block)

(defun rocking-energy-balance (omega angle side)
  "(1/2) I_edge OMEGA^2 - m g (rise of the centre at ANGLE) for the rocking block of
scenarios/block-rocking-on-an-edge.lisp (w = 1, k = 2, m = 1, g = 981/100) turning about
its right (SIDE 1) or left (SIDE -1) bottom edge: zero at its turning point."
  `(- (* 1/2 5/3 (expt ,omega 2))
      (* 981/100 (- (+ (cos ,angle) (* ,(- side) 1/2 (sin ,angle))) 1))))

(test block-rocks-on-its-edge-and-turns-back
  "The block set turning about its right edge turns back at the angle where its kinetic
energy has lifted its centre (-2 atan(1/7) for these numbers), comes back to its face with
the speed it started with, strikes the floor with its left edge and rocks on that edge at
(7/10) of that speed, turning back where that energy has lifted the centre again."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-rocking-on-an-edge"))
          (w0 '(sqrt 11772/10000)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (is (= 3 (length states)))
        (when (= 3 (length states))
          (destructuring-bind (rise back rock) states
            (flet ((final (state accessor) (second (assoc 'block (funcall accessor state) :test #'same-name-p*))))
              ;; up on the right edge, turning back
              (is (same-name-p* 'turns (first (ames::state-end-event rise))))
              (let ((angle (final rise #'ames::state-final-angles)))
                (is-same bridge "first turning angle" angle '(- (* 2 (atan 1/7))))
                (is-same bridge "energy at the first turning point"
                         (rocking-energy-balance w0 angle 1) 0))
              (is-same bridge "at rest at the turning point" (final rise #'ames::state-final-angular-velocities) 0)
              ;; back down to the face, at the speed it started with
              (is (same-name-p* 'collision (first (ames::state-end-event back))))
              (is-same bridge "back on its face" (final back #'ames::state-final-angles) 0)
              (is-same bridge "the speed it started with" (final back #'ames::state-final-angular-velocities) w0)
              ;; the impact on the left edge: Housner's ratio
              (let ((impact (ames::state-impact back)))
                (is (not (null impact)))
                (let ((before (second (assoc 'block (getf impact :angular-velocities-before) :test #'same-name-p*)))
                      (after (second (assoc 'block (getf impact :angular-velocities-after) :test #'same-name-p*))))
                  (is-same bridge "Housner's ratio" `(/ ,after ,before) '(- 1 (* 3/2 (/ 1 (+ 1 4)))))
                  ;; up on the left edge, turning back again
                  (is (same-name-p* 'turns (first (ames::state-end-event rock))))
                  (let ((angle (final rock #'ames::state-final-angles)))
                    (is-same bridge "energy at the second turning point"
                             (rocking-energy-balance after angle -1) 0)
                    (is-same bridge "the second rise is 49/100 of the first"
                             `(- (+ (cos ,angle) (* 1/2 (sin ,angle))) 1) '(* 49/100 1/10))))))))))))

(test watch-section-of-a-component
  "A component's :WATCH section gives termination conditions of kind :WATCH that change no
decision (their change is NIL) and carry their event; a watch without an event is
malformed."
  (let ((component (ames.engine::parse-component
                    'watching "A watch." '((:arguments (?b :entity body))
                                           (:watch (:when (< (angvel ?b) 0) :event (:turns ?b)))))))
    (is (equal '((< (angvel ?b) 0)) (ames.engine::component-watch-relations component)))
    (is (equal '(:turns ?b) (ames.engine::event-spec-event
                             (first (ames.engine::component-watch-events component))))))
  (signals ames.engine:component-definition-error
    (ames.engine::parse-component 'watching "A watch." '((:arguments (?b :entity body))
                                                        (:watch (< (angvel ?b) 0))))))

(defparameter *block-spun-at-one*
  "(scenario block-spun-at-one
     \"The rocking block set turning at w0 = 1: its turning angle is a root of a quadratic in
its half-angle tangent with irrational coefficients.\"
     (gravity 981/100)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body block :mass 1 :inertia :uniform :position (0 1) :velocity (1 1/2) :angular-velocity -1
                 :shape (polygon (-1/2 -1) (1/2 -1) (1/2 1) (-1/2 1)))
     (friction block floor :static 1)
     (simulate :states 2))"
  "The block of scenarios/block-rocking-on-an-edge.lisp set turning at w0 = 1.")

(test block-spun-at-one-turns-where-its-energy-says
  "At w0 = 1 the first turning angle (no rational sine) still balances the energy, and the
block falls back onto its face at the speed it started with (the order of the next
state's events needs the roots of a quadratic with irrational coefficients: its earliest
positive root, not the other one)."
  (with-fixture simulator-bridge ()
    (let ((scenario (first (ames:read-scenarios-from-string *block-spun-at-one*))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :state-limit (ames::history-outcome history)))
        (is (= 2 (length states)))
        (when (= 2 (length states))
          (destructuring-bind (rise back) states
            (flet ((final (state accessor) (second (assoc 'block (funcall accessor state) :test #'same-name-p*))))
              (is (same-name-p* 'turns (first (ames::state-end-event rise))))
              (is-same bridge "energy at the turning point"
                       (rocking-energy-balance 1 (final rise #'ames::state-final-angles) 1) 0)
              (is (same-name-p* 'collision (first (ames::state-end-event back))))
              (is-same bridge "back on its face" (final back #'ames::state-final-angles) 0)
              (is-same bridge "the speed it started with" (final back #'ames::state-final-angular-velocities) 1))))))))

;;; Corners put exactly on their faces at a numeric state's end (corner-snapping.lisp) are
;;; checked on the rod sliding off the ledge, in t/ledge-impacts.lisp.

;;; The symbolic rocking block's bound, w0^2 < 3 g (sqrt(w^2 + k^2) - k) / (w^2 + k^2) (it
;;; does not go over its edge), as the run asks it: a polynomial in w0 that is convex
;;; between the bounds 0 and that root (src/algebra/convex-bounds.lisp).

(defparameter *rocking-bound-facts*
  '((> g 0) (> w 0) (> k 0) (> w0 0)
    (< w0 (sqrt (/ (* 3 g (- (sqrt (+ (expt w 2) (expt k 2))) k)) (+ (expt w 2) (expt k 2))))))
  "The symbolic rocking block's declared facts: w0 below the speed that brings its centre
over its edge.")

(defun rocking-over-the-top (factor)
  "(D^2 w0^2 + 3 g k)^2 - 9 g^2 FACTOR D^2, D^2 = w^2 + k^2: negative for FACTOR = 1
exactly when the energy (1/2) I_edge w0^2 is less than m g (D - k)/2, the rise of the
centre to its top over the edge."
  `(- (expt (+ (* (+ (expt w 2) (expt k 2)) (expt w0 2)) (* 3 g k)) 2)
      (* 9 (expt g 2) ,factor (+ (expt w 2) (expt k 2)))))

(test convexity-between-declared-bounds
  "DECIDE proves what follows from a polynomial's convexity between two declared bounds,
and nothing that fails at an admissible point."
  (call-with-bridge
   (lambda (b)
     ;; 0 < x < 1: x^2 - x < 0 (convex, zero at both ends)
     (is (eq :true (decided b '((> x 0) (< x 1)) '(< (- (expt x 2) x) 0))))
     (is (eq :false (decided b '((> x 0) (< x 1)) '(>= (- (expt x 2) x) 0))))
     ;; but not x^2 - x/2 < 0 (1/2 at x = 1 - epsilon)
     (is (not (eq :true (decided b '((> x 0) (< x 1)) '(< (- (expt x 2) (* 1/2 x)) 0)))))
     ;; the rocking block: below the top
     (let ((over (rocking-over-the-top 1)))
       (is (eq :true (decided b *rocking-bound-facts* `(< ,over 0))))
       (is (eq :false (decided b *rocking-bound-facts* `(>= ,over 0)))))
     ;; a smaller top is not proven (w0 may be above it)
     (is (not (eq :true (decided b *rocking-bound-facts* `(< ,(rocking-over-the-top 1/2) 0))))))))

;;; A body resting by two corners on one face at a numeric state's end is put back flat on
;;; it (src/simulator/flat-corner-snapping.lisp): the rocking block on a frictionless floor
;;; (two degrees of freedom, integrated numerically) falls back onto its face; its angle,
;;; off 0 by the integration's round-off, is moved to 0 exactly and its centre to the
;;; height k/2 = 1, where both bottom corners are on the floor. An angle further off than
;;; the tolerance, or one corner only near the floor, is left as it is. (The run itself
;;; goes on past that corner's strike: t/corner-strikes.lisp.)

(defparameter *frictionless-rocking-block*
  "(scenario frictionless-rocking-block
     \"The rocking block of scenarios/block-rocking-on-an-edge.lisp on a frictionless floor.\"
     (gravity 981/100)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body block :mass 1 :inertia :uniform :position (0 1)
                 :velocity ((sqrt 11772/10000) (/ (sqrt 11772/10000) 2))
                 :angular-velocity (- (sqrt 11772/10000))
                 :shape (polygon (-1/2 -1) (1/2 -1) (1/2 1) (-1/2 1)))
     (simulate :states 1))"
  "The rocking block set turning about its right edge on a frictionless floor.")

(test body-on-two-corners-is-put-back-flat
  "Both bottom corners within 1e-11 of the floor: the angle goes to 0 exactly, the angular
velocity (1e-12) to 0, the centre to height 1, so that both gaps are exactly 0; an angle
of 1e-6 (a corner 5e-7 above the floor: beyond the tolerance) is left as it is, and so is a
block tilted by 0.1 (one corner on the floor)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *frictionless-rocking-block*)))
           (block (find-symbol "BLOCK" (symbol-package (ames:scenario-name scenario))))
           (run (ames.simulator::make-run (nth-value 1 (ames.scenario::check-scenario scenario bridge)) bridge)))
      (flet ((flat (theta position)
               (ames.simulator::flat-corner-angle run block theta position '())))
        ;; near flat: theta 3e-12, centre 1e-12 high
        (let ((theta 3/1000000000000) (position (list 3/10 (+ 1 1/1000000000000))))
          (multiple-value-bind (angle slope) (flat theta position)
            (is (eql 0 angle))
            (is (and slope (> (abs slope) 0.5d0))))
          ;; the position follows at that angle: both corners exactly on the floor
          (let ((snapped (second (assoc block (ames.simulator::snap-corners-onto-faces
                                               run (list (list block position)) (list (list block 0)))))))
            (is (eql 1 (second snapped)))
            (is (eql 3/10 (first snapped)))))
        ;; too far off to be round-off, and one corner only
        (is (null (flat 1/1000000 (list 3/10 1))))
        (let ((tilt 1/10))
          (is (null (flat tilt (list 3/10 (+ (* (cos tilt) 1) (* (sin tilt) 1/2)))))))))))
