;;;; src/scenario/objects.lisp -- scenario objects; the validator's choices (it turns a scenario
;;;; form into one: see validation.lisp, shapes.lisp and clauses.lisp).
;;;;
;;;; PARSE-SCENARIO takes the s-expression of one scenario (read from a file by
;;;; src/scenario/reader.lisp, or quoted at the REPL in any package) and returns a
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
;;;; - A body with :driven t moves at its constant :velocity whatever acts on it (a
;;;;   conveyor belt); it needs :velocity (its :position defaults to (0 0)), has no :mass,
;;;;   and is not :fixed.
;;;; - (arc ...) as a shape takes :solid :inside or :outside; the default is :inside,
;;;;   the side to the left of its counter-clockwise direction, as for SEGMENT and
;;;;   OUTLINE. An arc's :to must exceed its :from by at most 2 pi (checked when
;;;;   both are numbers). Arc pieces of an OUTLINE take no :solid.
;;;; - (simulate) takes :states, a positive integer, and :until, an expression that
;;;;   must be positive when it is a number. Either may be absent: NIL means no limit
;;;;   from the scenario (the simulator applies its own). Both: whichever comes first.
;;;; - (query ...) clauses are kept as data, unchecked, for the simulator.
;;;; - (friction BODY1 BODY2 :static MU-S [:kinetic MU-K]) names two distinct declared
;;;;   bodies, not both fixed; one clause per pair (in either order). The coefficients are
;;;;   expressions; a constant one must not be negative, and constant ones must have
;;;;   MU-K <= MU-S (the textbook's Coulomb friction). MU-K defaults to MU-S.
;;;; - Bounds: a form nested more than +DEEPEST-FORM+ deep or holding more than
;;;;   +LARGEST-FORM+ conses (or circular) is rejected before anything else.
;;;;
;;;; Checks done here without Maxima, when numbers decide them: contradictory constant
;;;; bounds on one parameter ((> x 2) with (< x 1), (> a (/ pi 2)) with (< a 1)),
;;;; default values that violate any assumption, non-positive constant radii and
;;;; masses, clockwise or degenerate polygons with numeric vertices, coincident points,
;;;; outline pieces with numeric ends that do not meet. Everything symbolic is left to
;;;; the semantic checks of src/scenario/semantics.lisp (Maxima and geometry).

(in-package #:ames.scenario)

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
   (frictions :initarg :frictions :initform '() :reader scenario-frictions
              :documentation "The SCENARIO-FRICTIONs (Coulomb friction between pairs of
bodies), in order of declaration.")
   (states :initarg :states :initform nil :reader scenario-states
           :documentation "Stop after this many states (a positive integer), or NIL.")
   (until :initarg :until :initform nil :reader scenario-until
          :documentation "Stop at this global time (an expression), or NIL.")
   (branch :initarg :branch :initform t :reader scenario-branch
           :documentation "True when an ambiguity splits the run into branches; NIL when it
stops the run, naming the missing fact.")
   (all-branches :initarg :all-branches :initform nil :reader scenario-all-branches
                 :documentation "True when every branch is simulated even where parameter
values select one ((simulate :all-branches t)); by default only the selected one is.")
   (queries :initarg :queries :initform '() :reader scenario-queries
            :documentation "The validated queries, each (NAME QUESTION) in the canonical form
of src/scenario/queries.lisp.")
   (restitutions :initarg :restitutions :initform '() :reader scenario-restitutions
                 :documentation "Newton's coefficients of restitution: a list of (BODY1 BODY2
E) for a pair's impacts and (NIL NIL E) for every other impact (without one, E is 0).")
   (extensions :initarg :extensions :initform '() :reader scenario-extensions
               :documentation "The clauses of the extensions, as a plist (see
src/scenario/extensions.lisp: :SPRINGS, :PULLEYS, :ROPES, :GRAVITATION).")
   (source :initarg :source :initform nil :reader scenario-source
           :documentation "Where the form came from (\"FILE, line N\"), or NIL.")
   (positions :initarg :positions :initform nil :reader scenario-positions
              :documentation "The SOURCE-TEXT the form was read from (where each of its
clauses is), or NIL for a form given at the REPL.")
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
            :documentation "True when the body is glued to the fixed frame.")
   (driven-p :initarg :driven-p :initform nil :reader scenario-body-driven-p
             :documentation "True when the body moves at its prescribed constant :velocity
whatever acts on it (a conveyor belt); it has no mass.")
   (inertia :initarg :inertia :initform nil :reader scenario-body-inertia
            :documentation "The moment of inertia about the reference point (the centre of
mass), an expression; NIL for a body that translates only (see rotation.lisp).")
   (inertia-kind :initarg :inertia-kind :initform nil :reader scenario-body-inertia-kind
                 :documentation "How the inertia was given: :VALUE, :UNIFORM or :RING; NIL.")
   (angle :initarg :angle :initform 0 :reader scenario-body-angle
          :documentation "The orientation at the start, radians counter-clockwise (0 for a
body that does not rotate).")
   (angular-velocity :initarg :angular-velocity :initform 0
                     :reader scenario-body-angular-velocity
                     :documentation "The angular velocity at the start, counter-clockwise."))
  (:documentation "A rigid body of a scenario: it translates, and rotates when it has an
inertia."))

(defclass scenario-force ()
  ((name :initarg :name :reader scenario-force-name
         :documentation "The force's symbol.")
   (body :initarg :body :reader scenario-force-body
         :documentation "The symbol of the body it acts on.")
   (value :initarg :value :reader scenario-force-value
          :documentation "The constant force (FX FY) in the fixed frame.")
   (point :initarg :point :initform nil :reader scenario-force-point
          :documentation "Where it acts, (X Y) in the body's own frame (:at), or NIL: at the
reference point."))
  (:documentation "A constant external force on one body."))

(defclass scenario-friction ()
  ((bodies :initarg :bodies :reader scenario-friction-bodies
           :documentation "The symbols of the two bodies, as the clause names them.")
   (static :initarg :static :reader scenario-friction-static
           :documentation "The coefficient of static friction MU-S, an expression.")
   (kinetic :initarg :kinetic :reader scenario-friction-kinetic
            :documentation "The coefficient of kinetic friction MU-K, an expression (MU-S
when the clause gives none)."))
  (:documentation "Coulomb friction on every contact between two bodies: the clause
(friction BODY1 BODY2 :static MU-S [:kinetic MU-K])."))

(defun scenario-restitution (scenario body1 body2)
  "The coefficient of restitution of impacts between BODY1 and BODY2 (either order):
the pair's own, else the scenario's default, else 0 (a plastic impact)."
  (let ((entries (scenario-restitutions scenario)))
    (third (or (find-if (lambda (entry)
                          (or (and (eq (first entry) body1) (eq (second entry) body2))
                              (and (eq (first entry) body2) (eq (second entry) body1))))
                        entries)
               (find nil entries :key #'first)
               '(nil nil 0)))))

(defun scenario-body-source (scenario body-name)
  "\"FILE, line N\" of the clause declaring the body named BODY-NAME in SCENARIO (by
name), else the scenario's own SOURCE; NIL for a scenario given at the REPL."
  (let* ((positions (scenario-positions scenario))
         (clause (and positions
                      (find-if (lambda (clause)
                                 (and (consp clause) (symbolp (first clause))
                                      (string= (symbol-name (first clause)) "BODY")
                                      (consp (rest clause)) (symbolp (second clause))
                                      (second clause)
                                      (string= (symbol-name (second clause))
                                               (symbol-name body-name))))
                               (and (alexandria:proper-list-p (scenario-form scenario))
                                    (scenario-form scenario)))))
         (line (and clause (form-line positions clause))))
    (if line (source-description positions line) (scenario-source scenario))))

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

(defmethod print-object ((friction scenario-friction) stream)
  (print-unreadable-object (friction stream :type t)
    (format stream "~{~S~^ ~}" (scenario-friction-bodies friction))))

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

(defun check-parameter-values (values &optional scenario)
  "VALUES, the numeric parameter values a simulation is given (its :PARAMETER-VALUES
argument): an alist ((NAME . NUMBER) ...) whose NAMEs are symbols or strings, matched
by name (case-insensitively) and each given once, and whose NUMBERs are finite reals.
Returns VALUES; when SCENARIO is given, as an alist keyed by SCENARIO's own parameter
symbols, in the order of VALUES.
Signals PARAMETER-VALUES-ERROR naming VALUES, or the entry at fault, when it is not such
an alist, and UNDECLARED-SYMBOL-ERROR naming a name that is not a parameter of
SCENARIO."
  (flet ((fail (datum control &rest arguments)
           (error 'parameter-values-error
                  :scenario (and scenario (scenario-name scenario))
                  :location "the parameter values" :datum (or datum "NIL")
                  :detail (apply #'format nil control arguments)))
         (entry-name (entry) (string (car entry))))
    (unless (alexandria:proper-list-p values)
      (fail values "the parameter values must be a list ((NAME . NUMBER) ...), not ~A"
            (short-form-string values)))
    (loop for (entry . later) on values
          do (unless (and (consp entry)
                          (or (stringp (car entry)) (and (symbolp (car entry)) (car entry))))
               (fail entry "each parameter value is a pair (NAME . NUMBER) with a symbol or ~
                            string NAME, not ~A" (short-form-string entry)))
             (unless (and (realp (cdr entry)) (finite-real-p (cdr entry)))
               (fail entry "the value of ~A must be a finite real number, not ~A"
                     (entry-name entry) (short-form-string (cdr entry))))
             (when (find (entry-name entry) later
                         :key (lambda (other) (and (consp other)
                                                   (or (stringp (car other)) (symbolp (car other)))
                                                   (string (car other))))
                         :test #'equalp)
               (fail entry "~A is given two values" (entry-name entry))))
    (if (null scenario)
        values
        (mapcar (lambda (entry)
                  (let ((parameter (find (entry-name entry) (scenario-parameters scenario)
                                         :key (lambda (p) (symbol-name (scenario-parameter-name p)))
                                         :test #'string-equal)))
                    (unless parameter
                      (error 'undeclared-symbol-error
                             :scenario (scenario-name scenario) :location "the parameter values"
                             :source (scenario-source scenario) :datum (car entry)
                             :detail (format nil "~A is not a parameter of this scenario"
                                             (entry-name entry))))
                    (cons (scenario-parameter-name parameter) (cdr entry))))
                values))))

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
