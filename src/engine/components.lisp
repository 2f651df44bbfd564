;;;; src/engine/components.lisp -- model components as data.

(in-package #:ames.engine)

;;; The data

(defstruct (argument (:constructor make-argument
                         (variable kind &key entity-kind where pattern collect clause)))
  "One argument of a model component: VARIABLE bound to an entity of ENTITY-KIND
whose properties match WHERE (:ENTITY), to a belief matching PATTERN (:BELIEF), or
to the canonically sorted values of COLLECT over every believed match of PATTERN
(:COLLECTION)."
  (variable nil :type symbol)
  (kind :entity :type (member :entity :belief :collection))
  (entity-kind nil :type symbol)
  (where '() :type list)
  (pattern nil)
  (collect nil)
  (clause nil))

(defstruct (event-spec (:constructor make-event-spec (event impact)))
  "What a termination condition stands for, as the component that owns it says: the
EVENT template reported when it fires, and the IMPACT template reported instead when it
is reached at a non-zero rate, an impulsive event such as a collision (NIL when the
component gives none). Templates are lists over the component's variables, e.g.
(:lift-off ?body1 ?body2)."
  (event nil :type list)
  (impact nil :type list))

(defstruct (transition (:constructor make-transition (target relation clause &optional event)))
  "A mode transition condition: when RELATION becomes true, the instance enters the
mode TARGET; EVENT, an EVENT-SPEC or NIL, says how it is reported."
  (target nil :type symbol)
  (relation nil)
  (clause nil)
  (event nil))

(defstruct (mode (:constructor make-mode (name &key entry-p entry-beliefs entry-relations
                                                 assertions equations transitions)))
  "A mode of a component: its entry conditions (belief patterns that must be
believed and relations decided on the initial values), qualitative ASSERTIONS,
quantitative EQUATIONS and TRANSITIONS."
  (name nil :type symbol)
  (entry-p nil :type boolean)             ; true when an (:entry ...) clause was given
  (entry-beliefs '() :type list)
  (entry-relations '() :type list)
  (assertions '() :type list)
  (equations '() :type list)
  (transitions '() :type list))

(defstruct (component (:constructor %make-component))
  "A model component (thesis section 3.2.2), as data. Build one with
PARSE-COMPONENT or DEFCOMPONENT."
  (name nil :type symbol)
  (documentation nil :type (or null string))
  (arguments '() :type list)
  (activation-beliefs '() :type list)     ; patterns, existential
  (activation-relations '() :type list)   ; decided on the initial values
  (activation-event nil)                  ; an EVENT-SPEC or NIL
  (deactivation-relations '() :type list) ; termination conditions
  (deactivation-events '() :type list)    ; an EVENT-SPEC or NIL for each of them
  (watch-relations '() :type list)        ; termination conditions that change nothing
  (watch-events '() :type list)           ; the EVENT-SPEC of each of them
  (assertions '() :type list)             ; in every mode
  (equations '() :type list)              ; in every mode
  (modes '() :type list)
  (definition nil))                       ; the sections as written

(setf (documentation 'component-name 'function) "The component's name (a symbol)."
      (documentation 'component-documentation 'function) "The component's docstring."
      (documentation 'component-definition 'function)
      "The sections of the component as they were written.")

(defmethod print-object ((component component) stream)
  (print-unreadable-object (component stream :type t)
    (prin1 (component-name component) stream)))

(defun component-argument-variables (component)
  "The declared variables of COMPONENT's arguments, in order."
  (mapcar #'argument-variable (component-arguments component)))

(defun component-key-variables (component)
  "The argument variables whose values make an instance's key: all but collections."
  (loop for argument in (component-arguments component)
        unless (eq (argument-kind argument) :collection)
          collect (argument-variable argument)))

(defun component-collection-arguments (component)
  "COMPONENT's :COLLECTION arguments."
  (remove :collection (component-arguments component)
          :key #'argument-kind :test-not #'eq))

(defun component-mode-names (component)
  "The names of COMPONENT's modes, in order (NIL when it has none)."
  (mapcar #'mode-name (component-modes component)))

(defun find-mode (component name)
  "COMPONENT's mode called NAME, or NIL."
  (find name (component-modes component) :key #'mode-name))

(defun component-read-patterns (component)
  "Every belief pattern COMPONENT reads: belief and collection arguments,
activation and mode entry conditions."
  (append (loop for argument in (component-arguments component)
                when (member (argument-kind argument) '(:belief :collection))
                  collect (argument-pattern argument))
          (component-activation-beliefs component)
          (loop for mode in (component-modes component)
                append (mode-entry-beliefs mode))))

(defun component-asserted-patterns (component)
  "Every belief pattern COMPONENT asserts, in any mode."
  (append (component-assertions component)
          (loop for mode in (component-modes component) append (mode-assertions mode))))
