;;;; src/engine/refresh.lisp -- refreshing an instance (its decisions, mode, collections and
;;;; equations) and building a model from scratch.

(in-package #:ames.engine)

;;; Refreshing an instance: its decisions, mode, collections and equations

(defun forget-activation (model instance)
  "Forget INSTANCE's activation decision and retract its activation assumption."
  (setf (instance-activation instance) nil)
  (let ((node (instance-activation-node instance)))
    (when node (retract model node))))

(defun forget-mode (model instance)
  "Forget INSTANCE's mode and retract its mode assumptions."
  (setf (instance-mode instance) nil)
  (loop for (nil . node) in (instance-mode-nodes instance) do (retract model node)))

(defun forget-collections (model instance)
  "Forget INSTANCE's collections and retract its closed-world assumption."
  (setf (instance-collections instance) nil)
  (let ((closure (instance-closure instance)))
    (when closure
      (setf (instance-closure instance) nil)
      (retract model (car closure)))))

(defun set-mode (model instance mode reason)
  "Put INSTANCE in MODE: enable its assumption with REASON, retract the others."
  (setf (instance-mode instance) mode)
  (loop for (name . node) in (instance-mode-nodes instance)
        unless (eq name mode) do (retract model node))
  (enable model (cdr (assoc mode (instance-mode-nodes instance))) reason))

(defun ensure-activation (model instance)
  "Decide a qualified INSTANCE's activation if it is not decided, and make its
activation assumption agree with the decision."
  (let ((node (instance-activation-node instance)))
    (when node
      (unless (instance-activation instance)
        (multiple-value-bind (decision reason) (decide-activation model instance)
          (setf (instance-activation instance) decision)
          (when (eq decision :true) (enable model node reason))))
      (if (eq (instance-activation instance) :true)
          (unless (ames.tms:node-enabled-p node) (enable model node '(:given)))
          (retract model node)))))

(defun ensure-mode (model instance)
  "Give an active INSTANCE a mode whose qualitative entry conditions hold: keep the
current one if they do, else decide anew."
  (when (component-modes (instance-component instance))
    (let ((mode (instance-mode instance)))
      (if (and mode (mode-valid-p instance mode))
          (let ((node (cdr (assoc mode (instance-mode-nodes instance)))))
            (unless (ames.tms:node-enabled-p node)
              (set-mode model instance mode '(:given))))
          (multiple-value-bind (mode reason) (decide-mode model instance)
            (set-mode model instance mode reason))))))

(defun current-collections (model instance)
  "INSTANCE's collection arguments over the believed beliefs: (values alist nodes),
the alist (?VAR . canonically sorted values), the nodes the beliefs that matched."
  (let ((collections '()) (nodes '()))
    (dolist (argument (component-collection-arguments (instance-component instance)))
      (let ((values '()) (pattern (argument-pattern argument)))
        (loop for (belief . node) in (candidate-beliefs model pattern (instance-bindings instance))
              when (ames.tms:node-in-p node)
                do (multiple-value-bind (bindings ok)
                       (match-pattern pattern belief (instance-bindings instance))
                     (when ok
                       (pushnew (substitute-bindings bindings (argument-collect argument))
                                values :test #'equal)
                       (pushnew node nodes))))
        (push (cons (argument-variable argument) (canonical-sort values)) collections)))
    (values (nreverse collections) (sort nodes #'< :key #'ames.tms:node-index))))

(defun ensure-collections (model instance)
  "Bring an active INSTANCE's collections up to date with what is believed, moving
its closed-world assumption to the new values when they changed."
  (when (component-collection-arguments (instance-component instance))
    (multiple-value-bind (collections nodes) (current-collections model instance)
      (unless (and (instance-closure instance)
                   (equal collections (instance-collections instance))
                   (equal nodes (cdr (instance-closure instance))))
        (forget-collections model instance)
        (let* ((memo (cons collections nodes))
               (closure (or (gethash memo (instance-closures instance))
                            (setf (gethash memo (instance-closures instance))
                                  (cons (ames.tms:make-node
                                         (model-jtms model)
                                         (list :collection (instance-key instance) collections)
                                         :assumption t)
                                        nodes)))))
          (setf (instance-collections instance) collections
                (instance-closure instance) closure)
          (enable model (car closure)
                  (list :closed-world
                        (mapcar (lambda (argument)
                                  (substitute-bindings (instance-bindings instance)
                                                       (argument-pattern argument)))
                                (component-collection-arguments
                                 (instance-component instance))))))))))

(defun ensure-equations (model instance)
  "Make, once for each mode and collection values, the equations of an active
INSTANCE: each justified by the instance, its mode assumption and entry beliefs, and,
when the equation reads a collection, the closed-world assumption and the beliefs
collected."
  (let* ((component (instance-component instance))
         (mode (instance-mode instance))
         (collection-variables (mapcar #'argument-variable
                                       (component-collection-arguments component)))
         (closure (instance-closure instance)))
    (flet ((make-equations (templates mode-name)
             (dolist (template templates)
               (let* ((reads-collections (intersection (form-variables template)
                                                       collection-variables))
                      (memo (list template mode-name (and reads-collections (car closure)))))
                 (unless (gethash memo (instance-made instance))
                   (setf (gethash memo (instance-made instance)) t)
                   (let ((base (append (list (instance-node instance))
                                       (and reads-collections closure))))
                     (dolist (equation (expand-template model instance template :equation t))
                       (let ((node (equation-node model equation)))
                         (if mode-name
                             (dolist (entry (cdr (assoc mode-name (instance-mode-supports instance))))
                               (push (justify model (component-name component) node
                                              (append base
                                                      (list (cdr (assoc mode-name
                                                                        (instance-mode-nodes instance))))
                                                      entry))
                                     (instance-equation-justifications instance)))
                             (push (justify model (component-name component) node base)
                                   (instance-equation-justifications instance)))))))))))
      (make-equations (component-equations component) nil)
      (when mode
        (make-equations (mode-equations (find-mode component mode)) mode)))))

(defun refresh-instance (model instance)
  "Bring INSTANCE's assumptions in line with its prerequisites: forget the decisions
of an unqualified instance; decide a qualified one's activation; give an active one
a mode, up-to-date collections and its equations; forget the mode and collections
of an inactive one. Checks the running budget (AMES.BASE:CHECK-BUDGET): a model of
very many instances cannot outlive its scenario run's time limit."
  (check-budget instance)
  (cond ((not (instance-qualified-p instance))
         (forget-activation model instance)
         (forget-mode model instance)
         (forget-collections model instance))
        (t (ensure-activation model instance)
           (cond ((instance-active-p instance)
                  (ensure-mode model instance)
                  (ensure-collections model instance)
                  (ensure-equations model instance))
                 (t (forget-mode model instance)
                    (forget-collections model instance))))))

;;; Building a model

(defun model-node-printer (datum stream)
  "How the engine's JTMS prints node data, informants and reasons: in lower case,
on one line."
  (let ((*print-case* :downcase) (*print-pretty* nil))
    (prin1 datum stream)))

(defun valid-decision-p (decision)
  "True when DECISION is (:activation KEY :true|:false) or (:mode KEY MODE)."
  (and (proper-list-p decision) (= 3 (length decision))
       (case (first decision)
         (:activation (member (third decision) '(:true :false)))
         (:mode (and (symbolp (third decision)) (third decision))))))

(defun build-model (engine situation &key decider decisions)
  "Build from scratch the model of a qualitative state: instantiate ENGINE's
components, in dependency order, for every binding of their arguments to
SITUATION's entities and to the beliefs asserted by earlier components, and decide
the quantitative conditions of the qualified instances.

DECIDER is a function of one relation (in the prefix algebra, over the state's
quantities) returning :TRUE, :FALSE or :UNKNOWN; it is called for activation and
mode entry conditions only. DECISIONS, a list like MODEL-DECISIONS returns --
(:activation KEY :true|:false) and (:mode KEY MODE) -- are taken instead of asking
the decider, for the instances they name (how a state can be rebuilt from the
decisions of the previous one).

Signals COMPONENT-DEPENDENCY-CYCLE, DUPLICATE-INSTANCE, TEMPLATE-EXPANSION-ERROR,
MISSING-DECIDER, INVALID-DECISION, UNDECIDED-RELATION (restart USE-DECISION) and
MODE-SELECTION-ERROR (restart CHOOSE-MODE)."
  (check-type engine engine)
  (check-type situation situation)
  (let ((model (%make-model engine situation
                            (ames.tms:make-jtms :title "model" :node-printer #'model-node-printer)
                            decider)))
    (dolist (decision decisions)
      (unless (valid-decision-p decision)
        (error 'engine-error :datum decision
                             :detail "A decision is (:ACTIVATION KEY :TRUE|:FALSE) or ~
                                      (:MODE KEY MODE)."))
      (setf (gethash (list (first decision) (second decision)) (model-given model))
            (third decision)))
    (setf (model-basis-decisions model) (copy-list decisions))
    (dolist (component (engine-order engine))
      (dolist (argument (component-collection-arguments component))
        (pushnew component (gethash (pattern-head (argument-pattern argument))
                                    (model-collectors model)))))
    (loop for component in (engine-order engine)
          for rank from 0
          do (dolist (instance (instantiate-component model component rank))
               (refresh-instance model instance)))
    (clrhash (model-given model))
    model))

(defun rebuild-from-scratch (model)
  "A new model built from scratch from MODEL's situation, decider and basis
decisions: what MODEL must equal."
  (build-model (model-engine model) (model-situation model)
               :decider (model-decider model) :decisions (model-basis-decisions model)))

(defun model-decisions (model)
  "The decisions MODEL rests on, canonically sorted: (:activation KEY :true|:false)
for each qualified instance with an activation assumption, (:mode KEY MODE) for
each active instance with modes. BUILD-MODEL accepts them as :DECISIONS."
  (let ((decisions '()))
    (dolist (instance (model-instance-list model))
      (when (instance-activation instance)
        (push (list :activation (instance-key instance) (instance-activation instance))
              decisions))
      (when (instance-mode instance)
        (push (list :mode (instance-key instance) (instance-mode instance)) decisions)))
    (canonical-sort decisions)))

(defun instance-event (instance spec)
  "The event and impact event of the EVENT-SPEC SPEC (or NIL) for INSTANCE: its
templates with INSTANCE's bindings and collections substituted. Two values."
  (if spec
      (let ((bindings (append (instance-collections instance) (instance-bindings instance))))
        (values (substitute-bindings bindings (event-spec-event spec))
                (substitute-bindings bindings (event-spec-impact spec))))
      (values nil nil)))

(defun model-termination-conditions (model)
  "The termination conditions of MODEL's state, as TERMINATION-CONDITION objects:
the deactivation conditions, watches and the current mode's transition conditions of
every active instance, and the activation condition (a conjunction) of every qualified
instance that is not active. Relations are expanded for the instance; each carries
the event its component names for it."
  (let ((conditions '()))
    (dolist (instance (model-instances model) (nreverse conditions))
      (let* ((component (instance-component instance))
             (key (instance-key instance)))
        (cond ((instance-active-p instance)
               (loop for template in (component-deactivation-relations component)
                     for spec in (component-deactivation-events component)
                     do (multiple-value-bind (event impact) (instance-event instance spec)
                          (push (make-termination-condition
                                 :deactivation key (expanded-relation model instance template)
                                 (list :deactivate key) event impact)
                                conditions)))
               (loop for template in (component-watch-relations component)
                     for spec in (component-watch-events component)
                     do (multiple-value-bind (event impact) (instance-event instance spec)
                          (push (make-termination-condition
                                 :watch key (expanded-relation model instance template)
                                 nil event impact)
                                conditions)))
               (let ((mode (instance-mode instance)))
                 (when mode
                   (dolist (transition (mode-transitions (find-mode component mode)))
                     (multiple-value-bind (event impact)
                         (instance-event instance (transition-event transition))
                       (push (make-termination-condition
                              :mode-transition key
                              (expanded-relation model instance (transition-relation transition))
                              (list :mode key :from mode :to (transition-target transition))
                              event impact)
                             conditions))))))
              ((and (component-activation-relations component)
                    (instance-qualified-p instance))
               (let ((relations (mapcar (lambda (template)
                                          (expanded-relation model instance template))
                                        (component-activation-relations component))))
                 (multiple-value-bind (event impact)
                     (instance-event instance (component-activation-event component))
                   (push (make-termination-condition
                          :activation key
                          (if (rest relations) (cons 'and relations) (first relations))
                          (list :activate key) event impact)
                         conditions)))))))))
