;;;; src/engine/situation.lisp -- situations: the scenario's entities, given to the engine as data.

(in-package #:ames.engine)

(defstruct (entity (:constructor make-entity (kind name properties)))
  "A thing of the scenario that components take as argument: a body, a gravity
field, a simple contact, an external force... KIND and NAME are symbols;
PROPERTIES is a property list the engine only matches against :WHERE clauses and
hands to template functions."
  (kind nil :type symbol)
  (name nil :type symbol)
  (properties '() :type list))

(setf (documentation 'entity-kind 'function) "The entity's kind, e.g. BODY."
      (documentation 'entity-name 'function) "The entity's name, unique in its situation."
      (documentation 'entity-properties 'function) "The entity's property list.")

(defmethod print-object ((entity entity) stream)
  (print-unreadable-object (entity stream :type t)
    (format stream "~S ~S" (entity-kind entity) (entity-name entity))))

(defun entity-property (entity key &optional default)
  "The value of ENTITY's property KEY, or DEFAULT when it has none."
  (getf (entity-properties entity) key default))

(defstruct (situation (:constructor %make-situation (entities data)))
  "The entities of a scenario, indexed by name and kind, plus DATA: whatever the
caller wants template functions to see (the simulator's scenario and geometry)."
  (entities '() :type list)
  (data nil)
  (by-name (make-hash-table :test #'eq) :type hash-table)
  (by-kind (make-hash-table :test #'eq) :type hash-table))

(setf (documentation 'situation-entities 'function)
      "The situation's entities, in the order given."
      (documentation 'situation-data 'function)
      "The caller's datum given to MAKE-SITUATION as :DATA.")

(defun parse-entity (description)
  "An ENTITY from DESCRIPTION, (KIND NAME :KEY VALUE ...), or DESCRIPTION itself if
it is an entity. Signals SITUATION-ERROR when it is malformed."
  (flet ((fail (detail) (error 'situation-error :datum description :detail detail)))
    (cond ((entity-p description) description)
          ((not (and (consp description) (proper-list-p description)
                     (>= (length description) 2)))
           (fail "An entity is described by (KIND NAME :PROPERTY VALUE ...)."))
          (t (destructuring-bind (kind name &rest properties) description
               (unless (and (symbolp kind) kind (not (keywordp kind)))
                 (fail "An entity's kind must be a symbol."))
               (unless (and (symbolp name) name (not (keywordp name)))
                 (fail "An entity's name must be a symbol."))
               (unless (and (evenp (length properties))
                            (loop for (key) on properties by #'cddr always (keywordp key)))
                 (fail "An entity's properties must be a property list with keyword keys."))
               (make-entity kind name properties))))))

(defun make-situation (entities &key data)
  "A situation holding ENTITIES, each an ENTITY or a list (KIND NAME :PROPERTY VALUE
...), e.g. ((body wedge :mass mw :fixed nil) (gravity-field earth :strength g)).
DATA is kept for template functions. Signals SITUATION-ERROR for a malformed entity
or a name used twice."
  (let ((situation (%make-situation (mapcar #'parse-entity entities) data)))
    (dolist (entity (situation-entities situation))
      (when (gethash (entity-name entity) (situation-by-name situation))
        (error 'situation-error :datum (entity-name entity)
                                :detail "Two entities of the situation have this name."))
      (setf (gethash (entity-name entity) (situation-by-name situation)) entity)
      (push entity (gethash (entity-kind entity) (situation-by-kind situation))))
    (maphash (lambda (kind entities)
               (setf (gethash kind (situation-by-kind situation)) (reverse entities)))
             (situation-by-kind situation))
    situation))

(defun find-entity (situation name)
  "The entity of SITUATION called NAME, or NIL."
  (values (gethash name (situation-by-name situation))))

(defun entities-of-kind (situation kind)
  "The entities of SITUATION of KIND, in the order given."
  (values (gethash kind (situation-by-kind situation))))

(defun match-entity (where entity bindings)
  "Match the :WHERE property pattern against ENTITY's properties (an absent
property reads as NIL), extending BINDINGS; second value true on success."
  (match-properties where
                    (lambda (key) (values (entity-property entity key nil) t))
                    bindings))
