;;;; src/kb/rotating-impacts.lisp -- impacts of rotating bodies: the angular impulse of an impulse
;;;; that acts at a point, Newton's restitution on the relative velocity of the contact points,
;;;; the rotational kinetic energy an impact dissipates.
;;;;
;;;; A rigid body struck at the point r from its centre of mass by the impulse J changes its
;;;; momentum by J (impacts.lisp's CHANGE-OF-MOMENTUM) and its angular momentum about the
;;;; centre by r x J:  I (omega' - omega) = sum of r x J.  Newton's law of restitution speaks
;;;; of the normal velocity of the two material points in contact, v + omega k x r, not of
;;;; the centres: the impact components (impacts.lisp) read the points' velocities through
;;;; POINT-VELOCITY-AT-IMPACT, the centre's for a body that does not rotate (so a translating
;;;; impact's equations are unchanged).
;;;;
;;;; THE VOCABULARY this file adds to the impact's situation (see impacts.lisp's header):
;;;;   (body NAME ... :rotating T :inertia I [:radius R] :angle THETA :turn (C S)
;;;;         :angular-velocity OMEGA)
;;;;        a rotating free body, its angle (C, S its cosine and sine, simplified) and
;;;;        angular velocity just before
;;;;   (touching-contact K ... [:observer-arm (RX RY)])
;;;;        the offset of the contact point from the observer's centre when the geometry
;;;;        gives it (a corner of a rotating polygon or segment); a disc's is -R n, the
;;;;        obstacle disc's +R n (rotation.lisp's header)
;;;; quantity terms
;;;;   (angvel-after B)            B's angular velocity just after the impact
;;;;   (angular-impulse . J)       the moment r x J about B's centre of the impulse J
;;;; belief
;;;;   (impulse-acts-at J :on B)   the impulse J acts at a point of the rotating body B and
;;;;                               (angular-impulse . J) is defined (a hinge's, a wound
;;;;                               rope's components assert it for their own impulses)
;;;; Friction impulses. A touching contact of a rough pair (a friction clause) one of whose
;;;; bodies rotates has :ROUGH-ROTATING T and :FRICTION MU (the pair's kinetic coefficient):
;;;; its impulse on the observer is Jn n + Jt t (t the normal turned a quarter turn
;;;; counter-clockwise), Jt by Coulomb's law over the impact (FRICTION-IMPULSE: sticking, the
;;;; points leave without relative tangential velocity, |Jt| <= mu Jn; sliding, Jt = -+ mu Jn
;;;; against the slip before, which must not reverse). Terms: (tangent-impulse K),
;;;; (slip-after K). A rough impact between bodies that do not rotate stays frictionless, as
;;;; impacts.lisp says (no spin to change: its textbook impact is the smooth one).

(in-package #:ames.kb)

(defun angular-velocity-before (situation body)
  "The rotating BODY's angular velocity just before the impact."
  (body-entity-property situation body :angular-velocity))

(defun impact-arm (situation contact body)
  "The offset (RX RY) from the rotating BODY's centre to the point of the touching
CONTACT: the contact's :OBSERVER-ARM when the geometry gave it, else -R n for the
observer disc and +R n for the obstacle disc (n the outward normal). Signals
UNMODELLED-SITUATION for a rotating body that is not a disc and has no arm given."
  (let* ((entity (entity-named situation contact))
         (observer-p (eq body (entity-property entity :observer)))
         (given (and observer-p (entity-property entity :observer-arm))))
    (or given
        (let ((radius (disc-radius situation body contact))
              (normal (entity-property entity :normal)))
          (mapcar (lambda (n) (if observer-p `(- (* ,radius ,n)) `(* ,radius ,n))) normal)))))

(defun point-velocity-at-impact (situation contact body axis when)
  "The AXIS component of the velocity of BODY's material point at the touching CONTACT,
just before the impact (WHEN :BEFORE, an expression over the situation's values) or just
after (:AFTER, over (vel-after BODY) and (angvel-after BODY)): v + omega k x r for a
rotating body, the centre's velocity v for one that does not rotate."
  (let ((v (ecase when
             (:before (entity-vector situation body :velocity axis))
             (:after (list 'vel-after body axis)))))
    (if (rotating-body-p situation body)
        (destructuring-bind (rx ry) (impact-arm situation contact body)
          (let ((omega (ecase when
                         (:before (angular-velocity-before situation body))
                         (:after (list 'angvel-after body)))))
            (ecase axis
              (:x `(- ,v (* ,omega ,ry)))
              (:y `(+ ,v (* ,omega ,rx))))))
        v)))

(defun rotational-energy-drop (situation body)
  "The rotational kinetic energy of BODY just before the impact minus just after, as a
list of terms: NIL for a body that does not rotate."
  (when (rotating-body-p situation body)
    (list `(* 1/2 ,(body-entity-property situation body :inertia)
              (- (expt ,(angular-velocity-before situation body) 2)
                 (expt (angvel-after ,body) 2))))))

(defun impact-turned-arm (situation body point)
  "The rotating BODY's own point POINT (PX PY) turned by its angle at the impact: the
offset of that point from its centre, from the body's :TURN (cos, sin of its angle)."
  (destructuring-bind (px py) point
    (destructuring-bind (c s) (body-entity-property situation body :turn)
      (list `(- (* ,c ,px) (* ,s ,py)) `(+ (* ,s ,px) (* ,c ,py))))))

(defun impulse-moment (arm impulse)
  "The moment r x J of the impulse named IMPULSE applied at the offset ARM (RX RY)."
  (destructuring-bind (rx ry) arm
    `(- (* ,rx ,(cons 'jy impulse)) (* ,ry ,(cons 'jx impulse)))))

(defun impact-tangent (situation contact)
  "The unit tangent (TX TY) of the touching CONTACT: its outward normal turned a quarter
turn counter-clockwise (friction.lisp's and the corners' convention)."
  (destructuring-bind (nx ny) (entity-property (entity-named situation contact) :normal)
    (list `(- ,ny) nx)))

(defun relative-point-velocity (situation contact when)
  "The velocity (X Y) of the observer's contact point relative to the obstacle's at the
touching CONTACT, just before (WHEN :BEFORE) or just after (:AFTER) the impact."
  (let* ((entity (entity-named situation contact))
         (a (entity-property entity :observer))
         (b (entity-property entity :obstacle)))
    (mapcar (lambda (axis)
              `(- ,(point-velocity-at-impact situation contact a axis when)
                  ,(point-velocity-at-impact situation contact b axis when)))
            '(:x :y))))

(defun impulse-along-contact (situation contact axis)
  "Template IMPULSE-ALONG-CONTACT: the AXIS component of the touching CONTACT's impulse on
its observer, (normal-impulse K) n, plus (tangent-impulse K) t on a contact whose friction
impulse is modelled (:ROUGH-ROTATING, see the file header)."
  (let* ((entity (entity-named situation contact))
         (normal `(* (normal-impulse ,contact) ,(axis-component (entity-property entity :normal) axis))))
    (if (entity-property entity :rough-rotating)
        `(+ ,normal (* (tangent-impulse ,contact) ,(axis-component (impact-tangent situation contact) axis)))
        normal)))

(defun register-rotating-impact-templates (kb)
  "Register in KB the template functions of impacts of rotating bodies."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'inertia (lambda (situation body) (body-entity-property situation body :inertia))
         "A rotating body's moment of inertia about its centre of mass.")
    (reg 'angvel-before #'angular-velocity-before
         "A rotating body's angular velocity just before the impact.")
    (reg 'angular-impulse-of (force-component-term 'angular-impulse)
         "The angular impulse (about its body's centre) of a named impulse.")
    (reg 'impulse-moment-at-contact
         (lambda (situation contact body impulse)
           (impulse-moment (impact-arm situation contact body) impulse))
         "The moment about a rotating body's centre of an impulse at a contact's point.")
    (reg 'impulse-moment-at-point
         (lambda (situation body point impulse)
           (impulse-moment (impact-turned-arm situation body point) impulse))
         "The moment of an impulse acting at a rotating body's own point, turned by its angle.")
    (reg 'sum-of-angular-impulses
         (lambda (situation impulses)
           (declare (ignore situation))
           (if impulses (cons '+ (mapcar (lambda (j) (cons 'angular-impulse j)) impulses)) 0))
         "The sum of the angular impulses of a list of impulses.")
    (reg 'impulse-along-contact #'impulse-along-contact
         "A component of a touching contact's impulse on its observer.")
    (reg 'slip-before
         (lambda (situation contact)
           (ames.geometry:dot (relative-point-velocity situation contact :before)
                              (impact-tangent situation contact)))
         "The contact points' relative velocity along the tangent just before the impact.")
    (reg 'slip-after-at-points
         (lambda (situation contact)
           (ames.geometry:dot (relative-point-velocity situation contact :after)
                              (impact-tangent situation contact)))
         "The contact points' relative velocity along the tangent just after the impact.")
    (reg 'impact-friction
         (lambda (situation contact) (entity-property (entity-named situation contact) :friction))
         "The coefficient of friction of a touching contact at an impact (the kinetic one).")))

(register-rotating-impact-templates *impacts*)

(defcomponent angular-impulse-at-a-contact (:knowledge-base *impacts*)
  "A touching contact's impulse acts on a rotating body at the contact point: its moment
about the body's centre is r x J, r from the centre to that point."
  (:arguments (?impulse :belief (impulse ?impulse :on ?body :contact ?contact))
              (?contact :entity touching-contact)
              (?body :entity body :where (:fixed nil :rotating t)))
  (:assert (impulse-acts-at ?impulse :on ?body))
  (:equations (= (angular-impulse-of ?impulse) (impulse-moment-at-contact ?contact ?body ?impulse))))

(defcomponent change-of-angular-momentum (:knowledge-base *impacts*)
  "A rotating free body's angular momentum about its centre changes by the sum of the
angular impulses on it: I (omega' - omega) = sum of r x J (the angular-momentum law
integrated over the impact; finite torques give none)."
  (:arguments (?body :entity body :where (:fixed nil :driven nil :rotating t))
              (?impulses :collect ?j :matching (impulse-acts-at ?j :on ?body)))
  (:equations (= (* (inertia ?body) (- (angvel-after ?body) (angvel-before ?body)))
                 (sum-of-angular-impulses ?impulses))))

(defcomponent friction-impulse (:knowledge-base *impacts*)
  "A rough touching contact with a rotating body that pushes also rubs: an impulse Jt
along its tangent t (Coulomb's law over the impact, with the kinetic coefficient mu).
Sticking, the contact points leave with no relative tangential velocity and |Jt| <= mu
Jn; sliding, Jt = -+ mu Jn against the slip before the impact, and the slip must not have
reversed just after (else it sticks). Which holds is settled by consistency."
  (:arguments (?contact :entity touching-contact
                        :where (:observer ?body1 :obstacle ?body2 :rough-rotating t)))
  (:activation (:believes (impulse (impulse ?contact) :from ?body2 :on ?body1 :contact ?contact)))
  ;; the contact named too: the impact event's impulse is the normal one, not summed with it
  (:assert (reported :impulses (:friction-impulse ?body1 ?body2 ?contact (tangent-impulse ?contact))))
  (:equations (= (slip-after ?contact) (slip-after-at-points ?contact)))
  (:mode :sticking
   (:entry (= (slip-after ?contact) 0))
   (:equations (= (slip-after ?contact) 0))
   (:transition :to :sliding-backward
                :when (> (tangent-impulse ?contact) (* (impact-friction ?contact) (normal-impulse ?contact)))
                :event (:slides ?body1 ?body2))
   (:transition :to :sliding-forward
                :when (< (tangent-impulse ?contact) (- (* (impact-friction ?contact) (normal-impulse ?contact))))
                :event (:slides ?body1 ?body2)))
  (:mode :sliding-forward
   (:entry (> (slip-before ?contact) 0))
   (:equations (= (tangent-impulse ?contact) (- (* (impact-friction ?contact) (normal-impulse ?contact)))))
   (:transition :to :sticking :when (< (slip-after ?contact) 0) :event (:sticks ?body1 ?body2)))
  (:mode :sliding-backward
   (:entry (< (slip-before ?contact) 0))
   (:equations (= (tangent-impulse ?contact) (* (impact-friction ?contact) (normal-impulse ?contact))))
   (:transition :to :sticking :when (> (slip-after ?contact) 0) :event (:sticks ?body1 ?body2))))
