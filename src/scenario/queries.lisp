;;;; src/scenario/queries.lisp -- validating (query NAME QUESTION) clauses (thesis 3.2.4,
;;;; "Problem Solving Extensions": analysis, parameter selection, proofs).
;;;;
;;;; A validated query is a list (NAME QUESTION) in a canonical form the simulator answers:
;;;;   (:value QUANTITY :at WHEN)          (:time EVENT)
;;;;   (:parameter P :such-that CONDITION) (:prove CONDITION :during WHEN-or-NIL)
;;;;   (:maximum QUANTITY :during WHEN)    (:minimum QUANTITY :during WHEN)
;;;;   (:time-at (:start N) or (:end N))   (:rest-time BODY)    (:reaches-time QUANTITY VALUE)
;;;;   (:distance BODY :during WHEN-or-NIL)
;;;; where a QUANTITY is an arithmetic expression of the algebra whose atoms may also be
;;;; quantity forms (:x B) (:y B) (:position B) (:velocity B) (:speed B) (:acceleration B)
;;;; (:normal-force A B) (:friction A B) (:tension ROPE) (:kinetic-energy B) (:momentum B)
;;;; (:energy) (:time) (:angle B) (:angular-velocity B) (:angular-acceleration B)
;;;; (:hinge-force HINGE), or (:component :x-or-:y VECTOR-QUANTITY); a WHEN is (:start N), (:end N), (:reaches QUANTITY VALUE) (the first time QUANTITY
;;;; takes VALUE: scenario-language.md, "Rotation"), (:event PATTERN) with PATTERN a list
;;;; (:KIND NAME...) as an event is printed, or (:time EXPR); a CONDITION is a relation
;;;; over quantities and parameters, (:outcome PATTERN) or (:not (:outcome PATTERN)).
;;;; Words are recognised by name; every body, rope or parameter a query names must be
;;;; declared (an unknown name is an UNDECLARED-SYMBOL-ERROR naming it).

(in-package #:ames.scenario)

(defparameter +quantity-words+
  '(("X" . 1) ("Y" . 1) ("POSITION" . 1) ("VELOCITY" . 1) ("SPEED" . 1) ("ACCELERATION" . 1)
    ("NORMAL-FORCE" . 2) ("FRICTION" . 2) ("TENSION" . 1) ("KINETIC-ENERGY" . 1)
    ("MOMENTUM" . 1) ("ENERGY" . 0) ("TIME" . 0)
    ("ANGLE" . 1) ("ANGULAR-VELOCITY" . 1) ("ANGULAR-ACCELERATION" . 1) ("HINGE-FORCE" . 1)
    ("ANGULAR-MOMENTUM" . 1))
  "The quantities a query may ask for, with how many names each takes.")

(defun query-reject (validation datum control &rest arguments)
  "Signal SCENARIO-SYNTAX-ERROR about a query."
  (apply #'reject validation 'scenario-syntax-error datum control arguments))

(defun query-name-of (validation x what)
  "The declared symbol of the name X of a WHAT (\"body\", \"rope\"...). Signals
UNDECLARED-SYMBOL-ERROR naming X when nothing of that name is declared."
  (let ((declaration (declared validation x)))
    (unless declaration
      (reject validation 'undeclared-symbol-error x
              "~A is not a declared ~A" (show x) what))
    (cdr declaration)))

(defun quantity-form-p (x)
  "True when X is a list headed by a quantity word."
  (and (consp x) (symbolp (car x)) (not (keywordp (car x)))
       (assoc (symbol-name (car x)) +quantity-words+ :test #'string=)))

(defparameter +vector-quantities+ '(:position :velocity :acceleration :momentum :hinge-force)
  "The quantities whose value is a vector, whose components (x Q) and (y Q) are asked.")

(defun checked-quantity (validation x)
  "X as a canonical QUANTITY (see the file header)."
  (cond ((and (quantity-form-p x) (member (symbol-name (car x)) '("X" "Y") :test #'string=)
              (proper-list-p x) (= 2 (length x)) (quantity-form-p (second x)))
         (let ((vector (checked-quantity validation (second x))))
           (unless (member (first vector) +vector-quantities+)
             (query-reject validation x "a component is taken of a vector quantity (position, velocity, acceleration, momentum), not ~A"
                           (show (second x))))
           (list :component (intern (symbol-name (car x)) :keyword) vector)))
        ((quantity-form-p x)
         (destructuring-bind (word . count) (assoc (symbol-name (car x)) +quantity-words+ :test #'string=)
           (unless (and (proper-list-p x) (= (length (rest x)) count))
             (query-reject validation x "~A takes ~D name~:P" (string-downcase word) count))
           (cons (intern word :keyword)
                 (mapcar (lambda (name) (query-name-of validation name "body or rope")) (rest x)))))
        ((atom x) (canonical-atom validation x))
        ((not (proper-list-p x)) (query-reject validation x "~A is not a proper list" (show x)))
        ((named-p (car x) "DEG") (degrees-expression validation x (lambda (y) (checked-quantity validation y))))
        (t (let ((operator (algebra-operator-named (car x))))
             (unless (and operator (arithmetic-operator-p operator))
               (query-reject validation x "~A is neither a quantity nor an arithmetic operator"
                             (show (car x))))
             (cons operator (mapcar (lambda (y) (checked-quantity validation y)) (rest x)))))))

(defvar *event-kinds* nil
  "NIL, or a function of no arguments giving the kinds of event (keywords) the knowledge
base declares, which a query's event pattern must name; the knowledge base sets it.")

(defun checked-pattern (validation x)
  "The event pattern X, (:KIND NAME...), with its names declared and, where
*EVENT-KINDS* gives them, its KIND among the declared ones."
  (unless (and (consp x) (proper-list-p x) (keywordp (car x)))
    (query-reject validation x "an event is written as it is printed, (:KIND BODY ...), not ~A" (show x)))
  (let ((kinds (and *event-kinds* (funcall *event-kinds*))))
    (when (and kinds (not (member (car x) kinds)))
      (query-reject validation x "~A is no kind of event; the kinds are ~{~(~S~)~^, ~}"
                    (show (car x)) (sort (copy-list kinds) #'string<))))
  (cons (car x) (mapcar (lambda (name)
                          (if (keywordp name) name (query-name-of validation name "body or rope")))
                        (rest x))))

(defun checked-when (validation x)
  "X as a canonical WHEN."
  (cond ((and (consp x) (proper-list-p x) (= (length x) 2)
              (member (and (symbolp (car x)) (symbol-name (car x))) '("START" "END") :test #'equal))
         (unless (and (integerp (second x)) (>= (second x) 0))
           (query-reject validation x "a state is named by its index, 0, 1, ..."))
         (list (intern (symbol-name (car x)) :keyword) (second x)))
        ((and (consp x) (keywordp (car x))) (list :event (checked-pattern validation x)))
        ((and (consp x) (named-p (car x) "REACHES"))
         (unless (and (proper-list-p x) (= 3 (length x)))
           (query-reject validation x "(reaches QUANTITY VALUE)"))
         (list :reaches (checked-quantity validation (second x))
               (checked-quantity validation (third x))))
        (t (list :time (checked-expression validation x)))))

(defun checked-condition (validation x)
  "X as a canonical CONDITION."
  (cond ((and (consp x) (keywordp (car x))) (list :outcome (checked-pattern validation x)))
        ((and (consp x) (named-p (car x) "NOT") (proper-list-p x) (= 2 (length x))
              (consp (second x)) (keywordp (car (second x))))
         (list :not (list :outcome (checked-pattern validation (second x)))))
        ((and (consp x) (proper-list-p x) (= 3 (length x)) (symbolp (car x))
              (member (symbol-name (car x)) '("<" ">" "<=" ">=" "=") :test #'string=))
         (list (algebra-operator-named (car x))
               (checked-quantity validation (second x)) (checked-quantity validation (third x))))
        (t (query-reject validation x "a condition is a relation such as (> (speed b) v), an outcome such as (:lift-off b s), or (not OUTCOME), not ~A" (show x)))))

(defparameter *question-options*
  '(("VALUE" :at) ("DISTANCE" :during) ("PARAMETER" :such-that) ("PROVE" :during)
    ("MAXIMUM" :during) ("MINIMUM" :during))
  "For each question word taking one argument and options, the option keys it accepts.")

(defun check-question-options (validation question word arguments)
  "Reject QUESTION (its WORD, ARGUMENTS) unless its arguments are one argument followed by
options, each a key WORD accepts with one value, none repeated: an option misspelt or a
stray atom would otherwise be ignored. Words not in *QUESTION-OPTIONS* are left to their
own checks."
  (let ((keys (rest (assoc word *question-options* :test #'equal))))
    (when keys
      (let ((options (rest arguments)))
        (unless (and arguments (evenp (length options))
                     (loop for (key) on options by #'cddr
                           always (member key keys))
                     (loop for (key . more) on options by #'cddr
                           never (member key (loop for (k) on (rest more) by #'cddr collect k))))
          (query-reject validation question "(~(~A~) ...) takes one argument, then the options ~{~(~S~)~^, ~}, each at most once and with a value, not ~A"
                        word keys (show question)))))))

(defun checked-query (validation clause)
  "The canonical query (NAME QUESTION) of the clause (query NAME QUESTION)."
  (enter validation "clause QUERY" clause)
  (unless (and (proper-list-p clause) (= 3 (length clause)) (symbolp (second clause))
               (second clause) (not (keywordp (second clause))))
    (query-reject validation clause "a query is (query NAME QUESTION)"))
  (let* ((question (third clause))
         (word (and (consp question) (symbolp (car question)) (symbol-name (car question))))
         (arguments (and (consp question) (proper-list-p question) (rest question))))
    (flet ((option (key)
             (let ((tail (member key arguments)))
               (and tail (second tail)))))
      (check-question-options validation question word arguments)
      (list (second clause)
            (cond ((equal word "VALUE")
                   (unless (option :at) (query-reject validation question "(value QUANTITY :at WHEN)"))
                   (list :value (checked-quantity validation (first arguments))
                         :at (checked-when validation (option :at))))
                  ((equal word "TIME") (checked-time-question validation question))
                  ((equal word "DISTANCE")
                   (list :distance (query-name-of validation (first arguments) "body")
                         :during (and (option :during) (checked-when validation (option :during)))))
                  ((equal word "PARAMETER")
                   (unless (option :such-that)
                     (query-reject validation question "(parameter P :such-that CONDITION)"))
                   (let ((declaration (declared validation (first arguments))))
                     (unless (eq (car declaration) :parameter)
                       (reject validation 'undeclared-symbol-error (first arguments)
                               "~A is not a declared parameter" (show (first arguments))))
                     (list :parameter (cdr declaration)
                           :such-that (checked-condition validation (option :such-that)))))
                  ((equal word "PROVE")
                   (list :prove (checked-condition validation (first arguments))
                         :during (and (option :during) (checked-when validation (option :during)))))
                  ((member word '("MAXIMUM" "MINIMUM") :test #'equal)
                   (list (intern word :keyword) (checked-quantity validation (first arguments))
                         :during (and (option :during) (checked-when validation (option :during)))))
                  (t (query-reject validation question
                                   "a question is (value ...), (time ...), (distance ...), (parameter ...), (prove ...), (maximum ...) or (minimum ...), not ~A"
                                   (show question))))))))

(defun checked-time-question (validation question)
  "The canonical form of (time X): X (start N) or (end N) gives (:TIME-AT (:START N)),
(:rest BODY) gives (:REST-TIME BODY), (reaches QUANTITY VALUE) gives (:REACHES-TIME
QUANTITY VALUE), an event pattern (:TIME PATTERN)."
  (let ((x (and (proper-list-p question) (second question))))
    (cond ((and (consp x) (member (and (symbolp (car x)) (not (keywordp (car x))) (symbol-name (car x)))
                                  '("START" "END") :test #'equal))
           (list :time-at (checked-when validation x)))
          ((and (consp x) (eq (car x) :rest))
           (unless (and (proper-list-p x) (= 2 (length x)))
             (query-reject validation x "(:rest BODY) names one body"))
           (list :rest-time (query-name-of validation (second x) "body")))
          ((and (consp x) (named-p (car x) "REACHES"))
           (unless (and (proper-list-p x) (= 3 (length x)))
             (query-reject validation x "(reaches QUANTITY VALUE)"))
           (list :reaches-time (checked-quantity validation (second x))
                 (checked-quantity validation (third x))))
          (t (list :time (checked-pattern validation x))))))

(defun checked-queries (validation clauses)
  "The canonical queries of the (query NAME QUESTION) CLAUSES, in order. A query's name
is its answer's name in every report: two queries of one name, or a query named like a
parameter, body, force, spring, pulley or rope, are a DUPLICATE-NAME-ERROR naming it."
  (let ((queries '()))
    (dolist (clause clauses (nreverse queries))
      (let* ((query (checked-query validation clause))
             (name (first query))
             (declaration (declared validation name)))
        (when (find (symbol-name name) queries
                    :key (lambda (other) (symbol-name (first other))) :test #'string=)
          (reject validation 'duplicate-name-error name
                  "two queries are named ~A" (show name)))
        (when declaration
          (reject validation 'duplicate-name-error name
                  "the query ~A is named like the ~(~A~) ~A; give it a name of its own"
                  (show name) (car declaration) (show (cdr declaration))))
        (push query queries)))))
