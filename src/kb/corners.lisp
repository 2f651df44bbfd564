;;;; src/kb/corners.lisp -- a corner touching a straight face, one of the two bodies rotating
;;;; and the other fixed: a ladder's ends on its wall and floor, a block resting on an
;;;; incline by its two bottom corners, a block tipping about one; and a fixed corner on a
;;;; rotating body's face (a rod landing across a ledge's edge, then resting on it).
;;;;
;;;; The simulator describes each such pair as an entity (it finds the corners and faces;
;;;; ames.geometry's rotating-contacts.lisp and fixed-corners.lisp give their geometry as
;;;; functions of the rotating body's configuration, whichever body has the corner):
;;;;   (corner-contact K :observer A :obstacle B :geometry C :mates (K ...))
;;;;       A the rotating body, B the fixed one, C an AMES.GEOMETRY:ROTATING-CONTACT whose
;;;;       expressions are over (pos A :x), (pos A :y) and (angle A); MATES the corners of A
;;;;       on the same face touching at the state's start (friction.lisp needs them).
;;;; The corner touches while its gap is 0 and it lies within the face (0 <= place <=
;;;; extent: a corner on the face's line past its end touches nothing, and reaching the
;;;; line there is no collision); it pushes A along the face's normal with the
;;;; magnitude (normal-force K), at the corner (a moment about A's centre: rotation.lisp's
;;;; moment of a contact force, whose arm the geometry gives); the restriction keeps the
;;;; gap's second derivative zero. The contact ends when the normal force would turn
;;;; attractive, (:lift-off A B): a ladder leaving its wall, a block's corner rising as it
;;;; tips about the other one; or when the corner slides past an end of a bounded face.
;;;; A flat face resting on a face is two such contacts (why: rotating-contacts.lisp).
;;;; Quantity terms are those of mechanics.lisp (normal-force K) and rotation.lisp.

(in-package #:ames.kb)

(defun corner-geometry (situation contact)
  "The AMES.GEOMETRY:ROTATING-CONTACT of the corner contact entity CONTACT."
  (entity-property (entity-named situation contact) :geometry))

(defun corner-rates (situation contact)
  "The rotating body's velocity, angular velocity, acceleration and angular acceleration
terms, as four values, for the corner CONTACT's observer."
  (let ((body (entity-property (entity-named situation contact) :observer)))
    (values (list `(vel ,body :x) `(vel ,body :y)) `(angvel ,body)
            (list `(acc ,body :x) `(acc ,body :y)) `(angacc ,body))))

(defun corner-touching (situation contact)
  "Template CORNER-TOUCHING: the corner is on the face's line, (= GAP 0): at the start
of a state where it touches with no normal velocity, whether the contact holds is the
consistency search's choice (a block's uphill corner rises at once when it tips); later it
is reached as the gap closes."
  (list '= (ames.geometry:rotating-contact-gap (corner-geometry situation contact)) 0))

(defun corner-within-face (situation contact end)
  "Template CORNER-WITHIN-FACE: the corner is not past the face's END (:START or :END):
(>= PLACE 0) or (<= PLACE EXTENT); (>= 1 0), true, on a half-plane's unbounded line."
  (let ((relations (ames.geometry:contact-extent-relations (corner-geometry situation contact))))
    (if relations
        (ecase end (:start (first relations)) (:end (second relations)))
        '(>= 1 0))))

(defun corner-past-an-end (situation contact)
  "Template CORNER-PAST-AN-END: the corner has slid past an end of a bounded face; never
(an empty disjunction) on a half-plane's line."
  (let* ((geometry (corner-geometry situation contact))
         (place (ames.geometry:rotating-contact-place geometry))
         (extent (ames.geometry:rotating-contact-extent geometry)))
    (if extent
        `(or (< ,place 0) (> ,place ,extent))
        '(or))))

(defun corner-gap-acceleration (situation contact)
  "Template CORNER-GAP-ACCELERATION: the second time derivative of the corner's gap."
  (multiple-value-bind (velocity omega acceleration alpha) (corner-rates situation contact)
    (ames.geometry:contact-gap-acceleration (corner-geometry situation contact)
                                            velocity omega acceleration alpha)))

(defun corner-slip-speed (situation contact)
  "Template CORNER-SLIP-SPEED: the corner's velocity along the face's tangent."
  (multiple-value-bind (velocity omega) (corner-rates situation contact)
    (ames.geometry:contact-slip-velocity (corner-geometry situation contact) velocity omega)))

(defun corner-slip-acc (situation contact)
  "Template CORNER-SLIP-ACC: the rate of CORNER-SLIP-SPEED."
  (multiple-value-bind (velocity omega acceleration alpha) (corner-rates situation contact)
    (ames.geometry:contact-slip-acceleration (corner-geometry situation contact) omega acceleration alpha
                                             velocity)))

(defun register-corner-templates (kb)
  "Register in KB the template functions of corner contacts."
  (register-template kb 'corner-slip-speed #'corner-slip-speed
                     :documentation "A corner's velocity along the face it touches.")
  (register-template kb 'corner-slip-acc #'corner-slip-acc
                     :documentation "The rate of a corner's velocity along the face.")
  (register-template kb 'corner-touching #'corner-touching
                     :documentation "A rotating body's corner is on or behind a face's line.")
  (register-template kb 'corner-within-face #'corner-within-face
                     :documentation "The corner is not past one end of the face.")
  (register-template kb 'corner-past-an-end #'corner-past-an-end
                     :documentation "The corner has slid past an end of the face.")
  (register-template kb 'corner-gap-acceleration #'corner-gap-acceleration
                     :documentation "The second time derivative of the corner's gap.")
  (register-template kb 'corner-normal
                     (lambda (situation contact axis)
                       (axis-component (ames.geometry:rotating-contact-normal
                                        (corner-geometry situation contact))
                                       axis))
                     :documentation "The unit normal along which the face pushes the corner.")
  (register-template kb 'corner-tangent
                     (lambda (situation contact axis)
                       (axis-component (ames.geometry:rotating-contact-tangent
                                        (corner-geometry situation contact))
                                       axis))
                     :documentation "The unit tangent of the face at the corner."))

(register-corner-templates *mechanics*)

(defcomponent corner-contact (:knowledge-base *mechanics*)
  "A rotating body's corner touches a fixed face, or a fixed corner the rotating body's
face, while its gap is zero and it lies within the face (a corner reaching the face's
line past its end meets nothing). The contact ends
when keeping it would need an attractive normal force (the corner lifts off: a ladder
leaves its wall, a block tips about its other corner) or when the corner slides past an
end of the face."
  (:arguments (?contact :entity corner-contact :where (:observer ?body1 :obstacle ?body2)))
  (:activation (corner-touching ?contact)
               (corner-within-face ?contact :start) (corner-within-face ?contact :end)
               (:event (:contact ?body1 ?body2) :impact (:collision ?body1 ?body2)))
  (:deactivation (:when (< (normal-force ?contact) 0) :event (:lift-off ?body1 ?body2))
                 (:when (corner-past-an-end ?contact) :event (:leaves ?body1 ?body2 :endpoint)))
  (:assert (corner-in-contact ?body1 ?body2 :at ?contact)))

(defcomponent corner-normal-force (:knowledge-base *mechanics*)
  "A touching corner is pushed along the face's normal by a compensating force, whose
magnitude keeps the corner on the face: the gap's second derivative is zero. It acts at
the corner, so it has a moment about the body's centre (rotation.lisp)."
  (:arguments (?contact :belief (corner-in-contact ?body1 ?body2 :at ?contact)))
  (:assert (force (normal ?contact) :type normal :from ?body2 :on ?body1 :contact ?contact)
           (reported :forces (:normal ?body1 ?body2 (normal-force ?contact))))
  (:equations (= (force-x (normal ?contact))
                 (* (normal-force ?contact) (corner-normal ?contact :x)))
              (= (force-y (normal ?contact))
                 (* (normal-force ?contact) (corner-normal ?contact :y)))
              (= (corner-gap-acceleration ?contact) 0)))

(defcomponent moment-of-a-corner-force (:knowledge-base *mechanics*)
  "A corner contact's forces (its normal force, a friction on it) act on the rotating body
at the corner: their moment about its centre is r x F, r the corner's arm from the centre
(the geometry's, see rotation.lisp's MOMENT-AT-CONTACT)."
  (:arguments (?force :belief (force ?force :on ?body :contact ?contact))
              (?contact :entity corner-contact)
              (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (acts-at ?force :on ?body))
  (:equations (= (moment-of ?force) (moment-at-contact ?contact ?body ?force))))
