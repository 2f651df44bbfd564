;;;; t/engine-toy-kb.lisp -- a small knowledge base about heating rooms, to show that the
;;;; engine knows nothing of mechanics, plus a numeric decider for the tests.
;;;;
;;;; It mirrors the shape of the mechanics knowledge base: HEATER has two modes with
;;;; transitions (like friction's static and sliding); OPEN-DOOR has a quantitative
;;;; activation and deactivation and asserts a pair of flows (like a contact and its
;;;; pair of normal forces); EXCHANGE-BALANCE binds two beliefs (like Newton's third
;;;; law); ENERGY-BALANCE collects every flow into a room (like Newton's second law
;;;; summing every force on a body); HEATED-ROOM requires a belief.

(in-package #:ames.tests)

(defun property-template (key)
  "A template function giving the property KEY of the entity named by its argument."
  (lambda (situation name)
    (ames.engine:entity-property (ames.engine:find-entity situation name) key)))

(defun flow-power (situation flow)
  "Template POWER: the quantity term of a heat flow named by the list FLOW,
e.g. (output radiator) -> (heat-power output radiator)."
  (declare (ignore situation))
  (cons 'heat-power flow))

(defun sum-of-flows (situation flows)
  "Template SUM-OF: the sum of the powers of FLOWS (0 for none), itself written with
the POWER template, which the engine expands in turn."
  (declare (ignore situation))
  (if flows
      (cons '+ (mapcar (lambda (flow) (list 'power flow)) flows))
      0))

(defun make-heating-kb ()
  "A fresh knowledge base about heated rooms."
  (let ((kb (ames.engine:make-knowledge-base :name "heating")))
    (ames.engine:register-template kb 'setpoint (property-template :setpoint))
    (ames.engine:register-template kb 'rating (property-template :rating))
    (ames.engine:register-template kb 'capacity (property-template :capacity))
    (ames.engine:register-template kb 'conductance (property-template :conductance))
    (ames.engine:register-template kb 'power #'flow-power)
    (ames.engine:register-template kb 'sum-of #'sum-of-flows)

    (ames.engine:defcomponent heater (:knowledge-base kb)
      "A working heater heats its room at its rating while the room is colder than
its setpoint, and is idle otherwise."
      (:arguments (?heater :entity heater :where (:room ?room :broken nil)))
      (:mode on
        (:entry (< (temperature ?room) (setpoint ?heater)))
        (:assert (heat-flow (output ?heater) :into ?room :from ?heater :kind radiant))
        (:equations (= (power (output ?heater)) (rating ?heater)))
        (:transition :to off :when (>= (temperature ?room) (setpoint ?heater))))
      (:mode off
        (:entry (>= (temperature ?room) (setpoint ?heater)))
        (:transition :to on :when (< (temperature ?room) (setpoint ?heater)))))

    (ames.engine:defcomponent open-door (:knowledge-base kb)
      "Heat flows through an open door from the warmer room into the colder one, in
proportion to the opening and the difference of temperatures."
      (:arguments (?door :entity door :where (:between ?room1 :and ?room2)))
      (:activation (> (opening ?door) 0))
      (:deactivation (<= (opening ?door) 0))
      (:assert (heat-flow (through ?door ?room1) :into ?room1 :from ?room2)
               (heat-flow (through ?door ?room2) :into ?room2 :from ?room1))
      (:equations
       (= (power (through ?door ?room1))
          (* (conductance ?door) (opening ?door)
             (- (temperature ?room2) (temperature ?room1))))))

    (ames.engine:defcomponent exchange-balance (:knowledge-base kb)
      "What a room gains through an exchange with another, the other loses."
      (:arguments (?gain :belief (heat-flow ?gain :into ?room1 :from ?room2))
                  (?loss :belief (heat-flow ?loss :into ?room2 :from ?room1)))
      (:equations (= (power ?gain) (- (power ?loss)))))

    (ames.engine:defcomponent energy-balance (:knowledge-base kb)
      "A room's temperature changes at the rate of all the heat flowing into it
over its heat capacity."
      (:arguments (?room :entity room)
                  (?flows :collect ?f :matching (heat-flow ?f :into ?room)))
      (:equations (= (* (capacity ?room) (temperature-rate ?room)) (sum-of ?flows))))

    (ames.engine:defcomponent heated-room (:knowledge-base kb)
      "A room some heater blows into has its air stirred."
      (:arguments (?room :entity room))
      (:activation (:believes (heat-flow ?_ :into ?room :kind radiant)))
      (:assert (heated ?room))
      (:equations (= (stirring ?room) 1)))
    kb))

(defun heating-situation ()
  "Two rooms joined by a door; a working radiator in the kitchen, a broken stove in
the hall."
  (ames.engine:make-situation
   '((room kitchen :capacity ck)
     (room hall :capacity ch)
     (heater radiator :room kitchen :rating p :setpoint s)
     (heater stove :room hall :rating q :setpoint s :broken t)
     (door d1 :between kitchen :and hall :conductance k))))

;;; A numeric decider over a table of initial values

(defun numeric-value (form values)
  "The number FORM denotes given VALUES, an alist (variable-or-term . number); NIL
when some quantity has no value."
  (flet ((args () (mapcar (lambda (x) (numeric-value x values)) (rest form))))
    (cond ((realp form) form)
          ((assoc form values :test #'equal) (cdr (assoc form values :test #'equal)))
          ((atom form) nil)
          ((member (first form) '(+ - * /))
           (let ((args (args)))
             (and (notany #'null args)
                  (ecase (first form)
                    (+ (reduce #'+ args))
                    (- (if (rest args) (reduce #'- args) (- (first args))))
                    (* (reduce #'* args))
                    (/ (if (rest args) (reduce #'/ args) (/ (first args))))))))
          (t nil))))

(defun numeric-truth (relation values)
  "RELATION's truth given VALUES: :TRUE, :FALSE or :UNKNOWN."
  (flet ((truth (flag) (if flag :true :false)))
    (case (first relation)
      ((< > <= >= = /=)
       (let ((a (numeric-value (second relation) values))
             (b (numeric-value (third relation) values)))
         (if (and a b)
             (truth (ecase (first relation)
                      (< (< a b)) (> (> a b)) (<= (<= a b)) (>= (>= a b))
                      (= (= a b)) (/= (/= a b))))
             :unknown)))
      (and (let ((answers (mapcar (lambda (r) (numeric-truth r values)) (rest relation))))
             (cond ((member :false answers) :false)
                   ((member :unknown answers) :unknown)
                   (t :true))))
      (not (case (numeric-truth (second relation) values)
             (:true :false) (:false :true) (t :unknown)))
      (t :unknown))))

(defun table-decider (values &optional log)
  "A decider answering from VALUES (an alist). When LOG (a cons) is given, every
relation asked is pushed onto its car."
  (lambda (relation)
    (when log (push relation (car log)))
    (numeric-truth relation values)))
