;;;; src/geometry/touching.lisp -- where two bodies touch along a simple contact, and the normal there.
;;;;
;;;; A simple contact is a locus of the relative position q = position(observer) -
;;;; position(obstacle); the point where the bodies touch follows from the features that
;;;; meet along it (the contact remembers their names, see minkowski.lisp): the
;;;; observer's point or corner; else the obstacle's corner or point; else the middle of
;;;; the observer's edge (two edges touch along a segment); else the point of a rim (a
;;;; circle, an arc) that faces the other body along the contact's normal. The normal is
;;;; the contact's outward normal at q: the direction in which the obstacle pushes the
;;;; observer. Everything is an expression; nothing is decided here but where q lies.

(in-package #:ames.geometry)

(defun feature-index (feature)
  "The index of the feature descriptor FEATURE ((:edge 2 :of b) gives 2), or NIL."
  (and (integerp (second feature)) (second feature)))

(defun shape-piece-named (shape name)
  "The boundary piece of SHAPE whose feature name is NAME ((:edge 2), (:arc 0)), or NIL."
  (find name (shape-boundary shape) :key #'piece-name :test #'equal))

(defun shape-vertex (shape index)
  "Vertex INDEX of SHAPE in its own frame: where its piece INDEX starts; for a shape of
one open piece (a segment, an arc track), vertex 1 is where that piece ends. NIL when
SHAPE has no such vertex."
  (let ((pieces (shape-boundary shape)))
    (cond ((typep shape 'polygon-shape) (nth index (shape-vertices shape)))
          ((and (typep shape '(or segment-shape arc-shape)) (eql index 1))
           (piece-end (first pieces)))
          ((< index (length pieces)) (piece-start (nth index pieces))))))

(defun rim-point (piece outward)
  "The point of the circular PIECE where the body's outward normal is the unit vector
OUTWARD: away from the centre on a convex piece, toward it on a concave one."
  (v+ (arc-piece-center piece)
      (vscale (if (eq (arc-piece-sense piece) :cw)
                  (e- (arc-piece-radius piece))
                  (arc-piece-radius piece))
              outward)))

(defun feature-touching-point (shape feature outward)
  "The point of SHAPE's FEATURE (a descriptor such as (:vertex 2 :of b)) that touches
the other body, in the body's own frame, when the body's outward normal there is the
unit vector OUTWARD: its reference point for (:point), the corner for (:vertex I), the
middle of the edge for (:edge I), the rim's point facing OUTWARD for (:circle) and
(:arc I). NIL when SHAPE has no such feature."
  (let ((index (feature-index feature)))
    (case (first feature)
      (:point (vec 0 0))
      (:vertex (and index (shape-vertex shape index)))
      (:edge (let ((piece (shape-piece-named shape (list :edge index))))
               (and piece (vmid (line-piece-start piece) (line-piece-end piece)))))
      (:circle (let ((piece (shape-piece-named shape '(:circle))))
                 (and piece (rim-point piece outward))))
      (:arc (let ((piece (shape-piece-named shape (list :arc index))))
              (and (typep piece 'arc-piece) (rim-point piece outward)))))))

(defun contact-touching-point (contact observer-shape obstacle-shape q)
  "Where the observer and the obstacle of CONTACT (with OBSERVER-SHAPE and
OBSTACLE-SHAPE) touch when their relative position is Q, on CONTACT: (values POINT
NORMAL), POINT in the obstacle's frame (relative to its reference point) and NORMAL the
contact's unit outward normal at Q, from the obstacle into the observer (see the file
header for which point). POINT is NIL when the features do not say. Signals
POSITION-NOT-ON-CONTACT when Q is not on CONTACT."
  (let* ((normal (contact-outward-normal contact (contact-parameter contact q)))
         (observer (contact-observer-feature contact))
         (obstacle (contact-obstacle-feature contact))
         (point (flet ((observer-at () (let ((a (feature-touching-point observer-shape observer
                                                                         (vneg normal))))
                                         (and a (v+ q a))))
                       (obstacle-at () (feature-touching-point obstacle-shape obstacle normal)))
                  (cond ((member (first observer) '(:point :vertex)) (observer-at))
                        ((member (first obstacle) '(:point :vertex)) (obstacle-at))
                        ((member (first observer) '(:edge :circle :arc)) (observer-at))
                        (t (obstacle-at))))))
    (values point normal)))
