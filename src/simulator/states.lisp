;;;; src/simulator/states.lisp -- one qualitative state analysed: its contacts and modes chosen,
;;;; its model solved and integrated, its end found, and the record a history keeps.
;;;;
;;;; Everything reported comes from the model: the forces are the knowledge base's
;;;; REPORTED beliefs with their quantities' values, the events those its components
;;;; name for the conditions that fired.

(in-package #:ames.simulator)

(defun body-group (groups body)
  "The GROUP among GROUPS that BODY belongs to, or NIL (a fixed body)."
  (find body groups :key #'group-bodies :test #'member))

(defun body-motion (run groups body what)
  "BODY's position (WHAT :POS) or velocity (:VEL) over its group's variable: a list
(X Y) of expressions; a fixed body's position, or (0 0) for its velocity; for a body
integrated numerically, the list (:NO-CLOSED-FORM)."
  (let ((group (body-group groups body)))
    (cond ((body-fixed-p run body)
           (if (eq what :pos) (body-position run body) (list 0 0)))
          ((eq (group-kind group) :numeric) (list :no-closed-form))
          (t (let ((head (if (eq what :pos) 'ames.kb:pos 'ames.kb:vel)))
               (mapcar (lambda (axis)
                         (cdr (assoc (list head body axis) (group-motion group) :test #'equal)))
                       '(:x :y)))))))

(defun over-motion (run solved groups expression)
  "EXPRESSION (over quantity terms) over the state's motion, simplified: a function of
TAU, or of the arc length for a body on a curve."
  (tidy run (motion-value groups (speed-line-signs-taken run groups (over-state-terms run solved expression)))
        :full))

(defun reported-entries (run solved groups section)
  "The entries the knowledge base reports in SECTION (:FORCES), their quantity terms
replaced by their values over the state's motion."
  (loop for (name entry) in (model-reported (run-model run))
        when (eq name section)
          collect (report-entry run solved groups entry)))

(defun reported-sections (run solved groups)
  "A plist of every section the knowledge base reports but :FORCES (such as :ENERGY and
:MOMENTUM), each with its entries' values over the state's motion."
  (let ((sections (remove :forces (remove-duplicates (mapcar #'first (model-reported (run-model run)))))))
    (loop for section in sections
          append (list section (reported-entries run solved groups section)))))

(defun report-entry (run solved groups form)
  "FORM, a report entry, with every quantity term in it replaced by its value."
  (cond ((quantity-term-p form) (over-motion run solved groups form))
        ((consp form) (mapcar (lambda (x) (report-entry run solved groups x)) form))
        (t form)))

(defun contact-descriptions (run contacts)
  "Each contact as (BODY1 BODY2 :FEATURE F :OBSERVER-FEATURE G)."
  (mapcar (lambda (contact)
            (let ((geometry (contact-geometry run contact)))
              (append (contact-bodies run contact)
                      (list :feature (ames.geometry:contact-obstacle-feature geometry)
                            :observer-feature (ames.geometry:contact-observer-feature geometry)))))
          contacts))

(defun end-event-of (fired)
  "The one event a state reports as its end, of the FIRED candidates: an impact's first
(a condition reached at a non-zero rate that its component declares impulsive, see
IMPULSIVE-P), else the first candidate's."
  (candidate-event (or (find-if #'impulsive-p fired) (first fired))))

(defun group-at-end (run groups group fired)
  "GROUP's end value: the arc length where FIRED ends it when it moves along a curve
(one of the fired candidates is on it), else the end time. Signals
UNSUPPORTED-SITUATION for a curved motion ended by another group's event (its place
then has no closed form)."
  (if (member (group-kind group) '(:path :line :rotation-path))
      (let ((own (find group fired :key #'candidate-group)))
        (unless own
          (error 'unsupported-situation
                 :datum (group-bodies group)
                 :detail "Another body's event ends the state while this body moves along a curve: where it is then has no closed form."))
        (candidate-at-arc own))
      (progn run groups (candidate-time (first fired)))))

(defun line-notes (groups)
  "The notes of the state's motions along a line of the configuration space (see
line.lisp) or along a rotating body's angle (rotation-path.lisp): the coordinate s, its
start and direction, and the energy integral."
  (loop for group in groups
        when (member (group-kind group) '(:line :rotation-path))
          collect (list :bodies (group-bodies group)
                        :coordinate (getf (group-line group) :coordinate)
                        :from (group-s0 group)
                        :direction (group-direction group)
                        :energy-integral `(= (expt arc-speed 2) ,(group-speed-squared group))
                        :ode (group-ode-kind group))))

(defun path-notes (run solved groups)
  "The notes of the state's curved motions: for each, its arc length's start, the
tangential acceleration, the energy integral and the normal forces over the arc."
  (loop for group in groups
        when (eq (group-kind group) :path)
          collect (let ((contact (group-contact group)))
                    (list :contact (contact-bodies run contact)
                          :arc-length-from (group-s0 group)
                          :direction (group-direction group)
                          :tangential-acceleration
                          (over-motion run solved groups
                                       `(ames.kb:path-acc ,contact :tangential))
                          :energy-integral `(= (expt arc-speed 2) ,(group-speed-squared group))
                          :ode (group-ode-kind group)))))

(defun reported-motion (run groups what)
  "Every body's position or velocity over the state, as the history reports it: for a
body on a curve, (:ON-PATH (X Y) :ARC-LENGTH S) over the arc length."
  (mapcar (lambda (body)
            (let ((group (find body groups :key #'group-bodies :test #'member))
                  (motion (body-motion run groups body what)))
              (list body (if (and group (member (group-kind group) '(:path :line :rotation-path)))
                             (list :on-path (mapcar (lambda (x) (tidy run x)) motion)
                                   :arc-length +arc-length+)
                             motion))))
          (body-names run)))

(defun time-limit-candidate (run)
  "The (simulate :until T) end as a CANDIDATE, when the scenario sets one and the
state's start time is an expression."
  (let ((until (scenario-until (run-scenario run))))
    (when (and until (closed-form-time-p (run-time run)))
      (make-candidate nil (list :time-limit until) (tidy run `(- ,until ,(run-time run)))))))

(defun impacts-at-once (run)
  "The activation conditions of the contacts reached with a velocity at the start of the
state (see APPROACHING-NOW-P), as CANDIDATEs at time 0 with their impact events."
  (loop for condition in (ames.engine:model-termination-conditions (run-model run))
        for contact = (and (eq (ames.engine:termination-condition-kind condition) :activation)
                           (gap-relation-contact (ames.engine:termination-condition-relation condition)))
        when (and contact (approaching-now-p run contact))
          collect (let ((rate (normal-approach run contact)))
                    (make-candidate condition (condition-event condition rate) 0 :rate rate))))

(defun contact-names (run)
  "An alist contact entity -> a phrase naming it by its bodies and features, for
explanations."
  (mapcar (lambda (entry)
            (let ((geometry (cdr entry)))
              (cons (car entry)
                    (format nil "~(~A~) on ~(~A~)"
                            (ames.geometry:contact-observer geometry)
                            (ames.geometry:contact-obstacle geometry)))))
          (run-contacts run)))

(defun equation-sources (model)
  "Each equation of MODEL with where it comes from: (EQUATION COMPONENT INSTANCE-KEY),
COMPONENT the informant of its justification in the JTMS (the component that asserted
it) and INSTANCE-KEY the instance."
  (loop for equation in (ames.engine:model-equations model)
        collect (let* ((node (ames.engine:find-node model equation))
                       (support (and node (ames.tms:node-support node))))
                  (if (ames.tms:justification-p support)
                      (list equation (ames.tms:justification-informant support)
                            (let ((instance (find-if (lambda (antecedent)
                                                       (let ((datum (ames.tms:node-datum antecedent)))
                                                         (and (consp datum) (eq (first datum) :instance))))
                                                     (ames.tms:justification-antecedents support))))
                              (and instance (second (ames.tms:node-datum instance)))))
                      (list equation nil nil)))))

(defun solved-accelerations (run solved groups)
  "Each body's acceleration in the SOLVED model, (BODY (AX AY)), in the body order of
RUN; (0 0) for a fixed body."
  (mapcar (lambda (body)
            (list body (if (body-fixed-p run body)
                           '(0 0)
                           (mapcar (lambda (axis)
                                     (over-motion run solved groups
                                                  `(ames.kb:acc ,body ,axis)))
                                   '(:x :y)))))
          (body-names run)))

(defun new-qualitative-state (run index trial solved groups)
  "The QUALITATIVE-STATE numbered INDEX that starts now, from the settled TRIAL, its
SOLVED model and the integrated GROUPS, its duration and end still :UNDECIDED."
  (let ((contacts (active-contacts run)))
    ;; the reported quantities' simplifications asked together (prefetch-values.lisp)
    (prefetch-quantity-values run solved (reported-quantity-terms run))
    (make-instance
     'qualitative-state
     :index index :start (run-time run) :duration :undecided
     :initial-velocities (run-velocities run)
     :contacts (contact-descriptions run contacts)
     :contact-points (mapcar (lambda (contact) (contact-touching run contact)) contacts)
     :accelerations (solved-accelerations run solved groups)
     :forces (reported-entries run solved groups :forces)
     :positions (reported-motion run groups :pos)
     :velocities (reported-motion run groups :vel)
     :end-event :undecided
     :analysis (list :equations (equation-sources (run-model run))
                     :contact-names (contact-names run)
                     :compact-equations (solved-model-equations solved)
                     :choices (trial-notes trial)
                     :integrators (mapcar (lambda (g) (list (group-bodies g) (group-kind g)))
                                          groups)
                     :check-model (check-model run solved))
     :path-coordinates (first (path-notes run solved groups))
     :line-coordinates (line-notes groups)
     :reported-sections (reported-sections run solved groups))))

(defun new-state (run index trial solved groups)
  "NEW-QUALITATIVE-STATE with the rotating bodies' motion noted (rotation.lisp)."
  (let ((state (new-qualitative-state run index trial solved groups)))
    (note-rotation-start run state solved groups)
    state))

(defun state-end-candidates (run solved groups state)
  "The events that may end STATE, as four values: the CANDIDATEs, the events whose time
is unknown, the events that never happen, and a flag. The flag is true when there is no
closed form and no numbers, so that the end cannot be found; STATE then says so."
  (let ((impacts (impacts-at-once run)))
    (if impacts
        (values impacts '() nil nil)
        (handler-case (multiple-value-bind (candidates unknown never)
                          (candidates-of run solved groups)
                        (values candidates unknown never nil))
          (no-closed-form (condition)
            ;; no closed form and no numbers: the state's end cannot be found
            (setf (state-duration state) (list :no-closed-form :needs :parameter-values)
                  (state-end-event state) :undecided
                  (state-undecided-detail state) (ames-error-detail condition))
            (values nil nil nil t))))))

(defun earliest-state-end (run state candidates unknown)
  "The CANDIDATEs (with the run's time limit) that fire first, as EARLIEST-CANDIDATES
finds them; an AMBIGUOUS-TRANSITION it signals carries STATE."
  (let ((limit (time-limit-candidate run)))
    (handler-bind ((ambiguous-transition
                     (lambda (condition)
                       (setf (ambiguous-transition-state condition) state))))
      (earliest-candidates run (if limit (cons limit candidates) candidates)
                           unknown))))

(defun note-state-candidates (state candidates fired never)
  "Record in STATE's analysis each candidate with its time and whether it FIRED, and
the events that NEVER happen."
  (setf (getf (state-analysis state) :candidates)
        (append (mapcar (lambda (c) (list (candidate-event c) :at (candidate-time c)
                                          :fired (and (member c fired) t)))
                        candidates)
                (mapcar (lambda (event) (list event :never)) never))))

(defun note-state-end (run state groups fired)
  "Record in STATE its end by the FIRED candidates (at least one): the duration, the
event, the final positions and velocities, the simultaneous events, the numeric
trajectory and the arc length reached."
  (let ((time (candidate-time (first fired))))
    (setf (state-duration state) time
          (state-end-event state) (end-event-of fired)
          (state-final-positions state) (end-values run groups fired :pos)
          (state-final-velocities state) (end-values run groups fired :vel))
    (note-rotation-end run state groups fired)
    (when (rest fired)
      (setf (state-simultaneous-events state) (mapcar #'candidate-event fired)))
    (let ((numeric (remove nil (mapcar #'group-samples groups))))
      (when numeric
        (setf (state-numeric-trajectory state) numeric)))
    (let ((arc (find-if #'candidate-at-arc fired)))
      (when arc
        (setf (state-end-arc-length state) (candidate-at-arc arc))))))

(defun note-state-forever (run state groups)
  "Record that STATE, which no event ends, lasts forever; periodic when every body
oscillates with one frequency."
  (unless (state-periodic state)
    ;; a swing between two turning points is watched by them (turns.lisp)
    (check-rotation-paths-forever run groups))
  (let ((oscillation (and (not (state-periodic state))
                          (linear-oscillation run groups))))
    (when oscillation
      ;; one frequency for every body: periodic (oscillation.lisp)
      (setf (state-periodic state) oscillation)))
  (setf (state-duration state) :forever (state-end-event state) :none))

(defun analyse-state (run index)
  "Choose, build, solve, integrate and end the current state, numbered INDEX. Returns
the QUALITATIVE-STATE and the fired CANDIDATEs (NIL when it lasts forever). When which
event ends it is ambiguous, the AMBIGUOUS-TRANSITION carries the state as far as it is
known."
  (let* ((trial (settle-choices run))
         (solved (trial-solved trial))
         (groups (integrate-groups run solved))
         (state (new-state run index trial solved groups)))
    (multiple-value-bind (candidates unknown never undecided)
        (state-end-candidates run solved groups state)
      (when undecided
        (return-from analyse-state (values state :undecided)))
      (let ((fired (earliest-state-end run state candidates unknown)))
        (note-state-candidates state candidates fired never)
        (let ((swing (periodic-swing run solved fired)))
          (when swing
            ;; between two turning points: periodic, forever (turns.lisp)
            (setf (state-periodic state) swing
                  fired nil)))
        (when fired
          (note-state-end run state groups fired))
        (unless fired
          (note-state-forever run state groups))
        (values state fired)))))
