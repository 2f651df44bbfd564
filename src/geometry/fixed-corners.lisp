;;;; src/geometry/fixed-corners.lisp -- where a rotating body touches a fixed one: its corners
;;;; on the fixed faces and the fixed corners on its faces, each only within the face.
;;;;
;;;; rotating-contacts.lisp builds one contact of either kind; here are every such pair of a
;;;; rotating shape and a fixed one (ROTATING-BODY-CONTACTS), and the relations saying that
;;;; a contact's point lies within its face (CONTACT-EXTENT-RELATIONS): a corner on the
;;;; line of a face but past the face's end touches nothing (a rod's end beyond a ledge's
;;;; edge), so touching is the gap 0 AND 0 <= place <= extent. A fixed corner on the rotating
;;;; body's face (a ledge's edge under a rod) is the :FACE-ON-VERTEX kind: its point is the
;;;; fixed corner, its normal the rotating face's inward one, its arm from the body's centre
;;;; to the fixed corner, its extent the rotating face's length.

(in-package #:ames.geometry)

(defun contact-extent-relations (contact)
  "The relations, over CONTACT's configuration, under which its point lies within its
face: ((>= PLACE 0) (<= PLACE EXTENT)); NIL for a face that is a whole line (a
half-plane's)."
  (let ((extent (rotating-contact-extent contact)))
    (and extent
         (let ((place (rotating-contact-place contact)))
           (list (list '>= place 0) (list '<= place extent))))))

(defun fixed-corners (shape)
  "The corners of the fixed SHAPE relative to its reference point, as SHAPE-CORNERS gives
them: a polygon's vertices, a segment's ends; NIL for a shape without corners (a
half-plane, a disc, an arc track)."
  (and (member (shape-kind shape) '(:polygon :segment))
       (shape-corners shape)))

(defun fixed-corner-contacts (decider shape configuration fixed-shape
                              &key (fixed-position (vec 0 0)))
  "Every :FACE-ON-VERTEX contact of a corner of FIXED-SHAPE (a body at rest at
FIXED-POSITION, unrotated) with a straight face of the rotating SHAPE in CONFIGURATION,
whatever its gap (the caller keeps those it can reach)."
  (loop for (feature . corner) in (fixed-corners fixed-shape)
        append (loop for (name start end unbounded) in (shape-faces shape)
                     unless unbounded
                       collect (face-on-vertex decider start end (v+ fixed-position corner)
                                               configuration
                                               :feature name :other-feature feature))))

(defun rotating-body-contacts (decider shape configuration fixed-shape
                               &key (fixed-position (vec 0 0)))
  "Every contact of the rotating SHAPE in CONFIGURATION with the fixed FIXED-SHAPE at
FIXED-POSITION: its corners on the fixed faces (CORNER-CONTACTS), then the fixed corners
on its faces (FIXED-CORNER-CONTACTS)."
  (append (corner-contacts decider shape configuration fixed-shape :fixed-position fixed-position)
          (fixed-corner-contacts decider shape configuration fixed-shape
                                 :fixed-position fixed-position)))
