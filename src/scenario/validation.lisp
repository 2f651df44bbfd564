;;;; src/scenario/validation.lisp -- the validation in progress, words and names, sizes,
;;;; expressions (the parameters are in parameters.lisp).

(in-package #:ames.scenario)

;;; ------------------------------------------------------------------------------------
;;; The validation in progress: where we are, for the conditions, and the names declared

(defstruct (validation (:constructor make-validation (form source &optional positions)))
  "What the validator knows while it checks one form."
  (form nil)
  (source nil)
  (positions nil)            ; the SOURCE-TEXT the form was read from, or NIL
  (name nil)                 ; the scenario's name, once known
  (location nil)             ; "body WEDGE", "clause GRAVITY"...
  (clause nil)               ; the clause being checked
  (names (make-hash-table :test 'equal))) ; symbol name -> (KIND . SYMBOL)

(defun fault-source (validation datum)
  "\"FILE, line N\" for DATUM at VALIDATION's current place: the line where DATUM was
read within the clause, else the clause's, else where DATUM appears in the form, else
the scenario's SOURCE."
  (let* ((positions (validation-positions validation))
         (clause (validation-clause validation))
         (line (and positions
                    (or (and datum (form-line positions datum clause))
                        (and clause (form-line positions clause))
                        (and datum (form-line positions datum (validation-form validation)))))))
    (if line
        (source-description positions line)
        (validation-source validation))))

(defun reject-because (validation class cause datum control &rest arguments)
  "Signal a scenario error of CLASS at VALIDATION's current place, wrapping CAUSE (or
NIL), with DATUM at fault (the clause, or the whole form, when DATUM is NIL). The
condition's SOURCE names the line of DATUM, or of its clause, when the form was read
from a text."
  (error class
         :scenario (validation-name validation)
         :location (validation-location validation)
         :clause (validation-clause validation)
         :source (fault-source validation datum)
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
    ames-scenario:force ames-scenario:simulate ames-scenario:query
    ames-scenario:restitution
    ames-scenario:friction
    ames-scenario:spring ames-scenario:pulley ames-scenario:rope ames-scenario:gravitation
    ames-scenario:hinge ames-scenario:drag)
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
                          "~S is not a keyword of ~A~A; its keywords are ~{~S~^ ~}"
                          key what (did-you-mean (symbol-name key)
                                                 (mapcar (lambda (k) (format nil ":~(~A~)" k))
                                                         allowed))
                          allowed))
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
                   ((named-p (car y) "DEG") (degrees-expression validation y #'walk))
                   (t (let ((operator (algebra-operator-named (car y))))
                        (cond ((null operator)
                               (reject validation 'scenario-expression-error y
                                       "~A is not an operator of the algebra (+ - * / ~
                                        expt sqrt exp log sin cos tan asin acos atan abs)"
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

(defun checked-body-name (validation name &optional (what "the clause"))
  "The declared symbol of the body NAME, which WHAT (a string: the clause or part that
names it) names. Signals SCENARIO-SYNTAX-ERROR or UNDECLARED-SYMBOL-ERROR."
  (let ((declaration (declared validation name)))
    (cond ((not (and (symbolp name) name (not (keywordp name))))
           (reject validation 'scenario-syntax-error name
                   "~A takes the names of bodies, not ~A" what (show name)))
          ((null declaration)
           (reject validation 'undeclared-symbol-error name
                   "~A is not a declared body" (show name)))
          ((not (eq (car declaration) :body))
           (reject validation 'undeclared-symbol-error name
                   "~A names a ~(~A~), not a body" (show name) (car declaration)))
          (t (cdr declaration)))))
