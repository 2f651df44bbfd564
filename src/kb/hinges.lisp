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
;;;; (:hinge NAME B (FX FY)); the query (hinge-force NAME) reads it, a vector. An impact in
;;;; a scenario with a hinge is refused (UNMODELLED-SITUATION): the impact model
;;;; (impacts.lisp) has no pin to hold.
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
  "No entities at an impact: signals UNMODELLED-SITUATION when SCENARIO has a hinge (an
impact's impulses would have to keep the pin at rest and turn the body about it, which
the impact model does not do: without this the hinged body would recoil as a free one)."
  (let ((hinge (first (ames.scenario:scenario-hinges scenario))))
    (when hinge
      (error 'unmodelled-situation
             :datum (ames.scenario:scenario-hinge-name hinge)
             :detail (format nil "An impact in a scenario with the hinge ~(~A~) is not modelled (the impulses would have to hold the pin)."
                             (ames.scenario:scenario-hinge-name hinge))))
    '()))

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

(define-phenomenon hinge
  "A rotating body's point pinned to the fixed frame (the hinge clause): the reaction
force that holds it, with its moment about the body's centre."
  (:entities #'hinge-entities)
  (:impact-entities #'hinge-impact-entities)
  (:force :hinge :names 2 :words "force of hinge ~A on ~A" :label (:name 0))
  (:quantity :hinge-force :force :hinge))
