;;;; src/engine/instances.lisp -- engines, instances, models, termination conditions and
;;;; template expansion; the design of model building (thesis section 3.2.3).
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
  (instance-table (make-datum-table))                ; key -> instance
  (instance-list '() :type list)                     ; newest first
  (by-component (make-hash-table :test #'eq))        ; name -> instances, newest first
  (belief-table (make-datum-table))                  ; belief -> node
  (beliefs-by-head (make-hash-table :test #'eq))     ; head -> ((belief . node) ...)
  (belief-index (make-datum-table))                  ; (head place value) -> ((belief . node) ...)
  (equation-table (make-datum-table))                ; equation -> node
  (entity-nodes (make-hash-table :test #'eq))        ; entity name -> premise node
  (dependents (make-hash-table :test #'eq))          ; node -> instances reading it
  (collectors (make-hash-table :test #'eq))          ; belief head -> collecting components
  (given (make-datum-table))                         ; decisions to use while building
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
                                      (kind instance relation change &optional event impact)))
  "A condition under which the state's model stops being valid: KIND is
:DEACTIVATION, :MODE-TRANSITION, :ACTIVATION or :WATCH; INSTANCE the instance's key;
RELATION the expanded relation in the prefix algebra; CHANGE what it stands for,
to give APPLY-TRANSITION when it fires: (:deactivate KEY), (:activate KEY) or
(:mode KEY :from MODE :to MODE), NIL for a watch (it ends the state with its event and
changes no decision: the next state is the same model from its new start). EVENT is the event the owning component says the
condition is, its variables replaced, e.g. (:lift-off particle sphere), or NIL when
the component names none; IMPACT the event it is instead when it is reached at a
non-zero rate (an impulsive event), or NIL."
  (kind nil :type (member :deactivation :mode-transition :activation :watch))
  (instance nil)
  (relation nil)
  (change nil)
  (event nil)
  (impact nil))

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
