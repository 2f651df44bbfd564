;;;; src/geometry/package.lisp -- shapes, configuration-space contacts and path coordinates.

(defpackage #:ames.geometry
  (:use #:cl #:ames.base)
  (:import-from #:ames.algebra #:constant-sign)
  (:documentation "Shapes, configuration-space obstacles split into simple contacts,
and path coordinates (thesis sections 2.5.2 and 2.5.7).

Conventions: the relative position of a pair is q = position(observer) -
position(obstacle), in the obstacle's (non-rotating) frame. A simple contact is
directed with the obstacle on its left; its outward normal (the unit tangent turned
clockwise) is the direction in which the normal force pushes the observer. Arc length s
runs from 0 at the contact's start. Curvature is positive when the contact bends toward
the obstacle; path acceleration = sddot T + sdot^2 K N, N the inward normal.

Entry points, in the order a simulator uses them (pass the Maxima bridge as :BRIDGE
and call inside ames.maxima:with-assumptions for symbolic shapes):
  PARSE-SHAPE form                        -> SHAPE (signals INVALID-SHAPE)
  MAKE-CONTACT-PAIR n1 s1 n2 s2           -> CONTACT-PAIR (observer chosen by
                                             CHOOSE-OBSERVER), PAIR-CONTACTS
  RELATIVE-POSITION, CHECK-SEPARATION /
  PENETRATES-P pair q                     -> invalid (overlapping) starts
  CONTACTS-AT pair q                      -> ((contact . s) ...) holding at q
  CONTACT-OUTWARD-NORMAL / -NORMAL-ANGLE  -> normal force direction at s
  CONTACT-POINT, -UNIT-TANGENT, -CURVATURE, PATH-VELOCITY, PATH-ACCELERATION
  CONTACT-MEETING                         -> the conditions for q(tau) to meet a contact
  CONTACT-LEAVINGS                        -> the conditions for s(tau) to pass an end
(when they first hold is the simulator's question: src/simulator/termination.lisp)")
  (:export
   ;; the one toolkit of plane vectors, lists (X Y) of expressions (vectors.lisp)
   #:vec #:vx #:vy #:v+ #:v- #:vneg #:vscale #:vdiv #:dot #:cross #:norm-squared #:vector-length
   ;; conditions
   #:geometry-error #:invalid-shape #:invalid-shape-form
   #:undecidable-geometric-fact #:undecidable-fact #:undecidable-subject
   #:assume-true #:assume-false
   #:unsupported-shape-pair #:unsupported-observer #:unsupported-obstacle
   #:position-not-on-contact #:position-contact
   #:bodies-overlap #:overlap-observer #:overlap-obstacle
   ;; shapes
   #:parse-shape #:shape #:shape-form #:shape-kind #:shape-convex-p #:shape-area
   #:shape-surface-p #:shape-closed-p
   ;; pairs of bodies
   #:choose-observer #:make-contact-pair #:make-contact-pair-with-observer
   #:call-with-prefetched-contact-pairs
   #:contact-pair #:pair-observer #:pair-obstacle #:pair-observer-shape
   #:pair-obstacle-shape #:pair-contacts
   #:relative-position #:contacts-at #:penetrates-p #:check-separation
   ;; simple contacts
   #:simple-contact #:contact-kind #:contact-index
   #:contact-observer #:contact-obstacle
   #:contact-observer-feature #:contact-obstacle-feature
   #:contact-description #:feature-description
   #:contact-length #:contact-start #:contact-end #:contact-center #:contact-radius
   #:contact-curvature #:contact-sense #:contact-neighbours
   #:contact-point #:contact-unit-tangent #:contact-outward-normal #:contact-inward-normal
   #:contact-tangent-angle #:contact-normal-angle
   #:position-on-contact-p #:contact-parameter #:contact-touching-point
   ;; path coordinates
   #:path-velocity #:path-acceleration #:differentiate
   ;; meeting and leaving contacts
   #:contact-meeting #:meeting #:make-meeting #:meeting-contact #:meeting-gap #:meeting-rate
   #:meeting-extent #:meeting-conditions
   #:contact-leavings #:leaving #:leaving-contact #:leaving-endpoint #:leaving-point
   #:leaving-equation #:leaving-direction #:leaving-neighbour
   ;; contacts of a rotating body, functions of (x, y, theta) (rotating-contacts.lisp)
   #:rotated #:make-configuration #:configuration #:configuration-x #:configuration-y
   #:configuration-theta #:configuration-centre #:body-point
   #:rotating-contact #:rotating-contact-p #:rotating-contact-kind #:rotating-contact-feature
   #:rotating-contact-other-feature #:rotating-contact-configuration #:rotating-contact-point
   #:rotating-contact-arm #:rotating-contact-gap #:rotating-contact-normal
   #:rotating-contact-tangent #:rotating-contact-place #:rotating-contact-extent
   #:vertex-on-face #:face-on-vertex
   #:contact-point-velocity #:contact-gap-rate #:contact-slip-velocity #:contact-slip-acceleration
   #:contact-gap-acceleration #:contact-torque
   #:shape-corners #:shape-faces #:corner-contacts #:corner-touching-p #:resting-face-contacts
   ;; every contact of a rotating body with a fixed one, within the faces (fixed-corners.lisp)
   #:contact-extent-relations #:fixed-corners #:fixed-corner-contacts #:rotating-body-contacts))
