;;;; src/kb/clause-entities.lisp -- the entities the knowledge base makes of the scenario
;;;; clauses it reads itself (src/scenario/kb-clauses.lisp).
;;;;
;;;; A validated scenario keeps such a clause as plain data (KIND NAME :KEY VALUE ...), KIND
;;;; a keyword. The phenomenon's kb file registers, with DEFINE-CLAUSE-ENTITY, the entity
;;;; kind it describes that clause with (a symbol of this package, the kind its components'
;;;; :ENTITY arguments name); CLAUSE-ENTITY turns the data into the entity. The simulator
;;;; calls CLAUSE-ENTITY on every such clause and knows none of them by name.

(in-package #:ames.kb)

(defvar *clause-entities* (make-hash-table :test #'eq)
  "Clause data kind (a keyword) -> the entity kind (a symbol of AMES.KB) it becomes.")

(defmacro define-clause-entity (kind entity-kind)
  "The knowledge base describes the clause data of KIND (a keyword) as entities of
ENTITY-KIND (an unquoted symbol of this package)."
  `(setf (gethash ,kind *clause-entities*) ',entity-kind))

(defun clause-entity (data)
  "The situation entity (ENTITY-KIND NAME :KEY VALUE ...) of the clause DATA (KIND NAME
:KEY VALUE ...). Signals UNMODELLED-SITUATION for a kind no kb file registered."
  (let ((kind (gethash (first data) *clause-entities*)))
    (unless kind
      (error 'unmodelled-situation :datum data
                                   :detail (format nil "no knowledge base reads the clause ~(~A~)" (first data))))
    (cons kind (rest data))))
