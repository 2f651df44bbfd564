;;;; src/witness/generate-ledges.lisp -- random scenarios of turning bodies landing across the
;;;; edge of a ledge or a step (issue 23): a uniform rod or a square block falls onto a
;;;; ledge whose top ends at (0, 0) with part of it over the ledge and the rest beyond the
;;;; edge; it lands on its own corner on the ledge's top, or on the ledge's corner under its
;;;; face, or both at once (the rod or block flat), then tips over the edge and slides off
;;;; it onto the floor, or rests on the ledge. The witness (siconos_rotation.py with
;;;; siconos_ledges.py: a fixed corner on a turning body's face) models both kinds of
;;;; vertex-face contact.
;;;;
;;;; Tilts are the angles of Pythagorean triples (their cosines and sines rational, so the
;;;; corners' positions are), the body's lowest point over the ledge or over the edge a
;;;; random clearance above it; the ledge stands on the floor and is longer than the body.

(in-package #:ames.witness)

(defun ledge-tilt ()
  "A random tilt: (COS SIN) of 0, or of a small angle of a Pythagorean triple either way."
  (destructuring-bind (a b c) (pick '(0 1 1) '(0 1 1) '(7 24 25) '(9 40 41) '(20 99 101) '(5 12 13))
    (let ((sign (pick 1 -1)))
      (list (/ b c) (* sign (/ a c))))))

(defun ledge-body-text (shape size cos sin centre velocity)
  "The turning body: a uniform rod (SHAPE :rod, length SIZE) or square block (:block,
side SIZE), turned by the angle of cosine COS and sine SIN, at CENTRE with VELOCITY."
  (format nil "(body ~A :mass m :inertia :uniform :shape ~A :position (~{~A~^ ~}) :angle ~A :velocity (~{~A~^ ~}))"
          (if (eq shape :rod) "rod" "block")
          (if (eq shape :rod)
              (format nil "(segment (~A 0) (~A 0))" (- (/ size 2)) (/ size 2))
              (let ((h (/ size 2)))
                (format nil "(polygon (~A ~A) (~A ~A) (~A ~A) (~A ~A))" (- h) (- h) h (- h) h h (- h) h)))
          centre (if (zerop sin) 0 (format nil "(atan ~A)" (/ sin cos))) velocity))

(defun ledge-landing-centre (shape size cos sin d clearance)
  "The centre of the body (SHAPE, SIZE) turned by (COS, SIN) whose bottom face's left end
is at x = -D (on the ledge's side of its edge at (0, 0)) and whose lowest point above the
ledge's top or its edge is CLEARANCE high: for a tilt down to the left the bottom-left
corner, for one down to the right the face's point over the edge."
  (let* ((half (/ size 2))
         (below (if (eq shape :rod) 0 half))      ; the bottom face under the centre
         ;; the bottom face's left end, from the centre: R (-half, -below)
         (left-x (- (* -1 half cos) (* -1 below sin)))
         (left-y (+ (* -1 half sin) (* -1 below cos)))
         (x (- (- d) left-x)))
    (list x (if (>= sin 0)
                (- clearance left-y)
                ;; the face's point over the edge, x = 0: along the face from its left end
                (let ((along (/ d cos)))
                  (- clearance (+ left-y (* along sin))))))))

(defun family-ledge-landing (name &optional (shape (pick :rod :block)))
  "A uniform rod or square block of SHAPE falls (released at rest, or moving sideways)
onto a ledge with a fraction of it over the ledge's top and the rest beyond its edge;
smooth, its restitution 0, 1/2 or 1 (0 or 1 when it lands flat with its centre over the
ledge: see below); a floor below the ledge. Three states: the landing,
the tipping over the edge or the bounce, what follows."
  (let* ((size (random-ratio 1/2 2)) (c-s (ledge-tilt))
         (cos (first c-s)) (sin (second c-s))
         (fraction (pick (random-ratio 1/10 2/5 20) (random-ratio 3/5 9/10 20)))
         (d (* fraction size))
         (clearance (random-ratio 1/10 1 20))
         (step (random-ratio 1/2 3/2))
         (width (+ (* 2 size) (random-ratio 1/2 2)))
         (vx (pick 0 0 (random-ratio -1/2 1/2)))
         (centre (ledge-landing-centre shape size cos sin d clearance)))
    (scenario-text name "A rod or a block falls across the edge of a ledge."
                   (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3))
                   (list (format nil "(body floor :fixed t :shape (half-plane (1 ~A) (0 ~A)))" (- step) (- step))
                         (format nil "(body ledge :fixed t :shape (polygon (~A ~A) (0 ~A) (0 0) (~A 0)))"
                                 (- width) (- step) (- step) (- width))
                         (ledge-body-text shape size cos sin centre (list vx 0))
                         (format nil "(restitution ~A)"
                                 (if (and (zerop sin) (> fraction 1/2))
                                     ;; flat with its centre over the ledge it bounces on
                                     ;; its corner and the ledge's edge at once: with
                                     ;; 0 < e < 1 a Zeno sequence, whose two contacts'
                                     ;; lift-offs the comparator's skip does not pass
                                     (pick 0 1)
                                     (restitution-choice))))
                   3)))

(defun family-step-landing (name)
  "A square block (FAMILY-LEDGE-LANDING's) landing across the edge of a step."
  (family-ledge-landing name :block))

(defun family-rod-landing (name)
  "A uniform rod (FAMILY-LEDGE-LANDING's) landing across the edge of a ledge."
  (family-ledge-landing name :rod))

(defparameter *ledge-families*
  '((:rod-ledge . family-rod-landing) (:block-step . family-step-landing))
  "The families of turning bodies landing across a ledge's edge, added to *FAMILIES* and
*ROTATION-FAMILIES*.")

(dolist (entry *ledge-families*)
  (unless (assoc (car entry) *rotation-families*)
    (setf *rotation-families* (append *rotation-families* (list entry))))
  (unless (assoc (car entry) *families*)
    (setf *families* (append *families* (list entry)))))
