;;;; src/scenario/conditions.lisp -- the conditions a defective scenario signals, and the SKIP-SCENARIO restart.
;;;;
;;;; SCENARIO-ERROR (an AMES-ERROR)
;;;;   SCENARIO-READ-ERROR          the text is not a readable form of the language
;;;;     SCENARIO-FILE-ERROR        the file cannot be opened or decoded
;;;;   SCENARIO-SYNTAX-ERROR        a form of the wrong shape: malformed clause, bad keyword...
;;;;     UNKNOWN-CLAUSE-ERROR       a clause the language does not have
;;;;     DUPLICATE-CLAUSE-ERROR     a second (gravity ...) or (simulate ...)
;;;;     MISSING-PROPERTY-ERROR     a body without :mass, :position, :velocity or :shape...
;;;;   UNDECLARED-SYMBOL-ERROR      a symbol that is no parameter, body, PI or number
;;;;   DUPLICATE-NAME-ERROR         a name used twice (parameters, bodies, forces share one)
;;;;   SCENARIO-EXPRESSION-ERROR    a malformed number or expression
;;;;   SCENARIO-SHAPE-ERROR         a bad shape form (or, once geometry is wired, a bad shape)
;;;;   CONTRADICTORY-ASSUMPTIONS-ERROR  parameter assumptions that cannot all hold
;;;;   OVERLAPPING-BODIES-ERROR     bodies that interpenetrate at the start (geometry's check)
;;;;
;;;; Every one names the scenario, where in it the defect is (a LOCATION such as "body
;;;; WEDGE" or "clause GRAVITY"), the clause, and in DATUM the offending sub-form. Reports
;;;; bind *PRINT-LEVEL* and *PRINT-LENGTH*, so any form, however deep or long, prints.

(in-package #:ames.scenario)

(defun form-package (form)
  "The package FORM's symbols were most likely written in: the home package of its
first symbol (the user's package at the REPL, AMES-SCENARIO for a file)."
  (let ((package (loop repeat 4
                       do (cond ((consp form) (setf form (car form)))
                                ((and form (symbolp form))
                                 (return (let ((home (symbol-package form)))
                                           (and home
                                                (not (eq home (find-package '#:keyword)))
                                                home))))
                                (t (return nil))))))
    (or package (find-package '#:ames-scenario))))

(defun short-form-string (form &optional (package (find-package '#:ames-scenario)))
  "FORM printed readably but cut short, for condition reports; symbols of PACKAGE
print without their package prefix."
  (with-standard-io-syntax
    (let ((*print-readably* nil) (*print-level* 4) (*print-length* 8)
          (*package* package))
      (prin1-to-string form))))

(defun report-scenario-error (condition stream)
  "Write CONDITION's report: where, what, the clause and the datum at fault."
  (flet ((short-form-string (form)
           (short-form-string form (form-package (or (scenario-error-scenario condition)
                                                     (scenario-error-clause condition))))))
   (format stream "~:[Scenario~;~:*Scenario ~A~]~@[, ~A~]~@[ (~A)~]: ~A"
          (let ((name (scenario-error-scenario condition)))
            (and name (short-form-string name)))
          (scenario-error-location condition)
          (scenario-error-source condition)
          (or (ames-error-detail condition) "defective scenario"))
  (let ((clause (scenario-error-clause condition))
        (datum (ames-error-datum condition)))
    (when (and clause (not (eq clause datum)))
      (format stream "~%  in: ~A" (short-form-string clause)))
    (when datum
      (format stream "~%  at fault: ~A" (short-form-string datum)))
    (let ((cause (scenario-error-cause condition)))
      ;; a cause that only repeats the detail (the algebra's own complaint) is not shown
      (when (and cause
                 (not (and (typep cause 'ames-error)
                           (equal (ames-error-detail cause) (ames-error-detail condition)))))
        (format stream "~%  because: ~A" cause))))))

(define-condition scenario-error (ames-error)
  ((scenario :initarg :scenario :initform nil :reader scenario-error-scenario
             :documentation "The scenario's name, when it could be read.")
   (location :initarg :location :initform nil :reader scenario-error-location
             :documentation "Where in the scenario: a string such as \"body WEDGE\".")
   (clause :initarg :clause :initform nil :reader scenario-error-clause
           :documentation "The whole clause in which the defect lies.")
   (source :initarg :source :initform nil :reader scenario-error-source
           :documentation "Where the form came from: a string such as
\"scenarios/x.lisp, line 3\", or NIL for a form given at the REPL.")
   (cause :initarg :cause :initform nil :reader scenario-error-cause
          :documentation "The condition of a lower layer that this one wraps, if any."))
  (:documentation "The root of every defect in a scenario. DATUM is the offending
sub-form (never NIL: an empty form is described by a string), DETAIL says what is
wrong with it.")
  (:report report-scenario-error))

(setf (documentation 'scenario-error-scenario 'function)
      "The name of the scenario at fault, when it could be read, else NIL."
      (documentation 'scenario-error-location 'function)
      "Where in the scenario: a string such as \"body WEDGE\", or NIL."
      (documentation 'scenario-error-clause 'function)
      "The whole clause in which the defect lies, or NIL."
      (documentation 'scenario-error-source 'function)
      "Where the form came from, a string such as \"scenarios/x.lisp, line 3\", or NIL
for a form given at the REPL."
      (documentation 'scenario-error-cause 'function)
      "The condition of a lower layer that this one wraps, or NIL.")

(define-condition scenario-read-error (scenario-error)
  ((file :initarg :file :initform nil :reader scenario-read-error-file
         :documentation "The file read, or NIL when reading a string.")
   (line :initarg :line :initform nil :reader scenario-read-error-line
         :documentation "The 1-based line of the fault.")
   (column :initarg :column :initform nil :reader scenario-read-error-column
           :documentation "The 0-based column of the fault.")
   (position :initarg :position :initform nil :reader scenario-read-error-position
             :documentation "The 0-based character offset of the fault."))
  (:documentation "Text that is not a form of the scenario language: forbidden syntax
(#. #S #P ' ` , pkg::sym ...), an unbalanced or too deeply nested list, an unreadable
token. DATUM is the start of the offending text.")
  (:report (lambda (condition stream)
             (format stream "Cannot read scenario~@[ from ~A~]~@[, line ~D~]~@[, column ~D~]: ~A~@[~%  at fault: ~A~]"
                     (scenario-read-error-file condition)
                     (scenario-read-error-line condition)
                     (scenario-read-error-column condition)
                     (ames-error-detail condition)
                     (let ((datum (ames-error-datum condition)))
                       (and datum (short-form-string datum)))))))

(setf (documentation 'scenario-read-error-file 'function)
      "The file read, or NIL when reading a string."
      (documentation 'scenario-read-error-line 'function)
      "The 1-based line of the fault."
      (documentation 'scenario-read-error-column 'function)
      "The 0-based column of the fault."
      (documentation 'scenario-read-error-position 'function)
      "The 0-based character offset of the fault.")

(define-condition scenario-file-error (scenario-read-error) ()
  (:documentation "A scenario file that cannot be opened, or whose bytes are not text.
DATUM is the pathname."))

(define-condition scenario-syntax-error (scenario-error) ()
  (:documentation "A form of the wrong shape: a malformed clause, an unknown keyword,
a wrong number of arguments, a value of the wrong kind."))

(define-condition unknown-clause-error (scenario-syntax-error) ()
  (:documentation "A clause whose head is not one of the language's clauses."))

(define-condition duplicate-clause-error (scenario-syntax-error) ()
  (:documentation "A clause that may appear at most once appears again (GRAVITY,
SIMULATE), or a keyword given twice."))

(define-condition missing-property-error (scenario-syntax-error) ()
  (:documentation "A required property is absent: a body's :shape, a moving body's
:mass, :position or :velocity, a force's :on or :value, the scenario's name."))

(define-condition undeclared-symbol-error (scenario-error) ()
  (:documentation "A symbol in an expression that is not a declared parameter or PI,
or a force on a body that is not declared."))

(define-condition duplicate-name-error (scenario-error) ()
  (:documentation "A name declared twice: parameters, bodies and forces share one
namespace (names are compared by their symbol names)."))

(define-condition scenario-expression-error (scenario-error) ()
  (:documentation "A malformed number or expression (outside the prefix algebra, a
quantity term, a complex number, a division by zero...). CAUSE holds the algebra's
MALFORMED-EXPRESSION when it found the fault."))

(define-condition scenario-shape-error (scenario-error) ()
  (:documentation "A bad shape form: unknown kind, wrong arity, missing or unknown
keywords, a non-positive radius, a clockwise or degenerate polygon. CAUSE holds
geometry's condition when the geometry layer found the fault."))

(define-condition contradictory-assumptions-error (scenario-error) ()
  (:documentation "Parameter assumptions that cannot all hold, or a default :value
that violates them. CAUSE holds the bridge's condition when Maxima found it."))

(define-condition overlapping-bodies-error (scenario-error) ()
  (:documentation "Two bodies that interpenetrate at the start (signalled by the
geometric check, see CHECK-SCENARIO-GEOMETRY)."))

(defun skip-scenario (&optional condition)
  "Invoke the SKIP-SCENARIO restart (active for CONDITION, when given): abandon the
scenario at fault and go on with the next one of the file. Signals CONTROL-ERROR when
no such restart is active."
  (let ((restart (find-restart 'skip-scenario condition)))
    (if restart
        (invoke-restart restart)
        (error 'control-error))))

(define-condition parameter-values-error (scenario-error) ()
  (:documentation "The numeric parameter values given to a simulation (the
:PARAMETER-VALUES argument, or --set on the command line) are not an alist ((NAME .
NUMBER) ...) of names and finite real numbers. DATUM is the argument or its offending
entry. See CHECK-PARAMETER-VALUES.")
  (:report (lambda (condition stream)
             (format stream "Invalid parameter values~@[ for scenario ~A~]: ~A~%  at fault: ~A"
                     (let ((name (scenario-error-scenario condition)))
                       (and name (short-form-string name (form-package name))))
                     (ames-error-detail condition)
                     (short-form-string (ames-error-datum condition))))))
