;;;; src/kb/gravitation.lisp -- universal gravitation (thesis 3.3.2, "Universal Gravitation").
;;;;
;;;; The gravitation phenomenon (below) describes the (gravitation G) clause and the pairs of bodies it may act
;;;; between:
;;;;   (gravitation-field NAME :constant G)
;;;;   (body-pair P :first B1 :second B2)     every two bodies that have a mass, not both fixed
;;;; The thesis's component: "force along line between centers of mass, with magnitude
;;;; G M1 M2 / r^2". The line is the span between the two reference points
;;;; (src/kb/spans.lisp), so two bodies released from rest fall toward each other along a
;;;; fixed line (the span keeps its direction: a motion of one degree of freedom, whose
;;;; energy integral gives the time of their meeting). Reported in :forces as
;;;; (:gravitation BODY OTHER (FX FY)), the pull on BODY toward OTHER.
;;;; The state ends if the two reference points meet ((:meet B1 B2)): the law is singular
;;;; there (bodies with extent touch before).

(in-package #:ames.kb)

(register-template *mechanics* 'gravitational-constant
                   (lambda (situation field) (entity-property (entity-named situation field) :constant))
                   :documentation "The constant G of universal gravitation.")

(defcomponent line-of-centres (:knowledge-base *mechanics*)
  "Gravitation acts along the span between the two bodies' reference points."
  (:arguments (?pair :entity body-pair :where (:first ?body1 :second ?body2))
              (?field :entity gravitation-field))
  (:assert (span ?pair :from (?body1 (0 0)) :to (?body2 (0 0)))))

(defcomponent universal-gravitation (:knowledge-base *mechanics*)
  "Every two bodies with mass attract each other with G m1 m2 / r^2 along the line of
their centres; Newton's third law gives the second body's pull from the first's."
  (:arguments (?pair :entity body-pair :where (:first ?body1 :second ?body2))
              (?field :entity gravitation-field))
  (:deactivation (:when (<= (span-length ?pair) 0) :event (:meet ?body1 ?body2)))
  (:assert (force (gravitation ?pair ?body1) :type gravitation :from ?body2 :on ?body1 :contact ?pair)
           (force (gravitation ?pair ?body2) :type gravitation :from ?body1 :on ?body2 :contact ?pair)
           (reported :forces (:gravitation ?body1 ?body2 ((fx gravitation ?pair ?body1) (fy gravitation ?pair ?body1))))
           (reported :forces (:gravitation ?body2 ?body1 ((fx gravitation ?pair ?body2) (fy gravitation ?pair ?body2)))))
  (:equations (= (force-x (gravitation ?pair ?body1))
                 (/ (* (gravitational-constant ?field) (mass ?body1) (mass ?body2) (span-direction ?pair :x))
                    (expt (span-length ?pair) 2)))
              (= (force-y (gravitation ?pair ?body1))
                 (/ (* (gravitational-constant ?field) (mass ?body1) (mass ?body2) (span-direction ?pair :y))
                    (expt (span-length ?pair) 2)))))

(defcomponent gravitational-binding-energy (:knowledge-base *mechanics*)
  "Two bodies under universal gravitation have the potential energy -G m1 m2 / r."
  (:arguments (?pair :entity body-pair :where (:first ?body1 :second ?body2))
              (?field :entity gravitation-field))
  (:assert (reported :energy (:potential (:gravitation ?body1 ?body2) (potential-energy gravitation ?pair))))
  (:equations (= (potential-energy gravitation ?pair)
                 (- (/ (* (gravitational-constant ?field) (mass ?body1) (mass ?body2))
                       (span-length ?pair))))))

(defun massive-body-pairs (scenario)
  "Every two bodies of SCENARIO that have a mass and are not both fixed, as (B1 B2)."
  (loop for (b1 . rest) on (remove nil (ames.scenario:scenario-bodies scenario)
                                   :key #'ames.scenario:scenario-body-mass)
        append (loop for b2 in rest
                     unless (and (ames.scenario:scenario-body-fixed-p b1)
                                 (ames.scenario:scenario-body-fixed-p b2))
                       collect (list (ames.scenario:scenario-body-name b1)
                                     (ames.scenario:scenario-body-name b2)))))

(defun gravitation-entities (scenario)
  "The (gravitation G) clause of SCENARIO as (gravitation-field GRAVITATION :constant G),
and every pair of bodies it may act between as (body-pair PAIR-i :first B1 :second B2)."
  (append
   (let ((constant (ames.scenario:scenario-gravitation scenario)))
     (and constant (list (list 'gravitation-field 'gravitation :constant constant))))
   (loop for (b1 b2) in (massive-body-pairs scenario)
         for index from 0
         collect (list 'body-pair (indexed-entity-name "PAIR" index) :first b1 :second b2))))

(define-phenomenon gravitation
  "Universal gravitation between every two bodies with mass (the gravitation clause)."
  (:entities #'gravitation-entities)
  (:force :gravitation :names 2 :words "gravitation of ~*~A on ~:*~:*~A")
  (:event :meet))
