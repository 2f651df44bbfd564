;;;; src/scenario/clauses.lisp -- validating bodies, forces, gravity and simulate, and the
;;;; whole scenario.

(in-package #:ames.scenario)

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
                                        '(:shape :mass :position :velocity :fixed :driven
                                          :inertia :angle :angular-velocity)
                                        what))
           (fixed (body-flag validation arguments :fixed))
           (driven (body-flag validation arguments :driven))
           (missing (remove-if (lambda (key) (assoc key arguments))
                               (cond (fixed '(:shape))
                                     (driven '(:shape :velocity))
                                     (t '(:shape :mass :position :velocity))))))
      (when (and fixed driven)
        (reject validation 'scenario-syntax-error clause "a body is :fixed or :driven, not both"))
      (when (and driven (assoc :mass arguments))
        (reject validation 'scenario-syntax-error clause
                "a driven body moves at its :velocity whatever acts on it: it has no :mass"))
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
        (apply #'make-instance 'scenario-body :name name :shape shape :mass mass
                                              :position position :velocity velocity
                                              :fixed-p fixed :driven-p driven
               (checked-rotation validation arguments shape mass fixed driven))))))

(defun body-flag (validation arguments key)
  "The value of the body's flag KEY (:fixed, :driven) in ARGUMENTS: T or NIL."
  (multiple-value-bind (value present) (keyword-value key arguments)
    (cond ((not present) nil)
          ((named-p value "T") t)
          ((named-p value "NIL") nil)
          (t (reject validation 'scenario-syntax-error value
                     "~(~S~) takes T or NIL, not ~A" key (show value))))))

(defun checked-force (validation clause)
  "The SCENARIO-FORCE that the clause (force NAME :on BODY :value (FX FY)) declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "force ~A" (symbol-name name))))
    (enter validation what clause)
    (let* ((arguments (checked-keywords validation (cddr clause) '(:on :value :at) what))
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
                                              "the force's :value")
                       :point (and (assoc :at arguments)
                                   (checked-vector validation (keyword-value :at arguments)
                                                   "the force's :at")))))))

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
  "The :states, :until, :branch and :all-branches of the (simulate ...) clause among
CLAUSES, as four values (:branch defaults to T, :all-branches to NIL)."
  (let ((clause (single-clause validation 'ames-scenario:simulate clauses)))
    (if (null clause)
        (values nil nil t nil)
        (let* ((arguments (checked-keywords validation (rest clause)
                                            '(:states :until :branch :all-branches)
                                            "simulate"))
               (states (keyword-value :states arguments))
               (until (multiple-value-bind (until present) (keyword-value :until arguments)
                        (and present (checked-expression validation until))))
               (branch (multiple-value-bind (value present) (keyword-value :branch arguments)
                         (cond ((not present) t)
                               ((named-p value "T") t)
                               ((named-p value "NIL") nil)
                               (t (reject validation 'scenario-syntax-error value
                                          ":branch takes T or NIL, not ~A" (show value))))))
               (all (multiple-value-bind (value present) (keyword-value :all-branches arguments)
                      (cond ((not present) nil)
                            ((named-p value "T") t)
                            ((named-p value "NIL") nil)
                            (t (reject validation 'scenario-syntax-error value
                                       ":all-branches takes T or NIL, not ~A" (show value)))))))
          (when (and (assoc :states arguments) (not (and (integerp states) (plusp states))))
            (reject validation 'scenario-syntax-error states
                    ":states takes a positive integer, not ~A" (show states)))
          (when until
            (check-positive-constant validation until "the :until time"
                                     'scenario-expression-error))
          (values states until branch all)))))

;;; ------------------------------------------------------------------------------------
;;; Collisions

(defun checked-restitution (validation clause)
  "The entry (BODY1 BODY2 E), or (NIL NIL E) for the default, that the clause
(restitution E) or (restitution BODY1 BODY2 E) declares. E must lie in [0, 1] when it
is a number."
  (enter validation "clause RESTITUTION" clause)
  (flet ((coefficient (x)
           (let* ((e (checked-expression validation x))
                  (value (expression-value e)))
             (when (and value (not (<= 0 value 1)))
               (reject validation 'scenario-expression-error x
                       "a coefficient of restitution lies between 0 and 1, not ~A" (show x)))
             e))
         (body (x)
           (let ((declaration (declared validation x)))
             (unless (and declaration (eq (car declaration) :body))
               (reject validation 'undeclared-symbol-error x "~A is not a declared body" (show x)))
             (cdr declaration))))
    (case (length clause)
      (2 (list nil nil (coefficient (second clause))))
      (4 (let ((b1 (body (second clause))) (b2 (body (third clause))))
           (when (eq b1 b2)
             (reject validation 'scenario-syntax-error clause
                     "an impact takes two different bodies"))
           (list b1 b2 (coefficient (fourth clause)))))
      (t (reject validation 'scenario-syntax-error clause
                 "restitution is (restitution E) or (restitution BODY1 BODY2 E)")))))

(defun checked-restitutions (validation clauses)
  "The restitution entries of CLAUSES; at most one default and one per pair."
  (let ((entries '()))
    (dolist (clause clauses (nreverse entries))
      (let ((entry (checked-restitution validation clause)))
        (when (find-if (lambda (old) (or (and (eq (first old) (first entry)) (eq (second old) (second entry)))
                                         (and (eq (first old) (second entry)) (eq (second old) (first entry)))))
                       entries)
          (reject validation 'duplicate-clause-error clause
                  "~:[the default coefficient of restitution~;this pair's coefficient of restitution~] is given twice"
                  (first entry)))
        (push entry entries)))))

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
                     "~A is not a clause of the scenario language~A; the clauses are ~
                      parameters, gravity, body, force, simulate, query, restitution, ~
                      friction, spring, pulley, rope, gravitation, hinge and drag"
                     (show (car clause))
                     (if (symbolp (car clause))
                         (did-you-mean (symbol-name (car clause))
                                       (mapcar #'symbol-name +clause-words+))
                         "")))
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
  (loop for (word kind) in '((ames-scenario:body :body) (ames-scenario:force :force)
                             (ames-scenario:spring :spring) (ames-scenario:pulley :pulley)
                             (ames-scenario:rope :rope) (ames-scenario:hinge :hinge)
                             (ames-scenario:drag :drag))
        do (dolist (clause (cdr (assoc word sorted)))
             (enter validation (format nil "clause ~A" word) clause)
             (when (null (rest clause))
               (reject validation 'missing-property-error clause
                       "the ~(~A~) has no name" kind))
             (check-name validation (second clause) (string-downcase kind))
             (enter validation (format nil "~(~A~) ~A" kind (symbol-name (second clause))) clause)
             (declare-name validation (second clause) kind))))

(defun parse-scenario (form &key source positions)
  "Validate FORM, the s-expression (scenario NAME [\"description\"] CLAUSE ...), and
return the SCENARIO it describes. FORM may come from a scenario file or from the REPL
in any package: the language's words are recognised by name. SOURCE (a string such as
\"scenarios/x.lisp, line 3\") is recorded for messages; POSITIONS, the SOURCE-TEXT the
form was read from (by the reader), lets messages name the line of the clause at fault.
Signals a SCENARIO-ERROR naming the clause or body at fault: SCENARIO-SYNTAX-ERROR
(and its UNKNOWN-CLAUSE-ERROR, DUPLICATE-CLAUSE-ERROR, MISSING-PROPERTY-ERROR),
UNDECLARED-SYMBOL-ERROR, DUPLICATE-NAME-ERROR, SCENARIO-EXPRESSION-ERROR,
SCENARIO-SHAPE-ERROR or CONTRADICTORY-ASSUMPTIONS-ERROR. Never evaluates anything of
FORM. The checks that need Maxima or geometry are CHECK-SCENARIO-ASSUMPTIONS and
CHECK-SCENARIO-GEOMETRY, which the caller runs when it has those layers."
  (let* ((validation (make-validation form source positions))
         (name (checked-scenario-name validation form)))
    (let* ((description (and (stringp (third form)) (third form)))
           (sorted (sorted-clauses validation (if description (cdddr form) (cddr form)))))
      (flet ((clauses (word) (cdr (assoc word sorted))))
        (declare-names validation sorted)
        (let ((parameters (checked-parameters validation (clauses 'ames-scenario:parameters))))
          (let ((gravity (checked-gravity validation (clauses 'ames-scenario:gravity)))
                (bodies (mapcar (lambda (clause) (checked-body validation clause))
                                (clauses 'ames-scenario:body)))
                (forces (mapcar (lambda (clause) (checked-force validation clause))
                                (clauses 'ames-scenario:force)))
                (frictions (checked-frictions validation (clauses 'ames-scenario:friction))))
            (when (null bodies)
              (enter validation "form" form)
              (reject validation 'missing-property-error form "the scenario has no body"))
            (multiple-value-bind (states until branch all-branches)
                (checked-simulate validation (clauses 'ames-scenario:simulate))
              (check-rotation
               validation
               (make-instance 'scenario
                             :name name :description description
                             :parameters parameters :gravity gravity
                             :bodies bodies :forces forces :frictions frictions
                             :states states :until until :branch branch
                             :all-branches all-branches
                             :queries (checked-queries validation (clauses 'ames-scenario:query))
                             :restitutions (checked-restitutions
                                            validation (clauses 'ames-scenario:restitution))
                             :extensions (checked-extensions validation sorted bodies)
                             :source source :positions positions :form form)))))))))

(defun checked-scenario-name (validation form)
  "The name of the scenario FORM, checked with its shape: a proper list (scenario NAME
...) of a bounded size, NAME a symbol; recorded in VALIDATION. Signals
SCENARIO-SYNTAX-ERROR or MISSING-PROPERTY-ERROR."
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
    (setf (validation-name validation) name)))

(defun checked-parameters (validation clauses)
  "The SCENARIO-PARAMETERs the (parameters SPEC ...) CLAUSES declare, each checked with
its bounds, and their default values checked together."
  (let ((parameters (loop for clause in clauses
                          append (mapcar (lambda (spec) (checked-parameter validation spec))
                                         (rest clause)))))
    (dolist (parameter parameters)
      (enter validation (format nil "parameter ~A"
                                (symbol-name (scenario-parameter-name parameter)))
             nil)
      (check-parameter-bounds validation parameter))
    (check-default-values validation parameters)
    parameters))
