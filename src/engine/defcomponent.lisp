;;;; src/engine/defcomponent.lisp -- DEFCOMPONENT, the form of a model component, and its
;;;; grammar (checked by PARSE-COMPONENT, grammar.lisp, when the form is macroexpanded).
;;;;
;;;; The grammar:
;;;;
;;;;     (defcomponent NAME (:knowledge-base KB-FORM)
;;;;       "Docstring: what piece of knowledge this is."
;;;;       (:arguments ARGUMENT...)
;;;;       (:activation CONDITION... [(:event EVENT [:impact EVENT])] | :always)
;;;;       (:deactivation RELATION-OR-EVENT-CONDITION... | :never)
;;;;       (:watch (:when RELATION :event EVENT) ...)   ; events that change no decision
;;;;       (:assert PATTERN...)             ; qualitative assertions, in every mode
;;;;       (:equations EQUATION...)         ; quantitative assertions, in every mode
;;;;       (:mode MODE-NAME                 ; zero or more modes, mutually exclusive, listed
;;;;                                        ; in order of preference (see below)
;;;;         (:entry CONDITION...)          ; needed when there are several modes
;;;;         (:assert PATTERN...)
;;;;         (:equations EQUATION...)
;;;;         (:transition :to MODE-NAME :when RELATION [:event EVENT] [:impact EVENT]) ...)
;;;;       ...)
;;;;
;;;;   Components own their events: EVENT is a list (:KIND ARGUMENT...) over the
;;;;   component's variables, e.g. (:lift-off ?body1 ?body2), reported when the condition
;;;;   ends a state; the optional :IMPACT event is reported instead when the condition is
;;;;   reached at a non-zero rate (a position-level condition crossed with a velocity: an
;;;;   impulsive event, such as (:collision ?body1 ?body2)). A deactivation condition with
;;;;   an event is written (:when RELATION :event EVENT [:impact EVENT]); a bare RELATION
;;;;   has no event of its own (the caller reports the change it stands for).
;;;;
;;;;   KB-FORM is evaluated: it gives the KNOWLEDGE-BASE to register in. Every section is
;;;;   optional; with no :ACTIVATION the component is always active once its arguments are
;;;;   bound, with no :DEACTIVATION it never ends.
;;;;
;;;;   ARGUMENT is one of
;;;;     (?VAR :entity KIND [:where PLIST])  ?VAR is each entity of KIND in the situation
;;;;                                         whose properties match PLIST (an absent
;;;;                                         property reads as NIL); variables in PLIST are
;;;;                                         bound too: (?c :entity simple-contact :where
;;;;                                         (:observer ?b1 :obstacle ?b2)).
;;;;     (?VAR :belief PATTERN)              a belief matching PATTERN; ?VAR occurs in it,
;;;;                                         the other variables are bound as well.
;;;;     (?VAR :collect TEMPLATE             ?VAR is the list of TEMPLATE's values over every
;;;;           :matching PATTERN)            believed match of PATTERN, in canonical order
;;;;                                         (all the forces on a body). It is known only
;;;;                                         once the instance is active, so only equations,
;;;;                                         deactivation and transition conditions may use it.
;;;;   Arguments are bound left to right; a variable bound earlier must match again
;;;;   (a join). An instance is identified by its KEY: (NAME value-of-each-non-collection
;;;;   ?VAR...).
;;;;
;;;;   A PATTERN is a belief with variables: (HEAD POSITIONAL... :KEY VALUE...). It
;;;;   matches a belief with the same head and positional elements and at least the
;;;;   properties it names, in any order: (force ?f :on ?b) matches (force (gravity w)
;;;;   :type gravity :from earth :on w). ?_ matches anything.
;;;;
;;;;   CONDITION is (:believes PATTERN) -- qualitative: some belief matching PATTERN must
;;;;   be believed; variables bound nowhere else are existential -- or a RELATION --
;;;;   quantitative: decided on the state's initial values by the caller's decider, which
;;;;   answers :true, :false or :unknown (the last signals UNDECIDED-RELATION).
;;;;
;;;;   RELATION and EQUATION are templates in the prefix algebra of AMES.BASE:
;;;;   (< (normal-magnitude ?c) 0), (= (* (mass ?b) (acc ?b :y)) (sum-of ?forces :y)).
;;;;   Variables are replaced by their values, then every form whose head is registered
;;;;   in the knowledge base with REGISTER-TEMPLATE is replaced by what its function
;;;;   returns (it gets the SITUATION and the form's arguments as data); other forms
;;;;   (acc ?b :y) are quantity terms. A template form may also stand alone for the whole
;;;;   relation or equation: (:activation (on-contact ?c)).
;;;;
;;;;   A watch is a termination condition of an active instance that ends the state with its
;;;;   EVENT and changes no decision of the model (no mode to leave, nothing deactivated):
;;;;   the next state has the same model, started from the new positions and velocities,
;;;;   and what its relation reads of the state's start (a state constant) is the new
;;;;   start's. A turning point is one (kb/rotation-turning.lisp): the angular velocity
;;;;   changes sign relative to the direction the state starts turning in.
;;;;
;;;;   Deactivation, watch and transition relations are termination conditions: the engine never
;;;;   decides them; they are tested on the solved model, so they may mention quantities
;;;;   that are not state variables (a normal force).
;;;;
;;;;   When the decider leaves several modes open (:CHOICE), the engine takes the first of
;;;;   them listed and MODEL-CHOICE-POINTS offers them in the order listed: a caller that
;;;;   finds several consistent prefers the earlier ones (a friction contact that can stick
;;;;   does not start sliding).
;;;;
;;;;   Example (the thesis's figure 2-8, Newton's second law):
;;;;
;;;;     (defcomponent newtons-second-law (:knowledge-base *mechanics*)
;;;;       "The free-body sum of every force on a body equals its mass times its
;;;;     acceleration in the fixed frame."
;;;;       (:arguments (?body :entity body :where (:fixed nil))
;;;;                   (?forces :collect ?f :matching (force ?f :on ?body)))
;;;;       (:activation :always)
;;;;       (:deactivation :never)
;;;;       (:equations (= (sum-of ?forces :x) (* (mass ?body) (acc ?body :x)))
;;;;                   (= (sum-of ?forces :y) (* (mass ?body) (acc ?body :y)))))
;;;;
;;;;   with SUM-OF and MASS registered as template functions. Every clause is checked
;;;;   when the form is macroexpanded: a malformed one signals COMPONENT-DEFINITION-ERROR
;;;;   naming it. The expansion only registers the data object that PARSE-COMPONENT
;;;;   builds from the same sections; it returns the component.

(in-package #:ames.engine)

(defmacro defcomponent (name &optional options documentation &body sections)
  "Define the model component NAME and register it in a knowledge base:

  (defcomponent NAME (:knowledge-base KB-FORM)
    \"Docstring: what piece of knowledge this is.\"
    (:arguments ARGUMENT...)
    (:activation CONDITION... [(:event EVENT [:impact EVENT])] | :always)
    (:deactivation RELATION-OR-EVENT-CONDITION... | :never)
    (:watch (:when RELATION :event EVENT) ...)
    (:assert PATTERN...) (:equations EQUATION...)
    (:mode MODE-NAME (:entry CONDITION...) (:assert PATTERN...) (:equations EQUATION...)
      (:transition :to MODE-NAME :when RELATION [:event EVENT] [:impact EVENT]) ...) ...)

The grammar of each section (arguments, patterns, conditions, relations and templates,
events, modes and the order of their preference) is described, with an example, in the
header of src/engine/defcomponent.lisp. KB-FORM is evaluated: it gives the
KNOWLEDGE-BASE to register in. Every clause is checked when the form is macroexpanded:
a malformed one signals COMPONENT-DEFINITION-ERROR naming it. The expansion only
registers the data object that PARSE-COMPONENT builds from the same sections; it
returns the component."
  (unless (and (proper-list-p options) (= 2 (length options))
               (eq (first options) :knowledge-base))
    (definition-error name options "After the name come the options (:KNOWLEDGE-BASE KB-FORM)."))
  ;; all the checking, at macroexpansion time
  (parse-component name documentation sections)
  `(register-component ,(second options)
                       (parse-component ',name ,documentation ',sections)))
