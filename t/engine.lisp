;;;; t/engine.lisp -- tests of the component engine on the heating knowledge base: ordering,
;;;; the model, termination conditions, transitions against rebuilds, explanations, errors.

(in-package #:ames.tests)

(def-suite engine :in all-tests :description "The component engine (src/engine/).")

(in-suite engine)

(defparameter +cold-kitchen+
  '(((temperature kitchen) . 15) ((temperature hall) . 18) (s . 20) ((opening d1) . 1))
  "Initial values: the kitchen is below the setpoint, the door is open.")

(defun heating-model (&key (values +cold-kitchen+) log)
  "A model of HEATING-SITUATION built with a fresh heating knowledge base."
  (ames.engine:build-model (ames.engine:make-engine (make-heating-kb)) (heating-situation)
                           :decider (table-decider values log)))

(defun set-equal-p (a b)
  "True when the lists A and B hold the same elements (EQUAL)."
  (and (subsetp a b :test #'equal) (subsetp b a :test #'equal)))

(defun active-keys (model)
  "The keys and modes of MODEL's active instances."
  (mapcar (lambda (instance)
            (list (ames.engine:instance-key instance) (ames.engine:instance-mode instance)))
          (ames.engine:model-active-instances model)))

(defun termination-lists (model)
  "MODEL's termination conditions as (KIND INSTANCE RELATION CHANGE) lists."
  (mapcar (lambda (c)
            (list (ames.engine:termination-condition-kind c)
                  (ames.engine:termination-condition-instance c)
                  (ames.engine:termination-condition-relation c)
                  (ames.engine:termination-condition-change c)))
          (ames.engine:model-termination-conditions model)))

(defparameter +door-equations+
  '((= (heat-power through d1 kitchen)
       (* k (opening d1) (- (temperature hall) (temperature kitchen))))
    (= (heat-power through d1 kitchen) (- (heat-power through d1 hall)))
    (= (heat-power through d1 hall) (- (heat-power through d1 kitchen))))
  "The equations the open door contributes, with its two exchange balances.")

(test components-are-ordered-by-their-data-dependencies
  (let* ((kb (make-heating-kb))
         (order (mapcar #'ames.engine:component-name (ames.engine:component-order kb))))
    (flet ((before (a b) (< (position a order) (position b order))))
      (is (before 'heater 'energy-balance))
      (is (before 'open-door 'energy-balance))
      (is (before 'open-door 'exchange-balance))
      (is (before 'heater 'heated-room)))
    (is (set-equal-p '(heater open-door)
                     (cdr (assoc 'energy-balance (ames.engine:component-dependencies kb)))))
    (is (null (cdr (assoc 'open-door (ames.engine:component-dependencies kb)))))))

(test the-model-of-a-cold-kitchen-with-an-open-door
  (let ((model (heating-model)))
    (is (set-equal-p
         (append '((= (heat-power output radiator) p)
                   (= (stirring kitchen) 1)
                   (= (* ck (temperature-rate kitchen))
                      (+ (heat-power output radiator) (heat-power through d1 kitchen)))
                   (= (* ch (temperature-rate hall)) (+ (heat-power through d1 hall))))
                 +door-equations+)
         (ames.engine:model-equations model)))
    (is (set-equal-p '((heat-flow (output radiator) :into kitchen :from radiator :kind radiant)
                       (heat-flow (through d1 kitchen) :into kitchen :from hall)
                       (heat-flow (through d1 hall) :into hall :from kitchen)
                       (heated kitchen))
                     (ames.engine:model-beliefs model)))
    (is (set-equal-p '(((heater radiator) on) ((open-door d1) nil)
                       ((exchange-balance (through d1 kitchen) (through d1 hall)) nil)
                       ((exchange-balance (through d1 hall) (through d1 kitchen)) nil)
                       ((energy-balance kitchen) nil) ((energy-balance hall) nil)
                       ((heated-room kitchen) nil))
                     (active-keys model)))
    ;; the broken stove is filtered out by :WHERE (:broken nil): no instance at all
    (is (null (ames.engine:find-instance model '(heater stove))))
    ;; the hall has no radiant flow: its HEATED-ROOM instance cannot exist
    (is (null (ames.engine:find-instance model '(heated-room hall))))
    (is (equal '(((?flows (output radiator) (through d1 kitchen))))
               (list (ames.engine:instance-collections
                      (ames.engine:find-instance model '(energy-balance kitchen))))))))

(test termination-conditions-name-instance-relation-and-change
  (let ((model (heating-model)))
    (is (set-equal-p
         '((:mode-transition (heater radiator) (>= (temperature kitchen) s)
            (:mode (heater radiator) :from on :to off))
           (:deactivation (open-door d1) (<= (opening d1) 0)
            (:deactivate (open-door d1))))
         (termination-lists model)))))

(test a-closed-door-gives-an-activation-condition
  (let ((model (heating-model :values '(((temperature kitchen) . 25) ((temperature hall) . 18)
                                        (s . 20) ((opening d1) . 0)))))
    (is (set-equal-p '(((heater radiator) off) ((energy-balance kitchen) nil)
                       ((energy-balance hall) nil))
                     (active-keys model)))
    (is (set-equal-p '((= (* ck (temperature-rate kitchen)) 0)
                       (= (* ch (temperature-rate hall)) 0))
                     (ames.engine:model-equations model)))
    (is (set-equal-p
         '((:mode-transition (heater radiator) (< (temperature kitchen) s)
            (:mode (heater radiator) :from off :to on))
           (:activation (open-door d1) (> (opening d1) 0) (:activate (open-door d1))))
         (termination-lists model)))))

(test the-decider-is-asked-only-what-is-needed
  (let ((log (list '())))
    (heating-model :log log)
    ;; the two heater modes' entry conditions and the door's activation; nothing on
    ;; the broken stove, and no termination condition is ever decided
    (is (set-equal-p '((< (temperature kitchen) s) (>= (temperature kitchen) s)
                       (> (opening d1) 0))
                     (car log)))))

(test a-mode-switch-is-incremental-and-equals-the-rebuild
  (let ((model (heating-model)))
    (multiple-value-bind (same report)
        (ames.engine:apply-transition model '((:mode (heater radiator) :from on :to off)))
      (is (eq model same))
      ;; exactly the heater and what reads its flow were re-derived
      (is (set-equal-p '((heater radiator) (energy-balance kitchen) (heated-room kitchen))
                       (ames.engine:transition-report-rederived report))))
    (is (set-equal-p (append '((= (* ck (temperature-rate kitchen))
                                  (+ (heat-power through d1 kitchen)))
                               (= (* ch (temperature-rate hall))
                                  (+ (heat-power through d1 hall))))
                             +door-equations+)
                     (ames.engine:model-equations model)))
    (is (equal '(:mode (heater radiator) :from off :to on)
               (ames.engine:termination-condition-change
                (find '(heater radiator) (ames.engine:model-termination-conditions model)
                      :key #'ames.engine:termination-condition-instance :test #'equal))))
    (is (null (ames.engine:check-incremental model)))
    ;; and back: the original model again
    (ames.engine:apply-transition model '((:mode (heater radiator) :from off :to on)))
    (is (null (ames.engine:model-difference model (heating-model))))
    (is (null (ames.engine:check-incremental model)))))

(test deactivation-and-reactivation-equal-the-rebuild
  (let ((model (heating-model)) (original (heating-model)))
    (ames.engine:apply-transition model '((:deactivate (open-door d1))))
    (is (set-equal-p '((= (heat-power output radiator) p)
                       (= (stirring kitchen) 1)
                       (= (* ck (temperature-rate kitchen)) (+ (heat-power output radiator)))
                       (= (* ch (temperature-rate hall)) 0))
                     (ames.engine:model-equations model)))
    (is (member '(:activation (open-door d1) (> (opening d1) 0) (:activate (open-door d1)))
                (termination-lists model) :test #'equal))
    (is (null (ames.engine:check-incremental model)))
    (ames.engine:apply-transition model '((:activate (open-door d1))))
    (is (null (ames.engine:model-difference model original)))
    (is (null (ames.engine:check-incremental model)))))

(test simultaneous-changes-equal-the-rebuild
  (let ((model (heating-model)))
    (ames.engine:apply-transition model '((:deactivate (open-door d1))
                                          (:mode (heater radiator) :from on :to off)))
    (is (set-equal-p '((= (* ck (temperature-rate kitchen)) 0)
                       (= (* ch (temperature-rate hall)) 0))
                     (ames.engine:model-equations model)))
    (is (null (ames.engine:check-incremental model)))))

(test why-names-the-informants-and-assumptions
  (let* ((model (heating-model))
         (equation '(= (* ck (temperature-rate kitchen))
                     (+ (heat-power output radiator) (heat-power through d1 kitchen))))
         (text (with-output-to-string (s) (ames.engine:explain model equation s))))
    (is (search "is IN, by energy-balance, from:" text))
    (is (search "(heat-flow (output radiator) :into kitchen :from radiator :kind radiant) is IN, by heater, from:"
                text))
    (is (search "(heat-flow (through d1 kitchen) :into kitchen :from hall) is IN, by open-door, from:"
                text))
    (is (search "(room kitchen) is a premise (:situation)." text))
    (is (search "(:mode (heater radiator) on) is an enabled assumption: (:decided ((< (temperature kitchen) s)))."
                text))
    (is (search "(:activation (open-door d1)) is an enabled assumption: (:decided ((> (opening d1) 0)))."
                text))
    (is (set-equal-p
         '((:mode (heater radiator) on)
           (:activation (open-door d1))
           (:collection (energy-balance kitchen) ((?flows (output radiator) (through d1 kitchen)))))
         (mapcar #'ames.tms:node-datum
                 (ames.tms:assumptions-of (ames.engine:find-node model equation)))))
    ;; after the transition the reason names the change, and the old equation is OUT
    (ames.engine:apply-transition model '((:mode (heater radiator) :from on :to off)))
    (is (search "(:mode (heater radiator) off) is an enabled assumption: (:transition (:mode (heater radiator) :from on :to off))."
                (with-output-to-string (s)
                  (ames.engine:explain model '(:instance (heater radiator)) s)
                  (ames.engine:explain model '(:mode (heater radiator) off) s))))
    (is (search "is OUT" (with-output-to-string (s) (ames.engine:explain model equation s))))
    (signals ames.engine:engine-error (ames.engine:explain model '(no such belief)))))

(test an-unknown-decision-is-not-guessed
  (let ((unknown-door '(((temperature kitchen) . 15) ((temperature hall) . 18) (s . 20))))
    (let ((condition (handler-case (heating-model :values unknown-door)
                       (ames.engine:undecided-relation (c) c))))
      (is (typep condition 'ames.engine:undecided-relation))
      (is (equal '(> (opening d1) 0) (ames.engine:undecided-relation-relation condition)))
      (is (equal '(open-door d1) (ames.engine:undecided-relation-instance condition)))
      (is (search "(OPENING D1)" (princ-to-string condition))))
    (dolist (decision '(:true :false))
      (let ((model (handler-bind ((ames.engine:undecided-relation
                                    (lambda (c) (ames.engine:use-decision decision c))))
                     (heating-model :values unknown-door))))
        (is (eq (eq decision :true)
                (ames.engine:instance-active-p (ames.engine:find-instance model '(open-door d1)))))
        (is (member (list :activation '(open-door d1) decision)
                    (ames.engine:model-decisions model) :test #'equal))
        (when (eq decision :true)
          (is (search "(:assumed (((> (opening d1) 0) :true)))"
                      (with-output-to-string (s)
                        (ames.engine:explain model '(:instance (open-door d1)) s)))))))
    (signals ames.engine:invalid-decision
      (handler-bind ((ames.engine:undecided-relation
                       (lambda (c) (ames.engine:use-decision :maybe c))))
        (heating-model :values unknown-door)))))

(test deciders-are-checked
  (signals ames.engine:missing-decider
    (ames.engine:build-model (ames.engine:make-engine (make-heating-kb)) (heating-situation)))
  (signals ames.engine:invalid-decision
    (ames.engine:build-model (ames.engine:make-engine (make-heating-kb)) (heating-situation)
                             :decider (constantly t))))

(defun lamp-kb (&key (dim-entry '(< (voltage ?lamp) 100)) (bright-entry '(>= (voltage ?lamp) 100)))
  "A one-component knowledge base whose two modes have the given entry conditions."
  (let ((kb (ames.engine:make-knowledge-base :name "lamps")))
    (ames.engine:register-component
     kb (ames.engine:parse-component
         'lamp "A lamp glows dimly or brightly."
         `((:arguments (?lamp :entity lamp))
           (:mode dim (:entry ,dim-entry) (:equations (= (glow ?lamp) 1)))
           (:mode bright (:entry ,bright-entry) (:equations (= (glow ?lamp) 2))))))
    kb))

(defun lamp-model (kb volts)
  "A model of one lamp at VOLTS."
  (ames.engine:build-model (ames.engine:make-engine kb)
                           (ames.engine:make-situation '((lamp l1)))
                           :decider (table-decider `(((voltage l1) . ,volts)))))

(test mode-entry-conditions-must-choose-exactly-one-mode
  (is (equal '((= (glow l1) 2)) (ames.engine:model-equations (lamp-model (lamp-kb) 150))))
  (let* ((overlapping (lamp-kb :bright-entry '(>= (voltage ?lamp) 50)))
         (condition (handler-case (lamp-model overlapping 70)
                      (ames.engine:mode-selection-error (c) c))))
    (is (equal '(dim bright) (ames.engine:mode-selection-error-candidates condition)))
    (is (equal '((= (glow l1) 2))
               (ames.engine:model-equations
                (handler-bind ((ames.engine:mode-selection-error
                                 (lambda (c) (ames.engine:choose-mode 'bright c))))
                  (lamp-model overlapping 70))))))
  (let ((gapped (lamp-kb :bright-entry '(>= (voltage ?lamp) 200))))
    (is (null (ames.engine:mode-selection-error-candidates
               (handler-case (lamp-model gapped 150)
                 (ames.engine:mode-selection-error (c) c)))))))

(test a-dependency-cycle-names-its-components
  (let ((kb (ames.engine:make-knowledge-base :name "cycle")))
    (ames.engine:defcomponent hen (:knowledge-base kb)
      "A hen lays an egg."
      (:arguments (?e :belief (egg ?e)))
      (:assert (hen (from ?e))))
    (ames.engine:defcomponent egg (:knowledge-base kb)
      "An egg hatches a hen."
      (:arguments (?h :belief (hen ?h)))
      (:assert (egg (from ?h))))
    (ames.engine:defcomponent bystander (:knowledge-base kb)
      "Reads hens, asserts nothing anyone reads."
      (:arguments (?h :belief (hen ?h)))
      (:assert (seen ?h)))
    (let ((condition (handler-case (ames.engine:make-engine kb)
                       (ames.engine:component-dependency-cycle (c) c))))
      (is (typep condition 'ames.engine:component-dependency-cycle))
      (is (set-equal-p '(hen egg) (ames.engine:dependency-cycle-components condition)))
      (is (search "HEN" (princ-to-string condition)))
      (is (search "EGG" (princ-to-string condition))))))

(test template-expansion-errors-name-the-instance-and-template
  (let ((kb (make-heating-kb)))
    ;; a POWER that forgets to flatten the flow's name into a quantity term
    (ames.engine:register-template kb 'power (lambda (situation flow)
                                               (declare (ignore situation))
                                               (list 'heat-power flow)))
    (let ((condition (handler-case (ames.engine:build-model (ames.engine:make-engine kb)
                                                            (heating-situation)
                                                            :decider (table-decider +cold-kitchen+))
                       (ames.engine:template-expansion-error (c) c))))
      (is (typep condition 'ames.engine:template-expansion-error))
      (is (search "(HEATER RADIATOR)" (princ-to-string condition)))
      (is (search "(POWER (OUTPUT ?HEATER))" (princ-to-string condition)))))
  (let ((kb (make-heating-kb)))
    (ames.engine:register-template kb 'rating (lambda (situation heater)
                                                (list 'rated heater situation)))
    (signals ames.engine:template-expansion-error
      (ames.engine:build-model (ames.engine:make-engine kb) (heating-situation)
                               :decider (table-decider +cold-kitchen+)))))

(test instance-keys-must-be-unique
  (let ((kb (ames.engine:make-knowledge-base)))
    (ames.engine:defcomponent draught (:knowledge-base kb)
      "One draught blows into every room."
      (:arguments (?room :entity room))
      (:assert (air-flow draught :into ?room)))
    (ames.engine:defcomponent draught-meter (:knowledge-base kb)
      "Meters a draught -- but several rooms share the draught's name."
      (:arguments (?flow :belief (air-flow ?flow :into ?room)))
      (:assert (metered ?flow)))
    (signals ames.engine:duplicate-instance
      (ames.engine:build-model (ames.engine:make-engine kb) (heating-situation)))))

(test transitions-refuse-changes-that-do-not-fit
  (let ((model (heating-model)))
    (dolist (change '((:deactivate (open-door d2))
                      (:deactivate (heater radiator))
                      (:activate (open-door d1))
                      (:mode (heater radiator) :from off :to on)
                      (:mode (heater radiator) :from on :to lukewarm)
                      (:mode (heater radiator) :to off)
                      (:explode (heater radiator))
                      :deactivate))
      (signals ames.engine:invalid-change (ames.engine:apply-transition model (list change))))
    (signals ames.engine:invalid-change
      (ames.engine:apply-transition model '((:deactivate (open-door d1))
                                            (:deactivate (open-door d1)))))
    ;; nothing was changed by the refused transitions
    (is (null (ames.engine:model-difference model (heating-model))))))

(test situations-check-their-entities
  (dolist (bad '(((room))
                 (("kitchen" hall))
                 ((room kitchen :capacity))
                 ((room kitchen capacity ck))
                 ((room kitchen) (door kitchen))))
    (signals ames.engine:situation-error (ames.engine:make-situation bad)))
  (let ((situation (heating-situation)))
    (is (eq 'kitchen (ames.engine:entity-name (ames.engine:find-entity situation 'kitchen))))
    (is (equal '(kitchen hall) (mapcar #'ames.engine:entity-name
                                       (ames.engine:entities-of-kind situation 'room))))
    (is (eq 'p (ames.engine:entity-property (ames.engine:find-entity situation 'radiator)
                                            :rating)))))

(test patterns-match-properties-in-any-order
  (flet ((match (pattern belief)
           (multiple-value-bind (bindings ok) (ames.engine::match-pattern pattern belief '())
             (and ok (sort (copy-list bindings) #'string< :key (lambda (b) (symbol-name (car b))))))))
    (is (equal '((?b . w) (?f . (gravity w)))
               (match '(force ?f :on ?b) '(force (gravity w) :type gravity :from earth :on w))))
    (is (null (match '(force ?f :on ?b :type normal) '(force (gravity w) :type gravity :on w))))
    (is (null (match '(force ?f ?g) '(force (gravity w) :on w))))
    (is (null (match '(force ?f :on ?f) '(force x :on y))))
    (is (equal '((?f . x)) (match '(force ?f :on ?_) '(force x :on y))))
    (is (null (match '(torque ?f) '(force x))))))

(test model-difference-sees-what-differs
  (let ((open (heating-model))
        (closed (heating-model :values '(((temperature kitchen) . 15) ((temperature hall) . 18)
                                         (s . 20) ((opening d1) . 0)))))
    (let ((difference (ames.engine:model-difference open closed)))
      (is (equal '(:equations :termination-conditions :active-instances :beliefs :decisions)
                 (mapcar #'first difference)))
      (is (member '(= (* ch (temperature-rate hall)) 0)
                  (getf (rest (assoc :equations difference)) :only-in-second) :test #'equal))))
  ;; tampering with the JTMS behind the engine's back is caught by the check
  (let ((model (heating-model)))
    (ames.tms:retract-assumption (ames.engine:find-node model '(:mode (heater radiator) on)))
    (signals ames.engine:incremental-mismatch (ames.engine:check-incremental model))
    (is (assoc :equations (ames.engine:check-incremental model :signal nil)))))

;;; Random houses and random transitions against rebuilds from scratch

(defparameter +rooms+ '(r0 r1 r2 r3 r4 r5) "Room names for random houses.")
(defparameter +heaters+ '(h0 h1 h2 h3 h4 h5) "Heater names, one per room at most.")
(defparameter +doors+ '(d0 d1 d2 d3 d4 d5 d6 d7) "Door names for random houses.")

(defun random-house ()
  "A generator of random houses: entity lists with 2 to 6 rooms, heaters (some
broken) and doors between random pairs of rooms."
  (lambda ()
    (let* ((n (+ 2 (random 5)))
           (rooms (subseq +rooms+ 0 n)))
      (append
       (mapcar (lambda (room) (list 'room room :capacity 'c)) rooms)
       (loop for room in rooms for heater in +heaters+
             when (< (random 1.0) 0.7)
               collect (list 'heater heater :room room :rating 'p :setpoint 's
                             :broken (< (random 1.0) 0.2)))
       (loop for door in +doors+ repeat (random (* 2 n))
             collect (let ((a (nth (random n) rooms)) (b (nth (random n) rooms)))
                       (list 'door door :between a :and (if (eq a b) (nth (mod (1+ (position a rooms)) n) rooms) b)
                             :conductance 'k)))))))

(defun random-values (entities)
  "Random initial values for ENTITIES' temperatures and door openings."
  (append (list (cons 's 20))
          (loop for (kind name) in entities
                when (eq kind 'room)
                  collect (cons (list 'temperature name) (+ 10 (random 20)))
                when (eq kind 'door)
                  collect (cons (list 'opening name) (random 3)))))

(test random-transitions-equal-rebuilds-from-scratch
  (for-all ((entities (random-house)))
    (let* ((situation (ames.engine:make-situation entities))
           (model (ames.engine:build-model (ames.engine:make-engine (make-heating-kb)) situation
                                           :decider (table-decider (random-values entities))))
           (agree t) (steps 0))
      (loop repeat 8
            for conditions = (ames.engine:model-termination-conditions model)
            while conditions
            do (let* ((fired (remove-duplicates
                              (loop repeat (1+ (random 2))
                                    collect (nth (random (length conditions)) conditions))
                              :key #'ames.engine:termination-condition-instance :test #'equal))
                      (changes (mapcar #'ames.engine:termination-condition-change fired)))
                 (multiple-value-bind (model report)
                     (ames.engine:apply-transition
                      model changes :decider (table-decider (random-values entities)))
                   (incf steps)
                   ;; every instance named by a change is among those re-derived
                   (unless (every (lambda (change)
                                    (member (second change)
                                            (ames.engine:transition-report-rederived report)
                                            :test #'equal))
                                  changes)
                     (setf agree nil))
                   (when (ames.engine:check-incremental model :signal nil)
                     (setf agree nil)))))
      (is-true agree))))

(test a-collection-follows-its-beliefs-not-only-its-values
  ;; Two sources assert beliefs that collect to the same value: when one source
  ;; stops, the collection's value is unchanged but now rests on the other belief.
  (let ((kb (ames.engine:make-knowledge-base)))
    (ames.engine:register-template kb 'size (lambda (situation items)
                                              (declare (ignore situation))
                                              (length items)))
    (ames.engine:defcomponent source (:knowledge-base kb)
      "A running source supplies the shared main of its room."
      (:arguments (?source :entity source :where (:room ?room :tag ?tag)))
      (:activation (> (level ?source) 0))
      (:deactivation (<= (level ?source) 0))
      (:assert (supply main :into ?room :tag ?tag)))
    (ames.engine:defcomponent supplies (:knowledge-base kb)
      "A room counts its distinct supplies."
      (:arguments (?room :entity room)
                  (?all :collect ?s :matching (supply ?s :into ?room)))
      (:equations (= (supplies ?room) (size ?all))))
    (let ((model (ames.engine:build-model
                  (ames.engine:make-engine kb)
                  (ames.engine:make-situation '((room r) (source s1 :room r :tag a)
                                                (source s2 :room r :tag b)))
                  :decider (table-decider '(((level s1) . 1) ((level s2) . 1))))))
      (is (equal '((= (supplies r) 1)) (ames.engine:model-equations model)))
      (ames.engine:apply-transition model '((:deactivate (source s1))))
      (is (equal '((= (supplies r) 1)) (ames.engine:model-equations model)))
      (is (null (ames.engine:check-incremental model)))
      (ames.engine:apply-transition model '((:deactivate (source s2))))
      (is (equal '((= (supplies r) 0)) (ames.engine:model-equations model)))
      (is (null (ames.engine:check-incremental model))))))
