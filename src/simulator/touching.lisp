;;;; src/simulator/touching.lisp -- where the bodies of a state's contacts touch, and the normal there.
;;;;
;;;; The run knows each contact's geometry and the bodies' positions at the start of a
;;;; state; the geometry layer says where the two bodies touch then
;;;; (AMES.GEOMETRY:CONTACT-TOUCHING-POINT). A state carries these points and normals
;;;; (STATE-CONTACT-POINTS) so that a report draws its contacts without deriving the
;;;; geometry again from the shape forms.

(in-package #:ames.simulator)

(defun contact-touching (run contact)
  "Where the bodies of the contact entity CONTACT touch at the start of the current
state, in the fixed frame: a plist (:POINT (X Y) :NORMAL (NX NY)), NORMAL the unit
normal from the obstacle (the second body of the contact's description) into the
observer (the first), both expressions; NIL for the locus of a point attached to a body
(a probe: see attachments.lisp) or where the features touching do not give a point."
  (unless (assoc contact (run-locus-kinds run))
    (destructuring-bind (observer obstacle) (contact-bodies run contact)
      (multiple-value-bind (point normal)
          (handler-case
              (ames.geometry:contact-touching-point (contact-geometry run contact)
                                                    (cdr (assoc observer (run-shapes run)))
                                                    (cdr (assoc obstacle (run-shapes run)))
                                                    (relative-initial-state run contact))
            ;; a contact chosen at the state's start lies on its locus; if it does not,
            ;; the state says nothing of where it touches rather than guess
            (ames.geometry:position-not-on-contact () nil))
        (when point
          (list :point (ames.geometry:v+ (body-position run obstacle) point) :normal normal))))))
