;;;; src/engine/grammar-checks.lisp -- the checks DEFCOMPONENT's grammar applies to patterns,
;;;; relation templates and variables, each naming the component and clause at fault.

(in-package #:ames.engine)

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

