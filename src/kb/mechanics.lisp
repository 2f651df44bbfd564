;;;; src/kb/mechanics.lisp -- AMES's knowledge of frictionless translational mechanics.
;;;;
;;;; One DEFCOMPONENT per piece of the thesis's knowledge (sections 2.5.2-2.5.7 and figures
;;;; 2-6 to 2-9). The components own what the simulator must not know by name:
;;;;   - their EVENTS: each activation, deactivation and transition condition names the
;;;;     event it is, e.g. (:lift-off ?body1 ?body2), and the impulsive event it is when
;;;;     reached at a non-zero rate, e.g. (:collision ?body1 ?body2);
;;;;   - their DYNAMICS: (derivative X RATE) beliefs say that the state variable X changes
;;;;     at RATE (both quantity terms); the simulator gathers them into the state's ODEs,
;;;;     solves the rest of the model for the rates and picks an integrator;
;;;;   - their REPORT: (reported :forces ENTRY) beliefs are the entries of a state's force
;;;;     list, as the scenario language's output section writes them, with quantity terms
;;;;     that the simulator replaces by their values.
;;;; Each state's situation holds these entities (the simulator describes the bodies and the
;;;; contacts, each phenomenon what it makes of its clause: see phenomena.lisp):
;;;;   (body NAME :fixed T-or-NIL :mass EXPR [:driven T])   a driven body has no mass
;;;;   (gravity-field NAME :strength EXPR)                      pointing -y
;;;;   (external-force NAME :on BODY :fx EXPR :fy EXPR)
;;;;   (simple-contact K :observer A :obstacle B :geometry C)   C an ames.geometry contact
;;;;   (friction-coefficients F :between (A B) :static MU-S :kinetic MU-K)   see friction.lisp
;;;; and reads back equations over these quantity terms (fixed frame, cartesian unless said):
;;;;   (acc B :x)  (vel B :x)  (pos B :x)        acceleration, velocity, position of body B
;;;;   (rel-acc A B :x)                          A's acceleration measured in B's frame
;;;;   (fx KIND ...) (fy KIND ...)               components of the force named (KIND ...)
;;;;   (normal-force K)                          magnitude of contact K's normal force
;;;;   (path-acc K :tangential) (path-acc K :normal)   A's relative acceleration in contact K's
;;;;                                             path coordinates (normal: toward the obstacle)
;;;;   (path-position K) (path-speed K)          arc length s and its rate along contact K
;;;;                                             (the rate: the observer's velocity relative
;;;;                                             to the obstacle along the unit tangent)
;;;;   (friction-force K)                        the friction on the observer of contact K,
;;;;                                             its signed component along the unit tangent
;;;;   (contact-gap K)                           how far A is from contact K's locus (the
;;;;                                             geometry's gap: the simulator computes it)
;;;; The state variables are the positions and velocities of the free bodies and, on a
;;;; curved contact, the arc length and speed along it (path coordinates).
;;;; Forces are named by lists: (gravity B), (external F), (normal K) on the observer and
;;;; (reaction K) on the obstacle.

(in-package #:ames.kb)

(defvar *mechanics* (make-knowledge-base :name "mechanics"
                                         :documentation "Frictionless translational mechanics (Wong 1994, chapter 2).")
  "The mechanics knowledge base. The components below register themselves in it.")

(defun mechanics-knowledge-base ()
  "The knowledge base of AMES's mechanics."
  *mechanics*)

;;; Template functions: how the components read the situation

(defun entity-named (situation name)
  "The entity NAME of SITUATION (the simulator always describes every name it uses)."
  (find-entity situation name))

(defun contact-geometry (situation contact)
  "The ames.geometry simple contact behind the situation's contact entity CONTACT (a
symbol naming a SIMPLE-CONTACT entity of SITUATION)."
  (entity-property (entity-named situation contact) :geometry))

(defun axis-component (vector axis)
  "The :X or :Y component of the two-element VECTOR."
  (ecase axis (:x (first vector)) (:y (second vector))))

(defun force-component-term (head)
  "A template function turning a force name such as (normal 3) into the quantity term
(HEAD normal 3)."
  (lambda (situation force)
    (declare (ignore situation))
    (cons head force)))

(defun sum-of-forces (situation forces axis)
  "Template SUM-OF: the sum of the AXIS components of the forces named in FORCES."
  (declare (ignore situation))
  (let ((head (ecase axis (:x 'fx) (:y 'fy))))
    (if forces (cons '+ (mapcar (lambda (force) (cons head force)) forces)) 0)))

(defun along-contact (function)
  "A template function of (CONTACT AXIS) giving the AXIS component of the vector
FUNCTION returns for the contact's geometry at its current arc length (path-position)."
  (lambda (situation contact axis)
    (axis-component (funcall function (contact-geometry situation contact)
                             (list 'path-position contact))
                    axis)))

(defun contact-touching (situation contact)
  "Template TOUCHING: the relation saying that the observer lies on CONTACT's locus."
  (declare (ignore situation))
  (list '= (list 'contact-gap contact) 0))

(defun contact-endpoints-passed (situation contact)
  "Template PAST-AN-END: the relation saying that the observer has moved past an end of
CONTACT's locus; an empty disjunction (never) for a whole line or circle."
  (let* ((geometry (contact-geometry situation contact))
         (s (list 'path-position contact)))
    (if (member (ames.geometry:contact-kind geometry) '(:line :circle))
        '(or)
        (list 'or (list '< s 0) (list '> s (ames.geometry:contact-length geometry))))))

(defun register-mechanics-templates (kb)
  "Register in KB the template functions the mechanics components use."
  (flet ((property (key)
           (lambda (situation name) (entity-property (entity-named situation name) key))))
    (register-template kb 'mass (property :mass)
                       :documentation "A body's mass.")
    (register-template kb 'strength (property :strength)
                       :documentation "A gravitational field's strength.")
    (register-template kb 'force-value
                       (lambda (situation force axis)
                         (entity-property (entity-named situation force)
                                          (ecase axis (:x :fx) (:y :fy))))
                       :documentation "A component of a given external force.")
    (register-template kb 'force-x (force-component-term 'fx)
                       :documentation "The x component of a named force.")
    (register-template kb 'force-y (force-component-term 'fy)
                       :documentation "The y component of a named force.")
    (register-template kb 'sum-of #'sum-of-forces
                       :documentation "The sum of one component of a list of forces.")
    (register-template kb 'outward-normal (along-contact #'ames.geometry:contact-outward-normal)
                       :documentation "The unit normal along which the obstacle pushes.")
    (register-template kb 'inward-normal (along-contact #'ames.geometry:contact-inward-normal)
                       :documentation "The unit normal pointing toward the obstacle.")
    (register-template kb 'unit-tangent (along-contact #'ames.geometry:contact-unit-tangent)
                       :documentation "The unit tangent of a contact's locus.")
    (register-template kb 'cosine-of-rotation
                       (lambda (situation contact)
                         (axis-component (ames.geometry:contact-unit-tangent
                                          (contact-geometry situation contact)
                                          (list 'path-position contact))
                                         :x))
                       :documentation "cos q, q the rotation of a straight contact's coordinates
(its tangent angle), as the x component of its unit tangent (simpler for Maxima than q).")
    (register-template kb 'sine-of-rotation
                       (lambda (situation contact)
                         (axis-component (ames.geometry:contact-unit-tangent
                                          (contact-geometry situation contact)
                                          (list 'path-position contact))
                                         :y))
                       :documentation "sin q, q the rotation of a straight contact's coordinates.")
    (register-template kb 'curvature
                       (lambda (situation contact)
                         (ames.geometry:contact-curvature (contact-geometry situation contact)))
                       :documentation "The signed curvature of a contact's locus.")
    (register-template kb 'touching #'contact-touching
                       :documentation "The observer lies on the contact's locus.")
    (register-template kb 'past-an-end #'contact-endpoints-passed
                       :documentation "The observer has moved past an end of the locus.")))

(register-mechanics-templates *mechanics*)

;;; Contact analysis (section 2.5.2, figure 2-6)

(defcomponent contact (:knowledge-base *mechanics*)
  "Two bodies touch while the observer's position relative to the obstacle lies on a
simple contact of its configuration-space obstacle. The contact ends when the observer
moves past an end of the contact's locus, or when keeping it would need an attractive
normal force (figure 2-6)."
  (:arguments (?contact :entity simple-contact :where (:observer ?body1 :obstacle ?body2)))
  (:activation (touching ?contact)
               (:event (:contact ?body1 ?body2) :impact (:collision ?body1 ?body2)))
  (:deactivation (:when (< (normal-force ?contact) 0) :event (:lift-off ?body1 ?body2))
                 (:when (past-an-end ?contact) :event (:leaves ?body1 ?body2 :endpoint)))
  (:assert (in-contact ?body1 ?body2 :along ?contact)))

;;; Kinematics (section 2.5.3)

(defcomponent kinematic-restriction (:knowledge-base *mechanics*)
  "A contact restricts the observer's motion relative to the obstacle to the contact's
locus, a one-dimensional path: measured in the path's coordinates, the relative
acceleration has no normal part but the centripetal one, speed squared times the
curvature (section 2.5.3, with the velocity constraint differentiated)."
  (:arguments (?contact :belief (in-contact ?body1 ?body2 :along ?contact)))
  (:assert (restricted ?body1 :wrt ?body2 :along ?contact)
           (path-coordinates ?contact :of ?body1 :wrt ?body2))
  (:equations (= (path-acc ?contact :normal)
                 (* (expt (path-speed ?contact) 2) (curvature ?contact)))))

(defcomponent driven-body (:knowledge-base *mechanics*)
  "A driven body (a conveyor belt) moves at its prescribed constant velocity whatever acts
on it: no acceleration, and a drive that supplies the force balancing every other force
on it (the drive's reaction, reported among the forces as the drive on the body)."
  (:arguments (?body :entity body :where (:driven t)))
  (:assert (force (drive ?body) :type drive :from environment :on ?body)
           (reported :forces (:drive ?body ((fx drive ?body) (fy drive ?body)))))
  (:equations (= (acc ?body :x) 0)
              (= (acc ?body :y) 0)))

(defcomponent drive-balances-the-forces (:knowledge-base *mechanics*)
  "The forces on a driven body, its drive's included, sum to zero (it does not accelerate)."
  (:arguments (?body :entity body :where (:driven t))
              (?forces :collect ?f :matching (force ?f :on ?body)))
  (:equations (= (sum-of ?forces :x) 0)
              (= (sum-of ?forces :y) 0)))

(defcomponent fixed-body (:knowledge-base *mechanics*)
  "A body glued to the fixed frame does not move: a zero-dimensional restriction
(section 2.5.3). Its reaction forces take whatever values the others need."
  (:arguments (?body :entity body :where (:fixed t)))
  (:equations (= (acc ?body :x) 0)
              (= (acc ?body :y) 0)))

;;; Dynamics (section 2.5.4, figure 2-7)

(defcomponent normal-force (:knowledge-base *mechanics*)
  "A contact brings an action-reaction pair of normal forces. Each is directed along the
normal of the contact's locus; its magnitude is not given: it is the compensating force
that the kinematic restriction fixes (section 2.5.4)."
  (:arguments (?contact :belief (in-contact ?body1 ?body2 :along ?contact)))
  (:assert (force (normal ?contact) :type normal :from ?body2 :on ?body1 :contact ?contact)
           (force (reaction ?contact) :type normal :from ?body1 :on ?body2 :contact ?contact)
           (reported :forces (:normal ?body1 ?body2 (normal-force ?contact))))
  (:equations (= (force-x (normal ?contact))
                 (* (normal-force ?contact) (outward-normal ?contact :x)))
              (= (force-y (normal ?contact))
                 (* (normal-force ?contact) (outward-normal ?contact :y)))))

(defcomponent terrestrial-gravitation (:knowledge-base *mechanics*)
  "A terrestrial field pulls every free body down, -y, with its mass times the field's
strength (figure 2-7). A driven body has no mass: what acts on it is the drive's."
  (:arguments (?body :entity body :where (:fixed nil :driven nil))
              (?field :entity gravity-field))
  (:assert (force (gravity ?body) :type gravity :from ?field :on ?body)
           (reported :forces (:gravity ?body ((fx gravity ?body) (fy gravity ?body)))))
  (:equations (= (force-x (gravity ?body)) 0)
              (= (force-y (gravity ?body)) (- (* (mass ?body) (strength ?field))))))

(defcomponent external-force (:knowledge-base *mechanics*)
  "A constant force from outside the scenario acts on a body with the value the user
gave (section 2.5.4)."
  (:arguments (?force :entity external-force :where (:on ?body)))
  (:assert (force (external ?force) :type external :from environment :on ?body)
           (reported :forces (:external ?force ?body ((fx external ?force) (fy external ?force)))))
  (:equations (= (force-x (external ?force)) (force-value ?force :x))
              (= (force-y (external ?force)) (force-value ?force :y))))

;;; Newtonian mechanics (section 2.5.5, figures 2-8 and 2-9)

(defcomponent newtons-second-law (:knowledge-base *mechanics*)
  "The sum of every force on a free body equals its mass times its acceleration in the
fixed frame, in cartesian coordinates (figure 2-8). A driven body has none (see
DRIVEN-BODY)."
  (:arguments (?body :entity body :where (:fixed nil :driven nil))
              (?forces :collect ?f :matching (force ?f :on ?body)))
  (:equations (= (sum-of ?forces :x) (* (mass ?body) (acc ?body :x)))
              (= (sum-of ?forces :y) (* (mass ?body) (acc ?body :y)))))

(defcomponent newtons-third-law (:knowledge-base *mechanics*)
  "The two forces of one interaction, of one type and between the same two bodies in
opposite directions, are vector negations of each other (figure 2-9)."
  (:arguments (?force1 :belief (force ?force1 :type ?type :from ?body2 :on ?body1
                                      :contact ?contact))
              (?force2 :belief (force ?force2 :type ?type :from ?body1 :on ?body2
                                      :contact ?contact)))
  (:equations (= (force-x ?force1) (- (force-x ?force2)))
              (= (force-y ?force1) (- (force-y ?force2)))))

(defcomponent kinematics-of-a-body (:knowledge-base *mechanics*)
  "Velocity is the time derivative of position and acceleration that of velocity
(section 2.5.5): a free body's state variables are its position and velocity, and
these are their ODEs. The simulator solves the rest of the model for the
accelerations and integrates (polynomials in tau while they are constant)."
  (:arguments (?body :entity body :where (:fixed nil)))
  (:assert (derivative (pos ?body :x) (vel ?body :x))
           (derivative (pos ?body :y) (vel ?body :y))
           (derivative (vel ?body :x) (acc ?body :x))
           (derivative (vel ?body :y) (acc ?body :y))))

;;; Reference frames (section 2.5.6) and coordinate systems (section 2.5.7)

(defcomponent reference-frame-conversion (:knowledge-base *mechanics*)
  "A body's acceleration in the fixed frame is its acceleration measured in another
body's frame plus that frame's own acceleration in the fixed frame (section 2.5.6).
Instantiated for every pair whose relative motion a contact describes."
  (:arguments (?contact :belief (restricted ?body1 :wrt ?body2 :along ?contact)))
  (:assert (frame-conversion ?body1 :wrt ?body2))
  (:equations (= (acc ?body1 :x) (+ (rel-acc ?body1 ?body2 :x) (acc ?body2 :x)))
              (= (acc ?body1 :y) (+ (rel-acc ?body1 ?body2 :y) (acc ?body2 :y)))))

(defcomponent path-coordinate-conversion (:knowledge-base *mechanics*)
  "The relative acceleration measured in a contact's own coordinates, converted to the
obstacle's cartesian coordinates (section 2.5.7, figure 2-4). On a straight contact those
coordinates are cartesian, offset and rotated by the contact's constant tangent angle q:
the conversion is the rotation by q. On a curved contact they are path coordinates, whose
unit tangent and inward normal turn with the arc length s; the centripetal part of the
normal component comes from the kinematic restriction."
  (:arguments (?contact :belief (path-coordinates ?contact :of ?body1 :wrt ?body2)))
  (:mode :rotated-cartesian
   (:entry (= (curvature ?contact) 0))
   (:equations (= (rel-acc ?body1 ?body2 :x)
                  (- (* (path-acc ?contact :tangential) (cosine-of-rotation ?contact))
                     (* (path-acc ?contact :normal) (sine-of-rotation ?contact))))
               (= (rel-acc ?body1 ?body2 :y)
                  (+ (* (path-acc ?contact :tangential) (sine-of-rotation ?contact))
                     (* (path-acc ?contact :normal) (cosine-of-rotation ?contact))))))
  (:mode :path
   (:entry (/= (curvature ?contact) 0))
   (:assert (derivative (path-position ?contact) (path-speed ?contact))
            (derivative (path-speed ?contact) (path-acc ?contact :tangential)))
   (:equations (= (rel-acc ?body1 ?body2 :x)
                  (+ (* (path-acc ?contact :tangential) (unit-tangent ?contact :x))
                     (* (path-acc ?contact :normal) (inward-normal ?contact :x))))
               (= (rel-acc ?body1 ?body2 :y)
                  (+ (* (path-acc ?contact :tangential) (unit-tangent ?contact :y))
                     (* (path-acc ?contact :normal) (inward-normal ?contact :y)))))))

;;; The weight's potential energy (energy.lisp says what a state reports of energy)

(defcomponent gravitational-potential-energy (:knowledge-base *mechanics*)
  "In a terrestrial field a free body's potential energy is m g y."
  (:arguments (?body :entity body :where (:fixed nil :driven nil))
              (?field :entity gravity-field))
  (:assert (reported :energy (:potential (:gravity ?body) (potential-energy gravity ?body))))
  (:equations (= (potential-energy gravity ?body) (* (mass ?body) (strength ?field) (pos ?body :y)))))

;;; The phenomena of this file (see phenomena.lisp): contact, terrestrial gravity, external
;;; forces (a driven body's drive is named generically: (:drive B (FX FY)))

(defun gravity-entities (scenario)
  "The (gravity G) clause of SCENARIO as the field (gravity-field EARTH :strength G)."
  (let ((strength (ames.scenario:scenario-gravity scenario)))
    (and strength (list (list 'gravity-field 'earth :strength strength)))))

(defun external-force-entities (scenario)
  "Each (force NAME :on B :value (FX FY) [:at (X Y)]) clause of SCENARIO as an
EXTERNAL-FORCE entity (with :AT (X Y), B's own point it acts at, when given: rotation.lisp)."
  (mapcar (lambda (force)
            (destructuring-bind (fx fy) (ames.scenario:scenario-force-value force)
              (list* 'external-force (ames.scenario:scenario-force-name force)
                     :on (ames.scenario:scenario-force-body force) :fx fx :fy fy
                     (let ((point (ames.scenario:scenario-force-point force)))
                       (and point (list :at point))))))
          (ames.scenario:scenario-forces scenario)))

(define-phenomenon contact
  "Two bodies touching along a simple contact of the configuration space (the simulator
describes the contacts between the bodies' shapes itself): the normal force, and the
events of meeting, colliding, lifting off and leaving past an end."
  (:force :normal :names 2 :words "normal force of ~*~A on ~:*~:*~A" :symbol "N"
          :arrow :along-contact-normal)
  (:event :contact :words "~A comes into contact with ~A" :short "touches ~A")
  (:event :collision :words "~A collides with ~A" :short "hits ~A")
  (:event :lift-off :words "~A lifts off ~A (the normal force would turn attractive)"
          :short "lifts off ~A")
  (:event :leaves :words "~A leaves ~A past the end of the contact"
          :at-feature-end "~A reaches the end of " :short "leaves ~A")
  (:quantity :normal-force :force :normal))

(define-phenomenon gravity
  "A terrestrial field, the scenario's (gravity G): each free body's weight."
  (:entities #'gravity-entities)
  (:force :gravity :names 1 :words "weight of ~A" :label "weight"))

(define-phenomenon external-force
  "A constant force from outside the scenario, each (force NAME :on B :value (FX FY))."
  (:entities #'external-force-entities)
  (:force :external :names 2 :words "external force ~A on ~A" :label (:name 0)))

(define-phenomenon drive
  "A driven body's drive (the body clause's :driven): the force that keeps its velocity,
named generically (\"drive B\")."
  (:force :drive :names 1))
