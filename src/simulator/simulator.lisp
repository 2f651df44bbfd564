;;;; src/simulator/simulator.lisp -- the qualitative-state simulator (thesis sections 2.5.8 and 3.2.3).
;;;;
;;;; For each qualitative state:
;;;;   1. the contacts: from the geometry for the first state, from the transition afterwards;
;;;;   2. the model: the mechanics knowledge base instantiated by the engine (every belief
;;;;      justified in its JTMS);
;;;;   3. the solution, through the Maxima bridge: accelerations and contact forces; on straight
;;;;      contacts motion is polynomial in the state's time TAU; on a curved contact the
;;;;      path-coordinate equation is integrated (closed form, or the energy integral);
;;;;   4. termination: the earliest of the termination conditions, proven earliest under the
;;;;      scenario's assumptions, or an AMBIGUOUS-TRANSITION naming the missing fact;
;;;;   5. the next state: positions and velocities carry over, and what changed qualitatively
;;;;      comes from the condition that fired, applied to the model incrementally (checked
;;;;      against a rebuild from scratch on every transition).

(in-package #:ames.simulator)

;;; Conditions

(define-condition simulation-error (ames-error) ()
  (:documentation "The simulation cannot go on. DATUM names the state, model or fact."))

(define-condition ambiguous-transition (simulation-error)
  ((candidates :initarg :candidates :reader ambiguous-transition-candidates
               :documentation "The termination candidates, each (EVENT TIME).")
   (missing-fact :initarg :missing-fact :reader ambiguous-transition-missing-fact
                 :documentation "A relation the assumptions do not decide.")
   (state :initarg :state :initform nil :accessor ambiguous-transition-state
          :documentation "The state whose end is ambiguous, as far as it is known (its model
and motion), or NIL."))
  (:documentation "Which termination condition comes first cannot be decided under the
scenario's assumptions (branching on it comes later). Restart: STOP-SIMULATION.")
  (:report (lambda (condition stream)
             (format stream "Ambiguous transition: which event ends the state is not decided by the assumptions.~%  missing fact: ~S~%  candidates:~{~%    ~S~}"
                     (ambiguous-transition-missing-fact condition)
                     (ambiguous-transition-candidates condition)))))

(define-condition unsolvable-model (simulation-error) ()
  (:documentation "The state's model has no solution, or no unique one."))

(define-condition unsupported-situation (simulation-error) ()
  (:documentation "The state is outside what AMES can model yet (named in DETAIL)."))

;;; The run: everything one simulation works with

(defclass run ()
  ((scenario :initarg :scenario :reader run-scenario)
   (bridge :initarg :bridge :reader run-bridge)
   (shapes :initarg :shapes :reader run-shapes
           :documentation "Alist body name -> ames.geometry shape.")
   (contacts :initarg :contacts :reader run-contacts
             :documentation "Alist contact entity name -> ames.geometry simple contact.")
   (model :initform nil :accessor run-model)
   (positions :initarg :positions :accessor run-positions
              :documentation "Alist body -> (X Y) at the start of the current state.")
   (velocities :initarg :velocities :accessor run-velocities
               :documentation "Alist body -> (VX VY) at the start of the current state.")
   (time :initform 0 :accessor run-time
         :documentation "Global time at which the current state starts.")
   (rederived :initform '() :accessor run-rederived
              :documentation "Instances re-derived at each transition (for benchmarks)."))
  (:documentation "The working context of one simulation."))

(defun run-body (run name)
  "The scenario body called NAME."
  (find-scenario-body name (run-scenario run)))

(defun body-fixed-p (run name)
  "True when body NAME is glued to the fixed frame."
  (scenario-body-fixed-p (run-body run name)))

(defun contact-geometry (run contact)
  "The ames.geometry simple contact behind the contact entity CONTACT."
  (cdr (assoc contact (run-contacts run))))

(defun tidy (run expression &optional (strategy :ratsimp))
  "EXPRESSION simplified by Maxima (rational canonical form unless STRATEGY says)."
  (ames.maxima:simplify (run-bridge run) expression :strategy strategy))

;;; Vectors of expressions

(defun vec+ (a b) (list `(+ ,(first a) ,(first b)) `(+ ,(second a) ,(second b))))
(defun vec- (a b) (list `(- ,(first a) ,(first b)) `(- ,(second a) ,(second b))))
(defun vec-dot (a b) `(+ (* ,(first a) ,(first b)) (* ,(second a) ,(second b))))

;;; Setting a run up

(defun contact-entity-name (index)
  "The symbol naming the INDEXth simple contact in the engine's situation."
  (intern (format nil "CONTACT-~D" index) '#:ames))

(defun body-shapes (scenario bridge)
  "Alist body name -> geometry shape for every body of SCENARIO."
  (mapcar (lambda (body)
            (cons (scenario-body-name body)
                  (ames.geometry:parse-shape (scenario-body-shape body) :bridge bridge)))
          (scenario-bodies scenario)))

(defun all-simple-contacts (scenario shapes bridge)
  "Alist contact name -> geometry contact for every pair of bodies not both fixed."
  (let ((contacts '()) (index 0))
    (loop for (body-1 . rest) on (scenario-bodies scenario)
          do (dolist (body-2 rest)
               (unless (and (scenario-body-fixed-p body-1) (scenario-body-fixed-p body-2))
                 (let* ((name-1 (scenario-body-name body-1))
                        (name-2 (scenario-body-name body-2))
                        (pair (ames.geometry:make-contact-pair
                               name-1 (cdr (assoc name-1 shapes))
                               name-2 (cdr (assoc name-2 shapes))
                               :bridge bridge
                               :fixed (mapcar #'scenario-body-name
                                              (scenario-fixed-bodies scenario)))))
                   (dolist (contact (ames.geometry:pair-contacts pair))
                     (push (cons (contact-entity-name index) contact) contacts)
                     (incf index))))))
    (nreverse contacts)))

(defun situation-entities (run)
  "The entities the mechanics knowledge base reads (see src/kb/mechanics.lisp)."
  (let ((scenario (run-scenario run)))
    (append
     (mapcar (lambda (body)
               (list 'ames.kb:body (scenario-body-name body)
                     :fixed (and (scenario-body-fixed-p body) t)
                     :mass (scenario-body-mass body)))
             (scenario-bodies scenario))
     (when (scenario-gravity scenario)
       (list (list 'ames.kb:gravity-field 'earth :strength (scenario-gravity scenario))))
     (mapcar (lambda (force)
               (list 'ames.kb:external-force (scenario-force-name force)
                     :on (scenario-force-body force)
                     :fx (first (scenario-force-value force))
                     :fy (second (scenario-force-value force))))
             (scenario-forces scenario))
     (mapcar (lambda (entry)
               (let ((contact (cdr entry)))
                 (list 'ames.kb:simple-contact (car entry)
                       :observer (ames.geometry:contact-observer contact)
                       :obstacle (ames.geometry:contact-obstacle contact)
                       :geometry contact)))
             (run-contacts run)))))

;;; Relative motion on contacts

(defun body-position (run body) (second (assoc body (run-positions run))))
(defun body-velocity (run body) (second (assoc body (run-velocities run))))

(defun relative-initial-state (run contact)
  "The observer's position and velocity relative to the obstacle at the state's start."
  (let ((geometry (contact-geometry run contact)))
    (values (vec- (body-position run (ames.geometry:contact-observer geometry))
                  (body-position run (ames.geometry:contact-obstacle geometry)))
            (vec- (body-velocity run (ames.geometry:contact-observer geometry))
                  (body-velocity run (ames.geometry:contact-obstacle geometry))))))

(defun touching-now (run contact)
  "Whether CONTACT holds at the start of the state: the relative position lies on its
locus and the relative velocity has no normal part. :TRUE or :FALSE."
  (let ((geometry (contact-geometry run contact)))
    (multiple-value-bind (q v) (relative-initial-state run contact)
      (if (not (ames.geometry:position-on-contact-p geometry q))
          :false
          (let* ((s (ames.geometry:contact-parameter geometry q))
                 (normal (ames.geometry:contact-outward-normal geometry s)))
            (if (holds run `(= ,(vec-dot v normal) 0))
                :true
                :false))))))

(defun state-decider (run)
  "The decider the engine uses for the quantitative activation conditions of this state:
TOUCHING relations go to the geometry, everything else to Maxima."
  (lambda (relation)
    (if (and (consp relation) (eq (first relation) '=)
             (consp (second relation)) (eq (first (second relation)) 'ames.kb:contact-gap))
        (touching-now run (second (second relation)))
        (ames.maxima:decide (run-bridge run) relation))))

;;; Solving a state's model

(defun derivative-equation-p (model equation)
  "True when EQUATION comes from a DERIVATIVE-RELATIONS instance of MODEL."
  (some (lambda (instance)
          (and (eq (ames.engine:component-name (ames.engine:instance-component instance))
                   'ames.kb::derivative-relations)
               (member equation (ames.engine:instance-equations instance) :test #'equal)))
        (ames.engine:model-active-instances model)))

(defun state-value-term-p (term)
  "True for the quantity terms that are the state's given values, not unknowns."
  (member (first term) '(ames.kb:pos0 ames.kb:vel0 ames.kb:path-position ames.kb:path-speed)))

(defun active-contacts (run)
  "The contact entities whose CONTACT instance is active in the current model."
  (loop for (name) in (run-contacts run)
        for instance = (ames.engine:find-instance (run-model run) (list 'ames.kb::contact name))
        when (and instance (ames.engine:instance-active-p instance))
          collect name))

(defun used-quantity-terms (run contacts)
  "The quantity terms whose values a state uses: every body's acceleration, the normal
force of each of CONTACTS (and its tangential path acceleration when it is curved), and
the terms of the model's termination conditions."
  (remove-duplicates
   (append (loop for body in (scenario-bodies (run-scenario run))
                 for name = (scenario-body-name body)
                 collect `(ames.kb:acc ,name :x) collect `(ames.kb:acc ,name :y))
           (loop for contact in contacts
                 collect `(ames.kb:normal-force ,contact)
                 when (curved-contact-p run contact)
                   collect `(ames.kb:path-acc ,contact :tangential))
           (loop for condition in (ames.engine:model-termination-conditions (run-model run))
                 append (remove-if-not #'quantity-term-p
                                       (expression-variables
                                        (ames.engine:termination-condition-relation condition)))))
   :test #'equal))

(defun solve-instantaneous-model (run equations &optional (used :all))
  "Solve the model's EQUATIONS (without the derivative relations) for every unknown
quantity term. Returns the solution alist, the values of the terms in USED (a list, see
USED-QUANTITY-TERMS, or :ALL) in their simplest form, the others as Maxima's solve()
gives them (their simplification is costly, and a state reads them not). Signals
UNSOLVABLE-MODEL."
  (let ((unknowns (remove-if #'state-value-term-p
                             (remove-if-not #'quantity-term-p
                                            (remove-duplicates
                                             (mapcan #'expression-variables equations)
                                             :test #'equal)))))
    (let ((solutions (handler-case
                         (ames.maxima:solve-equations (run-bridge run) equations unknowns)
                       (ames.maxima:solve-failed (condition)
                         (error 'unsolvable-model :datum equations
                                                  :detail (format nil "Maxima cannot solve the state's model: ~A"
                                                                  (ames-error-detail condition)))))))
      (cond ((null solutions)
             (error 'unsolvable-model :datum equations
                                      :detail "The state's model has no solution."))
            ((rest solutions)
             (error 'unsolvable-model :datum equations
                                      :detail "The state's model has several solutions."))
            (t (mapcar (lambda (entry)
                         (if (or (eq used :all) (member (car entry) used :test #'equal))
                             (cons (car entry) (tidy run (cdr entry) :full))
                             entry))
                       (first solutions)))))))

(defun solution-value (solution term)
  "The value of TERM in SOLUTION, or NIL."
  (cdr (assoc term solution :test #'equal)))

;;; Motion over a state with straight contacts: polynomials in TAU

(defstruct (motion (:constructor make-motion (body position velocity acceleration)))
  "How one body moves over a state: expressions in TAU (constant for a fixed body)."
  body position velocity acceleration)

(defun polynomial-motions (run solution derivative-equations)
  "The MOTION of every body over a state whose accelerations are constant: the
derivative relations of the model, with the state's initial values and the solved
accelerations substituted."
  (mapcar
   (lambda (body)
     (let ((name (scenario-body-name body)))
       (if (scenario-body-fixed-p body)
           (make-motion name (body-position run name) '(0 0) '(0 0))
           (let* ((acceleration (list (solution-value solution `(ames.kb:acc ,name :x))
                                      (solution-value solution `(ames.kb:acc ,name :y))))
                  (bindings (list (cons `(ames.kb:pos0 ,name :x) (first (body-position run name)))
                                  (cons `(ames.kb:pos0 ,name :y) (second (body-position run name)))
                                  (cons `(ames.kb:vel0 ,name :x) (first (body-velocity run name)))
                                  (cons `(ames.kb:vel0 ,name :y) (second (body-velocity run name)))
                                  (cons `(ames.kb:acc ,name :x) (first acceleration))
                                  (cons `(ames.kb:acc ,name :y) (second acceleration)))))
             (flet ((integrated (term)
                      (let ((equation (find term derivative-equations
                                            :key #'relation-lhs :test #'equal)))
                        (unless equation
                          (error 'unsolvable-model :datum term
                                                   :detail "The model has no derivative relation for this quantity."))
                        (tidy run (substitute-expressions bindings (relation-rhs equation)) :full))))
               (make-motion name
                            (list (integrated `(ames.kb:pos ,name :x))
                                  (integrated `(ames.kb:pos ,name :y)))
                            (list (integrated `(ames.kb:vel ,name :x))
                                  (integrated `(ames.kb:vel ,name :y)))
                            acceleration))))))
   (scenario-bodies (run-scenario run))))

(defun find-motion (motions body)
  "BODY's MOTION among MOTIONS."
  (find body motions :key #'motion-body))

(defun at-time (expression time)
  "EXPRESSION with TAU replaced by TIME."
  (substitute-expressions (list (cons 'tau time)) expression))

(defun relative-trajectory (motions geometry)
  "The observer's position relative to the obstacle of contact GEOMETRY, over TAU."
  (vec- (motion-position (find-motion motions (ames.geometry:contact-observer geometry)))
        (motion-position (find-motion motions (ames.geometry:contact-obstacle geometry)))))

(defun path-position-over-time (run motions contact)
  "The arc length s(TAU) along the straight active CONTACT."
  (let* ((geometry (contact-geometry run contact))
         (q0 (relative-initial-state run contact))
         (s0 (ames.geometry:contact-parameter geometry q0))
         (tangent (ames.geometry:contact-unit-tangent geometry s0)))
    (tidy run `(+ ,s0 ,(vec-dot (vec- (relative-trajectory motions geometry) q0) tangent)))))

;;; When does a termination condition fire?

(defun decide (run relation)
  "RELATION decided under the scenario's assumptions: :TRUE, :FALSE or :UNKNOWN."
  (ames.maxima:decide (run-bridge run) relation))

(defun holds (run relation)
  "True when RELATION is decided :TRUE under the scenario's assumptions (for the
questions where only :TRUE matters: a numeric counterexample answers them at once)."
  (ames.maxima:holds-p (run-bridge run) relation))

(defun time-derivative (expression)
  "d EXPRESSION / d TAU."
  (ames.geometry:differentiate expression 'tau))

(defun quadratic-coefficients (run g)
  "The coefficients (C0 C1 C2) of G in TAU when G is a polynomial of degree at most 2
in TAU, else NIL."
  (let* ((d1 (tidy run (time-derivative g) :ratsimp))
         (d2 (tidy run (time-derivative d1) :ratsimp)))
    (when (free-of-p 'tau d2)
      (list (tidy run (at-time g 0)) (tidy run (at-time d1 0)) (tidy run `(/ ,d2 2))))))

(defun quadratic-earliest-root (run g)
  "The earliest root TAU > 0 of G, a polynomial of degree at most 2 in TAU, found from
the signs of its coefficients, product and sum of roots and discriminant as decided
under the assumptions (with AMES's stronger DECIDE, where the bridge's own search gave
up): (values ROOT :FOUND), (values :NONE) or (values :UNKNOWN)."
  (destructuring-bind (&optional c0 c1 c2) (quadratic-coefficients run g)
    (flet ((sign-of (x)
             (let ((positive (decide run `(> ,x 0)))
                   (negative (decide run `(< ,x 0))))
               (cond ((eq positive :true) 1)
                     ((eq negative :true) -1)
                     ((and (eq positive :false) (eq negative :false)) 0)
                     ;; seen positive and negative: not identically 0 (saves a costly =)
                     ((and (not (ames.maxima:sign-varies-p (run-bridge run) x))
                           (holds run `(= ,x 0)))
                      0)
                     (t (return-from quadratic-earliest-root (values :unknown)))))))
      (unless c0 (return-from quadratic-earliest-root (values :unknown)))
      (let ((s0 (sign-of c0)) (s1 (sign-of c1)) (s2 (sign-of c2)))
        (cond ((zerop s0)                              ; roots 0 and -c1/c2
               (if (and (/= s2 0) (/= s1 0) (= s1 (- s2)))
                   (values (tidy run `(- (/ ,c1 ,c2))) :found)
                   (values :none)))
              ((zerop s2)                              ; linear
               (if (and (/= s1 0) (= s0 (- s1)))
                   (values (tidy run `(- (/ ,c0 ,c1))) :found)
                   (values :none)))
              (t
               (let* ((discriminant (tidy run `(- (* ,c1 ,c1) (* 4 ,c0 ,c2))))
                      (sd (sign-of discriminant))
                      (root (lambda (sign)
                              (tidy run `(/ (+ (- ,c1) (* ,sign ,s2 (sqrt ,discriminant))) (* 2 ,c2))))))
                 (cond ((minusp sd) (values :none))
                       ((/= s0 s2) (values (funcall root 1) :found))   ; product < 0: one positive root
                       ((= s1 s2) (values :none))                      ; product > 0, sum < 0
                       ((zerop s1) (values :none))
                       (t (values (funcall root -1) :found))))))))))

(defun earliest-root-after (run g after)
  "The earliest root of G (a function of TAU) strictly after AFTER, through the bridge,
then, from the start, by QUADRATIC-EARLIEST-ROOT when the bridge cannot decide.
Returns what AMES.MAXIMA:EARLIEST-ROOT returns, without the candidates of an undecided
answer (UNDECIDED-SIGN-FACT asks for them when it needs them)."
  (multiple-value-bind (root status)
      (ames.maxima:earliest-root (run-bridge run) g 'tau :after after :strictly t :candidates nil)
    (if (eq root :unknown)
        (multiple-value-bind (root2 status2)
            (quadratic-earliest-root
             run (if (eql after 0) g (tidy run (substitute-expressions
                                                (list (cons 'tau `(+ tau ,after))) g))))
          (cond ((eq root2 :none) (values :none nil))
                ((eq status2 :found) (values (tidy run `(+ ,root2 ,after)) :found))
                (t (values root status))))
        (values root status))))

(defun undecided-sign-fact (run g after)
  "The relation whose truth would settle where the polynomial G in TAU first vanishes:
the sign of its first coefficient (from the highest degree down) or of its discriminant
that the assumptions do not decide. When none is found, (:EARLIEST-ROOT-OF (= G 0)
:CANDIDATES CANDIDATES), CANDIDATES the roots after AFTER the bridge could not rule out."
  (let* ((d1 (tidy run (time-derivative g) :ratsimp))
         (d2 (tidy run (time-derivative d1) :ratsimp))
         (c0 (tidy run (at-time g 0)))
         (c1 (tidy run (at-time d1 0)))
         (c2 (tidy run `(/ ,d2 2))))
    (or (and (free-of-p 'tau d2)
             (let ((discriminant (tidy run `(- (* ,c1 ,c1) (* 4 ,c2 ,c0)))))
               (find :unknown
                     (loop for c in (list c2 c1 c0 discriminant)
                           collect `(> ,c 0) collect `(< ,c 0))
                     :key (lambda (fact) (decide run fact)))))
        `(:earliest-root-of (= ,g 0)
          :candidates ,(nth-value 1 (ames.maxima:earliest-root (run-bridge run) g 'tau
                                                               :after after :strictly t))))))

(defun first-time-negative (run g)
  "The earliest time TAU >= 0 from which G(TAU) < 0 (G a polynomial in TAU or a
constant). Returns (values :AT TIME), (values :NEVER) or (values :UNKNOWN FACT) where
FACT is the relation the assumptions do not decide."
  (let* ((g (tidy run g))
         (g0 (tidy run (at-time g 0))))
    (case (decide run `(< ,g0 0))
      (:true (return-from first-time-negative (values :at 0)))
      (:unknown (return-from first-time-negative (values :unknown `(< ,g0 0)))))
    (when (free-of-p 'tau g)
      (return-from first-time-negative (values :never)))
    ;; G starts at zero: it goes negative at once when its first non-zero derivative is
    (when (holds run `(= ,g0 0))
      (let ((derivative g))
        (loop repeat 3
              do (setf derivative (tidy run (time-derivative derivative)))
                 (let ((d0 (tidy run (at-time derivative 0))))
                   (case (decide run `(< ,d0 0))
                     (:true (return-from first-time-negative (values :at 0)))
                     (:unknown (return-from first-time-negative (values :unknown `(< ,d0 0)))))
                   (unless (holds run `(= ,d0 0)) (return))))))
    (let ((root (earliest-root-after run g 0)))
      (cond ((eq root :none) (values :never))
            ((eq root :unknown)
             (values :unknown (undecided-sign-fact run g 0)))
            (t
             (let ((slope (tidy run (at-time (time-derivative g) root))))
               (case (decide run `(< ,slope 0))
                 (:true (values :at (tidy run root :full)))
                 (:false (values :never)) ; rises, or touches zero and turns back
                 (t (values :unknown `(< ,slope 0))))))))))

(defun quantity-over-time (run motions solution term)
  "The value over TAU of the quantity TERM in a termination condition."
  (case (first term)
    (ames.kb:path-position (path-position-over-time run motions (second term)))
    (t (or (solution-value solution term)
           (error 'unsolvable-model :datum term
                                    :detail "A termination condition names a quantity the model does not give.")))))

(defun relation-firing-time (run motions solution relation)
  "When RELATION, a termination relation over the state's quantities, first holds:
(values :AT TIME), (values :NEVER) or (values :UNKNOWN FACT)."
  (flet ((over-time (x) (substitute-expressions
                         (mapcar (lambda (term) (cons term (quantity-over-time run motions solution term)))
                                 (remove-if-not #'quantity-term-p (expression-variables x)))
                         x)))
    (ecase (first relation)
      (or (let ((best nil) (unknown nil))
            (dolist (part (rest relation))
              (multiple-value-bind (status value) (relation-firing-time run motions solution part)
                (case status
                  (:at (if (or (null best) (holds run `(< ,value ,best)))
                           (setf best value)
                           (unless (holds run `(<= ,best ,value))
                             (setf unknown `(< ,value ,best)))))
                  (:unknown (setf unknown value)))))
            (cond (unknown (values :unknown unknown))
                  (best (values :at best))
                  (t (values :never)))))
      ((< <=) (first-time-negative run (over-time `(- ,(relation-lhs relation) ,(relation-rhs relation)))))
      ((> >=) (first-time-negative run (over-time `(- ,(relation-rhs relation) ,(relation-lhs relation))))))))

(defun extent-margin (relation)
  "For an extent RELATION (>= X Y) or (<= X Y), the expression that must be >= 0."
  (ecase (first relation)
    ((>= >) `(- ,(relation-lhs relation) ,(relation-rhs relation)))
    ((<= <) `(- ,(relation-rhs relation) ,(relation-lhs relation)))))

(defun stays-negative-p (run h)
  "True when H, a polynomial of degree at most 2 in TAU, is proven negative for every
TAU > 0: H(0) <= 0, H'(0) <= 0 and H'' <= 0, not all zero. A cheap, sound test that
rules out a meeting without solving for it; NIL when it does not apply, at once when H
is seen to be positive at some TAU > 0 (then no proof exists)."
  (when (ames.maxima:refuted-p (run-bridge run) `(< ,h 0) :assuming '((> tau 0)))
    (return-from stays-negative-p nil))
  (let* ((h (tidy run h :ratsimp))
         (d1 (tidy run (time-derivative h) :ratsimp))
         (d2 (tidy run (time-derivative d1) :ratsimp))
         (d3 (tidy run (time-derivative d2) :ratsimp)))
    (and (eql d3 0)
         (let ((h0 (at-time h 0)) (d10 (at-time d1 0)))
           (and (holds run `(<= ,h0 0))
                (holds run `(<= ,d10 0))
                (holds run `(<= ,d2 0))
                (or (holds run `(< ,h0 0))
                    (holds run `(< ,d10 0))
                    (holds run `(< ,d2 0))))))))

(defun contact-meeting-time (run motions contact)
  "When the relative trajectory first meets the potential CONTACT from its exterior:
(values :AT TIME RATE), (values :NEVER) or (values :UNKNOWN FACT). RATE is the
approach rate of the gap at that time (negative: a collision; zero: a grazing contact)."
  (let* ((geometry (contact-geometry run contact))
         (meeting (ames.geometry:contact-meeting geometry (relative-trajectory motions geometry)))
         (gap (tidy run (ames.geometry:meeting-gap meeting)))
         (after 0))
    ;; a condition that can never hold again rules the meeting out at once
    (when (some (lambda (h) (stays-negative-p run h))
                (cons `(- ,gap) ; the gap must close ...
                      (mapcar #'extent-margin (ames.geometry:meeting-extent meeting)))) ; ... within the ends
      (return-from contact-meeting-time (values :never)))
    ;; moving along the contact's own line or circle: it is met only by entering its extent
    (when (eql gap 0)
      (return-from contact-meeting-time
        (if (some (lambda (r) (stays-negative-p run (extent-margin r)))
                  (ames.geometry:meeting-extent meeting))
            (values :never)
            (values :unknown `(:moves-along-the-locus-of ,contact)))))
    ;; touching at the start and moving in: a collision at once
    (let ((rate0 (tidy run (at-time (ames.geometry:meeting-rate meeting) 0))))
      (when (and (holds run `(= ,(tidy run (at-time gap 0)) 0))
                 (holds run `(< ,rate0 0))
                 (every (lambda (r) (holds run (at-time r 0)))
                        (ames.geometry:meeting-extent meeting)))
        (return-from contact-meeting-time (values :at 0 rate0))))
    ;; a gap already closed at the start is not a meeting: look strictly after the start,
    ;; dividing out TAU so that the bridge sees the lowest degree
    (loop repeat 3
          while (and (not (free-of-p 'tau gap))
                     (holds run `(= ,(tidy run (at-time gap 0)) 0)))
          do (setf gap (tidy run `(/ ,gap tau))))
    (block search
     (loop repeat 4
          do (let ((root (earliest-root-after run gap after)))
               (cond ((eq root :none) (return-from search (values :never)))
                     ((eq root :unknown)
                      (return-from search (values :unknown (undecided-sign-fact run gap after))))
                     (t
                      (let* ((root (tidy run root :full))
                             (rate (tidy run (at-time (ames.geometry:meeting-rate meeting) root)))
                             (extent (mapcar (lambda (r) (at-time r root))
                                             (ames.geometry:meeting-extent meeting)))
                             (checks (cons `(<= ,rate 0) extent))
                             (answers (mapcar (lambda (r) (decide run r)) checks)))
                        (cond ((every (lambda (a) (eq a :true)) answers)
                               (return-from search (values :at root rate)))
                              ((member :unknown answers)
                               (return-from search (values :unknown (nth (position :unknown answers) checks))))
                              (t (setf after root))))))))
     (values :unknown `(:meeting ,contact)))))

;;; The candidates that could end a state, and the earliest of them

(defstruct (candidate (:constructor make-candidate (event time change)))
  "A termination condition that fires at TIME (an expression in the parameters): the
EVENT it is for the report and the CHANGE it stands for in the model."
  event time change)

(defun contact-bodies (run contact)
  "The observer and obstacle names of CONTACT, as a list."
  (let ((geometry (contact-geometry run contact)))
    (list (ames.geometry:contact-observer geometry) (ames.geometry:contact-obstacle geometry))))

(defun mentions-p (head relation)
  "True when RELATION contains a quantity term headed by HEAD."
  (some (lambda (v) (and (consp v) (eq (first v) head))) (expression-variables relation)))

(defun change-event (run change)
  "The event a model CHANGE would be, for reports: a contact that would appear or end."
  (let* ((key (second change))
         (contact (and (consp key) (eq (first key) 'ames.kb::contact) (second key))))
    (if contact
        (list* (if (eq (first change) :activate) :contact :contact-ends)
               (contact-bodies run contact))
        change)))

(defun termination-candidates (run motions solution)
  "Every termination condition of the current model that fires, as CANDIDATEs, and the
facts that could not be decided for the others (a list of relations)."
  (let ((candidates '()) (unknown '()))
    (dolist (condition (ames.engine:model-termination-conditions (run-model run)))
      (let* ((change (ames.engine:termination-condition-change condition))
             (relation (ames.engine:termination-condition-relation condition))
             (key (second change))
             (contact (and (consp key) (eq (first key) 'ames.kb::contact) (second key))))
        (multiple-value-bind (status time rate)
            (if (eq (ames.engine:termination-condition-kind condition) :activation)
                (contact-meeting-time run motions contact)
                (relation-firing-time run motions solution relation))
          (case status
            (:at
             (let ((event
                     (cond ((eq (ames.engine:termination-condition-kind condition) :activation)
                            (list* (if (holds run `(< ,rate 0)) :collision :contact)
                                   (contact-bodies run contact)))
                           ((mentions-p 'ames.kb:normal-force relation)
                            (list* :lift-off (contact-bodies run contact)))
                           (contact
                            (append (list :leaves) (contact-bodies run contact) (list :endpoint)))
                           (t (list :mode-change key)))))
               (push (make-candidate event time change) candidates)))
            (:unknown (push (list time (change-event run change)) unknown))))))
    (values (nreverse candidates) (nreverse unknown))))

(defun earliest-candidates (run candidates unknown)
  "The candidates that fire first, all at one time, proven earliest. Signals
AMBIGUOUS-TRANSITION (restart STOP-SIMULATION) when that cannot be decided."
  (flet ((ambiguous (fact)
           (setf fact (core-fact run fact))
           (error 'ambiguous-transition
                  :datum fact :missing-fact fact
                  :candidates (append (mapcar (lambda (c) (list (candidate-event c) (candidate-time c)))
                                              candidates)
                                      (mapcar (lambda (u) (list (second u) :undecided (first u)))
                                              unknown))
                  :detail "Which event ends the state is not decided by the assumptions.")))
    (when unknown (ambiguous (first (first unknown))))
    (when candidates
      (let ((first (find-if (lambda (c)
                              (every (lambda (o)
                                       (or (eq o c)
                                           (holds run `(<= ,(candidate-time c) ,(candidate-time o)))))
                                     candidates))
                            candidates)))
        (unless first
          (let ((pair (loop for c in candidates
                            thereis (loop for o in candidates
                                          unless (or (eq o c)
                                                     (member (decide run `(<= ,(candidate-time c) ,(candidate-time o)))
                                                             '(:true :false)))
                                            return (list c o)))))
            (ambiguous (if pair
                           `(<= ,(candidate-time (first pair)) ,(candidate-time (second pair)))
                           (candidate-time (first candidates))))))
        (remove-if-not (lambda (o)
                         (or (eq o first)
                             (holds run `(= ,(candidate-time o) ,(candidate-time first)))
                             (ames.maxima:equivalent-p (run-bridge run) (candidate-time o)
                                                       (candidate-time first))))
                       candidates)))))

;;; One straight state

(defun reported-forces (run solution contacts)
  "The forces of the state for the report."
  (let ((scenario (run-scenario run)))
    (append
     (mapcar (lambda (contact)
               (list* :normal (append (contact-bodies run contact)
                                      (list (solution-value solution `(ames.kb:normal-force ,contact))))))
             contacts)
     (when (scenario-gravity scenario)
       (loop for body in (scenario-moving-bodies scenario)
             for name = (scenario-body-name body)
             collect (list :gravity name
                           (list 0 (tidy run `(- (* ,(scenario-body-mass body)
                                                     ,(scenario-gravity scenario))))))))
     (mapcar (lambda (force)
               (list :external (scenario-force-name force) (scenario-force-body force)
                     (scenario-force-value force)))
             (scenario-forces scenario)))))

(defun state-contact-descriptions (run contacts)
  "Each active contact as (BODY1 BODY2 :FEATURE F :OBSERVER-FEATURE G)."
  (mapcar (lambda (contact)
            (let ((geometry (contact-geometry run contact)))
              (append (contact-bodies run contact)
                      (list :feature (ames.geometry:contact-obstacle-feature geometry)
                            :observer-feature (ames.geometry:contact-observer-feature geometry)))))
          contacts))

(defun end-event-of (events)
  "The one event a state reports as its end: a collision first, else the first."
  (or (find :collision events :key #'first) (first events)))

(defun analyse-straight-state (run index equations derivative-equations contacts)
  "Solve and end the state INDEX whose contacts are all straight. Returns the
QUALITATIVE-STATE and the fired CANDIDATEs (NIL when the state lasts forever). When
which event ends it is ambiguous, the AMBIGUOUS-TRANSITION carries the state as far as
it is known (its model and motion, duration :UNDECIDED)."
  (let* ((solution (solve-instantaneous-model run equations (used-quantity-terms run contacts)))
         (motions (polynomial-motions run solution derivative-equations))
         (state (make-instance
                 'qualitative-state
                 :index index :start (run-time run)
                 :duration :undecided
                 :contacts (state-contact-descriptions run contacts)
                 :accelerations (mapcar (lambda (m) (list (motion-body m) (motion-acceleration m)))
                                        motions)
                 :forces (reported-forces run solution contacts)
                 :positions (mapcar (lambda (m) (list (motion-body m) (motion-position m))) motions)
                 :velocities (mapcar (lambda (m) (list (motion-body m) (motion-velocity m))) motions)
                 :end-event :undecided)))
    (multiple-value-bind (candidates unknown) (termination-candidates run motions solution)
      (let* ((until (scenario-until (run-scenario run)))
             (fired (handler-bind ((ambiguous-transition
                                     (lambda (condition)
                                       (setf (ambiguous-transition-state condition) state))))
                      (earliest-candidates
                       run
                       (if (and until (not (consp (run-time run))) (not (keywordp (run-time run))))
                           ;; the scenario's (simulate :until T) ends the run at global time T
                           (cons (make-candidate (list :time-limit until)
                                                 (tidy run `(- ,until ,(run-time run)))
                                                 nil)
                                 candidates)
                           candidates)
                       unknown)))
             (end (and fired (candidate-time (first fired)))))
        (setf (state-duration state) (or end :forever)
              (state-end-event state) (if fired (end-event-of (mapcar #'candidate-event fired)) :none)
              (state-notes state) (when (rest fired)
                                    (list :events (mapcar #'candidate-event fired))))
        (when fired
          (setf (state-final-positions state)
                (mapcar (lambda (m) (list (motion-body m)
                                          (mapcar (lambda (x) (tidy run (at-time x end) :full))
                                                  (motion-position m))))
                        motions)
                (state-final-velocities state)
                (mapcar (lambda (m) (list (motion-body m)
                                          (mapcar (lambda (x) (tidy run (at-time x end) :full))
                                                  (motion-velocity m))))
                        motions)))
        (values state fired)))))

;;; The state loop

(defun curved-contact-p (run contact)
  "True when CONTACT's locus is an arc or a circle."
  (member (ames.geometry:contact-kind (contact-geometry run contact)) '(:arc :circle)))

(defun analyse-state (run index)
  "Build, solve and end the current state. Returns the QUALITATIVE-STATE and the fired
CANDIDATEs."
  (let* ((model (run-model run))
         (all (ames.engine:model-equations model))
         (derivative (remove-if-not (lambda (e) (derivative-equation-p model e)) all))
         (instantaneous (set-difference all derivative :test #'equal))
         (contacts (active-contacts run)))
    (if (some (lambda (c) (curved-contact-p run c)) contacts)
        (analyse-curved-state run index instantaneous contacts)
        (analyse-straight-state run index instantaneous derivative contacts))))

(defun initial-motion-state (scenario)
  "The alists body -> position and body -> velocity at the start of SCENARIO."
  (values (mapcar (lambda (body) (list (scenario-body-name body) (scenario-body-position body)))
                  (scenario-bodies scenario))
          (mapcar (lambda (body) (list (scenario-body-name body)
                                       (or (scenario-body-velocity body) '(0 0))))
                  (scenario-bodies scenario))))

(defun time-after (run start state)
  "The global time at which STATE, started at START, ends: an expression, or
(:END-OF-STATE N [:PLUS EXPR]) when a state's duration has no closed form."
  (let ((duration (state-duration state)))
    (cond ((and (consp start) (keywordp (first start)))
           (if (and (not (keywordp duration)) (not (and (consp duration) (keywordp (first duration)))))
               (list :end-of-state (second start)
                     :plus (tidy run `(+ ,(or (getf (cddr start) :plus) 0) ,duration)))
               (list :end-of-state (state-index state))))
          ((and (consp duration) (keywordp (first duration)))
           (list :end-of-state (state-index state)))
          (t (tidy run `(+ ,start ,duration))))))

(defun enter-next-state (run state fired &key (check-incremental t))
  "Carry the final positions and velocities of STATE over, and apply the changes the
FIRED candidates stand for to the model, incrementally (checked against a rebuild from
scratch when CHECK-INCREMENTAL)."
  (setf (run-positions run) (state-final-positions state)
        (run-velocities run) (state-final-velocities state)
        (run-time run) (time-after run (run-time run) state))
  (let ((changes (remove nil (remove-duplicates (mapcar #'candidate-change fired) :test #'equal))))
    (multiple-value-bind (model report)
        (ames.engine:apply-transition (run-model run) changes :decider (state-decider run))
      (declare (ignore model))
      (push (ames.engine:transition-report-rederived-count report) (run-rederived run)))
    (when check-incremental
      (ames.engine:check-incremental (run-model run)))))

(defvar *bridge* nil
  "The current Maxima bridge of the REPL and the command line, made on first use.")

(defun current-bridge ()
  "The current Maxima bridge, made on first use."
  (or *bridge* (setf *bridge* (ames.maxima:make-bridge))))

(defparameter *default-state-limit* 12
  "How many states a scenario runs when its (simulate ...) clause sets no :states.")

(defun simulate (scenario &key (bridge (current-bridge)) parameter-values
                            (check-incremental t))
  "Simulate SCENARIO (a SCENARIO object, or a scenario form as in a file) and return its
SIMULATION-HISTORY. BRIDGE is the Maxima bridge (by default the current one).
PARAMETER-VALUES, an alist (PARAMETER-NAME . NUMBER) matched by name, adds numeric
values to the report. CHECK-INCREMENTAL compares every incrementally updated model with
a rebuild from scratch.
Signals SCENARIO-ERROR for a defective scenario, AMBIGUOUS-TRANSITION (restart
STOP-SIMULATION, which returns the history so far) when the assumptions do not decide
which event ends a state, UNSOLVABLE-MODEL and UNSUPPORTED-SITUATION, and the Maxima
bridge's conditions."
  (let ((scenario (if (scenario-p scenario) scenario (parse-scenario scenario))))
    (handler-bind ((arithmetic-error
                     ;; numbers beyond floating point (a float times 1e60) in the geometry's
                     ;; or the simulator's own arithmetic
                     (lambda (condition)
                       (error 'simulation-error
                              :datum (scenario-name scenario)
                              :detail (format nil "Arithmetic on the scenario's numbers failed (~A); use exact numbers or smaller magnitudes."
                                              (type-of condition))))))
      (simulate-checked scenario bridge parameter-values check-incremental))))

(defun simulate-checked (scenario bridge parameter-values check-incremental)
  "SIMULATE's work on the validated SCENARIO."
  (progn
    (check-scenario scenario bridge)
    (ames.maxima:with-assumptions (bridge (scenario-assumption-relations scenario))
      (multiple-value-bind (positions velocities) (initial-motion-state scenario)
        (let* ((shapes (body-shapes scenario bridge))
               (run (make-instance 'run :scenario scenario :bridge bridge :shapes shapes
                                        :contacts (all-simple-contacts scenario shapes bridge)
                                        :positions positions :velocities velocities))
               (situation (ames.engine:make-situation (situation-entities run) :data run))
               (history (make-instance 'simulation-history
                                       :scenario scenario
                                       :parameter-values (resolve-parameter-values
                                                          scenario parameter-values)))
               (limit (or (scenario-states scenario) *default-state-limit*)))
          (setf (run-model run)
                (ames.engine:build-model (ames.engine:make-engine (ames.kb:mechanics-knowledge-base))
                                         situation :decider (state-decider run)))
          (restart-case
              (run-states run history 0 limit check-incremental)
            (stop-simulation (&optional condition)
              :report "Stop the simulation here and return the states so far."
              (setf (history-outcome history) (if (typep condition 'ambiguous-transition)
                                                  :ambiguous
                                                  :stopped))
              (when (and (typep condition 'ambiguous-transition)
                         (ambiguous-transition-state condition))
                (setf (history-states history)
                      (append (history-states history)
                              (list (ambiguous-transition-state condition)))))
              (setf (getf (history-notes history) :stopped-by) condition)))
          (add-numeric-values history bridge)
          (setf (history-rederived history) (reverse (run-rederived run)))
          history)))))

(defun factors-of (expression)
  "The factors of a product or quotient EXPRESSION, each as (FACTOR . POWER-SIGN), POWER-SIGN
-1 for a denominator."
  (cond ((and (consp expression) (eq (first expression) '*))
         (mapcan #'factors-of (rest expression)))
        ((and (consp expression) (eq (first expression) '/) (rest expression))
         (append (factors-of (second expression))
                 (mapcar (lambda (f) (cons (car f) (- (cdr f))))
                         (mapcan #'factors-of (cddr expression)))))
        ((and (consp expression) (eq (first expression) '-) (null (cddr expression)))
         (cons (cons -1 1) (factors-of (second expression))))
        (t (list (cons expression 1)))))

(defun core-fact (run fact)
  "FACT, a relation (> X 0), (< X 0) ... with X factored and every factor whose sign the
assumptions decide divided out: (> (* (- l1 l2) (- f k)) 0) with l1 > l2 becomes
(> (- f k) 0). FACT itself when nothing can be divided out."
  (if (not (and (consp fact) (member (first fact) '(< > <= >=))))
      fact
      (let* ((x (ames.maxima:simplify (run-bridge run)
                                      `(- ,(relation-lhs fact) ,(relation-rhs fact))
                                      :strategy :full))
             (sign 1) (kept '()))
        (dolist (factor (factors-of x))
          (let ((f (car factor)))
            (cond ((and (realp f) (plusp f)))
                  ((and (realp f) (minusp f)) (setf sign (- sign)))
                  ((holds run `(> ,f 0)))
                  ((holds run `(< ,f 0)) (setf sign (- sign)))
                  (t (push f kept)))))
        (if (or (null kept) (rest kept))
            fact
            (let ((operator (if (= sign 1)
                                (first fact)
                                (ecase (first fact) (> '<) (< '>) (>= '<=) (<= '>=)))))
              (list operator (first kept) 0))))))

(defun fact-from-values (run fact values)
  "FACT, or its negation, as the parameter VALUES decide it numerically; NIL when they
do not (no values, a value missing, or the two sides equal)."
  (when (and values (consp fact) (member (first fact) '(< > <= >=)))
    (let ((difference (numeric-or-nil (run-bridge run)
                                      `(- ,(relation-lhs fact) ,(relation-rhs fact)) values)))
      (when (and difference (/= difference 0))
        (let ((holds (ecase (first fact)
                       ((> >=) (plusp difference))
                       ((< <=) (minusp difference)))))
          (if holds
              fact
              (list (ecase (first fact) (> '<=) (>= '<) (< '>=) (<= '>))
                    (relation-lhs fact) (relation-rhs fact))))))))

(defun run-states (run history index limit check-incremental)
  "Analyse the states of RUN from INDEX on, appending them to HISTORY, until nothing
more changes, a collision, or LIMIT states. When the assumptions leave the end of a
state ambiguous but the history's parameter values decide the missing fact, that fact
is assumed (and noted in the history) for the rest of the run."
  (loop for index from index
        do (when (>= index limit)
             (setf (history-outcome history) :state-limit)
             (return))
           (multiple-value-bind (state fired)
               (handler-case (analyse-state run index)
                 (ambiguous-transition (condition)
                   (let ((fact (fact-from-values run (core-fact run (ambiguous-transition-missing-fact condition))
                                                 (history-parameter-values history))))
                     (when (or (null fact)
                               ;; a fact already assumed that did not settle it will not now
                               (member fact (getf (history-notes history) :assumed)
                                       :key (lambda (entry) (getf entry :fact)) :test #'equal)
                               (> (length (getf (history-notes history) :assumed)) 24))
                       (error condition))
                     (push (list :state index :fact fact) (getf (history-notes history) :assumed))
                     (return-from run-states
                       (ames.maxima:with-assumptions ((run-bridge run) (list fact))
                         (run-states run history index limit check-incremental))))))
             (setf (history-states history) (append (history-states history) (list state)))
             (cond ((null fired)
                    (setf (history-outcome history) :complete)
                    (return))
                   ((find :collision fired :key (lambda (c) (first (candidate-event c))))
                    (setf (history-outcome history) :collision)
                    (return))
                   ((find :time-limit fired :key (lambda (c) (first (candidate-event c))))
                    (setf (history-outcome history) :time-limit)
                    (return))
                   (t (enter-next-state run state fired :check-incremental check-incremental))))))

(defun stop-simulation (&optional condition)
  "Invoke the STOP-SIMULATION restart: end the simulation and return the history so far."
  (invoke-restart 'stop-simulation condition))

;;; Numbers beside the formulas

(defun resolve-parameter-values (scenario settings)
  "The alist (PARAMETER . NUMBER) for SETTINGS, an alist whose keys are parameter
symbols or names (strings), matched by name. Signals SCENARIO-ERROR naming a setting
that is not a parameter of SCENARIO."
  (mapcar (lambda (setting)
            (let ((parameter (find (string (car setting)) (scenario-parameters scenario)
                                   :key (lambda (p) (symbol-name (scenario-parameter-name p)))
                                   :test #'string-equal)))
              (unless parameter
                (error 'undeclared-symbol-error
                       :scenario (scenario-name scenario) :datum (car setting)
                       :detail (format nil "~A is not a parameter of this scenario" (car setting))))
              (cons (scenario-parameter-name parameter) (cdr setting))))
          settings))

(defun numeric-or-nil (bridge expression values)
  "The number EXPRESSION takes under VALUES, or NIL when it has none (a symbol left over,
or not a real)."
  (and (not (keywordp expression))
       (not (and (consp expression) (keywordp (first expression))))
       (handler-case (ames.maxima:numeric-value bridge expression values)
         (ames.maxima:numeric-evaluation-failed () nil))))

(defun add-numeric-values (history bridge)
  "When HISTORY has parameter values, record in each state's notes (:NUMERIC plist) the
numeric start, duration and final positions and velocities."
  (let ((values (history-parameter-values history))
        (clock 0d0))
    (when values
      (dolist (state (history-states history))
        (flet ((number-of (x) (numeric-or-nil bridge x values))
               (numbers-of (alist) (mapcar (lambda (entry)
                                             (list (first entry)
                                                   (mapcar (lambda (x) (numeric-or-nil bridge x values))
                                                           (second entry))))
                                           alist)))
          (let ((duration (state-duration state))
                (path (getf (state-notes state) :path-coordinates)))
            (when (and (consp duration) (eq (first duration) :no-closed-form) path)
              (let ((time (numeric-travel-time bridge
                                               (relation-rhs (getf path :energy-integral))
                                               (getf (rest duration) :from-arc-length)
                                               (getf (rest duration) :to-arc-length)
                                               values)))
                (when time (setf (getf (state-notes state) :numeric-duration) time)))))
          (setf (getf (state-notes state) :numeric)
                (list :start clock
                      :duration (let ((d (state-duration state)))
                                  (if (or (keywordp d) (and (consp d) (keywordp (first d))))
                                      (or (getf (state-notes state) :numeric-duration) d)
                                      (number-of d)))
                      :final-positions (numbers-of (state-final-positions state))
                      :final-velocities (numbers-of (state-final-velocities state))))
          (let ((duration (getf (getf (state-notes state) :numeric) :duration)))
            (setf clock (and clock (realp duration) (+ clock duration)))))))))

;;; A state on a curved contact
;;;
;;; On an arc the acceleration changes with the position, so the motion is not polynomial in
;;; TAU. The model is solved at a general arc length s and speed w (the path coordinates of
;;; section 2.5.7), which gives s'' = F(s) for the path-coordinate ODE and the normal force
;;; N(s, w). The bridge integrates the ODE: in closed form where Maxima can, otherwise as the
;;; energy integral w^2 = E(s), and N(s) follows by putting E(s) for w^2 (thesis 2.6.3).
;;; The state ends where N(s) reaches zero (lift-off) or at an end of the arc, whichever the
;;; observer reaches first in its direction of motion. The time of that end has no closed
;;; form in general: the state says so, and gives a number when parameter values are known.
;;; Supported: one free body on one curved contact with a fixed obstacle, and no other
;;; contact the body could meet (others are reported as UNSUPPORTED-SITUATION).

(defconstant +arc-length+ 'arc-length
  "The variable standing for the arc length s along a curved contact.")

(defconstant +arc-speed+ 'arc-speed
  "The variable standing for the speed ds/dtau along a curved contact.")

(defun check-curved-state-supported (run contacts)
  "Signal UNSUPPORTED-SITUATION unless the state is one free body on one curved contact
with a fixed obstacle and nothing else it could meet. Returns that contact."
  (flet ((unsupported (detail)
           (error 'unsupported-situation :datum (state-contact-descriptions run contacts)
                                         :detail detail)))
    (let* ((curved (remove-if-not (lambda (c) (curved-contact-p run c)) contacts))
           (contact (first curved))
           (free (scenario-moving-bodies (run-scenario run))))
      (unless (and (= (length curved) 1) (= (length contacts) 1))
        (unsupported "A curved contact together with other contacts is not supported yet."))
      (destructuring-bind (observer obstacle) (contact-bodies run contact)
        (unless (body-fixed-p run obstacle)
          (unsupported "A curved contact against a moving body is not supported yet."))
        (unless (and (= (length free) 1) (eq (scenario-body-name (first free)) observer))
          (unsupported "A curved contact while other bodies move is not supported yet."))
        (when (some (lambda (entry)
                      (and (not (eq (car entry) contact))
                           (member observer (contact-bodies run (car entry)))
                           (not (eq (ames.geometry:contact-obstacle (cdr entry)) obstacle))))
                    (run-contacts run))
          (unsupported "A body on a curved contact that could meet another body is not supported yet.")))
      contact)))

(defun speed-free (run expression energy)
  "EXPRESSION with the arc speed's square replaced by the energy integral ENERGY (the
speed enters the model only through the centripetal term)."
  (tidy run (substitute-expressions (list (cons +arc-speed+ `(sqrt ,energy))) expression)))

(defun gauss-legendre-nodes ()
  "Sixteen-point Gauss-Legendre nodes and weights on [0, 1]."
  (let ((x '(0.0950125098376374d0 0.2816035507792589d0 0.4580167776572274d0 0.6178762444026438d0
             0.7554044083550030d0 0.8656312023878318d0 0.9445750230732326d0 0.9894009349916499d0))
        (w '(0.1894506104550685d0 0.1826034150449236d0 0.1691565193950025d0 0.1495959888165767d0
             0.1246289712555339d0 0.0951585116824928d0 0.0622535239386479d0 0.0271524594117541d0)))
    (loop for xi in x for wi in w
          append (list (cons (/ (- 1 xi) 2) (/ wi 2)) (cons (/ (+ 1 xi) 2) (/ wi 2))))))

(defun numeric-travel-time (bridge energy s0 s1 values)
  "The time to travel from arc length S0 to S1 when the speed squared is ENERGY (in
+ARC-LENGTH+), with parameter VALUES: the integral of ds / sqrt(ENERGY), computed with
s = s0 + (s1 - s0) u^2 so that a start at rest is no singularity. NIL when a value is not
a real number."
  (let* ((start (numeric-or-nil bridge s0 values))
         (end (numeric-or-nil bridge s1 values)))
    (when (and start end)
      (let ((span (- end start)) (total 0d0))
        (loop for (u . weight) in (gauss-legendre-nodes)
              for s = (+ start (* span u u))
              for e = (numeric-or-nil bridge energy (acons +arc-length+ s values))
              do (unless (and e (plusp e)) (return-from numeric-travel-time nil))
                 (incf total (* weight (/ (* 2 (abs span) u) (sqrt e)))))
        total))))

(defun analyse-curved-state (run index equations contacts)
  "Solve and end the state INDEX in which one free body slides on a curved contact (see
the section header). Returns the QUALITATIVE-STATE and the fired CANDIDATEs."
  (let* ((contact (check-curved-state-supported run contacts))
         (geometry (contact-geometry run contact))
         (s-term `(ames.kb:path-position ,contact))
         (w-term `(ames.kb:path-speed ,contact))
         (symbols (list (cons s-term +arc-length+) (cons w-term +arc-speed+)))
         (solution (mapcar (lambda (entry)
                             (cons (car entry) (substitute-expressions symbols (cdr entry))))
                           (solve-instantaneous-model run equations
                                                      (used-quantity-terms run contacts))))
         (tangential (solution-value solution `(ames.kb:path-acc ,contact :tangential)))
         (normal (solution-value solution `(ames.kb:normal-force ,contact))))
    (destructuring-bind (observer obstacle) (contact-bodies run contact)
      (multiple-value-bind (q0 v0) (relative-initial-state run contact)
        (let* ((s0 (ames.geometry:contact-parameter geometry q0))
               (w0 (tidy run (vec-dot v0 (ames.geometry:contact-unit-tangent geometry s0))))
               (ode (ames.maxima:solve-autonomous-ode (run-bridge run) tangential +arc-length+
                                                      :velocity +arc-speed+
                                                      :initial-position s0 :initial-velocity w0))
               (energy (tidy run (ames.maxima:ode-solution-speed-squared ode)))
               (normal-along (speed-free run normal energy))
               (direction (cond ((holds run `(> ,w0 0)) 1)
                                ((holds run `(< ,w0 0)) -1)
                                ((holds run `(> ,(at-arc tangential s0) 0)) 1)
                                ((holds run `(< ,(at-arc tangential s0) 0)) -1)
                                (t (error 'ambiguous-transition
                                          :datum w0 :missing-fact `(> ,w0 0) :candidates '()
                                          :detail "The direction of motion on the curve is not decided."))))
               (candidates (curved-candidates run contact normal-along s0 direction)))
          (let* ((first (and candidates (first (sort-by-arc run candidates s0 direction))))
                 (s1 (and first (candidate-time first)))
                 (zero-duration (and s1 (holds run `(= ,s1 ,s0))))
                 (end-point (and s1 (vec+ (body-position run obstacle)
                                          (ames.geometry:contact-point geometry s1))))
                 (end-speed (and s1 (tidy run `(* ,direction (sqrt ,(at-arc energy s1))))))
                 (end-velocity (and s1 (mapcar (lambda (x) (tidy run `(* ,end-speed ,x)))
                                               (ames.geometry:contact-unit-tangent geometry s1))))
                 (position-on-path (vec+ (body-position run obstacle)
                                         (ames.geometry:contact-point geometry +arc-length+)))
                 (state (make-instance
                         'qualitative-state
                         :index index :start (run-time run)
                         :duration (cond ((null s1) :forever)
                                         (zero-duration 0)
                                         (t `(:no-closed-form :from-arc-length ,s0 :to-arc-length ,s1)))
                         :contacts (state-contact-descriptions run contacts)
                         :accelerations
                         (mapcar (lambda (body)
                                   (let ((name (scenario-body-name body)))
                                     (list name
                                           (if (eq name observer)
                                               (list (speed-free run (solution-value solution `(ames.kb:acc ,name :x)) energy)
                                                     (speed-free run (solution-value solution `(ames.kb:acc ,name :y)) energy))
                                               '(0 0)))))
                                 (scenario-bodies (run-scenario run)))
                         :forces (cons (list :normal observer obstacle normal-along)
                                       (rest (reported-forces run solution contacts)))
                         :positions (mapcar (lambda (body)
                                              (let ((name (scenario-body-name body)))
                                                (list name (if (eq name observer)
                                                               (list :on-path (mapcar (lambda (x) (tidy run x)) position-on-path)
                                                                     :arc-length +arc-length+)
                                                               (body-position run name)))))
                                            (scenario-bodies (run-scenario run)))
                         :end-event (if first (candidate-event first) :none)
                         :notes (list :path-coordinates
                                      (list :arc-length-from s0
                                            :tangential-acceleration (tidy run tangential)
                                            :energy-integral `(= (expt ,+arc-speed+ 2) ,energy)
                                            :normal-force normal-along
                                            :ode (ames.maxima:ode-solution-kind ode))))))
            (when first
              (setf (state-final-positions state)
                    (mapcar (lambda (body)
                              (let ((name (scenario-body-name body)))
                                (list name (if (eq name observer)
                                               (mapcar (lambda (x) (tidy run x)) end-point)
                                               (body-position run name)))))
                            (scenario-bodies (run-scenario run)))
                    (state-final-velocities state)
                    (mapcar (lambda (body)
                              (let ((name (scenario-body-name body)))
                                (list name (if (eq name observer) end-velocity '(0 0)))))
                            (scenario-bodies (run-scenario run))))
              (setf (getf (state-notes state) :lift-off-arc-length) s1))
            (values state (and first (list first)))))))))

(defun at-arc (expression s)
  "EXPRESSION at arc length S."
  (substitute-expressions (list (cons +arc-length+ s)) expression))

(defun curved-candidates (run contact normal-along s0 direction)
  "The ways the curved state on CONTACT can end, as CANDIDATEs whose TIME slot holds the
arc length where they happen: lift-off where the normal force NORMAL-ALONG (a function of
the arc length) reaches zero, and the arc's ends."
  (let* ((geometry (contact-geometry run contact))
         (bodies (contact-bodies run contact))
         (change (list :deactivate (list 'ames.kb::contact contact)))
         (candidates '()))
    (flet ((ahead-p (s)
             ;; on a circle, an angle difference of less than a quarter turn has the sign of
             ;; its sine, which Maxima can expand where inverse trigonometric terms defeat sign()
             (let ((answer (decide run `(> (* ,direction (- ,s ,s0)) 0)))
                   (radius (ames.geometry:contact-radius geometry)))
               (if (and (eq answer :unknown) radius)
                   (let ((turn (tidy run `(/ (- ,s ,s0) ,radius) :ratsimp)))
                     (if (holds run `(> ,(tidy run `(cos ,turn) :trigexpand) 0))
                         (decide run `(> (* ,direction ,(tidy run `(sin ,turn) :trigexpand)) 0))
                         :unknown))
                   answer))))
      (case (decide run `(< ,(at-arc normal-along s0) 0))
        (:true (return-from curved-candidates
                 (list (make-candidate (list* :lift-off bodies) s0 change))))
        (:unknown (error 'ambiguous-transition
                         :datum normal-along :missing-fact `(> ,(at-arc normal-along s0) 0)
                         :candidates '() :detail "The sign of the normal force is not decided.")))
      (dolist (root (ames.maxima:solve-equations (run-bridge run) (list `(= ,normal-along 0))
                                                 (list +arc-length+)))
        (let ((s (tidy run (cdr (first root)))))
          (case (ahead-p s)
            (:true (push (make-candidate (list* :lift-off bodies) s change) candidates))
            (:unknown (error 'ambiguous-transition
                             :datum s :missing-fact `(> (* ,direction (- ,s ,s0)) 0)
                             :candidates '() :detail "Where the normal force vanishes is not decided.")))))
      (when (eq (ames.geometry:contact-kind geometry) :arc)
        (dolist (end (list 0 (ames.geometry:contact-length geometry)))
          (when (eq (ahead-p end) :true)
            (push (make-candidate (append (list :leaves) bodies (list :endpoint)) end change)
                  candidates))))
      candidates)))

(defun sort-by-arc (run candidates s0 direction)
  "CANDIDATES sorted by how far ahead of S0 they are in DIRECTION; signals
AMBIGUOUS-TRANSITION when the order is not decided."
  (sort (copy-list candidates)
        (lambda (a b)
          (let ((answer (decide run `(< (* ,direction (- ,(candidate-time a) ,s0))
                                        (* ,direction (- ,(candidate-time b) ,s0))))))
            (when (eq answer :unknown)
              (error 'ambiguous-transition
                     :datum (list a b) :missing-fact `(< ,(candidate-time a) ,(candidate-time b))
                     :candidates (mapcar (lambda (c) (list (candidate-event c) (candidate-time c)))
                                         candidates)
                     :detail "Which end of the curved state comes first is not decided."))
            (eq answer :true)))))
