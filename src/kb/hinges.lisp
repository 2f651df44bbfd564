;;;; src/kb/hinges.lisp -- the hinge (scenario-language.md, "Rotation"): a rotating body's point
;;;; pinned to the fixed frame (a physical pendulum, a door, a massive pulley on its axle).
;;;;
;;;; The hinge phenomenon describes each (hinge NAME :body B :at (X Y)) clause as the entity
;;;;   (hinge NAME :body B :at (X Y))        (X Y) in B's own frame, turned by B's angle
;;;; The HINGE component holds the pin: the fixed frame pushes on B at the pin with a
;;;; reaction force of unknown components (a compensating force, like a normal force) that
;;;; keeps the pin's acceleration zero,
;;;;   a_centre + alpha k x r - omega^2 r = 0,      r = R(theta) (X Y)
;;;; (the rigid body's acceleration at the point r from its centre of mass), and the force
;;;; acts at the pin, so its moment about the centre is r x F. Reported in :forces as
;;;; (:hinge NAME B (FX FY)); the query (hinge-force NAME) reads it, a vector. At an impact
;;;; (impacts.lisp, rotating-impacts.lisp) the hinge's impulsive reaction J, of unknown
;;;; components, acts at the pin and keeps it still: the pin's velocity just after,
;;;; v' + omega' k x r, is zero (r at the body's angle then); its moment r x J enters the
;;;; body's change of angular momentum. Reported in :impulses as its components
;;;; (:hinge-impulse-x NAME B JX) and (:hinge-impulse-y NAME B JY).
;;;;
;;;; The rotating body's quantity terms are the rotation core's (rotation.lisp): its angle,
;;;; angular velocity and angular acceleration, and the moment of a force acting at a point.

(in-package #:ames.kb)

(defun hinge-entities (scenario)
  "Each (hinge NAME :body B :at (X Y)) clause of SCENARIO as a HINGE entity."
  (mapcar (lambda (hinge)
            (list 'hinge (ames.scenario:scenario-hinge-name hinge)
                  :body (ames.scenario:scenario-hinge-body hinge)
                  :at (ames.scenario:scenario-hinge-point hinge)))
          (ames.scenario:scenario-hinges scenario)))

(defun hinge-impact-entities (scenario)
  "The HINGE entities of SCENARIO at an impact: the same as in a state (HINGE-ENTITIES)."
  (hinge-entities scenario))

(defun hinge-arm (situation hinge)
  "The world vector from the hinged body's centre to its pin (rotation.lisp's TURNED-ARM)."
  (let ((entity (entity-named situation hinge)))
    (turned-arm situation (entity-property entity :body) (entity-property entity :at))))

(register-template *mechanics* 'hinge-arm
                   (lambda (situation hinge axis) (axis-component (hinge-arm situation hinge) axis))
                   :documentation "A component of the vector from a hinged body's centre to its pin.")

(defcomponent hinge (:knowledge-base *mechanics*)
  "A hinge pins a point of a rotating body to the fixed frame: the frame pushes on the
body at the pin with whatever force keeps the pin at rest, so the body's acceleration at
the pin, a + alpha k x r - omega^2 r (r from the centre to the pin), is zero. The force
acts at the pin: its moment about the centre is r x F."
  (:arguments (?hinge :entity hinge :where (:body ?body :at (?px ?py))))
  (:assert (force (hinge-reaction ?hinge) :type hinge :from environment :on ?body)
           (acts-at (hinge-reaction ?hinge) :on ?body)
           (reported :forces (:hinge ?hinge ?body ((fx hinge-reaction ?hinge) (fy hinge-reaction ?hinge)))))
  (:equations (= (+ (acc ?body :x) (- (* (angacc ?body) (hinge-arm ?hinge :y)))
                    (- (* (expt (angvel ?body) 2) (hinge-arm ?hinge :x))))
                 0)
              (= (+ (acc ?body :y) (* (angacc ?body) (hinge-arm ?hinge :x))
                    (- (* (expt (angvel ?body) 2) (hinge-arm ?hinge :y))))
                 0)
              (= (moment-of (hinge-reaction ?hinge))
                 (moment-at-point ?body (?px ?py) (hinge-reaction ?hinge)))))

(register-template *impacts* 'hinge-arm-at-impact
                   (lambda (situation hinge axis)
                     (let ((entity (entity-named situation hinge)))
                       (axis-component (impact-turned-arm situation (entity-property entity :body)
                                                          (entity-property entity :at))
                                       axis)))
                   :documentation "A component of the vector from a hinged body's centre to its
pin at the impact (the body's angle then).")

(defcomponent hinge-at-impact (:knowledge-base *impacts*)
  "At an impact the hinge holds its pin still: the frame gives the body at the pin
whatever impulse keeps the pin's velocity just after, v' + omega' k x r, zero. The
impulse acts at the pin: its moment about the centre is r x J."
  (:arguments (?hinge :entity hinge :where (:body ?body :at (?px ?py))))
  (:assert (impulse (hinge-impulse ?hinge) :from environment :on ?body)
           (impulse-acts-at (hinge-impulse ?hinge) :on ?body)
           (reported :impulses (:hinge-impulse-x ?hinge ?body (jx hinge-impulse ?hinge)))
           (reported :impulses (:hinge-impulse-y ?hinge ?body (jy hinge-impulse ?hinge))))
  (:equations (= (- (vel-after ?body :x) (* (angvel-after ?body) (hinge-arm-at-impact ?hinge :y))) 0)
              (= (+ (vel-after ?body :y) (* (angvel-after ?body) (hinge-arm-at-impact ?hinge :x))) 0)
              (= (angular-impulse-of (hinge-impulse ?hinge))
                 (impulse-moment-at-point ?body (?px ?py) (hinge-impulse ?hinge)))))

(define-phenomenon hinge
  "A rotating body's point pinned to the fixed frame (the hinge clause): the reaction
force that holds it, with its moment about the body's centre."
  (:entities #'hinge-entities)
  (:impact-entities #'hinge-impact-entities)
  (:force :hinge :names 2 :words "force of hinge ~A on ~A" :label (:name 0))
  (:impulse :hinge-impulse-x :names 2 :words "impulse of hinge ~A on ~A, x component")
  (:impulse :hinge-impulse-y :names 2 :words "impulse of hinge ~A on ~A, y component")
  (:quantity :hinge-force :force :hinge))
