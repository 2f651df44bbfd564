;;;; src/geometry/rotating-contacts.lisp -- contacts of a rotating body with a fixed one as
;;;; functions of its configuration (x, y, theta).
;;;;
;;;; A rotating body's configuration is the position (x, y) of its centre of mass and its
;;;; angle theta (counter-clockwise); its shape is given relative to the centre of mass at
;;;; theta = 0, so a point p of its own frame is at (x, y) + R(theta) p in the world.
;;;; Two kinds of contact with a fixed body's straight face are built here, each as
;;;; expressions of the configuration (any expressions: names, quantity terms):
;;;;   :VERTEX-ON-FACE  a corner of the rotating body (a polygon's vertex, a segment's end)
;;;;                    on a fixed straight face (a polygon's edge, a half-plane's line);
;;;;   :FACE-ON-VERTEX  a fixed corner on a straight face of the rotating body.
;;;; Each contact gives the contact POINT, the moment ARM (point - centre of mass), the
;;;; GAP (signed distance, positive apart, 0 touching), the unit NORMAL along which the
;;;; normal force pushes the rotating body, the unit TANGENT (the normal turned a quarter
;;;; turn counter-clockwise), and the PLACE along the face (0 at its start, the face's
;;;; EXTENT at its end; no extent for a half-plane's unbounded line): the contact holds
;;;; while 0 <= place <= extent. Velocities: with u = v + omega k x arm the velocity of the
;;;; body's material point at the contact point, the gap's rate is u . normal for both
;;;; kinds (the fixed body is at rest) and the slip velocity u . tangent; the gap's second
;;;; derivative is in CONTACT-GAP-ACCELERATION.
;;;;
;;;; A flat face resting on a fixed face (a block on a floor or an incline) is two
;;;; :VERTEX-ON-FACE contacts, one at each end of the face (RESTING-FACE-CONTACTS), not one
;;;; face contact with a pressure centre. Why: each vertex contact has its own normal
;;;; force, and N1 >= 0, N2 >= 0 is exactly the condition that the pressure centre lies
;;;; within the face (it sits at (N1 p1 + N2 p2)/(N1 + N2)); tipping is then one of the two
;;;; normal forces reaching 0, the ordinary lift-off event (:lift-off A B) that every
;;;; contact already has, and the state after it keeps the other vertex as a pivot that
;;;; needs nothing new. A face contact would need a second kind of condition (the pressure
;;;; centre leaving the face) and a mode change into a vertex contact anyway. The price:
;;;; with friction the two tangential forces are statically indeterminate, but they act
;;;; on one line (the face), so only their sum enters the motion and the torque.

(in-package #:ames.geometry)

(defun rotated (v theta)
  "The vector V turned counter-clockwise by the angle THETA: R(THETA) V."
  (let ((c (ecos theta)) (s (esin theta)))
    (vec (e- (e* c (vx v)) (e* s (vy v)))
         (e+ (e* s (vx v)) (e* c (vy v))))))

(defstruct (configuration (:constructor make-configuration (x y theta)))
  "A rotating body's configuration: its centre of mass at (X, Y), its angle THETA
(counter-clockwise from its own frame), each a prefix expression."
  x y theta)

(defun configuration-centre (configuration)
  "The centre of mass (X Y) of CONFIGURATION."
  (vec (configuration-x configuration) (configuration-y configuration)))

(defun body-point (configuration local)
  "The world position of the point LOCAL of the body's own frame in CONFIGURATION."
  (v+ (configuration-centre configuration) (rotated local (configuration-theta configuration))))

(defstruct (rotating-contact (:constructor %make-rotating-contact
                                 (kind feature other-feature configuration point arm gap
                                  normal tangent place extent &optional face-start)))
  "A contact of a rotating body with a fixed body's straight face or corner (see the
file header): KIND (:VERTEX-ON-FACE or :FACE-ON-VERTEX), the rotating body's FEATURE and
the fixed body's OTHER-FEATURE (feature names as in shapes.lisp, or NIL), the
CONFIGURATION, and the expressions POINT, ARM, GAP, NORMAL, TANGENT, PLACE and EXTENT
(NIL for an unbounded face). For :FACE-ON-VERTEX, FACE-START is the world position of
the rotating face's start (its gap is measured from it)."
  kind feature other-feature configuration point arm gap normal tangent place extent face-start)

(defun vertex-on-face (decider vertex face-start face-end configuration
                       &key feature other-feature unbounded)
  "The :VERTEX-ON-FACE contact of the rotating body's corner VERTEX (its own frame) with
the fixed straight face from FACE-START to FACE-END (world frame, the solid on its left,
as a boundary piece), the body in CONFIGURATION. UNBOUNDED when the face is the whole
line (a half-plane): no extent. DECIDER (or a bridge) decides the face's direction
when it has a symbolic length; FEATURE and OTHER-FEATURE name what touches."
  (let* ((decider (ensure-decider decider))
         (direction (v- face-end face-start))
         (tangent (unit-vector decider direction))
         (normal (rot-cw tangent))
         (arm (rotated vertex (configuration-theta configuration)))
         (point (v+ (configuration-centre configuration) arm))
         (offset (v- point face-start)))
    (%make-rotating-contact :vertex-on-face feature other-feature configuration point arm
                            (dot offset normal) normal tangent (dot offset tangent)
                            (and (not unbounded) (vector-length direction)))))

(defun face-on-vertex (decider face-start face-end corner configuration
                       &key feature other-feature)
  "The :FACE-ON-VERTEX contact of the fixed CORNER (world frame) with the rotating
body's straight face from FACE-START to FACE-END (its own frame, its solid on the left),
the body in CONFIGURATION. The normal force pushes the body along minus the face's
outward normal."
  (let* ((decider (ensure-decider decider))
         (theta (configuration-theta configuration))
         (local-direction (v- face-end face-start))
         (face-tangent (rotated (unit-vector decider local-direction) theta))
         (outward (rot-cw face-tangent))
         (start (body-point configuration face-start))
         (offset (v- corner start))
         (normal (vneg outward)))
    (%make-rotating-contact :face-on-vertex feature other-feature configuration corner
                            (v- corner (configuration-centre configuration))
                            (dot offset outward) normal (rot-ccw normal) (dot offset face-tangent)
                            (vector-length local-direction) start)))

;;; Velocities and accelerations

(defun contact-point-velocity (contact velocity omega)
  "The velocity of the rotating body's material point at CONTACT's point when its centre
of mass moves with VELOCITY (a vector) and it turns at OMEGA: v + omega k x arm."
  (v+ velocity (vscale omega (rot-ccw (rotating-contact-arm contact)))))

(defun contact-gap-rate (contact velocity omega)
  "The time derivative of CONTACT's gap: the contact point's velocity along the normal."
  (dot (contact-point-velocity contact velocity omega) (rotating-contact-normal contact)))

(defun contact-slip-velocity (contact velocity omega)
  "The velocity with which the rotating body slides along the fixed one at CONTACT's
point, along the contact's tangent (0 when it rolls or rests)."
  (dot (contact-point-velocity contact velocity omega) (rotating-contact-tangent contact)))

(defun contact-slip-acceleration (contact omega acceleration alpha &optional velocity)
  "The rate of CONTACT's slip velocity. A corner on a fixed face (its tangent fixed):
(a + alpha k x r - omega^2 r) . t. A fixed corner on the body's face (VELOCITY, the
centre's, needed): the derivative of u . t with u = v + omega k x (P - c), P fixed, and
t turning at omega: (a + alpha k x r - omega k x v) . t + u . (omega k x t)."
  (let ((arm (rotating-contact-arm contact))
        (tangent (rotating-contact-tangent contact)))
    (ecase (rotating-contact-kind contact)
      (:vertex-on-face
       (dot (v+ acceleration (vscale alpha (rot-ccw arm)) (vscale (e- (e* omega omega)) arm))
            tangent))
      (:face-on-vertex
       (let ((u (contact-point-velocity contact velocity omega)))
         (e+ (dot (v+ acceleration (vscale alpha (rot-ccw arm)) (vscale (e- omega) (rot-ccw velocity)))
                  tangent)
             (dot u (vscale omega (rot-ccw tangent)))))))))

(defun contact-gap-acceleration (contact velocity omega acceleration alpha)
  "The second time derivative of CONTACT's gap, for the centre's VELOCITY and
ACCELERATION and the angular velocity OMEGA and acceleration ALPHA. A corner on a fixed
face: (a + alpha k x r - omega^2 r) . n (n fixed). A fixed corner on the body's face:
the derivative of -(v + omega k x (P - c)) . n_b, whose normal n_b turns at omega."
  (let ((arm (rotating-contact-arm contact))
        (normal (rotating-contact-normal contact)))
    (ecase (rotating-contact-kind contact)
      (:vertex-on-face
       (dot (v+ acceleration (vscale alpha (rot-ccw arm)) (vscale (e- (e* omega omega)) arm))
            normal))
      (:face-on-vertex
       ;; gap' = u . normal with u = v + omega k x (P - c), P fixed: (P - c)' = -v and
       ;; normal' = omega k x normal
       (let ((u (contact-point-velocity contact velocity omega)))
         (e+ (dot (v+ acceleration (vscale alpha (rot-ccw arm)) (vscale (e- omega) (rot-ccw velocity)))
                  normal)
             (dot u (vscale omega (rot-ccw normal)))))))))

(defun contact-torque (contact force)
  "The torque about the centre of mass (counter-clockwise positive) of FORCE (a vector)
acting at CONTACT's point: arm x force."
  (cross (rotating-contact-arm contact) force))

;;; Corners and resting faces

(defun shape-corners (shape)
  "The corners of SHAPE in its own frame, as an alist ((:VERTEX I) . POINT): a polygon's
vertices, a segment's two ends. Signals UNSUPPORTED-SHAPE-PAIR for other shapes (a
disc's contacts are its own)."
  (case (shape-kind shape)
    (:polygon (loop for v in (shape-vertices shape) for i from 0
                    collect (cons (list :vertex i) v)))
    (:segment (let ((piece (first (shape-boundary shape))))
                (list (cons '(:vertex 0) (line-piece-start piece))
                      (cons '(:vertex 1) (line-piece-end piece)))))
    (t (error 'unsupported-shape-pair
              :observer (shape-form shape) :obstacle nil
              :detail "only a polygon's vertices and a segment's ends are corners"))))

(defun shape-faces (shape)
  "The straight faces of SHAPE (its own frame or, for a fixed body, relative to its
reference point) as a list of (NAME START END UNBOUNDED): its line pieces."
  (loop for piece in (shape-boundary shape)
        when (line-piece-p piece)
          collect (list (line-piece-name piece) (line-piece-start piece) (line-piece-end piece)
                        (line-piece-infinite piece))))

(defun corner-contacts (decider shape configuration fixed-shape &key (fixed-position (vec 0 0)))
  "Every :VERTEX-ON-FACE contact of a corner of the rotating SHAPE (in CONFIGURATION) with
a straight face of FIXED-SHAPE (a body at rest at FIXED-POSITION, unrotated), whatever
its gap: the caller keeps those touching (gap 0, place within the extent) at the start."
  (loop for (feature . vertex) in (shape-corners shape)
        append (loop for (name start end unbounded) in (shape-faces fixed-shape)
                     collect (vertex-on-face decider vertex (v+ fixed-position start)
                                             (v+ fixed-position end) configuration
                                             :feature feature :other-feature name
                                             :unbounded unbounded))))

(defun corner-touching-p (decider contact)
  "True when CONTACT's gap is known to be 0 and its place known to lie within the face
(by arithmetic or the bridge, after simplification; an unbounded face has no ends); NIL when not, or not decided (a
start that touches must be provably touching). Never signals."
  (let* ((decider (ensure-decider decider))
         (place (tidy decider (rotating-contact-place contact)))
         (extent (rotating-contact-extent contact)))
    (and (fact-known-p decider (list '= (tidy decider (rotating-contact-gap contact)) 0))
         ;; an unbounded face has no ends
         (or (null extent)
             (and (fact-known-p decider (list '>= place 0))
                  (fact-known-p decider (list '<= place (tidy decider extent))))))))

(defun resting-face-contacts (decider shape configuration fixed-shape
                              &key (fixed-position (vec 0 0)))
  "The corner contacts of the rotating SHAPE with FIXED-SHAPE that touch in CONFIGURATION
(CORNER-TOUCHING-P): one for a corner on a face, two (the ends of the resting face, in corner
order) for a flat face resting on a face: see the file header for why two vertex
contacts and no face contact."
  (remove-if-not (lambda (contact) (corner-touching-p decider contact))
                 (corner-contacts decider shape configuration fixed-shape
                                  :fixed-position fixed-position)))
