;;;; src/scenario.lisp -- scenario objects, and the validator that turns a scenario form into one.
;;;;
;;;; PARSE-SCENARIO takes the s-expression of one scenario (read from a file by
;;;; src/scenario-reader.lisp, or quoted at the REPL in any package) and returns a
;;;; SCENARIO, or signals a SCENARIO-ERROR naming the clause or body at fault. The
;;;; language is ../shared/design/scenario-language.md; this validator follows it and
;;;; decides what it leaves open as follows:
;;;;
;;;; - Words of the language (SCENARIO, PARAMETERS, BODY, POINT, POLYGON, T, NIL...) and
;;;;   operators are recognised by their symbol names, whatever package the form's
;;;;   symbols live in; keywords must be keywords. User names (parameters, bodies,
;;;;   forces) are kept as the user's own symbols, and every reference to one is
;;;;   replaced by the declared symbol, so that a REPL form in CL-USER and a file read
;;;;   into AMES-SCENARIO give scenarios that differ only in the home package of the
;;;;   user's names. Shapes are rewritten with the AMES-SCENARIO words (POINT,
;;;;   POLYGON...), operators with the CL operator symbols of the algebra.
;;;; - Names are compared by symbol name: MP and FOO::MP are the same name. Reserved,
;;;;   so no parameter, body or force may be called so: PI, T, NIL, TAU (the state's
;;;;   local time), keywords, and the algebra's operator names (+ SIN EXPT AND ...).
;;;; - The description string is optional; it must come right after the name.
;;;; - Clauses may come in any order; several PARAMETERS clauses are merged. GRAVITY
;;;;   and SIMULATE may appear at most once. Without GRAVITY there is no field.
;;;;   A scenario needs at least one BODY.
;;;; - A parameter spec may also be a bare symbol (a parameter with no assumption).
;;;;   In (> P EXPR) and its kin, P must be the parameter being declared; EXPR may use
;;;;   any declared parameter. (:value NUMBER) takes a literal real number; it may
;;;;   appear once per parameter.
;;;; - Expressions may also use EXP and LOG (the algebra has them). A constant divisor
;;;;   that is exactly zero is rejected.
;;;; - A body's :fixed takes T or NIL. A fixed body may have a :mass (kept, unused);
;;;;   its :velocity, if given, must be (0 0); its :position defaults to (0 0).
;;;;   A constant mass must be positive. Forces may act on fixed bodies (to no effect).
;;;; - (arc ...) as a shape takes :solid :inside or :outside; the default is :inside,
;;;;   the side to the left of its counter-clockwise direction, as for SEGMENT and
;;;;   OUTLINE. An arc's :to must exceed its :from by at most 2 pi (checked when
;;;;   both are numbers). Arc pieces of an OUTLINE take no :solid.
;;;; - (simulate) takes :states, a positive integer, and :until, an expression that
;;;;   must be positive when it is a number. Either may be absent: NIL means no limit
;;;;   from the scenario (the simulator applies its own). Both: whichever comes first.
;;;; - (query ...) clauses are kept as data, unchecked, for the simulator.
;;;; - Bounds: a form nested more than +DEEPEST-FORM+ deep or holding more than
;;;;   +LARGEST-FORM+ conses (or circular) is rejected before anything else.
;;;;
;;;; Checks done here without Maxima, when numbers decide them: contradictory constant
;;;; bounds on one parameter ((> x 2) with (< x 1), (> a (/ pi 2)) with (< a 1)),
;;;; default values that violate any assumption, non-positive constant radii and
;;;; masses, clockwise or degenerate polygons with numeric vertices, coincident points,
;;;; outline pieces with numeric ends that do not meet. Everything symbolic is left to
;;;; the semantic checks of src/scenario-semantics.lisp (Maxima and geometry).

(in-package #:ames)

(defconstant +deepest-form+ 100
  "The deepest nesting of lists accepted in a scenario form.")

(defconstant +largest-form+ 100000
  "The most conses accepted in one scenario form.")

;;; ------------------------------------------------------------------------------------
;;; The objects a validated scenario is made of

(defclass scenario ()
  ((name :initarg :name :reader scenario-name
         :documentation "The scenario's name, a symbol.")
   (description :initarg :description :initform nil :reader scenario-description
                :documentation "The one-line description string, or NIL.")
   (parameters :initarg :parameters :initform '() :reader scenario-parameters
               :documentation "The SCENARIO-PARAMETERs, in order of declaration.")
   (gravity :initarg :gravity :initform nil :reader scenario-gravity
            :documentation "The strength of the terrestrial field (pointing -y), an
expression, or NIL when the scenario has no gravity.")
   (bodies :initarg :bodies :initform '() :reader scenario-bodies
           :documentation "The SCENARIO-BODYs, in order of declaration.")
   (forces :initarg :forces :initform '() :reader scenario-forces
           :documentation "The SCENARIO-FORCEs, in order of declaration.")
   (states :initarg :states :initform nil :reader scenario-states
           :documentation "Stop after this many states (a positive integer), or NIL.")
   (until :initarg :until :initform nil :reader scenario-until
          :documentation "Stop at this global time (an expression), or NIL.")
   (queries :initarg :queries :initform '() :reader scenario-queries
            :documentation "The arguments of each (query ...) clause, as data.")
   (source :initarg :source :initform nil :reader scenario-source
           :documentation "Where the form came from (\"FILE, line N\"), or NIL.")
   (form :initarg :form :initform nil :reader scenario-form
         :documentation "The form the scenario was validated from."))
  (:documentation "A validated scenario: parameters, gravity, bodies, forces, when to
stop, and queries. Every expression in it is in the prefix algebra, over its declared
parameters, PI and numbers."))

(defclass scenario-parameter ()
  ((name :initarg :name :reader scenario-parameter-name
         :documentation "The parameter's symbol.")
   (assumptions :initarg :assumptions :initform '() :reader scenario-parameter-assumptions
                :documentation "What is known of it: :POSITIVE, :NONNEGATIVE, or
relations (> NAME EXPR), (< ...), (>= ...), (<= ...) with the algebra's operators.")
   (value :initarg :value :initform nil :reader scenario-parameter-value
          :documentation "The default numeric value, or NIL."))
  (:documentation "A symbolic constant of a scenario."))

(defclass scenario-body ()
  ((name :initarg :name :reader scenario-body-name
         :documentation "The body's symbol.")
   (shape :initarg :shape :reader scenario-body-shape
          :documentation "The shape form, in the body's frame, with AMES-SCENARIO's
words (POINT, (POLYGON (X Y) ...), ...) and checked expressions.")
   (mass :initarg :mass :initform nil :reader scenario-body-mass
         :documentation "The mass, an expression; NIL for a fixed body without one.")
   (position :initarg :position :reader scenario-body-position
             :documentation "The reference point's initial position (X Y).")
   (velocity :initarg :velocity :reader scenario-body-velocity
             :documentation "The initial velocity (VX VY); (0 0) for a fixed body.")
   (fixed-p :initarg :fixed-p :initform nil :reader scenario-body-fixed-p
            :documentation "True when the body is glued to the fixed frame."))
  (:documentation "A rigid body of a scenario (it translates and does not rotate)."))

(defclass scenario-force ()
  ((name :initarg :name :reader scenario-force-name
         :documentation "The force's symbol.")
   (body :initarg :body :reader scenario-force-body
         :documentation "The symbol of the body it acts on.")
   (value :initarg :value :reader scenario-force-value
          :documentation "The constant force (FX FY) in the fixed frame."))
  (:documentation "A constant external force on one body."))

(defun scenario-p (object)
  "True when OBJECT is a validated SCENARIO."
  (typep object 'scenario))

(defmethod print-object ((scenario scenario) stream)
  (print-unreadable-object (scenario stream :type t)
    (prin1 (scenario-name scenario) stream)))

(defmethod print-object ((parameter scenario-parameter) stream)
  (print-unreadable-object (parameter stream :type t)
    (prin1 (scenario-parameter-name parameter) stream)))

(defmethod print-object ((body scenario-body) stream)
  (print-unreadable-object (body stream :type t)
    (prin1 (scenario-body-name body) stream)))

(defmethod print-object ((force scenario-force) stream)
  (print-unreadable-object (force stream :type t)
    (prin1 (scenario-force-name force) stream)))

(defun same-name-p (a b)
  "True when the symbols A and B have the same name (names are compared by name)."
  (string= (symbol-name a) (symbol-name b)))

(defun find-scenario-parameter (name scenario)
  "The SCENARIO-PARAMETER of SCENARIO named NAME (compared by name), or NIL."
  (find name (scenario-parameters scenario) :key #'scenario-parameter-name :test #'same-name-p))

(defun find-scenario-body (name scenario)
  "The SCENARIO-BODY of SCENARIO named NAME (compared by name), or NIL."
  (find name (scenario-bodies scenario) :key #'scenario-body-name :test #'same-name-p))

(defun find-scenario-force (name scenario)
  "The SCENARIO-FORCE of SCENARIO named NAME (compared by name), or NIL."
  (find name (scenario-forces scenario) :key #'scenario-force-name :test #'same-name-p))

(defun scenario-moving-bodies (scenario)
  "The bodies of SCENARIO that are not fixed."
  (remove-if #'scenario-body-fixed-p (scenario-bodies scenario)))

(defun scenario-fixed-bodies (scenario)
  "The bodies of SCENARIO glued to the fixed frame."
  (remove-if-not #'scenario-body-fixed-p (scenario-bodies scenario)))

(defun assumption-relation (name assumption)
  "The relation of the algebra that ASSUMPTION about the parameter NAME states."
  (case assumption
    (:positive (make-relation '> name 0))
    (:nonnegative (make-relation '>= name 0))
    (t assumption)))

(defun scenario-assumption-relations (scenario)
  "The parameter assumptions of SCENARIO as relations of the prefix algebra, in order
of declaration, e.g. ((> mp 0) (> a 0) (< a (/ pi 2))): the facts to hand to the
Maxima bridge's WITH-ASSUMPTIONS. Default :values are not assumptions."
  (loop for parameter in (scenario-parameters scenario)
        nconc (loop with name = (scenario-parameter-name parameter)
                    for assumption in (scenario-parameter-assumptions parameter)
                    collect (assumption-relation name assumption))))

(defun scenario-parameter-values (scenario)
  "The default values of SCENARIO's parameters that have one, as an alist (SYMBOL .
NUMBER)."
  (loop for parameter in (scenario-parameters scenario)
        when (scenario-parameter-value parameter)
          collect (cons (scenario-parameter-name parameter)
                        (scenario-parameter-value parameter))))

(defparameter +shape-kinds+
  '((ames-scenario:point . :point) (ames-scenario:circle . :circle)
    (ames-scenario:polygon . :polygon) (ames-scenario:outline . :outline)
    (ames-scenario:segment . :segment) (ames-scenario:arc . :arc)
    (ames-scenario:half-plane . :half-plane))
  "Each shape word of the language with the keyword SHAPE-KIND returns for it.")

(defun shape-kind (shape)
  "The kind of a validated SHAPE: :POINT, :CIRCLE, :POLYGON, :OUTLINE, :SEGMENT, :ARC
or :HALF-PLANE."
  (cdr (assoc (if (consp shape) (car shape) shape) +shape-kinds+)))

;;; ------------------------------------------------------------------------------------
;;; The validation in progress: where we are, for the conditions, and the names declared

(defstruct (validation (:constructor make-validation (form source)))
  "What the validator knows while it checks one form."
  (form nil)
  (source nil)
  (name nil)                 ; the scenario's name, once known
  (location nil)             ; "body WEDGE", "clause GRAVITY"...
  (clause nil)               ; the clause being checked
  (names (make-hash-table :test 'equal))) ; symbol name -> (KIND . SYMBOL)

(defun reject-because (validation class cause datum control &rest arguments)
  "Signal a scenario error of CLASS at VALIDATION's current place, wrapping CAUSE (or
NIL), with DATUM at fault (the clause, or the whole form, when DATUM is NIL)."
  (error class
         :scenario (validation-name validation)
         :location (validation-location validation)
         :clause (validation-clause validation)
         :source (validation-source validation)
         :cause cause
         :datum (or datum (validation-clause validation) (validation-form validation)
                    "NIL (an empty form)")
         :detail (with-standard-io-syntax
                   (let ((*print-readably* nil) (*print-level* 4) (*print-length* 8)
                         (*package* (form-package (validation-form validation))))
                     (apply #'format nil control arguments)))))

(defun reject (validation class datum control &rest arguments)
  "Signal a scenario error of CLASS at VALIDATION's current place, DATUM at fault."
  (apply #'reject-because validation class nil datum control arguments))

(defun enter (validation location clause)
  "Note that VALIDATION now checks CLAUSE, at LOCATION (a string)."
  (setf (validation-location validation) location
        (validation-clause validation) clause))

(defstruct (shown (:constructor show (form)))
  "A form to print in a condition's detail: written with ~A, it prints as PRIN1 would,
under the print settings REJECT-BECAUSE binds (short, in the form's package)."
  form)

(defmethod print-object ((shown shown) stream)
  (prin1 (shown-form shown) stream))

;;; ------------------------------------------------------------------------------------
;;; Words, names and operators, by name

(defun named-p (x name)
  "True when X is a symbol whose name is NAME."
  (and (symbolp x) (string= (symbol-name x) name)))

(defun keyword-named-p (x name)
  "True when X is the keyword named NAME."
  (and (keywordp x) (string= (symbol-name x) name)))

(defparameter +algebra-operators+
  (append (mapcar #'car +arithmetic-operators+) +relation-operators+ +logical-operators+)
  "Every operator symbol of the prefix algebra.")

(defun algebra-operator-named (x)
  "The algebra's operator symbol with X's name, or NIL."
  (and (symbolp x)
       (find (symbol-name x) +algebra-operators+ :key #'symbol-name :test #'string=)))

(defun reserved-name-p (symbol)
  "True when SYMBOL's name may not name a parameter, body or force."
  (or (keywordp symbol)
      (member (symbol-name symbol) '("PI" "T" "NIL" "TAU") :test #'string=)
      (algebra-operator-named symbol)))

(defun language-word (x words)
  "The symbol of WORDS (AMES-SCENARIO's words) with X's name, or NIL."
  (and (symbolp x) (not (keywordp x))
       (find (symbol-name x) words :key #'symbol-name :test #'string=)))

(defparameter +clause-words+
  '(ames-scenario:parameters ames-scenario:gravity ames-scenario:body
    ames-scenario:force ames-scenario:simulate ames-scenario:query)
  "The clauses of a scenario.")

(defun check-name (validation name what)
  "Signal unless NAME may name a WHAT (a string: \"parameter\"...); return NAME."
  (cond ((not (symbolp name))
         (reject validation 'scenario-syntax-error name
                 "a ~A's name must be a symbol, not ~A" what (show name)))
        ((reserved-name-p name)
         (reject validation 'scenario-syntax-error name
                 "~A cannot name a ~A: keywords, PI, T, NIL, TAU and the operators' ~
                  names are reserved" (show name) what))
        (t name)))

(defun declare-name (validation name kind)
  "Record that NAME (already checked) names a KIND (:PARAMETER, :BODY or :FORCE).
Signals DUPLICATE-NAME-ERROR when the name is taken."
  (let* ((key (symbol-name name))
         (previous (gethash key (validation-names validation))))
    (when previous
      (reject validation 'duplicate-name-error name
              "~A is declared twice (already a ~(~A~)); parameters, bodies and forces ~
               share one namespace" (show name) (car previous)))
    (setf (gethash key (validation-names validation)) (cons kind name))))

(defun declared (validation name)
  "The declaration (KIND . SYMBOL) of the name NAME, or NIL."
  (and (symbolp name) (gethash (symbol-name name) (validation-names validation))))

;;; ------------------------------------------------------------------------------------
;;; Size, lists and keyword arguments

(defun check-form-size (validation form)
  "Signal SCENARIO-SYNTAX-ERROR when FORM nests deeper than +DEEPEST-FORM+ or holds
more than +LARGEST-FORM+ conses (which a circular form always does)."
  (let ((conses 0))
    (labels ((walk (x depth)
               (when (> depth +deepest-form+)
                 (reject validation 'scenario-syntax-error form
                         "the form is nested more than ~D deep" +deepest-form+))
               (loop while (consp x)
                     do (when (> (incf conses) +largest-form+)
                          (reject validation 'scenario-syntax-error form
                                  "the form holds more than ~D conses, or is circular"
                                  +largest-form+))
                        (walk (car x) (1+ depth))
                        (setf x (cdr x)))))
      (walk form 0))))

(defun proper-list-p (x)
  "True when X is a proper list (circular and dotted lists are not)."
  (alexandria:proper-list-p x))

(defun checked-keywords (validation list allowed what &key (class 'scenario-syntax-error))
  "LIST, a property list of keyword arguments of WHAT, checked: a proper list of
even length, each key one of ALLOWED (keywords), none twice. Returns it as an alist.
Signals CLASS (or DUPLICATE-CLAUSE-ERROR for a repeated key)."
  (unless (proper-list-p list)
    (reject validation class list "the arguments of ~A are not a proper list" what))
  (unless (evenp (length list))
    (reject validation class list
            "~A takes keyword arguments in pairs (~{~S~^ ~}); one has no value"
            what allowed))
  (loop for (key value) on list by #'cddr
        for known = (and (keywordp key) (find key allowed))
        do (cond ((not (keywordp key))
                  (reject validation class key
                          "~A where ~A expects a keyword (~{~S~^ ~})"
                          (show key) what allowed))
                 ((not known)
                  (reject validation class key
                          "~S is not a keyword of ~A; its keywords are ~{~S~^ ~}"
                          key what allowed))
                 ((member known seen)
                  (reject validation 'duplicate-clause-error key
                          "~S is given twice in ~A" key what)))
        collect known into seen
        collect (cons known value) into alist
        finally (return alist)))

(defun keyword-value (key alist &optional default)
  "The value of KEY in the keyword ALIST, or DEFAULT; second value true when present."
  (let ((entry (assoc key alist)))
    (if entry (values (cdr entry) t) (values default nil))))

;;; ------------------------------------------------------------------------------------
;;; Expressions

(defun canonical-atom (validation x)
  "The canonical form of the atom X in an expression: a number, PI or the declared
symbol of a parameter. Signals for anything else."
  (cond ((realp x)
         (unless (finite-real-p x)
           (reject validation 'scenario-expression-error x
                   "~A is not a finite real number" (show x)))
         x)
        ((numberp x)
         (reject validation 'scenario-expression-error x
                 "~A is not a real number" (show x)))
        ((not (symbolp x))
         (reject validation 'scenario-expression-error x
                 "~A is not a number or a parameter" (show x)))
        ((or (null x) (keywordp x) (named-p x "T"))
         (reject validation 'scenario-expression-error x
                 "~A is not a number or a parameter" (show x)))
        ((named-p x "PI") 'pi)
        (t (let ((declaration (declared validation x)))
             (cond ((null declaration)
                    (if (algebra-operator-named x)
                        (reject validation 'scenario-expression-error x
                                "the operator ~A stands where a value is expected"
                                (show x))
                        (reject validation 'undeclared-symbol-error x
                                "~A is not a declared parameter (declare it in ~
                                 (parameters ...))" (show x))))
                   ((eq (car declaration) :parameter) (cdr declaration))
                   (t (reject validation 'undeclared-symbol-error x
                              "~A names a ~(~A~), not a parameter; only parameters, PI ~
                               and numbers may appear in an expression"
                              (show x) (car declaration))))))))

(defun check-divisions (validation expression)
  "Signal SCENARIO-EXPRESSION-ERROR when EXPRESSION divides by a constant zero."
  (when (consp expression)
    (when (eq (car expression) '/)
      (dolist (divisor (if (rest (cdr expression)) (cddr expression) (cdr expression)))
        (let ((value (expression-value divisor)))
          (when (and value (zerop value))
            (reject validation 'scenario-expression-error expression
                    "~A divides by zero" (show expression))))))
    (dolist (argument (cdr expression))
      (check-divisions validation argument))))

(defun checked-expression (validation x)
  "X as a canonical arithmetic expression of the algebra over the declared
parameters, PI and numbers: operators become the algebra's symbols, parameter names
their declared symbols. Signals SCENARIO-EXPRESSION-ERROR or UNDECLARED-SYMBOL-ERROR."
  (labels ((walk (y)
             (cond ((atom y) (canonical-atom validation y))
                   ((not (proper-list-p y))
                    (reject validation 'scenario-expression-error y
                            "~A is not a proper list" (show y)))
                   (t (let ((operator (algebra-operator-named (car y))))
                        (cond ((null operator)
                               (reject validation 'scenario-expression-error y
                                       "~A is not an operator of the algebra (+ - * / ~
                                        expt sqrt exp log sin cos tan asin acos atan)"
                                       (show (car y))))
                              ((not (arithmetic-operator-p operator))
                               (reject validation 'scenario-expression-error y
                                       "~A is a condition where a quantity is expected"
                                       (show y)))
                              (t (cons operator (mapcar #'walk (cdr y))))))))))
    (let ((expression (walk x)))
      (handler-case (check-expression expression :kind :arithmetic :allow-terms nil)
        (malformed-expression (condition)
          (reject-because validation 'scenario-expression-error condition
                          (ames-error-datum condition) "~A"
                          (ames-error-detail condition))))
      (check-divisions validation expression)
      expression)))

(defun checked-vector (validation x what &key (class 'scenario-syntax-error))
  "X, a list (X Y) of two expressions (WHAT names it), with both checked."
  (unless (and (proper-list-p x) (= (length x) 2))
    (reject validation class x "~A must be a list (X Y) of two expressions, not ~A"
            what (show x)))
  (mapcar (lambda (coordinate) (checked-expression validation coordinate)) x))

(defun check-positive-constant (validation expression what class)
  "Signal CLASS when EXPRESSION is a number that is not positive."
  (multiple-value-bind (value exact) (expression-value expression)
    (when (and value (member (compare-values value exact 0 t) '(:less :equal)))
      (reject validation class expression "~A must be positive, not ~A" what (show expression)))))

;;; ------------------------------------------------------------------------------------
;;; Parameters

(defun parameter-spec-name (spec)
  "The name in a parameter SPEC (SYMBOL or (SYMBOL ASSUMPTION ...)), or SPEC itself."
  (if (consp spec) (car spec) spec))

(defparameter +bound-operators+ '(> < >= <=)
  "The relations an assumption may state.")

(defun checked-assumption (validation name assumption)
  "ASSUMPTION about the parameter NAME, canonical: :POSITIVE, :NONNEGATIVE or
(REL NAME EXPR). (:value N) is handled by the caller."
  (flet ((bad ()
           (reject validation 'scenario-syntax-error assumption
                   "~A is not an assumption; an assumption is :positive, :nonnegative, ~
                    (> ~A EXPR), (< ~A EXPR), (>= ~A EXPR), (<= ~A EXPR) or (:value NUMBER)"
                   (show assumption) (show name) (show name) (show name) (show name))))
    (cond ((keyword-named-p assumption "POSITIVE") :positive)
          ((keyword-named-p assumption "NONNEGATIVE") :nonnegative)
          ((not (and (consp assumption) (proper-list-p assumption))) (bad))
          ((not (find (algebra-operator-named (first assumption)) +bound-operators+)) (bad))
          ((/= (length assumption) 3) (bad))
          ((not (and (symbolp (second assumption)) (second assumption)
                     (same-name-p (second assumption) name)))
           (reject validation 'scenario-syntax-error assumption
                   "an assumption about ~A must have the form (~A ~A EXPR)"
                   (show name) (show (first assumption)) (show name)))
          (t (make-relation (algebra-operator-named (first assumption)) name
                            (checked-expression validation (third assumption)))))))

(defun checked-parameter (validation spec)
  "The SCENARIO-PARAMETER that SPEC, (SYMBOL ASSUMPTION ...) or SYMBOL, declares."
  (let ((name (cdr (declared validation (parameter-spec-name spec))))
        (assumptions '())
        (value nil))
    (enter validation (format nil "parameter ~A" (symbol-name name)) spec)
    (dolist (assumption (if (consp spec) (rest spec) '()))
      (if (and (consp assumption) (keyword-named-p (first assumption) "VALUE"))
          (progn
            (when value
              (reject validation 'duplicate-clause-error assumption
                      "~A has two default values" (show name)))
            (unless (and (proper-list-p assumption) (= (length assumption) 2)
                         (realp (second assumption)) (finite-real-p (second assumption)))
              (reject validation 'scenario-expression-error assumption
                      "a default value is (:value NUMBER) with a finite real NUMBER, not ~A"
                      (show assumption)))
            (setf value (second assumption)))
          (push (checked-assumption validation name assumption) assumptions)))
    (make-instance 'scenario-parameter :name name :assumptions (nreverse assumptions)
                                       :value value)))

(defun constant-bounds (parameter)
  "The bounds that PARAMETER's assumptions put on it with a numeric value: a list of
(SIDE VALUE EXACT STRICT ASSUMPTION), SIDE :LOWER or :UPPER."
  (loop with name = (scenario-parameter-name parameter)
        for assumption in (scenario-parameter-assumptions parameter)
        for relation = (assumption-relation name assumption)
        for operator = (first relation)
        append (multiple-value-bind (value exact) (expression-value (relation-rhs relation))
                 (and value
                      (list (list (if (member operator '(> >=)) :lower :upper)
                                  value exact (and (member operator '(> <)) t)
                                  assumption))))))

(defun check-parameter-bounds (validation parameter)
  "Signal CONTRADICTORY-ASSUMPTIONS-ERROR when two numeric bounds of PARAMETER
exclude each other (a (> x 2) with a (< x 1))."
  (let ((bounds (constant-bounds parameter)))
    (dolist (lower (remove :upper bounds :key #'first))
      (dolist (upper (remove :lower bounds :key #'first))
        (destructuring-bind (side-l low low-exact low-strict low-assumption) lower
          (declare (ignore side-l))
          (destructuring-bind (side-u high high-exact high-strict high-assumption) upper
            (declare (ignore side-u))
            (let ((order (compare-values low low-exact high high-exact)))
              (when (or (eq order :greater)
                        (and (eq order :equal) (or low-strict high-strict)))
                (reject validation 'contradictory-assumptions-error
                        (list low-assumption high-assumption)
                        "the assumptions ~A and ~A on ~A cannot both hold"
                        (show low-assumption) (show high-assumption)
                        (show (scenario-parameter-name parameter)))))))))))

(defun check-default-values (validation parameters)
  "Signal CONTRADICTORY-ASSUMPTIONS-ERROR when the default :values of PARAMETERS
violate one of their assumptions (decided where every parameter involved has one)."
  (let ((bindings (loop for parameter in parameters
                        when (scenario-parameter-value parameter)
                          collect (cons (scenario-parameter-name parameter)
                                        (scenario-parameter-value parameter)))))
    (dolist (parameter parameters)
      (let ((name (scenario-parameter-name parameter)))
        (dolist (assumption (scenario-parameter-assumptions parameter))
          (let ((relation (assumption-relation name assumption)))
            (multiple-value-bind (lhs lhs-exact) (expression-value (relation-lhs relation) bindings)
              (multiple-value-bind (rhs rhs-exact) (expression-value (relation-rhs relation) bindings)
                (when (and lhs rhs
                           (eq (relation-holds-p (first relation) lhs lhs-exact rhs rhs-exact)
                               :false))
                  (enter validation (format nil "parameter ~A" (symbol-name name)) nil)
                  (reject validation 'contradictory-assumptions-error assumption
                          "the default value ~A of ~A violates its assumption ~A"
                          lhs (show name) (show assumption)))))))))))

;;; ------------------------------------------------------------------------------------
;;; Shapes

(defparameter +shape-words+
  (mapcar #'car +shape-kinds+)
  "The words that begin a shape form.")

(defun shape-word (x)
  "The AMES-SCENARIO shape word named like X, or NIL."
  (language-word x +shape-words+))

(defun shape-reject (validation datum control &rest arguments)
  "Signal SCENARIO-SHAPE-ERROR."
  (apply #'reject validation 'scenario-shape-error datum control arguments))

(defun checked-point (validation x what)
  "X, a point (X Y) of a shape, checked."
  (checked-vector validation x what :class 'scenario-shape-error))

(defun numeric-point (point)
  "The numeric coordinates of POINT as (values X Y EXACT), or NIL."
  (multiple-value-bind (x x-exact) (expression-value (first point))
    (multiple-value-bind (y y-exact) (expression-value (second point))
      (and x y (values x y (and x-exact y-exact))))))

(defun points-coincide-p (a b)
  "True when the points A and B are the same form, or numerically the same."
  (or (equal a b)
      (multiple-value-bind (ax ay a-exact) (numeric-point a)
        (multiple-value-bind (bx by b-exact) (numeric-point b)
          (and ax bx
               (eq (compare-values ax a-exact bx b-exact) :equal)
               (eq (compare-values ay a-exact by b-exact) :equal))))))

(defun check-distinct-points (validation shape a b)
  "Signal SCENARIO-SHAPE-ERROR when the points A and B of SHAPE coincide."
  (when (points-coincide-p a b)
    (shape-reject validation shape "the points ~A and ~A coincide" (show a) (show b))))

(defun checked-polygon (validation shape)
  "(polygon (X Y) ...) checked: three vertices or more, no vertex repeated next to
itself, counter-clockwise when the vertices are numbers."
  (let ((vertices (loop for vertex in (rest shape)
                        for i from 1
                        collect (checked-point validation vertex
                                               (format nil "vertex ~D of the polygon" i)))))
    (when (< (length vertices) 3)
      (shape-reject validation shape "a polygon needs three vertices or more"))
    (loop for (a b) on (append vertices (list (first vertices)))
          while b
          do (check-distinct-points validation shape a b))
    (let ((area 0) (exact t))
      (loop for (a b) on (append vertices (list (first vertices)))
            while b
            do (multiple-value-bind (ax ay a-exact) (numeric-point a)
                 (multiple-value-bind (bx by b-exact) (numeric-point b)
                   (unless (and ax bx) (return-from checked-polygon
                                         (cons 'ames-scenario:polygon vertices)))
                   (setf exact (and exact a-exact b-exact))
                   (incf area (- (* ax by) (* bx ay))))))
      (case (compare-values area exact 0 t)
        (:less (shape-reject validation shape
                             "the polygon's vertices run clockwise; list them counter-clockwise"))
        (:equal (shape-reject validation shape "the polygon has no area"))))
    (cons 'ames-scenario:polygon vertices)))

(defun checked-arc (validation shape &key piece)
  "(arc :center (CX CY) :radius R :from A1 :to A2 [:solid :inside/:outside]) checked
and completed with its :solid side (default :inside); with PIECE true (a piece of an
outline), without :solid."
  (let* ((what (if piece "an arc piece of an outline" "an arc"))
         (arguments (checked-keywords validation (rest shape)
                                      (if piece
                                          '(:center :radius :from :to)
                                          '(:center :radius :from :to :solid))
                                      what :class 'scenario-shape-error)))
    (dolist (key '(:center :radius :from :to))
      (unless (assoc key arguments)
        (shape-reject validation shape "~A needs ~S" what key)))
    (let ((center (checked-point validation (keyword-value :center arguments) "the arc's :center"))
          (radius (checked-expression validation (keyword-value :radius arguments)))
          (from (checked-expression validation (keyword-value :from arguments)))
          (to (checked-expression validation (keyword-value :to arguments)))
          (solid (keyword-value :solid arguments :inside)))
      (unless (member solid '(:inside :outside))
        (shape-reject validation shape ":solid takes :inside or :outside, not ~A" (show solid)))
      (check-positive-constant validation radius "the arc's radius" 'scenario-shape-error)
      (multiple-value-bind (a1 a1-exact) (expression-value from)
        (multiple-value-bind (a2 a2-exact) (expression-value to)
          (when (and a1 a2)
            (unless (eq (compare-values a2 a2-exact a1 a1-exact) :greater)
              (shape-reject validation shape
                            "the arc's :to must exceed its :from (it runs counter-clockwise)"))
            (when (eq (compare-values (- a2 a1) (and a1-exact a2-exact) (* 2 pi) nil) :greater)
              (shape-reject validation shape "the arc turns more than a full circle")))))
      (append (list 'ames-scenario:arc :center center :radius radius :from from :to to)
              (unless piece (list :solid solid))))))

(defun arc-end-point (arc angle-key)
  "The numeric point of ARC (a checked arc) at its ANGLE-KEY (:FROM or :TO) end, as
a list (X Y NIL) (NIL: not exact), or NIL when not numeric."
  (destructuring-bind (cx cy) (getf (rest arc) :center)
    (let* ((radius (getf (rest arc) :radius))
           (angle (getf (rest arc) angle-key))
           (x (expression-value `(+ ,cx (* ,radius (cos ,angle)))))
           (y (expression-value `(+ ,cy (* ,radius (sin ,angle))))))
      (and x y (list x y nil)))))

(defun piece-end (piece end)
  "The numeric point (X Y EXACT) where the checked outline PIECE starts (END :START)
or ends (:END), or NIL when it is not numeric."
  (if (eq (first piece) 'ames-scenario:line)
      (multiple-value-bind (x y exact) (numeric-point (if (eq end :start) (second piece) (third piece)))
        (and x (list x y exact)))
      (arc-end-point piece (if (eq end :start) :from :to))))

(defun numeric-points-differ-p (a b)
  "True when the numeric points A and B, each (X Y EXACT), are clearly apart."
  (destructuring-bind (ax ay a-exact) a
    (destructuring-bind (bx by b-exact) b
      (and (or (member (compare-values ax a-exact bx b-exact) '(:less :greater))
               (member (compare-values ay a-exact by b-exact) '(:less :greater)))
           t))))

(defun checked-outline (validation shape)
  "(outline PIECE ...) checked: line and arc pieces, end to end where numbers tell."
  (when (null (rest shape))
    (shape-reject validation shape "an outline needs at least one piece"))
  (let ((pieces
          (loop for piece in (rest shape)
                for i from 1
                collect (let ((kind (and (consp piece) (proper-list-p piece)
                                         (language-word (car piece)
                                                        '(ames-scenario:line ames-scenario:arc)))))
                          (case kind
                            (ames-scenario:line
                             (unless (= (length piece) 3)
                               (shape-reject validation piece "a line piece is (line (X1 Y1) (X2 Y2))"))
                             (let ((a (checked-point validation (second piece) "a line's start"))
                                   (b (checked-point validation (third piece) "a line's end")))
                               (check-distinct-points validation piece a b)
                               (list 'ames-scenario:line a b)))
                            (ames-scenario:arc (checked-arc validation piece :piece t))
                            (t (shape-reject validation piece
                                             "piece ~D of the outline is not (line ...) or (arc ...)"
                                             i)))))))
    (loop for (previous next) on (append pieces (list (first pieces)))
          while next
          do (let ((end (piece-end previous :end))
                   (start (piece-end next :start)))
               (when (and end start (numeric-points-differ-p end start))
                 (shape-reject validation shape
                               "the outline's pieces do not meet end to end: ~A ends at ~
                                (~A ~A) but ~A starts at (~A ~A)" (show previous)
                               (first end) (second end) (show next)
                               (first start) (second start)))))
    (cons 'ames-scenario:outline pieces)))

(defun checked-shape (validation x)
  "The shape form X checked and rewritten with AMES-SCENARIO's words. Signals
SCENARIO-SHAPE-ERROR for a bad form (and the expression errors for its coordinates)."
  (let ((kinds "point, (circle R), (polygon (X Y) ...), (outline PIECE ...), ~
                (segment (X1 Y1) (X2 Y2)), (arc :center (CX CY) :radius R :from A1 :to A2) ~
                or (half-plane (X1 Y1) (X2 Y2))"))
    (cond ((and (atom x) (eq (shape-word x) 'ames-scenario:point)) 'ames-scenario:point)
          ((not (and (consp x) (proper-list-p x) (shape-word (car x))))
           (shape-reject validation x "~A is not a shape; a shape is ~A" (show x) kinds))
          (t
           (ecase (shape-word (car x))
             (ames-scenario:point
              (shape-reject validation x "a point shape is the bare word POINT"))
             (ames-scenario:circle
              (unless (= (length x) 2)
                (shape-reject validation x "a circle is (circle R)"))
              (let ((radius (checked-expression validation (second x))))
                (check-positive-constant validation radius "a circle's radius"
                                         'scenario-shape-error)
                (list 'ames-scenario:circle radius)))
             (ames-scenario:polygon (checked-polygon validation x))
             (ames-scenario:outline (checked-outline validation x))
             ((ames-scenario:segment ames-scenario:half-plane)
              (unless (= (length x) 3)
                (shape-reject validation x "~(~A~) takes two points: (~:*~(~A~) (X1 Y1) (X2 Y2))"
                              (shape-word (car x))))
              (let ((a (checked-point validation (second x) "the first point"))
                    (b (checked-point validation (third x) "the second point")))
                (check-distinct-points validation x a b)
                (list (shape-word (car x)) a b)))
             (ames-scenario:arc (checked-arc validation x)))))))

;;; ------------------------------------------------------------------------------------
;;; Bodies, forces, gravity, simulate

(defun zero-vector-p (vector)
  "True when the checked VECTOR is numerically (0 0)."
  (every (lambda (coordinate)
           (let ((value (expression-value coordinate))) (and value (zerop value))))
         vector))

(defun checked-body (validation clause)
  "The SCENARIO-BODY that the clause (body NAME :shape ... ) declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "body ~A" (symbol-name name))))
    (enter validation what clause)
    (let* ((arguments (checked-keywords validation (cddr clause)
                                        '(:shape :mass :position :velocity :fixed) what))
           (fixed (multiple-value-bind (value present) (keyword-value :fixed arguments)
                    (cond ((not present) nil)
                          ((named-p value "T") t)
                          ((named-p value "NIL") nil)
                          (t (reject validation 'scenario-syntax-error value
                                     ":fixed takes T or NIL, not ~A" (show value))))))
           (missing (remove-if (lambda (key) (assoc key arguments))
                               (if fixed '(:shape) '(:shape :mass :position :velocity)))))
      (when missing
        (reject validation 'missing-property-error clause
                "the body has no ~{~S~^, ~}~:[~; (a body that is not :fixed needs ~
                 :mass, :position and :velocity)~]" missing (not fixed)))
      (let ((shape (checked-shape validation (keyword-value :shape arguments)))
            (mass (multiple-value-bind (mass present) (keyword-value :mass arguments)
                    (and present (checked-expression validation mass))))
            (position (checked-vector validation (keyword-value :position arguments '(0 0))
                                      "the :position"))
            (velocity (checked-vector validation (keyword-value :velocity arguments '(0 0))
                                      "the :velocity")))
        (when mass
          (check-positive-constant validation mass "a mass" 'scenario-expression-error))
        (when (and fixed (not (zero-vector-p velocity)))
          (reject validation 'scenario-syntax-error (keyword-value :velocity arguments)
                  "a fixed body does not move: its :velocity can only be (0 0)"))
        (make-instance 'scenario-body :name name :shape shape :mass mass
                                      :position position :velocity velocity
                                      :fixed-p fixed)))))

(defun checked-force (validation clause)
  "The SCENARIO-FORCE that the clause (force NAME :on BODY :value (FX FY)) declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "force ~A" (symbol-name name))))
    (enter validation what clause)
    (let* ((arguments (checked-keywords validation (cddr clause) '(:on :value) what))
           (missing (remove-if (lambda (key) (assoc key arguments)) '(:on :value))))
      (when missing
        (reject validation 'missing-property-error clause "the force has no ~{~S~^, ~}" missing))
      (let* ((target (keyword-value :on arguments))
             (declaration (declared validation target)))
        (cond ((not (and (symbolp target) target (not (keywordp target))))
               (reject validation 'scenario-syntax-error target
                       ":on takes the name of a body, not ~A" (show target)))
              ((null declaration)
               (reject validation 'undeclared-symbol-error target
                       "~A is not a declared body" (show target)))
              ((not (eq (car declaration) :body))
               (reject validation 'undeclared-symbol-error target
                       "~A names a ~(~A~), not a body" (show target) (car declaration))))
        (make-instance 'scenario-force
                       :name name :body (cdr declaration)
                       :value (checked-vector validation (keyword-value :value arguments)
                                              "the force's :value"))))))

(defun single-clause (validation word clauses)
  "The only clause of CLAUSES, the scenario's (WORD ...) clauses, entered for checking;
NIL when there is none. Signals DUPLICATE-CLAUSE-ERROR naming the second when there
are more."
  (when clauses
    (let ((location (format nil "clause ~A" (symbol-name word))))
      (when (rest clauses)
        (enter validation location (second clauses))
        (reject validation 'duplicate-clause-error (second clauses)
                "there is more than one (~(~A~) ...) clause" (symbol-name word)))
      (enter validation location (first clauses))
      (first clauses))))

(defun checked-gravity (validation clauses)
  "The field strength of the (gravity STRENGTH) clause among CLAUSES, or NIL."
  (let ((clause (single-clause validation 'ames-scenario:gravity clauses)))
    (when clause
      (unless (= (length clause) 2)
        (reject validation 'scenario-syntax-error clause
                "gravity takes one strength: (gravity STRENGTH)"))
      (checked-expression validation (second clause)))))

(defun checked-simulate (validation clauses)
  "The :states and :until of the (simulate ...) clause among CLAUSES, as two values."
  (let ((clause (single-clause validation 'ames-scenario:simulate clauses)))
    (when clause
      (let* ((arguments (checked-keywords validation (rest clause) '(:states :until)
                                          "simulate"))
             (states (keyword-value :states arguments))
             (until (multiple-value-bind (until present) (keyword-value :until arguments)
                      (and present (checked-expression validation until)))))
        (when (and (assoc :states arguments) (not (and (integerp states) (plusp states))))
          (reject validation 'scenario-syntax-error states
                  ":states takes a positive integer, not ~A" (show states)))
        (when until
          (check-positive-constant validation until "the :until time"
                                   'scenario-expression-error))
        (values states until)))))

;;; ------------------------------------------------------------------------------------
;;; The scenario

(defun clause-word (clause)
  "The clause word of CLAUSE (a proper list), or NIL."
  (language-word (car clause) +clause-words+))

(defun sorted-clauses (validation clauses)
  "CLAUSES checked to be clauses of the language, as an alist (WORD . CLAUSES) in
order."
  (let ((sorted (mapcar #'list +clause-words+)))
    (dolist (clause clauses)
      (enter validation "clause" clause)
      (cond ((stringp clause)
             (reject validation 'scenario-syntax-error clause
                     "a description string may only come right after the name"))
            ((atom clause)
             (reject validation 'scenario-syntax-error clause
                     "~A is not a clause; a clause is a list such as (body NAME ...)"
                     (show clause)))
            ((not (proper-list-p clause))
             (reject validation 'scenario-syntax-error clause "the clause is not a proper list"))
            ((not (clause-word clause))
             (reject validation 'unknown-clause-error clause
                     "~A is not a clause of the scenario language; the clauses are ~
                      parameters, gravity, body, force, simulate and query"
                     (show (car clause))))
            (t (push clause (cdr (assoc (clause-word clause) sorted))))))
    (dolist (entry sorted sorted)
      (setf (cdr entry) (nreverse (cdr entry))))))

(defun declare-names (validation sorted)
  "Declare the names of the parameters, bodies and forces of the SORTED clauses."
  (dolist (clause (cdr (assoc 'ames-scenario:parameters sorted)))
    (enter validation "clause PARAMETERS" clause)
    (dolist (spec (rest clause))
      (let ((name (parameter-spec-name spec)))
        (enter validation "clause PARAMETERS" clause)
        (when (and (consp spec) (not (proper-list-p spec)))
          (reject validation 'scenario-syntax-error spec "~A is not a proper list" (show spec)))
        (check-name validation name "parameter")
        (declare-name validation name :parameter))))
  (loop for (word kind) in '((ames-scenario:body :body) (ames-scenario:force :force))
        do (dolist (clause (cdr (assoc word sorted)))
             (enter validation (format nil "clause ~A" word) clause)
             (when (null (rest clause))
               (reject validation 'missing-property-error clause
                       "the ~(~A~) has no name" kind))
             (check-name validation (second clause) (string-downcase kind))
             (enter validation (format nil "~(~A~) ~A" kind (symbol-name (second clause))) clause)
             (declare-name validation (second clause) kind))))

(defun parse-scenario (form &key source)
  "Validate FORM, the s-expression (scenario NAME [\"description\"] CLAUSE ...), and
return the SCENARIO it describes. FORM may come from a scenario file or from the REPL
in any package: the language's words are recognised by name. SOURCE (a string such as
\"scenarios/x.lisp, line 3\") is recorded for messages.
Signals a SCENARIO-ERROR naming the clause or body at fault: SCENARIO-SYNTAX-ERROR
(and its UNKNOWN-CLAUSE-ERROR, DUPLICATE-CLAUSE-ERROR, MISSING-PROPERTY-ERROR),
UNDECLARED-SYMBOL-ERROR, DUPLICATE-NAME-ERROR, SCENARIO-EXPRESSION-ERROR,
SCENARIO-SHAPE-ERROR or CONTRADICTORY-ASSUMPTIONS-ERROR. Never evaluates anything of
FORM. The checks that need Maxima or geometry are CHECK-SCENARIO-ASSUMPTIONS and
CHECK-SCENARIO-GEOMETRY, which the caller runs when it has those layers."
  (let ((validation (make-validation form source)))
    (enter validation "form" nil)
    (check-form-size validation form)
    (unless (and (consp form) (proper-list-p form) (named-p (first form) "SCENARIO"))
      (reject validation 'scenario-syntax-error form
              "a scenario is a list (scenario NAME \"description\" CLAUSE ...), not ~A"
              (show form)))
    (enter validation "form" form)
    (when (null (rest form))
      (reject validation 'missing-property-error form "the scenario has no name"))
    (let ((name (second form)))
      (when (or (not (symbolp name)) (null name) (keywordp name) (named-p name "T"))
        (reject validation 'scenario-syntax-error name
                "a scenario's name must be a symbol, not ~A" (show name)))
      (setf (validation-name validation) name)
      (let* ((description (and (stringp (third form)) (third form)))
             (sorted (sorted-clauses validation (if description (cdddr form) (cddr form)))))
        (flet ((clauses (word) (cdr (assoc word sorted))))
          (declare-names validation sorted)
          (let ((parameters (loop for clause in (clauses 'ames-scenario:parameters)
                                  append (mapcar (lambda (spec) (checked-parameter validation spec))
                                                 (rest clause)))))
            (dolist (parameter parameters)
              (enter validation (format nil "parameter ~A"
                                        (symbol-name (scenario-parameter-name parameter)))
                     nil)
              (check-parameter-bounds validation parameter))
            (check-default-values validation parameters)
            (let ((gravity (checked-gravity validation (clauses 'ames-scenario:gravity)))
                  (bodies (mapcar (lambda (clause) (checked-body validation clause))
                                  (clauses 'ames-scenario:body)))
                  (forces (mapcar (lambda (clause) (checked-force validation clause))
                                  (clauses 'ames-scenario:force))))
              (when (null bodies)
                (enter validation "form" form)
                (reject validation 'missing-property-error form "the scenario has no body"))
              (multiple-value-bind (states until)
                  (checked-simulate validation (clauses 'ames-scenario:simulate))
                (make-instance 'scenario
                               :name name :description description
                               :parameters parameters :gravity gravity
                               :bodies bodies :forces forces
                               :states states :until until
                               :queries (mapcar #'rest (clauses 'ames-scenario:query))
                               :source source :form form)))))))))
