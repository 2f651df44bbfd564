;;;; src/geometry/package.lisp -- shapes, configuration-space contacts and path coordinates.

(defpackage #:ames.geometry
  (:use #:cl #:ames.base)
  (:documentation "Shapes, configuration-space obstacles split into simple contacts,
and path coordinates. Relative positions follow one convention: q = position(observer)
- position(obstacle), in the obstacle's (non-rotating) frame. Simple contacts are
directed with the obstacle on their left; their outward normal is the direction in
which the normal force pushes the observer.")
  (:export
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
   #:position-on-contact-p #:contact-parameter
   ;; path coordinates
   #:path-velocity #:path-acceleration
   ;; meeting and leaving contacts
   #:contact-meeting #:meeting #:meeting-contact #:meeting-gap #:meeting-rate
   #:meeting-extent #:meeting-conditions
   #:contact-leavings #:leaving #:leaving-contact #:leaving-endpoint #:leaving-point
   #:leaving-equation #:leaving-direction #:leaving-neighbour
   #:earliest-meeting #:earliest-leaving))
