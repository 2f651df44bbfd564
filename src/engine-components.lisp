;;;; src/engine-components.lisp -- model components as data, DEFCOMPONENT's grammar and
;;;; checks, knowledge bases, template functions and the dependency order.

(in-package #:ames.engine)

;;; The data

(defstruct (argument (:constructor make-argument
                         (variable kind &key entity-kind where pattern collect clause)))
  "One argument of a model component: VARIABLE bound to an entity of ENTITY-KIND
whose properties match WHERE (:ENTITY), to a belief matching PATTERN (:BELIEF), or
to the canonically sorted values of COLLECT over every believed match of PATTERN
(:COLLECTION)."
  (variable nil :type symbol)
  (kind :entity :type (member :entity :belief :collection))
  (entity-kind nil :type symbol)
  (where '() :type list)
  (pattern nil)
  (collect nil)
  (clause nil))

(defstruct (transition (:constructor make-transition (target relation clause)))
  "A mode transition condition: when RELATION becomes true, the instance enters the
mode TARGET."
  (target nil :type symbol)
  (relation nil)
  (clause nil))

(defstruct (mode (:constructor make-mode (name &key entry-p entry-beliefs entry-relations
                                                 assertions equations transitions)))
  "A mode of a component: its entry conditions (belief patterns that must be
believed and relations decided on the initial values), qualitative ASSERTIONS,
quantitative EQUATIONS and TRANSITIONS."
  (name nil :type symbol)
  (entry-p nil :type boolean)             ; true when an (:entry ...) clause was given
  (entry-beliefs '() :type list)
  (entry-relations '() :type list)
  (assertions '() :type list)
  (equations '() :type list)
  (transitions '() :type list))

(defstruct (component (:constructor %make-component))
  "A model component (thesis section 3.2.2), as data. Build one with
PARSE-COMPONENT or DEFCOMPONENT."
  (name nil :type symbol)
  (documentation nil :type (or null string))
  (arguments '() :type list)
  (activation-beliefs '() :type list)     ; patterns, existential
  (activation-relations '() :type list)   ; decided on the initial values
  (deactivation-relations '() :type list) ; termination conditions
  (assertions '() :type list)             ; in every mode
  (equations '() :type list)              ; in every mode
  (modes '() :type list)
  (definition nil))                       ; the sections as written

(setf (documentation 'component-name 'function) "The component's name (a symbol)."
      (documentation 'component-documentation 'function) "The component's docstring."
      (documentation 'component-definition 'function)
      "The sections of the component as they were written.")

(defmethod print-object ((component component) stream)
  (print-unreadable-object (component stream :type t)
    (prin1 (component-name component) stream)))

(defun component-argument-variables (component)
  "The declared variables of COMPONENT's arguments, in order."
  (mapcar #'argument-variable (component-arguments component)))

(defun component-key-variables (component)
  "The argument variables whose values make an instance's key: all but collections."
  (loop for argument in (component-arguments component)
        unless (eq (argument-kind argument) :collection)
          collect (argument-variable argument)))

(defun component-collection-arguments (component)
  "COMPONENT's :COLLECTION arguments."
  (remove :collection (component-arguments component)
          :key #'argument-kind :test-not #'eq))

(defun component-mode-names (component)
  "The names of COMPONENT's modes, in order (NIL when it has none)."
  (mapcar #'mode-name (component-modes component)))

(defun find-mode (component name)
  "COMPONENT's mode called NAME, or NIL."
  (find name (component-modes component) :key #'mode-name))

(defun component-read-patterns (component)
  "Every belief pattern COMPONENT reads: belief and collection arguments,
activation and mode entry conditions."
  (append (loop for argument in (component-arguments component)
                when (member (argument-kind argument) '(:belief :collection))
                  collect (argument-pattern argument))
          (component-activation-beliefs component)
          (loop for mode in (component-modes component)
                append (mode-entry-beliefs mode))))

(defun component-asserted-patterns (component)
  "Every belief pattern COMPONENT asserts, in any mode."
  (append (component-assertions component)
          (loop for mode in (component-modes component) append (mode-assertions mode))))

;;; The grammar, checked

(defun definition-error (name clause detail &optional section)
  "Signal COMPONENT-DEFINITION-ERROR for the component NAME about CLAUSE."
  (error 'component-definition-error :component name :datum clause :detail detail
                                     :section section))

(defun proper-list-p (x)
  "True when X is a proper list."
  (alexandria:proper-list-p x))

(defun check-plist (name plist clause what)
  "Check that PLIST alternates keywords and values without repeating a key."
  (unless (and (proper-list-p plist) (evenp (length plist)))
    (definition-error name clause (format nil "~A must be a property list: ~
                                               keywords alternating with values." what)))
  (let ((seen '()))
    (loop for (key) on plist by #'cddr
          do (unless (keywordp key)
               (definition-error name clause (format nil "~A: ~S is not a keyword." what key)))
             (when (member key seen)
               (definition-error name clause (format nil "~A names ~S twice." what key)))
             (push key seen))))

(defun check-pattern (name pattern clause what)
  "Check that PATTERN has the shape of a belief: (HEAD POSITIONAL... KEY VALUE...)."
  (unless (and (consp pattern) (proper-list-p pattern))
    (definition-error name clause (format nil "~A must be a list (HEAD ARGUMENT...)." what)))
  (let ((head (pattern-head pattern)))
    (unless (and (symbolp head) head (not (keywordp head)) (not (pattern-variable-p head)))
      (definition-error name clause (format nil "~A must begin with a symbol naming ~
                                                 the kind of belief, not ~S." what head)))
    (when (operator-p head)
      (definition-error name clause (format nil "~A begins with ~S, an operator of the ~
                                                 algebra: that is a relation, not a belief."
                                            what head))))
  (check-plist name (property-part pattern) clause
               (format nil "The keyword part of ~A" what)))

(defun template-call-p (form)
  "True when FORM is a list whose head is not an operator of the algebra: a call of
a registered template, or a quantity term."
  (and (consp form) (symbolp (car form)) (car form) (not (keywordp (car form)))
       (not (pattern-variable-p (car form))) (not (operator-p (car form)))))

(defun expression-skeleton (form)
  "FORM with variables and template calls replaced by placeholder variables, so that
CHECK-EXPRESSION can check the algebra around them."
  (cond ((pattern-variable-p form) 'template-variable)
        ((template-call-p form) 'template-value)
        ((and (consp form) (operator-p (car form)) (proper-list-p form))
         (cons (car form) (mapcar #'expression-skeleton (cdr form))))
        (t form)))

(defun check-relation-template (name form clause what &key (equation nil))
  "Check a quantitative condition (or, with EQUATION, an equation) template: an
algebra relation over variables and template calls, or a single template call."
  (cond ((template-call-p form)
         (unless (proper-list-p form)
           (definition-error name clause (format nil "~A is not a proper list." what))))
        ((not (and (consp form) (proper-list-p form)
                   (if equation
                       (eq (car form) '=)
                       (or (relation-operator-p (car form)) (logical-operator-p (car form))))))
         (definition-error name clause
                           (if equation
                               (format nil "~A must be an equation (= LHS RHS) or a ~
                                            template call." what)
                               (format nil "~A must be a relation such as (< X Y), a ~
                                            combination of relations with AND, OR, NOT, ~
                                            or a template call." what))))
        (t (handler-case (check-expression (expression-skeleton form) :kind :condition)
             (malformed-expression (condition)
               (definition-error name clause
                                 (format nil "~A is not in the algebra: ~A (at ~S)."
                                         what (ames-error-detail condition)
                                         (ames-error-datum condition))))))))

(defun check-variables-bound (name form clause bound what &optional collections)
  "Check that every variable of FORM is among BOUND. COLLECTIONS are the collection
variables, named in the report when FORM uses one where it may not."
  (let* ((unbound (set-difference (form-variables form) bound))
         (collections (intersection unbound collections)))
    (when unbound
      (definition-error name clause
                        (format nil "~A uses ~{~S~^, ~}, which no argument binds~
                                     ~:[~; (a collection is known only once the ~
                                     instance is active: equations, deactivation and ~
                                     transition conditions may use it)~]."
                                what unbound collections)))))

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
    (let ((kinds (intersection '(:entity :belief :collect)
                               (loop for (key) on options by #'cddr collect key))))
      (unless (= 1 (length kinds))
        (definition-error name spec "An argument is exactly one of (?V :ENTITY KIND ...), ~
                                     (?V :BELIEF PATTERN) or (?V :COLLECT TEMPLATE :MATCHING ~
                                     PATTERN)."))
      (flet ((allow (&rest keys)
               (loop for (key) on options by #'cddr
                     unless (member key keys)
                       do (definition-error name spec
                                            (format nil "~S is not an option of this kind ~
                                                         of argument (allowed: ~{~S~^ ~})."
                                                    key keys)))))
        (ecase (first kinds)
          (:entity
           (allow :entity :where)
           (let ((kind (getf options :entity)) (where (getf options :where)))
             (unless (and (symbolp kind) kind (not (pattern-variable-p kind)))
               (definition-error name spec "The entity kind after :ENTITY must be a symbol."))
             (check-plist name where spec "The :WHERE clause")
             (values (make-argument variable :entity :entity-kind kind :where where :clause spec)
                     (cons variable (form-variables where)))))
          (:belief
           (allow :belief)
           (let ((pattern (getf options :belief)))
             (check-pattern name pattern spec "The pattern after :BELIEF")
             (unless (member variable (form-variables pattern))
               (definition-error name spec (format nil "The variable ~S must occur in its ~
                                                        :BELIEF pattern." variable)))
             (values (make-argument variable :belief :pattern pattern :clause spec)
                     (form-variables pattern))))
          (:collect
           (allow :collect :matching)
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
                     (list variable)))))))))

(defun parse-conditions (name section bound collections
                         &key allow-beliefs allow-always allow-never)
  "Parse the items of an activation, deactivation or entry SECTION: returns the
belief patterns and the relation templates (none when SECTION is NIL, absent). BOUND
are the variables relations may use."
  (let ((items (section-body name section)) (beliefs '()) (relations '()))
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
            (t (check-relation-template name item item "A condition")
               (check-variables-bound name item item bound "The condition" collections)
               (push item relations))))
    (values (nreverse beliefs) (nreverse relations))))

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
        unless (member key '(:to :when))
          do (definition-error name clause (format nil "Unknown transition option ~S." key)))
  (let ((target (getf (cdr clause) :to)) (relation (getf (cdr clause) :when)))
    (unless (and target relation)
      (definition-error name clause "A transition is (:TRANSITION :TO MODE :WHEN RELATION)."))
    (check-relation-template name relation clause "A transition condition")
    (check-variables-bound name relation clause all-bound "The transition condition"
                           collections)
    (make-transition target relation clause)))

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
                                '(:arguments :activation :deactivation :assert :equations :mode)
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
      (multiple-value-bind (activation-beliefs activation-relations)
          (parse-conditions name (section :activation parts) key-bound collections
                            :allow-beliefs t :allow-always t)
        (let ((deactivation-relations
                (nth-value 1 (parse-conditions name (section :deactivation parts)
                                               all-bound collections :allow-never t)))
              (modes (loop for clause in (cdr (assoc :mode parts))
                           collect (parse-mode name clause key-bound all-bound collections))))
          (check-modes name modes (cdr (assoc :mode parts)))
          (%make-component
           :name name :documentation documentation :arguments arguments
           :activation-beliefs activation-beliefs
           :activation-relations activation-relations
           :deactivation-relations deactivation-relations
           :assertions (parse-assertions name (section :assert parts) key-bound collections)
           :equations (parse-equations name (section :equations parts) all-bound)
           :modes modes
           :definition sections))))))

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

(defmacro defcomponent (name &optional options documentation &body sections)
  "Define the model component NAME and register it in a knowledge base.

  (defcomponent NAME (:knowledge-base KB-FORM)
    \"Docstring: what piece of knowledge this is.\"
    (:arguments ARGUMENT...)
    (:activation CONDITION... | :always)
    (:deactivation RELATION... | :never)
    (:assert PATTERN...)             ; qualitative assertions, in every mode
    (:equations EQUATION...)         ; quantitative assertions, in every mode
    (:mode MODE-NAME                 ; zero or more modes, mutually exclusive
      (:entry CONDITION...)          ; needed when there are several modes
      (:assert PATTERN...)
      (:equations EQUATION...)
      (:transition :to MODE-NAME :when RELATION) ...)
    ...)

KB-FORM is evaluated: it gives the KNOWLEDGE-BASE to register in. Every section is
optional; with no :ACTIVATION the component is always active once its arguments are
bound, with no :DEACTIVATION it never ends.

ARGUMENT is one of
  (?VAR :entity KIND [:where PLIST])  ?VAR is each entity of KIND in the situation
                                      whose properties match PLIST (an absent
                                      property reads as NIL); variables in PLIST are
                                      bound too: (?c :entity simple-contact :where
                                      (:observer ?b1 :obstacle ?b2)).
  (?VAR :belief PATTERN)              a belief matching PATTERN; ?VAR occurs in it,
                                      the other variables are bound as well.
  (?VAR :collect TEMPLATE             ?VAR is the list of TEMPLATE's values over every
        :matching PATTERN)            believed match of PATTERN, in canonical order
                                      (all the forces on a body). It is known only
                                      once the instance is active, so only equations,
                                      deactivation and transition conditions may use it.
Arguments are bound left to right; a variable bound earlier must match again
(a join). An instance is identified by its KEY: (NAME value-of-each-non-collection
?VAR...).

A PATTERN is a belief with variables: (HEAD POSITIONAL... :KEY VALUE...). It
matches a belief with the same head and positional elements and at least the
properties it names, in any order: (force ?f :on ?b) matches (force (gravity w)
:type gravity :from earth :on w). ?_ matches anything.

CONDITION is (:believes PATTERN) -- qualitative: some belief matching PATTERN must
be believed; variables bound nowhere else are existential -- or a RELATION --
quantitative: decided on the state's initial values by the caller's decider, which
answers :true, :false or :unknown (the last signals UNDECIDED-RELATION).

RELATION and EQUATION are templates in the prefix algebra of AMES.BASE:
(< (normal-magnitude ?c) 0), (= (* (mass ?b) (acc ?b :y)) (sum-of ?forces :y)).
Variables are replaced by their values, then every form whose head is registered
in the knowledge base with REGISTER-TEMPLATE is replaced by what its function
returns (it gets the SITUATION and the form's arguments as data); other forms
(acc ?b :y) are quantity terms. A template form may also stand alone for the whole
relation or equation: (:activation (on-contact ?c)).

Deactivation and transition relations are termination conditions: the engine never
decides them; they are tested on the solved model, so they may mention quantities
that are not state variables (a normal force).

Example (the thesis's figure 2-8, Newton's second law):

  (defcomponent newtons-second-law (:knowledge-base *mechanics*)
    \"The free-body sum of every force on a body equals its mass times its
  acceleration in the fixed frame.\"
    (:arguments (?body :entity body :where (:fixed nil))
                (?forces :collect ?f :matching (force ?f :on ?body)))
    (:activation :always)
    (:deactivation :never)
    (:equations (= (sum-of ?forces :x) (* (mass ?body) (acc ?body :x)))
                (= (sum-of ?forces :y) (* (mass ?body) (acc ?body :y)))))

with SUM-OF and MASS registered as template functions. Every clause is checked
when the form is macroexpanded: a malformed one signals COMPONENT-DEFINITION-ERROR
naming it. The expansion only registers the data object that PARSE-COMPONENT
builds from the same sections; it returns the component."
  (unless (and (proper-list-p options) (= 2 (length options))
               (eq (first options) :knowledge-base))
    (definition-error name options "After the name come the options (:KNOWLEDGE-BASE KB-FORM)."))
  ;; all the checking, at macroexpansion time
  (parse-component name documentation sections)
  `(register-component ,(second options)
                       (parse-component ',name ,documentation ',sections)))

;;; Knowledge bases and template functions

(defstruct (template (:constructor make-template (head function documentation)))
  "A registered template function: forms headed by HEAD are replaced, at
instantiation, by (APPLY FUNCTION SITUATION ARGUMENTS)."
  (head nil :type symbol)
  (function nil :type function)
  (documentation nil :type (or null string)))

(setf (documentation 'template-function 'function)
      "The function of a registered template: (SITUATION &rest ARGUMENTS) -> form."
      (documentation 'template-documentation 'function)
      "The documentation given to REGISTER-TEMPLATE.")

(defstruct (knowledge-base (:constructor %make-knowledge-base (name documentation)))
  "A named set of model components and template functions."
  (name nil)
  (documentation nil :type (or null string))
  (components '() :type list)          ; in order of first definition
  (templates (make-hash-table :test #'eq) :type hash-table)
  (order nil))                         ; cached COMPONENT-ORDER, NIL when stale

(setf (documentation 'knowledge-base-name 'function) "The knowledge base's name."
      (documentation 'knowledge-base-components 'function)
      "The knowledge base's components, in the order they were first defined.")

(defmethod print-object ((kb knowledge-base) stream)
  (print-unreadable-object (kb stream :type t :identity t)
    (format stream "~@[~A ~]~D component~:P" (knowledge-base-name kb)
            (length (knowledge-base-components kb)))))

(defun make-knowledge-base (&key name documentation)
  "A new, empty knowledge base. Several can coexist; each test can build its own."
  (%make-knowledge-base name documentation))

(defun register-component (knowledge-base component)
  "Add COMPONENT to KNOWLEDGE-BASE, replacing (in place) a component of the same
name. Returns COMPONENT."
  (check-type component component)
  (let ((tail (member (component-name component) (knowledge-base-components knowledge-base)
                      :key #'component-name)))
    (if tail
        (setf (car tail) component)
        (setf (knowledge-base-components knowledge-base)
              (append (knowledge-base-components knowledge-base) (list component)))))
  (setf (knowledge-base-order knowledge-base) nil)
  component)

(defun remove-component (knowledge-base name)
  "Remove the component NAME from KNOWLEDGE-BASE; true when there was one."
  (let ((component (find-component knowledge-base name nil)))
    (when component
      (setf (knowledge-base-components knowledge-base)
            (remove component (knowledge-base-components knowledge-base))
            (knowledge-base-order knowledge-base) nil)
      t)))

(defun find-component (knowledge-base name &optional (errorp t))
  "The component NAME of KNOWLEDGE-BASE. When there is none, signal
UNKNOWN-COMPONENT if ERRORP, else return NIL."
  (or (find name (knowledge-base-components knowledge-base) :key #'component-name)
      (and errorp
           (error 'unknown-component :datum name
                                     :detail (format nil "The knowledge base ~@[~A ~]has no ~
                                                          component of this name."
                                                     (knowledge-base-name knowledge-base))))))

(defun register-template (knowledge-base head function &key documentation)
  "Register FUNCTION as the template function of HEAD in KNOWLEDGE-BASE: in
conditions and equations, a form (HEAD ARG...) is replaced by (FUNCALL FUNCTION
SITUATION ARG...), where the ARGs are the form's arguments after variable
substitution, as data (not expanded). The result is expanded again, so it may
contain other template forms. FUNCTION must depend only on the situation and its
arguments. HEAD must be a symbol that is not an operator of the algebra. Replaces
an earlier registration. Returns HEAD."
  (unless (and (symbolp head) head (not (keywordp head)) (not (operator-p head))
               (not (pattern-variable-p head)))
    (error 'engine-error :datum head
                         :detail "A template head must be a symbol that is not an operator."))
  (check-type function function)
  (setf (gethash head (knowledge-base-templates knowledge-base))
        (make-template head function documentation))
  head)

(defun find-template (knowledge-base head)
  "The TEMPLATE registered for HEAD in KNOWLEDGE-BASE, or NIL."
  (and (symbolp head) (gethash head (knowledge-base-templates knowledge-base))))

;;; The order of instantiation

(defun component-dependencies (knowledge-base)
  "An alist (COMPONENT-NAME . NAMES): for each component, the components whose
assertions it may read (through belief and collection arguments and :BELIEVES
conditions), so that they must be instantiated before it."
  (let ((components (knowledge-base-components knowledge-base)))
    (loop for reader in components
          collect (cons (component-name reader)
                        (loop for writer in components
                              when (some (lambda (read)
                                           (some (lambda (asserted)
                                                   (patterns-may-match-p asserted read))
                                                 (component-asserted-patterns writer)))
                                         (component-read-patterns reader))
                                collect (component-name writer))))))

(defun find-cycle (dependencies)
  "A list of names forming a cycle in DEPENDENCIES (an alist name -> names it
depends on), or NIL."
  (let ((state (make-hash-table :test #'eq)))
    (labels ((visit (name path)
               (case (gethash name state)
                 (:done nil)
                 (:active (return-from find-cycle
                            (reverse (cons name (ldiff path (member name path))))))
                 (t (setf (gethash name state) :active)
                    (dolist (next (cdr (assoc name dependencies)))
                      (visit next (cons name path)))
                    (setf (gethash name state) :done)
                    nil))))
      (dolist (entry dependencies) (visit (car entry) '())))))

(defun component-order (knowledge-base)
  "KNOWLEDGE-BASE's components in an order where every component comes after all
the components whose assertions it may read (ties keep the definition order).
Signals COMPONENT-DEPENDENCY-CYCLE, naming the components, when there is none."
  (or (knowledge-base-order knowledge-base)
      (setf (knowledge-base-order knowledge-base)
            (let* ((dependencies (component-dependencies knowledge-base))
                   (cycle (find-cycle dependencies)))
              (when cycle
                (error 'component-dependency-cycle :components cycle :datum cycle))
              (let ((placed '()) (remaining (knowledge-base-components knowledge-base)))
                (loop while remaining
                      do (let ((next (find-if (lambda (component)
                                                (subsetp (cdr (assoc (component-name component)
                                                                     dependencies))
                                                         placed))
                                              remaining)))
                           (push (component-name next) placed)
                           (setf remaining (remove next remaining))))
                (mapcar (lambda (name) (find-component knowledge-base name))
                        (reverse placed)))))))
