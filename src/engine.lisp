;;;; src/engine.lisp -- building the model of a qualitative state from a knowledge base, and
;;;; updating it incrementally across a transition (thesis section 3.2.3).
;;;;
;;;; Every potential instance (a component with a binding of its arguments) is made,
;;;; in the components' dependency order, whether or not it is active: the belief
;;;; universe is then complete, and what holds in a state is a matter of JTMS labels.
;;;; The JTMS is monotonic; every non-monotonic choice is an assumption the engine
;;;; enables or retracts:
;;;;   (:activation KEY)          the instance's quantitative activation holds (or it
;;;;                              has not been deactivated by a transition),
;;;;   (:mode KEY MODE)           the instance is in MODE,
;;;;   (:collection KEY VALUES)   the closed-world assumption that the collection
;;;;                              arguments hold exactly VALUES.
;;;; An instance is QUALIFIED when its entity and belief arguments and its :BELIEVES
;;;; conditions are believed; only then are its quantitative conditions decided, and
;;;; a decision is forgotten when it stops being qualified (the initial values it was
;;;; decided on belong to another state). An instance is ACTIVE when its node is IN:
;;;; qualified and its activation assumption enabled. Only active instances get a
;;;; mode and collections, and contribute equations.
;;;;
;;;; REFRESH-INSTANCE brings one instance's assumptions in line with its
;;;; prerequisites. Building refreshes every instance in order; a transition applies
;;;; the changes it is given and refreshes, in order, only the instances whose
;;;; prerequisites changed label.

(in-package #:ames.engine)

;;; Engines

(defstruct (engine (:constructor %make-engine (knowledge-base order)))
  "A model builder for a knowledge base: its components in dependency order."
  (knowledge-base nil :type knowledge-base)
  (order '() :type list))

(setf (documentation 'engine-knowledge-base 'function) "The engine's knowledge base.")

(defmethod print-object ((engine engine) stream)
  (print-unreadable-object (engine stream :type t :identity t)
    (format stream "~@[~A ~]~D component~:P"
            (knowledge-base-name (engine-knowledge-base engine))
            (length (engine-order engine)))))

(defun make-engine (knowledge-base)
  "An engine that builds models from KNOWLEDGE-BASE. It orders the components by
their qualitative data dependencies once, now: make a new engine after changing the
knowledge base. Signals COMPONENT-DEPENDENCY-CYCLE when there is no such order."
  (check-type knowledge-base knowledge-base)
  (%make-engine knowledge-base (component-order knowledge-base)))

;;; Instances

(defstruct (instance (:constructor %make-instance (key component bindings rank)))
  "A potential instance of a component: one binding of its arguments."
  (key nil)
  (component nil :type component)
  (bindings '() :type list)
  (rank 0 :type fixnum)                  ; the component's place in the order
  (node nil)                             ; believed when the instance is active
  (activation-node nil)                  ; the (:activation KEY) assumption, if any
  (supports '() :type list)              ; antecedent lists of NODE, less activation
  (activation nil)                       ; the decision: NIL, :TRUE or :FALSE
  (mode nil)                             ; the current mode's name
  (mode-nodes '() :type list)            ; alist mode name -> (:mode KEY MODE) node
  (mode-supports '() :type list)         ; alist mode name -> entry antecedent lists
  (collections nil :type list)           ; alist ?var -> values, while active
  (closure nil)                          ; the current (closure-node . belief nodes)
  (closures (make-hash-table :test #'equal))  ; (collections . belief nodes) -> closure
  (equation-justifications '() :type list)   ; justifications of equations it made
  (made (make-hash-table :test #'equal))      ; equation templates already expanded
  (expansions (make-hash-table :test #'equal))) ; expanded condition templates

(setf (documentation 'instance-key 'function)
      "The instance's key: (COMPONENT-NAME value-of-each-non-collection-argument...)."
      (documentation 'instance-component 'function) "The instance's component."
      (documentation 'instance-bindings 'function)
      "The alist (?VARIABLE . VALUE) of the instance's argument binding."
      (documentation 'instance-node 'function)
      "The JTMS node (:INSTANCE KEY), believed exactly when the instance is active."
      (documentation 'instance-mode 'function)
      "The name of the active instance's current mode (NIL without modes or when inactive)."
      (documentation 'instance-collections 'function)
      "The active instance's collection arguments: an alist (?VARIABLE . VALUES).")

(defmethod print-object ((instance instance) stream)
  (print-unreadable-object (instance stream :type t)
    (format stream "~S~:[~; active~]~@[ ~S~]" (instance-key instance)
            (instance-active-p instance) (instance-mode instance))))

(defun instance-active-p (instance)
  "True when INSTANCE is active: its node is believed."
  (ames.tms:node-in-p (instance-node instance)))

(defun instance-qualified-p (instance)
  "True when INSTANCE's qualitative prerequisites (entity and belief arguments,
:BELIEVES activation conditions) are believed."
  (some (lambda (support) (every #'ames.tms:node-in-p support))
        (instance-supports instance)))

(defun instance-equations (instance)
  "The equations INSTANCE contributes now: those it justified that hold by its
justification."
  (let ((equations '()))
    (dolist (justification (instance-equation-justifications instance))
      (when (ames.tms:justification-satisfied-p justification)
        (pushnew (ames.tms:node-datum (ames.tms:justification-consequence justification))
                 equations :test #'equal)))
    (canonical-sort equations)))

;;; Models

(defstruct (model (:constructor %make-model (engine situation jtms decider)))
  "The model of a qualitative state: every potential instance of the knowledge
base's components in a situation, with its beliefs in a JTMS."
  (engine nil :type engine)
  (situation nil :type situation)
  (jtms nil)
  (decider nil :type (or null function))
  (instance-table (make-hash-table :test #'equal))   ; key -> instance
  (instance-list '() :type list)                     ; newest first
  (by-component (make-hash-table :test #'eq))        ; name -> instances, newest first
  (belief-table (make-hash-table :test #'equal))     ; belief -> node
  (beliefs-by-head (make-hash-table :test #'eq))     ; head -> ((belief . node) ...)
  (equation-table (make-hash-table :test #'equal))   ; equation -> node
  (entity-nodes (make-hash-table :test #'eq))        ; entity name -> premise node
  (dependents (make-hash-table :test #'eq))          ; node -> instances reading it
  (collectors (make-hash-table :test #'eq))          ; belief head -> collecting components
  (given (make-hash-table :test #'equal))            ; decisions to use while building
  (basis-decisions '() :type list)
  (dirty nil)                                        ; during a transition: rank -> instances
  (pending (make-hash-table :test #'eq))
  (refreshed (make-hash-table :test #'eq)))

(setf (documentation 'model-engine 'function) "The engine that built the model."
      (documentation 'model-situation 'function) "The situation the model is of."
      (documentation 'model-jtms 'function) "The JTMS holding the model's beliefs."
      (documentation 'model-decider 'function)
      "The decider of the current state's quantitative conditions."
      (documentation 'model-basis-decisions 'function)
      "The decisions the model was built or last updated from: those given to
BUILD-MODEL, or the decisions before the last transition with its changes applied.
REBUILD-FROM-SCRATCH starts from them.")

(defmethod print-object ((model model) stream)
  (print-unreadable-object (model stream :type t :identity t)
    (format stream "~D active of ~D instance~:P"
            (count-if #'instance-active-p (model-instance-list model))
            (length (model-instance-list model)))))

(defun model-instances (model)
  "Every potential instance of MODEL, in the order they were made."
  (reverse (model-instance-list model)))

(defun model-active-instances (model)
  "MODEL's active instances, in the order they were made."
  (remove-if-not #'instance-active-p (model-instances model)))

(defun find-instance (model key)
  "The instance of MODEL whose key is KEY, or NIL."
  (values (gethash key (model-instance-table model))))

(defun believed-data (table)
  "The data of TABLE (a hash table from datum to JTMS node) whose nodes are IN, in
canonical order."
  (let ((data '()))
    (maphash (lambda (datum node)
               (when (ames.tms:node-in-p node) (push datum data)))
             table)
    (canonical-sort data)))

(defun model-equations (model)
  "The model proper: the equations believed in MODEL, in canonical order."
  (believed-data (model-equation-table model)))

(defun model-beliefs (model)
  "The qualitative assertions believed in MODEL, in canonical order."
  (believed-data (model-belief-table model)))

(defun find-node (model datum)
  "The JTMS node of MODEL standing for DATUM: a qualitative assertion, an equation,
an entity's (KIND NAME), an instance's (:INSTANCE KEY), or one of the engine's
assumptions (:ACTIVATION KEY), (:MODE KEY MODE), (:COLLECTION KEY VALUES). NIL when
there is none."
  (or (gethash datum (model-belief-table model))
      (gethash datum (model-equation-table model))
      (let ((instance (and (consp datum) (keywordp (car datum)) (consp (cdr datum))
                           (find-instance model (second datum)))))
        (and instance
             (case (first datum)
               (:instance (instance-node instance))
               (:activation (instance-activation-node instance))
               (:mode (cdr (assoc (third datum) (instance-mode-nodes instance))))
               (:collection (loop for closure being the hash-values of (instance-closures instance)
                                  when (equal datum (ames.tms:node-datum (car closure)))
                                    return (car closure))))))
      (and (consp datum) (consp (cdr datum)) (symbolp (second datum))
           (let ((node (gethash (second datum) (model-entity-nodes model))))
             (and node (equal (ames.tms:node-datum node) datum) node)))))

(defun explain (model datum &optional (stream *standard-output*))
  "Print on STREAM why DATUM (a belief, an equation, (:INSTANCE KEY)...) is or is
not believed in MODEL: its justification tree, naming the component that is the
informant of each step and the reason for each assumption. Returns the node.
Signals ENGINE-ERROR when MODEL has no node for DATUM."
  (let ((node (find-node model datum)))
    (unless node
      (error 'engine-error :datum datum :detail "The model has no belief of this datum."))
    (ames.tms:why node stream)))

;;; Termination conditions

(defstruct (termination-condition (:constructor make-termination-condition
                                      (kind instance relation change)))
  "A condition under which the state's model stops being valid: KIND is
:DEACTIVATION, :MODE-TRANSITION or :ACTIVATION; INSTANCE the instance's key;
RELATION the expanded relation in the prefix algebra; CHANGE what it stands for,
to give APPLY-TRANSITION when it fires: (:deactivate KEY), (:activate KEY) or
(:mode KEY :from MODE :to MODE)."
  (kind nil :type (member :deactivation :mode-transition :activation))
  (instance nil)
  (relation nil)
  (change nil))

(defmethod print-object ((condition termination-condition) stream)
  (print-unreadable-object (condition stream :type t)
    (format stream "~S when ~S" (termination-condition-change condition)
            (termination-condition-relation condition))))

(defun termination-condition-list (condition)
  "CONDITION as the list (KIND INSTANCE RELATION CHANGE), for comparisons."
  (list (termination-condition-kind condition) (termination-condition-instance condition)
        (termination-condition-relation condition) (termination-condition-change condition)))

;;; Template expansion

(defconstant +template-depth-limit+ 64
  "How deeply template functions may expand into one another before the engine
reports a loop.")

(defun expand-template (model instance template &key equation)
  "TEMPLATE (a condition, or with EQUATION an equation) with INSTANCE's bindings and
collections substituted and every registered template form expanded. Returns the
checked relation, or for an equation a list of equations (an expansion (AND (= ...)
...) gives several). Signals TEMPLATE-EXPANSION-ERROR when the result is not in
the algebra."
  (let* ((kb (engine-knowledge-base (model-engine model)))
         (situation (model-situation model))
         (bindings (append (instance-collections instance) (instance-bindings instance))))
    (flet ((fail (datum detail)
             (error 'template-expansion-error :datum datum :detail detail
                                              :instance (instance-key instance)
                                              :template template)))
      (labels ((walk (form depth)
                 (cond ((or (atom form) (not (proper-list-p form))) form)
                       ((operator-p (car form))
                        (cons (car form) (mapcar (lambda (x) (walk x depth)) (cdr form))))
                       (t (let ((registered (find-template kb (car form))))
                            (cond ((null registered) form)
                                  ((> depth +template-depth-limit+)
                                   (fail form "Template functions expand into one another ~
                                               without end."))
                                  (t (walk (apply (template-function registered)
                                                  situation (cdr form))
                                           (1+ depth)))))))))
        (let ((expanded (walk (substitute-bindings bindings template) 0)))
          (handler-case (check-expression expanded :kind :condition)
            (malformed-expression (condition)
              (fail expanded (format nil "The expansion is not a ~:[condition~;equation~] of ~
                                          the algebra: ~A (at ~S)."
                                     equation (ames-error-detail condition)
                                     (ames-error-datum condition)))))
          (cond ((not equation) expanded)
                ((eq (car expanded) '=) (list expanded))
                ((and (eq (car expanded) 'and)
                      (every (lambda (x) (eq (car x) '=)) (cdr expanded)))
                 (cdr expanded))
                (t (fail expanded "An equation template must expand into (= LHS RHS) or ~
                                   (AND (= ...) ...)."))))))))

(defun expanded-relation (model instance template)
  "TEMPLATE expanded for INSTANCE as a condition, memoized on its collections."
  (let ((key (cons template (instance-collections instance))))
    (multiple-value-bind (relation found) (gethash key (instance-expansions instance))
      (if found
          relation
          (setf (gethash key (instance-expansions instance))
                (expand-template model instance template))))))

;;; Deciding quantitative conditions

(defun ask-decider (model relation)
  "MODEL's decider's answer for RELATION: :TRUE, :FALSE or :UNKNOWN."
  (let ((decider (model-decider model)))
    (unless decider
      (error 'missing-decider :datum relation
                              :detail "A quantitative condition must be decided, but the ~
                                       model has no decider."))
    (let ((answer (funcall decider relation)))
      (unless (member answer '(:true :false :unknown))
        (error 'invalid-decision :datum answer
                                 :detail (format nil "The decider answered this for ~S; it ~
                                                      must answer :TRUE, :FALSE or :UNKNOWN."
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

(defun conjunction-answer (model relations answers)
  "The decider's verdict on the conjunction of RELATIONS without resolving unknowns:
:FALSE at the first false one, else :UNKNOWN if any is unknown, else :TRUE. ANSWERS
is a hash table caching each relation's answer."
  (let ((verdict :true))
    (dolist (relation relations verdict)
      (let ((answer (or (gethash relation answers)
                        (setf (gethash relation answers) (ask-decider model relation)))))
        (case answer
          (:false (return :false))
          (:unknown (setf verdict :unknown)))))))

(defun decide-activation (model instance)
  "Decide INSTANCE's activation: (values decision reason), the decision being :TRUE
or :FALSE. Uses a given decision when building, else the decider; an unknown answer
is resolved through UNDECIDED-RELATION, never guessed."
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
                   (values verdict (list :decided relations))
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
UNDECIDED-RELATION, and none or several true modes signal MODE-SELECTION-ERROR."
  (let* ((component (instance-component instance))
         (key (instance-key instance))
         (given (gethash (list :mode key) (model-given model)))
         (answers (make-hash-table :test #'equal)))
    (when (and given (find-mode component given) (mode-valid-p instance given))
      (return-from decide-mode (values given '(:given))))
    (loop
      (let ((true '()) (unknown '()))
        (dolist (mode (component-modes component))
          (let* ((relations (mapcar (lambda (template) (expanded-relation model instance template))
                                    (mode-entry-relations mode)))
                 (verdict (if (mode-valid-p instance (mode-name mode))
                              (conjunction-answer model relations answers)
                              :false)))
            (case verdict
              (:true (push (cons mode relations) true))
              (:unknown (push (cons mode relations) unknown)))))
        (cond ((= 1 (length true))
               (return (values (mode-name (car (first true)))
                               (list :decided (cdr (first true))))))
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
                 (loop for (belief . node) in (beliefs-with-head model (pattern-head pattern))
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
                  append (loop for (belief . node) in (beliefs-with-head model (pattern-head pattern))
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
        (loop for (belief . node) in (beliefs-with-head model (pattern-head pattern))
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
of an inactive one."
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

(defun model-termination-conditions (model)
  "The termination conditions of MODEL's state, as TERMINATION-CONDITION objects:
the deactivation conditions and the current mode's transition conditions of every
active instance, and the activation condition (a conjunction) of every qualified
instance that is not active. Relations are expanded for the instance."
  (let ((conditions '()))
    (dolist (instance (model-instances model) (nreverse conditions))
      (let* ((component (instance-component instance))
             (key (instance-key instance)))
        (cond ((instance-active-p instance)
               (dolist (template (component-deactivation-relations component))
                 (push (make-termination-condition
                        :deactivation key (expanded-relation model instance template)
                        (list :deactivate key))
                       conditions))
               (let ((mode (instance-mode instance)))
                 (when mode
                   (dolist (transition (mode-transitions (find-mode component mode)))
                     (push (make-termination-condition
                            :mode-transition key
                            (expanded-relation model instance (transition-relation transition))
                            (list :mode key :from mode :to (transition-target transition)))
                           conditions)))))
              ((and (component-activation-relations component)
                    (instance-qualified-p instance))
               (let ((relations (mapcar (lambda (template)
                                          (expanded-relation model instance template))
                                        (component-activation-relations component))))
                 (push (make-termination-condition
                        :activation key
                        (if (rest relations) (cons 'and relations) (first relations))
                        (list :activate key))
                       conditions))))))))

;;; Transitions

(defstruct (transition-report (:constructor make-transition-report (changes rederived)))
  "What APPLY-TRANSITION did: the CHANGES applied and the keys of the instances it
re-derived (refreshed because a prerequisite or decision changed)."
  (changes '() :type list)
  (rederived '() :type list))

(setf (documentation 'transition-report-changes 'function)
      "The changes the transition applied."
      (documentation 'transition-report-rederived 'function)
      "The keys of the instances the transition re-derived, in order.")

(defun transition-report-rederived-count (report)
  "How many instances the transition re-derived."
  (length (transition-report-rederived report)))

(defun change-instance (model change)
  "The instance CHANGE is about, after checking CHANGE's shape and that it fits
MODEL; signals INVALID-CHANGE."
  (flet ((fail (detail) (error 'invalid-change :datum change :detail detail)))
    (unless (and (proper-list-p change) (member (first change) '(:deactivate :activate :mode)))
      (fail "A change is (:DEACTIVATE KEY), (:ACTIVATE KEY) or (:MODE KEY :FROM MODE :TO MODE)."))
    (let ((instance (find-instance model (second change))))
      (unless instance (fail "The model has no instance of this key."))
      (ecase (first change)
        (:deactivate
         (unless (= 2 (length change)) (fail "A deactivation is (:DEACTIVATE KEY)."))
         (unless (instance-active-p instance) (fail "The instance is not active."))
         (unless (instance-activation-node instance)
           (fail "The instance's component has no activation or deactivation condition.")))
        (:activate
         (unless (= 2 (length change)) (fail "An activation is (:ACTIVATE KEY)."))
         (when (instance-active-p instance) (fail "The instance is already active."))
         (unless (instance-activation-node instance)
           (fail "The instance's component has no activation or deactivation condition."))
         (unless (instance-qualified-p instance)
           (fail "The instance's qualitative prerequisites are not believed.")))
        (:mode
         (unless (and (= 6 (length change)) (eq (third change) :from) (eq (fifth change) :to))
           (fail "A mode change is (:MODE KEY :FROM MODE :TO MODE)."))
         (unless (instance-active-p instance) (fail "The instance is not active."))
         (unless (eq (fourth change) (instance-mode instance))
           (fail (format nil "The instance is in mode ~S." (instance-mode instance))))
         (unless (find-mode (instance-component instance) (sixth change))
           (fail "The instance's component has no such mode."))
         (when (eq (fourth change) (sixth change))
           (fail "A mode change must lead to another mode."))))
      instance)))

(defun decisions-after (decisions changes)
  "DECISIONS (as MODEL-DECISIONS gives them) with CHANGES applied."
  (let ((decisions (copy-list decisions)))
    (dolist (change changes decisions)
      (let ((decision (ecase (first change)
                        (:deactivate (list :activation (second change) :false))
                        (:activate (list :activation (second change) :true))
                        (:mode (list :mode (second change) (sixth change))))))
        (setf decisions (cons decision
                              (remove-if (lambda (old) (and (eq (first old) (first decision))
                                                            (equal (second old)
                                                                   (second decision))))
                                         decisions)))))))

(defun apply-change (model instance change)
  "Apply CHANGE to INSTANCE: retract or enable its assumptions."
  (ecase (first change)
    (:deactivate
     (setf (instance-activation instance) :false)
     (retract model (instance-activation-node instance)))
    (:activate
     (setf (instance-activation instance) :true)
     (enable model (instance-activation-node instance) (list :transition change)))
    (:mode
     (set-mode model instance (sixth change) (list :transition change))))
  (mark-dirty model instance))

(defun apply-transition (model changes &key (decider (model-decider model)))
  "Update MODEL in place for the next qualitative state, given the CHANGES the
fired termination conditions stand for (their TERMINATION-CONDITION-CHANGE):
retract or enable the matching assumptions, then re-derive, in dependency order,
only the instances whose prerequisites changed. Everything else stays believed.
DECIDER decides the conditions of instances that become qualified; it replaces the
model's decider. Returns MODEL and a TRANSITION-REPORT.

Signals INVALID-CHANGE (before changing anything) when a change is malformed, does
not fit the model, or two changes name one instance; and, while re-deriving, the
conditions BUILD-MODEL signals."
  (let ((instances (mapcar (lambda (change) (change-instance model change)) changes)))
    (loop for (instance . rest) on instances
          for change in changes
          when (member instance rest)
            do (error 'invalid-change :datum change
                                      :detail "Two changes name this instance."))
    (let ((basis (decisions-after (model-decisions model) changes))
          (rank-count (length (engine-order (model-engine model)))))
      (setf (model-decider model) decider
            (model-basis-decisions model) basis
            (model-dirty model) (make-array rank-count :initial-element '()))
      (clrhash (model-pending model))
      (clrhash (model-refreshed model))
      (unwind-protect
           (progn
             (loop for instance in instances
                   for change in changes
                   do (apply-change model instance change))
             (loop for rank = (position-if #'identity (model-dirty model))
                   while rank
                   do (let ((instance (pop (aref (model-dirty model) rank))))
                        (remhash instance (model-pending model))
                        (setf (gethash instance (model-refreshed model)) t)
                        (refresh-instance model instance)))
             (values model
                     (make-transition-report
                      (copy-list changes)
                      (mapcar #'instance-key
                              (remove-if-not (lambda (instance)
                                               (gethash instance (model-refreshed model)))
                                             (model-instances model))))))
        (setf (model-dirty model) nil)))))

;;; Comparing models

(defun model-difference (first second)
  "What differs between the models FIRST and SECOND, compared as sets: their
equations, termination conditions, active instances with their modes, believed
assertions and decisions. NIL when they agree; else a list of entries
(WHAT :ONLY-IN-FIRST ITEMS :ONLY-IN-SECOND ITEMS)."
  (let ((differences '()))
    (flet ((compare (what items-1 items-2)
             (let ((only-1 (set-difference items-1 items-2 :test #'equal))
                   (only-2 (set-difference items-2 items-1 :test #'equal)))
               (when (or only-1 only-2)
                 (push (list what :only-in-first (canonical-sort only-1)
                                  :only-in-second (canonical-sort only-2))
                       differences))))
           (active (model)
             (mapcar (lambda (instance) (list (instance-key instance) (instance-mode instance)))
                     (model-active-instances model)))
           (terminations (model)
             (mapcar #'termination-condition-list (model-termination-conditions model))))
      (compare :equations (model-equations first) (model-equations second))
      (compare :termination-conditions (terminations first) (terminations second))
      (compare :active-instances (active first) (active second))
      (compare :beliefs (model-beliefs first) (model-beliefs second))
      (compare :decisions (model-decisions first) (model-decisions second)))
    (nreverse differences)))

(defun check-incremental (model &key (signal t))
  "Rebuild MODEL from scratch (REBUILD-FROM-SCRATCH) and compare: return NIL when
the rebuild has the same equations, termination conditions, active instances and
modes, beliefs and decisions, else the MODEL-DIFFERENCE -- after signalling
INCREMENTAL-MISMATCH with it when SIGNAL is true (the default)."
  (let ((difference (model-difference model (rebuild-from-scratch model))))
    (when (and difference signal)
      (error 'incremental-mismatch :difference difference :datum (model-basis-decisions model)
                                   :detail "The incremental model differs from the rebuild."))
    difference))
