;;;; src/kb/phenomena.lisp -- the registry of phenomena: everything the layers above the
;;;; knowledge base need to know of a force law or contact law, declared beside its components.
;;;;
;;;; A PHENOMENON is one physical effect (contact, terrestrial gravity, an external force,
;;;; Coulomb friction, springs, ropes, universal gravitation, impacts, turning points). Its
;;;; kb file declares it with DEFINE-PHENOMENON, next to the DEFCOMPONENTs that model it:
;;;;
;;;;   (define-phenomenon friction
;;;;     "Coulomb friction on the contacts between two bodies (friction.lisp)."
;;;;     (:entities #'friction-entities)             ; scenario -> the situation's entities
;;;;     (:force :friction :names 2 :words "friction of ~*~A on ~:*~:*~A" :symbol "F")
;;;;     (:event :starts-sliding :words "~A starts sliding on ~A")
;;;;     (:quantity :friction :force :friction))
;;;;
;;;; The options (each may repeat, except the functions):
;;;;   (:entities F)         F of a validated scenario: the entities of the scenario's clause
;;;;                         that the state's situation holds (kb vocabulary, e.g.
;;;;                         (friction-coefficients NAME :between (A B) ...)).
;;;;   (:impact-entities F)  likewise, for the situation of an impact (impacts.lisp).
;;;;   (:probes F)           F of a scenario: the points attached to bodies whose loci on the
;;;;                         other bodies the geometry must give (a bumper's free end), each a
;;;;                         plist (:POINT NAME :BODY B :AT (X Y) :AXIS (UX UY) :KIND ENTITY-KIND).
;;;;   (:entity-phrases F)   F of a scenario: an alist entity name -> the phrase that names it
;;;;                         to people ("rope, piece 1"), for the entities the phenomenon makes.
;;;;   (:force KIND ...)     a kind of entry the components report in :FORCES, (KIND NAME...
;;;;                         VALUE [:KEY V ...]): :NAMES how many names lead it, :WORDS the
;;;;                         FORMAT control of its label over them, :SYMBOL the letter of a
;;;;                         scalar value ("N"), :ARROW :ALONG-CONTACT-NORMAL when the value is a
;;;;                         magnitude along the normal of the contact between its two names
;;;;                         (else a vector drawn at its last body), :LABEL the picture's label
;;;;                         of the arrow: a string, or (:NAME I) the entry's Ith name.
;;;;   (:impulse KIND ...)   a kind of entry an impact reports in :IMPULSES: :NAMES, :WORDS.
;;;;   (:event KIND ...)     an event its components name: :WORDS the FORMAT control of the
;;;;                         report's sentence over the event's names, :SHORT the picture's
;;;;                         label over the event's second name, :AT-FEATURE-END a FORMAT
;;;;                         control over the first name, said instead of :WORDS followed by
;;;;                         the contact's feature when the state has a contact between the
;;;;                         event's two names.
;;;;   (:quantity Q :force KIND)   the query quantity Q of the scenario language (src/scenario/
;;;;                         queries.lisp) reads the reported force entry KIND naming the
;;;;                         query's names, in either order; 0 when none is reported.
;;;; Anything not declared is named generically by the reports (the keyword's words and the
;;;; names), so a new phenomenon works before its words are chosen.
;;;;
;;;; Adding a phenomenon: a new file in src/kb/ (listed in ames.asd after the files it uses)
;;;; with its DEFCOMPONENTs and one DEFINE-PHENOMENON; the clause's syntax in src/scenario/.
;;;; The simulator, queries, reports and `explain` look phenomena up here and name none.

(in-package #:ames.kb)

(defstruct (phenomenon (:constructor make-phenomenon))
  "One physical effect the knowledge base models; see the file header for the slots."
  (name nil :type symbol)
  (documentation nil)
  (entities nil)
  (impact-entities nil)
  (probes nil)
  (entity-phrases nil)
  (forces '())
  (impulses '())
  (events '())
  (quantities '()))

(defvar *phenomena* '()
  "The registered phenomena, in the order of their definitions (the order the situation
lists their entities in).")

(defun register-phenomenon (phenomenon)
  "Add PHENOMENON to *PHENOMENA*, replacing one of the same name in place; returns it."
  (let ((old (position (phenomenon-name phenomenon) *phenomena* :key #'phenomenon-name)))
    (if old
        (setf (nth old *phenomena*) phenomenon)
        (setf *phenomena* (append *phenomena* (list phenomenon))))
    phenomenon))

(defun find-phenomenon (name)
  "The registered phenomenon called NAME, or NIL."
  (find name *phenomena* :key #'phenomenon-name))

(defmacro define-phenomenon (name &body body)
  "Declare the phenomenon NAME (see the file header for the options): BODY is an optional
documentation string and options (:ENTITIES F), (:IMPACT-ENTITIES F), (:PROBES F),
(:ENTITY-PHRASES F), (:FORCE KIND . PLIST), (:IMPULSE KIND . PLIST), (:EVENT KIND . PLIST),
(:QUANTITY Q . PLIST). The functions are evaluated, the descriptions are data."
  (let ((documentation (and (stringp (first body)) (pop body))))
    (flet ((all (key) (loop for option in body when (eq (first option) key) collect (rest option)))
           (one (key) (second (assoc key body))))
      (dolist (option body)
        (unless (member (first option) '(:entities :impact-entities :probes :entity-phrases
                                         :force :impulse :event :quantity))
          (error "DEFINE-PHENOMENON ~S: unknown option ~S" name option)))
      `(register-phenomenon
        (make-phenomenon :name ',name :documentation ,documentation
                         :entities ,(one :entities) :impact-entities ,(one :impact-entities)
                         :probes ,(one :probes) :entity-phrases ,(one :entity-phrases)
                         :forces ',(all :force) :impulses ',(all :impulse)
                         :events ',(all :event) :quantities ',(all :quantity))))))

;;; What the layers above read

(defun collected (function scenario)
  "The lists FUNCTION (a phenomenon's accessor) gives for SCENARIO, appended over the
phenomena in their order."
  (loop for phenomenon in *phenomena*
        for maker = (funcall function phenomenon)
        when maker append (funcall maker scenario)))

(defun situation-entities-of (scenario)
  "Every entity the phenomena make of SCENARIO's clauses for a state's situation (the
bodies and the contacts between shapes are the simulator's: it adds them)."
  (collected #'phenomenon-entities scenario))

(defun impact-entities-of (scenario)
  "Every entity the phenomena make of SCENARIO's clauses for an impact's situation."
  (collected #'phenomenon-impact-entities scenario))

(defun probes-of (scenario)
  "The points attached to SCENARIO's bodies whose loci the geometry gives (see :PROBES)."
  (collected #'phenomenon-probes scenario))

(defun entity-phrases-of (scenario)
  "An alist entity name -> the phrase naming it to people, for the entities the phenomena
make of SCENARIO that need one."
  (collected #'phenomenon-entity-phrases scenario))

(defun described (kind accessor)
  "The description plist of KIND in the phenomena's ACCESSOR lists, or NIL; the second
value is true when a phenomenon describes KIND (possibly with an empty plist: named
generically)."
  (loop for phenomenon in *phenomena*
        for entry = (assoc kind (funcall accessor phenomenon))
        when entry return (values (rest entry) t)))

(defun force-description (kind)
  "The plist (:NAMES :WORDS :SYMBOL :ARROW :LABEL) of the reported force KIND, or NIL;
true as a second value when a phenomenon describes KIND."
  (described kind #'phenomenon-forces))

(defun impulse-description (kind)
  "The plist (:NAMES :WORDS) of the impulse KIND an impact reports, or NIL; true as a
second value when a phenomenon describes KIND."
  (described kind #'phenomenon-impulses))

(defun event-description (kind)
  "The plist (:WORDS :SHORT :AT-FEATURE-END) of the event KIND, or NIL; true as a second
value when a phenomenon describes KIND."
  (described kind #'phenomenon-events))

(defun quantity-description (query-kind)
  "The plist (:FORCE KIND) of the query quantity QUERY-KIND a phenomenon answers, or NIL."
  (described query-kind #'phenomenon-quantities))

(defun indexed-entity-name (prefix index)
  "The symbol PREFIX-INDEX naming an entity a phenomenon makes of a clause (not from user
data): FRICTION-0, SEGMENT-3."
  (intern (format nil "~A-~D" prefix index) '#:ames.kb))
