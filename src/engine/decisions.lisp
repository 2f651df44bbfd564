;;;; src/engine/decisions.lisp -- deciding quantitative conditions, keeping the JTMS, and
;;;; making the potential instances of a component.

(in-package #:ames.engine)

;;; Deciding quantitative conditions

(defun ask-decider (model relation &optional (decider (model-decider model)))
  "DECIDER's answer (by default MODEL's decider's) for RELATION: :TRUE, :FALSE,
:UNKNOWN or :CHOICE."
  (let ((decider decider))
    (unless decider
      (error 'missing-decider :datum relation
                              :detail "A quantitative condition must be decided, but the ~
                                       model has no decider."))
    (let ((answer (funcall decider relation)))
      (unless (member answer '(:true :false :unknown :choice))
        (error 'invalid-decision :datum answer
                                 :detail (format nil "The decider answered this for ~S; it ~
                                                      must answer :TRUE, :FALSE, :UNKNOWN ~
                                                      or :CHOICE."
                                                 relation)))
      answer)))

(defun read-decision ()
  "Ask on *QUERY-IO* for :TRUE or :FALSE (for the USE-DECISION restart)."
  (loop
    (format *query-io* "~&Decide the relation: type true or false: ")
    (finish-output *query-io*)
    (let ((answer (string-trim " " (read-line *query-io*))))
      (cond ((string-equal answer "true") (return (list :true)))
            ((string-equal answer "false") (return (list :false)))))))

(defun resolve-unknown (instance relation)
  "Signal UNDECIDED-RELATION for RELATION of INSTANCE; return the decision supplied
through the USE-DECISION restart."
  (restart-case (error 'undecided-relation :instance (instance-key instance)
                                           :relation relation :datum relation)
    (use-decision (decision)
      :report "Supply the relation's truth value (:TRUE or :FALSE)."
      :interactive read-decision
      (unless (member decision '(:true :false))
        (error 'invalid-decision :datum decision
                                 :detail "USE-DECISION takes :TRUE or :FALSE."))
      decision)))

(defun conjunction-answer (model relations answers &optional (decider (model-decider model)))
  "The decider's verdict on the conjunction of RELATIONS without resolving unknowns:
:FALSE at the first false one, else :UNKNOWN if any is unknown, else :CHOICE if any
is a choice (the decider's answer for a condition that may hold or not, to be settled
by the caller's consistency search), else :TRUE. ANSWERS is a hash table caching
each relation's answer."
  (let ((verdict :true))
    (dolist (relation relations verdict)
      (let ((answer (or (gethash relation answers)
                        (setf (gethash relation answers) (ask-decider model relation decider)))))
        (case answer
          (:false (return :false))
          (:unknown (setf verdict :unknown))
          (:choice (unless (eq verdict :unknown) (setf verdict :choice))))))))

(defun decide-activation (model instance)
  "Decide INSTANCE's activation: (values decision reason), the decision being :TRUE
or :FALSE. Uses a given decision when building, else the decider; an unknown answer
is resolved through UNDECIDED-RELATION, never guessed. A :CHOICE (the activation may
hold or not) is taken as :TRUE, with the reason (:CHOICE RELATIONS): the caller's
consistency search (see MODEL-CHOICE-POINTS) settles it."
  (let* ((key (instance-key instance))
         (given (gethash (list :activation key) (model-given model)))
         (templates (component-activation-relations (instance-component instance))))
    (cond (given (values given '(:given)))
          ((null templates) (values :true '(:always)))
          (t (let* ((relations (mapcar (lambda (template)
                                         (expanded-relation model instance template))
                                       templates))
                    (answers (make-hash-table :test #'equal))
                    (verdict (conjunction-answer model relations answers)))
               (if (not (eq verdict :unknown))
                   (if (eq verdict :choice)
                       (values :true (list :choice relations))
                       (values verdict (list :decided relations)))
                   (let ((assumed '()))
                     (dolist (relation relations (values :true (list :assumed assumed)))
                       (when (eq (gethash relation answers) :unknown)
                         (let ((decision (resolve-unknown instance relation)))
                           (push (list relation decision) assumed)
                           (when (eq decision :false)
                             (return (values :false (list :assumed assumed))))))))))))))

(defun mode-valid-p (instance mode-name)
  "True when the qualitative entry conditions of INSTANCE's mode MODE-NAME hold."
  (some (lambda (support) (every #'ames.tms:node-in-p support))
        (cdr (assoc mode-name (instance-mode-supports instance)))))

(defun decide-mode (model instance)
  "Choose INSTANCE's mode by the entry conditions: (values mode reason). A given
mode is used when building if its qualitative entry conditions hold. Exactly one
mode's conditions must hold (they are exclusive by contract, so the others are not
pressed when one is true); unknown answers are resolved through
UNDECIDED-RELATION, and none or several true modes signal MODE-SELECTION-ERROR.
When no mode is true but some are a :CHOICE, the first of those is taken with the
reason (:CHOICE RELATIONS): the caller's consistency search settles it."
  (let* ((component (instance-component instance))
         (key (instance-key instance))
         (given (gethash (list :mode key) (model-given model)))
         (answers (make-hash-table :test #'equal)))
    (when (and given (find-mode component given) (mode-valid-p instance given))
      (return-from decide-mode (values given '(:given))))
    (loop
      (let ((true '()) (unknown '()) (choices '()))
        (dolist (mode (component-modes component))
          (let* ((relations (mapcar (lambda (template) (expanded-relation model instance template))
                                    (mode-entry-relations mode)))
                 (verdict (if (mode-valid-p instance (mode-name mode))
                              (conjunction-answer model relations answers)
                              :false)))
            (case verdict
              (:true (push (cons mode relations) true))
              (:choice (push (cons mode relations) choices))
              (:unknown (push (cons mode relations) unknown)))))
        (cond ((= 1 (length true))
               (return (values (mode-name (car (first true)))
                               (list :decided (cdr (first true))))))
              ((and (null true) (null unknown) choices)
               (let ((first (car (last choices))))
                 (return (values (mode-name (car first)) (list :choice (cdr first))))))
              ((or (rest true) (null unknown))
               (return
                 (restart-case
                     (error 'mode-selection-error :instance key :datum key
                                                  :candidates (mapcar (lambda (entry)
                                                                        (mode-name (car entry)))
                                                                      (reverse true)))
                   (choose-mode (mode)
                     :report "Choose the instance's mode."
                     (unless (find-mode component mode)
                       (error 'invalid-decision :datum mode
                                                :detail (format nil "~S has no such mode."
                                                                (component-name component))))
                     (values mode '(:chosen))))))
              (t ;; resolve the first unknown relation of the first undecided mode, retry
               (let* ((entry (car (last unknown)))
                      (relation (find :unknown (cdr entry)
                                      :key (lambda (r) (gethash r answers)))))
                 (setf (gethash relation answers) (resolve-unknown instance relation)))))))))

;;; Keeping the JTMS, and the record of what changed

(defun note-changes (model came-in went-out)
  "During a transition, mark for refreshing the instances that read the nodes that
CAME-IN or WENT-OUT."
  (when (model-dirty model)
    (dolist (node came-in) (mark-readers model node))
    (dolist (node went-out) (mark-readers model node))))

(defun enable (model node reason)
  "Enable the assumption NODE with REASON, noting what changed."
  (unless (and (ames.tms:node-enabled-p node) (equal reason (ames.tms:node-enabling-reason node)))
    (multiple-value-call #'note-changes model (ames.tms:enable-assumption node reason))))

(defun retract (model node)
  "Retract the assumption NODE, noting what changed."
  (when (ames.tms:node-enabled-p node)
    (multiple-value-call #'note-changes model (ames.tms:retract-assumption node))))

(defun justify (model informant node antecedents)
  "Justify NODE by INFORMANT from ANTECEDENTS, noting what changed; return the
justification."
  (multiple-value-bind (justification came-in went-out)
      (ames.tms:justify-node informant node antecedents)
    (note-changes model came-in went-out)
    justification))

(defun mark-dirty (model instance)
  "Queue INSTANCE for refreshing in the running transition."
  (unless (gethash instance (model-pending model))
    (setf (gethash instance (model-pending model)) t)
    (push instance (aref (model-dirty model) (instance-rank instance)))))

(defun add-reader (model node instance)
  "Record that INSTANCE must be refreshed when NODE changes label."
  (pushnew instance (gethash node (model-dependents model)) :test #'eq))

(defun mark-readers (model node)
  "Queue every instance that reads NODE: through its arguments and conditions, or,
for a belief, through a collection whose pattern it matches."
  (dolist (instance (gethash node (model-dependents model)))
    (mark-dirty model instance))
  (let ((belief (ames.tms:node-datum node)))
    (when (and (consp belief) (eq node (gethash belief (model-belief-table model))))
      (dolist (component (gethash (pattern-head belief) (model-collectors model)))
        (dolist (instance (gethash (component-name component) (model-by-component model)))
          (when (some (lambda (argument)
                        (nth-value 1 (match-pattern (argument-pattern argument) belief
                                                    (instance-bindings instance))))
                      (component-collection-arguments component))
            (mark-dirty model instance)))))))

;;; Making the potential instances

(defun entity-node (model entity)
  "The premise node of ENTITY, made on first use."
  (or (gethash (entity-name entity) (model-entity-nodes model))
      (setf (gethash (entity-name entity) (model-entity-nodes model))
            (ames.tms:make-premise (model-jtms model)
                                   (list (entity-kind entity) (entity-name entity))
                                   :situation))))

(defun belief-node (model belief)
  "The node of the qualitative assertion BELIEF, made on first use."
  (or (gethash belief (model-belief-table model))
      (let ((node (ames.tms:make-node (model-jtms model) belief)))
        (push (cons belief node) (gethash (pattern-head belief) (model-beliefs-by-head model)))
        (index-belief model belief node)
        (setf (gethash belief (model-belief-table model)) node))))

(defun equation-node (model equation)
  "The node of EQUATION, made on first use."
  (or (gethash equation (model-equation-table model))
      (setf (gethash equation (model-equation-table model))
            (ames.tms:make-node (model-jtms model) equation))))

(defun beliefs-with-head (model head)
  "Every (belief . node) of MODEL whose head is HEAD, oldest first."
  (reverse (gethash head (model-beliefs-by-head model))))

(defun enumerate-bindings (model component)
  "Every binding of COMPONENT's entity and belief arguments (whether or not the
beliefs are believed now): a list of (BINDINGS . NODES), NODES being the entity
and belief nodes the binding rests on."
  (let ((partials (list (cons '() '())))
        (situation (model-situation model)))
    (dolist (argument (component-arguments component) partials)
      (let ((extended '()))
        (dolist (partial partials)
          (destructuring-bind (bindings . nodes) partial
            (ecase (argument-kind argument)
              (:entity
               (let ((variable (argument-variable argument)))
                 (multiple-value-bind (value bound) (binding-value variable bindings)
                   (dolist (entity (if bound
                                       (let ((entity (and (symbolp value)
                                                          (find-entity situation value))))
                                         (and entity
                                              (eq (entity-kind entity)
                                                  (argument-entity-kind argument))
                                              (list entity)))
                                       (entities-of-kind situation
                                                         (argument-entity-kind argument))))
                     (multiple-value-bind (bindings ok)
                         (match-entity (argument-where argument) entity
                                       (if bound bindings
                                           (acons variable (entity-name entity) bindings)))
                       (when ok
                         (push (cons bindings (cons (entity-node model entity) nodes))
                               extended)))))))
              (:belief
               (let ((pattern (argument-pattern argument)))
                 (loop for (belief . node) in (candidate-beliefs model pattern bindings)
                       do (multiple-value-bind (bindings ok) (match-pattern pattern belief bindings)
                            (when ok (push (cons bindings (cons node nodes)) extended))))))
              (:collection (push partial extended)))))
        (setf partials (nreverse extended))))))

(defun belief-alternatives (model patterns bindings)
  "The ways to satisfy every belief pattern of PATTERNS (existential variables
joined across them) under BINDINGS: a list of node lists. NIL when there is none,
(NIL) when PATTERNS is empty."
  (let ((partials (list (cons bindings '()))))
    (dolist (pattern patterns)
      (setf partials
            (loop for (bindings . nodes) in partials
                  append (loop for (belief . node) in (candidate-beliefs model pattern bindings)
                               for (extended ok) = (multiple-value-list
                                                    (match-pattern pattern belief bindings))
                               when ok collect (cons extended (cons node nodes))))))
    (mapcar (lambda (partial) (reverse (cdr partial))) partials)))

(defun instance-key-of (component bindings)
  "The key of COMPONENT's instance for BINDINGS."
  (cons (component-name component)
        (mapcar (lambda (variable) (binding-value variable bindings))
                (component-key-variables component))))

(defun make-potential-instance (model component rank bindings argument-nodes alternatives)
  "Make the instance of COMPONENT for BINDINGS: its node justified by the argument
nodes, each alternative of its :BELIEVES conditions and its activation assumption;
its mode assumptions; and its qualitative assertions, justified by it."
  (let ((name (component-name component))
        (key (instance-key-of component bindings)))
    (when (gethash key (model-instance-table model))
      (error 'duplicate-instance :datum key
                                 :detail (format nil "Two bindings of ~S's arguments give the ~
                                                      same instance key." name)))
    (make-instance-nodes model (%make-instance key component bindings rank)
                         argument-nodes alternatives)))

(defun make-instance-nodes (model instance argument-nodes alternatives)
  "Make INSTANCE's nodes and justifications (see MAKE-POTENTIAL-INSTANCE); return it."
  (let* ((jtms (model-jtms model))
         (component (instance-component instance))
         (name (component-name component))
         (key (instance-key instance))
         (bindings (instance-bindings instance))
         (node (ames.tms:make-node jtms (list :instance key)))
         (activation (and (or (component-activation-relations component)
                              (component-deactivation-relations component))
                          (ames.tms:make-node jtms (list :activation key) :assumption t))))
    (setf (gethash key (model-instance-table model)) instance
          (instance-node instance) node
          (instance-activation-node instance) activation
          (instance-supports instance) (mapcar (lambda (alternative)
                                                 (append argument-nodes alternative))
                                               alternatives))
    (push instance (model-instance-list model))
    (push instance (gethash name (model-by-component model)))
    (add-reader model node instance)
    (dolist (support (instance-supports instance))
      (dolist (antecedent support) (add-reader model antecedent instance))
      (justify model name node (if activation (cons activation support) support)))
    (dolist (mode (component-modes component))
      (let ((mode-node (ames.tms:make-node jtms (list :mode key (mode-name mode)) :assumption t))
            (entries (belief-alternatives model (mode-entry-beliefs mode) bindings)))
        (push (cons (mode-name mode) mode-node) (instance-mode-nodes instance))
        (push (cons (mode-name mode) entries) (instance-mode-supports instance))
        (dolist (entry entries)
          (dolist (antecedent entry) (add-reader model antecedent instance)))))
    (setf (instance-mode-nodes instance) (nreverse (instance-mode-nodes instance))
          (instance-mode-supports instance) (nreverse (instance-mode-supports instance)))
    ;; qualitative assertions: every mode's, so that the belief universe is complete
    (dolist (pattern (component-assertions component))
      (justify model name (belief-node model (substitute-bindings bindings pattern))
               (list node)))
    (dolist (mode (component-modes component))
      (dolist (pattern (mode-assertions mode))
        (let ((belief (belief-node model (substitute-bindings bindings pattern))))
          (dolist (entry (cdr (assoc (mode-name mode) (instance-mode-supports instance))))
            (justify model name belief
                     (list* node (cdr (assoc (mode-name mode) (instance-mode-nodes instance)))
                            entry))))))
    instance))

(defun instantiate-component (model component rank)
  "Make every potential instance of COMPONENT in MODEL; return them."
  (loop for (bindings . nodes) in (enumerate-bindings model component)
        for alternatives = (belief-alternatives model (component-activation-beliefs component)
                                                bindings)
        ;; with no way to satisfy its :BELIEVES conditions, there is no instance
        when alternatives
          collect (make-potential-instance model component rank bindings
                                           (reverse nodes) alternatives)))
