;;;; src/engine/grammar.lisp -- DEFCOMPONENT's grammar, checked when a component is defined.

(in-package #:ames.engine)

;;; The grammar: sections, arguments, events, conditions, modes and transitions.

(defun section-body (name section)
  "The items of SECTION, checked to be a proper list."
  (unless (proper-list-p section)
    (definition-error name section "A section must be a proper list (:KEYWORD ITEM...)."))
  (cdr section))

(defun parse-argument (name spec bound declared)
  "Parse one argument SPEC given the variables BOUND and DECLARED so far. Returns
the argument and the variables it binds."
  (unless (and (consp spec) (proper-list-p spec))
    (definition-error name spec "An argument must be a list (?VARIABLE :KIND ...)."))
  (destructuring-bind (variable &rest options) spec
    (unless (and (pattern-variable-p variable) (not (anonymous-variable-p variable)))
      (definition-error name spec (format nil "An argument begins with its variable, ~
                                               a symbol such as ?BODY, not ~S." variable)))
    (when (member variable declared)
      (definition-error name spec (format nil "The argument ~S is declared twice." variable)))
    (check-plist name options spec "An argument's options")
    (ecase (argument-spec-kind name spec options)
      (:entity (parse-entity-argument name spec variable options))
      (:belief (parse-belief-argument name spec variable options))
      (:collect (parse-collect-argument name spec variable options bound)))))

(defun argument-spec-kind (name spec options)
  "The kind of the argument SPEC of NAME, from its OPTIONS: :ENTITY, :BELIEF or
:COLLECT. Signals a definition error unless it is exactly one of them."
  (let ((kinds (intersection '(:entity :belief :collect)
                             (loop for (key) on options by #'cddr collect key))))
    (unless (= 1 (length kinds))
      (definition-error name spec "An argument is exactly one of (?V :ENTITY KIND ...), ~
                                   (?V :BELIEF PATTERN) or (?V :COLLECT TEMPLATE :MATCHING ~
                                   PATTERN)."))
    (first kinds)))

(defun check-argument-options (name spec options keys)
  "Signal a definition error for the first of the OPTIONS (a plist) of the argument SPEC
of NAME whose key is not among KEYS, the options of its kind."
  (loop for (key) on options by #'cddr
        unless (member key keys)
          do (definition-error name spec
                               (format nil "~S is not an option of this kind ~
                                            of argument (allowed: ~{~S~^ ~})."
                                       key keys))))

(defun parse-entity-argument (name spec variable options)
  "Parse the argument SPEC of NAME, (VARIABLE :ENTITY KIND [:WHERE PLIST]). Returns the
argument and the variables it binds: VARIABLE and those of the :WHERE clause."
  (check-argument-options name spec options '(:entity :where))
  (let ((kind (getf options :entity)) (where (getf options :where)))
    (unless (and (symbolp kind) kind (not (pattern-variable-p kind)))
      (definition-error name spec "The entity kind after :ENTITY must be a symbol."))
    (check-plist name where spec "The :WHERE clause")
    (values (make-argument variable :entity :entity-kind kind :where where :clause spec)
            (cons variable (form-variables where)))))

(defun parse-belief-argument (name spec variable options)
  "Parse the argument SPEC of NAME, (VARIABLE :BELIEF PATTERN), VARIABLE occurring in
PATTERN. Returns the argument and the variables it binds: those of PATTERN."
  (check-argument-options name spec options '(:belief))
  (let ((pattern (getf options :belief)))
    (check-pattern name pattern spec "The pattern after :BELIEF")
    (unless (member variable (form-variables pattern))
      (definition-error name spec (format nil "The variable ~S must occur in its ~
                                               :BELIEF pattern." variable)))
    (values (make-argument variable :belief :pattern pattern :clause spec)
            (form-variables pattern))))

(defun parse-collect-argument (name spec variable options bound)
  "Parse the argument SPEC of NAME, (VARIABLE :COLLECT TEMPLATE :MATCHING PATTERN),
VARIABLE not among the variables BOUND by other arguments and TEMPLATE using only
PATTERN's variables. Returns the argument and the variables it binds: VARIABLE."
  (check-argument-options name spec options '(:collect :matching))
  (let ((pattern (getf options :matching)) (template (getf options :collect)))
    (unless (getf options :matching)
      (definition-error name spec "A :COLLECT argument needs :MATCHING PATTERN."))
    (check-pattern name pattern spec "The pattern after :MATCHING")
    (when (member variable bound)
      (definition-error name spec (format nil "The collection variable ~S is ~
                                               already bound by another argument."
                                          variable)))
    (let ((unknown (set-difference (form-variables template)
                                   (form-variables pattern))))
      (when unknown
        (definition-error name spec (format nil "The collected template uses ~
                                                 ~{~S~^, ~}, absent from the ~
                                                 :MATCHING pattern." unknown))))
    (values (make-argument variable :collection :pattern pattern :collect template
                                                :clause spec)
            (list variable))))

(defun parse-event-spec (name item bound collections &key (event-key :event))
  "Parse the event part of a condition ITEM: the plist after it holding EVENT-KEY
TEMPLATE and optionally :IMPACT TEMPLATE. Returns an EVENT-SPEC, or NIL when ITEM
names no event."
  (let ((event (getf item event-key)) (impact (getf item :impact)))
    (loop for (key) on item by #'cddr
          unless (member key (list event-key :impact :when))
            do (definition-error name item (format nil "Unknown option ~S in an event ~
                                                      condition." key)))
    (when (or event impact)
      (dolist (template (remove nil (list event impact)))
        (unless (and (consp template) (proper-list-p template) (keywordp (car template)))
          (definition-error name item "An event is a list (:KIND ARGUMENT...), such as ~
                                       (:lift-off ?body1 ?body2)."))
        (check-variables-bound name template item bound "The event" collections))
      (make-event-spec event impact))))

(defun parse-conditions (name section bound collections
                         &key allow-beliefs allow-always allow-never allow-events)
  "Parse the items of an activation, deactivation or entry SECTION: returns the
belief patterns, the relation templates (none when SECTION is NIL, absent) and, with
ALLOW-EVENTS, the EVENT-SPECs: for an activation section a single one, from an
item (:event TEMPLATE [:impact TEMPLATE]); for a deactivation section one per
relation (NIL for a bare relation), from items (:when RELATION :event TEMPLATE
[:impact TEMPLATE]). BOUND are the variables relations may use."
  (let ((items (section-body name section))
        (beliefs '()) (relations '()) (events '()) (activation-event nil))
    (dolist (item items)
      (cond ((member item '(:always :never))
             (unless (if (eq item :always) allow-always allow-never)
               (definition-error name item (format nil "~S is not allowed in this section." item)
                                 section))
             (unless (= 1 (length items))
               (definition-error name section (format nil "~S stands alone in its section."
                                                      item))))
            ((and (consp item) (eq (car item) :believes))
             (unless allow-beliefs
               (definition-error name item "Only activation and mode entry conditions may ~
                                            require beliefs: deactivation conditions are ~
                                            relations tested on the solved model." section))
             (unless (and (proper-list-p item) (= 2 (length item)))
               (definition-error name item "A belief condition is (:BELIEVES PATTERN)." section))
             (check-pattern name (second item) item "The pattern after :BELIEVES")
             (push (second item) beliefs))
            ((and (consp item) (eq (car item) :event))
             (unless (eq allow-events :activation)
               (definition-error name item "(:EVENT ...) names the event of an activation ~
                                            section; a deactivation names its event with ~
                                            (:WHEN RELATION :EVENT ...)." section))
             (when activation-event
               (definition-error name item "An activation section names one event." section))
             (check-plist name item item "An event item")
             (setf activation-event (parse-event-spec name item bound collections)))
            ((and (consp item) (eq (car item) :when))
             (unless (eq allow-events :deactivation)
               (definition-error name item "(:WHEN RELATION :EVENT ...) belongs in a ~
                                            deactivation section." section))
             (check-plist name item item "A deactivation condition")
             (let ((relation (getf item :when)))
               (check-relation-template name relation item "A condition")
               (check-variables-bound name relation item bound "The condition" collections)
               (push relation relations)
               (push (parse-event-spec name item bound collections) events)))
            (t (check-relation-template name item item "A condition")
               (check-variables-bound name item item bound "The condition" collections)
               (push item relations)
               (push nil events))))
    (values (nreverse beliefs) (nreverse relations)
            (if (eq allow-events :activation) activation-event (nreverse events)))))

(defun parse-assertions (name section bound collections)
  "Parse an :ASSERT section: belief patterns whose variables are all in BOUND (none
when SECTION is NIL, absent)."
  (let ((patterns (section-body name section)))
    (dolist (pattern patterns)
      (check-pattern name pattern pattern "An assertion")
      (check-variables-bound name pattern pattern bound "The assertion" collections))
    patterns))

(defun parse-equations (name section bound)
  "Parse an :EQUATIONS section: equation templates whose variables are in BOUND (none
when SECTION is NIL, absent)."
  (let ((equations (section-body name section)))
    (dolist (equation equations)
      (check-relation-template name equation equation "An equation" :equation t)
      (check-variables-bound name equation equation bound "The equation"))
    equations))

(defun split-sections (name sections allowed &key repeatable)
  "Check that each of SECTIONS is (KEY ...) with KEY among ALLOWED, and that only
the REPEATABLE keys repeat. Returns an alist (KEY . sections)."
  (let ((found '()))
    (dolist (section sections)
      (unless (and (consp section) (keywordp (car section)))
        (definition-error name section (format nil "Expected a section (~{~S~^ | ~} ...)."
                                               allowed)))
      (unless (member (car section) allowed)
        (definition-error name section (format nil "Unknown section ~S (expected one of ~
                                                    ~{~S~^ ~})." (car section) allowed)))
      (let ((entry (assoc (car section) found)))
        (cond ((null entry) (push (list (car section) section) found))
              ((member (car section) repeatable) (push section (cdr entry)))
              (t (definition-error name section (format nil "The section ~S appears twice."
                                                        (car section)))))))
    (mapcar (lambda (entry) (cons (car entry) (reverse (cdr entry)))) found)))

(defun section (key sections)
  "The single section KEY of the alist SECTIONS, or NIL."
  (second (assoc key sections)))

(defun parse-transition (name clause all-bound collections)
  "Parse (:TRANSITION :TO MODE :WHEN RELATION) into a TRANSITION."
  (check-plist name (cdr clause) clause "A transition")
  (loop for (key) on (cdr clause) by #'cddr
        unless (member key '(:to :when :event :impact))
          do (definition-error name clause (format nil "Unknown transition option ~S." key)))
  (let ((target (getf (cdr clause) :to)) (relation (getf (cdr clause) :when)))
    (unless (and target relation)
      (definition-error name clause "A transition is (:TRANSITION :TO MODE :WHEN RELATION ~
                                     [:EVENT TEMPLATE] [:IMPACT TEMPLATE])."))
    (check-relation-template name relation clause "A transition condition")
    (check-variables-bound name relation clause all-bound "The transition condition"
                           collections)
    (make-transition target relation clause
                     (parse-event-spec name (list* :when relation
                                                   (loop for (k v) on (cdr clause) by #'cddr
                                                         when (member k '(:event :impact))
                                                           append (list k v)))
                                       all-bound collections))))

(defun parse-mode (name clause key-bound all-bound collections)
  "Parse a (:MODE NAME CLAUSE...) section into a MODE (transition targets are
checked by PARSE-COMPONENT)."
  (unless (and (proper-list-p clause) (>= (length clause) 2))
    (definition-error name clause "A mode is (:MODE NAME CLAUSE...)."))
  (let ((mode-name (second clause)))
    (unless (and (symbolp mode-name) mode-name (not (pattern-variable-p mode-name)))
      (definition-error name clause (format nil "A mode's name must be a symbol, not ~S."
                                            mode-name)))
    (let ((parts (split-sections name (cddr clause)
                                 '(:entry :assert :equations :transition)
                                 :repeatable '(:transition))))
      (multiple-value-bind (entry-beliefs entry-relations)
          (parse-conditions name (section :entry parts) key-bound collections
                            :allow-beliefs t :allow-always t)
        (make-mode mode-name
                   :entry-p (and (section :entry parts) t)
                   :entry-beliefs entry-beliefs :entry-relations entry-relations
                   :assertions (parse-assertions name (section :assert parts)
                                                 key-bound collections)
                   :equations (parse-equations name (section :equations parts) all-bound)
                   :transitions (loop for transition in (cdr (assoc :transition parts))
                                      collect (parse-transition name transition all-bound
                                                                collections)))))))

(defun parse-component (name documentation sections)
  "Build a COMPONENT from data: its NAME (a symbol), DOCUMENTATION (a string) and
SECTIONS, the body of a DEFCOMPONENT after the docstring (see DEFCOMPONENT for the
grammar). Signals COMPONENT-DEFINITION-ERROR naming the clause at fault."
  (unless (and (symbolp name) name (not (keywordp name)) (not (pattern-variable-p name)))
    (definition-error name name "A component's name must be a symbol."))
  (unless (stringp documentation)
    (definition-error name documentation "A component needs a docstring after its options."))
  (unless (proper-list-p sections)
    (definition-error name sections "The sections must form a proper list."))
  (let* ((parts (split-sections name sections
                                '(:arguments :activation :deactivation :watch :assert :equations :mode)
                                :repeatable '(:mode)))
         (arguments '()) (bound '()) (declared '()))
    (when (section :arguments parts)
      (dolist (spec (section-body name (section :arguments parts)))
        (multiple-value-bind (argument binds) (parse-argument name spec bound declared)
          (push argument arguments)
          (push (argument-variable argument) declared)
          (setf bound (union bound binds)))))
    (setf arguments (nreverse arguments))
    (let* ((collections (loop for a in arguments
                              when (eq (argument-kind a) :collection)
                                collect (argument-variable a)))
           (key-bound (set-difference bound collections))
           (all-bound bound))
      (multiple-value-bind (activation-beliefs activation-relations activation-event)
          (parse-conditions name (section :activation parts) key-bound collections
                            :allow-beliefs t :allow-always t :allow-events :activation)
        (multiple-value-bind (ignored deactivation-relations deactivation-events)
            (parse-conditions name (section :deactivation parts)
                              all-bound collections :allow-never t :allow-events :deactivation)
          (declare (ignore ignored))
         (let ((modes (loop for clause in (cdr (assoc :mode parts))
                           collect (parse-mode name clause key-bound all-bound collections))))
          (check-modes name modes (cdr (assoc :mode parts)))
          (multiple-value-bind (watch-relations watch-events)
              (parse-watches name (section :watch parts) all-bound collections)
          (%make-component
           :name name :documentation documentation :arguments arguments
           :activation-beliefs activation-beliefs
           :activation-relations activation-relations
           :activation-event activation-event
           :deactivation-relations deactivation-relations
           :deactivation-events deactivation-events
           :watch-relations watch-relations :watch-events watch-events
           :assertions (parse-assertions name (section :assert parts) key-bound collections)
           :equations (parse-equations name (section :equations parts) all-bound)
           :modes modes
           :definition sections))))))))

(defun parse-watches (name section bound collections)
  "Parse a :WATCH section, items (:WHEN RELATION :EVENT TEMPLATE): (values RELATIONS
EVENT-SPECS), one of each per item (none when SECTION is NIL, absent). A watch names
its event: it changes nothing in the model, so the event is all it stands for."
  (multiple-value-bind (beliefs relations events)
      (parse-conditions name section bound collections :allow-events :deactivation)
    (declare (ignore beliefs))
    (loop for event in events
          for item in (section-body name section)
          unless (and event (event-spec-event event))
            do (definition-error name item "A watch is (:WHEN RELATION :EVENT TEMPLATE)."
                                 section))
    (values relations events)))

(defun check-modes (name modes clauses)
  "Check MODES (parsed from CLAUSES) together: unique names, transitions to other
declared modes, and entry conditions wherever there is a choice."
  (loop for (mode . rest) on modes
        for clause in clauses
        do (when (find (mode-name mode) rest :key #'mode-name)
             (definition-error name clause (format nil "The mode ~S is defined twice."
                                                   (mode-name mode))))
           (when (and (cdr modes) (not (mode-entry-p mode)))
             (definition-error name clause "With several modes, each mode needs (:ENTRY ...) ~
                                            conditions to choose it by."))
           (dolist (transition (mode-transitions mode))
             (let ((target (transition-target transition)))
               (unless (find target modes :key #'mode-name)
                 (definition-error name (transition-clause transition)
                                   (format nil "The transition goes to ~S, which is not a ~
                                                mode of ~S." target name)))
               (when (eq target (mode-name mode))
                 (definition-error name (transition-clause transition)
                                   "A transition must lead to another mode."))))))
