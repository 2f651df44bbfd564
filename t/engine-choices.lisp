;;;; t/engine-choices.lisp -- components own their events, and the choices a state leaves open.
;;;;
;;;; A small knowledge base of switches and lamps, nothing of mechanics: a lamp's contact
;;;; may close or not when its switch is "loose" (the decider answers :CHOICE), and a
;;;; dimmer starts in one of two modes. The engine must list those choices, let them be
;;;; settled by ordinary changes, and give every termination condition the event its
;;;; component names.

(in-package #:ames.tests)

(in-suite engine)

(defun make-lamp-kb ()
  "A knowledge base with events and choices."
  (let ((kb (ames.engine:make-knowledge-base :name "lamps")))
    (ames.engine:defcomponent lamp-circuit (:knowledge-base kb)
      "A lamp lights while its switch's contact is closed; the contact opens when the
current would reverse, and breaks when the switch passes its travel."
      (:arguments (?lamp :entity lamp :where (:switch ?switch)))
      (:activation (= (gap ?switch) 0)
                   (:event (:closes ?switch ?lamp) :impact (:sparks ?switch ?lamp)))
      (:deactivation (:when (< (current ?lamp) 0) :event (:opens ?switch ?lamp))
                     (:when (> (travel ?switch) 1) :event (:breaks ?switch))
                     (< (voltage ?lamp) 0))
      (:assert (lit ?lamp))
      (:equations (= (current ?lamp) (/ (voltage ?lamp) 10))))
    (ames.engine:defcomponent dimmer (:knowledge-base kb)
      "A dimmer is bright or dim."
      (:arguments (?lamp :belief (lit ?lamp)))
      (:mode bright
        (:entry (> (knob ?lamp) 0))
        (:equations (= (power ?lamp) 100))
        (:transition :to dim :when (< (knob ?lamp) 0) :event (:dims ?lamp)))
      (:mode dim
        (:entry (< (knob ?lamp) 1))
        (:equations (= (power ?lamp) 10))
        (:transition :to bright :when (> (knob ?lamp) 1))))
    kb))

(defun lamp-decider (relation)
  "Touching relations (= (gap S) 0) are choices; the knob of every lamp allows both
modes; the rest is false."
  (cond ((and (eq (first relation) '=) (equal (third relation) 0)) :choice)
        ((member (first relation) '(< >)) :choice)
        (t :false)))

(test components-own-their-events
  (let* ((kb (make-lamp-kb))
         (model (ames.engine:build-model (ames.engine:make-engine kb)
                                         (ames.engine:make-situation '((switch s1) (lamp l1 :switch s1)))
                                         :decider #'lamp-decider))
         (conditions (ames.engine:model-termination-conditions model)))
    (flet ((event-of (relation-head)
             (let ((c (find relation-head conditions
                            :key (lambda (c) (let ((r (ames.engine:termination-condition-relation c)))
                                               (and (consp (second r)) (first (second r))))))))
               (and c (list (ames.engine:termination-condition-event c)
                            (ames.engine:termination-condition-impact c))))))
      (is (equal '((:opens s1 l1) nil) (event-of 'current)))
      (is (equal '((:breaks s1) nil) (event-of 'travel)))
      (is (equal '(nil nil) (event-of 'voltage)) "a bare relation names no event")
      (let ((dims (find :mode-transition conditions :key #'ames.engine:termination-condition-kind)))
        (is (not (null dims)))
        (when dims
          ;; the dimmer starts bright (the first mode that is a choice)
          (is (equal '(:dims l1) (ames.engine:termination-condition-event dims))))))))

(test open-choices-are-listed-and-settled-by-changes
  (let* ((kb (make-lamp-kb))
         (model (ames.engine:build-model (ames.engine:make-engine kb)
                                         (ames.engine:make-situation '((switch s1) (lamp l1 :switch s1)))
                                         :decider #'lamp-decider))
         (points (ames.engine:model-choice-points model)))
    (is (= 2 (length points)))
    (let ((circuit (find :activation points :key #'ames.engine:choice-point-kind))
          (dimmer (find :mode points :key #'ames.engine:choice-point-kind)))
      (is (not (null circuit)))
      (is (not (null dimmer)))
      (when (and circuit dimmer)
        (is (eq :true (ames.engine:choice-point-current circuit)) "a choice starts active")
        (is (equal '((= (gap s1) 0)) (ames.engine:choice-point-relations circuit)))
        (is (equal '(bright dim) (ames.engine:choice-point-options dimmer)))
        (is (null (ames.engine:choice-change model circuit :true)) "already so: no change")
        (signals ames.engine:invalid-change (ames.engine:choice-change model circuit :maybe))
        ;; choose dim, then open the circuit: the dimmer's instance goes with the lamp
        (ames.engine:apply-transition model (list (ames.engine:choice-change model dimmer 'dim)))
        (is (member '(= (power l1) 10) (ames.engine:model-equations model) :test #'equal))
        (ames.engine:apply-transition model (list (ames.engine:choice-change model circuit :false)))
        (is (null (ames.engine:model-equations model)))
        (is (null (ames.engine:check-incremental model :signal nil))
            "the settled choices rebuild to the same model")
        (let ((after (ames.engine:model-choice-points model)))
          (is (= 1 (length after)) "only the circuit is open again: ~S" after)
          (is (eq :false (ames.engine:choice-point-current (first after)))))))))

(test an-event-clause-is-checked
  (signals ames.engine:component-definition-error
    (ames.engine:parse-component 'bad "Bad." '((:arguments (?x :entity thing))
                                               (:activation (> (size ?x) 0) (:event (:grows ?y))))))
  (signals ames.engine:component-definition-error
    (ames.engine:parse-component 'bad "Bad." '((:arguments (?x :entity thing))
                                               (:deactivation (:event (:shrinks ?x))))))
  (signals ames.engine:component-definition-error
    (ames.engine:parse-component 'bad "Bad." '((:arguments (?x :entity thing))
                                               (:deactivation (:when (< (size ?x) 0) :event grows)))))
  (signals ames.engine:component-definition-error
    (ames.engine:parse-component 'bad "Bad." '((:arguments (?x :entity thing))
                                               (:activation (> (size ?x) 0) (:event (:a ?x))
                                                (:event (:b ?x)))))))
