;;;; src/kb/springs.lisp -- ideal springs (Hooke's law) and bumpers (thesis 3.3.2, "Springs").
;;;;
;;;; The spring phenomenon (below) describes the scenario's springs with these entities (the
;;;; point contacts are the loci of its probes, which the simulator has the geometry give):
;;;;   (spring S :from (B1 (X1 Y1)) :to (B2 (X2 Y2)) :stiffness K :rest-length L0)
;;;;   (bumper S :on B :at (X Y) :toward (DX DY) :stiffness K :rest-length L0)
;;;;   (point-contact C :point S :observer B :obstacle B2 :geometry G)
;;;; A point contact is a locus of the bumper's free end (the point at distance L0 from its
;;;; attachment along (DX DY), a point of body B) against a face of another body B2: the
;;;; geometry's simple contact G, B2's shape seen by that point. Unlike a body's own
;;;; contacts it can be crossed: B2 pressing into the free end compresses the spring.
;;;;
;;;; An attached spring acts along its span (src/kb/spans.lisp): the force on B2 is
;;;; -K (l - L0) u, u the unit vector from B1's point to B2's, and Newton's third law gives
;;;; B1's. A bumper touched by B2 (the thesis's spring end in contact with the block) pushes
;;;; it along (DX DY) with K times the compression, never pulls, and is left when the
;;;; compression returns to zero. The compression is measured along the bumper's axis: the
;;;; free end, pushed back along the axis, stays on B2's face (exact on a straight face;
;;;; the face's ends are those of the free end's resting point). Reported in :forces as
;;;; (:spring S BODY (FX FY)) for each body the spring acts on.

(in-package #:ames.kb)

(define-condition unmodelled-situation (ames-error) ()
  (:documentation "A situation the knowledge base has no model for (a bumper against a
curved face, ...). DATUM names the entity, DETAIL says what is missing."))

(defun bumper-axis (situation bumper)
  "The unit vector (UX UY) of BUMPER's axis, from its attachment toward its free end."
  (let* ((toward (entity-property (entity-named situation bumper) :toward))
         (norm (ames.geometry:vector-length toward)))
    (mapcar (lambda (x) `(/ ,x ,norm)) toward)))

(defun point-contact-compression (situation contact)
  "How far the bumper's free end is pushed back along its axis by the obstacle of the
point CONTACT: the free end's resting point's depth behind the obstacle's face, measured
along the axis. Only straight faces: signals UNMODELLED-SITUATION for a curved one."
  (let* ((entity (entity-named situation contact))
         (geometry (entity-property entity :geometry))
         (bumper (entity-named situation (entity-property entity :point)))
         (observer (entity-property entity :observer))
         (obstacle (entity-property entity :obstacle)))
    (unless (member (ames.geometry:contact-kind geometry) '(:segment :line))
      (error 'unmodelled-situation
             :datum contact
             :detail (format nil "The bumper ~A meets a curved face of ~A: only straight faces are modelled."
                             (entity-name bumper) obstacle)))
    (let* ((relative (mapcar (lambda (axis)
                               `(- ,(point-term situation (list observer '(0 0)) axis 'pos)
                                   ,(point-term situation (list obstacle '(0 0)) axis 'pos)))
                             '(:x :y)))
           (start (ames.geometry:contact-point geometry 0))
           (normal (ames.geometry:contact-outward-normal geometry 0))
           (depth `(- ,(ames.geometry:dot (mapcar (lambda (q p) `(- ,q ,p)) relative start) normal))))
      ;; the free end pushed back by c along -u stays on the face: depth = c (-u.n)
      `(/ ,depth (- ,(ames.geometry:dot (bumper-axis situation (entity-name bumper)) normal))))))

(defun register-spring-templates (kb)
  "Register in KB the template functions of springs and bumpers."
  (flet ((property (key)
           (lambda (situation name) (entity-property (entity-named situation name) key))))
    (register-template kb 'stiffness (property :stiffness)
                       :documentation "A spring's stiffness K.")
    (register-template kb 'rest-length (property :rest-length)
                       :documentation "A spring's rest length L0.")
    (register-template kb 'bumper-direction
                       (lambda (situation bumper axis) (axis-component (bumper-axis situation bumper) axis))
                       :documentation "A component of a bumper's unit axis.")
    (register-template kb 'compression #'point-contact-compression
                       :documentation "How far a point contact's obstacle pushes a bumper's free end back.")
    (register-template kb 'pressed
                       (lambda (situation contact)
                         (declare (ignore situation))
                         (list '<= (list 'contact-gap contact) 0))
                       :documentation "The obstacle reaches or presses a point contact's point.")))

(register-spring-templates *mechanics*)

(defcomponent spring-along-span (:knowledge-base *mechanics*)
  "An attached spring lies along the straight span between its attachment points."
  (:arguments (?spring :entity spring :where (:from ?a :to ?b)))
  (:assert (span ?spring :from ?a :to ?b)))

(defcomponent hookes-law (:knowledge-base *mechanics*)
  "An ideal spring pulls its second body back toward its first with K times its
extension, along the span: -K (l - L0) u (Hooke's law); Newton's third law gives the
first body's force."
  (:arguments (?spring :entity spring :where (:from (?body1 ?_) :to (?body2 ?_))))
  (:assert (force (spring ?spring ?body2) :type spring :from ?body1 :on ?body2 :contact ?spring)
           (force (spring ?spring ?body1) :type spring :from ?body2 :on ?body1 :contact ?spring)
           (reported :forces (:spring ?spring ?body1 ((fx spring ?spring ?body1) (fy spring ?spring ?body1))))
           (reported :forces (:spring ?spring ?body2 ((fx spring ?spring ?body2) (fy spring ?spring ?body2)))))
  (:equations (= (force-x (spring ?spring ?body2))
                 (* -1 (stiffness ?spring) (- (span-length ?spring) (rest-length ?spring))
                    (span-direction ?spring :x)))
              (= (force-y (spring ?spring ?body2))
                 (* -1 (stiffness ?spring) (- (span-length ?spring) (rest-length ?spring))
                    (span-direction ?spring :y)))))

(defcomponent bumper-contact (:knowledge-base *mechanics*)
  "A body pressing a bumper's free end compresses it: the bumper pushes the body along
its axis with K times the compression (and its mount back, Newton's third law). It is
met when the body reaches the free end and left when the compression returns to zero
(it never pulls)."
  (:arguments (?contact :entity point-contact :where (:point ?spring :observer ?mount :obstacle ?body))
              (?spring :entity bumper))
  (:activation (pressed ?contact) (:event (:contact ?body ?spring)))
  (:deactivation (:when (< (compression ?contact) 0) :event (:leaves ?body ?spring)))
  (:assert (pressing ?body ?spring :along ?contact)
           (force (bumper ?contact ?body) :type spring :from ?mount :on ?body :contact ?contact)
           (force (bumper ?contact ?mount) :type spring :from ?body :on ?mount :contact ?contact)
           (reported :forces (:spring ?spring ?mount ((fx bumper ?contact ?mount) (fy bumper ?contact ?mount))))
           (reported :forces (:spring ?spring ?body ((fx bumper ?contact ?body) (fy bumper ?contact ?body)))))
  (:equations (= (force-x (bumper ?contact ?body))
                 (* (stiffness ?spring) (compression ?contact) (bumper-direction ?spring :x)))
              (= (force-y (bumper ?contact ?body))
                 (* (stiffness ?spring) (compression ?contact) (bumper-direction ?spring :y)))))

(defcomponent spring-closing (:knowledge-base *mechanics*)
  "A spring whose ends move along its line can shrink to zero length and open again on
the other side: its line of action is defined by its ends (Hooke's d/|d|), so its
direction turns over there. Its length along the line, which changes sign where the ends
meet, is watched: the event (:spring-closes S) ends the state at zero length, and the
next state's span opens along the ends' relative velocity (spans.lisp)."
  (:arguments (?spring :entity spring)
              (?opening :belief (aligned-span ?spring :from ?a :to ?b :opening ?opening)))
  (:mode :open
   (:entry (>= (line-span-length ?a ?b ?opening) 0))
   (:transition :to :through :when (< (line-span-length ?a ?b ?opening) 0) :event (:spring-closes ?spring)))
  ;; never at a state's start: the length along the line starts at |d0| >= 0
  (:mode :through
   (:entry (< (line-span-length ?a ?b ?opening) 0))))

;;; The potential energies (energy.lisp says what a state reports of energy)

(defcomponent elastic-potential-energy (:knowledge-base *mechanics*)
  "A spring's potential energy is 1/2 K (l - L0)^2."
  (:arguments (?spring :entity spring))
  (:assert (reported :energy (:potential (:spring ?spring) (potential-energy spring ?spring))))
  (:equations (= (potential-energy spring ?spring)
                 (* 1/2 (stiffness ?spring) (expt (- (span-length ?spring) (rest-length ?spring)) 2)))))

(defcomponent bumper-potential-energy (:knowledge-base *mechanics*)
  "A compressed bumper's potential energy is 1/2 K c^2, c its compression."
  (:arguments (?contact :belief (pressing ?body ?spring :along ?contact)))
  (:assert (reported :energy (:potential (:bumper ?spring ?body) (potential-energy bumper ?contact))))
  (:equations (= (potential-energy bumper ?contact)
                 (* 1/2 (stiffness ?spring) (expt (compression ?contact) 2)))))

;;; The clause, the bumper's free end, and the names (see phenomena.lisp)

(defun spring-entities (scenario)
  "Each (spring ...) clause of SCENARIO as a SPRING entity (attached at both ends) or a
BUMPER entity (attached at one end, :toward its free end)."
  (mapcar (lambda (spring)
            (let ((name (ames.scenario:scenario-spring-name spring))
                  (from (ames.scenario:scenario-spring-from spring))
                  (stiffness (ames.scenario:scenario-spring-stiffness spring))
                  (rest-length (ames.scenario:scenario-spring-rest-length spring)))
              (if (ames.scenario:scenario-spring-bumper-p spring)
                  (list 'bumper name :on (first from) :at (second from)
                                     :toward (ames.scenario:scenario-spring-toward spring)
                                     :stiffness stiffness :rest-length rest-length)
                  (list 'spring name :from from :to (ames.scenario:scenario-spring-to spring)
                                     :stiffness stiffness :rest-length rest-length))))
          (ames.scenario:scenario-springs scenario)))

(defun bumper-axis-vector (spring)
  "The unit vector along the bumper SPRING's axis (a scenario spring), toward its free end."
  (destructuring-bind (dx dy) (ames.scenario:scenario-spring-toward spring)
    (let ((norm `(sqrt (+ (expt ,dx 2) (expt ,dy 2)))))
      (list `(/ ,dx ,norm) `(/ ,dy ,norm)))))

(defun bumper-free-end (spring)
  "The point of the bumper SPRING's body where its free end rests: (X Y) in its frame, at
the rest length from the attachment along the axis."
  (destructuring-bind (x y) (second (ames.scenario:scenario-spring-from spring))
    (destructuring-bind (ux uy) (bumper-axis-vector spring)
      (let ((l0 (ames.scenario:scenario-spring-rest-length spring)))
        (list `(+ ,x (* ,l0 ,ux)) `(+ ,y (* ,l0 ,uy)))))))

(defun bumper-probes (scenario)
  "Each bumper's free end as a probe: a point of its body that retreats along the axis
when pressed, whose loci on the other bodies are POINT-CONTACT entities."
  (loop for spring in (ames.scenario:scenario-springs scenario)
        when (ames.scenario:scenario-spring-bumper-p spring)
          collect (list :point (ames.scenario:scenario-spring-name spring)
                        :body (first (ames.scenario:scenario-spring-from spring))
                        :at (bumper-free-end spring)
                        :axis (bumper-axis-vector spring)
                        :kind 'point-contact)))

(define-phenomenon spring
  "Ideal springs attached at both ends (Hooke's law) and bumpers (a spring attached at one
end, pushing what presses its free end): the spring clause."
  (:entities #'spring-entities)
  (:probes #'bumper-probes)
  (:force :spring :names 2 :words "spring ~A on ~A")
  (:event :spring-closes :words "~A shrinks to zero length (its ends meet) and opens on the other side"))
