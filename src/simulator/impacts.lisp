;;;; src/simulator/impacts.lisp -- resolving an impact: the instantaneous model of the knowledge
;;;; base's impact components, its contacts chosen by consistency, the velocities just after.
;;;;
;;;; A state ends in an impact when a condition is reached with a velocity that its component
;;;; declares impulsive (its :IMPACT event). The positions carry over; the velocities jump. The
;;;; impact's model is built from AMES.KB:IMPACT-KNOWLEDGE-BASE over every contact that touches
;;;; at that moment (several at once are solved together: a block landing on two supports, a
;;;; particle reaching the corner of a slope and the ground, a chain of touching blocks), and
;;;; which of them push is settled by the same consistency search as a state's contacts: no
;;;; impulse pulls, no contact is left approaching. Then the next state starts with the
;;;; velocities just after.

(in-package #:ames.simulator)

(defun touching-contacts (run)
  "The contacts of two bodies' shapes whose observer lies on their locus now (a probe's
locus is no surface: nothing touches it), less those a corner excuses (see
EXCUSED-AT-CORNER-P)."
  (let ((touching (loop for (name) in (run-contacts run)
                        when (and (shape-contact-p run name) (touching-on-locus-p run name))
                          collect name)))
    (remove-if (lambda (contact) (excused-at-corner-p run contact touching)) touching)))

(defun excused-at-corner-p (run contact touching)
  "True when CONTACT, one of the TOUCHING contacts, meets another of them at a corner that
is not concave (see CORNER-ALTERNATIVES), the observer separating from CONTACT's face
just before the impact and not from the other's. At such a corner the observer is
outside the obstacle when it is outside either face: the other face, which the impact
leaves unpenetrated (it pushes, or the bodies do not approach through it), keeps it
out, and CONTACT must not stop a motion that leaves past its end (a particle sliding
off the foot of a slope onto the ground, bouncing up)."
  (and (sign-is run (normal-approach run contact) :positive)
       (some (lambda (other)
               (and (member other touching)
                    (sign-is run (normal-approach run other) :negative :zero)))
             (touching-alternatives run contact))))

(defun reached-names (reached)
  "An alist name -> component: the names in the instances of the conditions of the
REACHED candidates, each with the component whose condition it is (the head of the
instance's key): what the impact is the reaching of."
  (loop for candidate in reached
        for condition = (candidate-condition candidate)
        for key = (and condition (ames.engine:termination-condition-instance condition))
        when (consp key)
          append (mapcar (lambda (name) (cons name (first key))) (alexandria:flatten (rest key)))))

(defun marked-reached (entities names)
  "ENTITIES, each (KIND NAME . PLIST), with :REACHED C added to those the knowledge base
makes of the scenario's clauses whose NAME the alist NAMES (see REACHED-NAMES) gives the
component C of: whose condition's reaching the impact is (a rope's piece closing up)."
  (mapcar (lambda (entity)
            (let ((entry (assoc (second entity) names)))
              (if entry (append entity (list :reached (cdr entry))) entity)))
          entities))

(defun impact-entities (run contacts &optional reached)
  "The situation of an impact (see src/kb/impacts.lisp): the bodies with their positions
and velocities just before, each of CONTACTS with its outward normal there
(AMES.KB:TOUCHING-CONTACT-ENTITY), and what the phenomena make of their clauses for an
impact (AMES.KB:IMPACT-ENTITIES-OF: the ropes), those the REACHED candidates' conditions
name marked :REACHED with their component (MARKED-REACHED)."
  (let ((scenario (run-scenario run)))
    (append
     (mapcar (lambda (body)
               (let ((name (scenario-body-name body)))
                 (append (list 'ames.kb:body name
                               :fixed (and (scenario-body-fixed-p body) t)
                               :driven (and (scenario-body-driven-p body) t)
                               :mass (scenario-body-mass body)
                               :position (body-position run name)
                               :velocity (body-velocity run name))
                         (and (rotating-p run name)
                              (append (rotation-properties body)
                                      (list :angle (body-angle run name)
                                            ;; cos and sin of the angle in the form the
                                            ;; geometry's arms take (one radical, not two)
                                            :turn (list (corner-now run name `(cos (ames.kb:angle ,name)))
                                                        (corner-now run name `(sin (ames.kb:angle ,name))))
                                            :angular-velocity (body-angular-velocity run name)))))))
             (scenario-bodies scenario))
     (marked-reached (ames.kb:impact-entities-of scenario) (reached-names reached))
     (touching-corner-entities run (remove-if-not (lambda (entry) (member (first entry) contacts))
                                                  (run-corner-contacts run)))
     (mapcar (lambda (contact)
               (let ((geometry (contact-geometry run contact)))
                 (destructuring-bind (observer obstacle) (contact-bodies run contact)
                   (ames.kb:touching-contact-entity
                    scenario contact observer obstacle
                    (mapcar (lambda (x) (tidy run x))
                            (ames.geometry:contact-outward-normal
                             geometry (initial-arc-length run contact)))))))
             ;; the corners' are TOUCHING-CORNER-ENTITIES
             (remove-if (lambda (contact) (assoc contact (run-corner-contacts run))) contacts)))))

(defun corner-now (run body expression)
  "EXPRESSION, over the rotating BODY's (pos BODY :x), (pos BODY :y) and (angle BODY),
at the current positions and angle."
  (let ((position (body-position run body)))
    (tidy run (substitute-expressions
               (list (cons `(ames.kb:pos ,body :x) (first position))
                     (cons `(ames.kb:pos ,body :y) (second position))
                     (cons `(ames.kb:angle ,body) (body-angle run body)))
               expression))))

(defun touching-corners (run &optional reached)
  "The corner contacts of RUN (corners.lisp: a rotating polygon's or segment's corner on
a fixed face) whose gap is zero now, or whose reaching ends the state (named by the
instance of one of the REACHED candidates: a state ended numerically leaves the gap at
its rounding, about 1e-15), as entries (NAME BODY OBSTACLE . GEOMETRY)."
  (let ((named (loop for candidate in reached
                     for condition = (candidate-condition candidate)
                     when condition
                       append (alexandria:flatten
                               (ames.engine:termination-condition-instance condition)))))
    (remove-if-not (lambda (entry)
                     (destructuring-bind (name body obstacle . geometry) entry
                       (declare (ignore obstacle))
                       (or (member name named) (corner-touches-at-impact-p run body geometry))))
                   (run-corner-contacts run))))

(defun corner-touches-at-impact-p (run body geometry)
  "True when the corner contact GEOMETRY of BODY touches now (CORNER-TOUCHING-NOW), an
undecided place within the face settled by the run's parameter values (recorded as
assumed from them). An impact is no place to branch: with no values that settle it,
signals UNSUPPORTED-SITUATION naming the relation, never guessed."
  (multiple-value-bind (verdict relation) (corner-touching-now run body geometry)
    (case verdict
      (:true t)
      (:false nil)
      (t (case (ames.algebra:decide-by-values relation)
           (:true t)
           (:false nil)
           (t (error 'unsupported-situation
                     :datum relation
                     :detail (format nil "Whether a corner of ~A touches within the face at the impact is not decided: ~S."
                                     body relation))))))))

(defun touching-corner-entities (run corners)
  "The touching contacts of the CORNERS touching now (TOUCHING-CORNERS), each with the
face's normal and the corner's arm from the body's centre at the current configuration."
  (loop for (name body obstacle . geometry) in corners
        collect (ames.kb:touching-contact-entity
                 (run-scenario run) name body obstacle
                 (mapcar (lambda (x) (corner-now run body x))
                         (ames.geometry:rotating-contact-normal geometry))
                 :arm (mapcar (lambda (x) (corner-now run body x))
                              (ames.geometry:rotating-contact-arm geometry)))))

(defun impact-contact-descriptions (run contacts)
  "Each of CONTACTS (shape contacts and corner contacts) as (BODY1 BODY2 :FEATURE F
:OBSERVER-FEATURE G), as CONTACT-DESCRIPTIONS gives a shape contact's."
  (loop for contact in contacts
        for corner = (assoc contact (run-corner-contacts run))
        collect (if corner
                    (destructuring-bind (name body obstacle . geometry) corner
                      (declare (ignore name))
                      (list body obstacle
                            :feature (ames.geometry:rotating-contact-other-feature geometry)
                            :observer-feature (ames.geometry:rotating-contact-feature geometry)))
                    (first (contact-descriptions run (list contact))))))

(defun rotations-after (run solved)
  "The rotating bodies' (BODY THETA OMEGA) just after the impact: the angle unchanged,
the angular velocity (ames.kb:angvel-after BODY) in SOLVED."
  (loop for (body theta) in (run-rotations run)
        collect (list body theta (quantity-value solved `(ames.kb:angvel-after ,body)))))

(defun impact-decider (run)
  "The decider of an impact's model: a relation over the impact's unknowns (whether a
touching contact pushes, whether a rough one sticks) is always a choice (settled by
consistency); everything else goes to Maxima, and what the
assumptions leave open to the run's parameter values when it has them (the fact is
recorded as assumed from the values: ames.algebra:DECIDE-BY-VALUES). An impact is no
place to branch: its outcome is one, the question only how the algebra shows it."
  (lambda (relation)
    (if (and (consp relation) (some #'quantity-term-p (expression-variables relation)))
        ;; over the impact's unknowns (a contact's separation just after, a slip):
        ;; settled by consistency
        :choice
        (let* ((relation (constant-roots-taken run (valued-relation run relation))) ; numeric-ends.lisp
               (verdict (decide run relation)))
          (or (and (eq verdict :unknown) (ames.algebra:decide-by-values relation))
              verdict)))))

(defun call-with-model (run model decider thunk)
  "Call THUNK with RUN working on MODEL and DECIDER (an impact's), then restore the
state's."
  (let ((saved (run-model run)))
    (setf (run-model run) model (run-decider-override run) decider)
    (unwind-protect (funcall thunk)
      (setf (run-model run) saved (run-decider-override run) nil))))

(defun resolve-impact (run &optional reached)
  "Resolve the impact at the run's current positions and velocities (those just before),
REACHED the impulsive candidates that end the state (see TOUCHING-CORNERS):
returns the velocities just after (an alist body -> (VX VY)) and a plist describing the
impact (:CONTACTS, :IMPULSES, :ENERGY-LOST, :VELOCITIES-BEFORE, :VELOCITIES-AFTER,
:CHOICES). Signals what the consistency search signals."
  (let* ((contacts (append (touching-contacts run) (mapcar #'first (touching-corners run reached))))
         (decider (impact-decider run))
         (situation (ames.engine:make-situation (impact-entities run contacts reached) :data run))
         (model (ames.engine:build-model (ames.engine:make-engine (ames.kb:impact-knowledge-base))
                                         situation :decider decider)))
    (call-with-model
     run model decider
     (lambda ()
       (let* ((trial (settle-choices run))
              (solved (trial-solved trial))
              (after (mapcar (lambda (body)
                               (list body
                                     (mapcar (lambda (axis)
                                               (quantity-value solved `(ames.kb:vel-after ,body ,axis)))
                                             '(:x :y))))
                             (body-names run)))
              (report (loop for (section entry) in (model-reported model)
                            collect (list section (value-entry solved entry)))))
         (values after
                 (append
                 (list :contacts (impact-contact-descriptions run (active-contact-instances run contacts))
                       :impulses (loop for (section entry) in report
                                       when (eq section :impulses) collect entry)
                       :energy-lost (loop for (section entry) in report
                                          when (eq section :impact) return (second entry))
                       :velocities-before (run-velocities run)
                       :velocities-after after
                       :choices (trial-notes trial))
                 ;; rotating bodies: their angular velocities just before and after
                 (and (run-rotations run)
                      (list :angular-velocities-before
                            (loop for (body nil omega) in (run-rotations run) collect (list body omega))
                            :angular-velocities-after
                            (loop for (body nil omega) in (rotations-after run solved)
                                  collect (list body omega)))))))))))

(defun active-contact-instances (run contacts)
  "Those of the touching CONTACTS an impulse acts through in the impact's model (an
(impulse NAME ... :contact K) belief), in the order of the beliefs."
  (remove-duplicates
   (loop for belief in (ames.engine:model-beliefs (run-model run))
         when (and (eq (first belief) 'ames.kb:impulse)
                   (member (getf (cddr belief) :contact) contacts))
           collect (getf (cddr belief) :contact))
   :from-end t))

(defun value-entry (solved form)
  "FORM, a report entry, with every quantity term replaced by its value in SOLVED."
  (cond ((quantity-term-p form) (quantity-value solved form))
        ((consp form) (mapcar (lambda (x) (value-entry solved x)) form))
        (t form)))

(defun impact-event (event impact)
  "EVENT, an impact event (:KIND NAME ...), with the impulse of the IMPACT's entries that
name only things EVENT names (an entry is (:KIND NAME... VALUE), as the impact's
components report them: the impulse between two bodies, or along a rope), and the
kinetic energy lost, from the resolved IMPACT."
  (let* ((impulses (remove-if-not (lambda (entry)
                                    (every (lambda (name) (member name (rest event)))
                                           (butlast (rest entry))))
                                  (getf impact :impulses)))
         (values (mapcar (lambda (entry) (car (last entry))) impulses)))
    (append event
            (list :impulse (if (rest values) (cons '+ values) (first values))
                  :energy-lost (getf impact :energy-lost)))))

;;; Zeno: impacts whose times form a geometric series

(defun scaling-factor (run before after)
  "The number LAMBDA with AFTER = LAMBDA * BEFORE for the velocity alists BEFORE and
AFTER (every body, both axes), when there is one; else NIL."
  (let ((factor nil))
    (loop for (body v) in after
          for u = (second (assoc body before))
          do (loop for a in v for b in u
                   do (cond ((holds run `(= ,b 0))
                             (unless (holds run `(= ,a 0)) (return-from scaling-factor nil)))
                            (t (let ((ratio (tidy run `(/ ,a ,b) :full)))
                                 (cond ((null factor) (setf factor ratio))
                                       ((not (ames.maxima:equivalent-p (run-bridge run) ratio factor))
                                        (return-from scaling-factor nil))))))))
    factor))

(defun same-positions-p (run a b)
  "True when the position alists A and B are proven equal."
  (every (lambda (entry)
           (let ((other (second (assoc (first entry) b))))
             (and other (every (lambda (x y) (ames.maxima:equivalent-p (run-bridge run) x y))
                               (second entry) other))))
         a))

(defun zeno-accumulation (run previous current)
  "When the impact records PREVIOUS and CURRENT (plists :TIME :POSITIONS :AFTER
:CONTACTS) repeat one another, the same contacts at the same positions with every
velocity after scaled by one factor 0 < LAMBDA < 1, and the flight between them under
constant accelerations (CURRENT's :UNIFORM: a flight from the same place with its velocity
scaled by LAMBDA then lasts LAMBDA times as long; a force that depends on the velocity or
the position, a drag or a spring, breaks the series), the impacts go on forever at times
in a geometric series: returns the plist (:FACTOR LAMBDA :CYCLE D :TIME T) with D the
time between the two impacts and T their accumulation point, CURRENT's time plus
LAMBDA D / (1 - LAMBDA). Else NIL."
  (when (and previous
             (getf current :uniform)
             (equal (getf previous :contacts) (getf current :contacts))
             (closed-form-time-p (getf previous :time))
             (closed-form-time-p (getf current :time))
             (same-positions-p run (getf current :positions) (getf previous :positions)))
    (let ((factor (scaling-factor run (getf previous :after) (getf current :after))))
      (when (and factor (holds run `(> ,factor 0)) (holds run `(< ,factor 1)))
        (let ((cycle (tidy run `(- ,(getf current :time) ,(getf previous :time)) :full)))
          (list :factor factor :cycle cycle
                :time (tidy run `(+ ,(getf current :time) (/ (* ,factor ,cycle) (- 1 ,factor))) :full)))))))

(defun impact-rotations (run impact)
  "RUN's rotations (BODY THETA OMEGA) once the resolved IMPACT has changed the angular
velocities (its :ANGULAR-VELOCITIES-AFTER; the angles do not jump)."
  (let ((after (getf impact :angular-velocities-after)))
    (loop for (body theta omega) in (run-rotations run)
          collect (list body theta (let ((entry (assoc body after)))
                                     (if entry (second entry) omega))))))
