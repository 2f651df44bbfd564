;;;; src/kb/rotation.lisp -- rigid bodies that rotate (thesis 3.3.2, "Rotational Dynamics"): their
;;;; angle and angular velocity, the angular-momentum law about the centre of mass, the moments of
;;;; the forces that act at a point, and a disc's contact point.
;;;;
;;;; THE VOCABULARY this file adds (for the components of other phenomena: hinges, wound
;;;; ropes, rotating polygons):
;;;;   entity   (body NAME :fixed NIL :mass M :rotating T :inertia I :radius R)
;;;;            a rotating body (the simulator adds :rotating, :inertia and, for a (circle R)
;;;;            shape, :radius); I is about the centre of mass, the body's reference point
;;;;   quantity terms
;;;;     (angle B)      B's orientation theta, counter-clockwise, radians (0 = as drawn)
;;;;     (angvel B)     its angular velocity omega = d theta/dt (a state variable, like
;;;;                    (angle B): the simulator carries both over between states)
;;;;     (angacc B)     its angular acceleration alpha = d omega/dt
;;;;     (moment . F)   the moment about B's centre of mass of the force named F acting on
;;;;                    the rotating body B, e.g. (moment friction contact-0): r x F, its
;;;;                    z component (counter-clockwise positive)
;;;;     (rotational-energy B)   (1/2) I omega^2, reported as the kinetic energy term
;;;;                    (:kinetic (:rotation B) E) beside B's translational (:kinetic B E)
;;;;     (angular-momentum B)    about the origin, reported as (:angular-momentum B L) in
;;;;                    the :momentum section
;;;;   belief   (acts-at F :on B)   the force F on the rotating body B acts at a point of it
;;;;            and (moment . F) is defined: every such moment enters B's angular-momentum
;;;;            law. A component applying a force at a point (a rope wound on a disc, a
;;;;            hinge) asserts it and defines the moment, with the template
;;;;            (moment-at-point B (PX PY) F) for a point of B's own frame, or
;;;;            (moment-about ARM F), ARM the point's offset (RX RY) from the centre as
;;;;            expressions (not template forms: a template gets its arguments unexpanded).
;;;;   templates
;;;;     (inertia B)                      B's moment of inertia about its centre of mass
;;;;     (sum-of-moments FORCES)          the sum of the moments of the forces FORCES
;;;;     (moment-about (RX RY) F)         RX (fy . F) - RY (fx . F), RX RY expressions
;;;;     (moment-at-contact K B F)        F's moment about B's centre, F acting at contact
;;;;                                      K's point (functions: CONTACT-ARM)
;;;;     (moment-at-point B (PX PY) F)    F's moment, F acting at B's own point (PX PY)
;;;;                                      turned by (angle B) (function: TURNED-ARM)
;;;;     (slip-speed K) (slip-acc K)      friction.lisp's slip: the relative velocity and
;;;;                                      its rate of the two contact points along K's tangent
;;;;
;;;; A disc's contact point (a disc on a face, on a vertex, on another disc) lies on its rim
;;;; along the contact normal: the observer's at its centre minus R times the outward normal,
;;;; the obstacle's at its centre plus R times it. Since the outward normal is the unit
;;;; tangent turned a quarter turn clockwise, r x t = -R for the observer's point and +R for
;;;; the obstacle's: the slip along the tangent is (path-speed K) - R_A omega_A - R_B omega_B,
;;;; exactly, on a straight or a curved contact, and its rate is the same with the
;;;; accelerations. A rotating body that is not a disc has no contact point here yet (the
;;;; simulator refuses it in a contact): a rotating polygon's vertex on a face extends
;;;; CONTACT-ARM (its arm R(theta) v) and SPIN-ALONG-TANGENT (omega (r x t), whose rate then
;;;; also has omega's and t's turning in it).

(in-package #:ames.kb)

;;; Template functions

(defun body-entity-property (situation body key)
  "KEY of the body entity BODY of SITUATION."
  (entity-property (entity-named situation body) key))

(defun rotating-body-p (situation body)
  "True when BODY is a rotating (and not fixed) body of SITUATION."
  (and (body-entity-property situation body :rotating)
       (not (body-entity-property situation body :fixed))))

(defun disc-radius (situation body contact)
  "The radius of the rotating disc BODY in CONTACT; an UNMODELLED-SITUATION for a rotating
body that is not a disc (its contact point turns with it: not modelled here)."
  (or (body-entity-property situation body :radius)
      (error 'unmodelled-situation
             :datum body
             :detail (format nil "~A rotates and is not a disc: the point where it touches in ~A ~
                                  is not modelled yet" body contact))))

(defun contact-arm (situation contact body)
  "The offset (RX RY) from the rotating BODY's centre to the point of CONTACT (see the file
header): -R n for the observer disc, +R n for the obstacle disc, n the outward normal at
the contact's current arc length."
  (let ((geometry (contact-geometry situation contact)))
    ;; a corner contact's geometry knows its own arm (corners.lisp)
    (when (ames.geometry:rotating-contact-p geometry)
      (return-from contact-arm (ames.geometry:rotating-contact-arm geometry))))
  (let* ((entity (entity-named situation contact))
         (observer (entity-property entity :observer))
         (normal (ames.geometry:contact-outward-normal (contact-geometry situation contact)
                                                       (list 'path-position contact)))
         (radius (disc-radius situation body contact))
         (factor (if (eq body observer) `(- ,radius) radius)))
    (mapcar (lambda (n) `(* ,factor ,n)) normal)))

(defun moment-about (situation arm force)
  "Template MOMENT-ABOUT: the moment r x F of the force named FORCE applied at the offset
ARM, a list (RX RY) of expressions."
  (declare (ignore situation))
  (destructuring-bind (rx ry) arm
    `(- (* ,rx ,(cons 'fy force)) (* ,ry ,(cons 'fx force)))))

(defun moment-at-contact (situation contact body force)
  "Template MOMENT-AT-CONTACT: the moment about BODY's centre of FORCE acting at
CONTACT's point (see CONTACT-ARM)."
  (moment-about situation (contact-arm situation contact body) force))

(defun moment-at-point (situation body point force)
  "Template MOMENT-AT-POINT: the moment about BODY's centre of FORCE acting at BODY's own
point POINT (PX PY), turned with the body (see TURNED-ARM)."
  (moment-about situation (turned-arm situation body point) force))

(defun turned-arm (situation body point)
  "BODY's own point POINT (PX PY) turned by its current angle (angle BODY)."
  (declare (ignore situation))
  (destructuring-bind (px py) point
    (let ((c `(cos (angle ,body))) (s `(sin (angle ,body))))
      (list `(- (* ,c ,px) (* ,s ,py)) `(+ (* ,s ,px) (* ,c ,py))))))

(defun spin-along-tangent (situation contact rate-head)
  "The part the bodies' rotation adds to the relative motion of CONTACT's two points
along its tangent: - R_A (RATE-HEAD A) - R_B (RATE-HEAD B) over the rotating discs A
(observer) and B (obstacle) (see the file header), as a list of terms (NIL when neither
rotates)."
  (let ((entity (entity-named situation contact)))
    (loop for body in (list (entity-property entity :observer) (entity-property entity :obstacle))
          when (rotating-body-p situation body)
            collect `(- (* ,(disc-radius situation body contact) (,rate-head ,body))))))

(defun slip-speed (situation contact)
  "Template SLIP-SPEED: the velocity of the observer's contact point relative to the
obstacle's along CONTACT's unit tangent; (path-speed CONTACT) when neither body rotates."
  (let ((spin (spin-along-tangent situation contact 'angvel)))
    (if spin
        `(+ (path-speed ,contact) ,@spin)
        (list 'path-speed contact))))

(defun slip-acc (situation contact)
  "Template SLIP-ACC: the rate of SLIP-SPEED; (path-acc CONTACT :tangential) when neither
body rotates."
  (let ((spin (spin-along-tangent situation contact 'angacc)))
    (if spin
        `(+ (path-acc ,contact :tangential) ,@spin)
        (list 'path-acc contact :tangential))))

(defun sum-of-moments (situation forces)
  "Template SUM-OF-MOMENTS: the sum of the moments (moment . F) of FORCES."
  (declare (ignore situation))
  (if forces (cons '+ (mapcar (lambda (force) (cons 'moment force)) forces)) 0))

(defun register-rotation-templates (kb)
  "Register in KB the template functions of rotation (see the file header)."
  (register-template kb 'inertia (lambda (situation body) (body-entity-property situation body :inertia))
                     :documentation "A rotating body's moment of inertia about its centre of mass.")
  (register-template kb 'moment-of (force-component-term 'moment)
                     :documentation "The moment of a named force about its body's centre.")
  (register-template kb 'moment-about #'moment-about
                     :documentation "The moment of a force applied at an offset from the centre.")
  (register-template kb 'moment-at-contact #'moment-at-contact
                     :documentation "The moment of a contact's force about a rotating disc's centre.")
  (register-template kb 'moment-at-point #'moment-at-point
                     :documentation "The moment of a force acting at a body's own point.")
  (register-template kb 'slip-speed #'slip-speed
                     :documentation "The relative velocity of a contact's two points along its tangent.")
  (register-template kb 'slip-acc #'slip-acc
                     :documentation "The rate of the slip speed.")
  (register-template kb 'sum-of-moments #'sum-of-moments
                     :documentation "The sum of the moments of a list of forces."))

(register-rotation-templates *mechanics*)

;;; Components

(defcomponent kinematics-of-a-rotating-body (:knowledge-base *mechanics*)
  "A rotating body's angular velocity is the rate of its angle, its angular acceleration
the rate of its angular velocity: its angle and angular velocity are state variables,
integrated like a position and a velocity."
  (:arguments (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (derivative (angle ?body) (angvel ?body))
           (derivative (angvel ?body) (angacc ?body))))

(defcomponent angular-momentum-law (:knowledge-base *mechanics*)
  "The rate of a rotating body's angular momentum about its centre of mass is the sum of
the moments about it of the forces that act at its points: I alpha = sum of r x F
(the weight, and a force at the centre, have none)."
  (:arguments (?body :entity body :where (:fixed nil :rotating t))
              (?forces :collect ?f :matching (acts-at ?f :on ?body)))
  (:equations (= (sum-of-moments ?forces) (* (inertia ?body) (angacc ?body)))))

(defcomponent moment-of-a-contact-force (:knowledge-base *mechanics*)
  "A contact's forces (the normal force, friction) act on a rotating disc at the contact
point: their moment about its centre is r x F, r from the centre to that point. (Other
interactions that pair their forces by a :contact key, a spring's span, are not contacts
of shapes: where they act is theirs to say.)"
  (:arguments (?force :belief (force ?force :on ?body :contact ?contact))
              (?contact :entity simple-contact)
              (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (acts-at ?force :on ?body))
  (:equations (= (moment-of ?force) (moment-at-contact ?contact ?body ?force))))

(defcomponent moment-of-an-applied-force (:knowledge-base *mechanics*)
  "A force given to act at a point (PX PY) of a rotating body (its own frame) keeps its
world components as the body turns: its moment about the centre is R(theta) p x F."
  (:arguments (?force :entity external-force :where (:on ?body :at (?px ?py)))
              (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (acts-at (external ?force) :on ?body))
  (:equations (= (moment-of (external ?force))
                 (moment-at-point ?body (?px ?py) (external ?force)))))

(defcomponent rotational-energy-and-angular-momentum (:knowledge-base *mechanics*)
  "A rotating body's kinetic energy of rotation is (1/2) I omega^2, a kinetic energy term
of its own beside the translational one (energy.lisp), so that the sum of the energy
terms stays the system's energy; its angular momentum about the origin is
I omega + m (x vy - y vx)."
  (:arguments (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (reported :energy (:kinetic (:rotation ?body) (rotational-energy ?body)))
           (reported :momentum (:angular-momentum ?body (angular-momentum ?body))))
  (:equations (= (rotational-energy ?body)
                 (* 1/2 (inertia ?body) (expt (angvel ?body) 2)))
              (= (angular-momentum ?body)
                 (+ (* (inertia ?body) (angvel ?body))
                    (* (mass ?body) (- (* (pos ?body :x) (vel ?body :y))
                                       (* (pos ?body :y) (vel ?body :x))))))))

;; The angular momentum about the origin is a kind of momentum term of its own (terms.lisp).
;; The query (angular-momentum B) asks for it (a rotating body's: the scenario layer refuses
;; it of another, whose angular momentum no component reports).
(define-reported-term :angular-momentum :section :momentum :label "angular momentum total"
                                        :query :angular-momentum)

(define-phenomenon rotation
  "Rigid bodies that rotate (a body with an :inertia): their angle and angular velocity,
the moments of the forces acting at their points, rotational energy, angular momentum.
Rolling is friction's static mode at a disc's contact (friction.lisp).")
