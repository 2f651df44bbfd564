;;;; src/engine/knowledge-base.lisp -- knowledge bases, template functions and the order of
;;;; instantiation by qualitative data dependencies.

(in-package #:ames.engine)

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
