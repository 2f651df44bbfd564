;;;; src/kb/impacts.lisp -- what happens at an impact: impulses along the contact normals,
;;;; Newton's law of restitution, momentum (thesis section 3.3.2, "Collisions").
;;;;
;;;; An impact is instantaneous: the positions do not change, the velocities jump. Its model
;;;; is built by the same engine from its own knowledge base, over a situation the simulator
;;;; describes at the moment of impact:
;;;;   (body NAME :fixed T-or-NIL :mass EXPR :velocity (VX VY))   velocities just before
;;;;   (touching-contact K :observer A :obstacle B :normal (NX NY) :restitution E)
;;;;                                                   every contact that touches then, with
;;;;                                                   its outward normal there
;;;; and it reads back these quantity terms:
;;;;   (vel-after B :x)             a body's velocity just after the impact
;;;;   (jx NAME...) (jy NAME...)    the components of the impulse named (NAME...)
;;;;   (normal-impulse K)           the magnitude of contact K's impulse on its observer
;;;;   (separation-after K)         the observer's velocity relative to the obstacle along
;;;;                                K's outward normal just after (negative: approaching)
;;;;   (energy-lost impact)         the kinetic energy the impact dissipates
;;;; A touching contact may push or not; which is chosen by consistency, as for a state:
;;;; a pushing contact pulls at once if its impulse is negative, one that does not push is
;;;; penetrated at once if the bodies still approach through it. Impacts are frictionless
;;;; but for a rough contact with a rotating body; a rotating body's contact point moves with
;;;; v + omega k x r, and its impulses have moments: src/kb/rotating-impacts.lisp.

(in-package #:ames.kb)

(defvar *impacts* (make-knowledge-base :name "impacts"
                                       :documentation "Frictionless impacts (Wong 1994, 3.3.2).")
  "The knowledge base of impacts. The components below register themselves in it.")

(defun impact-knowledge-base ()
  "The knowledge base of impacts."
  *impacts*)

(defun knowledge-bases ()
  "Every knowledge base of AMES: a state's (mechanics) and an impact's."
  (list *mechanics* *impacts*))

(defun entity-vector (situation name key axis)
  "The AXIS component of the vector property KEY of the entity NAME."
  (axis-component (entity-property (entity-named situation name) key) axis))

(defun kinetic-energy-drop (situation bodies)
  "Template KINETIC-ENERGY-DROP: the kinetic energy of BODIES just before the impact
minus just after."
  (if bodies
      (cons '+ (loop for body in bodies
                     for mass = (entity-property (entity-named situation body) :mass)
                     collect `(* 1/2 ,mass
                                 (- (+ (expt ,(entity-vector situation body :velocity :x) 2)
                                       (expt ,(entity-vector situation body :velocity :y) 2))
                                    (+ (expt (vel-after ,body :x) 2)
                                       (expt (vel-after ,body :y) 2))))
                     ;; a rotating body's (1/2) I omega^2 (rotating-impacts.lisp)
                     append (rotational-energy-drop situation body)))
      0))

(defun register-impact-templates (kb)
  "Register in KB the template functions the impact components use."
  (flet ((property (key)
           (lambda (situation name) (entity-property (entity-named situation name) key))))
    (register-template kb 'mass (property :mass) :documentation "A body's mass.")
    (register-template kb 'restitution (property :restitution)
                       :documentation "A touching contact's coefficient of restitution.")
    (register-template kb 'velocity-before
                       (lambda (situation body axis) (entity-vector situation body :velocity axis))
                       :documentation "A component of a body's velocity just before the impact.")
    (register-template kb 'impact-normal
                       (lambda (situation contact axis) (entity-vector situation contact :normal axis))
                       :documentation "A component of a touching contact's outward normal.")
    (register-template kb 'separation-before
                       (lambda (situation contact)
                         (let ((entity (entity-named situation contact)))
                           (flet ((velocity (body axis) ; its contact point's (rotating-impacts.lisp)
                                    (point-velocity-at-impact situation contact body axis :before)))
                             (let ((a (entity-property entity :observer))
                                   (b (entity-property entity :obstacle)))
                               `(+ (* (- ,(velocity a :x) ,(velocity b :x)) ,(entity-vector situation contact :normal :x))
                                   (* (- ,(velocity a :y) ,(velocity b :y)) ,(entity-vector situation contact :normal :y)))))))
                       :documentation "The observer's velocity along the normal just before.")
    (register-template kb 'impulse-x (force-component-term 'jx)
                       :documentation "The x component of a named impulse.")
    (register-template kb 'impulse-y (force-component-term 'jy)
                       :documentation "The y component of a named impulse.")
    (register-template kb 'sum-of-impulses
                       (lambda (situation impulses axis)
                         (declare (ignore situation))
                         (let ((head (ecase axis (:x 'jx) (:y 'jy))))
                           (if impulses (cons '+ (mapcar (lambda (j) (cons head j)) impulses)) 0)))
                       :documentation "The sum of one component of a list of impulses.")
    (register-template kb 'kinetic-energy-drop #'kinetic-energy-drop
                       :documentation "The kinetic energy of some bodies before minus after.")
    (register-template kb 'approaching-after
                       (lambda (situation contact)
                         (declare (ignore situation))
                         (list '< (list 'separation-after contact) 0))
                       :documentation "The bodies still approach through the contact after the impact.")
    (register-template kb 'point-velocity-after
                       (lambda (situation contact body axis)
                         (point-velocity-at-impact situation contact body axis :after))
                       :documentation "A component of a body's velocity just after the impact at a
contact's point (its centre's when it does not rotate: rotating-impacts.lisp).")))

(register-impact-templates *impacts*)

(defcomponent impact-kinematics (:knowledge-base *impacts*)
  "The observer's velocity relative to the obstacle along a touching contact's outward
normal, just after the impact."
  (:arguments (?contact :entity touching-contact :where (:observer ?body1 :obstacle ?body2)))
  (:equations (= (separation-after ?contact)
                 (+ (* (- (point-velocity-after ?contact ?body1 :x) (point-velocity-after ?contact ?body2 :x))
                       (impact-normal ?contact :x))
                    (* (- (point-velocity-after ?contact ?body1 :y) (point-velocity-after ?contact ?body2 :y))
                       (impact-normal ?contact :y))))))

(defcomponent contact-impulse (:knowledge-base *impacts*)
  "A touching contact may push its observer with an impulse along its outward normal (never
pull); then Newton's law of restitution holds on it: the bodies separate along the normal
at E times the speed they approached with. A contact that does not push must not be
penetrated: the bodies do not approach through it after the impact."
  (:arguments (?contact :entity touching-contact :where (:observer ?body1 :obstacle ?body2)))
  (:activation (approaching-after ?contact)
               (:event (:impulse ?body1 ?body2)))
  (:deactivation (:when (< (normal-impulse ?contact) 0) :event (:would-pull ?body1 ?body2)))
  (:assert (impulse (impulse ?contact) :from ?body2 :on ?body1 :contact ?contact)
           (impulse (counter-impulse ?contact) :from ?body1 :on ?body2 :contact ?contact)
           (reported :impulses (:impulse ?body1 ?body2 (normal-impulse ?contact))))
  (:equations (= (impulse-x (impulse ?contact)) (impulse-along-contact ?contact :x))
              (= (impulse-y (impulse ?contact)) (impulse-along-contact ?contact :y))
              (= (separation-after ?contact)
                 (* -1 (restitution ?contact) (separation-before ?contact)))))

(defcomponent third-law-of-impulses (:knowledge-base *impacts*)
  "The two impulses of one contact are opposite (Newton's third law, integrated over the
impact)."
  (:arguments (?impulse1 :belief (impulse ?impulse1 :from ?body2 :on ?body1 :contact ?contact))
              (?impulse2 :belief (impulse ?impulse2 :from ?body1 :on ?body2 :contact ?contact)))
  (:equations (= (impulse-x ?impulse1) (- (impulse-x ?impulse2)))
              (= (impulse-y ?impulse1) (- (impulse-y ?impulse2)))))

(defcomponent change-of-momentum (:knowledge-base *impacts*)
  "A free body's momentum changes by the sum of the impulses on it (Newton's second law
integrated over the impact; finite forces such as gravity give no impulse)."
  (:arguments (?body :entity body :where (:fixed nil :driven nil))
              (?impulses :collect ?j :matching (impulse ?j :on ?body)))
  (:assert (moving-at-impact ?body))
  (:equations (= (* (mass ?body) (- (vel-after ?body :x) (velocity-before ?body :x)))
                 (sum-of-impulses ?impulses :x))
              (= (* (mass ?body) (- (vel-after ?body :y) (velocity-before ?body :y)))
                 (sum-of-impulses ?impulses :y))))

(defcomponent driven-body-at-impact (:knowledge-base *impacts*)
  "A driven body keeps its velocity, whatever impulse it takes (its drive's)."
  (:arguments (?body :entity body :where (:driven t)))
  (:equations (= (vel-after ?body :x) (velocity-before ?body :x))
              (= (vel-after ?body :y) (velocity-before ?body :y))))

(defcomponent fixed-body-at-impact (:knowledge-base *impacts*)
  "A fixed body does not move, whatever impulse it takes."
  (:arguments (?body :entity body :where (:fixed t)))
  (:equations (= (vel-after ?body :x) 0)
              (= (vel-after ?body :y) 0)))

(defcomponent energy-of-the-impact (:knowledge-base *impacts*)
  "The kinetic energy the impact dissipates: all of the approach's share for E = 0, none
for E = 1 (an elastic impact)."
  (:arguments (?bodies :collect ?b :matching (moving-at-impact ?b)))
  (:assert (reported :impact (:energy-lost (energy-lost impact))))
  (:equations (= (energy-lost impact) (kinetic-energy-drop ?bodies))))

;;; The clause and the names (see phenomena.lisp)

(defun touching-contact-entity (scenario contact observer obstacle normal &key arm)
  "The impact situation's entity of the CONTACT touching at the impact between OBSERVER
and OBSTACLE, with its outward NORMAL there and the restitution SCENARIO's (restitution
...) clauses give the pair; :ROUGH-ROTATING T and :FRICTION MU when a friction clause
names the pair and one of them rotates (rotating-impacts.lisp), and the
contact point's offset ARM from the observer's centre when the geometry gives it (a
rotating body's corner: rotating-impacts.lisp)."
  (append (list 'touching-contact contact :observer observer :obstacle obstacle :normal normal
                :restitution (ames.scenario:scenario-restitution scenario observer obstacle))
          (let ((friction (ames.scenario:find-scenario-friction observer obstacle scenario)))
            (and friction
                 (some (lambda (name)
                         (let ((body (ames.scenario:find-scenario-body name scenario)))
                           (and (ames.scenario:scenario-body-rotating-p body)
                                (not (ames.scenario:scenario-body-fixed-p body)))))
                       (list observer obstacle))
                 ;; its friction impulse: rotating-impacts.lisp
                 (list :rough-rotating t
                       :friction (ames.scenario:scenario-friction-kinetic friction))))
          (and arm (list :observer-arm arm))))

(define-phenomenon impact
  "Frictionless impacts: impulses along the contact normals and Newton's law of
restitution (the restitution clause)."
  (:impulse :impulse :names 2 :words "impulse of ~*~A on ~:*~:*~A")
  (:impulse :friction-impulse :names 3 :words "friction impulse of ~*~A on ~:*~:*~A, along the tangent")
  (:event :slides :words "~A slides on ~A through the impact")
  (:event :sticks :words "~A stops slipping on ~A in the impact"))
